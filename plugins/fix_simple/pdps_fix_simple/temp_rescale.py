r"""Fix ``temp/rescale``: every N steps, if the group's temperature is more than a window away from
its target, scale the velocities to bring it a fraction of the way there (LAMMPS's fix temp/rescale).

.. math::

    T_t = T_\mathrm{start} + \frac{s - s_0}{s_1 - s_0}(T_\mathrm{stop} - T_\mathrm{start}), \qquad
    |T - T_t| > W:\ \mathbf{v}_i \leftarrow \mathbf{v}_i\sqrt{\frac{T - f(T - T_t)}{T}}

with s the step and s_0, s_1 the run's first and last (or ``run ... start/stop``); T the group's
temperature with d N - d degrees of freedom (LAMMPS's compute temp), or that of the temperature
compute ``fix_modify ID temp CID`` names: its T decides, the fix's group is scaled, and a compute with
a bias (temp/partial: the components it leaves out) has it kept out of the scaling, as LAMMPS's
remove_bias and restore_bias do. A compute of another group than the fix's is warned of, as LAMMPS
warns.

Syntax::

    fix ID GROUP temp/rescale N TSTART TSTOP WINDOW FRACTION
    fix_modify ID temp CID

Example::

    fix heat all temp/rescale 100 1.0 1.5 0.05 1.0
"""

import math

from pdps_core.api import Fix, ScriptError, StyleArgs, observables, param


class FixTempRescale(Fix):
    name = "temp/rescale"
    usage = "fix ID GROUP temp/rescale N TSTART TSTOP WINDOW FRACTION"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        t_start: float = param(ge=0, unit="temperature")
        t_stop: float = param(ge=0, unit="temperature")
        window: float = param(ge=0, unit="temperature")
        fraction: float = param(ge=0, le=1, unit="dimensionless")

    temp_id = None          # fix_modify temp: the temperature compute named instead of the group's

    def modify_param(self, sim, keyword, value):
        if keyword != "temp":
            return False
        compute = sim.computes.get(value)
        if compute is None:
            raise ScriptError(f"compute {value} is not defined (temperature of fix {self.id})")
        if not type(compute).gives_temperature:
            raise ScriptError(f"compute {value} ({compute.name}) is not a temp compute, so it gives no temperature")
        if compute.group != self.group:
            sim.warn(f"fix {self.id} {self.name}: temperature compute {value} is of group {compute.group}, not the "
                     f"fix's {self.group} (LAMMPS's fix_modify warns so too)")
        self.temp_id = value
        return True

    def init_run(self, sim):
        if self.temp_id is not None and self.temp_id not in sim.computes:
            raise ScriptError(f"fix {self.id}: its temperature compute {self.temp_id} is not defined")

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        compute = sim.computes[self.temp_id] if self.temp_id is not None else None
        t = observables.temperature(sim, self.group) if compute is None else float(sim.compute_value(self.temp_id))
        if t == 0.0:
            return
        target = sim.ramp(self.args.t_start, self.args.t_stop)
        if abs(t - target) > self.args.window:
            goal = t - self.args.fraction * (t - target)
            factor = math.sqrt(goal / t)
            p = sim.particles
            chosen = sim.groups.select(sim, self.group)
            v = p.v[:p.nlocal]
            if hasattr(compute, "velocity_bias"):
                bias = compute.velocity_bias(sim)[chosen]
                v[chosen] = bias + factor * (v[chosen] - bias)
            else:
                v[chosen] *= factor
