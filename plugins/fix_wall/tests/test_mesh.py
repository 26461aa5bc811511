"""fix wall/mesh: STL walls (ascii and binary), impacts with the analytic restitution and contact
time, a sphere on an inclined mesh (rolling and sliding), one contact at a shared edge or corner,
moving meshes (conveyor, translating plate, turntable), candidate lists, and file errors.

Units lj; spheres of diameter 1 and density 1 (m = pi/6, R = 0.5). data/square.stl is the square
[-1, 1]^2 at z = 0 in two triangles (diagonal from (-1, -1) to (1, 1)); data/hopper.stl (binary) is a
square funnel, opening half-width 0.3 at z = 0 and 1 at z = 1, in eight triangles.
"""

import math
import os

import meshio
import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import NoForcePair, make_box, register_styles
from pdps_granular_contact import contact_models

MASS = math.pi / 6.0
KN, E = 1.0e4, 0.8
CN = contact_models.lsd_damping(KN, MASS, E)
TC = contact_models.lsd_contact_time(KN, CN, MASS)
STATIC = f"model lsd {E} {KN} 0 0 0 0"          # no damping, no friction: F = kn * overlap * n


def run_sphere(sim, mesh, start, velocity=(0, 0, 0), dt=TC / 100, steps=0, rotate="yes",
               gravity=None, omega=None):
    sim.command(f"""
        create_particle 1 single {start[0]} {start[1]} {start[2]} diameter 1 density 1
        velocity all set {velocity[0]} {velocity[1]} {velocity[2]}
        fix 1 all test/nve_sphere rotate {rotate}
        {f"fix 2 all test/wall_gravity {gravity[0]} {gravity[1]} {gravity[2]}" if gravity else ""}
        fix w all wall/mesh {mesh}
        fix r all test/record
        timestep {dt}
    """)
    if omega is not None:
        sim.particles.omega[0] = omega
    sim.command(f"run {steps}")
    return sim.fixes["r"]


def rebound(record, gap_of):
    """Speed after the impact and the contact time, from where the gap changes sign."""
    t = np.array(record.t)
    gap = np.array([gap_of(p) for p in record.series("x")])
    down = np.flatnonzero((gap[:-1] > 0) & (gap[1:] <= 0))[0]
    up = np.flatnonzero((gap[:-1] <= 0) & (gap[1:] > 0))[0]

    def when(k):
        return t[k] + (t[k + 1] - t[k]) * gap[k] / (gap[k] - gap[k + 1])

    return np.linalg.norm(record.series("v")[-1]), when(up) - when(down)


# ---- impacts ------------------------------------------------------------------------------------
@pytest.mark.parametrize("model", [f"model lsd {E} {KN} {CN} {2 / 7 * KN} {CN / 2} 0.3",
                                   f"model lsd {E} {KN} 0.3"], ids=["pdps-form", "restitution-form"])
def test_drop_on_a_flat_stl_mesh(scene, data, model):
    """Head-on at speed 1 onto the square, away from its diagonal: e and t_c of the law within 1 %
    and 2 %."""
    sim = scene()
    record = run_sphere(sim, f"file {data}/square.stl scale 2 {model}", (0.7, -0.4, 0.505),
                        (0, 0, -1), steps=230)
    speed, tc = rebound(record, lambda p: p[2] - 0.5)
    assert speed == pytest.approx(E, rel=0.01)
    assert tc == pytest.approx(TC, rel=0.02)


def test_drop_on_the_shared_edge_is_one_contact(scene, data):
    """Right over the diagonal both triangles have the same closest point: still e and t_c, not the
    rebound of a doubled stiffness (t_c / sqrt 2)."""
    sim = scene()
    record = run_sphere(sim, f"file {data}/square.stl scale 2 model lsd {E} {KN} 0.3",
                        (0.3, 0.3, 0.505), (0, 0, -1), steps=230)
    speed, tc = rebound(record, lambda p: p[2] - 0.5)
    assert speed == pytest.approx(E, rel=0.01)
    assert tc == pytest.approx(TC, rel=0.02)


