"""Everything a run writes: the screen, the log file, thermo lines and their CSV copy, dumps, and
the progress line.

The log file gets every command as it is read, the thermo table and the timing table; the log, its
CSV copy (see ``thermo_csv``) and each dump are flushed at every output step, so a run that stops
loses nothing already written. Progress goes to stderr (see ``progress``).
"""

import sys
import math
import time

from .progress import Progress
from .thermo import Thermo
from ..errors import ScriptError, SimulationError
from .thermo_csv import ThermoCSV


class Output:
    def __init__(self, sim, screen=None, log=None):
        self.sim = sim
        # in a parallel run every rank computes what is written, rank 0 alone writes it
        self.root = sim.comm.is_root
        self.screen = (sys.stdout if screen is None else screen) if self.root else False
        self.log = None
        self.thermo = Thermo(sim)
        self.csv = ThermoCSV()
        self.csv_follows_log = True
        # a silent simulation (and every rank but 0) shows no progress
        self.progress = None if self.screen is False else Progress()
        self.dumps = {}
        self.echo_to = "log"            # LAMMPS's echo: none, screen, log or both
        self.warnings = []              # every warning given, in order
        self.started = time.perf_counter()   # the info command's wall time counts from here
        if log:
            self.open_log(log)

    # ---- screen and log -------------------------------------------------------------------------
    def open_log(self, path, append=False):
        """Switch the log to ``path`` (appended to with ``append``); one that cannot be opened is a
        one-line error and the log written so far stays as it is."""
        handle = None
        if self.log is not None:
            # what the current log still buffers goes out first: a log naming the same file would
            # otherwise write it over the new one's start when it closes (issue 30)
            self.log.flush()
        if self.root:
            try:
                handle = open(path, "a" if append else "w")
            except OSError as exc:
                raise ScriptError(f"cannot open log file {path}: {exc.strerror}") from None
        self.close_log()
        if self.root:
            self.log = handle
            if self.csv_follows_log:
                self.csv.use(f"{path}.csv", append)

    def close_log(self):
        if self.log is not None:
            self.log.close()
            self.log = None
        if self.csv_follows_log:
            self.csv.use(None)

    def thermo_csv(self, path):
        """The thermo CSV at ``path`` from the next run on (None: none), wherever the log goes."""
        self.csv_follows_log = False
        self.csv.use(path if self.root else None)

    def message(self, text):
        if self.screen is not False:
            if self.progress is not None:
                self.progress.clear()
            print(text, file=self.screen)
        if self.log is not None:
            print(text, file=self.log)

    def warn(self, text):
        """A warning on screen and in the log, kept in ``warnings``; the run goes on."""
        self.warnings.append(text)
        self.message(f"WARNING: {text}")

    def forget_styles(self):
        """LAMMPS's clear: dumps closed and forgotten, thermo settings back to their defaults."""
        for dump in self.dumps.values():
            dump.close()
        self.dumps = {}
        self.thermo = Thermo(self.sim)

    def echo(self, text):
        """A command as read: where ``echo`` sends it (the log only by default, as LAMMPS)."""
        if self.echo_to in ("screen", "both") and self.screen is not False:
            if self.progress is not None:
                self.progress.clear()
            print(text, file=self.screen)
        if self.echo_to in ("log", "both") and self.log is not None:
            print(text, file=self.log)

    def flush(self):
        if self.progress is not None:
            self.progress.clear()
        if self.log is not None:
            self.log.flush()
        self.csv.flush()
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
        for style in [*self.sim.fixes.values(), *self.sim.analyzes.values()]:
            needs |= style_needs(self.sim, style, step)
        return "energy" in needs, "virial" in needs

    # ---- writing --------------------------------------------------------------------------------
    def setup(self, step, last):
        self.thermo.validate()
        begun = self.csv.start(self.thermo.names())
        if begun:
            self.message(f"thermo columns changed: the thermo CSV goes on in {begun}")
        self.message(self.thermo.header())
        if self.progress is not None:
            self.progress.start(step, last)
        self.write(step, last)

    def write(self, step, last):
        t0 = time.perf_counter()
        wrote = False
        for dump in self.dumps.values():
            # a run starting where the last one ended has written this frame already; first yes
            # adds only the first step after the dump command, when the dump has written nothing (LAMMPS)
            last_step = getattr(dump, "last_step", None)
            due = step % dump.every == 0 or (dump.first and step == self.sim.run_first_step and last_step is None)
            if due and last_step != step:
                dump.write(self.sim)
                dump.last_step = step
                wrote = True
        if self.thermo.due(step, self.sim.run_first_step, last):
            values = self.thermo.values()
            self.message(self.thermo.line(values))
            if self.thermo.flush_each:
                self.flush()
            self.csv.row(values, self.thermo.integer())
            wrote = True
            bad = next((name for name, value in zip(self.thermo.names(), values)
                        if not math.isfinite(value)), None)
            if bad is not None:
                self.flush()
                raise SimulationError(f"thermo {bad} is {values[self.thermo.names().index(bad)]} at step "
                                      f"{step}: the run stops rather than go on with non-finite values "
                                      "(velocities or forces too large?)")
        if wrote:
            self.flush()
        if self.progress is not None:
            self.progress.update(step)
        self.sim.timers.stage["Output"] += time.perf_counter() - t0

    def close(self):
        for dump in self.dumps.values():
            dump.close()
        self.flush()
        self.close_log()
        self.csv.close()


def style_needs(sim, style, step):
    """What a fix or analyze style will read at this step (it may say so with ``needs(step)``)."""
    needs = getattr(style, "needs", None)
    return set(needs(step)) if callable(needs) else set()
