"""fix mesh/surface and fix move/mesh: every motion puts the vertices where its formula says, to
round-off, at several times (the oscillating ones where LIGGGHTS's step-by-step update of the
velocity at each step's end puts them); superposed motions compose as the manual gives (the
second in the frame carried by the first); the wall velocity is the time derivative of the vertex
positions; bad words get one line.

The reference positions are computed here from the formulas, with Rodrigues' formula written out
(v cos + (k x v) sin + k (k.v)(1 - cos)), not with the code under test.
"""

import math
import os

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import make_box

DATA = os.path.join(os.path.dirname(__file__), "data")
DT = 0.01


def turned(points, axis, origin, angle):
    k = np.asarray(axis, float) / np.linalg.norm(axis)
    v = points - origin
    return (origin + v * math.cos(angle) + np.cross(k, v) * math.sin(angle)
            + np.outer(v @ k, k) * (1.0 - math.cos(angle)))


def mesh_scene(data, *moves, extra=""):
    sim = make_box(f"""
        fix cad all mesh/surface file {data}/square.stl type 1 scale 2 move 0.5 0 1 {extra}
        {chr(10).join(f"fix m{k} all move/mesh mesh cad {m}" for k, m in enumerate(moves))}
        timestep {DT}
    """, box="-10 10 -10 10 -10 10", particle_style="sphere")
    return sim, sim.fixes["cad"]


def positions_over_time(sim, mesh, steps):
    """(time, vertices) after each of the runs of the given lengths."""
    out = []
    for n in steps:
        sim.command(f"run {n}")
        out.append((sim.step * DT, mesh.vertices.copy()))
    return out


X0 = None


def start(data):
    sim, mesh = mesh_scene(data)
    return mesh.placed.copy()


LINEAR = "linear 0.3 -0.2 0.1"
WIGGLE = "wiggle amplitude 0.1 0.05 -0.2 period 0.37"
ROTATE = "rotate origin 0.2 -0.1 0.3 axis 1 1 2 period 1.3"
RIGGLE = "riggle origin 0.2 -0.1 0.3 axis 0 1 1 period 0.7 amplitude 25"
VIBLIN = "viblin axis 1 0 1 order 2 amplitude 0.1 0.03 phase 0.3 -1.2 period 0.5"
VIBROT = "vibrot origin 0 0 1 axis 0 0 1 order 3 amplitude 0.2 0.1 0.05 phase 0 0.5 1.0 period 0.8"


def _stepped(rate, t):
    """sum over the steps n = 1..t/DT of rate(n DT) DT: LIGGGHTS's update of the oscillating motions."""
    return sum(rate(n * DT) for n in range(1, round(t / DT) + 1)) * DT


def expected(style, x0, t):
    if style == LINEAR:
        return x0 + np.array([0.3, -0.2, 0.1]) * t
    if style == WIGGLE:
        w = 2 * math.pi / 0.37
        return x0 + np.array([0.1, 0.05, -0.2]) * _stepped(lambda s: w * math.cos(w * s), t)
    if style == ROTATE:
        return turned(x0, [1, 1, 2], np.array([0.2, -0.1, 0.3]), 2 * math.pi / 1.3 * t)
    if style == RIGGLE:
        w = 2 * math.pi / 0.7
        angle = _stepped(lambda s: math.radians(25) * w * math.cos(w * s), t)
        return turned(x0, [0, 1, 1], np.array([0.2, -0.1, 0.3]), angle)
    if style == VIBLIN:
        w = 2 * math.pi / 0.5
        shift = _stepped(lambda s: -0.1 * w * math.sin(w * s + 0.3) - 0.03 * 2 * w * math.sin(2 * w * s - 1.2), t)
        return x0 + np.array([1, 0, 1]) / math.sqrt(2) * shift
    w = 2 * math.pi / 0.8
    angle = _stepped(lambda s: sum(-c * k * w * math.sin(k * w * s + p)
                                   for k, c, p in zip((1, 2, 3), (0.2, 0.1, 0.05), (0, 0.5, 1.0))), t)
    return turned(x0, [0, 0, 1], np.array([0.0, 0.0, 1.0]), angle)