def test_elastic_hertz_impact_on_a_binary_stl(scene, data, tmp_path):
    """Hertz with e = 1 on the square written as binary STL: rebound at the impact speed, contact
    time 2.868 (m*^2 / (R* E*^2 v))^(1/5) with m* = m, R* = R (wall of infinite mass and radius)."""
    binary = tmp_path / "square_binary.stl"
    with np.errstate(over="ignore"):       # meshio's binary-or-ascii guess overflows on ascii
        meshio.write(binary, meshio.read(os.path.join(data, "square.stl")), binary=True)
    youngs, poisson, v = 1.0e5, 0.3, 1.0
    e_star = youngs / (2 * (1 - poisson ** 2))
    tc_law = contact_models.hertz_contact_time(e_star, 0.5, MASS, v)
    sim = scene()
    record = run_sphere(sim, f"file {binary} scale 2 model hertz {youngs} {poisson} 1 0.3",
                        (0.1, 0.6, 0.503), (0, 0, -v), dt=tc_law / 200, steps=240)
    speed, tc = rebound(record, lambda p: p[2] - 0.5)
    assert speed == pytest.approx(v, rel=0.01)
    assert tc == pytest.approx(tc_law, rel=0.02)


# ---- a sphere on an inclined plane --------------------------------------------------------------
def incline(scene, data, degrees, mu, rotate, seconds=0.4):
    """The square (scaled to 8 x 8) turned by ``degrees`` about y (it rises towards -x), a sphere
    resting on it at its equilibrium overlap just uphill of the square's diagonal (which it crosses
    after about 0.2), gravity 10 down; returns the acceleration along the slope (downhill positive)
    fitted after the tangential spring has settled, and the record."""
    theta = math.radians(degrees)
    g = 10.0
    sim = scene(box="-6 6 -6 6 -6 6")
    normal = np.array([math.sin(theta), 0.0, math.cos(theta)])
    downhill = np.array([math.cos(theta), 0.0, -math.sin(theta)])
    centre = (0.5 - MASS * g * math.cos(theta) / KN) * normal - 0.05 * downhill
    dt = TC / 50
    record = run_sphere(sim, f"file {data}/square.stl scale 4 rotate axis 0 1 0 angle {degrees} "
                             f"model lsd {E} {KN} {mu}",
                        centre, dt=dt, steps=int(seconds / dt), rotate=rotate, gravity=(0, 0, -g))
    t = np.array(record.t)
    along = record.series("v") @ downhill
    late = t > 0.25 * seconds          # after the tangential spring has settled
    return np.polyfit(t[late], along[late], 1)[0], record, downhill, normal


def test_rolling_without_slipping_below_the_limit(scene, data):
    """A free sphere rolls without slipping while tan(theta) <= 7/2 mu: a = 5/7 g sin(theta), and
    the contact point does not slide (v = omega R). Here tan 20 deg = 0.36 < 3.5 * 0.2 = 0.7, but
    > mu: a sphere that could not spin would slide."""
    a, record, downhill, normal = incline(scene, data, 20.0, 0.2, "yes")
    assert a == pytest.approx(5 / 7 * 10.0 * math.sin(math.radians(20.0)), rel=0.01)
    # the contact point stays at rest, also when the contact passes from one triangle to the next
    # (the spring is handed over: without that the slip jumps to 4 % of the speed)
    t = np.array(record.t)
    v, omega = record.series("v"), record.series("omega")
    slip = np.linalg.norm(v + np.cross(omega, -0.5 * normal), axis=1)
    settled = t > 0.15
    assert np.all(slip[settled] < 0.01 * np.linalg.norm(v[settled], axis=1))
    assert record.series("x")[-1] @ downhill > record.series("x")[0] @ downhill + 0.1


