r"""Fix ``viscous``: a damping force proportional to each particle's velocity (LAMMPS's and
LIGGGHTS's fix viscous), e.g. to drain kinetic energy from a granular packing.

.. math::  \mathbf{F}_i \mathrel{-}= \gamma\, \mathbf{v}_i

A free particle of mass :math:`m` slows down as :math:`\mathbf{v}(t) = \mathbf{v}_0 e^{-\gamma t/m}`;
with velocity Verlet the force is taken from the half-step velocity, so the decay per step is
:math:`1 - \gamma\Delta t/m` (first order in :math:`\gamma\Delta t/m`, stable for
:math:`\gamma\Delta t/m < 2`). For Stokes drag on a sphere of diameter d in a fluid of viscosity
:math:`\eta`, :math:`\gamma = 3\pi\eta d` (or use ``fix addforce drag_stokes``, which takes each
particle's radius). Applied in ``post_force`` and at setup.

Parameters:

- ``GAMMA``: damping coefficient (force/velocity units), >= 0.

LAMMPS's ``scale TYPE RATIO`` keyword is not supported.

Syntax::

    fix ID GROUP viscous GAMMA

Example::

    fix damp all viscous 0.5
"""

from pdps_core.api import Fix, StyleArgs, param

from ._common import chosen


class FixViscous(Fix):
    name = "viscous"
    usage = "fix ID GROUP viscous GAMMA"

    class Args(StyleArgs):
        gamma: float = param(ge=0, unit="force/velocity")

    def setup(self, sim):
        self.post_force(sim)

    def min_post_force(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        selected = chosen(sim, self.group)
        p.f[: p.nlocal][selected] -= self.args.gamma * p.v[: p.nlocal][selected]
