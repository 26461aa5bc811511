r"""Compute ``ke/atom``: the kinetic energy of each particle (LAMMPS's compute ke/atom).

.. math::

    ke_i = \tfrac12 m_i v_i^2

in energy units (times ``mvv2e``); 0 for particles outside the group. Syntax::

    compute ID GROUP ke/atom

Example::

    compute k all ke/atom
    dump 1 all custom 100 ke.dump id c_k
"""

import numpy as np

from pdps_core.api import Compute, observables


class ComputeKEAtom(Compute):
    name = "ke/atom"
    usage = "compute ID GROUP ke/atom"

    def peratom(self, sim):
        n = sim.particles.nlocal
        v = sim.particles.v[:n]
        energy = 0.5 * sim.units.mvv2e * observables.masses(sim) * (v[:, 0] * v[:, 0] + v[:, 1] * v[:, 1]
                                                                    + v[:, 2] * v[:, 2])
        return np.where(observables.outside_clumps(sim, sim.groups.select(sim, self.group)), energy, 0.0)
