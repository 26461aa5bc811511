r"""Compute ``msd/nongauss``: the mean squared displacement of a group, its mean fourth power and the
non-Gaussian parameter, a vector of 3 (LAMMPS's and LIGGGHTS's compute msd/nongauss).

.. math::

    \langle r^2\rangle = \frac1N\sum_{i \in G} |\Delta\mathbf{x}_i|^2, \qquad
    \langle r^4\rangle = \frac1N\sum_{i \in G} |\Delta\mathbf{x}_i|^4, \qquad
    \alpha_2 = \frac{3\langle r^4\rangle}{5\langle r^2\rangle^2} - 1

with :math:`\Delta\mathbf{x}_i` each particle's unwrapped displacement since the compute was defined
(relative to the centre of mass with ``com yes``), kept as compute msd keeps it. ``c_ID[1]``
``c_ID[2]`` ``c_ID[3]`` (``[0]`` .. ``[2]`` in the PDPS dialect) are distance², distance⁴ and
dimensionless; :math:`\alpha_2` is 0 for Gaussian displacements, and 0 (LAMMPS: -nan) while no
particle has moved. An empty group gives 0.

Syntax::

    compute ID GROUP msd/nongauss [com yes|no]

Example::

    compute ng all msd/nongauss
    thermo_style custom step c_ng[3]
"""

from typing import Literal

import numpy as np

from pdps_core.api import StyleArgs, keyword

from .msd import ComputeMSD
from .peratom import unwrapped


class ComputeMSDNonGauss(ComputeMSD):
    name = "msd/nongauss"
    usage = "compute ID GROUP msd/nongauss [com yes|no]"
    origin_prefix = "msd_nongauss_origin"

    class Args(StyleArgs):
        com: Literal["yes", "no"] = keyword("no")
        average: Literal["no"] = keyword("no")      # compute msd's keyword, not LAMMPS's here

    def vector(self, sim):
        here = unwrapped(sim) - self._centre(sim)
        origin = self.origins(sim, here)
        chosen = sim.groups.select(sim, self.group)
        squares = ((here[chosen] - origin[chosen]) ** 2).sum(axis=1)
        sums = np.asarray(sim.comm.sum(np.array([squares.sum(), (squares * squares).sum(),
                                                  float(chosen.sum())])), dtype=np.float64)
        if sums[2] == 0:
            return np.zeros(3)
        r2, r4 = sums[0] / sums[2], sums[1] / sums[2]
        # no displacement yet (the step of the definition): LAMMPS prints 0/0 as -nan, pdps 0
        return np.array([r2, r4, 3 * r4 / (5 * r2 * r2) - 1 if r2 > 0 else 0.0])
