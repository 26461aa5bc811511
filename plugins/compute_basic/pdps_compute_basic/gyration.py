r"""Compute ``gyration``: the radius of gyration of a group and its gyration tensor (LAMMPS's and
LIGGGHTS's compute gyration).

.. math::

    R_g = \sqrt{\frac{1}{M}\sum_{i \in G} m_i\,|\mathbf{x}^u_i - \mathbf{x}_\mathrm{cm}|^2}, \qquad
    T_{ab} = \frac{1}{M}\sum_{i \in G} m_i\,(x^u_{i,a} - x_{\mathrm{cm},a})(x^u_{i,b} - x_{\mathrm{cm},b})

with M the group's mass, :math:`\mathbf{x}^u` positions unwrapped through periodic images and
:math:`\mathbf{x}_\mathrm{cm}` the group's centre of mass (as compute com). The scalar is
:math:`R_g` (distance); the vector the six components xx, yy, zz, xy, xz, yz of T (distance², in
that order: ``c_ID[1]`` .. ``c_ID[6]``, ``[0]`` .. ``[5]`` in the PDPS dialect). An empty group
gives 0.

Syntax::

    compute ID GROUP gyration

Example::

    compute rg polymer gyration
    thermo_style custom step c_rg c_rg[1]
"""

import numpy as np

from pdps_core.api import Compute, observables

from .com import centre_of_mass
from .peratom import unwrapped

PAIRS = ((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))


class ComputeGyration(Compute):
    name = "gyration"
    usage = "compute ID GROUP gyration"

    def _moments(self, sim):
        """(sum m |dx|^2, the six sums m dx_a dx_b, M) over ranks."""
        chosen = sim.groups.select(sim, self.group)
        mass = observables.masses(sim, chosen)
        centre = centre_of_mass(sim, self.group)
        delta = unwrapped(sim)[chosen] - centre
        sums = np.array([mass @ (delta[:, a] * delta[:, b]) for a, b in PAIRS] + [float(mass.sum())])
        return np.asarray(sim.comm.sum(sums), dtype=np.float64)

    def scalar(self, sim):
        sums = self._moments(sim)
        return float(np.sqrt(sums[:3].sum() / sums[6])) if sums[6] > 0 else 0.0

    def vector(self, sim):
        sums = self._moments(sim)
        return sums[:6] / sums[6] if sums[6] > 0 else np.zeros(6)
