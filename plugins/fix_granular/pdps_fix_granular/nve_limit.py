r"""Fix ``nve/limit``: velocity Verlet with the displacement of each particle in one step capped,
for starts from heavily overlapping configurations (LAMMPS's and LIGGGHTS's fix nve/limit).

After each half-kick :math:`\mathbf{v} \mathrel{+}= \tfrac{\Delta t}{2m}\mathbf{F}` the velocity is
scaled back to the speed that moves the particle by at most :math:`x_{max}` in a step:

.. math::

    |\mathbf{v}| > v_{max} = x_{max}/\Delta t \;\Rightarrow\;
    \mathbf{v} \leftarrow \mathbf{v}\, v_{max}/|\mathbf{v}|, \qquad
    \mathbf{x} \mathrel{+}= \Delta t\,\mathbf{v}

so :math:`|\Delta\mathbf{x}| \le x_{max}` every step. With ``radius_ratio`` (LIGGGHTS) the cap of
each particle is :math:`x_{max} R_i`. Forces are left as they are; on steps where no cap acts this is
exactly fix nve, on steps where one acts energy is not conserved.

Spins are not integrated: spheres keep their angular velocity, as in LAMMPS's and LIGGGHTS's fix
nve/limit (LIGGGHTS 3.8.0's numbers recorded in plugins/fix_granular/tests/data/liggghts.cases.json,
case nve_limit); a scene that needs them turning uses nve/sphere once the overlaps are gone.

The number of capped velocity updates (each half-step, as LAMMPS's scalar of this fix) is
kept in ``count`` for the current run. The first step of a run on which the cap acts gives a
warning; when it stops acting, a line says on which steps and how often it did.

Parameters:

- ``absolute`` | ``radius_ratio`` (optional word, LIGGGHTS; default ``absolute``): whether
  :math:`x_{max}` is a distance or a multiple of each particle's radius.
- ``XMAX``: largest displacement per step (distance units, or radii), > 0.

Syntax::

    fix ID GROUP nve/limit [absolute|radius_ratio] XMAX

Examples::

    fix 1 all nve/limit 0.01
    fix 1 all nve/limit radius_ratio 0.05
"""

import math
from typing import Literal

from numba import njit
from pdps_core.api import Fix, StyleArgs, observables, param

from ._common import require_radii, require_spheres

LIMIT_STYLES = ("absolute", "radius_ratio")


@njit(cache=True)
def _cap(vector, i, limit):
    """Scale row i of ``vector`` down to length ``limit``; True when it had to be."""
    norm_sq = vector[i, 0] ** 2 + vector[i, 1] ** 2 + vector[i, 2] ** 2
    # a vector capped before may sit an ulp above the limit: that is not a new cap
    if norm_sq > limit * limit * (1.0 + 1e-12):
        scale = limit / math.sqrt(norm_sq)
        for d in range(3):
            vector[i, d] *= scale
        return True
    return False


@njit(cache=True)
def limited_kick(x, v, f, mass, radius, mask, groupbit, nlocal, dt, xmax, per_radius, drift, ftm2v):
    """Half-kick, cap |v| at xmax/dt (xmax * radius with ``per_radius``), then drift when asked.
    Returns how many velocities were capped."""
    half = 0.5 * dt * ftm2v
    capped = 0
    for i in range(nlocal):
        if mask[i] & groupbit:
            reach = xmax * radius[i] if per_radius else xmax
            dtfm = half / mass[i]
            for d in range(3):
                v[i, d] += dtfm * f[i, d]
            if _cap(v, i, reach / dt):
                capped += 1
            if drift:
                for d in range(3):
                    x[i, d] += dt * v[i, d]
    return capped


class FixNVELimit(Fix):
    name = "nve/limit"
    time_integrate = True
    usage = "fix ID GROUP nve/limit [absolute|radius_ratio] XMAX"

    class Args(StyleArgs):
        # LAMMPS writes "nve/limit XMAX", LIGGGHTS "nve/limit absolute|radius_ratio XMAX"
        limitstyle: Literal["absolute", "radius_ratio"] = param("absolute")
        xmax: float = param(gt=0, unit="distance")     # or radii, with radius_ratio

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.per_radius = args.limitstyle == "radius_ratio"
        if self.per_radius:
            require_spheres(sim, "fix nve/limit radius_ratio")
        self.count = 0
        self._capped_now = 0
        self._warned = False
        self._episode = None        # [first step, last step, capped updates] while the cap acts

    def setup(self, sim):
        if self.per_radius:
            require_radii(sim, self.group, "fix nve/limit")
        self.count = 0
        self._warned = False
        self._episode = None

    def _limit_text(self):
        return f"{self.args.xmax:g} radius" if self.per_radius else f"{self.args.xmax:g}"

    def _kick(self, sim, drift):
        p = sim.particles
        mass = observables.masses(sim)
        radius = p.radius if p.has("radius") else mass     # read only with radius_ratio
        groupbit = sim.groups.bit(self.group)
        capped = limited_kick(p.x, p.v, p.f, mass, radius, p.mask, groupbit, p.nlocal, sim.dt,
                              self.args.xmax, self.per_radius, drift, sim.units.ftm2v)
        return capped

    def initial_integrate(self, sim):
        self._capped_now = self._kick(sim, drift=True)

    def final_integrate(self, sim):
        capped = int(sim.comm.sum(self._capped_now + self._kick(sim, drift=False)))
        self.count += capped
        if capped:
            if self._episode is None:
                self._episode = [sim.step, sim.step, 0]
            self._episode[1] = sim.step
            self._episode[2] += capped
            if not self._warned:
                self._warned = True
                sim.warn(f"fix {self.id} (nve/limit): the displacement limit {self._limit_text()} "
                         f"acted on {capped} update(s) at step {sim.step}; energy is not conserved "
                         "while it acts")
        elif self._episode is not None:
            first, last, total = self._episode
            self._episode = None
            sim.info(f"fix {self.id} (nve/limit): the displacement limit "
                     f"{self._limit_text()} acted {total} time(s) on steps {first} to {last}")
