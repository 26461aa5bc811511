r"""Normal models ``hooke`` and ``hertz`` of LAMMPS's classic granular styles:

.. math::

    F_n = s\,(k_n\delta - m^*\gamma_n v_n), \qquad s = 1\ \text{(hooke)},\ \sqrt{\delta R^*}\
    \text{(hertz, LAMMPS's polyhertz)}

(:math:`F_n \ge 0` with ``limit_damping``); :math:`k_n` force/distance (hooke) or pressure / nktv2p
(hertz), :math:`\gamma_n` 1/time (``pdps_granular_contact.lammps_classic``).
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import DELTA, FN, FN_LIMIT, M_EFF, R_EFF, VN

from .base import ClassicSubModel


@njit(cache=True)
def classic_normal_force(c, k, hist, h):
    """k: kn, gamma_n, limit_damping (1/0), hertz (1/0)."""
    overlap = c[DELTA]
    scale = math.sqrt(overlap * c[R_EFF]) if k[3] != 0.0 else 1.0
    fn = scale * (k[0] * overlap - c[M_EFF] * k[1] * c[VN])
    if k[2] != 0.0 and fn < 0.0:
        fn = 0.0
    c[FN] = fn
    c[FN_LIMIT] = fn


class NormalHooke(ClassicSubModel):
    kind = "classic.normal"
    name = "hooke"
    compute = classic_normal_force
    names = ("kn", "gamma_n", "limit_damping", "hertz")


class NormalHertz(NormalHooke):
    name = "hertz"
