r"""Rolling friction ``epsd`` of LIGGGHTS (elastic-plastic spring-dashpot; Ai et al., Powder
Technol. 206, 269 (2011)): a torque spring per contact (3 values of history),

.. math::

    \mathbf{M}_r \mathrel{+}= k_r\,\boldsymbol\omega_{r,t}\Delta t,\quad k_r = 2.25\,k_n\mu_r^2R^{*2},
    \quad |\mathbf{M}_r| \le \mu_r|F_n|R^*

and, below the cap, a dashpot :math:`\eta_r\,2\sqrt{I_rk_r}\,\boldsymbol\omega_{r,t}` added (not
stored), with :math:`I_r = 1.4\,(m_iR_i^2)(m_jR_j^2)/(m_iR_i^2 + m_jR_j^2)` (1.5 in 2-d;
:math:`1.4\,m_iR_i^2` against a wall). :math:`\boldsymbol\omega_{r,t}` is the relative spin less its
part along n (all of it with ``torsionTorque on``); :math:`k_n` and :math:`F_n` (without cohesion
unless ``tangential_reduce on``) the normal model's; :math:`R^* = R_i` against a wall. i gets
:math:`-\mathbf{M}_r`, j :math:`+\mathbf{M}_r`. :math:`\mu_r` from ``coefficientRollingFriction``,
:math:`\eta_r` from ``coefficientRollingViscousDamping`` (both ``peratomtypepair``,
dimensionless). In a run's setup force computation the torque is grown as in a step but not
stored (LIGGGHTS's ``shearupdate``).

Syntax: ``pair_style gran model ... rolling_friction epsd``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import (DIMENSION, DT, FN_LIMIT, KN, MASS_I, MASS_J, MRX, MRY, MRZ, NX,
                                                 NY, NZ, RADIUS_I, RADIUS_J, R_EFF, UPDATE, WALL, WRX, WRY, WRZ)

from .base import GranSubModel

@njit(cache=True)
def spring_torque(c, kr, mu_r, torsion, hist, h):
    """The capped spring torque into MR (stored when the history advances); returns whether it was
    capped. ``torsion`` (1/0): the spin along n turns the spring too."""
    along = 0.0 if torsion != 0.0 else c[WRX] * c[NX] + c[WRY] * c[NY] + c[WRZ] * c[NZ]
    step = kr * c[DT]
    mx = hist[h] + step * (c[WRX] - along * c[NX])
    my = hist[h + 1] + step * (c[WRY] - along * c[NY])
    mz = hist[h + 2] + step * (c[WRZ] - along * c[NZ])
    size = math.sqrt(mx * mx + my * my + mz * mz)
    cap = abs(c[FN_LIMIT]) * c[R_EFF] * mu_r
    capped = size > cap
    if capped:
        mx *= cap / size
        my *= cap / size
        mz *= cap / size
    if c[UPDATE] != 0.0:
        hist[h] = mx
        hist[h + 1] = my
        hist[h + 2] = mz
    c[MRX] = mx
    c[MRY] = my
    c[MRZ] = mz
    return capped


@njit(cache=True)
def rolling_dashpot(c, kr, eta_r, torsion):
    """Below the cap: eta_r 2 sqrt(I_r k_r) omega_r,t added to MR (not stored)."""
    shape = 1.5 if c[DIMENSION] == 2.0 else 1.4
    own_i = c[MASS_I] * c[RADIUS_I] * c[RADIUS_I]
    if c[WALL] > 0.0:
        inertia = shape * own_i
    else:
        own_j = c[MASS_J] * c[RADIUS_J] * c[RADIUS_J]
        inertia = shape * own_i * own_j / (own_i + own_j)
    damping = eta_r * 2.0 * math.sqrt(inertia * kr)
    along = 0.0 if torsion != 0.0 else c[WRX] * c[NX] + c[WRY] * c[NY] + c[WRZ] * c[NZ]
    c[MRX] += damping * (c[WRX] - along * c[NX])
    c[MRY] += damping * (c[WRY] - along * c[NY])
    c[MRZ] += damping * (c[WRZ] - along * c[NZ])


@njit(cache=True)
def epsd_torque(c, k, hist, h):
    """k: mu_r, eta_r, torsionTorque (1/0)."""
    mu_r = k[0]
    kr = 2.25 * c[KN] * mu_r * mu_r * c[R_EFF] * c[R_EFF]
    if not spring_torque(c, kr, mu_r, k[2], hist, h):
        rolling_dashpot(c, kr, k[1], k[2])


class RollingEPSD(GranSubModel):
    kind = "gran.rolling"
    name = "epsd"
    history_width = 3
    compute = epsd_torque
    settings_read = {"torsionTorque": "off"}

    def coefficients(self, material):
        return material.columns(material.property("coefficientRollingFriction"),
                                material.property("coefficientRollingViscousDamping"), self.on("torsionTorque"))
