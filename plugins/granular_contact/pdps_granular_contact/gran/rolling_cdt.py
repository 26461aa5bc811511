r"""Rolling friction ``cdt`` of LIGGGHTS (constant directional torque; Ai et al., Powder Technol.
206, 269 (2011)): a torque against the relative spin :math:`\boldsymbol\omega_r`,

.. math::

    \mathbf{M}_r = \mu_r k_n\delta R^*\,\frac{\boldsymbol\omega_r}{|\boldsymbol\omega_r|}
    \text{ less its part along }\mathbf{n}

(against a wall the arm is :math:`R_i - \delta/2` instead of :math:`R^*`); i gets
:math:`-\mathbf{M}_r`, j :math:`+\mathbf{M}_r`. :math:`k_n` is the normal model's, :math:`\mu_r`
from ``fix property/global coefficientRollingFriction peratomtypepair`` (dimensionless). No history.

Syntax: ``pair_style gran model ... rolling_friction cdt``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import (ARM_I, DELTA, KN, MRX, MRY, MRZ, NX, NY, NZ, R_EFF, WALL, WRX, WRY,
                                                 WRZ)

from .base import GranSubModel


@njit(cache=True)
def cdt_torque(c, k, hist, h):
    """k: mu_r."""
    size = math.sqrt(c[WRX] * c[WRX] + c[WRY] * c[WRY] + c[WRZ] * c[WRZ])
    if size > 0.0:
        along = c[WRX] * c[NX] + c[WRY] * c[NY] + c[WRZ] * c[NZ]
        scale = k[0] * c[KN] * c[DELTA] * (c[ARM_I] if c[WALL] > 0.0 else c[R_EFF]) / size
        c[MRX] = scale * (c[WRX] - along * c[NX])
        c[MRY] = scale * (c[WRY] - along * c[NY])
        c[MRZ] = scale * (c[WRZ] - along * c[NZ])


class RollingCDT(GranSubModel):
    kind = "gran.rolling"
    name = "cdt"
    compute = cdt_torque

    def coefficients(self, material):
        return material.columns(material.property("coefficientRollingFriction"))
