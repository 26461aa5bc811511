r"""Normal model ``hooke/stiffness`` of LIGGGHTS: a linear spring-dashpot with the stiffnesses and
dampings given per type pair,

.. math::

    F_n = k_n\delta - \gamma_n v_n,\qquad \gamma_n = m^*\gamma_n',\ \gamma_t = m^*\gamma_t'

(``absolute_damping on``: :math:`\gamma_n, \gamma_t` as given, not scaled by the effective mass).
``fix property/global`` ``kn``, ``kt`` (force/distance), ``gamman``, ``gammat`` (1/time), or
``gamman_abs``, ``gammat_abs`` (mass/time) with ``absolute_damping on``, all ``peratomtypepair``;
:math:`k_n, k_t` divided by the unit system's ``nktv2p``. :math:`k_t` and :math:`\gamma_t` are the
tangential model's. Settings ``tangential_damping`` (default on), ``limitForce`` (default off),
``absolute_damping`` (default off).

Syntax: ``pair_style gran model hooke/stiffness tangential ... [absolute_damping on]``
"""

from numba import njit

from pdps_granular_contact.contact_state import DELTA, FN, FN_LIMIT, GAMMA_N, GAMMA_T, KN, KT, M_EFF, VN

from pdps_granular_contact.contact_models import spring_dashpot_time

from .base import GranSubModel


def _at_least_zero(value):
    return value >= 0


PER_PAIR = ("per_type_pair", "peratomtypepair", _at_least_zero, ">= 0")


@njit(cache=True)
def hooke_stiffness_force(c, k, hist, h):
    """k: kn, kt, gamma_n, gamma_t, absolute_damping (1/0), tangential_damping (1/0), limitForce
    (1/0), nktv2p."""
    scale = 1.0 if k[4] != 0.0 else c[M_EFF]
    gamma_n = scale * k[2]
    kn = k[0] / k[7]
    c[KN] = kn
    c[KT] = k[1] / k[7]
    c[GAMMA_N] = gamma_n
    c[GAMMA_T] = scale * k[3] if k[5] != 0.0 else 0.0
    fn = -gamma_n * c[VN] + kn * c[DELTA]
    if k[6] != 0.0 and fn < 0.0:
        fn = 0.0
    c[FN] = fn
    c[FN_LIMIT] = fn


class NormalHookeStiffness(GranSubModel):
    kind = "gran.normal"
    name = "hooke/stiffness"
    compute = hooke_stiffness_force
    settings_read = {"tangential_damping": "on", "limitForce": "off", "absolute_damping": "off"}
    properties = {name: PER_PAIR for name in ("kn", "kt", "gamman", "gammat", "gamman_abs", "gammat_abs")}

    def contact_time(self, material, t, m_eff, r_eff, speed):
        absolute = self.on("absolute_damping")
        gamma_n = material.property("gamman_abs" if absolute else "gamman")[t, t] * (1.0 if absolute else m_eff)
        return spring_dashpot_time(material.property("kn")[t, t] / material.sim.units.nktv2p, gamma_n, m_eff)

    def coefficients(self, material):
        absolute = self.on("absolute_damping")
        damping = ("gamman_abs", "gammat_abs") if absolute else ("gamman", "gammat")
        return material.columns(material.property("kn"), material.property("kt"),
                                *(material.property(name) for name in damping), absolute,
                                self.on("tangential_damping"), self.on("limitForce"), material.sim.units.nktv2p)
