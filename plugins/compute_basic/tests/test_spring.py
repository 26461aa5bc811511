"""Fix spring (tether, couple) against the formulas worked out here on a few particles, with no
pair style (the forces after ``run 0`` are the spring's alone):

    d = x_cm - (x, y, z)  (tether),  d = x_cm2 - x_cm - (x, y, z)  (couple),  NULL components 0,
    F = K (r - R0) d / r,   f_i = -F m_i / M (tether; couple: +F m_i / M, -F m_j / M2 on group2),
    E = 1/2 K (r - R0)^2,   and -dE/dx_i = f_i.

LIGGGHTS 3.8.0's numbers for it are in tests/data/liggghts.cases.json (spring_tether, spring_couple).
"""

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import make_box

K, R0 = 2.0, 0.5
MASSES = np.array([1.0, 3.0, 2.0])
PLACES = np.array([[2.0, 3.0, 4.0], [3.0, 5.0, 4.5], [7.0, 6.0, 5.0]])


def _three(fix, places=PLACES, dimension=None):
    """Particles 1 and 2 (types 1, 2: group pair) and 3 (type 3: group lone), the fix, run 0 (in
    2-d the particles at z = 0)."""
    flat = dimension == 2
    particles = "".join(f"create_particle {k + 1} single {p[0]} {p[1]} {0.0 if flat else p[2]}\n"
                        for k, p in enumerate(places))
    return make_box("mass 1 1.0\nmass 2 3.0\nmass 3 2.0\n" + particles + "group pair type 1 2\ngroup lone type 3\n"
                    + fix + "\nrun 0", ntypes=3, particle_style="atomic", dimension=dimension,
                    box="0 10 0 10 -0.5 0.5" if flat else "0 10 0 10 0 10")


def _by_tag(sim, values):
    return np.asarray(values)[np.argsort(sim.tag)]


def _expected_tether(places, point, kept, masses=MASSES[:2]):
    centre = masses @ places[:2] / masses.sum()
    d = (centre - point) * kept
    r = np.linalg.norm(d)
    force = K * (r - R0) * d / r
    return -force[None, :] * (masses / masses.sum())[:, None], 0.5 * K * (r - R0) ** 2, -force, r - R0


def test_tether_pulls_each_particle_by_its_share_of_the_mass():
    sim = _three(f"fix s pair spring tether {K} 1.0 2.0 3.0 {R0}")
    forces, energy, total, dr = _expected_tether(PLACES, np.array([1.0, 2.0, 3.0]), np.ones(3))
    f = _by_tag(sim, sim.f)
    np.testing.assert_allclose(f[:2], forces, rtol=1e-13)
    np.testing.assert_allclose(f[2], 0.0, atol=0.0)
    fix = sim.fixes["s"]
    assert fix.scalar(sim) == pytest.approx(energy, rel=1e-13)
    np.testing.assert_allclose(fix.vector(sim), [*total, np.linalg.norm(total)], rtol=1e-13)
    assert dr > 0


def test_a_null_coordinate_is_neither_measured_nor_pulled():
    sim = _three(f"fix s pair spring tether {K} 1.0 NULL 3.0 {R0}")
    forces, energy, _, _ = _expected_tether(PLACES, np.array([1.0, 0.0, 3.0]), np.array([1.0, 0.0, 1.0]))
    f = _by_tag(sim, sim.f)
    np.testing.assert_allclose(f[:2], forces, rtol=1e-13)
    assert (f[:, 1] == 0.0).all()
    assert sim.fixes["s"].scalar(sim) == pytest.approx(energy, rel=1e-13)
    # moving the group along y changes nothing
    moved = PLACES + [0.0, 2.5, 0.0]
    again = _three(f"fix s pair spring tether {K} 1.0 NULL 3.0 {R0}", places=moved)
    np.testing.assert_allclose(_by_tag(again, again.f), f, rtol=1e-13)
    assert again.fixes["s"].scalar(again) == pytest.approx(energy, rel=1e-13)


def test_inside_r0_the_spring_pushes_and_its_magnitude_turns_negative():
    # the centre of pair is 0.1 from the point: r - R0 < 0
    centre = MASSES[:2] @ PLACES[:2] / MASSES[:2].sum()
    sim = _three(f"fix s pair spring tether {K} {centre[0] + 0.1} {centre[1]} {centre[2]} {R0}")
    total = sim.fixes["s"].vector(sim)
    assert total[3] == pytest.approx(-K * (R0 - 0.1), rel=1e-10)
    # the point lies along +x of the centre: the group is pushed away from it, along -x
    assert total[0] == pytest.approx(-K * (R0 - 0.1), rel=1e-10)
    assert sim.fixes["s"].scalar(sim) == pytest.approx(0.5 * K * (0.1 - R0) ** 2, rel=1e-10)


def test_couple_pulls_the_two_centres_with_opposite_forces():
    sim = _three(f"fix s pair spring couple lone {K} 1.0 NULL -2.0 {R0}")
    m1, m2 = MASSES[:2], MASSES[2]
    centre1 = m1 @ PLACES[:2] / m1.sum()
    d = (PLACES[2] - centre1 - [1.0, 0.0, -2.0]) * [1.0, 0.0, 1.0]
    r = np.linalg.norm(d)
    force = K * (r - R0) * d / r
    f = _by_tag(sim, sim.f)
    np.testing.assert_allclose(f[:2], force[None, :] * (m1 / m1.sum())[:, None], rtol=1e-13)
    np.testing.assert_allclose(f[2], -force * m2 / m2, rtol=1e-13)
    np.testing.assert_allclose(f.sum(axis=0), 0.0, atol=1e-14)
    fix = sim.fixes["s"]
    np.testing.assert_allclose(fix.vector(sim), [*force, np.linalg.norm(force)], rtol=1e-13)
    assert fix.scalar(sim) == pytest.approx(0.5 * K * (r - R0) ** 2, rel=1e-13)


