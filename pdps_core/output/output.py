"""Everything a run writes: the screen, the log file, thermo lines and dumps.

The log file gets every command as it is read, the thermo table and the timing table; both the log
and each dump are flushed at every output step, so a run that stops loses nothing already written.
"""

import sys
import time

from .thermo import Thermo


class Output:
    def __init__(self, sim, screen=None, log=None):
        self.sim = sim
        self.screen = sys.stdout if screen is None else screen
        self.log = None
        self.thermo = Thermo(sim)
        self.dumps = {}
        if log:
            self.open_log(log)

    # ---- screen and log -------------------------------------------------------------------------
    def open_log(self, path):
        self.close_log()
        self.log = open(path, "w")

    def close_log(self):
        if self.log is not None:
            self.log.close()
            self.log = None

    def message(self, text):
        if self.screen is not False:
            print(text, file=self.screen)
        if self.log is not None:
            print(text, file=self.log)

    def echo(self, text):
        """A command as read: to the log only (LAMMPS's default echo)."""
        if self.log is not None:
            print(text, file=self.log)

    def flush(self):
        if self.log is not None:
            self.log.flush()
        if self.screen not in (None, False):
            self.screen.flush()

    # ---- schedule -------------------------------------------------------------------------------
    def flags(self, step, last):
        """(eflag, vflag) for this step: what the outputs due now will read."""
        if step == last:
            return True, True
        needs = set()
        if self.thermo.due(step, self.sim.run_first_step, last):
            needs |= self.thermo.needs()
        for dump in self.dumps.values():
            if step % dump.every == 0:
                needs |= getattr(dump, "needs", set())
        for analyze in self.sim.analyzes.values():
            needs |= analyze_needs(self.sim, analyze, step)
        return "energy" in needs, "virial" in needs

    # ---- writing --------------------------------------------------------------------------------
    def setup(self, step, last):
        self.thermo.validate()
        self.message(self.thermo.header())
        self.write(step, last)

    def write(self, step, last):
        t0 = time.perf_counter()
        wrote = False
        for dump in self.dumps.values():
            # a run starting where the last one ended has written this frame already (LAMMPS)
            if step % dump.every == 0 and getattr(dump, "last_step", None) != step:
                dump.write(self.sim)
                dump.last_step = step
                wrote = True
        if self.thermo.due(step, self.sim.run_first_step, last):
            self.message(self.thermo.line())
            wrote = True
        if wrote:
            self.flush()
        self.sim.timers.stage["Output"] += time.perf_counter() - t0

    def close(self):
        for dump in self.dumps.values():
            dump.close()
        self.flush()
        self.close_log()


def analyze_needs(sim, analyze, step):
    """What an analyze style will read at this step (it may say so with a ``needs(step)`` method)."""
    needs = getattr(analyze, "needs", None)
    return set(needs(step)) if callable(needs) else set()
