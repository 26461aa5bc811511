"""Tests marked ``wheels`` build and install the distributions (minutes, see tests/test_wheels.py):
they run only when a -m expression names them (`pytest -m wheels`), not with `make test`'s "not slow"."""


def pytest_collection_modifyitems(config, items):
    if "wheels" in (config.getoption("markexpr") or ""):
        return
    kept = [item for item in items if item.get_closest_marker("wheels") is None]
    if len(kept) < len(items):
        config.hook.pytest_deselected(items=[item for item in items if item not in kept])
        items[:] = kept


_STATUS = {}


def pytest_sessionfinish(session, exitstatus):
    _STATUS["exit"] = int(exitstatus)


def pytest_unconfigure(config):
    """Leave with pytest's status once it has reported: the fresh-clone run of 2026-12-07 passed
    every test and then died in LLVM's own exit-time teardown (a StringMap assertion in numba's
    llvmlite, exit 134), which is not a verdict on the code under test."""
    import os
    import sys
    if "exit" in _STATUS and os.environ.get("PDPS_TEST_NORMAL_EXIT") is None:
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(_STATUS["exit"])
