"""When ave/time and ave/space sample and average: LAMMPS's fix ave/time rule, shared by both.

``NEVERY NREPEAT NFREQ``: an average of NREPEAT samples taken NEVERY steps apart, the last on a
multiple of NFREQ. ``2 3 10`` samples steps 6 8 10, 16 18 20, ... and averages at 10, 20, ...;
``1 1 N`` is a snapshot every N steps. NFREQ must be a multiple of NEVERY and NREPEAT*NEVERY at most
NFREQ (LAMMPS: "Inconsistent fix ave/time nevery/nrepeat/nfreq values"), so windows never overlap.
The start of a run samples if its step is due (a run starting at step 0 with NREPEAT 1 averages
step 0), and a step already sampled at the end of one run is not sampled again by the next.
"""

from pydantic import model_validator

from pdps_core.api import StyleArgs, param


class ScheduleArgs(StyleArgs):
    """``NEVERY NREPEAT NFREQ``, which a style's own Args follow."""
    nevery: int = param(gt=0, unit="timesteps")
    nrepeat: int = param(gt=0, unit="dimensionless")
    nfreq: int = param(gt=0, unit="timesteps")

    @model_validator(mode="after")
    def _windows_fit(self):
        if self.nfreq % self.nevery:
            raise ValueError(f"nfreq must be a multiple of nevery (got nevery {self.nevery}, "
                             f"nfreq {self.nfreq})")
        if self.nrepeat * self.nevery > self.nfreq:
            raise ValueError(f"nrepeat * nevery must not exceed nfreq (got {self.nrepeat} * "
                             f"{self.nevery} = {self.nrepeat * self.nevery} > {self.nfreq})")
        return self


class Schedule:
    """The next step to sample (``due``) and where in its window of NREPEAT samples it falls."""

    def __init__(self, nevery, nrepeat, nfreq, step, start=0):
        self.nevery, self.nrepeat, self.nfreq = nevery, nrepeat, nfreq
        self.start = start              # no window ends before this step (ave/time's start)
        self.irepeat = 0
        self.due = self.first_due(step)

    def first_due(self, step):
        """The first sample at or after ``step`` that starts a window (LAMMPS's nextvalid), the
        window ending on a multiple of NFREQ no earlier than ``start``."""
        due = (step // self.nfreq) * self.nfreq + self.nfreq
        while due < self.start:
            due += self.nfreq
        if due - self.nfreq == step and self.nrepeat == 1:
            return step
        due -= (self.nrepeat - 1) * self.nevery
        return due + self.nfreq if due < step else due

    def run_setup(self, step):
        """A run starts: a window the clock has left (reset_timestep) is dropped."""
        if self.due < step or self.due > step + self.nfreq:
            self.irepeat = 0
            self.due = self.first_due(step)

    def advance(self, step):
        """Called after sampling ``step``; True when that sample completed a window."""
        self.irepeat += 1
        if self.irepeat < self.nrepeat:
            self.due += self.nevery
            return False
        self.irepeat = 0
        self.due = step + self.nfreq - (self.nrepeat - 1) * self.nevery
        return True
