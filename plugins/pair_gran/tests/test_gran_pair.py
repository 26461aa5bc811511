"""pair gran/hooke, gran/hooke/history and gran/hertz/history: LAMMPS's recorded trajectories of
two- and three-sphere scenes, and the force law against its formulas."""

import math

import numpy as np
import pytest

from pdps_core.api import Fix, registry
from pdps_core.testing import ContactsHeld, register_styles

M1 = 1.9098593171027440      # density of a sphere of diameter 1 and mass 1
HOOKE = "200000.0 NULL 50.0 NULL 0.5 1"

CASES = ["hooke_history_head_on", "hooke_history_oblique", "hooke_oblique", "hooke_history_dampflag0",
         "hertz_history_limit_damping", "hooke_history_stick_on_frozen", "hertz_history_slide_on_frozen",
         "hooke_history_three_spheres"]


@pytest.mark.parametrize("name", CASES)
def test_trajectories_equal_lammps(lammps_case, name):
    """x, v, omega of every particle at every dumped step equal LAMMPS's to 1e-12 of their scale
    (data/NAME.ref), and a contact changed the motion."""
    record, table = lammps_case(name)
    assert not np.allclose(record.v[max(table) - 1], record.v[0])


def test_head_on_collision_rebounds_with_the_restitution_of_the_linear_law(scene):
    """e = exp(-gamma_n t_c / 2), t_c = pi / sqrt(kn/m* - gamma_n^2/4), m* = 1/2: the discrete
    collision converges to it at first order in the time step (LAMMPS's own run of
    hooke_history_head_on, 50 steps per contact, rebounds 0.35 % faster)."""
    kn, gamma_n, m_eff = 200000.0, 50.0, 0.5
    t_c = math.pi / math.sqrt(kn / m_eff - gamma_n ** 2 / 4)
    exact = math.exp(-gamma_n * t_c / 2)
    errors = []
    for steps in (250, 1000):
        sim = scene(f"gran/hooke/history {HOOKE}", [(1, 1.0, M1, (4.5, 5.0, 5.0), (1.0, 0.0, 0.0), (0, 0, 0)),
                                                    (1, 1.0, M1, (5.5, 5.0, 5.0), (-1.0, 0.0, 0.0), (0, 0, 0))],
                    extra=f"timestep {t_c / steps!r}\nfix 1 all nve/sphere\n")
        sim.command(f"run {int(1.1 * steps)}")
        v = sim.v[np.argsort(sim.tag)]
        assert v[1, 0] == pytest.approx(-v[0, 0], rel=1e-12)
        errors.append(abs(-v[0, 0] - exact) / exact)
    assert errors[1] < 3e-4
    assert errors[0] > 3.0 * errors[1]


def pair_forces(sim):
    """Forces and torques (id order) of a run 0: the setup forces, the spring not advanced."""
    sim.command("run 0")
    order = np.argsort(sim.tag)
    return sim.f[order].copy(), sim.particles.torque[: sim.nlocal][order].copy()


def contact(xi, xj, vi, vj, wi, wj, ri, rj):
    """(overlap, n, v_n, v_tr) of a contact as LAMMPS's pair gran styles define them."""
    d = np.subtract(xi, xj)
    r = np.linalg.norm(d)
    n = d / r
    vr = np.subtract(vi, vj)
    v_n = vr @ n
    vtr = vr - v_n * n - np.cross(ri * np.asarray(wi) + rj * np.asarray(wj), n)
    return ri + rj - r, n, v_n, vtr


# sphere 1 (d 1, density 2) and sphere 2 (d 1.4, density 1) overlapping, moving and spinning
TWO = [(1, 1.0, 2.0, (4.5, 5.0, 5.0), (1.0, 0.3, 0.0), (0.0, 0.0, 5.0)),
       (1, 1.4, 1.0, (5.68, 5.1, 5.05), (-0.5, 0.0, 0.2), (1.0, -2.0, 0.0))]


def two_sphere_contact():
    (_, di, rhoi, xi, vi, wi), (_, dj, rhoj, xj, vj, wj) = TWO
    mi, mj = (rho * math.pi * d ** 3 / 6 for rho, d in ((rhoi, di), (rhoj, dj)))
    return contact(xi, xj, vi, vj, wi, wj, di / 2, dj / 2), mi, mj


