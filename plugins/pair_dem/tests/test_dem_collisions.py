"""Head-on collisions of two spheres: the measured restitution coefficient and contact time against
the closed-form spring-dashpot result (dem/lsd) and the damped Hertz contact (dem/hertz)."""

import math

import numpy as np
import pytest

from pdps_core.testing import sphere_mass
from pdps_granular_contact import contact_models as cm

V0 = 1.0            # each sphere approaches at V0, so the impact speed is 2 V0
STEPS_PER_CONTACT = 500


def collide(dem, pair, coeffs, tc, first, second, ntypes=1):
    """Two spheres (type, diameter, density) approaching head-on along x; returns (restitution,
    contact time measured as the number of force evaluations in contact times dt, dt)."""
    (t1, d1, rho1), (t2, d2, rho2) = first, second
    dt = tc / STEPS_PER_CONTACT
    contact = 0.5 * (d1 + d2)
    # they touch half a step after the start, and have parted well before the end
    gap = 2.0 * V0 * 0.5 * dt
    sim = dem.spheres(pair, coeffs,
                      [(t1, 4.0, 5, 5, d1, rho1), (t2, 4.0 + contact + gap, 5, 5, d2, rho2)], ntypes=ntypes,
                      extra=f"timestep {dt!r}\nfix rec all test/dem/record\nfix move all test/nve_sphere")
    m1, m2 = sphere_mass(d1, rho1), sphere_mass(d2, rho2)
    # centre-of-mass frame, so the pair stays in the box
    dem.set_motion(sim, 1, v=(2 * V0 * m2 / (m1 + m2), 0, 0))
    dem.set_motion(sim, 2, v=(-2 * V0 * m1 / (m1 + m2), 0, 0))
    sim.command(f"run {int(1.2 * STEPS_PER_CONTACT) + 2}")
    record = sim.fixes["rec"]
    in_contact = sum(1 for f in record.forces if np.any(f != 0.0))
    v = record.v[-1]
    assert not np.any(record.forces[-1]), "the spheres must have parted before the end"
    assert np.sum([m1, m2] * v[:, 0]) == pytest.approx(0.0, abs=1e-12)      # momentum conserved
    return -(v[0, 0] - v[1, 0]) / (2.0 * V0), in_contact * dt, dt


@pytest.mark.parametrize("e, second", [(0.9, (1, 1.0, 1.0)), (0.5, (1, 1.0, 1.0)),
                                       (0.5, (2, 0.6, 4.0))])
def test_lsd_restitution_and_contact_time(dem, e, second):
    """Damping from e and the masses of each contact: any two spheres bounce with e after the
    spring-dashpot time pi / sqrt(kn/m* - (Cn/2m*)^2)."""
    kn = 1.0e4
    first = (1, 1.0, 1.0)
    m1, m2 = sphere_mass(*first[1:]), sphere_mass(*second[1:])
    m_star = m1 * m2 / (m1 + m2)
    tc = cm.lsd_contact_time(kn, cm.lsd_damping(kn, m_star, e), m_star)
    restitution, duration, dt = collide(dem, "dem/lsd 0.3 1.0", [f"* * kn {kn} e {e} mu 0.5"], tc,
                                        first, second, ntypes=2)
    assert restitution == pytest.approx(e, rel=0.01)
    assert duration == pytest.approx(tc, rel=0.02)
    assert abs(duration - tc) <= 1.5 * dt        # the contact is resolved to a step


def test_lsd_pdps_example_coefficients_bounce_as_their_fixed_damping_says(dem):
    """``pair_coeff * * 1000 16.6016 314.29 6.3008 0.5 1``: unit spheres (m* = pi/12) bounce with
    e = 0.153, not the pair_style's 0.3, which PDPS does not use (docstring)."""
    kn, cn = 1000.0, 16.6016
    m_star = math.pi / 12.0
    zeta = cn / (2.0 * math.sqrt(kn * m_star))
    e = math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta * zeta))
    assert e == pytest.approx(0.153, abs=5e-4)
    tc = cm.lsd_contact_time(kn, cn, m_star)
    restitution, duration, _ = collide(dem, "dem/lsd 0.3 1.0", ["* * 1000 16.6016 314.29 6.3008 0.5 1"], tc,
                                       (1, 1.0, 1.0), (1, 1.0, 1.0))
    assert restitution == pytest.approx(e, rel=0.01)
    assert duration == pytest.approx(tc, rel=0.02)


