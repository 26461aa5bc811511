r"""Fix ``dt/reset``: every N steps, a new time step such that no particle of the group moves
farther than Xmax in the next step (LAMMPS's and LIGGGHTS's fix dt/reset).

For each particle, with velocity :math:`\mathbf{v}`, force :math:`\mathbf{f}` and mass :math:`m`
(the force-to-acceleration factor of the units included):

.. math::

    \Delta t_i = \min\left(\frac{X_{max}}{|\mathbf{v}|},\ \sqrt{\frac{2X_{max}}{|\mathbf{f}|/m}}\right),
    \qquad \delta_i = \left|\Delta t_i\,\mathbf{v} + \tfrac12\Delta t_i^2\,\mathbf{f}/m\right|,

and :math:`\Delta t_i` shrunk by :math:`X_{max}/\delta_i` where :math:`\delta_i > X_{max}` (a
conservative estimate, not the quartic's root); the new step is the least over the group and the
ranks, then bounded below by Tmin and above by Tmax (either NULL: no bound). It is applied at the
end of the step (and at a run's setup); the elapsed time (thermo ``time``) adds each step's own
size. Fixes that keep constants of the step (barostats, thermostats, rigid bodies) redo them
(``reset_dt``); fix move refuses a changing step, as LAMMPS's does. Where nothing in the group moves
or feels a force and no Tmax is given, the step stays as it is, with a warning (LAMMPS and LIGGGHTS
would take :math:`10^{20}`).

Output: ``f_ID``, the last step at which the time step changed (the step the fix was defined
before any change).

Syntax::

    fix ID GROUP dt/reset N Tmin Tmax Xmax [units lattice|box]

N the interval (steps); Tmin, Tmax (time) or NULL; Xmax (distance) in lattice spacings along x unless
``units box``; the default is the dialect's: lattice in LAMMPS's and PDPS's, box in LIGGGHTS's (its
source; its manual says lattice).

Example::

    fix adapt all dt/reset 10 1.0e-5 0.01 0.1
    fix adapt all dt/reset 10 NULL 2.0 0.2 units box
"""

import math
from typing import Literal

from numba import njit
from pydantic import model_validator

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, observables, param

BIG = 1.0e20


@njit(cache=True)
def smallest_step(v, f, mass, mask, groupbit, nlocal, xmax, ftm2v):
    """The least Delta t_i over the group's owned particles (BIG when none moves or feels a force)."""
    least = BIG
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        inverse = 1.0 / mass[i]
        vsq = v[i, 0] ** 2 + v[i, 1] ** 2 + v[i, 2] ** 2
        fsq = f[i, 0] ** 2 + f[i, 1] ** 2 + f[i, 2] ** 2
        by_v = xmax / math.sqrt(vsq) if vsq > 0.0 else BIG
        by_f = math.sqrt(2.0 * xmax / (ftm2v * math.sqrt(fsq) * inverse)) if fsq > 0.0 else BIG
        dt = min(by_v, by_f)
        half = 0.5 * dt * dt * inverse * ftm2v
        dx = dt * v[i, 0] + half * f[i, 0]
        dy = dt * v[i, 1] + half * f[i, 1]
        dz = dt * v[i, 2] + half * f[i, 2]
        moved = math.sqrt(dx * dx + dy * dy + dz * dz)
        if moved > xmax:
            dt *= xmax / moved
        least = min(least, dt)
    return least


class FixDtReset(Fix):
    name = "dt/reset"
    usage = "fix ID GROUP dt/reset N Tmin Tmax Xmax [units lattice|box]"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        tmin: float | Literal["NULL"] = param(unit="time")
        tmax: float | Literal["NULL"] = param(unit="time")
        xmax: float = param(gt=0, unit="distance")
        units: Literal["box", "lattice"] | None = keyword(None)

        @model_validator(mode="after")
        def _bounds(self):
            for name in ("tmin", "tmax"):
                value = getattr(self, name)
                if value != "NULL" and value < 0.0:
                    raise ValueError(f"{name.capitalize()} must be >= 0 or NULL (got {value:g})")
            if "NULL" not in (self.tmin, self.tmax) and not self.tmin < self.tmax:
                raise ValueError(f"Tmin must be below Tmax (got {self.tmin:g} {self.tmax:g})")
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        units = args.units or sim.dialect.command_units
        spacing = float(sim.lattice.spacing[0]) if (units == "lattice" and sim.lattice is not None) else 1.0
        self.xmax = args.xmax * spacing
        self.tmin = None if args.tmin == "NULL" else args.tmin
        self.tmax = None if args.tmax == "NULL" else args.tmax
        self.last_change = sim.step
        self.warned = False

    def setup(self, sim):
        self._reset(sim)

    def end_of_step(self, sim):
        if sim.step % self.args.every == 0:
            self._reset(sim)

    def _reset(self, sim):
        p = sim.particles
        least = smallest_step(p.v, p.f, observables.masses(sim), p.mask, sim.groups.bit(self.group), p.nlocal,
                              self.xmax, sim.units.ftm2v)
        dt = float(sim.comm.min(least))
        if self.tmin is not None:
            dt = max(dt, self.tmin)
        if self.tmax is not None:
            dt = min(dt, self.tmax)
        if dt >= BIG:
            if not self.warned:
                self.warned = True
                sim.warn(f"fix {self.id} dt/reset: nothing in group {self.group} moves or feels a force and no "
                         f"Tmax is given: the time step stays {sim.dt:g} (step {sim.step})")
            return
        if dt == sim.dt:
            return
        if not dt > 0.0 or not math.isfinite(dt):
            raise ScriptError(f"fix {self.id} dt/reset: the new time step is {dt!r} at step {sim.step}")
        self.last_change = sim.step
        sim.change_timestep(dt)

    def scalar(self, sim):
        """The last step at which the time step changed."""
        return float(self.last_change)