def test_sliding_above_the_rolling_limit(scene, data):
    """tan 40 deg = 0.84 > 3.5 * 0.2: the sphere slides, a = g (sin - mu cos), while friction spins
    it up at 5 mu g cos / (2R)."""
    theta = math.radians(40.0)
    a, record, downhill, normal = incline(scene, data, 40.0, 0.2, "yes")
    assert a == pytest.approx(10.0 * (math.sin(theta) - 0.2 * math.cos(theta)), rel=0.01)
    t = np.array(record.t)
    spin = np.linalg.norm(record.series("omega"), axis=1)
    late = t > 0.1
    assert np.polyfit(t[late], spin[late], 1)[0] == pytest.approx(
        5 * 0.2 * 10.0 * math.cos(theta) / (2 * 0.5), rel=0.01)


@pytest.mark.parametrize("degrees, mu, sticks", [(20.0, 0.5, True), (20.0, 0.2, False)])
def test_a_sphere_that_cannot_spin_sticks_below_the_friction_angle(scene, data, degrees, mu,
                                                                     sticks):
    """Rotation locked (the sphere can only slide): it stays put while tan(theta) < mu
    (tan 20 deg = 0.36 < 0.5) and slides at g (sin - mu cos) above (0.36 > 0.2)."""
    theta = math.radians(degrees)
    a, record, downhill, _ = incline(scene, data, degrees, mu, "no")
    if sticks:
        # it only loads its tangential spring, m g sin / kt = 6e-4 (the spring's overshoot slips
        # a little past the Coulomb limit), then stays; frictionless it would slide 0.27
        along = record.series("x") @ downhill
        stretch = MASS * 10.0 * math.sin(theta) / (2 / 7 * KN)
        assert 0.0 < along.max() - along[0] < 3 * stretch
        assert abs(record.series("v")[-1] @ downhill) < 5e-3
    else:
        assert a == pytest.approx(10.0 * (math.sin(theta) - mu * math.cos(theta)), rel=0.01)


# ---- edges and corners --------------------------------------------------------------------------
def resting_force(scene, mesh_words, position):
    sim = scene()
    sim.command(f"""
        create_particle 1 single {position[0]} {position[1]} {position[2]} diameter 1 density 1
        fix w all wall/mesh {mesh_words} {STATIC}
        run 0
    """)
    return sim.f[0].copy()


@pytest.mark.parametrize("offset", [0.0, 1e-4, 0.02])
def test_edge_shared_by_two_triangles_is_one_contact(scene, data, offset):
    """Over the diagonal of the flat square, or just beside it (where one triangle's closest point
    is inside its face and the other's on the shared edge, a point of the first triangle): force
    kn * overlap up, once."""
    f = resting_force(scene, f"file {data}/square.stl", (0.2, 0.2 + offset, 0.45))
    np.testing.assert_allclose(f, [0, 0, KN * 0.05], rtol=1e-10, atol=1e-9)


def test_outer_edge_and_corner_contacts_point_from_the_edge_and_the_corner(scene, data):
    d = 0.4
    f = resting_force(scene, f"file {data}/square.stl", (1 + 0.6 * d, 0.3, 0.8 * d))
    np.testing.assert_allclose(f, KN * 0.1 * np.array([0.6, 0, 0.8]), rtol=1e-10, atol=1e-9)
    # the corner (1, 1, 0) is shared by both triangles
    f = resting_force(scene, f"file {data}/square.stl", (1 + d / math.sqrt(3), 1 + d / math.sqrt(3),
                                                         -d / math.sqrt(3)))
    np.testing.assert_allclose(f, KN * 0.1 * np.array([1, 1, -1]) / math.sqrt(3), rtol=1e-10)


