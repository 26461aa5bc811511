r"""Fix ``spring/rg``: a spring on the radius of gyration of a group, pulling it towards
:math:`R_{g0}` (LAMMPS's and LIGGGHTS's fix spring/rg).

.. math::

    \mathbf{F}_i = -2K\left(1 - \frac{R_{g0}}{R_g}\right)\frac{m_i}{M}\,(\mathbf{x}_i - \mathbf{x}_{cm}),
    \qquad R_g^2 = \frac{1}{M}\sum_i m_i |\mathbf{x}_i - \mathbf{x}_{cm}|^2

over the group's particles (unwrapped positions, M their mass), added every step in
``post_force`` and at setup. ``K`` in energy/distance^2 (energy/area); ``RG0`` a distance, or ``NULL`` for the
group's radius of gyration when the first run starts. LIGGGHTS 3.8.0 weighs each particle by its
type's mass, which granular spheres do not have (their masses are per particle), so it pulls them
with no force; pdps takes each particle's own mass, as LAMMPS does (LIGGGHTS's numbers for point
particles recorded in plugins/compute_basic/tests/data/liggghts.cases.json, case spring_rg).

Syntax::

    fix ID GROUP spring/rg K RG0|NULL

Example::

    fix squeeze polymer spring/rg 5.0 1.0
"""

from typing import Literal

import numpy as np

from pdps_core.api import Fix, StyleArgs, observables, param

from .com import centre_of_mass
from .peratom import unwrapped


class FixSpringRG(Fix):
    name = "spring/rg"
    usage = "fix ID GROUP spring/rg K RG0|NULL"

    class Args(StyleArgs):
        k: float = param(unit="energy/area")
        rg0: Literal["NULL"] | float = param(unit="distance")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.rg0 = None if args.rg0 == "NULL" else float(args.rg0)

    def _pull(self, sim, apply):
        chosen = sim.groups.select(sim, self.group)
        mass = np.asarray(observables.masses(sim, chosen), dtype=np.float64)
        total = float(sim.comm.sum(float(mass.sum())))
        if total <= 0:
            return None
        centre = centre_of_mass(sim, self.group)
        delta = unwrapped(sim)[chosen] - centre
        rg = float(np.sqrt(sim.comm.sum(float(mass @ (delta * delta).sum(axis=1))) / total))
        if apply and rg > 0:
            p = sim.particles
            f = p.f[: p.nlocal]
            f[chosen] -= 2.0 * self.args.k * (1.0 - self.rg0 / rg) * (mass / total)[:, None] * delta
        return rg

    def setup(self, sim):
        if self.rg0 is None:
            self.rg0 = self._pull(sim, apply=False) or 0.0
        self._pull(sim, apply=True)

    def post_force(self, sim):
        self._pull(sim, apply=True)
