r"""Tangential model ``spring`` of PDPS's dem contacts: a spring per contact (3 values of history)
with a dashpot and Coulomb's limit,

.. math::

    \mathbf{F}_t = -k_t\boldsymbol\xi - C_t\mathbf{v}_t, \qquad |\mathbf{F}_t| \le \mu|F_n|

The spring :math:`\boldsymbol\xi` is first turned into the current tangent plane keeping its
length, then grows by :math:`\mathbf{v}_t\Delta t`; when :math:`|\mathbf{F}_t|` (damping included)
passes the limit, the force is scaled to it and the spring cut back to what it allows. :math:`k_t,
C_t` and :math:`F_n` are the normal model's, :math:`\mu` the type pair's friction coefficient
(dimensionless, table mu). In a run's setup force computation the spring acts as stored, neither
turned nor grown, and nothing is kept.
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import (DT, FN_LIMIT, FTX, FTY, FTZ, GAMMA_T, KT, NX, NY, NZ, UPDATE, VTX,
                                                 VTY, VTZ)

from .base import DemSubModel


@njit(cache=True)
def spring_force(c, k, hist, h):
    """k: mu."""
    n0, n1, n2 = c[NX], c[NY], c[NZ]
    s0, s1, s2 = hist[h], hist[h + 1], hist[h + 2]
    length = math.sqrt(s0 * s0 + s1 * s1 + s2 * s2)
    along = s0 * n0 + s1 * n1 + s2 * n2
    s0 -= along * n0
    s1 -= along * n1
    s2 -= along * n2
    turned = math.sqrt(s0 * s0 + s1 * s1 + s2 * s2)
    if turned > 0.0:
        s0 *= length / turned
        s1 *= length / turned
        s2 *= length / turned
    dt = c[DT] if c[UPDATE] != 0.0 else 0.0
    vt0, vt1, vt2 = c[VTX], c[VTY], c[VTZ]
    s0 += vt0 * dt
    s1 += vt1 * dt
    s2 += vt2 * dt
    kt, ct = c[KT], c[GAMMA_T]
    ft0 = -kt * s0 - ct * vt0
    ft1 = -kt * s1 - ct * vt1
    ft2 = -kt * s2 - ct * vt2
    ft_mag = math.sqrt(ft0 ** 2 + ft1 ** 2 + ft2 ** 2)
    limit = k[0] * abs(c[FN_LIMIT])
    if ft_mag > limit and ft_mag > 0.0:
        # sliding: the spring is cut back to what Coulomb's limit allows
        scale = limit / ft_mag
        ft0 *= scale
        ft1 *= scale
        ft2 *= scale
        s0 = -(ft0 + ct * vt0) / kt if kt > 0.0 else 0.0
        s1 = -(ft1 + ct * vt1) / kt if kt > 0.0 else 0.0
        s2 = -(ft2 + ct * vt2) / kt if kt > 0.0 else 0.0
    c[FTX] = ft0
    c[FTY] = ft1
    c[FTZ] = ft2
    if c[UPDATE] != 0.0:
        hist[h] = s0
        hist[h + 1] = s1
        hist[h + 2] = s2


class TangentialSpring(DemSubModel):
    kind = "dem.tangential"
    name = "spring"
    history_width = 3
    compute = spring_force

    def coefficients(self, tables):
        return tables.columns(tables.table("mu"))
