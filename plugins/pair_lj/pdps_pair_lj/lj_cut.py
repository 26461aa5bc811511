r"""Pair style ``lj/cut``: the 12-6 Lennard-Jones potential cut off at :math:`r_c` (Jones, Proc. R.
Soc. A 106, 463 (1924); LAMMPS's ``pair_style lj/cut``).

.. math::

    E(r) = 4\varepsilon\left[\left(\frac{\sigma}{r}\right)^{12} - \left(\frac{\sigma}{r}\right)^{6}\right]
           - E_\mathrm{shift}, \qquad r < r_c

    \mathbf{F}_{ij} = \frac{24\varepsilon}{r^2}\left[2\left(\frac{\sigma}{r}\right)^{12}
                       - \left(\frac{\sigma}{r}\right)^{6}\right]\mathbf{r}_{ij}

:math:`E_\mathrm{shift} = E(r_c)` with ``pair_modify shift yes``, else 0 (LAMMPS's default). The force is
not shifted: it jumps to zero at the cutoff. ``pair_modify tail yes`` adds LAMMPS's long-range
corrections for g(r) = 1 beyond the cutoff to pe and press:
:math:`E_\mathrm{tail} = \sum_{ij} \frac{8\pi N_i N_j \varepsilon\sigma^6(\sigma^6 - 3r_c^6)}{9 r_c^9 V}`,
each diagonal virial component gaining
:math:`\sum_{ij} \frac{16\pi N_i N_j \varepsilon\sigma^6(2\sigma^6 - 3r_c^6)}{9 r_c^9 V}` (Allen & Tildesley).

Parameters:

- ``pair_style lj/cut RC``: ``RC`` global cutoff (> 0, distance).
- ``pair_coeff I J EPSILON SIGMA [RC]``: ``EPSILON`` well depth (energy), ``SIGMA`` the zero of the
  potential (> 0, distance), ``RC`` this pair's cutoff (> 0, distance; default the global one).

Unset i != j pairs are mixed from the i i and j j coefficients, geometrically by default as in LAMMPS
(:math:`\varepsilon_{ij} = \sqrt{\varepsilon_i\varepsilon_j}`, :math:`\sigma_{ij} = \sqrt{\sigma_i\sigma_j}`,
:math:`r_{c,ij} = \sqrt{r_{c,i} r_{c,j}}`); ``pair_modify mix arithmetic`` takes the arithmetic mean
of sigma and the cutoff (Lorentz-Berthelot); ``pair_modify mix sixthpower`` LAMMPS's sixth-power rule
(:math:`\varepsilon_{ij} = 2\sqrt{\varepsilon_i\varepsilon_j}\sigma_i^3\sigma_j^3/(\sigma_i^6+\sigma_j^6)`,
:math:`\sigma_{ij} = ((\sigma_i^6+\sigma_j^6)/2)^{1/6}`, the cutoff alike). ``fix adapt pair lj/cut
epsilon|sigma I J v_NAME`` changes them in a run.

Example (LAMMPS's ``in.lj`` melt)::

    pair_style lj/cut 2.5
    pair_coeff 1 1 1.0 1.0 2.5
"""

import math

from numba import njit
from pdps_core.api import PairLaw, ScriptError, StyleArgs, param


@njit(cache=True, inline="always")
def lj_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """coeff = (48 eps sigma^12, 24 eps sigma^6, 4 eps sigma^12, 4 eps sigma^6, E_shift)."""
    r2inv = 1.0 / rsq
    r6inv = r2inv * r2inv * r2inv
    fpair = r6inv * (coeff[0] * r6inv - coeff[1]) * r2inv
    return fpair, r6inv * (coeff[2] * r6inv - coeff[3]) - coeff[4]


class PairLJCut(PairLaw):
    name = "lj/cut"
    usage = "pair_style lj/cut RC"
    coeff_usage = "EPSILON SIGMA [RC]"
    mix_default = "geometric"
    params = ("lj1", "lj2", "lj3", "lj4", "offset")
    adaptable = {"epsilon": "epsilon", "sigma": "sigma"}
    law = staticmethod(lj_law)
    masked = True       # a few multiplications: cheaper than a mispredicted cutoff branch

    class Args(StyleArgs):
        cutoff: float = param(gt=0, unit="distance")

    class Coeff(StyleArgs):
        epsilon: float = param(unit="energy")
        sigma: float = param(gt=0, unit="distance")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def mix_coeff(self, ci, cj, rule):
        rc_i = ci.cutoff if ci.cutoff is not None else self.args.cutoff
        rc_j = cj.cutoff if cj.cutoff is not None else self.args.cutoff
        if rule == "sixthpower":
            s6_i, s6_j = ci.sigma ** 6, cj.sigma ** 6
            epsilon = 2.0 * math.sqrt(ci.epsilon * cj.epsilon) * ci.sigma ** 3 * cj.sigma ** 3 / (s6_i + s6_j)
            sixth = (lambda p, q: (0.5 * (p ** 6 + q ** 6)) ** (1.0 / 6.0))
            return self.Coeff(epsilon=epsilon, sigma=sixth(ci.sigma, cj.sigma), cutoff=sixth(rc_i, rc_j))
        mean = (lambda p, q: math.sqrt(p * q)) if rule == "geometric" else (lambda p, q: 0.5 * (p + q))
        return self.Coeff(epsilon=math.sqrt(ci.epsilon * cj.epsilon), sigma=mean(ci.sigma, cj.sigma),
                          cutoff=mean(rc_i, rc_j))

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        rc = c.cutoff if c.cutoff is not None else self.args.cutoff
        s6 = c.sigma ** 6
        s12 = s6 * s6
        offset = 0.0
        if self.shift:
            ratio6 = (c.sigma / rc) ** 6
            offset = 4.0 * c.epsilon * (ratio6 * ratio6 - ratio6)
        return rc, (48.0 * c.epsilon * s12, 24.0 * c.epsilon * s6, 4.0 * c.epsilon * s12,
                    4.0 * c.epsilon * s6, offset)

    def tail_ij(self, i, j, count_i, count_j):
        """LAMMPS's lj/cut tail: etail = 8 pi N_i N_j eps sig^6 (sig^6 - 3 rc^6) / (9 rc^9),
        ptail = 16 pi N_i N_j eps sig^6 (2 sig^6 - 3 rc^6) / (9 rc^9), in LAMMPS's order of operations."""
        c = self.resolved[(i, j)]
        rc = c.cutoff if c.cutoff is not None else self.args.cutoff
        sig2 = c.sigma * c.sigma
        sig6 = sig2 * sig2 * sig2
        rc3 = rc * rc * rc
        rc6 = rc3 * rc3
        rc9 = rc3 * rc6
        if not (rc9 > 0.0 and math.isfinite(rc9)):
            raise ScriptError(f"pair_coeff {i} {j}: cutoff {rc:g} too small or large for the tail correction "
                              "(rc^9 is not a positive finite number)")
        prefactor = 8.0 * math.pi * count_i * count_j * c.epsilon * sig6 / (9.0 * rc9)
        return prefactor * (sig6 - 3.0 * rc6), 2.0 * prefactor * (2.0 * sig6 - 3.0 * rc6)
