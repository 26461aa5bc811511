"""A fix that misbehaves on purpose, so the fuzz harness can be shown to catch each kind of fault.

``fix ID GROUP fuzz/misbehave MODE`` (registered in a worker only when PDPS_FUZZ_SELFTEST is set):
at the first step, ``segfault`` kills the process with SIGSEGV, ``abort`` with SIGABRT, ``exit``
leaves it with os._exit(3), ``spin`` computes in C without releasing the interpreter lock (a hang
that nothing can interrupt), ``sleep`` waits forever without stepping (a hang the watchdog
interrupts), ``raise`` raises a ValueError (an internal error), ``nan`` writes a file of numbers
holding a nan and lets the run end well (non-finite output), ``warn`` prints a raw Python warning and
then stops with a script error (two lines on stderr), ``descheduled`` computes for 3 s of CPU time
once while a child process lets it run only a quarter of the time (SIGSTOP 0.3 s, SIGCONT 0.1 s),
as a machine busy with other work would, and lets the run end well.
"""

import os
import signal
import subprocess
import time
import warnings


from pdps_core.errors import ScriptError
from pdps_core.styles import Fix, StyleArgs, registry


class Misbehave(Fix):
    name = "fuzz/misbehave"

    class Args(StyleArgs):
        mode: str

    def end_of_step(self, sim):
        mode = self.args.mode
        if mode == "segfault":
            os.kill(os.getpid(), signal.SIGSEGV)
        elif mode == "abort":
            os.abort()
        elif mode == "exit":
            os._exit(3)
        elif mode == "spin":
            sum(range(10**12))
        elif mode == "sleep":
            while True:
                time.sleep(0.05)
        elif mode == "raise":
            raise ValueError("misbehaving on purpose")
        elif mode == "nan":
            with open("numbers.txt", "w") as handle:
                handle.write("# step value\n1 2.5\n2 nan\n")
        elif mode == "descheduled" and not getattr(self, "was_throttled", False):
            self.was_throttled = True
            pid = os.getpid()
            # the loop ends with the case: a watchdog's kill skips the finally below, and a loop left
            # running would stop whatever process takes the pid next
            throttle = subprocess.Popen(["sh", "-c", f"while kill -STOP {pid} 2>/dev/null; do sleep 0.2; "
                                                     f"kill -CONT {pid}; sleep 0.2; done"])
            try:
                until = time.process_time() + 4.0
                while time.process_time() < until:
                    sum(range(10000))
            finally:
                throttle.kill()
                throttle.wait()
                os.kill(pid, signal.SIGCONT)
        elif mode == "warn":
            warnings.warn("a raw warning", RuntimeWarning)
            raise ScriptError("stopped after a raw warning")


def register():
    registry.register("fix", Misbehave.name, Misbehave)