@pytest.mark.parametrize("style", [LINEAR, WIGGLE, ROTATE, RIGGLE, VIBLIN, VIBROT],
                         ids=["linear", "wiggle", "rotate", "riggle", "viblin", "vibrot"])
def test_each_motion_puts_the_vertices_where_its_formula_says(data, style):
    sim, mesh = mesh_scene(data, style)
    x0 = mesh.placed.copy()
    for t, vertices in positions_over_time(sim, mesh, [1, 16, 40, 100]):
        np.testing.assert_allclose(vertices, expected(style, x0, t), rtol=0, atol=1e-12)


def test_variable_motions_integrate_their_rates(data):
    """linear/variable with a constant velocity and rotate/variable with a constant omega are
    linear and rotate (to round-off of the summed steps)."""
    sim, mesh = mesh_scene(data)
    sim.command("""
        variable vx equal 0.3
        variable vy equal -0.2
        variable vz equal 0.1
        variable w equal 2*PI/1.3
        fix a all move/mesh mesh cad linear/variable v_vx v_vy v_vz
    """)
    x0 = mesh.placed.copy()
    sim.command("run 50")
    np.testing.assert_allclose(mesh.vertices, expected(LINEAR, x0, 50 * DT), atol=1e-12)
    sim2, mesh2 = mesh_scene(data)
    sim2.command("""
        variable w equal 2*PI/1.3
        fix a all move/mesh mesh cad rotate/variable origin 0.2 -0.1 0.3 axis 1 1 2 omega v_w
    """)
    sim2.command("run 50")
    np.testing.assert_allclose(mesh2.vertices, expected(ROTATE, mesh2.placed, 50 * DT), atol=1e-12)


def test_variable_velocity_that_changes_in_time(data):
    """v_x = t (the time): the mesh moves by the sum of v dt over the steps, LIGGGHTS's explicit
    update, which tends to t^2 / 2."""
    sim, mesh = mesh_scene(data)
    sim.command("""
        variable vx equal time
        variable zero equal 0
        fix a all move/mesh mesh cad linear/variable v_vx v_zero v_zero
    """)
    sim.command("run 100")
    # time at each step's update is the step's time: sum_{n=0}^{99} n dt * dt (time before the step)
    # or sum_{n=1}^{100}; either is t^2/2 within dt t / 2
    moved = mesh.vertices[:, 0] - mesh.placed[:, 0]
    assert moved == pytest.approx(np.full(len(moved), 0.5), abs=0.5 * DT * 1.0 + 1e-12)


def test_superposed_motions_move_in_the_frame_of_the_earlier_ones(data):
    """rotate about z through the origin, then rotate about an axis through (1, 0, 1) carried by the
    first: X = T1(T2(X0)); then a wiggle on top of both: X = T1(T2(T3(X0)))."""
    first = "rotate origin 0 0 0 axis 0 0 1 period 2.0"
    second = "rotate origin 1 0 1 axis 1 0 0 period 0.9"
    sim, mesh = mesh_scene(data, first, second, WIGGLE)
    x0 = mesh.placed.copy()
    for t, vertices in positions_over_time(sim, mesh, [7, 30, 63]):
        inner = expected(WIGGLE, x0, t)
        middle = turned(inner, [1, 0, 0], np.array([1.0, 0.0, 1.0]), 2 * math.pi / 0.9 * t)
        outer = turned(middle, [0, 0, 1], np.zeros(3), 2 * math.pi / 2.0 * t)
        np.testing.assert_allclose(vertices, outer, atol=1e-12)


@pytest.mark.parametrize("moves", [[ROTATE], [RIGGLE, LINEAR], [VIBROT, WIGGLE, ROTATE]],
                         ids=["rotate", "riggle+linear", "vibrot+wiggle+rotate"])