@pytest.mark.parametrize("style", ["gran/hooke", "gran/hooke/history"])
def test_setup_forces_follow_lammps_formulas(scene, style):
    """F_n = kn delta - m* gamma_n v_n; F_t = -m* gamma_t v_tr (the spring is zero at setup, and
    under the Coulomb limit), gran/hooke: min(mu |F_n|, m* gamma_t |v_tr|); torques -R n x F_t."""
    sim = scene(f"{style} 200000.0 NULL 50.0 NULL 0.5 1", TWO)
    f, torque = pair_forces(sim)
    (overlap, n, v_n, vtr), mi, mj = two_sphere_contact()
    m_eff = mi * mj / (mi + mj)
    fn = 200000.0 * overlap - m_eff * 50.0 * v_n
    ft = -m_eff * 25.0 * vtr
    if style == "gran/hooke":
        ft *= min(1.0, 0.5 * abs(fn) / np.linalg.norm(ft))
    assert f[0] == pytest.approx(fn * n + ft, rel=1e-12)
    assert f[1] == pytest.approx(-(fn * n + ft), rel=1e-12)
    assert torque[0] == pytest.approx(-0.5 * np.cross(n, ft), rel=1e-12)
    assert torque[1] == pytest.approx(-0.7 * np.cross(n, ft), rel=1e-12)


@pytest.mark.parametrize("units, nktv2p", [("lj", 1.0), ("real", 68568.415)])
def test_hertz_scales_every_term_by_polyhertz_and_stiffness_by_nktv2p(scene, units, nktv2p):
    """F_n = sqrt(delta R*) (kn/nktv2p delta - m* gamma_n v_n), F_t = -sqrt(delta R*) m* gamma_t v_tr
    at setup; in real units the weak spring lets F_t exceed mu |F_n|."""
    sim = scene("gran/hertz/history 2000000.0 NULL 400.0 NULL 0.5 1", TWO, setup=f"units {units}")
    f, _ = pair_forces(sim)
    (overlap, n, v_n, vtr), mi, mj = two_sphere_contact()
    m_eff = mi * mj / (mi + mj)
    polyhertz = math.sqrt(overlap * 0.5 * 0.7 / 1.2)
    fn = polyhertz * (2.0e6 / nktv2p * overlap - m_eff * 400.0 * v_n)
    ft = -polyhertz * m_eff * 200.0 * vtr
    if np.linalg.norm(ft) > 0.5 * abs(fn):
        # over the Coulomb limit with a spring of zero length (a new contact): LAMMPS drops F_t
        ft = np.zeros(3)
    assert (units == "real") == (not ft.any())
    assert f[0] == pytest.approx(fn * n + ft, rel=1e-12)


def test_null_gives_lammps_defaults_and_dampflag_0_switches_tangential_damping_off(scene):
    sim = scene(f"gran/hooke/history {HOOKE}", TWO)
    assert (sim.pair.kt, sim.pair.gamma_t) == (pytest.approx(2 / 7 * 200000.0), 25.0)
    off = scene("gran/hooke/history 200000.0 NULL 50.0 30.0 0.5 0", TWO)
    f, torque = pair_forces(off)
    (overlap, n, v_n, _), mi, mj = two_sphere_contact()
    assert off.pair.gamma_t == 0.0
    assert f[0] == pytest.approx((200000.0 * overlap - mi * mj / (mi + mj) * 50.0 * v_n) * n, rel=1e-12)
    assert torque == pytest.approx(np.zeros((2, 3)), abs=1e-12)


def test_limit_damping_keeps_a_separating_contact_from_pulling(scene):
    """Overlap 0.001 separating at 20: kn delta - m* gamma_n v_n = 200 - 500 < 0 pulls, unless
    limit_damping."""
    apart = [(1, 1.0, M1, (5.0, 5.0, 5.0), (-10.0, 0.0, 0.0), (0, 0, 0)),
             (1, 1.0, M1, (5.999, 5.0, 5.0), (10.0, 0.0, 0.0), (0, 0, 0))]
    pulled, _ = pair_forces(scene(f"gran/hooke {HOOKE}", apart))
    assert pulled[0] == pytest.approx([300.0, 0.0, 0.0], rel=1e-9)     # the left one pulled right
    limited, _ = pair_forces(scene(f"gran/hooke {HOOKE} limit_damping", apart))
    assert limited == pytest.approx(np.zeros((2, 3)), abs=1e-12)


