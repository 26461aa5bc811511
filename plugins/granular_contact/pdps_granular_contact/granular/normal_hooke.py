r"""Normal model ``hooke`` of LAMMPS's pair granular: a linear spring,

.. math::

    F_{ne} = k_n\delta

with the overlap :math:`\delta`; the damping model adds its force (:math:`-\eta_n v_n`, η_n from
the damping coefficient η_n0 below). Coefficients: ``k_n`` (force/distance, >= 0), ``eta_n0``
(the damping coefficient, its unit the damping model's: mass/time for velocity, 1/time for
mass_velocity, 1/(time distance) for viscoelastic, dimensionless for tsuji and coeff_restitution,
which read it as a restitution coefficient). Mixed between types as the geometric mean of each.
The contact radius :math:`a = \sqrt{\delta R^*}` is what models that need one read.

Syntax: ``pair_coeff I J hooke k_n eta_n0 damping ... tangential ...``
(LAMMPS's pair granular; Brilliantov et al., Phys. Rev. E 53, 5382 (1996)).
"""

import math

from numba import njit

from pdps_core.api import param

from pdps_granular_contact.contact_state import CONTACT_RADIUS, DELTA, FN, R_EFF

from .base import GranularSubModel, StyleArgs


@njit(cache=True)
def hooke_force(c, k, hist, h):
    """k: k_n."""
    c[CONTACT_RADIUS] = math.sqrt(c[DELTA] * c[R_EFF])
    c[FN] = k[0] * c[DELTA]


class HookeCoefficients(StyleArgs):
    k_n: float = param(ge=0, unit="force/distance")
    eta_n0: float = param(ge=0, unit="as the formula")


class NormalHooke(GranularSubModel):
    kind = "granular.normal"
    name = "hooke"
    Args = HookeCoefficients
    compute = hooke_force

    def values(self, law, contact):
        return (law.args("normal").k_n,)

    def elastic_time(self, law, m_eff, r_eff, speed):
        """Half the period of the linear spring, pi sqrt(m*/k_n)."""
        k_n = law.args("normal").k_n
        return math.pi * math.sqrt(m_eff / k_n) if k_n > 0.0 else None
