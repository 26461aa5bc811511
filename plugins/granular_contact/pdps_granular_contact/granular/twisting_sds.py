r"""Twisting model ``sds`` of LAMMPS's pair granular: a spring-dashpot-slider on the twist angle
(``pdps_granular_contact.granular.twisting``: :math:`M_t = -k_{twist}\phi - \gamma_{twist}\Omega_t`,
:math:`|M_t| \le \mu_{twist}F_{n,crit}`; 1 value of history). Coefficients: ``k_twist``
(torque, per radian, >= 0), ``gamma_twist`` (torque*time, >= 0), ``mu_twist`` (distance, >= 0: a
torque per normal force); mixed as geometric means. Where LAMMPS would divide by :math:`k_{twist}
= 0` at the limit the angle is set to 0.

Syntax: ``pair_coeff I J ... twisting sds k_twist gamma_twist mu_twist`` (LAMMPS's pair granular;
Marshall, J. Comput. Phys. 228, 1541 (2009)).
"""

from numba import njit

from pdps_core.api import param

from .base import GranularSubModel, StyleArgs
from .twisting import twist_torque


@njit(cache=True)
def twist_spring(c, k, hist, h):
    """k: k_twist, gamma_twist, mu_twist."""
    twist_torque(c, hist, h, k[0], k[1], k[2])


class TwistingCoefficients(StyleArgs):
    k_twist: float = param(ge=0, unit="torque")
    gamma_twist: float = param(ge=0, unit="torque*time")
    mu_twist: float = param(ge=0, unit="distance")


class TwistingSDS(GranularSubModel):
    kind = "granular.twisting"
    name = "sds"
    Args = TwistingCoefficients
    compute = twist_spring
    history_width = 1
    # the same seen from either sphere: (w_i - w_j) x n and (w_i - w_j).n do not change when i and j swap
    history_transfer = (1,)
