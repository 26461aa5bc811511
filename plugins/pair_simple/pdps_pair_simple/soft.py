r"""Pair style ``soft``: a cosine bump, finite at r = 0, to push overlapping particles apart
(LAMMPS's ``pair_style soft``).

.. math::

    E(r) = A\left[1 + \cos\left(\frac{\pi r}{r_c}\right)\right], \qquad
    \mathbf{F}_{ij} = \frac{A\pi}{r_c}\sin\left(\frac{\pi r}{r_c}\right)\frac{\mathbf{r}_{ij}}{r},
    \qquad r < r_c

Parameters:

- ``pair_style soft RC``: ``RC`` global cutoff (> 0, distance).
- ``pair_coeff I J A [RC]``: ``A`` the prefactor (energy), ``RC`` this pair's cutoff (distance).

Unset i != j pairs mix as LAMMPS: A = sqrt(A_i A_j), the cutoff by ``pair_modify mix`` (geometric by
default). The energy is 0 at the cutoff, so ``pair_modify shift`` changes nothing. Coincident particles
feel no force (sin 0 = 0). ``fix adapt pair soft a I J v_NAME`` changes A in a run (LAMMPS's push-off
ramp). Example::

    pair_style soft 1.12246
    pair_coeff * * 10.0
"""

import math

from numba import njit
from pdps_core.api import PairLaw, StyleArgs, param

from .mixing import cutoff_of, mixed_cutoff


@njit(cache=True, inline="always")
def soft_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """coeff = (A, pi / rc)."""
    r = math.sqrt(rsq)
    arg = coeff[1] * r
    return coeff[0] * math.sin(arg) * coeff[1] / r, coeff[0] * (1.0 + math.cos(arg))


class PairSoft(PairLaw):
    name = "soft"
    usage = "pair_style soft RC"
    coeff_usage = "A [RC]"
    mix_default = "geometric"
    params = ("prefactor", "pi_over_cut")
    law = staticmethod(soft_law)
    adaptable = {"a": "prefactor"}

    class Args(StyleArgs):
        cutoff: float = param(gt=0, unit="distance")

    class Coeff(StyleArgs):
        prefactor: float = param(unit="energy")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def mix_coeff(self, ci, cj, rule):
        return self.Coeff(prefactor=math.sqrt(ci.prefactor * cj.prefactor), cutoff=mixed_cutoff(self, ci, cj, rule))

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        rc = cutoff_of(self, c)
        return rc, (c.prefactor, math.pi / rc)
