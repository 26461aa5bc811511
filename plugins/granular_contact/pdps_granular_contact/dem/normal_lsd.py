r"""Normal model ``lsd`` of PDPS's dem/lsd: a linear spring-dashpot,

.. math::

    F_n = k_n\delta - C_nv_n, \qquad C_n = C_n' + c\sqrt{m^*}

with :math:`k_n` (force/distance) and :math:`C_n'` (mass/time) of the type pair's pair_coeff, and
:math:`c` (per square-root mass) when the damping comes from a restitution coefficient (its form of
pair_coeff: :math:`C_n = 2\zeta\sqrt{k_nm^*}` per contact). The tangential spring's stiffness and
damping it hands on: :math:`k_t`, :math:`C_t = C_t' + \rho\,c\sqrt{m^*}`. Setting ``limit_damping``
(:math:`F_n \ge 0`). Coefficients: pdps_pair_dem.lsd's tables kn, cn, kt, ct, cn_per_root_mass,
ct_over_cn.
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import DELTA, FN, FN_LIMIT, GAMMA_N, GAMMA_T, KN, KT, M_EFF, VN

from .base import DemSubModel


@njit(cache=True)
def lsd_force(c, k, hist, h):
    """k: kn, cn, kt, ct, cn per root mass, ct over cn, limit_damping (1/0)."""
    damping = k[4] * math.sqrt(c[M_EFF])
    cn = k[1] + damping
    fn = k[0] * c[DELTA] - cn * c[VN]
    if k[6] != 0.0 and fn < 0.0:
        fn = 0.0
    c[KN] = k[0]
    c[KT] = k[2]
    c[GAMMA_N] = cn
    c[GAMMA_T] = k[3] + k[5] * damping
    c[FN] = fn
    c[FN_LIMIT] = fn


class NormalLSD(DemSubModel):
    kind = "dem.normal"
    name = "lsd"
    compute = lsd_force
    settings_read = {"limit_damping": False}

    def coefficients(self, tables):
        return tables.columns(*(tables.table(name) for name in ("kn", "cn", "kt", "ct", "cn_per_root_mass",
                                                                  "ct_over_cn")),
                              1.0 if self.settings["limit_damping"] else 0.0)
