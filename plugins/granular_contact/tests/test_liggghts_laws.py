"""LIGGGHTS's contact sub-models (pdps_granular_contact.gran, composed by
pdps_granular_contact.composition) against closed-form results: a sphere rolling on a plane stops
where each rolling-friction model's deceleration puts it, and the cohesion models' forces and
pull-off forces. Integrated here with a small velocity-Verlet loop over the composed law of one
contact, the plane being the law's wall (as fix wall/gran model calls it)."""

import math
from types import SimpleNamespace

import numpy as np
import pytest

from pdps_granular_contact import contact_state as cs
from pdps_granular_contact.composition import ContactModel
from pdps_granular_contact.material import Material
from pdps_granular_contact.contact_models import shear_effective, youngs_effective
from pdps_granular_contact.gran.cohesion_sjkr import sjkr_area

R, RHO, G = 0.005, 2500.0, 9.81
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
INERTIA = 0.4 * MASS * R ** 2
YOUNGS, POISSON = 5.0e6, 0.45
Y_STAR = youngs_effective(YOUNGS, POISSON, YOUNGS, POISSON)
G_STAR = shear_effective(YOUNGS, POISSON, YOUNGS, POISSON)


class Preset(Material):
    """One particle type's material given as numbers, not read from a script."""

    def __init__(self, values):
        self.sim, self.ntypes, self.who = SimpleNamespace(units=SimpleNamespace(nktv2p=1.0)), 1, "test"
        self._read, self.declared = dict(values), {}


def per_pair(value):
    table = np.zeros((2, 2))
    table[1, 1] = value
    return table


class Law:
    """The composed law of LIGGGHTS's words on one contact (type 1 with type 1)."""

    def __init__(self, rolling="off", cohesion="off", normal="hertz", mu_roll=0.0, eta_roll=0.0, k=0.0, e=0.5,
                 mu=0.5):
        chosen = {"normal": normal, "tangential": "history"}
        chosen.update({part: word for part, word in (("rolling", rolling), ("cohesion", cohesion)) if word != "off"})
        self.model = ContactModel("gran", chosen, {"tangential_damping": "on", "limitForce": "off"})
        material = Preset({"youngsModulus": np.array([0.0, YOUNGS]), "poissonsRatio": np.array([0.0, POISSON]),
                           "coefficientRestitution": per_pair(e), "coefficientFriction": per_pair(mu),
                           "coefficientRollingFriction": per_pair(mu_roll),
                           "coefficientRollingViscousDamping": per_pair(eta_roll),
                           "cohesionEnergyDensity": per_pair(k), "characteristicVelocity": 1.0,
                           "rollingStiffness": 2.25})
        self.coeff = self.model.bind(material)
        self.contact = self.model.kernels().contact
        self.c = np.zeros(cs.SIZE)
        self.hist = np.zeros(self.model.history_width)

    def at(self, what):
        return self.hist[self.model.history_at(what):]

    def __call__(self, r, radius_i, radius_j, n, v, w_i, w_j=(0.0, 0.0, 0.0), dt=1e-6, update=True):
        """The contact's quantities after the sub-models (contact_state slots); radius_j 0: a wall."""
        c, wall = self.c, radius_j == 0.0
        c[cs.R], c[cs.RADIUS_I], c[cs.RADIUS_J] = r, radius_i, radius_j
        c[cs.DELTA] = radius_i + radius_j - r
        c[cs.R_EFF] = radius_i if wall else radius_i * radius_j / (radius_i + radius_j)
        c[cs.MASS_I], c[cs.MASS_J] = MASS, 0.0 if wall else MASS
        c[cs.M_EFF] = MASS if wall else MASS / 2
        c[cs.WALL] = 1.0 if wall else 0.0
        c[cs.NX:cs.NZ + 1], c[cs.VX:cs.VZ + 1] = n, v
        c[cs.WIX:cs.WIZ + 1], c[cs.WJX:cs.WJZ + 1] = w_i, w_j
        c[cs.DT], c[cs.UPDATE], c[cs.DIMENSION] = dt, 1.0 if update else 0.0, 3.0
        self.contact(c, self.coeff, 1, 1, self.hist)
        return c

    def force(self):
        c = self.c
        return c[cs.FN] * c[cs.NX:cs.NZ + 1] + c[cs.FTX:cs.FTZ + 1]

    def tangential(self):
        return self.c[cs.FTX:cs.FTZ + 1].copy()

    def roll(self):
        return self.c[cs.MRX:cs.MRZ + 1].copy()


def resting_overlap():
    """Hertz overlap under the weight: m g = 4/3 Y* sqrt(R) delta^3/2."""
    return (MASS * G / (4.0 / 3.0 * Y_STAR * math.sqrt(R))) ** (2.0 / 3.0)


