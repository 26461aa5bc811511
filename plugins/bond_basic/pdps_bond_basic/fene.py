r"""Bond style ``fene``: the finitely extensible nonlinear elastic bond of bead-spring polymers, an
attractive log spring plus the repulsive WCA core (Kremer and Grest, J. Chem. Phys. 92, 5057
(1990); LAMMPS's ``bond_style fene``).

.. math::

    E(r) = -\tfrac12 K R_0^2 \ln\left[1 - \left(\frac{r}{R_0}\right)^2\right]
           + 4\epsilon\left[\left(\frac{\sigma}{r}\right)^{12} - \left(\frac{\sigma}{r}\right)^{6}\right]
           + \epsilon

with the second term only for :math:`r < 2^{1/6}\sigma`. The log spring is defined only below R0:
a bond longer than :math:`\sqrt{0.9}\,R_0` (where :math:`1 - (r/R_0)^2` falls below 0.1) is warned of
and its spring taken at that value, 0.1, as LAMMPS does; one longer than 2 R0 (the value -3 or less,
LAMMPS's "Bad FENE bond") stops the run.

Parameters:

- ``bond_style fene`` (no arguments).
- ``bond_coeff N K R0 epsilon sigma``: ``K`` the spring's stiffness (energy/distance^2), ``R0`` its
  largest extension (distance), ``epsilon`` (energy) and ``sigma`` (distance) the core's LJ
  parameters.

Use ``special_bonds fene`` (0 1 1) with it, as the Kremer-Grest model does. Example::

    bond_style fene
    bond_coeff 1 30.0 1.5 1.0 1.0
"""

import math

from numba import njit
from pdps_core.api import Bond, StyleArgs, param

TWO_1_3 = 2.0 ** (1.0 / 3.0)


@njit(cache=True, inline="always")
def fene_law(rsq, coeff):
    """coeff = (K, R0, epsilon, sigma)."""
    k, r0, epsilon, sigma = coeff[0], coeff[1], coeff[2], coeff[3]
    r0sq = r0 * r0
    rlogarg = 1.0 - rsq / r0sq
    # beyond sqrt(0.9) R0 the spring is held at its value there (the core warns), as LAMMPS's
    if rlogarg < 0.1:
        rlogarg = 0.1
    fbond = -k / rlogarg
    energy = -0.5 * k * r0sq * math.log(rlogarg)
    if rsq < TWO_1_3 * sigma * sigma:
        sr2 = sigma * sigma / rsq
        sr6 = sr2 * sr2 * sr2
        fbond += 48.0 * epsilon * sr6 * (sr6 - 0.5) / rsq
        energy += 4.0 * epsilon * sr6 * (sr6 - 1.0) + epsilon
    return fbond, energy


class BondFENE(Bond):
    name = "fene"
    usage = "bond_style fene"
    coeff_usage = "K R0 epsilon sigma"
    params = ("stiffness", "r0", "epsilon", "sigma")
    law = staticmethod(fene_law)
    stretch_warning = "sqrt(0.9) R0 (their springs are taken at that length, as LAMMPS's)"
    stretch_failure = "2 R0, where the FENE spring is undefined (LAMMPS's Bad FENE bond)"

    class Coeff(StyleArgs):
        stiffness: float = param(ge=0, unit="energy/area")
        r0: float = param(gt=0, unit="distance")
        epsilon: float = param(ge=0, unit="energy")
        sigma: float = param(gt=0, unit="distance")

    def stretch_limits(self, coeff):
        return math.sqrt(0.9) * coeff.r0, 2.0 * coeff.r0

    def equilibrium_distance(self, coeff):
        """LAMMPS's: 0.97 sigma (the spring and core balance near there for the usual K, R0)."""
        return 0.97 * coeff.sigma
