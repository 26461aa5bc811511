r"""Granular contact laws shared by pair styles and walls (numba functions over scalars and 3-vectors).

A contact between body i and body j (a particle or a wall) with overlap :math:`\delta > 0`, unit normal
:math:`\mathbf{n}` pointing from j to i, and relative velocity of the contact points
:math:`\mathbf{v} = \mathbf{v}_i - \mathbf{v}_j - (R_i \boldsymbol{\omega}_i + R_j \boldsymbol{\omega}_j)
\times \mathbf{n}` (the contact point lies at :math:`-R_i\mathbf{n}` from i and :math:`+R_j\mathbf{n}` from j) splits into :math:`v_n = \mathbf{v}\cdot\mathbf{n}` and
:math:`\mathbf{v}_t = \mathbf{v} - v_n \mathbf{n}`. The tangential spring :math:`\boldsymbol{\xi}`
(history, kept per contact) grows by :math:`\mathbf{v}_t \Delta t`, is turned into the current tangent
plane, and is truncated so that Coulomb's law :math:`|\mathbf{F}_t| \le \mu |F_n|` holds (LAMMPS's
gran/hooke/history and gran/hertz/history; LIGGGHTS's tangential_history).

Linear spring-dashpot (``lsd``, PDPS manual's dem/lsd):

.. math::

    F_n = k_n \delta - C_n v_n, \qquad \mathbf{F}_t = -k_t \boldsymbol{\xi} - C_t \mathbf{v}_t

Hertz-Mindlin (``hertz``, LIGGGHTS's hertz model), with effective radius :math:`R^*`, mass :math:`m^*`,
Young's modulus :math:`E^*` and shear modulus :math:`G^*`, and :math:`\beta = \ln e /
\sqrt{\ln^2 e + \pi^2}`:

.. math::

    S_n = 2E^*\sqrt{R^*\delta},\ S_t = 8G^*\sqrt{R^*\delta},\ k_n = \tfrac43 E^*\sqrt{R^*\delta},\
    k_t = S_t,\ C_n = -2\sqrt{5/6}\,\beta\sqrt{S_n m^*},\ C_t = -2\sqrt{5/6}\,\beta\sqrt{S_t m^*}

and the same force expressions. Near the end of a contact the damping can make :math:`F_n < 0` (a
pull); as in LAMMPS this is kept by default, which gives the analytic restitution coefficient exactly,
and ``limit_damping=True`` (LAMMPS's keyword of that name) sets it to zero instead.

Each law writes the force on i into ``force`` (the force on j is its negative), updates ``shear`` in
place, and returns :math:`F_n`.
"""

import math

import numpy as np
from numba import njit

HERTZ_DAMPING = 2.0 * math.sqrt(5.0 / 6.0)
# body_mass where no fix provides it
NO_BODY_MASS = np.zeros(0)


@njit(cache=True)
def contact_mass(rmass, body_mass, i):
    """The mass particle i brings to a contact's effective mass: its rigid body's where a fix of
    rigid bodies provides ``body_mass`` and i is in a body (> 0), else its own (LAMMPS's pair gran/*,
    pair granular and fix wall/gran with mass_rigid from fix rigid's extract("masstotal"))."""
    body = body_mass[i] if len(body_mass) > 0 else 0.0
    # no inline="always" and no early return: either left array reference counting (atomic,
    # out-of-line calls) in the callers' pair loops
    return body if body > 0.0 else rmass[i]


@njit(cache=True)
def _spring_dashpot(overlap, n, v, shear, kn, cn, kt, ct, mu, dt, limit_damping, force):
    """Both laws once their stiffnesses and dampings are known for this overlap: F_n = kn delta -
    cn v_n along n, then the tangential spring with its Coulomb limit. Vectors of one contact are
    kept in scalars: the function runs for every contact of every step, and allocates nothing."""
    vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2]
    vt0 = v[0] - vn * n[0]
    vt1 = v[1] - vn * n[1]
    vt2 = v[2] - vn * n[2]
    fn = kn * overlap - cn * vn
    if limit_damping and fn < 0.0:
        fn = 0.0
    for d in range(3):
        force[d] += fn * n[d]
    # keep the spring in the tangent plane of the current normal, with its length
    length = math.sqrt(shear[0] ** 2 + shear[1] ** 2 + shear[2] ** 2)
    along = shear[0] * n[0] + shear[1] * n[1] + shear[2] * n[2]
    for d in range(3):
        shear[d] -= along * n[d]
    turned = math.sqrt(shear[0] ** 2 + shear[1] ** 2 + shear[2] ** 2)
    if turned > 0.0:
        for d in range(3):
            shear[d] *= length / turned
    shear[0] += vt0 * dt
    shear[1] += vt1 * dt
    shear[2] += vt2 * dt
    ft0 = -kt * shear[0] - ct * vt0
    ft1 = -kt * shear[1] - ct * vt1
    ft2 = -kt * shear[2] - ct * vt2
    ft_mag = math.sqrt(ft0 ** 2 + ft1 ** 2 + ft2 ** 2)
    limit = mu * abs(fn)
    if ft_mag > limit:
        # sliding: the spring is cut back to what Coulomb's limit allows
        if ft_mag > 0.0:
            scale = limit / ft_mag
            ft0 *= scale
            ft1 *= scale
            ft2 *= scale
            shear[0] = -(ft0 + ct * vt0) / kt if kt > 0.0 else 0.0
            shear[1] = -(ft1 + ct * vt1) / kt if kt > 0.0 else 0.0
            shear[2] = -(ft2 + ct * vt2) / kt if kt > 0.0 else 0.0
    force[0] += ft0
    force[1] += ft1
    force[2] += ft2
    return fn


@njit(cache=True)
def lsd_contact(overlap, n, v, shear, kn, cn, kt, ct, mu, dt, limit_damping, force):
    """Linear spring-dashpot with Coulomb friction; returns F_n, adds the force on i to ``force``."""
    return _spring_dashpot(overlap, n, v, shear, kn, cn, kt, ct, mu, dt, limit_damping, force)


@njit(cache=True)
def hertz_contact(overlap, n, v, shear, e_star, g_star, r_star, m_star, beta, mu, dt, limit_damping,
                  force):
    """Hertz-Mindlin with Coulomb friction; returns F_n, adds the force on i to ``force``."""
    root = math.sqrt(r_star * overlap)
    sn = 2.0 * e_star * root
    st = 8.0 * g_star * root
    kn = 4.0 / 3.0 * e_star * root
    cn = -HERTZ_DAMPING * beta * math.sqrt(sn * m_star)
    ct = -HERTZ_DAMPING * beta * math.sqrt(st * m_star)
    return _spring_dashpot(overlap, n, v, shear, kn, cn, st, ct, mu, dt, limit_damping, force)


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