def test_the_wall_velocity_is_the_derivative_of_the_vertex_positions(data, moves):
    """velocity + spin x (p - pivot) at each vertex against central differences of its positions
    over steps of 1e-7 (error O(dt) with the oscillating motions' step-end velocities: below 1e-5 of
    the speeds here)."""
    sim, mesh = mesh_scene(data, *moves)
    sim.command("run 20")
    h = 1e-7
    sim.command(f"timestep {h}")
    before = mesh.vertices.copy()
    sim.command("run 1")
    now = mesh.vertices.copy()
    wall = mesh.velocity + np.cross(mesh.spin, now - mesh.pivot)
    sim.command("run 1")
    after = mesh.vertices.copy()
    numeric = (after - before) / (2 * h)
    scale = np.abs(numeric).max()
    np.testing.assert_allclose(wall, numeric, atol=1e-5 * scale)


def test_a_mesh_that_does_not_move_has_no_wall_velocity(data):
    sim, mesh = mesh_scene(data)
    sim.command("run 5")
    assert not mesh.moving
    np.testing.assert_array_equal(mesh.vertices, mesh.placed)
    assert not np.any(mesh.velocity) and not np.any(mesh.spin)


@pytest.mark.parametrize("words, message", [
    ("mesh nothere linear 1 0 0", "fix nothere is not defined"),
    ("mesh cad spin 1 0 0", "motion must be one of linear, linear/variable, wiggle, rotate"),
    ("mesh cad linear 1 0", "motion linear takes 3 value(s): number number number (got 1 0)"),
    ("mesh cad linear 1 0 0 5", "unknown keyword 5 (known: origin, axis, order, amplitude, phase, period, omega)"),
    ("mesh cad wiggle amplitude 1 0 0 every 2", "amplitude must be a finite number (got every)"),
    ("mesh cad rotate origin 0 0 0 axis 0 0 0 period 1", "rotate axis must not be zero"),
    ("mesh cad rotate origin 0 0 0 axis 0 0 1 period -1", "rotate: period must be > 0 (got -1)"),
    ("mesh cad viblin axis 0 0 1 order 11 amplitude 1 phase 0 period 1",
     "viblin: order must be from 1 to 10 (got 11)"),
    ("mesh cad viblin axis 0 0 1 order 2 amplitude 1 phase 0 period 1",
     "viblin: amplitude needs 2 value(s) (got 1)"),
    ("mesh cad linear/variable 1 2 3", "linear/variable: expected a variable v_NAME (got 1)"),
    ("mesh cad wiggle amplitude 1 0 0", "wiggle: expected keyword period; usage: wiggle amplitude AX AY AZ period T"),
    ("mesh cad linear 1 0 0 period 2", "linear takes no period"),
    ("linear 1 0 0", "expected mesh MESH_ID and a motion"),
    ("mesh cad linear abc 0 0", "motion must be a finite number (got abc)"),
    ("cad linear 1 0 0", "motion must be one of linear, linear/variable, wiggle, rotate, rotate/variable, "
     "riggle, viblin, vibrot (got cad)"),
])
def test_bad_move_mesh_words(data, words, message):
    sim, _ = mesh_scene(data)
    with pytest.raises(ScriptError) as info:
        sim.command("fix bad all move/mesh " + words)
    assert message in str(info.value)
    assert "\n" not in str(info.value)


def test_the_keywords_of_a_motion_stand_in_any_order(data):
    """LIGGGHTS writes origin, axis, period in that order; any order means the same turn: a quarter
    period turns the mesh by 90 degrees about the axis through the origin, which stays where it is."""
    poses = []
    for words in ("rotate origin 1 0 0 axis 0 0 1 period 2", "rotate period 2 axis 0 0 1 origin 1 0 0"):
        sim, _ = mesh_scene(data, words)
        mover = sim.fixes["m0"]
        mover.elapsed = 0.5
        poses.append(mover.pose())
    for first, second in zip(*poses):
        np.testing.assert_array_equal(first, second)
    rotation, shift = poses[0][:2]
    np.testing.assert_allclose(rotation @ [1.0, 0.0, 0.0] + shift, [1.0, 0.0, 0.0], atol=1e-15)
    np.testing.assert_allclose(rotation @ [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], atol=1e-15)


def test_a_conveyor_cannot_be_moved(data):
    sim, _ = mesh_scene(data, extra="surface_vel 1 0 0")
    with pytest.raises(ScriptError, match="a conveyor cannot also be moved"):
        sim.command("fix bad all move/mesh mesh cad linear 1 0 0")


