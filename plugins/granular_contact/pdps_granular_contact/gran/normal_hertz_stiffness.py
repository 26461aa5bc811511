r"""Normal model ``hertz/stiffness`` of LIGGGHTS: Hertz's law with the stiffnesses and dampings given
per type pair, each scaled by :math:`\sqrt{R^*\delta}`,

.. math::

    F_n = \sqrt{R^*\delta}\,(k_n\delta - m^*\gamma_n v_n),\qquad
    k_t \leftarrow \sqrt{R^*\delta}\,k_t,\ \gamma_t \leftarrow \sqrt{R^*\delta}\,m^*\gamma_t

``fix property/global`` ``kn``, ``kt`` (pressure), ``gamman``, ``gammat`` (1/(time distance)), all
``peratomtypepair``; :math:`k_n, k_t` divided by the unit system's ``nktv2p``. Settings
``tangential_damping`` (default on), ``limitForce`` (default off).

Syntax: ``pair_style gran model hertz/stiffness tangential ...``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import DELTA, FN, FN_LIMIT, GAMMA_N, GAMMA_T, KN, KT, M_EFF, R_EFF, VN

from pdps_granular_contact.contact_models import hertz_contact_time

from .base import GranSubModel
from .normal_hooke_stiffness import PER_PAIR


@njit(cache=True)
def hertz_stiffness_force(c, k, hist, h):
    """k: kn, kt, gamma_n, gamma_t, tangential_damping (1/0), limitForce (1/0), nktv2p."""
    root = math.sqrt(c[R_EFF] * c[DELTA])
    kn = root * k[0] / k[6]
    gamma_n = root * c[M_EFF] * k[2]
    c[KN] = kn
    c[KT] = root * k[1] / k[6]
    c[GAMMA_N] = gamma_n
    c[GAMMA_T] = root * c[M_EFF] * k[3] if k[4] != 0.0 else 0.0
    fn = -gamma_n * c[VN] + kn * c[DELTA]
    if k[5] != 0.0 and fn < 0.0:
        fn = 0.0
    c[FN] = fn
    c[FN_LIMIT] = fn


class NormalHertzStiffness(GranSubModel):
    kind = "gran.normal"
    name = "hertz/stiffness"
    compute = hertz_stiffness_force
    settings_read = {"tangential_damping": "on", "limitForce": "off"}
    properties = {name: PER_PAIR for name in ("kn", "kt", "gamman", "gammat")}

    def contact_time(self, material, t, m_eff, r_eff, speed):
        """The elastic Hertz time: kn sqrt(R* delta) delta is Hertz's 4/3 E* sqrt(R*) delta^3/2 with E* = 3 kn / 4."""
        if speed <= 0.0:
            return None
        e_star = 0.75 * material.property("kn")[t, t] / material.sim.units.nktv2p
        return hertz_contact_time(e_star, r_eff, m_eff, speed)

    def coefficients(self, material):
        return material.columns(*(material.property(name) for name in ("kn", "kt", "gamman", "gammat")),
                                self.on("tangential_damping"), self.on("limitForce"), material.sim.units.nktv2p)
