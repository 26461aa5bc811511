"""LIGGGHTS's contact models (pdps_granular_contact.liggghts) against closed-form results: a sphere
rolling on a plane stops where each rolling-friction model's deceleration puts it, and the cohesion
models' forces and pull-off forces. Integrated here with a small velocity-Verlet loop over the law of
one contact, the plane being the law's wall (as fix wall/gran model calls it)."""

import math

import numpy as np
import pytest
from pdps_granular_contact import liggghts as lg

R, RHO, G = 0.005, 2500.0, 9.81
MASS = RHO * 4.0 / 3.0 * math.pi * R ** 3
INERTIA = 0.4 * MASS * R ** 2
YOUNGS, POISSON = 5.0e6, 0.45


def table(mu_roll=0.0, eta_roll=0.0, cohesion=0.0, e=0.5, mu=0.5):
    """A material table for one type touching itself (a wall of the particle's own material)."""
    t = np.zeros((len(lg.MATERIAL), 2, 2))
    t[lg.Y_STAR, 1, 1] = lg.youngs_effective(YOUNGS, POISSON, YOUNGS, POISSON)
    t[lg.G_STAR, 1, 1] = lg.shear_effective(YOUNGS, POISSON, YOUNGS, POISSON)
    t[lg.BETA, 1, 1] = lg.restitution_beta(e)
    t[lg.LOG_E, 1, 1] = math.log(e)
    t[lg.MU, 1, 1], t[lg.MU_ROLL, 1, 1], t[lg.ETA_ROLL, 1, 1] = mu, mu_roll, eta_roll
    t[lg.COHESION, 1, 1] = cohesion
    return t


def models(rolling="off", cohesion="off", normal="hertz"):
    return np.array([lg.NORMAL_MODELS[normal], lg.HISTORY, lg.ROLLING_MODELS[rolling],
                     lg.COHESION_MODELS[cohesion], 1, 0, 3], dtype=np.int64)


def resting_overlap(mat):
    """Hertz overlap under the weight: m g = 4/3 Y* sqrt(R) delta^3/2."""
    return (MASS * G / (4.0 / 3.0 * mat[lg.Y_STAR, 1, 1] * math.sqrt(R))) ** (2.0 / 3.0)


def roll(rolling, mu_roll, v0, dt=1e-5, eta_roll=0.01):
    """A sphere rolling without slipping along +x on the plane z = 0 under gravity, started at its
    resting overlap; returns (distance rolled when its velocity first reverses or vanishes, overlap)."""
    mat = table(mu_roll, eta_roll)
    mods = models(rolling)
    delta = resting_overlap(mat)
    x = np.array([0.0, 0.0, R - delta])
    arm = R - 0.5 * delta
    v = np.array([v0, 0.0, 0.0])
    w = np.array([0.0, v0 / arm, 0.0])
    n = np.array([0.0, 0.0, 1.0])
    hist = np.zeros(lg.HISTORY_WIDTH)
    force, tangential, torque_roll = np.zeros(3), np.zeros(3), np.zeros(3)
    vtr = np.zeros(3)

    def forces():
        r = x[2]
        a = R - 0.5 * (R - r)
        vn = v @ n
        vtr[:] = v - vn * n - a * np.cross(w, n)
        lg.liggghts_contact(mods, True, mat, 1, 1, r, R, 0.0, MASS, 0.0, MASS, n, vn, vtr, w, 0.0, 1.0, dt,
                            True, hist, force, tangential, torque_roll)
        f = force + np.array([0.0, 0.0, -MASS * G])
        t = -a * np.cross(n, tangential) - torque_roll
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
    # cdt: mu_r k_n delta (R - delta/2) against a wall, k_n delta = m g at rest
    ("cdt", lambda mu_r, delta: mu_r * MASS * G * (R - 0.5 * delta)),
    # epsd, epsd2: the spring torque capped at mu_r |F_n| R
    ("epsd", lambda mu_r, delta: mu_r * MASS * G * R),
    ("epsd2", lambda mu_r, delta: mu_r * MASS * G * R),
])
def test_a_rolling_sphere_stops_where_the_rolling_torque_puts_it(rolling, torque_of):
    """epsd's dashpot acts until the spring reaches its cap (some 50 steps here), unbounded by the
    cap: with eta_r = 0.3 it would take 4 % of the momentum there; eta_r = 0.01 keeps that at
    0.1 %, so the distance is the mobilised torque's."""
    mu_r, v0 = 0.1, 0.1
    distance, delta = roll(rolling, mu_r, v0)
    expected = stop_distance(torque_of(mu_r, delta), v0, delta)
    assert distance == pytest.approx(expected, rel=0.02)
    # about 7 mm (1.4 diameters): 0.7 m/s^2 of deceleration
    assert 0.006 < expected < 0.008


def test_without_rolling_friction_the_sphere_rolls_on():
    """The same sphere without a rolling model keeps its speed: 0.1 m/s for 0.2 s is 20 mm."""
    distance, _ = roll_for("off", 20000)
    assert distance == pytest.approx(0.02, rel=1e-6)