@pytest.mark.parametrize("words, message", [
    ("type 1", "expected file FILE or fix MESH_ID (got neither)"),
    ("file {data}/square.stl fix other", "expected file FILE or fix MESH_ID (got both)"),
    ("file {data}/square.stl type 7", "type must be from 1 to 1, the number of types (got 7)"),
    ("file {data}/square.stl type x", "type must be an integer (got x)"),
    ("file {data}/square.stl curvature 61", "curvature must be in (0, 60] degrees (got 61)"),
    ("file {data}/square.stl precision 0.002", "precision must be in (0, 0.001] (got 0.002)"),
    ("file {data}/square.stl precision -1e-5", "precision must be in (0, 0.001] (got -1e-05)"),
    ("file {data}/square.stl surface_ang_vel origin 0 0 0 axis 0 0 1 spin 1",
     "surface_ang_vel must be one of 'omega' (got spin)"),
    ("file {data}/square.stl scale 0", "scale must be > 0 (got 0)"),
    ("file {data}/nothere.stl", "mesh file {data}/nothere.stl does not exist"),
    ("file {data}/square.stl wobble 1", "unknown keyword wobble"),
    ("file {data}/square.stl element_exclusion_list read ex.txt", "element exclusion list ex.txt does not exist"),
    ("file {data}/square.stl element_exclusion_list keep ex.txt",
     "element_exclusion_list must be one of 'read' or 'write' (got keep)"),
    ("file {data}/square.stl min_feature_length 0.1", "min_feature_length needs element_exclusion_list write FILE"),
    ("file {data}/square.stl min_feature_length 0.1 element_exclusion_list write ex.txt",
     "min_feature_length is not supported: LIGGGHTS 3.8.0 has no feature removal either"),
    ("file {data}/square.stl mass_temperature 0", "mass_temperature must be > 0 (got 0)"),
    ("file {data}/square.stl extrude_planar 0", "extrude_planar must be > 0 (got 0)"),
    ("fix nothere", "fix nothere is not defined"),
    ("file {data}/square.stl scale 2 scale x", "placement scale must be a finite number (got x)"),
])
def test_bad_mesh_surface_words(data, words, message):
    sim = make_box(box="-4 4 -4 4 -4 4", particle_style="sphere")
    with pytest.raises(ScriptError) as info:
        sim.command("fix cad all mesh/surface " + words.format(data=data))
    assert message.format(data=data) in str(info.value)
    assert "\n" not in str(info.value)


# ---- a sphere on a moving plate -----------------------------------------------------------------
MASS = math.pi / 6.0
KN, E_REST, G = 1.0e4, 0.8, 10.0


def plate_run(data, motion, velocity, steps=400):
    """A sphere (d = 1, density 1) resting at its equilibrium overlap on the square plate at z = 0
    under gravity, moving with the plate's velocity; returns the wall force on it at each step."""
    sim = make_box(f"""
        fix cad all mesh/surface file {data}/square.stl scale 3
        {f"fix mv all move/mesh mesh cad {motion}" if motion else ""}
        create_particle 1 single 0.2 0.1 {0.5 - MASS * G / KN} diameter 1 density 1
        velocity all set {velocity[0]} {velocity[1]} {velocity[2]}
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-G}
        fix w all wall/mesh mesh cad model lsd {E_REST} {KN} 0.5
        fix r all test/record
        timestep 0.001
    """, box="-10 10 -10 10 -10 10", particle_style="sphere")
    sim.command(f"run {steps}")
    force = np.array(sim.fixes["r"].series("f")) + np.array([0.0, 0.0, MASS * G])
    return force, sim


@pytest.mark.parametrize("velocity", [(0.0, 0.0, 0.7), (0.4, -0.3, 0.0), (0.2, 0.1, -0.3)],
                         ids=["rising", "sliding-sideways", "oblique"])
