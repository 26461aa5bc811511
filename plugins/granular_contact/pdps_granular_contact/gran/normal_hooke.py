r"""Normal model ``hooke`` of LIGGGHTS: a linear spring-dashpot whose stiffness is Hertz's at a
characteristic impact speed V, so that a contact at that speed lasts as a Hertz contact would, and
whose damping gives the restitution coefficient e:

.. math::

    k_n = k_t = \tfrac{16}{15}\sqrt{R^*}\,Y^*\Big(\frac{15\,m^*V^2}{16\sqrt{R^*}\,Y^*}\Big)^{1/5},\qquad
    \gamma_n = \gamma_t = \sqrt{\frac{4m^*k_n}{1 + \pi^2/\ln^2 e}}

(:math:`Y^*` as in ``hertz``; V from ``fix property/global characteristicVelocity scalar``, a
velocity). :math:`k_n, k_t` divided by the unit system's ``nktv2p``; :math:`F_n = k_n\delta -
\gamma_n v_n`. Settings ``tangential_damping``, ``limitForce`` as ``hertz``.

Syntax: ``pair_style gran model hooke tangential ...``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import (DELTA, FN, FN_LIMIT, GAMMA_N, GAMMA_T, KN, KT, M_EFF, R_EFF, VN)

from pdps_granular_contact.contact_models import spring_dashpot_time

from .base import GranSubModel


@njit(cache=True)
def hooke_constants(y_star, log_e, charvel, m_eff, r_eff):
    """(k_n before nktv2p, gamma_n) of the module docstring."""
    root = math.sqrt(r_eff)
    kn = 16.0 / 15.0 * root * y_star * (15.0 * m_eff * charvel * charvel / (16.0 * root * y_star)) ** 0.2
    # e = 1 (log e = 0): no damping, the limit of the formula
    gamma_n = math.sqrt(4.0 * m_eff * kn * log_e * log_e / (log_e * log_e + math.pi * math.pi))
    return kn, gamma_n


@njit(cache=True)
def hooke_force(c, k, hist, h):
    """k: Y*, ln e, V, tangential_damping (1/0), limitForce (1/0), nktv2p."""
    kn, gamma_n = hooke_constants(k[0], k[1], k[2], c[M_EFF], c[R_EFF])
    c[KN] = kn / k[5]
    c[KT] = kn / k[5]
    c[GAMMA_N] = gamma_n
    c[GAMMA_T] = gamma_n if k[3] != 0.0 else 0.0
    fn = c[KN] * c[DELTA] - gamma_n * c[VN]
    if k[4] != 0.0 and fn < 0.0:
        fn = 0.0
    c[FN] = fn
    c[FN_LIMIT] = fn


class NormalHooke(GranSubModel):
    kind = "gran.normal"
    name = "hooke"
    compute = hooke_force
    settings_read = {"tangential_damping": "on", "limitForce": "off"}

    def contact_time(self, material, t, m_eff, r_eff, speed):
        kn, gamma_n = hooke_constants(material.youngs_effective()[t, t], material.log_restitution()[t, t],
                                      material.property("characteristicVelocity"), m_eff, r_eff)
        return spring_dashpot_time(kn / material.sim.units.nktv2p, gamma_n, m_eff)

    def coefficients(self, material):
        return material.columns(material.youngs_effective(), material.log_restitution(),
                                material.property("characteristicVelocity"), self.on("tangential_damping"),
                                self.on("limitForce"), material.sim.units.nktv2p)
