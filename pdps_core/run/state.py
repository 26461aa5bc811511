"""The run part of a simulation: the step and the time, the current run's bounds, what was computed
on which step, the integrator, and the schedules a run keeps (LAMMPS's Update)."""

import numpy as np

from ..errors import ScriptError
from .minimize import MinSettings


class RunState:
    __slots__ = ("step", "dt", "time", "run_first_step", "run_last_step", "ramp_bounds", "random_epoch",
                 "highest_step", "pe", "evdwl", "ebond", "virial", "pair_virial", "eflag", "vflag", "energy_step", "virial_step",
                 "in_setup", "in_init", "integrator", "run_wall_start", "restart_output", "min_settings",
                 "minimize_result", "box_changed", "tally_step", "tally_atom")

    def __init__(self, dt):
        self.step = 0
        self.dt = dt                    # the timestep (time units)
        self.time = 0.0
        self.run_first_step = 0
        self.run_last_step = 0
        self.ramp_bounds = (0, 0)       # the run's first and last step, or run start/stop's
        self.random_epoch = 0           # reset_timestep backwards so far (random_key)
        self.highest_step = 0
        self.pe = 0.0
        self.evdwl = 0.0                # the pair style's share of pe (thermo evdwl)
        self.ebond = 0.0                # the bond style's share of pe (thermo ebond)
        self.virial = np.zeros(6)
        self.pair_virial = np.zeros(6)  # the pair style's share of virial (compute pressure pair)
        self.eflag = False              # energy is computed on the current step (read by fixes)
        self.vflag = False              # virial is computed on the current step
        self.energy_step = None         # the step energies were last computed on
        self.virial_step = None
        self.in_setup = False           # True while a run computes its setup forces
        self.in_init = False            # True while styles' init_run is called (neighbor requests)
        self.integrator = None          # the Verlet or Minimizer of the current (or last) run
        self.run_wall_start = None      # perf_counter at the loop's start (thermo's cpu), None before
        self.restart_output = None      # the `restart N FILE` schedule (state/restart.py)
        self.min_settings = MinSettings()
        self.minimize_result = None
        self.box_changed = False        # change_box since the last neighbor decision (Verlet rebuilds)
        self.tally_step = None          # the step per-particle energy/virial was tallied on
        self.tally_atom = False         # per-particle energy/virial is tallied on the current step

    def ramp(self, start, stop):
        """start + (stop - start) * (step - first step) / (last step - first step) of the current run
        (of ``run N start S stop E``'s S and E when given): LAMMPS's ramp(x, y), what a thermostat
        ramping T_START to T_STOP reads each step."""
        first, last = self.ramp_bounds
        if last <= first:
            return start
        return start + (stop - start) * (self.step - first) / (last - first)

    def random_key(self, seed):
        """The key a style's random numbers use for its ``seed``: the seed itself until
        reset_timestep sends the step back to steps already run, then a new key for each such
        reset, so a production run after ``reset_timestep 0`` does not replay the noise of the
        equilibration (LAMMPS's generators never rewind either)."""
        if self.random_epoch == 0:
            return seed
        return (seed + self.random_epoch * 0x9E3779B97F4A7C15) % (2 ** 63 - 1) + 1

    def reset_step(self, step):
        """reset_timestep: a step below one already reached starts a new random epoch."""
        self.highest_step = max(self.highest_step, self.step)
        if step < self.highest_step:
            self.random_epoch += 1
            self.highest_step = step
        self.step = step

    def require_energy(self):
        if self.energy_step != self.step:
            raise ScriptError(f"potential energy was not computed on step {self.step}: "
                              "read it on a thermo step, or run 0 first")

    def require_virial(self):
        if self.virial_step != self.step:
            raise ScriptError(f"virial was not computed on step {self.step}: "
                              "read it on a thermo step, or run 0 first")
