r"""Compute ``erotate/sphere``: the rotational kinetic energy of a group of spheres (LAMMPS's compute
erotate/sphere).

.. math::

    E_\mathrm{rot} = \sum_{i \in G} \tfrac12 I_i \omega_i^2, \qquad I_i = \tfrac25 m_i r_i^2

in energy units (times ``mvv2e``). Needs ``particle_style sphere`` (radius, rmass, omega). Extensive:
thermo prints it divided by the particle count when it normalises energies (lj units). Syntax::

    compute ID GROUP erotate/sphere

Example::

    compute rot all erotate/sphere
    thermo_style custom step ke c_rot
"""

import numpy as np

from pdps_core.api import Compute, ScriptError, observables

INERTIA = 0.4   # solid sphere


class ComputeERotateSphere(Compute):
    name = "erotate/sphere"
    usage = "compute ID GROUP erotate/sphere"
    extensive = True

    def __init__(self, sim, id, group, args):
        if "sphere" not in sim.particle_styles:
            raise ScriptError("compute erotate/sphere needs particle_style sphere (radius, rmass, omega)")
        super().__init__(sim, id, group, args)

    def scalar(self, sim):
        p = sim.particles
        n = p.nlocal
        w = p.omega[:n]
        chosen = observables.outside_clumps(sim, sim.groups.select(sim, self.group))
        local = float(np.sum(((w[:, 0] * w[:, 0] + w[:, 1] * w[:, 1] + w[:, 2] * w[:, 2])
                              * p.radius[:n] * p.radius[:n] * p.rmass[:n])[chosen]))
        return sim.comm.sum(local) * (0.5 * sim.units.mvv2e * INERTIA)


class ComputeERotate(ComputeERotateSphere):
    """Compute ``erotate`` (LIGGGHTS): the rotational kinetic energy of all particles, the sum of its
    child computes for spheres, superquadrics and multisphere bodies; pdps's particles are spheres,
    so it is erotate/sphere's (LIGGGHTS 3.8.0 prints the two alike on spheres, measured 12-02)::

        compute ID GROUP erotate
    """
    name = "erotate"
    usage = "compute ID GROUP erotate"

    def scalar(self, sim):
        return super().scalar(sim) + observables.clump_energies(sim)[1]