def roll(rolling, mu_roll, v0, dt=1e-5, eta_roll=0.01):
    """A sphere rolling without slipping along +x on the plane z = 0 under gravity, started at its
    resting overlap; returns (distance rolled when its velocity first reverses or vanishes, overlap)."""
    law = Law(rolling, mu_roll=mu_roll, eta_roll=eta_roll)
    delta = resting_overlap()
    x = np.array([0.0, 0.0, R - delta])
    arm = R - 0.5 * delta
    v = np.array([v0, 0.0, 0.0])
    w = np.array([0.0, v0 / arm, 0.0])
    n = np.array([0.0, 0.0, 1.0])

    def forces():
        r = x[2]
        a = R - 0.5 * (R - r)
        law(r, R, 0.0, n, v, w, dt=dt)
        f = law.force() + np.array([0.0, 0.0, -MASS * G])
        t = -a * np.cross(n, law.tangential()) - law.roll()
        return f, t

    f, t = forces()
    for step in range(2_000_000):
        v += 0.5 * dt * f / MASS
        w += 0.5 * dt * t / INERTIA
        x += dt * v
        f, t = forces()
        v += 0.5 * dt * f / MASS
        w += 0.5 * dt * t / INERTIA
        if v[0] <= 0.0:
            return x[0], delta
    raise AssertionError("the sphere did not stop")


def stop_distance(torque, v0, delta):
    """v0^2 / 2|a| with a = -M a_c / (I + m a_c^2): a rolling torque M opposing the spin of a
    sphere rolling without slip about its contact point, a_c = R - delta/2 from its centre."""
    arm = R - 0.5 * delta
    return v0 ** 2 / (2.0 * torque * arm / (INERTIA + MASS * arm ** 2))


@pytest.mark.parametrize("rolling, torque_of", [
    # cdt: mu_r k_n delta R against a wall (R* = R), k_n delta = m g at rest
    ("cdt", lambda mu_r, delta: mu_r * MASS * G * R),
    # epsd, epsd2: the spring torque capped at mu_r |F_n| R
    ("epsd", lambda mu_r, delta: mu_r * MASS * G * R),
    ("epsd2", lambda mu_r, delta: mu_r * MASS * G * R),
    # epsd3 with rollingStiffness 2.25: epsd's spring
    ("epsd3", lambda mu_r, delta: mu_r * MASS * G * R),
])
def test_a_rolling_sphere_stops_where_the_rolling_torque_puts_it(rolling, torque_of):
    """epsd's dashpot acts until the spring reaches its cap (some 50 steps here), unbounded by the
    cap: with eta_r = 0.3 it would take 4 % of the momentum there; eta_r = 0.01 keeps that at
    0.1 %, so the distance is the mobilised torque's."""
    mu_r, v0 = 0.1, 0.1
    distance, delta = roll(rolling, mu_r, v0)
    expected = stop_distance(torque_of(mu_r, delta), v0, delta)
    # measured: 0.003 % (cdt), 0.004 % (epsd2), 0.13 % (epsd, epsd3: the dashpot until the spring caps)
    assert distance == pytest.approx(expected, rel=0.005)
    # about 7 mm (1.4 diameters): 0.7 m/s^2 of deceleration
    assert 0.006 < expected < 0.008


def test_without_rolling_friction_the_sphere_rolls_on():
    """The same sphere without a rolling model keeps its speed: 0.1 m/s for 0.2 s is 20 mm."""
    distance, _ = roll_for("off", 20000)
    assert distance == pytest.approx(0.02, rel=1e-6)


def roll_for(rolling, steps, dt=1e-5):
    """Distance rolled in ``steps`` steps at 0.1 m/s (no stop expected)."""
    law = Law(rolling)
    delta = resting_overlap()
    x, v = np.array([0.0, 0.0, R - delta]), np.array([0.1, 0.0, 0.0])
    arm = R - 0.5 * delta
    w, n = np.array([0.0, 0.1 / arm, 0.0]), np.array([0.0, 0.0, 1.0])
    for _ in range(steps):
        law(x[2], R, 0.0, n, v, w, dt=dt)
        v += dt * (law.force() + [0.0, 0.0, -MASS * G]) / MASS
        w += dt * (-(R - 0.5 * (R - x[2])) * np.cross(n, law.tangential()) - law.roll()) / INERTIA
        x += dt * v
    return x[0], delta


def pair_force(cohesion, r, k, radius_i=R, radius_j=R):
    """Normal force of two spheres at rest, centres r apart (positive: repulsive)."""
    law = Law(cohesion=cohesion, k=k)
    zero = np.zeros(3)
    return law(r, radius_i, radius_j, np.array([1.0, 0.0, 0.0]), zero, zero, update=False)[cs.FN]


def hertz(delta, radius_i=R, radius_j=R):
    r_star = radius_i * radius_j / (radius_i + radius_j)
    return 4.0 / 3.0 * Y_STAR * math.sqrt(r_star * delta) * delta


@pytest.mark.parametrize("cohesion, area", [
    # the circle where two spheres of radii Ri, Rj at distance r intersect: pi a^2
    ("sjkr", lambda r, ri, rj: math.pi * (ri ** 2 - ((r * r + ri * ri - rj * rj) / (2 * r)) ** 2)),
    ("sjkr2", lambda r, ri, rj: 2 * math.pi * 2 * ri * rj / (ri + rj) * (ri + rj - r)),
])
@pytest.mark.parametrize("radius_j", [R, 0.5 * R])
def test_cohesion_force_is_k_times_the_contact_area(cohesion, area, radius_j):
    k = 5.0e4
    for delta in (1e-6, 1e-5, 1e-4):
        r = R + radius_j - delta
        expected = hertz(delta, R, radius_j) - k * area(r, R, radius_j)
        assert pair_force(cohesion, r, k, R, radius_j) == pytest.approx(expected, rel=1e-10)


