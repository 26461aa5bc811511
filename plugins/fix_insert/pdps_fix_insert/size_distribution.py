r"""The random distributions of a particle template's radius and density (LIGGGHTS's
probability_distribution), with their moments.

- ``constant V``: every draw is V.
- ``uniform number A B``: uniform on [A, B].
- ``uniform mass A B`` (radius only): the *mass* is spread uniformly over radii in [A, B], so the
  number density of radii is :math:`f(r) \propto r^{-3}` there; drawn by inverting its distribution
  function, :math:`r = \left(A^{-2} - u\,(A^{-2} - B^{-2})\right)^{-1/2}` (LIGGGHTS's ``h1, h2``).
- ``gaussian number MU SIGMA``: normal, cut at :math:`\mu \pm 3\sigma` (drawn again outside, as
  LIGGGHTS does), :math:`\mu - 3\sigma > 0` required.
- ``lognormal number MU SIGMA``: :math:`\ln r` normal with mean MU and deviation SIGMA, cut at
  :math:`\pm 3\sigma` in :math:`\ln r`. ``lognormal mass MU SIGMA``: the mass distribution is that
  lognormal; its number distribution is the lognormal of mean :math:`\mu - 3\sigma^2` (dividing a
  lognormal density by :math:`r^3` shifts it), on the same cut support. LIGGGHTS-PUBLIC parses
  lognormal but stops with "lognormal distribution currently deactivated"; pdps draws it.
- For a density, the words ``number``/``mass`` are not written: ``uniform A B``, ``gaussian MU
  SIGMA``, ``lognormal MU SIGMA``.

Moments (:math:`\langle r^3\rangle` for the expected volume, the mean density for the expected mass)
are integrated over the cut support (Simpson's rule in :math:`\ln r`, 4,000 intervals: to 1e-10 of
the closed forms for lognormals up to sigma = 2 and uniform mass up to B/A = 1000), so a cut
Gaussian's expected mass is the one its draws average to.
"""

import math
from dataclasses import dataclass

import numpy as np

from pdps_core.api import ScriptError


# numbers after the style word (a radius's not constant: after number|mass)
ARITY = {"constant": 1, "uniform": 2, "gaussian": 2, "lognormal": 2}


@dataclass(frozen=True)
class Distribution:
    style: str          # constant, uniform, gaussian, lognormal
    basis: str          # number or mass
    a: float            # value, low end, mean or mean of the logarithm
    b: float = 0.0      # high end or deviation

    @classmethod
    def read(cls, values, what, radius):
        """From what follows ``radius`` or ``density``: the style word, ``number``/``mass`` for a
        radius not constant, then the numbers (as the template's ``Args`` read them, or words)."""
        style = values[0]
        if style not in ARITY:
            raise ScriptError(f"{what} style must be constant, uniform, gaussian or lognormal (got {style})")
        basis = "number"
        rest = values[1:]
        if radius and style != "constant":
            basis, rest = rest[0], rest[1:]
            if basis not in ("number", "mass"):
                raise ScriptError(f"{what} {style}: expected number or mass (got {basis})")
        a, b = ([float(v) for v in rest] + [0.0])[:2]
        if style == "constant" and a <= 0:
            raise ScriptError(f"{what} constant must be > 0 (got {a:g})")
        if style == "uniform" and not 0 < a < b:
            raise ScriptError(f"{what} uniform needs 0 < low < high (got {a:g} {b:g})")
        if style in ("gaussian", "lognormal") and b <= 0:
            raise ScriptError(f"{what} {style}: sigma must be > 0 (got {b:g})")
        if style == "lognormal" and basis == "mass" and b > 1.0:
            raise ScriptError(f"{what} lognormal mass: sigma must be <= 1 (got {b:g}): beyond, the number "
                              "distribution's peak lies more than 3 sigma below the cut")
        if style == "gaussian":
            if basis == "mass":
                raise ScriptError(f"{what} gaussian mass is not defined (LIGGGHTS neither): use gaussian "
                                  "number, or lognormal mass")
            if a - 3.0 * b <= 0:
                raise ScriptError(f"{what} gaussian: mu - 3 sigma must be > 0 (got {a:g} - 3 x {b:g})")
        made = cls(style, basis, a, b)
        try:
            lo, hi = made.support()
            fine = 0.0 < lo <= hi < 1e100 and math.isfinite(made.mean_of(3))
        except OverflowError:
            fine = False
        if not fine:
            shown = " ".join(v if isinstance(v, str) else f"{v:g}" for v in values)
            hint = " (mu and sigma are those of ln of the value)" if style == "lognormal" else ""
            raise ScriptError(f"{what} {shown}: the values would not be finite numbers below 1e100{hint}")
        return made

    # ---- the number density of the values ----
    def support(self):
        if self.style == "constant":
            return self.a, self.a
        if self.style == "uniform":
            return self.a, self.b
        if self.style == "gaussian":
            return self.a - 3.0 * self.b, self.a + 3.0 * self.b
        return math.exp(self.a - 3.0 * self.b), math.exp(self.a + 3.0 * self.b)

    def _log_mean(self):
        """Mean of ln r of the number distribution (lognormal)."""
        return self.a - 3.0 * self.b * self.b if self.basis == "mass" else self.a

    def density(self, r):
        """Unnormalised number density at r (inside the support)."""
        if self.style == "uniform":
            return np.ones_like(r) if self.basis == "number" else r ** -3.0
        if self.style == "gaussian":
            return np.exp(-0.5 * ((r - self.a) / self.b) ** 2)
        return np.exp(-0.5 * ((np.log(r) - self._log_mean()) / self.b) ** 2) / r

    def mean_of(self, power):
        """The mean of value**power over the number distribution: Simpson's rule in u = ln r
        (dr = r du), where a lognormal is a Gaussian and r^-3 an exponential, so that wide
        distributions (sigma 2, or B/A = 1000) are integrated as accurately as narrow ones."""
        if self.style == "constant":
            return self.a ** power
        lo, hi = self.support()
        u = np.linspace(math.log(lo), math.log(hi), 4001)
        r = np.exp(u)
        weight = np.full(4001, 2.0)
        weight[1::2] = 4.0
        weight[0] = weight[-1] = 1.0
        f = self.density(r) * r * weight
        return float(np.sum(f * r ** power) / np.sum(f))

    def draw(self, rng, n):
        """n values."""
        if self.style == "constant":
            return np.full(n, self.a)
        if self.style == "uniform":
            u = rng.random(n)
            if self.basis == "number":
                return self.a + u * (self.b - self.a)
            inverse_lo = self.a ** -2.0
            return (inverse_lo - u * (inverse_lo - self.b ** -2.0)) ** -0.5
        lo, hi = (self.a - 3.0 * self.b, self.a + 3.0 * self.b)
        centre = self.a if self.style == "gaussian" else self._log_mean()
        if self.style == "lognormal":
            lo, hi = self.a - 3.0 * self.b, self.a + 3.0 * self.b     # the cut, in ln r
        out = np.empty(n)
        filled = 0
        while filled < n:
            values = centre + self.b * rng.standard_normal(n - filled)
            values = values[(values >= lo) & (values <= hi)]
            out[filled:filled + len(values)] = values
            filled += len(values)
        return out if self.style == "gaussian" else np.exp(out)
