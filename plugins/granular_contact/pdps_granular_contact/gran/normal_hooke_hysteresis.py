r"""Normal model ``hooke/hysteresis`` of LIGGGHTS: ``hooke``'s spring on loading, a stiffer one on
unloading and reloading, and an adhesive branch (Walton & Braun, J. Rheol. 30, 949 (1986); Luding,
Granular Matter 10, 235 (2008)). With :math:`k_n, \gamma_n` of ``hooke`` (characteristic velocity,
restitution), the largest overlap of the contact so far :math:`\delta_{max}` (1 value of history),

.. math::

    k_{2,max} = \phi_k k_n,\quad k_c = \phi_c k_n,\quad
    \delta_{lim} = \frac{k_{2,max}}{k_{2,max} - k_n}\,2\phi_f R^*

and, below :math:`\delta_{lim}`, :math:`k_2 = k_n + (k_{2,max} - k_n)\delta_{max}/\delta_{lim}`:

.. math::

    f = \begin{cases} k_n\delta & k_2(\delta - \delta_{max}) + k_n\delta_{max} \ge k_n\delta \\
    k_2(\delta - \delta_{max}) + k_n\delta_{max} & \text{between} \\
    -k_c\delta & k_2(\delta - \delta_{max}) + k_n\delta_{max} \le -k_c\delta \end{cases}

(above it :math:`k_2 = k_{2,max}` and :math:`f = \max(k_{2,max}(\delta - \delta_{lim}) + k_n
\delta_{lim}, -k_c\delta)`); on the adhesive branch :math:`\delta_{max}` moves to
:math:`\tfrac12\big(\delta + \sqrt{\delta^2 + 4(k_n + k_c)\delta\,\delta_{lim}/(k_{2,max} - k_n)}\big)`.
:math:`F_n = f - \gamma_n v_n` (``limitForce`` does not apply). :math:`\phi_k, \phi_c, \phi_f` from
``fix property/global coefficientMaxElasticStiffness``, ``coefficientAdhesionStiffness``,
``coefficientPlasticityDepth`` (``peratomtypepair``, dimensionless). Setting
``tangential_damping`` as ``hooke``.

Syntax: ``pair_style gran model hooke/hysteresis tangential ...``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import DELTA, FN, FN_LIMIT, GAMMA_N, GAMMA_T, KN, KT, M_EFF, R_EFF, UPDATE, VN

from pdps_granular_contact.contact_models import spring_dashpot_time

from .base import GranSubModel
from .normal_hooke import hooke_constants


def _positive(value):
    return value > 0


PER_PAIR = ("per_type_pair", "peratomtypepair", _positive, "> 0")


@njit(cache=True)
def hysteresis_force(c, k, hist, h):
    """k: Y*, ln e, V, tangential_damping (1/0), nktv2p, phi_k, phi_c, phi_f."""
    r_eff = c[R_EFF]
    kn, gamma_n = hooke_constants(k[0], k[1], k[2], c[M_EFF], r_eff)
    kn /= k[4]
    c[KN] = kn
    c[KT] = kn
    c[GAMMA_N] = gamma_n
    c[GAMMA_T] = gamma_n if k[3] != 0.0 else 0.0
    k2_max = kn * k[5]
    kc = kn * k[6]
    delta = c[DELTA]
    # the largest overlap so far, noted in setup too (LIGGGHTS's)
    if delta > hist[h]:
        hist[h] = delta
    delta_max = hist[h]
    delta_lim = (k2_max / (k2_max - kn)) * k[7] * 2.0 * r_eff
    adhesive = False
    if delta_max >= delta_lim:
        f = k2_max * (delta - delta_lim) + kn * delta_lim
        if f < -kc * delta:
            f = -kc * delta
            adhesive = True
    else:
        k2 = kn + (k2_max - kn) * delta_max / delta_lim
        f = k2 * (delta - delta_max) + kn * delta_max
        if f >= kn * delta:
            f = kn * delta
        elif f <= -kc * delta:
            f = -kc * delta
            adhesive = True
    if adhesive and c[UPDATE] != 0.0:
        hist[h] = 0.5 * (delta + math.sqrt(delta * delta + 4.0 * ((kn + kc) * delta * delta_lim / (k2_max - kn))))
    fn = f - gamma_n * c[VN]
    c[FN] = fn
    c[FN_LIMIT] = fn


class NormalHookeHysteresis(GranSubModel):
    kind = "gran.normal"
    name = "hooke/hysteresis"
    history_width = 1
    compute = hysteresis_force
    settings_read = {"tangential_damping": "on"}
    properties = {name: PER_PAIR for name in ("coefficientMaxElasticStiffness", "coefficientAdhesionStiffness",
                                              "coefficientPlasticityDepth")}

    def contact_time(self, material, t, m_eff, r_eff, speed):
        """The unloading spring's (the stiffest, k_2,max = phi_k k_n) time."""
        kn, gamma_n = hooke_constants(material.youngs_effective()[t, t], material.log_restitution()[t, t],
                                      material.property("characteristicVelocity"), m_eff, r_eff)
        stiffest = kn * material.property("coefficientMaxElasticStiffness")[t, t]
        return spring_dashpot_time(stiffest / material.sim.units.nktv2p, gamma_n, m_eff)

    def coefficients(self, material):
        return material.columns(material.youngs_effective(), material.log_restitution(),
                                material.property("characteristicVelocity"), self.on("tangential_damping"),
                                material.sim.units.nktv2p, material.property("coefficientMaxElasticStiffness"),
                                material.property("coefficientAdhesionStiffness"),
                                material.property("coefficientPlasticityDepth"))
