"""fix wall/dem: a sphere hitting a block face or a polygon rebounds with the analytic restitution
coefficient and contact time of the linear spring-dashpot; static contacts with faces, edges and
corners; sliding turns into rolling at 5/7 of the initial speed (torque); history and errors.

Units lj; spheres of diameter 1 and density 1 (m = pi/6, R = 0.5). Impacts run without gravity at a
constant approach speed, with the time step t_c / 100.
"""

import math

import numpy as np
import pytest

from pdps_core.api import Region, ScriptError, StyleArgs
from pdps_core.testing import make_box, register_styles
from pdps_granular_contact import contact_models

MASS = math.pi / 6.0
KN, E = 1.0e4, 0.8


def impact(sim, wall, start, velocity, dt, steps, rotate="yes"):
    """Run one sphere from ``start`` at ``velocity`` with ``wall`` defined; its recorded history."""
    sim.command(f"""
        create_particle 1 single {start[0]} {start[1]} {start[2]} diameter 1 density 1
        velocity all set {velocity[0]} {velocity[1]} {velocity[2]}
        fix 1 all test/nve_sphere rotate {rotate}
        fix w all {wall}
        fix r all test/record
        timestep {dt}
        run {steps}
    """)
    return sim.fixes["r"]


def measure_rebound(record, gap_of, speed):
    """Restitution (speed after / speed before) and contact time from the times the gap (distance
    from the centre to the wall minus R) changes sign, by linear interpolation."""
    t = np.array(record.t)
    x = record.series("x")
    gap = np.array([gap_of(p) for p in x])
    down = np.flatnonzero((gap[:-1] > 0) & (gap[1:] <= 0))[0]
    up = np.flatnonzero((gap[:-1] <= 0) & (gap[1:] > 0))[0]

    def when(k):
        return t[k] + (t[k + 1] - t[k]) * gap[k] / (gap[k] - gap[k + 1])

    after = np.linalg.norm(record.series("v")[-1])
    return after / speed, when(up) - when(down)


def analytic(cn):
    tc = contact_models.lsd_contact_time(KN, cn, MASS)
    return math.exp(-math.pi * (cn / (2 * math.sqrt(KN * MASS)))
                    / math.sqrt(1 - cn ** 2 / (4 * KN * MASS))), tc


CN = contact_models.lsd_damping(KN, MASS, E)
PDPS = f"{E} {KN} {CN} {2 / 7 * KN} {CN / 2} 0.3 0.5"
TC = contact_models.lsd_contact_time(KN, CN, MASS)


@pytest.mark.parametrize("numbers", [PDPS, f"{E} {KN} 0.3"], ids=["pdps-form", "restitution-form"])
def test_drop_on_a_block_floor_from_outside(scene, numbers):
    """The sphere falls at 1 onto the top face (z = 0) of a block below it; restitution within 1 %
    and contact time within 2 % of e and t_c of the law."""
    sim = scene()
    sim.command("region floor block -3 3 -3 3 -3.5 0")
    record = impact(sim, f"wall/dem lsd region floor {numbers}", (0.2, -0.1, 0.505), (0, 0, -1),
                    TC / 100, 230)
    e, tc = measure_rebound(record, lambda p: p[2] - 0.5, 1.0)
    e_law, tc_law = analytic(CN)
    assert e_law == pytest.approx(E, rel=1e-12)
    assert e == pytest.approx(e_law, rel=0.01)
    assert tc == pytest.approx(tc_law, rel=0.02)
    v = record.series("v")[-1]
    assert abs(v[0]) < 1e-12 and abs(v[1]) < 1e-12     # head-on: no tangential force


