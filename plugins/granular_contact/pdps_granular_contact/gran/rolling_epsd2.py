r"""Rolling friction ``epsd2`` of LIGGGHTS: the torque spring of ``epsd`` (3 values of history)
with the stiffness :math:`k_r = k_tR^{*2}` (:math:`k_t` the normal model's tangential stiffness),
capped at :math:`\mu_r|F_n|R^*`, without a dashpot; setting ``torsionTorque`` as ``epsd``. :math:`\mu_r` from ``fix property/global
coefficientRollingFriction peratomtypepair`` (dimensionless).

Syntax: ``pair_style gran model ... rolling_friction epsd2``
"""

from numba import njit

from pdps_granular_contact.contact_state import KT, R_EFF

from .base import GranSubModel
from .rolling_epsd import spring_torque


@njit(cache=True)
def epsd2_torque(c, k, hist, h):
    """k: mu_r, torsionTorque (1/0)."""
    spring_torque(c, c[KT] * c[R_EFF] * c[R_EFF], k[0], k[1], hist, h)


class RollingEPSD2(GranSubModel):
    kind = "gran.rolling"
    name = "epsd2"
    history_width = 3
    compute = epsd2_torque
    settings_read = {"torsionTorque": "off"}

    def coefficients(self, material):
        return material.columns(material.property("coefficientRollingFriction"), self.on("torsionTorque"))
