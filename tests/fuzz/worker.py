"""A fuzz worker: a long-lived process that imports pdps once and runs cases in-process, one at a time.

Run by runner.py as ``python worker.py``; never imported by the tests. Protocol: one JSON request per
line on stdin, ``{"dir": ..., "script": ..., "inputs": [...], "limit": seconds}``; one JSON reply per
line on the original stdout (``classify.run_case``'s dict). Everything else the process prints at the
C level (fd 1 and 2) goes to the stderr file runner.py gave it, where faulthandler also writes the
Python stack on a fatal signal, or on SIGUSR1 (runner.py sends it to a case over its time limit,
just before SIGKILL).

The address space is capped (``PDPS_FUZZ_MEMORY`` GiB, default 4), so an input that asks for a huge
allocation meets a MemoryError here instead of the machine's swap.
"""

import faulthandler
import json
import os
import resource
import signal
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import classify  # noqa: E402  (beside this file, whatever the current folder)


def main():
    replies = os.fdopen(os.dup(1), "w", buffering=1)
    devnull = os.open(os.devnull, os.O_WRONLY)
    os.dup2(devnull, 1)
    # the watchdog interrupts a case as SIGINT would: a worker started from a background job
    # inherits SIGINT ignored, and Python then leaves it ignored
    signal.signal(signal.SIGINT, signal.default_int_handler)
    faulthandler.enable(file=sys.stderr, all_threads=True)
    faulthandler.register(signal.SIGUSR1, file=sys.stderr, all_threads=True)
    gib = float(os.environ.get("PDPS_FUZZ_MEMORY", "4"))
    limit = int(gib * 2**30)
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    classify.prepare()
    if os.environ.get("PDPS_FUZZ_SELFTEST"):
        import selftest
        selftest.register()
    replies.write(json.dumps({"ready": os.getpid()}) + "\n")
    for line in sys.stdin:
        request = json.loads(line)
        sys.stderr.write(f"\n=== case {request['dir']}\n")
        sys.stderr.flush()
        reply = classify.run_case(request["dir"], request["script"], request["inputs"],
                                  request["limit"])
        replies.write(json.dumps(reply) + "\n")


if __name__ == "__main__":
    main()