def ridge(tmp_path, angle):
    """Two triangles meeting along the y axis, each sloping down by ``angle`` away from it."""
    drop = math.tan(math.radians(angle))
    points = np.array([[0, -2, 0], [0, 2, 0], [2, 2, -2 * drop], [2, -2, -2 * drop],
                       [-2, 2, -2 * drop], [-2, -2, -2 * drop]], dtype=float)
    path = tmp_path / "ridge.stl"
    meshio.write(path, meshio.Mesh(points, [("triangle", np.array([[0, 3, 2], [0, 2, 1],
                                                                      [0, 1, 4], [0, 4, 5]]))]))
    return path


def test_sphere_on_a_ridge_touches_the_edge_once(scene, tmp_path):
    """Over a convex ridge the four triangles along it all have their closest point on the ridge
    line: one contact, straight up from the ridge."""
    f = resting_force(scene, f"file {ridge(tmp_path, 20)}", (0.0, 0.3, 0.45))
    np.testing.assert_allclose(f, [0, 0, KN * 0.05], rtol=1e-10, atol=1e-9)
    # a little to the side the face is closer: one contact along the face normal
    theta = math.radians(20)
    n = np.array([math.sin(theta), 0.0, math.cos(theta)])
    centre = np.array([0.5, 0.3, -0.5 * math.tan(theta)]) + 0.45 * n
    f = resting_force(scene, f"file {ridge(tmp_path, 20)}", centre)
    np.testing.assert_allclose(f, KN * 0.05 * n, rtol=1e-9, atol=1e-9)


def test_sphere_in_a_valley_touches_both_faces(scene, tmp_path):
    """Upside down the ridge is a valley: a sphere resting in it touches both faces, two contacts,
    whose horizontal parts cancel."""
    theta = math.radians(20)
    f = resting_force(scene, f"file {ridge(tmp_path, 20)} rotate axis 1 0 0 angle 180",
                      (0.0, 0.3, 0.45 / math.cos(theta)))
    np.testing.assert_allclose(f, [0, 0, 2 * KN * 0.05 * math.cos(theta)], rtol=1e-9, atol=1e-9)


def test_sphere_settles_in_the_hopper_outlet(scene, data):
    """Dropped into the binary-STL funnel, whose outlet (0.6 wide) is narrower than the sphere, it
    comes to rest on the axis touching the four sides; the walls then carry its weight."""
    sim = scene()
    g = 10.0
    run_sphere(sim, f"file {data}/hopper.stl model lsd 0.3 {KN} 0.3", (0.05, -0.03, 0.9),
               dt=TC / 30, steps=4000, gravity=(0, 0, -g))
    assert np.linalg.norm(sim.v[0]) < 1e-3
    np.testing.assert_allclose(sim.x[0, :2], 0.0, atol=1e-3)
    wall = sim.f[0] + np.array([0, 0, MASS * g])
    np.testing.assert_allclose(wall, [0, 0, MASS * g], atol=1e-3)
    assert (sim.fixes["w"].history.partner[0] >= 0).sum() == 4


# ---- moving meshes ------------------------------------------------------------------------------
def test_conveyor_drags_a_resting_sphere_to_the_belt_speed(scene, data):
    """surface_vel U: a sphere that cannot spin is dragged up to U; a free one ends rolling at
    2/7 U (friction speeds it up and spins it until its contact point moves with the belt:
    v + omega R = U with omega R = 5/2 v). Averages over the last 0.2 (two periods of the
    tangential spring, whose oscillation has mostly decayed)."""
    u, g, seconds, dt = 0.5, 10.0, 0.8, TC / 50
    start = (-1.5, 0, 0.5 - MASS * g / KN)
    belt = f"file {data}/square.stl scale 3 surface_vel {u} 0 0 model lsd {E} {KN} 0.4"

    def final(rotate):
        record = run_sphere(scene(), belt, start, dt=dt, steps=int(seconds / dt), rotate=rotate,
                            gravity=(0, 0, -g))
        late = np.array(record.t) > seconds - 0.2
        omega = record.series("omega")[late, 1].mean() if rotate == "yes" else 0.0
        return record.series("v")[late, 0].mean(), omega

    v, _ = final("no")
    assert v == pytest.approx(u, rel=0.01)
    v, omega = final("yes")
    assert v == pytest.approx(2 / 7 * u, rel=0.01)
    assert -omega * 0.5 == pytest.approx(5 / 7 * u, rel=0.01)


