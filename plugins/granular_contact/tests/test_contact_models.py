"""PDPS's dem sub-models (pdps_granular_contact.dem: lsd, hertz, tangential spring), composed as
pair dem/* and the PDPS walls compose them, against closed-form results: one contact with a wall
integrated by a tiny velocity-Verlet loop (no simulation needed)."""

import math

import numpy as np
import pytest

from pdps_granular_contact import contact_models as cm
from pdps_granular_contact import contact_state as cs
from pdps_granular_contact.composition import ContactModel
from pdps_granular_contact.dem.base import Tables


def per_pair(value):
    table = np.zeros((2, 2))
    table[1, 1] = value
    return table


class DemLaw:
    """One contact of a body with a wall under the composed law of a dem pair style."""

    def __init__(self, normal, mu, limit_damping=False, **values):
        model = ContactModel("dem", {"normal": normal, "tangential": "spring"}, {"limit_damping": limit_damping})
        tables = dict(kn=0.0, cn=0.0, kt=0.0, ct=0.0, cn_per_root_mass=0.0, ct_over_cn=0.0, mu=mu, e_star=0.0,
                      g_star=0.0, beta=0.0)
        tables.update(values)
        self.coeff = model.bind(Tables(1, {name: per_pair(value) for name, value in tables.items()}))
        self.contact = model.kernels().contact
        self.c, self.spring = np.zeros(cs.SIZE), np.zeros(3)

    def __call__(self, overlap, n, v, dt, r_eff=0.25, m_eff=0.5):
        """The force on the body (3) of this overlap and velocity; the spring is kept."""
        c = self.c
        c[cs.R], c[cs.RADIUS_I], c[cs.RADIUS_J], c[cs.DELTA] = r_eff - overlap, r_eff, 0.0, overlap
        c[cs.R_EFF], c[cs.M_EFF], c[cs.MASS_I], c[cs.MASS_J], c[cs.WALL] = r_eff, m_eff, m_eff, 0.0, 1.0
        c[cs.NX:cs.NZ + 1], c[cs.VX:cs.VZ + 1] = n, v
        c[cs.WIX:cs.WJZ + 1] = 0.0
        c[cs.DT], c[cs.UPDATE], c[cs.DIMENSION] = dt, 1.0, 3.0
        self.contact(c, self.coeff, 1, 1, self.spring)
        return c[cs.FN] * c[cs.NX:cs.NZ + 1] + c[cs.FTX:cs.FTZ + 1]


def collide(law, v0, dt, m_star=0.5, r_star=0.25, steps=200000):
    """Head-on collision of a body of mass m* with a fixed wall: (restitution, contact time)."""
    n = np.array([1.0, 0.0, 0.0])
    overlap, v, t = 0.0, -v0, 0.0
    for _ in range(steps):
        force = law(max(overlap, 0.0), n, np.array([v, 0.0, 0.0]), dt, r_star, m_star) if overlap > 0 else np.zeros(3)
        v += 0.5 * dt * force[0] / m_star
        overlap -= v * dt
        if overlap <= 0.0 and t > 0.0:
            return v / v0, t
        force = law(overlap, n, np.array([v, 0.0, 0.0]), dt, r_star, m_star) if overlap > 0 else np.zeros(3)
        v += 0.5 * dt * force[0] / m_star
        t += dt
    raise AssertionError("contact did not end")


@pytest.mark.parametrize("e", [0.9, 0.5])
def test_linear_spring_dashpot_gives_the_requested_restitution_and_contact_time(e):
    kn, m_star = 2.0e5, 0.5
    cn = cm.lsd_damping(kn, m_star, e)
    tc = cm.lsd_contact_time(kn, cn, m_star)
    measured_e, measured_t = collide(DemLaw("lsd", 0.5, kn=kn, cn=cn), 1.0, tc / 2000, m_star)
    assert measured_e == pytest.approx(e, rel=2e-3)
    assert measured_t == pytest.approx(tc, rel=2e-3)


def test_hertz_elastic_contact_time():
    e_star, r_star, m_star, v0 = 5.0e6, 0.25, 0.5, 1.0
    tc = cm.hertz_contact_time(e_star, r_star, m_star, v0)
    law = DemLaw("hertz", 0.5, e_star=e_star, g_star=1.0e6, beta=0.0)
    measured_e, measured_t = collide(law, v0, tc / 4000, m_star, r_star)
    assert measured_e == pytest.approx(1.0, abs=1e-3)
    assert measured_t == pytest.approx(tc, rel=5e-3)


def test_coulomb_limit_and_spring_in_the_tangent_plane():
    n = np.array([0.0, 0.0, 1.0])
    law = DemLaw("lsd", 0.5, kn=1000.0, kt=100.0)
    # sticking: small tangential velocity, spring force -kt * v dt
    force = law(0.01, n, np.array([0.1, 0.0, 0.0]), 0.01)
    assert law.c[cs.FN] == pytest.approx(10.0)
    assert force[0] == pytest.approx(-100.0 * 0.1 * 0.01)
    # sliding: a large displacement is cut to mu * Fn and the spring shortened to match
    law.spring[:] = [1.0, 0.0, 0.3]            # out-of-plane part is turned into the tangent plane
    force = law(0.01, n, np.zeros(3), 0.01)
    assert math.hypot(force[0], force[1]) == pytest.approx(0.5 * 10.0)
    assert law.spring[2] == pytest.approx(0.0) and 100.0 * math.hypot(*law.spring[:2]) == pytest.approx(5.0)


def test_limit_damping_never_pulls():
    n = np.array([1.0, 0.0, 0.0])
    separating_fast = np.array([10.0, 0.0, 0.0])
    assert DemLaw("lsd", 0.5, kn=1e3, cn=50.0)(1e-4, n, separating_fast, 1e-3)[0] < 0
    force = DemLaw("lsd", 0.5, limit_damping=True, kn=1e3, cn=50.0)(1e-4, n, separating_fast, 1e-3)
    assert force[0] == 0.0
