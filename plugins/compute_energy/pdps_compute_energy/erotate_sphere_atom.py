r"""Compute ``erotate/sphere/atom``: the rotational kinetic energy of each sphere (LAMMPS's and
LIGGGHTS's compute erotate/sphere/atom).

.. math::

    e_i = \tfrac12 I_i \omega_i^2, \qquad I_i = \tfrac25 m_i r_i^2

in energy units (times ``mvv2e``); 0 for particles outside the group. Needs ``particle_style
sphere`` (radius, rmass, omega). Syntax::

    compute ID GROUP erotate/sphere/atom

Example::

    compute erot all erotate/sphere/atom
    dump 1 all custom 100 spin.dump id c_erot
"""

import numpy as np

from pdps_core.api import Compute, ScriptError, observables

from .erotate_sphere import INERTIA


class ComputeERotateSphereAtom(Compute):
    name = "erotate/sphere/atom"
    usage = "compute ID GROUP erotate/sphere/atom"

    def __init__(self, sim, id, group, args):
        if "sphere" not in sim.particle_styles:
            raise ScriptError("compute erotate/sphere/atom needs particle_style sphere (radius, rmass, omega)")
        super().__init__(sim, id, group, args)

    def peratom(self, sim):
        p = sim.particles
        n = p.nlocal
        w, r = p.omega[:n], p.radius[:n]
        # LAMMPS's order of operations: (w.w) r r m, then times 0.5 mvv2e INERTIA
        energy = (w[:, 0] * w[:, 0] + w[:, 1] * w[:, 1] + w[:, 2] * w[:, 2]) * r * r * p.rmass[:n]
        energy *= 0.5 * sim.units.mvv2e * INERTIA
        return np.where(observables.outside_clumps(sim, sim.groups.select(sim, self.group)), energy, 0.0)