def test_a_sphere_on_a_plate_moving_at_constant_velocity_feels_the_force_of_a_fixed_plate(
        data, velocity):
    """Galilean invariance: carried along at the plate's velocity, the sphere feels at every step
    the contact force it feels on the fixed plate (m g up, nothing sideways) to round-off."""
    fixed, _ = plate_run(data, None, (0, 0, 0))
    moving, sim = plate_run(data, f"linear {velocity[0]} {velocity[1]} {velocity[2]}", velocity)
    np.testing.assert_allclose(fixed[-1], [0, 0, MASS * G], rtol=0, atol=1e-9)
    np.testing.assert_allclose(moving, fixed, rtol=0, atol=1e-9 * MASS * G)
    # and it did travel with the plate, whose candidate lists were rebuilt as it went
    np.testing.assert_allclose(sim.x[0, :2], np.array([0.2, 0.1]) + 0.4 * np.array(velocity[:2]), atol=1e-9)
    travelled = 0.4 * np.linalg.norm(velocity)
    assert sim.fixes["w"].builds == 1 + int(travelled / (0.5 * sim.neighbor.skin))


def test_moving_meshes_and_their_walls_continue_through_a_restart_file(data, tmp_path):
    """rotate + wiggle on a mesh/surface/stress floor under a wall/gran model with spheres resting on
    it: 30 steps, write_restart, read_restart, 20 steps is the 50-step run, vertices, particles and
    floor force alike (the motions' clocks and the contact histories are in the file)."""
    from pdps_core.testing import restart_round_trip
    setup = f"""
        atom_style granular
        boundary f f f
        region box block -4 4 -4 4 -2 4
        create_box 1 box
        create_atoms 1 single 0.3 0.1 0.4995
        create_atoms 1 single -0.4 -0.3 0.4998
        set type 1 diameter 1 density 1
        fix m1 all property/global youngsModulus peratomtype 1.0e5
        fix m2 all property/global poissonsRatio peratomtype 0.3
        fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
        fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
        fix floor all mesh/surface/stress file {data}/square.stl scale 2
        fix spin all move/mesh mesh floor rotate origin 0 0 0 axis 0 0 1 period 3.0
        fix shake all move/mesh mesh floor wiggle amplitude 0 0 0.002 period 0.05
        fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes floor
        fix 1 all nve/sphere
        fix 2 all gravity 10 vector 0 0 -1
        timestep 0.001
    """
    straight, resumed = restart_round_trip(tmp_path, setup, 30, 20)
    np.testing.assert_array_equal(resumed.fixes["floor"].vertices, straight.fixes["floor"].vertices)
    np.testing.assert_array_equal(resumed.x, straight.x)
    np.testing.assert_array_equal(resumed.fixes["floor"].vector(resumed), straight.fixes["floor"].vector(straight))
    assert straight.fixes["floor"].vector(straight)[2] < 0


@pytest.mark.parametrize("conveyor, expected", [
    ("surface_vel 0.5 0 0", lambda x: np.array([0.5, 0.0, 0.0])),
    ("surface_ang_vel origin 0 0 0 axis 0 0 2 omega 1.0", lambda x: np.cross([0, 0, 1.0], [x[0], x[1], 0.0])),
], ids=["surface_vel", "surface_ang_vel"])
def test_a_conveyor_mesh_drags_a_resting_sphere_to_its_surface_velocity(data, conveyor, expected):
    """mesh/surface with surface_vel (a belt) or surface_ang_vel (a turning surface, as a shear cell):
    the mesh stays put, and a sphere that cannot spin, resting on it, is dragged by friction to the
    surface's velocity where it touches."""
    g = 10.0
    sim = make_box(f"""
        fix cad all mesh/surface file {data}/square.stl scale 3 {conveyor}
        create_particle 1 single 0.6 0.0 {0.5 - MASS * g / KN} diameter 1 density 1
        fix 1 all test/nve_sphere rotate no
        fix 2 all test/wall_gravity 0 0 {-g}
        fix w all wall/mesh mesh cad model lsd {E_REST} {KN} 0.5
        timestep 0.0005
    """, box="-10 10 -10 10 -10 10", particle_style="sphere")
    sim.command("run 1200")
    np.testing.assert_allclose(sim.v[0], expected(sim.x[0]), atol=0.01 * 0.6)
    np.testing.assert_array_equal(sim.fixes["cad"].vertices, sim.fixes["cad"].placed)


