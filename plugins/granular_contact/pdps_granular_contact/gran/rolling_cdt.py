r"""Rolling friction ``cdt`` of LIGGGHTS (constant directional torque; Ai et al., Powder Technol.
206, 269 (2011)): a torque against the relative spin :math:`\boldsymbol\omega_r`,

.. math::

    \mathbf{M}_r = \mu_r k_n\delta R^*\,\frac{\boldsymbol\omega_r}{|\boldsymbol\omega_r|}
    \text{ less its part along }\mathbf{n}

(:math:`R^* = R_i` against a wall; ``torsionTorque on`` keeps the part along n); i gets
:math:`-\mathbf{M}_r`, j :math:`+\mathbf{M}_r`. :math:`k_n` is the normal model's, :math:`\mu_r`
from ``fix property/global coefficientRollingFriction peratomtypepair`` (dimensionless). No history.

Syntax: ``pair_style gran model ... rolling_friction cdt``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import DELTA, KN, MRX, MRY, MRZ, NX, NY, NZ, R_EFF, WRX, WRY, WRZ

from .base import GranSubModel


@njit(cache=True)
def cdt_torque(c, k, hist, h):
    """k: mu_r, torsionTorque (1/0)."""
    size = math.sqrt(c[WRX] * c[WRX] + c[WRY] * c[WRY] + c[WRZ] * c[WRZ])
    if size > 0.0:
        scale = k[0] * c[KN] * c[DELTA] * c[R_EFF] / size
        mx = scale * c[WRX]
        my = scale * c[WRY]
        mz = scale * c[WRZ]
        if k[1] == 0.0:
            along = mx * c[NX] + my * c[NY] + mz * c[NZ]
            mx -= along * c[NX]
            my -= along * c[NY]
            mz -= along * c[NZ]
        c[MRX] = mx
        c[MRY] = my
        c[MRZ] = mz


class RollingCDT(GranSubModel):
    kind = "gran.rolling"
    name = "cdt"
    compute = cdt_torque
    settings_read = {"torsionTorque": "off"}

    def coefficients(self, material):
        return material.columns(material.property("coefficientRollingFriction"), self.on("torsionTorque"))
