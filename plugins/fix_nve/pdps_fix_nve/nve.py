r"""Fix ``nve``: velocity-Verlet integration of Newton's equations for a group (constant N, V, E).

.. math::

    \mathbf{v}(t+\tfrac{\Delta t}{2}) = \mathbf{v}(t) + \tfrac{\Delta t}{2m}\mathbf{F}(t), \quad
    \mathbf{x}(t+\Delta t) = \mathbf{x}(t) + \Delta t\,\mathbf{v}(t+\tfrac{\Delta t}{2}), \quad
    \mathbf{v}(t+\Delta t) = \mathbf{v}(t+\tfrac{\Delta t}{2}) + \tfrac{\Delta t}{2m}\mathbf{F}(t+\Delta t)

The first half-kick and the drift run in ``initial_integrate``, the second half-kick in
``final_integrate``, as LAMMPS's fix nve. Masses are the per-particle ``rmass`` when the particle style
has one, else the per-type mass.

Syntax::

    fix ID GROUP nve

Example::

    fix 1 all nve
"""

import numpy as np
from numba import njit

from pdps_core.api import Fix

NO_RMASS = np.zeros(0)


@njit(cache=True)
def nve_initial(x, v, f, type_, mass, rmass, mask, groupbit, nlocal, dt, ftm2v):
    """Half kick and drift; the mass is ``rmass[i]`` when given, else the type's."""
    half = 0.5 * dt * ftm2v
    with_rmass = len(rmass) > 0
    for i in range(nlocal):
        if mask[i] & groupbit:
            dtfm = half / (rmass[i] if with_rmass else mass[type_[i]])
            for d in range(3):
                v[i, d] += dtfm * f[i, d]
                x[i, d] += dt * v[i, d]


@njit(cache=True)
def nve_final(v, f, type_, mass, rmass, mask, groupbit, nlocal, dt, ftm2v):
    half = 0.5 * dt * ftm2v
    with_rmass = len(rmass) > 0
    for i in range(nlocal):
        if mask[i] & groupbit:
            dtfm = half / (rmass[i] if with_rmass else mass[type_[i]])
            for d in range(3):
                v[i, d] += dtfm * f[i, d]


class FixNVE(Fix):
    name = "nve"
    time_integrate = True
    usage = "fix ID GROUP nve"

    def initial_integrate(self, sim):
        a = sim.particles.arrays
        nve_initial(a["x"], a["v"], a["f"], a["type"], sim.mass, a.get("rmass", NO_RMASS), a["mask"],
                    sim.groups.bit(self.group), sim.particles.nlocal, sim.dt, sim.units.ftm2v)

    def final_integrate(self, sim):
        a = sim.particles.arrays
        nve_final(a["v"], a["f"], a["type"], sim.mass, a.get("rmass", NO_RMASS), a["mask"],
                  sim.groups.bit(self.group), sim.particles.nlocal, sim.dt, sim.units.ftm2v)
