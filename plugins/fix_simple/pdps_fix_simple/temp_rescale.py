r"""Fix ``temp/rescale``: every N steps, if the group's temperature is more than a window away from
its target, scale the velocities to bring it a fraction of the way there (LAMMPS's fix temp/rescale).

.. math::

    T_t = T_\mathrm{start} + \frac{s - s_0}{s_1 - s_0}(T_\mathrm{stop} - T_\mathrm{start}), \qquad
    |T - T_t| > W:\ \mathbf{v}_i \leftarrow \mathbf{v}_i\sqrt{\frac{T - f(T - T_t)}{T}}

with s the step and s_0, s_1 the run's first and last (or ``run ... start/stop``); T the group's
temperature with d N - d degrees of freedom (LAMMPS's compute temp), or that of the temperature
compute ``fix_modify ID temp CID`` names (pdps_core's NamedTemperature: a compute's bias is kept out of
the scaling, as LAMMPS's).

Syntax::

    fix ID GROUP temp/rescale N TSTART TSTOP WINDOW FRACTION
    fix_modify ID temp CID

Example::

    fix heat all temp/rescale 100 1.0 1.5 0.05 1.0
"""

import math

from pdps_core.api import Fix, NamedTemperature, StyleArgs, param



class FixTempRescale(NamedTemperature, Fix):
    name = "temp/rescale"
    usage = "fix ID GROUP temp/rescale N TSTART TSTOP WINDOW FRACTION"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        t_start: float = param(ge=0, unit="temperature")
        t_stop: float = param(ge=0, unit="temperature")
        window: float = param(ge=0, unit="temperature")
        fraction: float = param(ge=0, le=1, unit="dimensionless")

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        t = self.current_temperature(sim)
        if t == 0.0:
            return
        target = sim.ramp(self.args.t_start, self.args.t_stop)
        if abs(t - target) > self.args.window:
            goal = t - self.args.fraction * (t - target)
            self.scale_velocities(sim, math.sqrt(goal / t))
