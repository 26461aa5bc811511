r"""What granular contacts share beyond their sub-models: the contact mass (a rigid body's), the
effective moduli and damping constants of two materials, the durations of contacts (time-step
advice) and the area where two spheres intersect.

- :math:`1/E^* = (1-\nu_i^2)/Y_i + (1-\nu_j^2)/Y_j`, :math:`1/G^* = 2(2-\nu_i)(1+\nu_i)/Y_i +
  2(2-\nu_j)(1+\nu_j)/Y_j`, :math:`\beta = \ln e/\sqrt{\ln^2 e + \pi^2}` (LIGGGHTS's);
- a linear spring-dashpot's damping for restitution e, :math:`C_n = 2\zeta\sqrt{k_nm^*}`,
  :math:`\zeta = -\ln e/\sqrt{\pi^2 + \ln^2 e}`, and its contact time
  :math:`\pi/\sqrt{k_n/m^* - (C_n/2m^*)^2}`;
- Hertz's elastic contact time :math:`2.868\,(m^{*2}/(R^*E^{*2}v))^{1/5}` and the Rayleigh time
  :math:`\pi R\sqrt{\rho/G}/(0.1631\nu + 0.8766)`.

The laws themselves are sub-models (``pdps_granular_contact.gran``, ``.dem``), composed by
``pdps_granular_contact.composition``; LAMMPS's classic ones are ``lammps_classic``.
"""

import math

import numpy as np
from numba import njit

HERTZ_DAMPING = 2.0 * math.sqrt(5.0 / 6.0)
# body_mass where no fix provides it
NO_BODY_MASS = np.zeros(0)
# the surface liquid contents and fluxes a contact loop takes where no wet model is composed
NO_LIQUID = (np.zeros(0), np.zeros(0))


@njit(cache=True)
def contact_mass(rmass, body_mass, i):
    """The mass particle i brings to a contact's effective mass: its rigid body's where a fix of
    rigid bodies provides ``body_mass`` and i is in a body (> 0), else its own (LAMMPS's pair gran/*,
    pair granular and fix wall/gran with mass_rigid from fix rigid's extract("masstotal"))."""
    body = body_mass[i] if len(body_mass) > 0 else 0.0
    # no inline="always" and no early return: either left array reference counting (atomic,
    # out-of-line calls) in the callers' pair loops
    return body if body > 0.0 else rmass[i]


def youngs_effective(youngs_i, poisson_i, youngs_j, poisson_j):
    """E* of two materials: 1/E* = (1 - nu_i^2)/Y_i + (1 - nu_j^2)/Y_j."""
    return 1.0 / ((1.0 - poisson_i ** 2) / youngs_i + (1.0 - poisson_j ** 2) / youngs_j)


def shear_effective(youngs_i, poisson_i, youngs_j, poisson_j):
    """G* of two materials: 1/G* = 2(2 - nu_i)(1 + nu_i)/Y_i + 2(2 - nu_j)(1 + nu_j)/Y_j."""
    return 1.0 / (2.0 * (2.0 - poisson_i) * (1.0 + poisson_i) / youngs_i
                  + 2.0 * (2.0 - poisson_j) * (1.0 + poisson_j) / youngs_j)


def restitution_beta(e):
    """LIGGGHTS's damping parameter from the restitution coefficient (0 < e <= 1)."""
    log_e = math.log(e)
    return log_e / math.sqrt(log_e * log_e + math.pi * math.pi)


def lsd_damping(kn, m_star, e):
    """C_n giving restitution e for a linear spring kn and effective mass m*:
    e = exp(-pi zeta / sqrt(1 - zeta^2)), C_n = 2 zeta sqrt(kn m*)."""
    log_e = math.log(e)
    zeta = -log_e / math.sqrt(math.pi * math.pi + log_e * log_e)
    return 2.0 * zeta * math.sqrt(kn * m_star)


def lsd_contact_time(kn, cn, m_star):
    """Duration of a linear spring-dashpot contact: pi / sqrt(kn/m* - (C_n / 2m*)^2)."""
    return math.pi / math.sqrt(kn / m_star - (cn / (2.0 * m_star)) ** 2)


def spring_dashpot_time(kn, gamma_n, m_star):
    """Duration of a linear spring-dashpot contact F = kn delta - gamma_n v_n: pi / sqrt(kn/m* -
    (gamma_n / 2m*)^2); an overdamped one counts with its undamped pi sqrt(m*/kn)."""
    rate = kn / m_star - (gamma_n / (2.0 * m_star)) ** 2
    return math.pi / math.sqrt(rate) if rate > 0.0 else math.pi * math.sqrt(m_star / kn)


def hertz_contact_time(e_star, r_star, m_star, v_impact):
    """Duration of an elastic Hertz contact at impact speed v: 2.868 (m*^2 / (R* E*^2 v))^(1/5)."""
    return 2.868 * (m_star ** 2 / (r_star * e_star ** 2 * v_impact)) ** 0.2


def rayleigh_time(radius, density, shear_modulus, poisson):
    """Rayleigh time pi R sqrt(rho/G) / (0.1631 nu + 0.8766), as LIGGGHTS's check/timestep/gran."""
    return math.pi * radius * math.sqrt(density / shear_modulus) / (0.1631 * poisson + 0.8766)


def intersection_area(r, ri, rj):
    """pi a^2 of the circle where spheres at distances r intersect (arrays); the smaller one's
    cross-section once its centre is inside the other, as the cohesion laws (contact_area) and
    LIGGGHTS 3.8's heat transfer take it."""
    circle = -0.25 * math.pi * (r - ri - rj) * (r + ri - rj) * (r - ri + rj) * (r + ri + rj) / r ** 2
    return np.where(r < np.maximum(ri, rj), math.pi * np.minimum(ri, rj) ** 2, circle)
