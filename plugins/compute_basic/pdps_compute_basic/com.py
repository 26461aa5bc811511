r"""Compute ``com``: the centre of mass of a group, a vector ``c_ID[0]``, ``c_ID[1]``, ``c_ID[2]``.

.. math::

    \mathbf{x}_\mathrm{cm} = \frac{\sum_{i \in G} m_i\, \mathbf{x}^u_i}{\sum_{i \in G} m_i},
    \qquad \mathbf{x}^u_i = \mathbf{x}_i + \mathbf{n}_i L

with :math:`\mathbf{x}^u` the positions unwrapped through periodic images (image counts
:math:`\mathbf{n}_i`, box lengths L), so a group drifting across a periodic face moves its centre of
mass smoothly (LAMMPS's compute com). Distance units; indices 0-based. An empty group gives 0.
``compute centroid`` (pack compute_thermo) is the same without the masses.

Syntax::

    compute ID GROUP com

Example::

    compute cm grains com
    thermo_style custom step c_cm[2]
"""

import numpy as np

from pdps_core.api import Compute, observables

from .peratom import unwrapped


def centre_of_mass(sim, group):
    """The group's unwrapped centre of mass over every rank (0 for an empty group)."""
    chosen = sim.groups.select(sim, group)
    mass = observables.masses(sim, chosen)
    moment = sim.comm.sum(mass @ unwrapped(sim)[chosen])
    total = sim.comm.sum(float(mass.sum()))
    return np.asarray(moment, dtype=np.float64) / total if total > 0 else np.zeros(3)


class ComputeCOM(Compute):
    name = "com"
    usage = "compute ID GROUP com"

    def vector(self, sim):
        return centre_of_mass(sim, self.group)