def test_translating_plate_launches_a_sphere_at_one_plus_e_times_its_speed(scene, data):
    """A plate rising at V hits a sphere at rest (no gravity): in the plate's frame a head-on impact
    at V, so the sphere leaves at V (1 + e). The mesh moves, so its candidate lists are rebuilt."""
    speed = 0.5
    sim = scene(skin=0.02)
    run_sphere(sim, f"file {data}/square.stl scale 2 move 0 0 -0.51 velocity 0 0 {speed} "
                    f"model lsd {E} {KN} 0.3", (0.4, 0.2, 0.0), steps=300)
    assert sim.v[0, 2] == pytest.approx(speed * (1 + E), rel=0.01)
    assert sim.fixes["w"].builds >= 3          # moved 0.034, skin / 2 = 0.01


def test_turntable_carries_a_sphere_around(scene, data):
    """The square spinning about its normal (z) through its centre at omega = 1: a sphere resting
    at radius 0.6 (rotation locked) is brought to the table's local velocity omega x r (friction
    mu g = 4 is far above the centripetal omega^2 r = 0.6)."""
    g = 10.0
    sim = scene()
    run_sphere(sim, f"file {data}/square.stl scale 2 omega 0 0 1 about 0 0 0 "
                    f"model lsd {E} {KN} 0.4", (0.6, 0.0, 0.5 - MASS * g / KN), dt=TC / 50,
               steps=int(0.6 / (TC / 50)), rotate="no", gravity=(0, 0, -g))
    x, v = sim.x[0], sim.v[0]
    table = np.cross([0, 0, 1.0], [x[0], x[1], 0.0])
    np.testing.assert_allclose(v, table, atol=0.01 * 0.6)
    assert math.hypot(x[0], x[1]) == pytest.approx(0.6, rel=0.01)


# ---- candidate lists ----------------------------------------------------------------------------
def test_candidate_lists_are_rebuilt_only_after_half_a_skin(scene, tmp_path):
    """A sphere rolling slowly over a plane of 800 triangles: lists are built once at setup and again
    only each time it has moved half the skin (0.1); the rolling is smooth across the triangles."""
    n = 20
    grid = np.array([[i, j, 0.0] for i in range(n + 1) for j in range(n + 1)]) * 0.5 - 5.0
    grid[:, 2] = 0.0
    quads = np.array([[i * (n + 1) + j, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1,
                       i * (n + 1) + j + 1] for i in range(n) for j in range(n)])
    path = tmp_path / "plane.vtk"
    meshio.write(path, meshio.Mesh(grid, [("quad", quads)]))
    sim = scene(box="-6 6 -6 6 -6 6", skin=0.2)
    v0 = 0.5
    record = run_sphere(sim, f"file {path} model lsd {E} {KN} 0.5",
                        (0.05, 0.12, 0.5 - MASS * 10.0 / KN), (v0, 0, 0), dt=TC / 30,
                        steps=int(1.0 / (TC / 30)), gravity=(0, 0, -10.0),
                        omega=(0.0, v0 / 0.5, 0.0))
    fix = sim.fixes["w"]
    assert len(fix.triangles) == 800
    travelled = sim.x[0, 0] - 0.05
    assert travelled == pytest.approx(v0 * 1.0, rel=0.01)
    assert fix.builds == pytest.approx(1 + travelled / 0.1, abs=1)
    vx = record.series("v")[:, 0]
    assert np.ptp(vx) < 1e-3 * v0         # rolls on across the triangle edges without a jolt