@pytest.mark.parametrize("cohesion", ["sjkr", "sjkr2"])
def test_pull_off_force_of_two_spheres(cohesion):
    """Pulled apart slowly, two cohesive spheres of radius R resist at most with the pull-off force
    max over delta of k A(delta) - c delta^3/2, c = 4/3 Y* sqrt(R*): with sjkr A = pi (R delta -
    delta^2/4), the maximum at sqrt(delta) = (sqrt(9/4 c^2 + 2 pi^2 k^2 R) - 3/2 c) / (pi k); with
    sjkr2 A = 2 pi R delta, at sqrt(delta) = 4 pi k R / (3 c)."""
    k = 5.0e4
    c = 4.0 / 3.0 * Y_STAR * math.sqrt(R / 2)
    if cohesion == "sjkr":
        root = (math.sqrt(2.25 * c * c + 2 * math.pi ** 2 * k * k * R) - 1.5 * c) / (math.pi * k)
        pull_off = k * math.pi * (R * root ** 2 - root ** 4 / 4) - c * root ** 3
    else:
        root = 4 * math.pi * k * R / (3 * c)
        pull_off = k * 2 * math.pi * R * root ** 2 - c * root ** 3
    # the law, the spheres pulled apart from twice the overlap of the maximum in 2000 steps
    deltas = np.linspace(2 * root ** 2, 0.0, 2001)[:-1]
    pulled = min(pair_force(cohesion, 2 * R - d, k) for d in deltas)
    assert -pulled == pytest.approx(pull_off, rel=0.01)
    assert pull_off > 0.1 * MASS * G


@pytest.mark.parametrize("rolling", ["epsd", "epsd2"])
def test_rolling_spring_grows_then_caps_and_epsd_damps_below_the_cap(rolling):
    """One contact of two equal spheres spinning oppositely about z (n along x): the spring torque
    grows by k_r omega_r dt (k_r = 2.25 k_n mu_r^2 R*^2 for epsd, k_t R*^2 for epsd2); below the cap
    epsd adds eta_r 2 sqrt(I_r k_r) omega_r (not stored), I_r = 1.4 (m R^2)/2; the cap is
    mu_r |F_n| R*."""
    mu_r, eta, dt, delta = 0.3, 0.4, 1e-6, 2e-5
    law = Law(rolling, mu_roll=mu_r, eta_roll=eta)
    n, zero = np.array([1.0, 0.0, 0.0]), np.zeros(3)
    spin = np.array([0.0, 0.0, 4.0])
    r_star = R / 2
    y_star, g_star = Y_STAR, G_STAR
    kn = 4 / 3 * y_star * math.sqrt(r_star * delta)
    kt = 8 * g_star * math.sqrt(r_star * delta)
    kr = 2.25 * kn * mu_r ** 2 * r_star ** 2 if rolling == "epsd" else kt * r_star ** 2
    cap = mu_r * kn * delta * r_star
    damping = eta * 2 * math.sqrt(1.4 * MASS * R ** 2 / 2 * kr) if rolling == "epsd" else 0.0
    # spins +4 and -4 about z: the relative spin 8, the contact points rolling on each other
    for step in range(1, 4):
        c = law(2 * R - delta, R, R, n, zero, spin / 2, -spin / 2, dt=dt)
        assert c[cs.FN] == pytest.approx(kn * delta, rel=1e-12)
        assert law.at("rolling")[2] == pytest.approx(kr * dt * 4.0 * step, rel=1e-12)
        assert c[cs.MRZ] == pytest.approx(kr * dt * 4.0 * step + damping * 4.0, rel=1e-12)
    for _ in range(int(cap / (kr * dt * 4.0)) + 5):
        c = law(2 * R - delta, R, R, n, zero, spin / 2, -spin / 2, dt=dt)
    assert c[cs.MRZ] == pytest.approx(cap, rel=1e-12)
    assert law.at("rolling")[2] == pytest.approx(cap, rel=1e-12)


def test_sjkr_area_of_a_sphere_whose_centre_is_inside_the_other():
    """A small sphere pushed in past its centre: the area is its cross-section, finite and positive
    (the intersection circle shrinks to nothing and its formula turns negative inside)."""
    small = 0.2 * R
    for r in (0.5 * (R - small), 0.999 * R):
        assert sjkr_area(r, R, small, False) == pytest.approx(math.pi * small ** 2, rel=1e-15)
        assert sjkr_area(r, small, R, False) == pytest.approx(math.pi * small ** 2, rel=1e-15)
    # just outside that regime the circle is still there and nearly that big (a^2 = s^2 - s^4/4R^2 at r = R)
    assert 0.98 * math.pi * small ** 2 < sjkr_area(1.001 * R, R, small, False) < math.pi * small ** 2