def test_a_frozen_partner_gives_the_contact_the_other_particles_mass(scene):
    """m* = m_i when j is in the group of fix freeze (LAMMPS's rule)."""
    particles = [(1, 1.0, M1, (5.0, 5.0, 5.0), (0.0, 0.0, 0.0), (0, 0, 0)),
                 (1, 1.0, 3 * M1, (5.0, 5.0, 5.99), (0.0, 0.0, -1.0), (0, 0, 0))]
    sim = scene(f"gran/hooke {HOOKE}", particles,
                extra="group base id 1\nfix 1 base freeze\n")
    f, _ = pair_forces(sim)
    # the base is frozen: its force is zeroed, the top's damping uses its own mass 3
    assert f[1] == pytest.approx([0.0, 0.0, 200000.0 * 0.01 - 3.0 * 50.0 * (-1.0)], rel=1e-12)
    assert f[0] == pytest.approx(np.zeros(3), abs=1e-12)


def test_a_contact_across_the_periodic_boundary_and_rebuilt_lists_keeps_its_spring(scene):
    """A sphere pressed onto a frozen one and pulled sideways below the Coulomb limit (it rolls on
    its spring): the same motion in the middle of the box with lists kept, and straddling the
    periodic corner (its partner a ghost) with lists rebuilt and particles re-sorted every step."""
    def pressed(offset, lists):
        base, top = np.add((5.0, 5.0, 5.0), offset), np.add((5.0, 5.0, 5.99999), offset)
        spheres = [(1, 1.0, M1, tuple(map(float, base)), (0, 0, 0), (0, 0, 0)),
                   (1, 1.0, M1, tuple(map(float, top % 10.0)), (0, 0, 0), (0, 0, 0))]
        sim = scene(f"gran/hooke/history {HOOKE}", spheres, extra=lists + """
            group base id 1
            group top id 2
            fix 1 all nve/sphere
            fix 2 top addforce 0.2 0.0 -1.0
            fix 3 base freeze
            """)
        sim.command("run 3000")
        order = np.argsort(sim.tag)
        x = sim.x[order] + sim.particles.image[: sim.nlocal][order] * sim.box.length
        apart = (x[1] - x[0] + 5.0) % 10.0 - 5.0        # the nearest image
        return apart, sim.v[order][1], sim.particles.omega[: sim.nlocal][order][1]
    middle = pressed((0.0, 0.0, 0.0), "")
    corner = pressed((4.7, 0.0, 4.7), "neigh_modify delay 0 every 1 check no\natom_modify sort 1 1.0\n")
    for a, b in zip(middle, corner):
        assert b == pytest.approx(a, abs=1e-10)
    # the top sphere rolled on the base without losing it: it moved sideways and still touches
    assert 0.001 < middle[0][0] and np.linalg.norm(middle[0]) < 1.0


def test_coarse_timestep_is_warned(scene):
    """The lightest sphere (density 2, d 1: m = pi/3) meets its copy in t_c = pi / sqrt(kn/m* -
    gamma_n^2/4) = 0.00508: timestep 0.001 resolves that with 5 steps."""
    sim = scene(f"gran/hooke/history {HOOKE}", TWO, extra="timestep 0.001\n")
    before = len(sim.warnings)
    sim.command("run 0")
    warnings = sim.warnings[before:]
    m_eff = math.pi / 6
    t_c = math.pi / math.sqrt(200000.0 / m_eff - 625.0)
    assert sim.pair.timestep_limits(sim)["contact"] == pytest.approx(t_c, rel=1e-12)
    assert warnings == [f"pair gran/hooke/history: timestep 0.001 is more than the shortest contact "
                        f"({t_c:.3g}) / 10: collisions lose restitution; use timestep <= {t_c / 10:.3g}"]


def hot_gas(scene, style, check, seed, pair=None, material=""):
    """100 spheres (d 1, m 1) near the sites of a lattice of spacing 1.2 in a periodic box 6 wide,
    with Gaussian velocities of deviation 8 (lists rebuilt every few steps at timestep 0.0004, skin
    0.1), pair ``style`` with HOOKE's constants (or the pair_style words ``pair``, with the fixes of
    ``material``) and the fix ``check`` on all."""
    rng = np.random.default_rng(seed)
    sites = (np.stack(np.meshgrid(*[np.arange(5)] * 3, indexing="ij"), -1).reshape(-1, 3)[:100] * 1.2
             + rng.uniform(-0.02, 0.02, (100, 3)))
    spheres = [(1, 1.0, M1, tuple(map(float, site)), tuple(map(float, rng.normal(0.0, 8.0, 3))), (0, 0, 0))
               for site in sites]
    return scene(pair or f"{style} {HOOKE}", spheres, box="0 6 0 6 0 6", extra=material + f"""
        timestep 0.0004
        neighbor 0.1 bin
        neigh_modify delay 0 every 1 check yes
        fix 1 all nve/sphere
        fix check all {check}
        """)


