r"""Normal model ``jkr`` of LAMMPS's pair granular: the adhesive elastic contact of Johnson, Kendall
and Roberts. The contact radius a solves JKR's relation of the overlap,

.. math::

    \delta = \frac{a^2}{R^*} - 2\sqrt{\frac{\pi\gamma a}{E^*}}

(the root LAMMPS's calculate_contact_radius writes in closed form), and

.. math::

    F_{ne} = \frac{4E^*a^3}{3R^*} - 2\pi a^2\sqrt{\frac{4\gamma E^*}{\pi a}}, \qquad
    F_{n,crit} = |F_{ne} + 2F_{po}|, \quad F_{po} = 3\pi\gamma R^*

with E* as hertz/material's and γ the surface energy density (JKR's pull-off force :math:`\tfrac32
\pi wR^*` of the work of adhesion w = 2γ). Spheres touch when they first overlap; once touching, the
contact lasts while they are closer than :math:`R_i + R_j + \delta_{po}`, :math:`\delta_{po} =
(3\pi^2/16)^{1/3}(R^*\gamma^2/E^{*2})^{1/3}` (a neck holds them at negative overlap until it
breaks); the neighbor cutoff of the types covers that distance. The contact's history slot (one
value) is what says it touched (LAMMPS's touch flag). Coefficients: ``E`` (pressure, > 0),
``eta_n0`` (the damping coefficient, in the damping model's unit), ``nu`` (dimensionless),
``gamma`` (energy/area, >= 0); mixed as dmt's. Cannot be used with ``limit_damping``, tsuji or
coeff_restitution (LAMMPS refuses them).

Syntax: ``pair_coeff I J jkr E eta_n0 nu gamma damping ... tangential ...``
(LAMMPS's pair granular; Johnson, Kendall & Roberts, Proc. R. Soc. Lond. A 324, 301 (1971)).
"""

import math

from numba import njit

from pdps_granular_contact.contact_state import CONTACT_RADIUS, DELTA, FN, FN_LIMIT, R_EFF

from .base import GranularSubModel
from .normal_dmt import AdhesiveCoefficients
from .normal_hertz_material import material_time, mix_material, modulus

SQRT6 = math.sqrt(6.0)
PULLOFF_PREFIX = (3.0 * math.pi * math.pi / 16.0) ** (1.0 / 3.0)


@njit(cache=True)
def cbrt(x):
    """The real cube root (numba has no math.cbrt)."""
    return math.copysign(abs(x) ** (1.0 / 3.0), x)


@njit(cache=True)
def jkr_contact_radius(r_eff, overlap, gamma, modulus):
    """The root a of JKR's overlap relation, LAMMPS's closed form (negative radicands clipped)."""
    d_r = overlap * r_eff
    r2 = r_eff * r_eff
    t0 = gamma * gamma * r2 * r2 * modulus
    t1 = 27.0 * math.pi * math.pi * t0
    t2 = 8.0 * d_r * d_r * d_r * modulus * modulus * modulus
    t3 = 4.0 * d_r * d_r * modulus
    t4 = cbrt(t1 + t2 + 3.0 * math.sqrt(3.0) * math.pi * math.sqrt(max(0.0, t0 * (t1 + 2.0 * t2))))
    t5 = t3 / t4 + t4 / modulus
    t6 = math.sqrt(max(0.0, 2.0 * d_r + t5))
    return (t6 + math.sqrt(max(0.0, 4.0 * d_r - t5 + 6.0 * SQRT6 * gamma * math.pi * r2 / (modulus * t6)))) / SQRT6


@njit(cache=True)
def jkr_force(c, k, hist, h):
    """k: E*, gamma."""
    r_eff = c[R_EFF]
    a = jkr_contact_radius(r_eff, c[DELTA], k[1], k[0])
    c[CONTACT_RADIUS] = a
    # no area (gamma 0 at delta 0): no neck either
    neck = 2.0 * math.pi * a * a * math.sqrt(4.0 * k[1] * k[0] / (math.pi * a)) if a > 0.0 else 0.0
    elastic = 4.0 / 3.0 * k[0] * a * a * a / r_eff - neck
    c[FN] = elastic
    c[FN_LIMIT] = abs(elastic + 6.0 * math.pi * k[1] * r_eff)


@njit(cache=True)
def jkr_pulloff_distance(k, radius_i, radius_j):
    """How far beyond touching (centre distance R_i + R_j) a JKR contact breaks. k: E*, gamma."""
    r_eff = radius_i * radius_j / (radius_i + radius_j) if radius_j > 0.0 else radius_i
    return PULLOFF_PREFIX * cbrt(r_eff * k[1] * k[1] / (k[0] * k[0]))


class NormalJKR(GranularSubModel):
    kind = "granular.normal"
    name = "jkr"
    Args = AdhesiveCoefficients
    compute = jkr_force
    pulloff = jkr_pulloff_distance
    history_width = 1
    material = True
    cohesive = True

    mix = classmethod(mix_material)
    elastic_time = material_time

    def values(self, law, contact):
        return (modulus(law), law.args("normal").gamma)
