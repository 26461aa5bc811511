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

from numba import njit

from pdps_core.api import Fix, observables


@njit(cache=True)
def nve_initial(x, v, f, mass, mask, groupbit, nlocal, dt, ftm2v):
    half = 0.5 * dt * ftm2v
    for i in range(nlocal):
        if mask[i] & groupbit:
            dtfm = half / mass[i]
            for d in range(3):
                v[i, d] += dtfm * f[i, d]
                x[i, d] += dt * v[i, d]


@njit(cache=True)
def nve_final(v, f, mass, mask, groupbit, nlocal, dt, ftm2v):
    half = 0.5 * dt * ftm2v
    for i in range(nlocal):
        if mask[i] & groupbit:
            dtfm = half / mass[i]
            for d in range(3):
                v[i, d] += dtfm * f[i, d]


class FixNVE(Fix):
    name = "nve"
    usage = "fix ID GROUP nve"

    def initial_integrate(self, sim):
        p = sim.particles
        nve_initial(p.x, p.v, p.f, observables.masses(sim), p.mask, sim.groups.bit(self.group),
                    p.nlocal, sim.dt, sim.units.ftm2v)

    def final_integrate(self, sim):
        p = sim.particles
        nve_final(p.v, p.f, observables.masses(sim), p.mask, sim.groups.bit(self.group),
                  p.nlocal, sim.dt, sim.units.ftm2v)