@pytest.mark.parametrize("neighbor", ["neigh_modify delay 0 every 1 check yes", "neigh_modify every 20 check no"])
def test_a_sphere_arriving_from_far_between_rebuilds_rebounds_as_if_always_watched(scene, neighbor):
    """Only particles within reach + skin of a wall surface at a rebuild are visited at each step:
    a sphere starting 6.45 skins above the floor (the skin 0.1 crossed in 10 steps, the floor met
    between two rebuilds) feels the floor at every step it overlaps it, and at no other, and
    rebounds with the law's restitution and contact time."""
    sim = scene()
    sim.command(f"region floor block -3 3 -3 3 -3.5 0\n{neighbor}")
    speed = 100 * 0.01 / TC
    record = impact(sim, f"wall/dem lsd region floor {PDPS}", (0.2, -0.1, 1.145), (0, 0, -speed),
                    TC / 100, 200)
    touching = record.series("x")[:, 2] < 0.5
    pushed = record.series("f")[:, 2] != 0.0
    assert touching.any() and (touching == pushed).all()
    e, tc = measure_rebound(record, lambda p: p[2] - 0.5, speed)
    e_law, tc_law = analytic(CN)
    assert e == pytest.approx(e_law, rel=0.01)
    assert tc == pytest.approx(tc_law, rel=0.02)


def test_oblique_hit_on_the_inside_of_a_container_face(scene):
    """Inside a box, the sphere hits the xhi face at 45 degrees without friction: the normal
    velocity rebounds with e, the tangential one is kept."""
    sim = scene()
    sim.command("region tank block -3 3 -3 3 -3 3")
    s = math.sqrt(0.5)
    record = impact(sim, f"wall/dem lsd region tank {E} {KN} {CN} 0 0 0 0.5", (2.4965, 0, 0),
                    (s, s, 0), TC / 100, 230)
    e, tc = measure_rebound(record, lambda p: 2.5 - p[0], 1.0)
    v = record.series("v")[-1]
    assert -v[0] / s == pytest.approx(E, rel=0.01)
    assert v[1] == pytest.approx(s, rel=1e-12)
    assert tc == pytest.approx(TC, rel=0.02)


def test_drop_on_a_polygon_from_below(scene):
    """A polygon is two-sided: a sphere rising into it from below rebounds downwards with e."""
    sim = scene()
    sim.command("region lid polygon p1 -2 -2 1 p2 2 -2 1 p3 2 2 1 p4 -2 2 1")
    record = impact(sim, f"wall/dem lsd region lid {PDPS}", (0, 0.3, 0.495), (0, 0, 1), TC / 100, 230)
    e, tc = measure_rebound(record, lambda p: 0.5 - p[2], 1.0)
    assert e == pytest.approx(E, rel=0.01)
    assert tc == pytest.approx(TC, rel=0.02)
    assert record.series("v")[-1][2] < 0


def static_force(scene, walls, position, numbers=f"{E} {KN} 0 0 0 0 0.5"):
    """The wall force on a resting sphere (setup forces: no velocity, no history): k_n times the
    overlap along each contact normal."""
    sim = scene()
    sim.command(walls)
    names = " ".join(f"region {w.split()[1]}" for w in walls.strip().splitlines())
    sim.command(f"""
        create_particle 1 single {position[0]} {position[1]} {position[2]} diameter 1 density 1
        fix w all wall/dem lsd {names} {numbers}
        run 0
    """)
    return sim.f[0].copy(), sim.particles.torque[0].copy()


def test_corner_of_a_container_gives_one_contact_per_face(scene):
    f, torque = static_force(scene, "region tank block -3 3 -3 3 -3 3", (-2.6, 2.7, -2.9))
    np.testing.assert_allclose(f, KN * np.array([0.1, -0.2, 0.4]), rtol=1e-12)
    np.testing.assert_array_equal(torque, 0.0)


def test_edge_and_corner_of_an_obstacle_give_one_contact_each(scene):
    """Outside a block: near an edge the force is along the line from the edge, near a corner along
    the diagonal, with one overlap's worth of force (not one per face)."""
    d = 0.4
    f, _ = static_force(scene, "region post block -1 1 -1 1 -3 0",
                        (1 + d / math.sqrt(2), 0.3, d / math.sqrt(2)))
    np.testing.assert_allclose(f, KN * 0.1 * np.array([1, 0, 1]) / math.sqrt(2), rtol=1e-12)
    f, _ = static_force(scene, "region post block -1 1 -1 1 -3 0",
                        (-1 - d / math.sqrt(3), 1 + d / math.sqrt(3), d / math.sqrt(3)))
    np.testing.assert_allclose(f, KN * 0.1 * np.array([-1, 1, 1]) / math.sqrt(3), rtol=1e-12)