def test_only_spheres_with_candidate_triangles_are_visited(scene, data):
    """A sphere sliding on the square holds a contact; thrown up beyond its radius plus the skin it
    is no longer visited after the next rebuild of the candidate lists, with no contact left open;
    falling back, it is visited again and its new contact starts from an unstretched spring."""
    sim = scene(skin=0.1)
    run_sphere(sim, f"file {data}/square.stl scale 2 model lsd {E} {KN} 0.5", (0.3, 0.2, 0.499),
               (0.2, 0, 0), rotate="no", steps=5)
    fix, partner = sim.fixes["w"], sim.particles.arrays["wall_w_partner"]
    assert fix.near.tolist() == [0] and (partner[0] >= 0).sum() == 1
    sim.particles.v[0] = (0.0, 0.0, 2.0)
    sim.command("run 600")
    assert sim.x[0, 2] > 0.5 + 0.1 + 0.05
    assert fix.near.tolist() == [] and (partner[0] < 0).all()
    sim.particles.v[0] = (0.0, 0.0, -2.0)
    steps = int((sim.x[0, 2] - 0.499) / (2.0 * TC / 100))
    sim.command(f"run {steps}")
    assert fix.near.tolist() == [0] and (partner[0] >= 0).sum() == 1
    spring = sim.particles.arrays["wall_w_history"][0, :3]
    assert np.abs(spring).max() < 1e-12


register_styles(NoForcePair)


def test_re_sorted_particles_keep_their_walls_and_histories(scene, data):
    """Spheres (which do not see each other) falling into the funnel and stopping in its outlet give
    the same trajectories, bit for bit, whether or not the core re-sorts them in memory every 5
    steps."""
    final = []
    for sort in (False, True):
        sim = scene(skin=0.05)
        sim.command("lattice spacing x 0.45 y 0.45 z 0.45\nregion cloud block -0.45 0.45 -0.45 0.45 1.3 2.0")
        sim.command("create_particle 1 region cloud diameter 0.8 density 1")
        if sort:
            sim.command(f"pair_style {NoForcePair.name}\npair_coeff * *\natom_modify sort 5 0.5")
        sim.command(f"""
            fix 1 all test/nve_sphere
            fix 2 all test/wall_gravity 0 0 -10
            fix w all wall/mesh file {data}/hopper.stl model lsd 0.5 {KN} 0.4
            timestep {TC / 30}
            run 1200
        """)
        order = np.argsort(sim.tag)
        final.append((sim.x[order].copy(), sim.particles.omega[: sim.nlocal][order].copy()))
        if sort:
            assert sim.neighbor.last_sort is not None and sim.neighbor.last_sort > 1100
            assert not np.array_equal(sim.tag, np.sort(sim.tag))      # they were moved in memory
    np.testing.assert_array_equal(final[0][0], final[1][0])
    np.testing.assert_array_equal(final[0][1], final[1][1])
    assert np.abs(final[0][1]).max() > 0.1                             # friction acted


def test_grid_candidates_match_a_brute_force_search(data):
    """The cell grid finds exactly the triangles whose bounding box is within reach, for points all
    around the hopper (inside, outside, beyond the grid)."""
    from pdps_fix_wall.mesh import bin_triangles, candidate_triangles, read_triangles

    points, triangles = read_triangles(os.path.join(data, "hopper.stl"), "hopper.stl")
    corners = points[triangles]
    box_lo, box_hi = corners.min(axis=1), corners.max(axis=1)
    x = np.random.default_rng(7).uniform(-1.6, 1.6, size=(400, 3))
    reach = np.random.default_rng(8).uniform(0.05, 0.4, size=400)
    farthest = reach.max()
    grid_lo = box_lo.min(axis=0) - farthest
    extent = box_hi.max(axis=0) + farthest - grid_lo
    nbins = np.array([5, 4, 3])
    cell = extent / nbins
    start, members = bin_triangles(box_lo, box_hi, grid_lo, cell, nbins, farthest)
    chosen = np.arange(400, dtype=np.int64)
    offsets, found = candidate_triangles(x, chosen, reach, box_lo, box_hi, grid_lo, cell, nbins,
                                         start, members)
    gap = np.linalg.norm(np.maximum(0, np.maximum(box_lo[None] - x[:, None], x[:, None] - box_hi[None])),
                         axis=2)
    for k in range(400):
        assert sorted(found[offsets[k]:offsets[k + 1]]) == list(np.flatnonzero(gap[k] < reach[k]))
    assert 0 < len(found) < 400 * len(triangles) / 2