def test_mesh_surface_planar_takes_a_flat_mesh_and_refuses_a_funnel(data):
    sim = make_box(f"fix face all mesh/surface/planar file {data}/square.stl scale 2 rotate axis 1 1 0 angle 30",
                   box="-4 4 -4 4 -4 4", particle_style="sphere")
    assert len(sim.fixes["face"].triangles) == 2
    with pytest.raises(ScriptError, match=r"hopper.stl is not planar: a vertex lies 1\.\d+ from the plane of its "
                                          r"first triangle \(use fix mesh/surface\)$"):
        sim.command(f"fix funnel all mesh/surface/planar file {data}/hopper.stl")


@pytest.mark.parametrize("curvature, taken_over", [(5.0, True), (1.0, False)])
def test_curvature_is_the_angle_within_which_a_contact_hands_its_history_on(curvature, taken_over):
    """wall_slots with the cosine of mesh/surface's curvature: a contact that ended on triangle 5
    (normal along z, spring (1, 2, 0)) and a new one on triangle 6 whose normal is 3 degrees away:
    within curvature 5 the new contact continues the old one's spring; within 1 it starts afresh."""
    from pdps_granular_contact.contact_slots import wall_slots
    sim = make_box(f"fix cad all mesh/surface file {DATA}/square.stl curvature {curvature}",
                   box="-4 4 -4 4 -4 4", particle_style="sphere")
    capacity, width = 4, 6
    partner = np.full((1, capacity), -1, dtype=np.int64)
    values = np.zeros((1, capacity * width))
    partner[0, 0] = 5
    values[0, 0:6] = [1.0, 2.0, 0.0, 0.0, 0.0, 1.0]
    tilt = math.radians(3.0)
    normal = np.array([[math.sin(tilt), 0.0, math.cos(tilt)]])
    slots = np.empty(1, dtype=np.int64)
    ok = wall_slots(0, 0, 1, np.array([0.4]), normal, np.array([6]), 0.5, partner, values, 3, True,
                    np.empty(capacity, dtype=np.bool_), slots, sim.fixes["cad"].transfer_cos)
    assert ok
    assert partner[0].tolist().count(6) == 1 and 5 not in partner[0].tolist()
    spring = values[0, slots[0] * width:slots[0] * width + 3].tolist()
    assert spring == ([1.0, 2.0, 0.0] if taken_over else [0.0, 0.0, 0.0])


def test_an_unfixed_motion_leaves_the_mesh_where_it_took_it(data):
    """LIGGGHTS's movingMeshGran tutorial: linear, unfix, then rotate about the origin: the rotation
    turns the moved mesh, X(t) = R(t) (X0 + V t1), as LIGGGHTS 3.8.0's bucket went (its dump mesh/stl
    at step 60000 to 1e-7, where pdps turned the mesh as read and added the move after, 0.65 off);
    between the two motions the mesh is at rest. Unfixing one of two motions at once is refused."""
    import meshio
    sim = make_box(f"""
        fix cad all mesh/surface file {data}/square.stl
        fix go all move/mesh mesh cad linear -0.5 0 -0.3
        timestep 0.001
        run 200
        unfix go
        run 10
    """, box="-4 4 -4 4 -4 4", particle_style="sphere")
    mesh = sim.fixes["cad"]
    square = meshio.read(f"{data}/square.stl")
    moved = square.points + [-0.1, 0.0, -0.06]
    np.testing.assert_allclose(mesh.vertices, moved, atol=1e-12)
    np.testing.assert_array_equal(mesh.velocity, 0.0)
    sim.command("fix turn all move/mesh mesh cad rotate origin 0 0 0 axis 0 1 0 period 2.0\nrun 300")
    angle = math.pi * 0.3
    turn = np.array([[math.cos(angle), 0, math.sin(angle)], [0, 1, 0], [-math.sin(angle), 0, math.cos(angle)]])
    np.testing.assert_allclose(mesh.vertices, moved @ turn.T, atol=1e-12)
    sim.command("fix up all move/mesh mesh cad linear 0 0 1")
    with pytest.raises(ScriptError, match="mesh cad has other move/mesh fixes \\(up\\) moving it at once"):
        sim.command("unfix turn")
    assert "turn" in sim.fixes
