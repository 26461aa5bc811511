r"""Rolling friction ``epsd3`` of LIGGGHTS: ``epsd``'s torque spring and dashpot (3 values of
history) with a stiffness scaled by a global factor,

.. math::

    k_r = k_{roll}\,k_n\mu_r^2R^{*2}

:math:`k_{roll}` from ``fix property/global rollingStiffness scalar`` (dimensionless; LIGGGHTS asks
>= 1 in SI units), :math:`\mu_r` from ``coefficientRollingFriction`` and the dashpot's
:math:`\eta_r` from ``coefficientRollingViscousDamping`` (``peratomtypepair``); capped at
:math:`\mu_r|F_n|R^*`, setting ``torsionTorque`` as ``epsd``.

Syntax: ``pair_style gran model ... rolling_friction epsd3``
"""

from numba import njit

from pdps_granular_contact.contact_state import KN, R_EFF

from .base import GranSubModel
from .rolling_epsd import rolling_dashpot, spring_torque


@njit(cache=True)
def epsd3_torque(c, k, hist, h):
    """k: mu_r, eta_r, rolling stiffness, torsionTorque (1/0)."""
    mu_r = k[0]
    kr = k[2] * c[KN] * mu_r * mu_r * c[R_EFF] * c[R_EFF]
    if not spring_torque(c, kr, mu_r, k[3], hist, h):
        rolling_dashpot(c, kr, k[1], k[3])


class RollingEPSD3(GranSubModel):
    kind = "gran.rolling"
    name = "epsd3"
    history_width = 3
    compute = epsd3_torque
    settings_read = {"torsionTorque": "off"}
    properties = {"rollingStiffness": ("scalar", "scalar", lambda k: k > 0, "> 0")}

    def coefficients(self, material):
        return material.columns(material.property("coefficientRollingFriction"),
                                material.property("coefficientRollingViscousDamping"),
                                material.property("rollingStiffness"), self.on("torsionTorque"))
