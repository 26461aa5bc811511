r"""Pair style ``lj/cubic``: Lennard-Jones out to its inflection point, then a cubic that falls to
zero energy and force at :math:`r_m = \tfrac{67}{48} r_s` (Holian and Ravelo, Phys. Rev. B 51,
11275 (1995); LAMMPS's ``pair_style lj/cubic``).

.. math::

    E(r) = 4\epsilon\left[\left(\frac{\sigma}{r}\right)^{12} - \left(\frac{\sigma}{r}\right)^{6}\right]
    \quad (r \le r_s), \qquad
    E(r) = \epsilon\left[\phi_s + \phi'_s\, t - \frac{A_3}{6} t^3\right], \quad
    t = \frac{r - r_s}{r_0} \quad (r_s < r < r_m)

with :math:`r_0 = 2^{1/6}\sigma` (the minimum), :math:`r_s = (26/7)^{1/6}\sigma` the inflection
point, and the constants of the unit-epsilon potential there: :math:`\phi_s = 4 u (u - 1)`,
:math:`\phi'_s = -24 u (2u - 1)\, r_0 / r_s` with :math:`u = (\sigma/r_s)^6`, :math:`A_3 = 8
\phi_s'^3 / (9 \phi_s^2)`; the cutoff :math:`r_m = \tfrac{67}{48} r_s`. Energy and force are
continuous everywhere and zero at r_m, so ``pair_modify shift`` changes nothing.

Parameters:

- ``pair_style lj/cubic`` (no arguments: the cutoff follows from sigma).
- ``pair_coeff I J EPSILON SIGMA``: ``EPSILON`` the well depth (energy), ``SIGMA`` the zero of the
  potential (> 0, distance).

Unset i != j pairs mix epsilon and sigma by ``pair_modify mix`` (geometric by default) and take the
mixed distances of the two radii r_s and r_m, as LAMMPS's. Example (LAMMPS's numdiff example,
argon in metal units)::

    pair_style lj/cubic
    pair_coeff * * 0.0102701 3.42
"""

import math

from numba import njit
from pdps_core.api import PairLaw, StyleArgs, param

# the unit potential's constants at the inflection point, from their definitions
RT6TWO = 2.0 ** (1.0 / 6.0)
_RS = (26.0 / 7.0) ** (1.0 / 6.0)
SS = _RS / RT6TWO                          # r_s / r_0
_U = _RS ** -6
PHIS = 4.0 * _U * (_U - 1.0)
DPHIDS = -24.0 * _U * (2.0 * _U - 1.0) / _RS * RT6TWO
A3 = 8.0 * DPHIDS ** 3 / (9.0 * PHIS * PHIS)
SM = 67.0 / 48.0 * SS                      # r_m / r_0


@njit(cache=True, inline="always")
def lj_cubic_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """coeff = (48 eps sigma^12, 24 eps sigma^6, 4 eps sigma^12, 4 eps sigma^6, r_s^2, r_s, eps, r_0)."""
    r2inv = 1.0 / rsq
    if rsq <= coeff[4]:
        r6inv = r2inv * r2inv * r2inv
        return r6inv * (coeff[0] * r6inv - coeff[1]) * r2inv, r6inv * (coeff[2] * r6inv - coeff[3])
    r = math.sqrt(rsq)
    t = (r - coeff[5]) / coeff[7]
    fpair = coeff[6] * (-DPHIDS + A3 * t * t / 2.0) / (coeff[7] * r)
    return fpair, coeff[6] * (PHIS + DPHIDS * t - A3 * t * t * t / 6.0)


class PairLJCubic(PairLaw):
    name = "lj/cubic"
    usage = "pair_style lj/cubic"
    coeff_usage = "EPSILON SIGMA"
    mix_default = "geometric"
    params = ("lj1", "lj2", "lj3", "lj4", "inner_sq", "inner", "epsilon", "r_minimum")
    law = staticmethod(lj_cubic_law)

    class Coeff(StyleArgs):
        epsilon: float = param(unit="energy")
        sigma: float = param(gt=0, unit="distance")

    def mix_coeff(self, ci, cj, rule):
        mixed = self.Coeff(epsilon=self._mix_energy(ci, cj, rule), sigma=self._mix_distance(ci.sigma, cj.sigma, rule))
        # LAMMPS mixes the two radii of the i i and j j pairs, not the mixed sigma's
        mixed._radii = tuple(self._mix_distance(a, b, rule) for a, b in zip(self._radii(ci), self._radii(cj)))
        return mixed

    @staticmethod
    def _mix_energy(ci, cj, rule):
        if rule == "sixthpower":
            return (2.0 * math.sqrt(ci.epsilon * cj.epsilon) * ci.sigma ** 3 * cj.sigma ** 3
                    / (ci.sigma ** 6 + cj.sigma ** 6))
        return math.sqrt(ci.epsilon * cj.epsilon)

    @staticmethod
    def _mix_distance(a, b, rule):
        if rule == "geometric":
            return math.sqrt(a * b)
        if rule == "arithmetic":
            return 0.5 * (a + b)
        return (0.5 * (a ** 6 + b ** 6)) ** (1.0 / 6.0)

    @staticmethod
    def _radii(c):
        """(r_s, r_m) of one pair: set at pair_coeff from its sigma, or mixed."""
        radii = getattr(c, "_radii", None)
        if radii is None:
            r0 = c.sigma * RT6TWO
            radii = (r0 * SS, r0 * SM)
        return radii

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        inner, cutoff = self._radii(c)
        s6 = c.sigma ** 6
        s12 = s6 * s6
        return cutoff, (48.0 * c.epsilon * s12, 24.0 * c.epsilon * s6, 4.0 * c.epsilon * s12,
                        4.0 * c.epsilon * s6, inner * inner, inner, c.epsilon, c.sigma * RT6TWO)
