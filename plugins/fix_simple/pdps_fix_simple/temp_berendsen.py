r"""Fix ``temp/berendsen``: Berendsen's weak coupling of the group's temperature to a target
(Berendsen et al., J. Chem. Phys. 81, 3684 (1984); LAMMPS's fix temp/berendsen), every step:

.. math::

    \mathbf{v}_i \leftarrow \lambda\mathbf{v}_i, \qquad
    \lambda = \sqrt{1 + \frac{\Delta t}{\tau}\left(\frac{T_t}{T} - 1\right)}

with T_t ramped from TSTART to TSTOP over the run (as temp/rescale) and T the group's temperature,
or that of the temperature compute ``fix_modify ID temp CID`` names (pdps_core's NamedTemperature: a
compute's bias is kept out of the scaling, as LAMMPS's).

Syntax::

    fix ID GROUP temp/berendsen TSTART TSTOP DAMP
    fix_modify ID temp CID

DAMP the coupling time tau (time units). Example::

    fix cool all temp/berendsen 1.0 1.0 0.5
"""

import math

from pdps_core.api import Fix, NamedTemperature, ScriptError, StyleArgs, param



class FixTempBerendsen(NamedTemperature, Fix):
    name = "temp/berendsen"
    usage = "fix ID GROUP temp/berendsen TSTART TSTOP DAMP"

    class Args(StyleArgs):
        t_start: float = param(ge=0, unit="temperature")
        t_stop: float = param(ge=0, unit="temperature")
        damp: float = param(gt=0, unit="time")

    def end_of_step(self, sim):
        t = self.current_temperature(sim)
        if t == 0.0:
            raise ScriptError(f"fix {self.id} temp/berendsen: the group's temperature is 0, so velocities "
                              "cannot be scaled to the target")
        target = sim.ramp(self.args.t_start, self.args.t_stop)
        square = 1.0 + sim.dt / self.args.damp * (target / t - 1.0)
        if square < 0.0:
            raise ScriptError(f"fix {self.id} temp/berendsen: the scaling factor is not real at step {sim.step} "
                              f"(1 + dt/damp (T_target/T - 1) = {square:.4g}): make damp larger than the timestep")
        self.scale_velocities(sim, math.sqrt(square))