@pytest.mark.parametrize("fix", [f"fix s pair spring tether {K} 1.0 NULL 3.0 {R0}",
                                 f"fix s pair spring couple lone {K} 1.0 0.5 -2.0 {R0}"])
def test_the_force_is_minus_the_gradient_of_the_energy(fix):
    sim = _three(fix)
    f = _by_tag(sim, sim.f)
    h = 1e-6
    for particle in range(3):
        for axis in range(3):
            energies = []
            for sign in (1.0, -1.0):
                places = PLACES.copy()
                places[particle, axis] += sign * h
                moved = _three(fix, places=places)
                energies.append(moved.fixes["s"].scalar(moved))
            assert -(energies[0] - energies[1]) / (2 * h) == pytest.approx(f[particle, axis], rel=1e-6, abs=1e-9)


def test_energy_joins_pe_after_fix_modify_and_the_centre_is_unwrapped():
    sim = _three(f"fix s pair spring tether {K} 1.0 2.0 3.0 {R0}\nfix_modify s energy yes\n"
                 "compute pe all pe")
    _, energy, _, _ = _expected_tether(PLACES, np.array([1.0, 2.0, 3.0]), np.ones(3))
    assert sim.computes["pe"].scalar(sim) == pytest.approx(energy, rel=1e-13)
    # particle 2 seen one box further along x (image +1): its unwrapped x is 13
    rows = np.argsort(sim.tag)
    sim.particles.image[rows[1]] = [1, 0, 0]
    sim.command("run 0")
    unwrapped = PLACES + [[0.0, 0.0, 0.0], [10.0, 0.0, 0.0], [0.0, 0.0, 0.0]]
    forces, energy, _, _ = _expected_tether(unwrapped, np.array([1.0, 2.0, 3.0]), np.ones(3))
    np.testing.assert_allclose(_by_tag(sim, sim.f)[:2], forces, rtol=1e-13)
    assert sim.fixes["s"].scalar(sim) == pytest.approx(energy, rel=1e-13)


def test_an_empty_group_pulls_nothing_and_stays_finite():
    sim = _three(f"group none empty\nfix s none spring tether {K} 1.0 2.0 3.0 {R0}")
    assert (sim.f == 0.0).all()
    assert np.isfinite(sim.fixes["s"].vector(sim)).all()


def test_minimize_brings_the_centre_to_r0_from_the_point():
    sim = _three(f"fix s pair spring tether {K} 1.0 2.0 3.0 {R0}\nfix_modify s energy yes\n"
                 "minimize 0.0 1e-10 1000 10000")
    m = MASSES[:2]
    centre = m @ _by_tag(sim, sim.x)[:2] / m.sum()
    assert np.linalg.norm(centre - [1.0, 2.0, 3.0]) == pytest.approx(R0, rel=1e-6)


@pytest.mark.parametrize("fix, message", [
    (f"fix s pair spring tether {K} 1 2 3", "spring tether takes 5 value(s): number number|NULL number|NULL "
                                            "number|NULL number (got 2.0 1 2 3)"),
    (f"fix s pair spring tether {K} 1 2 3 {R0} 7", "too many arguments: unexpected '7'"),
    (f"fix s pair spring couple lone {K} 1 2 3", "spring couple takes 6 value(s)"),
    (f"fix s pair spring tether {K} 1 2 3 -0.5", "spring tether: R0 must be >= 0 (got -0.5)"),
    (f"fix s pair spring tether {K} 1 abc 3 {R0}", "spring tether: Y must be a finite number or NULL (got abc)"),
    ("fix s pair spring tether stiff 1 2 3 0.5", "spring tether: K must be a finite number (got stiff)"),
    (f"fix s pair spring couple nope {K} 1 2 3 {R0}",
     "spring couple: GROUP2: group nope is not defined (defined: all, pair, lone)"),
    (f"fix s pair spring couple pair {K} 1 2 3 {R0}",
     "spring couple: GROUP2 must differ from the fix group (got pair twice)"),
    (f"fix s pair spring pull {K} 1 2 3 {R0}", "spring must be one of tether, couple (got pull)"),
])
def test_bad_input_gives_one_line_naming_the_value(fix, message):
    sim = make_box("mass * 1.0\ncreate_particle 1 single 1 1 1\ngroup pair type 1\ngroup lone type 2", ntypes=2)
    with pytest.raises(ScriptError) as error:
        sim.command(fix)
    assert "\n" not in str(error.value)
    assert message in str(error.value)


def test_in_2d_z_must_be_null_or_zero():
    with pytest.raises(ScriptError, match=r"spring tether: z must be NULL or 0 in a 2-d simulation \(got 3\)"):
        _three(f"fix s pair spring tether {K} 1.0 2.0 3.0 {R0}", dimension=2)
    sim = _three(f"fix s pair spring tether {K} 1.0 2.0 NULL {R0}", dimension=2)
    assert (sim.f[:, 2] == 0.0).all() and (sim.f[:, :2] != 0.0).any()


def test_a_deleted_group2_stops_the_next_run():
    sim = _three(f"fix s pair spring couple lone {K} 1.0 0.5 -2.0 {R0}")
    sim.command("group lone delete")
    with pytest.raises(ScriptError, match="spring couple: GROUP2: group lone is not defined"):
        sim.command("run 0")
