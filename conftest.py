"""Tests marked ``wheels`` build and install the distributions (minutes, see tests/test_wheels.py):
they run only when a -m expression names them (`pytest -m wheels`), not with `make test`'s "not slow"."""


def pytest_collection_modifyitems(config, items):
    if "wheels" in (config.getoption("markexpr") or ""):
        return
    kept = [item for item in items if item.get_closest_marker("wheels") is None]
    if len(kept) < len(items):
        config.hook.pytest_deselected(items=[item for item in items if item not in kept])
        items[:] = kept
