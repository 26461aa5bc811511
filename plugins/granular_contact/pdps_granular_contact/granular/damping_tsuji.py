r"""Damping model ``tsuji`` of LAMMPS's pair granular: a dashpot of the contact's stiffness that
gives a restitution coefficient e independent of the impact speed,

.. math::

    \eta_n = \alpha(e)\sqrt{m^* F_{ne}/\delta}, \qquad
    \alpha(e) = 1.2728 - 4.2783e + 11.087e^2 - 22.348e^3 + 27.467e^4 - 18.022e^5 + 4.8218e^6

(Marshall's fit, J. Comput. Phys. 228, 1541 (2009), eq. 53; Tsuji et al., Powder Technol. 71, 239
(1992)), the normal model's ``eta_n0`` read as e (dimensionless, 0 < e <= 1), :math:`F_{ne}` the
normal model's elastic force (0 damping where :math:`m^*F_{ne}/\delta \le 0`). Cannot be used
with a cohesive normal model (dmt, jkr), as LAMMPS.

Syntax: ``pair_coeff I J NORMAL ... damping tsuji ...`` (LAMMPS's pair granular).
"""

import math

from numba import njit

from pdps_core.api import ScriptError

from pdps_granular_contact.contact_state import DELTA, FN, M_EFF

from .damping import DampingModel, add_damping

MARSHALL_FIT = (1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218)


@njit(cache=True)
def stiffness_damping(c, k, hist, h):
    """k: the damping factor, limit_damping, cohesive."""
    overlap = c[DELTA]
    root = math.sqrt(max(0.0, c[M_EFF] * c[FN] / overlap)) if overlap > 0.0 else 0.0
    add_damping(c, k, k[0] * root)


class DampingTsuji(DampingModel):
    kind = "granular.damping"
    name = "tsuji"
    compute = stiffness_damping
    allows_cohesion = False

    @classmethod
    def check(cls, law):
        e = law.args("normal").eta_n0
        if not 0.0 < e <= 1.0:
            raise ScriptError(f"damping {cls.name} reads the normal model's eta_n0 as a restitution coefficient: "
                              f"it must be > 0 and <= 1 (got {e:g})")

    def coefficient(self, law):
        e = law.args("normal").eta_n0
        return sum(a * e ** n for n, a in enumerate(MARSHALL_FIT))