class HookeForcesOfEveryPair(Fix):
    """After the pair forces of every step: the largest difference between the forces on the owned
    particles and gran/hooke's (HOOKE, spheres of diameter 1 and mass 1, the box 6 wide) summed over
    every pair by minimum image, and whether the list was rebuilt at this step."""
    name = "test/hooke_every_pair"

    def init_run(self, sim):
        self.errors, self.rebuilt, self.contacts = [], [], []

    def post_force(self, sim):
        p = sim.particles
        x, v, w = p.x[: p.nlocal], p.v[: p.nlocal], p.omega[: p.nlocal]
        delta = x[:, None, :] - x[None, :, :]
        delta -= 6.0 * np.round(delta / 6.0)
        r = np.sqrt((delta ** 2).sum(axis=2))
        np.fill_diagonal(r, np.inf)
        touching = r < 1.0
        n = delta / r[..., None]
        vr = v[:, None, :] - v[None, :, :]
        v_n = (vr * n).sum(axis=2)
        vtr = vr - v_n[..., None] * n - np.cross(0.5 * (w[:, None, :] + w[None, :, :]), n)
        fn = 200000.0 * (1.0 - r) - 0.5 * 50.0 * v_n
        speed = np.linalg.norm(vtr, axis=2)
        ft = np.minimum(0.5 * np.abs(fn), 0.5 * 25.0 * speed) / np.where(speed > 0.0, speed, 1.0)
        force = np.where(touching[..., None], fn[..., None] * n - ft[..., None] * vtr, 0.0)
        self.errors.append(float(np.abs(p.f[: p.nlocal] - force.sum(axis=1)).max() / 200000.0))
        self.rebuilt.append(sim.neighbor.ago == 0)
        self.contacts.append(int(touching.sum()) // 2)


def test_forces_of_every_contact_at_every_step_across_rebuilds(scene):
    """A hot gas of 100 spheres whose lists are rebuilt every few steps (pair gran keeps the particle
    of every list entry between builds): at every step the forces are gran/hooke's over every pair
    of the box, computed afresh by minimum image."""
    registry.register("fix", "test/hooke_every_pair", HookeForcesOfEveryPair)
    sim = hot_gas(scene, "gran/hooke", "test/hooke_every_pair", seed=5)
    sim.command("run 400")
    check = sim.fixes["check"]
    print(f"builds {sim.neighbor.builds}, contacts per step up to {max(check.contacts)}, "
          f"largest error {max(check.errors):.2e} of kn")
    assert sum(check.rebuilt) > 20 and sum(check.contacts) > 400
    assert max(check.errors) < 1e-12


# LIGGGHTS's Hertz law with a spring, rolling friction and cohesion (pair gran model's own kernel)
LIGGGHTS_PAIR = "gran model hertz tangential history rolling_friction cdt cohesion sjkr"
LIGGGHTS_MATERIAL = ("fix m1 all property/global youngsModulus peratomtype 5.e6\n"
                     "fix m2 all property/global poissonsRatio peratomtype 0.45\n"
                     "fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5\n"
                     "fix m4 all property/global coefficientFriction peratomtypepair 1 0.5\n"
                     "fix m5 all property/global coefficientRollingFriction peratomtypepair 1 0.1\n"
                     "fix m6 all property/global cohesionEnergyDensity peratomtypepair 1 1000.0\n")


@pytest.mark.parametrize("pair, material", [(None, ""), (LIGGGHTS_PAIR, LIGGGHTS_MATERIAL)],
                         ids=["gran/hooke/history", "gran model"])
def test_contact_slots_hold_exactly_the_contacts_of_each_step(scene, pair, material):
    """gran/hooke/history forgets a contact at the end of the step its spheres came apart (LAMMPS);
    gran model at the next list build (LIGGGHTS 3.8, whose pair loop zeroes no spring of a listed
    pair that does not touch: spheres that touch again before the build take up their spring). In a
    hot gas whose lists are rebuilt every few steps (between builds only the rows that held or made a
    contact are swept), the slots hold at every step exactly the pairs that touch, or for gran model
    those and the pairs that came apart since the last build, which some steps have."""
    register_styles(ContactsHeld)
    sim = hot_gas(scene, "gran/hooke/history", "test/contacts_held", seed=6, pair=pair, material=material)
    sim.command("run 400")
    check = sim.fixes["check"]
    print(f"builds {sim.neighbor.builds}, contacts per step up to {max(check.contacts)}, "
          f"steps holding pairs apart {check.exact.count(False)}")
    assert sim.neighbor.builds > 20 and sum(check.contacts) > 400
    if pair is None:
        assert all(check.exact)
    else:
        assert all(check.until_build) and check.exact.count(False) > 20
