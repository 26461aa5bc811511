r"""Cohesion model ``sjkr2`` of LIGGGHTS: as ``sjkr`` with the area of a contact circle linear in
the overlap,

.. math::

    F_n \mathrel{-}= k\,2\pi\frac{2R_iR_j}{R_i+R_j}\,\delta

(:math:`2\pi R_i\delta` against a wall); k the cohesion energy density (energy/volume) of ``fix
property/global cohesionEnergyDensity peratomtypepair``; setting ``tangential_reduce`` as ``sjkr``.

Syntax: ``pair_style gran model ... cohesion sjkr2``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import DELTA, FN, FN_LIMIT, RADIUS_I, RADIUS_J, WALL

from .base import GranSubModel


@njit(cache=True)
def sjkr2_force(c, k, hist, h):
    """k: cohesion energy density, tangential_reduce (1/0)."""
    ri = c[RADIUS_I]
    if c[WALL] > 0.0:
        area = 2.0 * math.pi * ri * c[DELTA]
    else:
        rj = c[RADIUS_J]
        area = 2.0 * math.pi * (2.0 * ri * rj / (ri + rj)) * c[DELTA]
    c[FN] -= k[0] * area
    if k[1] != 0.0:
        c[FN_LIMIT] -= k[0] * area


class CohesionSJKR2(GranSubModel):
    kind = "gran.cohesion"
    name = "sjkr2"
    compute = sjkr2_force
    settings_read = {"tangential_reduce": "off"}

    def coefficients(self, material):
        return material.columns(material.property("cohesionEnergyDensity"), self.on("tangential_reduce"))
