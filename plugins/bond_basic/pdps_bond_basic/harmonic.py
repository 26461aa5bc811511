r"""Bond style ``harmonic``: a spring between two bonded particles (LAMMPS's ``bond_style harmonic``).

.. math::

    E(r) = K (r - r_0)^2, \qquad \mathbf{F}_1 = -2K\,\frac{r - r_0}{r}\,\mathbf{r}_{12}

with r the bond's length and r_12 = r_1 - r_2; the usual factor 1/2 is in K, as in LAMMPS.

Parameters:

- ``bond_style harmonic`` (no arguments).
- ``bond_coeff N K R0``: ``K`` the stiffness (energy/distance^2), ``R0`` the equilibrium length
  (distance).

A bond of zero length has no direction and no force. Example::

    bond_style harmonic
    bond_coeff 1 100.0 1.1
"""

import math

from numba import njit
from pdps_core.api import Bond, StyleArgs, param


@njit(cache=True, inline="always")
def harmonic_law(rsq, coeff):
    """coeff = (K, r0)."""
    r = math.sqrt(rsq)
    dr = r - coeff[1]
    fbond = -2.0 * coeff[0] * dr / r if r > 0.0 else 0.0
    return fbond, coeff[0] * dr * dr


class BondHarmonic(Bond):
    name = "harmonic"
    usage = "bond_style harmonic"
    coeff_usage = "K R0"
    params = ("stiffness", "r0")
    law = staticmethod(harmonic_law)

    class Coeff(StyleArgs):
        stiffness: float = param(ge=0, unit="energy/area")
        r0: float = param(ge=0, unit="distance")