def test_polygon_edge_contact_and_two_walls_add_up(scene):
    """A sphere beside a shelf's edge is pushed along the line from the edge; with a block floor as
    a second wall both forces add."""
    walls = ("region shelf polygon p1 -2 -2 0.9 p2 0 -2 0.9 p3 0 2 0.9 p4 -2 2 0.9\n"
             "region floor block -3 3 -3 3 -3 0")
    f, _ = static_force(scene, walls, (0.2, 0.0, 0.45))
    delta = np.array([0.2, 0.0, 0.45 - 0.9])
    gap = np.linalg.norm(delta)
    expected = KN * (0.5 - gap) * delta / gap + KN * 0.05 * np.array([0, 0, 1])
    np.testing.assert_allclose(f, expected, rtol=1e-12)
    f, _ = static_force(scene, walls, (0.4, 0.0, 0.55))
    np.testing.assert_array_equal(f, 0.0)


@pytest.mark.parametrize("order", [(0, 1), (1, 0)])
def test_two_spheres_in_a_closed_cylinder_each_feel_their_own_wall(scene, order):
    """One sphere rests on the bottom cap of a closed cylinder, the other against its curved wall:
    each feels k_n times its own overlap along its own wall's normal, whichever comes first (the
    cylinder's contacts must come in the order of the points)."""
    sim = scene()
    positions = [(0.0, 0.0, 0.4), (1.7, 0.0, 2.0)]
    expected = [KN * 0.1 * np.array([0.0, 0.0, 1.0]), KN * 0.2 * np.array([-1.0, 0.0, 0.0])]
    for k in order:
        x, y, z = positions[k]
        sim.command(f"create_particle 1 single {x} {y} {z} diameter 1 density 1")
    sim.command(f"""
        region can cylinder z 0 0 2 0 4
        fix w all wall/dem lsd region can {E} {KN} 0 0 0 0 0.5
        run 0
    """)
    for tag, k in enumerate(order, 1):
        np.testing.assert_allclose(sim.f[sim.particles.index_of_tag(tag)], expected[k], rtol=1e-12)


def test_sliding_sphere_starts_rolling_at_five_sevenths_of_its_speed(scene):
    """A sphere put on the floor sliding at v0 without spin: friction mu m g slows it and spins it up
    until it rolls, at v = 5/7 v0 with omega R = v, after t = 2 v0 / (7 mu g) (torque on the
    sphere, spin in the contact velocity). Gravity 10, mu 0.3."""
    sim = scene(box="-4 4 -4 4 -2 4")
    g, mu, v0 = 10.0, 0.3, 2.0
    delta = MASS * g / KN
    sim.command(f"""
        region floor block INF INF INF INF -2 0
        create_particle 1 single -3 0 {0.5 - delta} diameter 1 density 1
        velocity all set {v0} 0 0
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 -{g}
        fix w all wall/dem lsd region floor {E} {KN} {mu}
        fix r all test/record
        timestep {TC / 50}
    """)
    t_roll = 2 * v0 / (7 * mu * g)
    sim.command(f"run {int(1.5 * t_roll / (TC / 50))}")
    v = sim.v[0]
    omega = sim.particles.omega[0]
    assert v[0] == pytest.approx(5 / 7 * v0, rel=0.01)
    assert omega[1] * 0.5 == pytest.approx(v[0], rel=0.01)     # rolling: omega x (-R z) = -v
    record = sim.fixes["r"]
    t = np.array(record.t)
    early = t < 0.5 * t_roll
    slope = np.polyfit(t[early], record.series("v")[early, 0], 1)[0]
    assert slope == pytest.approx(-mu * g, rel=0.01)


def test_contact_history_is_kept_during_a_contact_and_freed_after(scene):
    sim = scene()
    sim.command("region floor block -3 3 -3 3 -3.5 0")
    impact(sim, f"wall/dem lsd region floor {E} {KN} 0.3", (0, 0, 0.52), (0.5, 0, -1), TC / 100, 120)
    history = sim.fixes["w"].history
    assert (history.partner[0] >= 0).sum() == 1
    spring = history.values[0, :3]
    assert spring[0] > 0 and spring[2] == 0.0          # stretched along the sliding direction
    sim.command("run 200")
    assert (history.partner[0] >= 0).sum() == 0


