r"""Normal model ``dmt`` of LAMMPS's pair granular: Hertz's force less the constant pull of
Derjaguin, Muller and Toporov's adhesion,

.. math::

    F_{ne} = \tfrac43 E^* a\delta - F_{po}, \qquad F_{po} = 4\pi\gamma R^*, \qquad a = \sqrt{\delta R^*}

with E* as hertz/material's and γ the surface energy density (the work of adhesion is 2γ). The
Coulomb limits of the tangential, rolling and twisting models read :math:`F_{n,crit} = |F_{ne} +
2F_{po}|`, not the total normal force (LAMMPS's set_fncrit). The contact ends at :math:`\delta = 0`.
Coefficients: ``E`` Young's modulus (pressure, > 0), ``eta_n0`` (the damping coefficient, in the
damping model's unit), ``nu`` Poisson's ratio (dimensionless), ``gamma`` the surface energy density
(energy/area, >= 0). Mixed as hertz/material, γ as the geometric mean. Cannot be used with
``limit_damping``, nor with tsuji or coeff_restitution damping (LAMMPS refuses both).

Syntax: ``pair_coeff I J dmt E eta_n0 nu gamma damping ... tangential ...``
(LAMMPS's pair granular; Derjaguin et al., J. Colloid Interface Sci. 53, 314 (1975)).
"""

import math

from numba import njit

from pdps_core.api import param

from pdps_granular_contact.contact_state import CONTACT_RADIUS, DELTA, FN, FN_LIMIT, R_EFF

from .base import GranularSubModel, StyleArgs
from .normal_hertz_material import material_time, mix_material, modulus


@njit(cache=True)
def dmt_force(c, k, hist, h):
    """k: 4/3 E*, gamma."""
    a = math.sqrt(c[DELTA] * c[R_EFF])
    c[CONTACT_RADIUS] = a
    pulloff = 4.0 * math.pi * k[1] * c[R_EFF]
    elastic = k[0] * a * c[DELTA] - pulloff
    c[FN] = elastic
    c[FN_LIMIT] = abs(elastic + 2.0 * pulloff)


class AdhesiveCoefficients(StyleArgs):
    E: float = param(gt=0, unit="pressure")
    eta_n0: float = param(ge=0, unit="as the formula")
    nu: float = param(gt=-1, le=0.5, unit="dimensionless")
    gamma: float = param(ge=0, unit="energy/area")


class NormalDMT(GranularSubModel):
    kind = "granular.normal"
    name = "dmt"
    Args = AdhesiveCoefficients
    compute = dmt_force
    material = True
    cohesive = True

    mix = classmethod(mix_material)
    elastic_time = material_time

    def values(self, law, contact):
        return (4.0 / 3.0 * modulus(law), law.args("normal").gamma)
