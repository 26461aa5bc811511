r"""Compute ``ke``: the kinetic energy of a group, a scalar ``c_ID``, and per particle.

.. math::

    KE = \sum_{i \in G} \tfrac12 m_i v_i^2, \qquad ke_i = \tfrac12 m_i v_i^2

in energy units (times ``mvv2e`` of the unit system), as LAMMPS's compute ke and ke/atom. The
spheres of rigid clumps (fix multisphere) are left out, each clump's body counted once,
:math:`\tfrac12 M V^2`, whatever the group (LIGGGHTS's compute ke): the total,
with the centre-of-mass motion included. Like LAMMPS, thermo prints it divided by the number of
particles when it normalises energies (lj units); a variable reads the total. The per-atom value (``dump custom ... c_ID``, ``compute reduce ... c_ID``) is 0
for particles outside the group.

Syntax::

    compute ID GROUP ke

Example::

    compute k all ke
    thermo_style custom step c_k
    dump 1 all custom 100 ke.dump id c_k
"""

import numpy as np

from pdps_core.api import Compute, observables


class ComputeKE(Compute):
    name = "ke"
    usage = "compute ID GROUP ke"
    extensive = True

    def scalar(self, sim):
        return observables.kinetic_energy_with_clumps(sim, self.group)

    def peratom(self, sim):
        p = sim.particles
        v = p.v[: p.nlocal]
        chosen = sim.groups.select(sim, self.group)
        energy = 0.5 * observables.masses(sim) * np.einsum("ij,ij->i", v, v) * sim.units.mvv2e
        return np.where(chosen, energy, 0.0)
