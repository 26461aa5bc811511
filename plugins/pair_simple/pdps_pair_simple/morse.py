r"""Pair style ``morse``: the Morse potential (P. M. Morse, Phys. Rev. 34, 57 (1929); LAMMPS's
``pair_style morse``).

.. math::

    E(r) = D_0\left[e^{-2\alpha(r - r_0)} - 2e^{-\alpha(r - r_0)}\right] - E_\mathrm{shift},
    \qquad \mathbf{F}_{ij} = 2\alpha D_0\left[e^{-2\alpha(r - r_0)} - e^{-\alpha(r - r_0)}\right]
    \frac{\mathbf{r}_{ij}}{r}, \qquad r < r_c

:math:`E_\mathrm{shift}` = E(r_c) with ``pair_modify shift yes``, else 0.

Parameters:

- ``pair_style morse RC``: ``RC`` global cutoff (> 0, distance).
- ``pair_coeff I J D0 ALPHA R0 [RC]``: ``D0`` well depth (energy), ``ALPHA`` stiffness (1/distance),
  ``R0`` equilibrium distance (distance), ``RC`` this pair's cutoff.

As in LAMMPS there is no mixing: every type pair needs its pair_coeff. Example::

    pair_style morse 2.5
    pair_coeff * * 1.0 5.0 1.12
"""

import math

from numba import njit
from pdps_core.api import PairLaw, StyleArgs, param

from .mixing import cutoff_of


@njit(cache=True, inline="always")
def morse_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """coeff = (D0, alpha, r0, 2 alpha D0, E_shift)."""
    r = math.sqrt(rsq)
    dexp = math.exp(-coeff[1] * (r - coeff[2]))
    return coeff[3] * (dexp * dexp - dexp) / r, coeff[0] * (dexp * dexp - 2.0 * dexp) - coeff[4]


class PairMorse(PairLaw):
    name = "morse"
    usage = "pair_style morse RC"
    coeff_usage = "D0 ALPHA R0 [RC]"
    params = ("d0", "alpha", "r0", "morse1", "offset")
    law = staticmethod(morse_law)

    class Args(StyleArgs):
        cutoff: float = param(gt=0, unit="distance")

    class Coeff(StyleArgs):
        d0: float = param(unit="energy")
        alpha: float = param(unit="1/distance")
        r0: float = param(unit="distance")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        rc = cutoff_of(self, c)
        offset = 0.0
        if self.shift:
            alpha_dr = -c.alpha * (rc - c.r0)
            offset = c.d0 * (math.exp(2.0 * alpha_dr) - 2.0 * math.exp(alpha_dr))
        return rc, (c.d0, c.alpha, c.r0, 2.0 * c.d0 * c.alpha, offset)
