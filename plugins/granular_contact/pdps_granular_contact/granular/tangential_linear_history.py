r"""Tangential model ``linear_history`` of LAMMPS's pair granular: a linear spring per contact with
a dashpot and Coulomb's limit,

.. math::

    \mathbf{F}_t = -k_t\boldsymbol\xi - \eta_t\mathbf{v}_{tr}, \quad \eta_t = x_{\gamma,t}\eta_n,
    \qquad |\mathbf{F}_t| \le \mu_s F_{n,crit}

The spring :math:`\boldsymbol\xi` (3 values of history) is first turned into the current tangent
plane, its length kept (only where its normal part matters: :math:`k_t|\boldsymbol\xi\cdot
\mathbf{n}| > 10^{-10}\mu_sF_{n,crit}`), then grows by :math:`\mathbf{v}_{tr}\Delta t` (Luding,
Granul. Matter 10, 235 (2008), eq. 17); at the Coulomb limit the force is scaled onto it and the
spring set to its elastic part, :math:`\boldsymbol\xi = -(\mathbf{F}_t + \eta_t\mathbf{v}_{tr})/k_t`
(a spring of zero length gives no force instead). In a run's setup force computation the spring
neither turns nor grows. Coefficients: ``k_t`` (force/distance, >= 0), ``x_gamma_t``
(dimensionless, >= 0), ``mu_s`` (dimensionless, >= 0); mixed as geometric means. Where LAMMPS would
divide by :math:`k_t = 0` at the limit, the spring is set to 0.

Syntax: ``pair_coeff I J ... tangential linear_history k_t x_gamma_t mu_s`` (LAMMPS's pair granular).
"""

from numba import njit

from pdps_core.api import param

from pdps_granular_contact.contact_state import DT, FN_LIMIT, UPDATE, VTX, VTY, VTZ

from .base import GranularSubModel, StyleArgs
from .frame import EPSILON, along_normal, rotate_rescale
from .tangential_mindlin import coulomb_limit


@njit(cache=True)
def linear_spring(c, k, hist, h):
    """k: k_t, x_gamma_t, mu_s."""
    stiffness = k[0]
    limit = k[2] * c[FN_LIMIT]
    if c[UPDATE] != 0.0:
        if abs(along_normal(c, hist, h)) * stiffness > EPSILON * limit:
            rotate_rescale(c, hist, h)
        dt = c[DT]
        hist[h] += c[VTX] * dt
        hist[h + 1] += c[VTY] * dt
        hist[h + 2] += c[VTZ] * dt
    coulomb_limit(c, hist, h, -stiffness, k[1], limit, stiffness)


class SpringCoefficients(StyleArgs):
    k_t: float = param(ge=0, unit="force/distance")
    x_gamma_t: float = param(ge=0, unit="dimensionless")
    mu_s: float = param(ge=0, unit="dimensionless")


class TangentialLinearHistory(GranularSubModel):
    kind = "granular.tangential"
    name = "linear_history"
    Args = SpringCoefficients
    compute = linear_spring
    history_width = 3
