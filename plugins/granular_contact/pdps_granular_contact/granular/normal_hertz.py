r"""Normal model ``hertz`` of LAMMPS's pair granular: Hertz's elastic force with a given stiffness,

.. math::

    F_{ne} = k_n a\delta, \qquad a = \sqrt{\delta R^*}

(the contact radius a, which the damping, tangential and rolling models read). Coefficients:
``k_n`` (force/area, >= 0; for LAMMPS's form of Hertz's :math:`\tfrac43 E^*`), ``eta_n0`` (the
damping coefficient, in the damping model's unit). Mixed between types as the geometric mean of
each.

Syntax: ``pair_coeff I J hertz k_n eta_n0 damping ... tangential ...``
(LAMMPS's pair granular; Hertz, J. reine angew. Math. 92, 156 (1882)).
"""

import math

from numba import njit

from pdps_core.api import param

from pdps_granular_contact.contact_models import hertz_contact_time
from pdps_granular_contact.contact_state import CONTACT_RADIUS, DELTA, FN, R_EFF

from .base import GranularSubModel, StyleArgs


@njit(cache=True)
def hertz_force(c, k, hist, h):
    """k: the stiffness (4/3 E* for hertz/material)."""
    a = math.sqrt(c[DELTA] * c[R_EFF])
    c[CONTACT_RADIUS] = a
    c[FN] = k[0] * a * c[DELTA]


class HertzCoefficients(StyleArgs):
    k_n: float = param(ge=0, unit="pressure")
    eta_n0: float = param(ge=0, unit="as the formula")


class NormalHertz(GranularSubModel):
    kind = "granular.normal"
    name = "hertz"
    Args = HertzCoefficients
    compute = hertz_force

    def values(self, law, contact):
        return (law.args("normal").k_n,)

    def elastic_time(self, law, m_eff, r_eff, speed):
        """Hertz's 2.868 (m*^2 / (R* E*^2 v))^(1/5) with the E* = 3/4 k of this model's stiffness k."""
        stiffness = self.values(law, "pair")[0]
        if speed <= 0.0 or stiffness <= 0.0:
            return None
        return hertz_contact_time(0.75 * stiffness, r_eff, m_eff, speed)