def damped_hertz(beta, dtau=5.0e-4):
    """Reference solution of the damped Hertz contact, independent of the pair style: in units of
    the impact speed v and T = (m*^2 / (k^2 v))^(1/5), k = 4/3 E* sqrt(R*), the overlap obeys
    s'' = -s^(3/2) - sqrt(5) |beta| s^(1/4) s', s(0) = 0, s'(0) = 1 (RK4). Returns (contact duration
    in units of T, restitution)."""
    damping = math.sqrt(5.0) * abs(beta)

    def rate(s, u):
        s = max(s, 0.0)
        return u, -s ** 1.5 - damping * s ** 0.25 * u

    s, u, t = 0.0, 1.0, 0.0
    while True:
        k1 = rate(s, u)
        k2 = rate(s + 0.5 * dtau * k1[0], u + 0.5 * dtau * k1[1])
        k3 = rate(s + 0.5 * dtau * k2[0], u + 0.5 * dtau * k2[1])
        k4 = rate(s + dtau * k3[0], u + dtau * k3[1])
        s_new = s + dtau / 6.0 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        u_new = u + dtau / 6.0 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
        if s_new <= 0.0:
            share = s / (s - s_new)
            return t + share * dtau, -(u + share * (u_new - u))
        s, u, t = s_new, u_new, t + dtau


def test_the_damped_hertz_reference_is_the_hertz_time_without_damping():
    duration, restitution = damped_hertz(0.0)
    e_star, r_star, m_star, v = 2.0e6, 0.3, 0.7, 1.3
    scale = (m_star ** 2 / ((4.0 / 3.0 * e_star) ** 2 * r_star * v)) ** 0.2
    assert duration * scale == pytest.approx(cm.hertz_contact_time(e_star, r_star, m_star, v), rel=2e-4)
    assert restitution == pytest.approx(1.0, abs=1e-6)


@pytest.mark.parametrize("e, second, coeffs", [
    (0.9, (1, 1.0, 1.0), ["* * 1.0e6 0.3 0.9 0.5"]),
    (0.5, (1, 1.0, 1.0), ["* * 1.0e6 0.3 0.5 0.5"]),
    # two materials: E* and G* combine type 1's and type 2's own Young's modulus and Poisson ratio
    (0.5, (2, 0.8, 2.5), ["1 1 1.0e6 0.3 0.5 0.5", "2 2 3.0e6 0.2 0.5 0.5", "1 2 NULL NULL 0.5 0.5"]),
])
def test_hertz_restitution_and_contact_time(dem, e, second, coeffs):
    first = (1, 1.0, 1.0)
    y = {1: (1.0e6, 0.3), 2: (3.0e6, 0.2)}
    (y1, nu1), (y2, nu2) = y[first[0]], y[second[0]]
    e_star = 1.0 / ((1 - nu1 ** 2) / y1 + (1 - nu2 ** 2) / y2)
    r1, r2 = 0.5 * first[1], 0.5 * second[1]
    r_star = r1 * r2 / (r1 + r2)
    m1, m2 = sphere_mass(*first[1:]), sphere_mass(*second[1:])
    m_star = m1 * m2 / (m1 + m2)
    v = 2.0 * V0
    elastic = cm.hertz_contact_time(e_star, r_star, m_star, v)
    duration, expected_e = damped_hertz(cm.restitution_beta(e))
    tc = duration * (m_star ** 2 / ((4.0 / 3.0 * e_star) ** 2 * r_star * v)) ** 0.2
    assert expected_e == pytest.approx(e, rel=1e-4)      # this damping gives e at any speed
    restitution, measured, dt = collide(dem, "dem/hertz", coeffs, tc, first, second, ntypes=2)
    assert restitution == pytest.approx(e, rel=0.01)
    assert measured == pytest.approx(tc, rel=0.02)
    if e == 0.9:
        assert measured == pytest.approx(elastic, rel=0.02)   # light damping: near the elastic time
