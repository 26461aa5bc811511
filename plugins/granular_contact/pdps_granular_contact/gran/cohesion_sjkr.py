r"""Cohesion model ``sjkr`` of LIGGGHTS: simplified Johnson-Kendall-Roberts (Johnson, Kendall &
Roberts, Proc. R. Soc. A 324, 301 (1971)): while the bodies touch, an attraction proportional to
the area of their contact circle,

.. math::

    F_n \mathrel{-}= k A, \qquad A = -\frac{\pi}{4}\,\frac{(r-R_i-R_j)(r+R_i-R_j)(r-R_i+R_j)(r+R_i+R_j)}{r^2}

(:math:`A = \pi(R_i^2 - r^2)` against a wall at distance r; :math:`\pi\min(R_i,R_j)^2` once the
smaller sphere's centre is inside the other, where that circle shrinks and vanishes). k is the
cohesion energy density (energy/volume) of ``fix property/global cohesionEnergyDensity
peratomtypepair``. The tangential Coulomb limit and the rolling cap do not see it, unless the
setting ``tangential_reduce on`` (LIGGGHTS's; default off).

Syntax: ``pair_style gran model ... cohesion sjkr``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import FN, FN_LIMIT, R, RADIUS_I, RADIUS_J, WALL

from .base import GranSubModel


@njit(cache=True)
def sjkr_area(r, radius_i, radius_j, wall):
    """The contact circle's area (module docstring)."""
    if wall:
        return math.pi * (radius_i * radius_i - r * r)
    if r < max(radius_i, radius_j):
        return math.pi * min(radius_i, radius_j) ** 2
    return -0.25 * math.pi * ((r - radius_i - radius_j) * (r + radius_i - radius_j)
                              * (r - radius_i + radius_j) * (r + radius_i + radius_j)) / (r * r)


@njit(cache=True)
def sjkr_force(c, k, hist, h):
    """k: cohesion energy density, tangential_reduce (1/0)."""
    pull = k[0] * sjkr_area(c[R], c[RADIUS_I], c[RADIUS_J], c[WALL] > 0.0)
    c[FN] -= pull
    if k[1] != 0.0:
        c[FN_LIMIT] -= pull


class CohesionSJKR(GranSubModel):
    kind = "gran.cohesion"
    name = "sjkr"
    compute = sjkr_force
    settings_read = {"tangential_reduce": "off"}

    def coefficients(self, material):
        return material.columns(material.property("cohesionEnergyDensity"), self.on("tangential_reduce"))
