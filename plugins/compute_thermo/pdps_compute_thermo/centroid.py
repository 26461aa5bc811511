r"""Compute ``centroid``: the geometric centre of a group, a vector ``c_ID[0]``, ``c_ID[1]``, ``c_ID[2]``.

.. math::

    \mathbf{x}_c = \frac{1}{N}\sum_{i=1}^{N} \mathbf{x}_i

Positions are unwrapped through periodic boundaries (x + image * L), so a group drifting across a
periodic face moves its centroid smoothly, as LAMMPS's compute com does. Indices are 0-based as in
the PDPS manual.

Syntax::

    compute ID GROUP centroid

Example::

    compute 5 all centroid
    thermo_style custom step c_5[0] c_5[1] c_5[2]
"""

import numpy as np

from pdps_core.api import Compute, observables


class ComputeCentroid(Compute):
    name = "centroid"
    usage = "compute ID GROUP centroid"

    def vector(self, sim):
        p = sim.particles
        chosen = sim.groups.select(sim, self.group)
        n = p.nlocal
        unwrapped = p.x[:n][chosen] + p.image[:n][chosen] * sim.box.length
        total = sim.comm.sum(unwrapped.sum(axis=0))
        count = observables.count(sim, self.group)
        return np.asarray(total) / count if count else np.zeros(3)
