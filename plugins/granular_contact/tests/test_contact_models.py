"""The shared granular contact laws against closed-form results, integrated here with a tiny
two-body velocity-Verlet loop (no simulation needed)."""

import math

import numpy as np
import pytest

from pdps_granular_contact import contact_models as cm


def collide(law, v0, m_star, dt, steps=200000):
    """Head-on collision of a body of mass m* with a fixed wall: (restitution, contact time)."""
    n = np.array([1.0, 0.0, 0.0])
    overlap, v, t, shear = 0.0, -v0, 0.0, np.zeros(3)
    force = np.zeros(3)
    for _ in range(steps):
        force[:] = 0.0
        law(overlap, n, np.array([v, 0.0, 0.0]), shear, force)
        v += 0.5 * dt * force[0] / m_star
        overlap -= v * dt
        if overlap <= 0.0 and t > 0.0:
            return v / v0, t
        force[:] = 0.0
        law(overlap, n, np.array([v, 0.0, 0.0]), shear, force)
        v += 0.5 * dt * force[0] / m_star
        t += dt
    raise AssertionError("contact did not end")


@pytest.mark.parametrize("e", [0.9, 0.5])
def test_linear_spring_dashpot_gives_the_requested_restitution_and_contact_time(e):
    kn, m_star = 2.0e5, 0.5
    cn = cm.lsd_damping(kn, m_star, e)
    tc = cm.lsd_contact_time(kn, cn, m_star)
    law = lambda d, n, v, s, f: cm.lsd_contact(d, n, v, s, kn, cn, 0.0, 0.0, 0.5, tc / 2000, False, f)
    measured_e, measured_t = collide(law, 1.0, m_star, tc / 2000)
    assert measured_e == pytest.approx(e, rel=2e-3)
    assert measured_t == pytest.approx(tc, rel=2e-3)


def test_hertz_elastic_contact_time():
    e_star, r_star, m_star, v0 = 5.0e6, 0.25, 0.5, 1.0
    tc = cm.hertz_contact_time(e_star, r_star, m_star, v0)
    law = lambda d, n, v, s, f: cm.hertz_contact(d, n, v, s, e_star, 1.0e6, r_star, m_star, 0.0, 0.5,
                                                 tc / 4000, False, f)
    measured_e, measured_t = collide(law, v0, m_star, tc / 4000)
    assert measured_e == pytest.approx(1.0, abs=1e-3)
    assert measured_t == pytest.approx(tc, rel=5e-3)


def test_coulomb_limit_and_spring_in_the_tangent_plane():
    n = np.array([0.0, 0.0, 1.0])
    shear = np.array([0.0, 0.0, 0.0])
    force = np.zeros(3)
    # sticking: small tangential velocity, spring force -kt * v dt
    fn = cm.lsd_contact(0.01, n, np.array([0.1, 0.0, 0.0]), shear, 1000.0, 0.0, 100.0, 0.0, 0.5, 0.01, False, force)
    assert fn == pytest.approx(10.0)
    assert force[0] == pytest.approx(-100.0 * 0.1 * 0.01)
    # sliding: a large displacement is cut to mu * Fn and the spring shortened to match
    shear[:] = [1.0, 0.0, 0.3]            # out-of-plane part is turned into the tangent plane
    force[:] = 0.0
    cm.lsd_contact(0.01, n, np.zeros(3), shear, 1000.0, 0.0, 100.0, 0.0, 0.5, 0.01, False, force)
    assert math.hypot(force[0], force[1]) == pytest.approx(0.5 * 10.0)
    assert shear[2] == pytest.approx(0.0) and 100.0 * math.hypot(*shear[:2]) == pytest.approx(5.0)


def test_limit_damping_never_pulls():
    n = np.array([1.0, 0.0, 0.0])
    force = np.zeros(3)
    separating_fast = np.array([10.0, 0.0, 0.0])
    assert cm.lsd_contact(1e-4, n, separating_fast, np.zeros(3), 1e3, 50.0, 0, 0, 0.5, 1e-3, False, force) < 0
    force[:] = 0.0
    assert cm.lsd_contact(1e-4, n, separating_fast, np.zeros(3), 1e3, 50.0, 0, 0, 0.5, 1e-3, True, force) == 0.0
    assert force[0] == 0.0
