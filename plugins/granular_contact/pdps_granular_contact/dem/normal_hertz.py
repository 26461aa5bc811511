r"""Normal model ``hertz`` of PDPS's dem/hertz: Hertz-Mindlin from material constants (LIGGGHTS's
formulas: ``pdps doc pair dem/hertz``),

.. math::

    S_n = 2E^*\sqrt{R^*\delta},\ S_t = 8G^*\sqrt{R^*\delta},\
    F_n = \tfrac43E^*\sqrt{R^*\delta}\,\delta - C_nv_n,\ C_{n,t} = -2\sqrt{5/6}\,\beta\sqrt{S_{n,t}m^*}

handing on :math:`k_t = S_t` and :math:`C_t` to the tangential spring. Setting ``limit_damping``.
Coefficients: pdps_pair_dem.hertz's tables e_star, g_star (pressure), beta.
"""

import math

from numba import njit

from pdps_granular_contact.contact_models import HERTZ_DAMPING
from pdps_granular_contact.contact_state import DELTA, FN, FN_LIMIT, GAMMA_N, GAMMA_T, KN, KT, M_EFF, R_EFF, VN

from .base import DemSubModel


@njit(cache=True)
def hertz_force(c, k, hist, h):
    """k: E*, G*, beta, limit_damping (1/0)."""
    root = math.sqrt(c[R_EFF] * c[DELTA])
    sn = 2.0 * k[0] * root
    st = 8.0 * k[1] * root
    kn = 4.0 / 3.0 * k[0] * root
    cn = -HERTZ_DAMPING * k[2] * math.sqrt(sn * c[M_EFF])
    fn = kn * c[DELTA] - cn * c[VN]
    if k[3] != 0.0 and fn < 0.0:
        fn = 0.0
    c[KN] = kn
    c[KT] = st
    c[GAMMA_N] = cn
    c[GAMMA_T] = -HERTZ_DAMPING * k[2] * math.sqrt(st * c[M_EFF])
    c[FN] = fn
    c[FN_LIMIT] = fn


class NormalHertz(DemSubModel):
    kind = "dem.normal"
    name = "hertz"
    compute = hertz_force
    settings_read = {"limit_damping": False}

    def coefficients(self, tables):
        return tables.columns(tables.table("e_star"), tables.table("g_star"), tables.table("beta"),
                              1.0 if self.settings["limit_damping"] else 0.0)
