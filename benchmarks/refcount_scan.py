"""Which compiled kernels keep numba's reference counting: a check for a slow kernel, not a test.

numba keeps an atomic, out-of-line increment and decrement of an array around every call of a
helper that stores into it under a branch (numba issue #2350), inside the loop that calls it. In
the granular contact and wall kernels that was half to three quarters of their time until they were
compiled with ``_nrt=False`` (docs/performance.md, "No reference counting where contact helpers
store"). This runs a pytest selection with empty numba and pdps caches (numba shows no machine code
of a kernel loaded from its cache), then counts the calls to ``NRT_incref`` and ``NRT_decref`` in
the machine code of every pdps kernel the selection compiled, most first::

    .venv/bin/python benchmarks/refcount_scan.py plugins/fix_wall/tests -k mesh

A few calls (the core's list build has 5) are usually views made once, outside the loops; a
kernel with more, or with calls in a loop over particles or pairs, is worth a look (the plugin guide
says how to remove the counting; an ``inline="always"`` helper is listed too, though only its
inlined copies run). Not part of ``make test``: compiling every kernel afresh takes minutes.
"""

import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
REPORT = "PDPS_REFCOUNT_REPORT"


def pytest_sessionfinish(session, exitstatus):
    """As a pytest plugin (``-p refcount_scan``): write every compiled pdps kernel's count."""
    from numba.core.registry import CPUDispatcher
    counts, seen = {}, set()
    for name, module in list(sys.modules.items()):
        if not name.startswith("pdps") or module is None:
            continue
        for kernel in list(vars(module).values()):
            if not isinstance(kernel, CPUDispatcher) or id(kernel) in seen:
                continue
            seen.add(id(kernel))
            label = f"{kernel.py_func.__module__}.{kernel.py_func.__name__}"
            for signature in kernel.signatures:
                # the machine code before the Python wrapper (cpython) numba adds
                code = kernel.inspect_asm(signature).split("_ZN7cpython")[0]
                counts[label] = max(counts.get(label, 0), len(re.findall(r"NRT_incref|NRT_decref", code)))
    with open(os.environ[REPORT], "w") as handle:
        for label, count in sorted(counts.items(), key=lambda item: (-item[1], item[0])):
            handle.write(f"{count} {label}\n")


def main():
    if len(sys.argv) < 2:
        sys.exit(f"usage: {Path(sys.argv[0]).name} PYTEST_ARGS...   (a test selection that runs the kernels)")
    with tempfile.TemporaryDirectory() as empty:
        report = Path(empty) / "report.txt"
        env = dict(os.environ, NUMBA_CACHE_DIR=f"{empty}/numba", PDPS_CACHE_DIR=f"{empty}/pdps",
                   PYTHONPATH=os.pathsep.join([str(HERE), os.environ.get("PYTHONPATH", "")]), **{REPORT: str(report)})
        done = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "refcount_scan", *sys.argv[1:]], cwd=ROOT,
                              env=env)
        if not report.exists():
            sys.exit(f"refcount_scan: pytest ended with exit code {done.returncode} and no report")
        print("calls to NRT_incref/NRT_decref in each kernel's machine code (kernels with none left out):")
        for line in report.read_text().splitlines():
            if not line.startswith("0 "):
                print("  " + line)


if __name__ == "__main__":
    main()
