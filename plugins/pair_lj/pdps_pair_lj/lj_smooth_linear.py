r"""Pair style ``lj/smooth/linear`` (alias ``lj/sf``): the shifted-force 12-6 Lennard-Jones potential,
whose energy and force both go to zero at the cutoff :math:`r_c` (Toxvaerd & Dyre, J. Chem. Phys.
134, 081102 (2011); LAMMPS's ``pair_style lj/smooth/linear``).

.. math::

    \phi(r) = 4\varepsilon\left[\left(\frac{\sigma}{r}\right)^{12} - \left(\frac{\sigma}{r}\right)^{6}\right],
    \qquad
    E(r) = \phi(r) - \phi(r_c) - (r - r_c)\,\phi'(r_c), \qquad r < r_c

    \mathbf{F}_{ij} = \left[-\phi'(r) + \phi'(r_c)\right]\frac{\mathbf{r}_{ij}}{r}

The potential is already zero at the cutoff, so ``pair_modify shift`` changes nothing (as in LAMMPS),
and the style has no tail correction (``pair_modify tail yes`` is refused).

Parameters:

- ``pair_style lj/smooth/linear RC`` (or ``lj/sf RC``): ``RC`` global cutoff (> 0, distance).
- ``pair_coeff I J EPSILON SIGMA [RC]``: ``EPSILON`` well depth (energy), ``SIGMA`` the zero of the
  unshifted potential (> 0, distance), ``RC`` this pair's cutoff (> 0, distance; default the global one).

Unset i != j pairs are mixed from the i i and j j coefficients as LAMMPS mixes them: geometric by
default (:math:`\varepsilon_{ij} = \sqrt{\varepsilon_i\varepsilon_j}`, :math:`\sigma_{ij} = \sqrt{\sigma_i\sigma_j}`,
:math:`r_{c,ij} = \sqrt{r_{c,i} r_{c,j}}`), ``pair_modify mix arithmetic`` or ``sixthpower`` as for
``lj/cut``.

Example (LAMMPS's KAPPA/in.heat family)::

    pair_style lj/sf 2.5
    pair_coeff 1 1 1.0 1.0 2.5
"""

import math

from numba import njit
from pdps_core.api import PairLaw

from .lj_cut import PairLJCut


@njit(cache=True, inline="always")
def lj_sf_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """coeff = (48 eps sigma^12, 24 eps sigma^6, 4 eps sigma^12, 4 eps sigma^6, phi(rc), -phi'(rc), rc)."""
    r2inv = 1.0 / rsq
    r6inv = r2inv * r2inv * r2inv
    rinv = math.sqrt(r2inv)
    force_r = rinv * r6inv * (coeff[0] * r6inv - coeff[1]) - coeff[5]
    energy = r6inv * (coeff[2] * r6inv - coeff[3]) - coeff[4] + (1.0 / rinv - coeff[6]) * coeff[5]
    return force_r * rinv, energy


class PairLJSmoothLinear(PairLaw):
    name = "lj/smooth/linear"
    usage = "pair_style lj/smooth/linear RC"
    coeff_usage = "EPSILON SIGMA [RC]"
    mix_default = "geometric"
    params = ("lj1", "lj2", "lj3", "lj4", "ljcut", "dljcut", "cut")
    law = staticmethod(lj_sf_law)
    masked = True

    Args = PairLJCut.Args
    Coeff = PairLJCut.Coeff
    mix_coeff = PairLJCut.mix_coeff

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        rc = c.cutoff if c.cutoff is not None else self.args.cutoff
        s6 = c.sigma ** 6
        lj1, lj2 = 48.0 * c.epsilon * s6 * s6, 24.0 * c.epsilon * s6
        lj3, lj4 = 4.0 * c.epsilon * s6 * s6, 4.0 * c.epsilon * s6
        rc6inv = rc ** -6.0
        ljcut = rc6inv * (lj3 * rc6inv - lj4)
        dljcut = rc6inv * (lj1 * rc6inv - lj2) / rc
        return rc, (lj1, lj2, lj3, lj4, ljcut, dljcut, rc)


class PairLJSF(PairLJSmoothLinear):
    """LAMMPS's other name of the same style."""
    name = "lj/sf"
    usage = "pair_style lj/sf RC"