# ---- files --------------------------------------------------------------------------------------
def mesh_error(tmp_path, name, content):
    path = tmp_path / name
    if content is not None:
        path.write_bytes(content)
    sim = make_box(box="-4 4 -4 4 -4 4", particle_style="sphere")
    with pytest.raises(ScriptError) as info:
        sim.command(f"fix w all wall/mesh file {path} model lsd 0.8 1e4 0.3")
    return str(info.value), str(path)


def test_missing_file(tmp_path):
    message, path = mesh_error(tmp_path, "nowhere.stl", None)
    assert message == f"<command>:1: fix: mesh file {path} does not exist"


def test_empty_file(tmp_path):
    message, path = mesh_error(tmp_path, "empty.stl", b"")
    assert message == f"<command>:1: fix: mesh file {path} is empty"


@pytest.mark.parametrize("name, content", [
    ("nothing.stl", b"solid nothing\nendsolid nothing\n"),
    ("tetra.vtk", None),
])
def test_file_without_triangles_is_not_a_surface(tmp_path, name, content):
    if content is None:
        meshio.write(tmp_path / name, meshio.Mesh(np.eye(4, 3), [("tetra", np.array([[0, 1, 2, 3]]))]))
    message, path = mesh_error(tmp_path, name, content)
    assert message == f"<command>:1: fix: mesh file {path} has no triangles: not a surface mesh"


def test_file_that_is_not_a_mesh(tmp_path):
    message, path = mesh_error(tmp_path, "words.stl", b"hello world\n")
    assert message.startswith(f"<command>:1: fix: mesh file {path} cannot be read as a surface mesh: ")
    assert "\n" not in message


def test_placement_is_applied_in_the_order_given(data):
    """LIGGGHTS: scale, move and rotate act in the order written."""
    sim = make_box(box="-9 9 -9 9 -9 9", particle_style="sphere")
    corner = []
    for words in ("scale 2 move 1 0 0", "move 1 0 0 scale 2",
                  "move 1 0 0 rotate axis 0 0 1 angle 90"):
        sim.command(f"fix w all wall/mesh file {data}/square.stl {words} model lsd 0.8 1e4 0.3")
        corner.append(sim.fixes["w"].vertices[2])      # (1, 1, 0) in the file
    np.testing.assert_allclose(corner, [[3, 2, 0], [4, 2, 0], [-1, 2, 0]], atol=1e-14)


def test_a_placement_given_again_is_applied_again_in_its_place(data):
    """LIGGGHTS: each scale, move and rotate acts once where it is written, repeated ones too, also
    when other keywords stand between them."""
    sim = make_box(box="-9 9 -9 9 -9 9", particle_style="sphere")
    sim.command(f"fix w all wall/mesh file {data}/square.stl scale 2 move 1 0 0 model lsd 0.8 1e4 0.3 "
                "scale 2 rotate axis 0 0 1 angle 90 move 0 0 1")
    # (1, 1, 0) -> (2, 2, 0) -> (3, 2, 0) -> (6, 4, 0) -> (-4, 6, 0) -> (-4, 6, 1)
    np.testing.assert_allclose(sim.fixes["w"].vertices[2], [-4, 6, 1], atol=1e-14)


