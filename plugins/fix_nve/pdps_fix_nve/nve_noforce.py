r"""Fix ``nve/noforce``: the group drifts at its velocities, whatever the forces (LAMMPS's and
LIGGGHTS's fix nve/noforce).

.. math::  \mathbf{x}(t+\Delta t) = \mathbf{x}(t) + \Delta t\,\mathbf{v}(t)

in ``initial_integrate``; velocities are left as they are (other fixes may set them: fix move, a
wall's prescribed velocity, velocity between runs). Forces are still computed on the particles
and act on their neighbours.

Syntax::

    fix ID GROUP nve/noforce

Example::

    fix 3 wall nve/noforce
"""

from numba import njit

from pdps_core.api import Fix


@njit(cache=True)
def drift(x, v, mask, groupbit, nlocal, dt):
    for i in range(nlocal):
        if mask[i] & groupbit:
            for d in range(3):
                x[i, d] += dt * v[i, d]


class FixNVENoforce(Fix):
    name = "nve/noforce"
    time_integrate = True
    usage = "fix ID GROUP nve/noforce"

    def initial_integrate(self, sim):
        a = sim.particles.arrays
        drift(a["x"], a["v"], a["mask"], sim.groups.bit(self.group), sim.particles.nlocal, sim.dt)
