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
- ``scale TYPE RATIO`` (repeatable): particles of TYPE are damped with GAMMA * RATIO (LAMMPS's
  keyword; a 200-particle LJ fluid under ``viscous 0.8 scale 2 2.5`` gives LAMMPS's thermo,
  plugins/fix_simple/tests/test_lammps_fixes.py).

Syntax::

    fix ID GROUP viscous GAMMA [scale TYPE RATIO]...

Example::

    fix damp all viscous 0.5
"""

import numpy as np

from pdps_core.api import ScriptError, StyleArgs, keyword, param

from ._common import ForceFix, chosen


class FixViscous(ForceFix):
    name = "viscous"
    usage = "fix ID GROUP viscous GAMMA [scale TYPE RATIO]..."

    class Args(StyleArgs):
        gamma: float = param(ge=0, unit="force/velocity")
        scale: list[tuple[int, float]] = keyword(default_factory=list, unit="dimensionless")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.gamma = np.full(sim.ntypes + 1, args.gamma)
        for ptype, ratio in args.scale:
            if not 1 <= ptype <= sim.ntypes:
                raise ScriptError(f"scale: type {ptype} is out of range 1..{sim.ntypes}")
            if not ratio >= 0:
                raise ScriptError(f"scale: ratio must be >= 0 (got {ratio:g})")
            self.gamma[ptype] = args.gamma * ratio

    def post_force(self, sim):
        p = sim.particles
        selected = chosen(sim, self.group)
        n = p.nlocal
        p.f[:n][selected] -= self.gamma[p.type[:n][selected], None] * p.v[:n][selected]
