r"""Rolling model ``sds`` of LAMMPS's pair granular: a spring-dashpot-slider on the rolling
displacement,

.. math::

    \mathbf{v}_{rl} = R^*(\boldsymbol\omega_i - \boldsymbol\omega_j)\times\mathbf{n}, \qquad
    \mathbf{F}_r = -k_{roll}\boldsymbol\xi_r - \gamma_{roll}\mathbf{v}_{rl}, \quad
    |\mathbf{F}_r| \le \mu_{roll}F_{n,crit}, \qquad
    \boldsymbol\tau_i = R^*\mathbf{n}\times\mathbf{F}_r = -\boldsymbol\tau_j

(Wang et al., Particuology 23, 49 (2015), eq. 31; Luding, Granul. Matter 10, 235 (2008)). The
displacement :math:`\boldsymbol\xi_r` (3 values of history) turns into the tangent plane keeping its
length (where :math:`k_{roll}|\boldsymbol\xi_r\cdot\mathbf{n}| > 10^{-10}\mu_{roll}F_{n,crit}`),
grows by :math:`\mathbf{v}_{rl}\Delta t`, and at the limit is set to the elastic part of the cut
force, :math:`-(\mathbf{F}_r + \gamma_{roll}\mathbf{v}_{rl})/k_{roll}`; in a run's setup force
computation nothing of it is stored (LAMMPS's). The displacement is the same seen from either
sphere (:math:`\mathbf{v}_{rl}` does not change when i and j swap), so the other sphere keeps it
unchanged, not negated as LAMMPS 22 Jul 2025 does, whose trajectories then change when its atom
sort makes the other sphere hold the contact. Coefficients: ``k_roll`` (force/distance, >= 0),
``gamma_roll`` (force*time/distance, >= 0), ``mu_roll`` (dimensionless, >= 0); mixed as geometric
means. Where LAMMPS would divide by :math:`k_{roll} = 0` the displacement is set to 0.

Syntax: ``pair_coeff I J ... rolling sds k_roll gamma_roll mu_roll`` (LAMMPS's pair granular).
"""

from numba import njit

from pdps_core.api import param

from pdps_granular_contact.contact_state import (DT, FN_LIMIT, MRX, MRY, MRZ, NX, NY, NZ, R_EFF, UPDATE, WRX, WRY,
                                                 WRZ)

from .base import GranularSubModel, StyleArgs
from .frame import EPSILON, along_normal, coulomb_cut, rotate_rescale


@njit(cache=True)
def rolling_spring(c, k, hist, h):
    """k: k_roll, gamma_roll, mu_roll."""
    nx, ny, nz = c[NX], c[NY], c[NZ]
    r_eff = c[R_EFF]
    vx = r_eff * (c[WRY] * nz - c[WRZ] * ny)
    vy = r_eff * (c[WRZ] * nx - c[WRX] * nz)
    vz = r_eff * (c[WRX] * ny - c[WRY] * nx)
    limit = k[2] * c[FN_LIMIT]
    update = c[UPDATE] != 0.0
    if update:
        if abs(along_normal(c, hist, h)) * k[0] > EPSILON * limit:
            rotate_rescale(c, hist, h)
        dt = c[DT]
        hist[h] += vx * dt
        hist[h + 1] += vy * dt
        hist[h + 2] += vz * dt
    # unlike the tangential spring, not cut back in a run's setup (LAMMPS's)
    fx, fy, fz = coulomb_cut(hist, h, -k[0] * hist[h] - k[1] * vx, -k[0] * hist[h + 1] - k[1] * vy,
                             -k[0] * hist[h + 2] - k[1] * vz, -k[1] * vx, -k[1] * vy, -k[1] * vz, limit, -k[0],
                             update)
    # i turns by R* n x F_r: the loop gives i -M and j +M
    c[MRX] = -r_eff * (ny * fz - nz * fy)
    c[MRY] = -r_eff * (nz * fx - nx * fz)
    c[MRZ] = -r_eff * (nx * fy - ny * fx)


class RollingCoefficients(StyleArgs):
    k_roll: float = param(ge=0, unit="force/distance")
    gamma_roll: float = param(ge=0, unit="force*time/distance")
    mu_roll: float = param(ge=0, unit="dimensionless")


class RollingSDS(GranularSubModel):
    kind = "granular.rolling"
    name = "sds"
    Args = RollingCoefficients
    compute = rolling_spring
    history_width = 3
    # the same seen from either sphere: (w_i - w_j) x n and (w_i - w_j).n do not change when i and j swap
    history_transfer = (1, 1, 1)