def roll_for(rolling, steps, dt=1e-5):
    """Distance rolled in ``steps`` steps at 0.1 m/s (no stop expected)."""
    mat, mods = table(0.0), models(rolling)
    delta = resting_overlap(mat)
    x, v = np.array([0.0, 0.0, R - delta]), np.array([0.1, 0.0, 0.0])
    arm = R - 0.5 * delta
    w, n = np.array([0.0, 0.1 / arm, 0.0]), np.array([0.0, 0.0, 1.0])
    hist, force, tangential, torque_roll = np.zeros(lg.HISTORY_WIDTH), np.zeros(3), np.zeros(3), np.zeros(3)
    for _ in range(steps):
        vn = v @ n
        vtr = v - vn * n - (R - 0.5 * (R - x[2])) * np.cross(w, n)
        lg.liggghts_contact(mods, True, mat, 1, 1, x[2], R, 0.0, MASS, 0.0, MASS, n, vn, vtr, w, 0.0, 1.0, dt,
                            True, hist, force, tangential, torque_roll)
        v += dt * (force + [0.0, 0.0, -MASS * G]) / MASS
        w += dt * (-(R - 0.5 * (R - x[2])) * np.cross(n, tangential) - torque_roll) / INERTIA
        x += dt * v
    return x[0], delta


def pair_force(cohesion, r, k, radius_i=R, radius_j=R):
    """Normal force of two spheres at rest, centres r apart (positive: repulsive)."""
    mat = table(cohesion=k)
    n, zero = np.array([1.0, 0.0, 0.0]), np.zeros(3)
    out = [np.zeros(3) for _ in range(3)]
    return lg.liggghts_contact(models(cohesion=cohesion), False, mat, 1, 1, r, radius_i, radius_j, MASS, MASS,
                               MASS / 2, n, 0.0, zero, zero, 0.0, 1.0, 1e-6, False, np.zeros(lg.HISTORY_WIDTH),
                               *out)


def hertz(delta, radius_i=R, radius_j=R):
    r_star = radius_i * radius_j / (radius_i + radius_j)
    return 4.0 / 3.0 * lg.youngs_effective(YOUNGS, POISSON, YOUNGS, POISSON) * math.sqrt(r_star * delta) * delta


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
    c = 4.0 / 3.0 * lg.youngs_effective(YOUNGS, POISSON, YOUNGS, POISSON) * math.sqrt(R / 2)
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
    mat = table(mu_roll=mu_r, eta_roll=eta)
    mods = models(rolling)
    n, zero = np.array([1.0, 0.0, 0.0]), np.zeros(3)
    spin = np.array([0.0, 0.0, 4.0])
    hist = np.zeros(lg.HISTORY_WIDTH)
    force, tangential, torque = np.zeros(3), np.zeros(3), np.zeros(3)
    r_star = R / 2
    y_star, g_star = mat[lg.Y_STAR, 1, 1], mat[lg.G_STAR, 1, 1]
    kn = 4 / 3 * y_star * math.sqrt(r_star * delta)
    kt = 8 * g_star * math.sqrt(r_star * delta)
    kr = 2.25 * kn * mu_r ** 2 * r_star ** 2 if rolling == "epsd" else kt * r_star ** 2
    cap = mu_r * kn * delta * r_star
    damping = eta * 2 * math.sqrt(1.4 * MASS * R ** 2 / 2 * kr) if rolling == "epsd" else 0.0
    for step in range(1, 4):
        fn = lg.liggghts_contact(mods, False, mat, 1, 1, 2 * R - delta, R, R, MASS, MASS, MASS / 2, n, 0.0, zero,
                                 spin, 0.0, 1.0, dt, True, hist, force, tangential, torque)
        assert fn == pytest.approx(kn * delta, rel=1e-12)
        assert hist[5] == pytest.approx(kr * dt * 4.0 * step, rel=1e-12)
        assert torque[2] == pytest.approx(kr * dt * 4.0 * step + damping * 4.0, rel=1e-12)
    for _ in range(int(cap / (kr * dt * 4.0)) + 5):
        lg.liggghts_contact(mods, False, mat, 1, 1, 2 * R - delta, R, R, MASS, MASS, MASS / 2, n, 0.0, zero, spin,
                            0.0, 1.0, dt, True, hist, force, tangential, torque)
    assert torque[2] == pytest.approx(cap, rel=1e-12)
    assert hist[5] == pytest.approx(cap, rel=1e-12)


def test_sjkr_area_of_a_sphere_whose_centre_is_inside_the_other():
    """A small sphere pushed in past its centre: the area is its cross-section, finite and positive
    (the intersection circle shrinks to nothing and its formula turns negative inside)."""
    small = 0.2 * R
    for r in (0.5 * (R - small), 0.999 * R):
        assert lg.contact_area(lg.SJKR, False, r, R, small) == pytest.approx(math.pi * small ** 2, rel=1e-15)
        assert lg.contact_area(lg.SJKR, False, r, small, R) == pytest.approx(math.pi * small ** 2, rel=1e-15)
    # just outside that regime the circle is still there and nearly that big (a^2 = s^2 - s^4/4R^2 at r = R)
    assert 0.98 * math.pi * small ** 2 < lg.contact_area(lg.SJKR, False, 1.001 * R, R, small) < math.pi * small ** 2