def test_relative_file_names_are_read_from_the_script_folder(data, tmp_path):
    script = tmp_path / "in.mesh"
    script.write_text(f"particle_style sphere\nregion box block -4 4 -4 4 -4 4\ncreate_box 1 box\n"
                      f"fix w all wall/mesh file {os.path.relpath(data, tmp_path)}/hopper.stl "
                      f"move 0 0 -1 model lsd 0.8 1e4 0.3\n")
    sim = Simulation(screen=False, log=None).file(str(script))
    fix = sim.fixes["w"]
    assert len(fix.triangles) == 8
    np.testing.assert_allclose(fix.vertices[:, 2].min(), -1.0)


@pytest.mark.parametrize("words, message", [
    ("model lsd 0.8 1e4 0.3", "missing keyword file"),
    ("file {data}/square.stl", "missing keyword model"),
    ("file {data}/square.stl spin 1 model lsd 0.8 1e4 0.3", "unknown keyword spin"),
    ("file {data}/square.stl scale 0 model lsd 0.8 1e4 0.3", "scale must be > 0 (got 0)"),
    ("file {data}/square.stl move 1 2 model lsd 0.8 1e4 0.3", "keyword move needs 3 value(s) (got 1 2)"),
    ("file {data}/square.stl rotate 0 0 1 angle 30 x model lsd 0.8 1e4 0.3",
     "placement rotate must be one of 'axis' (got 0)"),
    ("file {data}/square.stl rotate axis 0 0 0 angle 30 model lsd 0.8 1e4 0.3",
     "rotate axis must not be zero"),
    ("file {data}/square.stl omega 0 0 1 at 0 0 0 model lsd 0.8 1e4 0.3",
     "omega must be one of 'about' (got at)"),
    ("file {data}/square.stl surface_vel 1 0 0 velocity 0 0 1 model lsd 0.8 1e4 0.3",
     "surface_vel (a conveyor) cannot be combined with velocity or omega"),
    ("file {data}/square.stl model lsd 0.8 1e4", "model lsd takes number number number number number number or number number number (got 0.8 1e4)"),
    ("file {data}/square.stl model hertz 1e5 0.7 0.8 0.3", "nu must be in (-1, 0.5) (got 0.7)"),
    ("file {data}/square.stl model jkr 1", "model must be one of lsd, hertz (got jkr)"),
    ("file {data}/square.stl model lsd 0.8 1e308 0.3",
     "model must be 0 or of magnitude from 1e-50 to 1e+50 (got 1e+308)"),
])
def test_bad_arguments(data, words, message):
    sim = make_box(box="-4 4 -4 4 -4 4", particle_style="sphere")
    with pytest.raises(ScriptError) as info:
        sim.command("fix w all wall/mesh " + words.format(data=data))
    assert message in str(info.value)
    assert "\n" not in str(info.value)


def test_point_particles_are_an_error(data):
    sim = make_box(f"mass 1 1\ncreate_particle 1 single 0 0 1\nfix w all wall/mesh file {data}/square.stl "
                   f"model lsd 0.8 1e4 0.3", box="-4 4 -4 4 -4 4")
    with pytest.raises(ScriptError, match=r"needs particle radii \(particle_style sphere\)"):
        sim.command("run 0")


def test_a_flat_mesh_with_skin_0_and_no_sphere_bins_without_dividing_by_zero(data):
    # the candidate grid had cells of width 0 across the plate (found by the fuzz suite)
    sim = make_box(f"neighbor 0 bin\nfix w all wall/mesh file {data}/square.stl model lsd 0.8 1e4 0.3",
                   box="-4 4 -4 4 -4 4", particle_style="sphere")
    sim.command("run 3")
    assert sim.step == 3 and sim.fixes["w"].builds == 1
