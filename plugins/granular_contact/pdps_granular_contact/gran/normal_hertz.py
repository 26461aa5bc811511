r"""Normal model ``hertz`` of LIGGGHTS (Di Renzo & Di Maio, Chem. Eng. Sci. 59, 525 (2004); damping
of Tsuji et al., Powder Technol. 71, 239 (1992)): Hertz's elastic force with a damping that makes
the restitution coefficient independent of the impact speed, and the tangential stiffness and
damping the tangential model uses.

With :math:`Y^*, G^*` of the two materials (``fix property/global youngsModulus peratomtype``,
``poissonsRatio peratomtype``; :math:`1/Y^* = (1-\nu_i^2)/Y_i + (1-\nu_j^2)/Y_j`, :math:`1/G^* =
2(2-\nu_i)(1+\nu_i)/Y_i + 2(2-\nu_j)(1+\nu_j)/Y_j`) and :math:`\beta = \ln e/\sqrt{\ln^2 e +
\pi^2}` of the restitution coefficient e (``coefficientRestitution peratomtypepair``):

.. math::

    S_n = 2Y^*\sqrt{R^*\delta},\ S_t = 8G^*\sqrt{R^*\delta},\ k_n = \tfrac43 Y^*\sqrt{R^*\delta},\
    k_t = S_t,\ \gamma_{n,t} = -2\sqrt{5/6}\,\beta\sqrt{S_{n,t}\,m^*}

:math:`k_n, k_t` divided by the unit system's ``nktv2p``; :math:`F_n = k_n\delta - \gamma_n v_n`.
Settings: ``tangential_damping on|off`` (default on; off: :math:`\gamma_t = 0`), ``limitForce
on|off`` (default off; on: :math:`F_n \ge 0`, no pull at the end of a contact). Units: Y pressure,
e and :math:`\nu` dimensionless.

Syntax: ``pair_style gran model hertz tangential ...``
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import (DELTA, FN, FN_LIMIT, GAMMA_N, GAMMA_T, KN, KT, M_EFF, R_EFF, VN)

from pdps_granular_contact.contact_models import hertz_contact_time

from .base import GranSubModel

SQRT_FIVE_SIXTHS = math.sqrt(5.0 / 6.0)


@njit(cache=True)
def hertz_force(c, k, hist, h):
    """k: Y*, G*, beta, tangential_damping (1/0), limitForce (1/0), nktv2p."""
    root = math.sqrt(c[R_EFF] * c[DELTA])
    sn = 2.0 * k[0] * root
    st = 8.0 * k[1] * root
    kn = 4.0 / 3.0 * k[0] * root
    gamma_n = -2.0 * SQRT_FIVE_SIXTHS * k[2] * math.sqrt(sn * c[M_EFF])
    gamma_t = -2.0 * SQRT_FIVE_SIXTHS * k[2] * math.sqrt(st * c[M_EFF]) if k[3] != 0.0 else 0.0
    kn /= k[5]
    c[KN] = kn
    c[KT] = st / k[5]
    c[GAMMA_N] = gamma_n
    c[GAMMA_T] = gamma_t
    fn = kn * c[DELTA] - gamma_n * c[VN]
    if k[4] != 0.0 and fn < 0.0:
        fn = 0.0
    c[FN] = fn
    c[FN_LIMIT] = fn


class NormalHertz(GranSubModel):
    kind = "gran.normal"
    name = "hertz"
    compute = hertz_force
    settings_read = {"tangential_damping": "on", "limitForce": "off"}

    def contact_time(self, material, t, m_eff, r_eff, speed):
        """The elastic Hertz time at that speed (none when nothing moves)."""
        if speed <= 0.0:
            return None
        return hertz_contact_time(material.youngs_effective()[t, t], r_eff, m_eff, speed)

    def coefficients(self, material):
        return material.columns(material.youngs_effective(), material.shear_effective(), material.restitution_beta(),
                                self.on("tangential_damping"), self.on("limitForce"),
                                material.sim.units.nktv2p)
