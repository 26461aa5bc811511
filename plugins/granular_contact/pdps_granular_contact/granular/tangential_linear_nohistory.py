r"""Tangential model ``linear_nohistory`` of LAMMPS's pair granular: viscous friction capped at
Coulomb's limit, no spring,

.. math::

    \mathbf{F}_t = -\min(\mu_s F_{n,crit},\ \eta_t|\mathbf{v}_{tr}|)\,\frac{\mathbf{v}_{tr}}{|\mathbf{v}_{tr}|},
    \qquad \eta_t = x_{\gamma,t}\,\eta_n

with the damping model's :math:`\eta_n` and the normal model's :math:`F_{n,crit}`. Coefficients:
``x_gamma_t`` (dimensionless, >= 0), ``mu_s`` the friction coefficient (dimensionless, >= 0); mixed
as geometric means. No history.

Syntax: ``pair_coeff I J ... tangential linear_nohistory x_gamma_t mu_s`` (LAMMPS's pair granular;
the tangential law of its classic gran/hooke).
"""

import math

from numba import njit

from pdps_core.api import param

from pdps_granular_contact.contact_state import FN_LIMIT, FTX, FTY, FTZ, GAMMA_N, GAMMA_T, VTX, VTY, VTZ

from .base import GranularSubModel, StyleArgs


@njit(cache=True)
def viscous_friction(c, k, hist, h):
    """k: x_gamma_t, mu_s."""
    damp = k[0] * c[GAMMA_N]
    c[GAMMA_T] = damp
    vrel = math.sqrt(c[VTX] * c[VTX] + c[VTY] * c[VTY] + c[VTZ] * c[VTZ])
    ft = min(k[1] * c[FN_LIMIT], damp * vrel) / vrel if vrel != 0.0 else 0.0
    c[FTX] = -ft * c[VTX]
    c[FTY] = -ft * c[VTY]
    c[FTZ] = -ft * c[VTZ]


class ViscousCoefficients(StyleArgs):
    x_gamma_t: float = param(ge=0, unit="dimensionless")
    mu_s: float = param(ge=0, unit="dimensionless")


class TangentialLinearNoHistory(GranularSubModel):
    kind = "granular.tangential"
    name = "linear_nohistory"
    Args = ViscousCoefficients
    compute = viscous_friction