def test_point_particles_touch_at_the_cutoff():
    """particle_style atomic: the PDPS cutoff is the contact distance (no radius, no rotation)."""
    sim = make_box(f"""
        mass 1 2
        region floor block -3 3 -3 3 -3.5 0
        create_particle 1 single 0 0 0.2
        fix w all wall/dem lsd region floor {E} {KN} 0 0 0 0 0.25
        run 0
    """, box="-4 4 -4 4 -4 4", boundary="f f f")
    np.testing.assert_allclose(sim.f[0], [0, 0, KN * 0.05], rtol=1e-12)


def test_large_time_step_warns(scene):
    sim = scene()
    sim.command("region floor block -3 3 -3 3 -3.5 0")
    impact(sim, f"wall/dem lsd region floor {E} {KN} 0.3", (0, 0, 2), (0, 0, 0), TC / 5, 0)
    assert any("fewer than 10 steps" in w for w in sim.warnings)


class Lump(Region):
    """A region with an inside and no surface."""
    name = "test/wall_lump"

    class Args(StyleArgs):
        pass

    def inside(self, x):
        return np.zeros(len(x), dtype=bool)


class OldFloor(Region):
    """A region written to the contract before surface_contacts took buffers: the plane z = 0,
    touched from above, its rows given last point first."""
    name = "test/wall_old_floor"

    class Args(StyleArgs):
        pass

    def inside(self, x):
        return np.asarray(x)[:, 2] <= 0.0

    def surface_contacts(self, x, reach):
        index = np.flatnonzero(np.asarray(x)[:, 2] < reach)[::-1]
        normal = np.zeros((len(index), 3))
        normal[:, 2] = 1.0
        return index, np.asarray(x)[index, 2], normal, np.zeros(len(index), dtype=np.int64)


register_styles(Lump, OldFloor)


def test_a_region_written_before_surface_buffers_still_makes_a_wall(scene):
    """A region style whose surface_contacts takes no buffers, and gives its rows in any order, is
    called without them: each sphere feels k_n times its own overlap."""
    sim = scene()
    sim.command(f"""
        create_particle 1 single 0 0 0.4 diameter 1 density 1
        create_particle 1 single 2 0 0.3 diameter 1 density 1
        region floor test/wall_old_floor
        fix w all wall/dem lsd region floor {E} {KN} 0 0 0 0 0.5
        run 0
    """)
    for tag, overlap in ((1, 0.1), (2, 0.2)):
        np.testing.assert_allclose(sim.f[sim.particles.index_of_tag(tag)], [0.0, 0.0, KN * overlap], rtol=1e-12)


@pytest.mark.parametrize("words, message", [
    ("hertz region floor 0.8 1e4 0.3", "model must be one of 'lsd' (got hertz)"),
    ("lsd 0.8 1e4 0.3", "expected at least one region R after lsd"),
    ("lsd region nowhere 0.8 1e4 0.3", "region nowhere is not defined"),
    ("lsd region lump 0.8 1e4 0.3", "region lump (test/wall_lump) has no surface to act as a wall"),
    ("lsd region floor 0.8 1e4", "law must be number number number number number number number or number number number "
     "number or number number number (got 0.8 1e4)"),
    ("lsd region floor 1.5 1e4 0.3", "e must be in (0, 1] (got 1.5)"),
    ("lsd region floor 0.8 -1 0.3", "kn must be > 0 (got -1)"),
    ("lsd region floor 0.8 1e4 x", "law must be a finite number (got x)"),
    ("lsd region floor 0.8 1e4 1 1 -1 0.3 0.5", "Ct must be >= 0 (got -1)"),
])
def test_bad_arguments(scene, words, message):
    sim = scene()
    sim.command("region floor block -3 3 -3 3 -3.5 0\nregion lump test/wall_lump")
    with pytest.raises(ScriptError) as info:
        sim.command(f"fix w all wall/dem {words}")
    assert message in str(info.value)
    assert "\n" not in str(info.value)


def test_atomic_particles_without_cutoff_are_an_error():
    sim = make_box("mass 1 1\ncreate_particle 1 single 0 0 0\nregion floor block -3 3 -3 3 -3.5 0\n"
                   "fix w all wall/dem lsd region floor 0.8 1e4 0.3", box="-4 4 -4 4 -4 4")
    with pytest.raises(ScriptError, match="needs particle radii"):
        sim.command("run 0")
