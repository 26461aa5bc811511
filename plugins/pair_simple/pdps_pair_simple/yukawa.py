r"""Pair style ``yukawa``: a screened Coulomb interaction (LAMMPS's ``pair_style yukawa``).

.. math::

    E(r) = A\frac{e^{-\kappa r}}{r} - E_\mathrm{shift}, \qquad
    \mathbf{F}_{ij} = A e^{-\kappa r}\left(\kappa + \frac{1}{r}\right)\frac{\mathbf{r}_{ij}}{r^2},
    \qquad r < r_c

:math:`E_\mathrm{shift}` = E(r_c) with ``pair_modify shift yes``, else 0.

Parameters:

- ``pair_style yukawa KAPPA RC``: ``KAPPA`` the screening length's inverse (1/distance), ``RC`` the
  global cutoff (> 0, distance).
- ``pair_coeff I J A [RC]``: ``A`` the prefactor (energy*distance), ``RC`` this pair's cutoff.

Unset i != j pairs mix as LAMMPS: A = sqrt(A_i A_j), the cutoff by ``pair_modify mix`` (geometric by
default). Example::

    pair_style yukawa 2.0 2.5
    pair_coeff * * 100.0
"""

import math

from numba import njit
from pdps_core.api import PairLaw, StyleArgs, param

from .mixing import cutoff_of, mixed_cutoff


@njit(cache=True, inline="always")
def yukawa_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """coeff = (A, kappa, E_shift)."""
    r2inv = 1.0 / rsq
    r = math.sqrt(rsq)
    rinv = 1.0 / r
    screening = math.exp(-coeff[1] * r)
    return coeff[0] * screening * (coeff[1] + rinv) * r2inv, coeff[0] * screening * rinv - coeff[2]


class PairYukawa(PairLaw):
    name = "yukawa"
    usage = "pair_style yukawa KAPPA RC"
    coeff_usage = "A [RC]"
    mix_default = "geometric"
    params = ("a", "kappa", "offset")
    law = staticmethod(yukawa_law)

    class Args(StyleArgs):
        kappa: float = param(unit="1/distance")
        cutoff: float = param(gt=0, unit="distance")

    class Coeff(StyleArgs):
        a: float = param(unit="energy*distance")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def mix_coeff(self, ci, cj, rule):
        return self.Coeff(a=math.sqrt(ci.a * cj.a), cutoff=mixed_cutoff(self, ci, cj, rule))

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        rc = cutoff_of(self, c)
        kappa = self.args.kappa
        offset = c.a * math.exp(-kappa * rc) / rc if self.shift else 0.0
        return rc, (c.a, kappa, offset)
