r"""Tangential model ``history`` of LIGGGHTS: a spring per contact with Coulomb's limit.

The spring :math:`\boldsymbol\xi` (3 values of history) grows by :math:`\mathbf{v}_{tr}\Delta t`
and is projected onto the current tangent plane (its length not restored); :math:`\mathbf{F}_t =
-k_t\boldsymbol\xi`; if :math:`k_t|\boldsymbol\xi| > \mu|F_n|` the force is scaled to the Coulomb
limit and :math:`\boldsymbol\xi = -\mathbf{F}_t/k_t` (no damping while sliding), else
:math:`\mathbf{F}_t \mathrel{-}= \gamma_t\mathbf{v}_{tr}`. :math:`k_t, \gamma_t` are the normal
model's, :math:`F_n` the normal model's force without the cohesion (LIGGGHTS's default
``tangential_reduce off``), :math:`\mu` from ``fix property/global coefficientFriction
peratomtypepair`` (dimensionless). In a run's setup force computation the spring is neither grown
nor projected (LIGGGHTS's ``shearupdate``). Note the differences from LAMMPS's
``linear_history``: the Coulomb test uses the spring force alone, and the damping acts only while
the contact sticks. The force is added to what a cohesion model put in the tangential force (a
liquid bridge's viscous drag, as LIGGGHTS adds both to the particles).

Syntax: ``pair_style gran model ... tangential history``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import (FN_LIMIT, FTX, FTY, FTZ, GAMMA_T, KT, NX, NY, NZ, DT, UPDATE, VTX, VTY,
                                                 VTZ)

from .base import GranSubModel


@njit(cache=True)
def history_force(c, k, hist, h):
    """k: mu."""
    kt = c[KT]
    if c[UPDATE] != 0.0:
        dt = c[DT]
        hist[h] += c[VTX] * dt
        hist[h + 1] += c[VTY] * dt
        hist[h + 2] += c[VTZ] * dt
        along = hist[h] * c[NX] + hist[h + 1] * c[NY] + hist[h + 2] * c[NZ]
        hist[h] -= along * c[NX]
        hist[h + 1] -= along * c[NY]
        hist[h + 2] -= along * c[NZ]
    length = math.sqrt(hist[h] * hist[h] + hist[h + 1] * hist[h + 1] + hist[h + 2] * hist[h + 2])
    ftx = -kt * hist[h]
    fty = -kt * hist[h + 1]
    ftz = -kt * hist[h + 2]
    limit = k[0] * abs(c[FN_LIMIT])
    if kt * length > limit:
        if length != 0.0:
            ratio = limit / (kt * length)
            ftx *= ratio
            fty *= ratio
            ftz *= ratio
            hist[h] = -ftx / kt
            hist[h + 1] = -fty / kt
            hist[h + 2] = -ftz / kt
        else:
            ftx = 0.0
            fty = 0.0
            ftz = 0.0
    else:
        ftx -= c[GAMMA_T] * c[VTX]
        fty -= c[GAMMA_T] * c[VTY]
        ftz -= c[GAMMA_T] * c[VTZ]
    # added to a cohesion model's tangential force (a liquid bridge's drag), which the limit does not see
    c[FTX] += ftx
    c[FTY] += fty
    c[FTZ] += ftz


class TangentialHistory(GranSubModel):
    kind = "gran.tangential"
    name = "history"
    history_width = 3
    compute = history_force

    def coefficients(self, material):
        return material.columns(material.property("coefficientFriction"))
