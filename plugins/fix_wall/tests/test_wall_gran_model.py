"""fix wall/gran model ... (LIGGGHTS's spelling): a sphere bouncing head-on off each primitive wall
(planes from either side, cylinders from inside and outside) and off a mesh plane leaves at e times
its speed, e the coefficientRestitution of the type pair (particle, wall); the hooke model's contact
time; sliding walls (shear) and turning cylinders drag a sphere by friction; exact error lines.

Units lj; spheres of diameter 1, density 1 (m = pi/6). Two types: particles of type 1, walls of type
2 with another material, so the pair (1, 2) is what the wall must use.
"""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import liggghts_material, make_box

MASS = math.pi / 6.0
E12 = 0.7
MATERIAL = liggghts_material((1.0e5, 3.0e5), (0.3, 0.25), (0.9, E12, E12, 0.5), (0.5, 0.4, 0.4, 0.3),
                             characteristicVelocity=1.0)


def y_star():
    return 1.0 / ((1 - 0.3 ** 2) / 1.0e5 + (1 - 0.25 ** 2) / 3.0e5)


def hooke_time():
    """Contact time of LIGGGHTS's hooke law for m* = m, R* = R = 0.5, V = 1."""
    ys, r = y_star(), 0.5
    kn = 16 / 15 * math.sqrt(r) * ys * (15 * MASS / (16 * math.sqrt(r) * ys)) ** 0.2
    log_e = math.log(E12)
    gamma = math.sqrt(4 * MASS * kn * log_e ** 2 / (log_e ** 2 + math.pi ** 2))
    return math.pi / math.sqrt(kn / MASS - (gamma / (2 * MASS)) ** 2)


def bounce(model, wall, start, velocity, steps=400, extra=""):
    dt = hooke_time() / 100
    sim = make_box(f"""
        create_particle 1 single {start[0]} {start[1]} {start[2]} diameter 1 density 1
        velocity all set {velocity[0]} {velocity[1]} {velocity[2]}
        {MATERIAL}
        {extra}
        fix 1 all test/nve_sphere
        fix w all wall/gran model {model} tangential history {wall}
        fix r all test/record
        timestep {dt}
    """, box="-6 6 -6 6 -6 6", particle_style="sphere", ntypes=2, boundary="f f f")
    sim.command(f"run {steps}")
    return sim


PRIMITIVES = [
    ("primitive type 2 xplane -1.0", (-0.49, 0.2, 0.1), (-1, 0, 0)),
    ("primitive type 2 xplane -1.0", (-1.51, 0.2, 0.1), (1, 0, 0)),          # from the other side
    ("primitive type 2 yplane 2.0", (0.3, 1.49, 0.0), (0, 1, 0)),
    ("primitive type 2 zplane 0.5", (0.0, 0.0, 1.01), (0, 0, -1)),
    ("primitive type 2 zcylinder 3.0 0.5 -0.5", (0.5 + 2.49 * 0.6, -0.5 + 2.49 * 0.8, 0.3), (0.6, 0.8, 0)),
    ("primitive type 2 zcylinder 1.0 0.5 -0.5", (0.5, -0.5 + 1.51, 0.3), (0, -1, 0)),      # outside
    ("primitive type 2 xcylinder 3.0 1.0 0.0", (0.3, 1.0 + 2.49, 0.0), (0, 1, 0)),           # (y, z)
    ("primitive type 2 ycylinder 3.0 1.0 0.0", (0.0, 0.4, 1.0 - 2.49), (0, 0, -1)),          # (z, x)
]


@pytest.mark.parametrize("wall, start, direction", PRIMITIVES,
                         ids=["xplane", "xplane-below", "yplane", "zplane", "zcylinder-inside",
                              "zcylinder-outside", "xcylinder", "ycylinder"])
@pytest.mark.parametrize("model, tolerance", [("hooke", 0.005), ("hertz", 0.01)])
def test_head_on_bounce_off_each_primitive_has_the_pair_restitution(wall, start, direction, model,
                                                                     tolerance):
    """Speed 1 straight at the wall: it comes back along the same line at e12 = 0.7 (hooke: the
    linear law's e exactly, to the time step's error; hertz: LIGGGHTS's damping, close to e)."""
    v = np.array(direction, float)
    sim = bounce(model, wall, start, v)
    assert sim.v[0] @ v == pytest.approx(-E12, rel=tolerance)
    np.testing.assert_allclose(np.cross(sim.v[0], v), 0.0, atol=1e-9)


def test_a_primitive_wall_keeps_two_history_slots_a_particle():
    """A plane touches a sphere at one point: its contact history is 2 slots a particle (a partner
    and 6 values each, hertz's spring and the contact's normal: 112 bytes), not the 16 a mesh wall
    keeps; the bounce, which needs the spring of its one contact, still leaves at e."""
    sim = bounce("hertz", "primitive type 2 zplane 0.5", (0.0, 0.0, 1.01), (0, 0, -1))
    arrays = sim.particles.arrays
    assert arrays["wall_w_partner"].shape[1:] == (2,)
    assert arrays["wall_w_history"].shape[1:] == (12,)
    assert arrays["wall_w_partner"].itemsize * 2 + arrays["wall_w_history"].itemsize * 12 == 112
    assert sim.v[0, 2] == pytest.approx(E12, rel=0.01)


def test_hooke_contact_time_against_a_plane():
    """The sphere touches the plane for the linear law's contact time pi / sqrt(kn/m - (gn/2m)^2),
    within 2 % (two time steps)."""
    sim = bounce("hooke", "primitive type 2 zplane 0.0", (0, 0, 0.505), (0, 0, -1))
    record = sim.fixes["r"]
    t = np.array(record.t)
    touching = np.array(record.series("x"))[:, 2] < 0.5
    assert touching.sum() * (t[1] - t[0]) == pytest.approx(hooke_time(), rel=0.02)


def test_bounce_off_a_mesh_plane(data):
    """The square (type 2) as a mesh wall: the same rebound as off zplane."""
    sim = bounce("hooke", "mesh n_meshes 1 meshes cad", (0.3, -0.2, 0.51), (0, 0, -1),
                 extra=f"fix cad all mesh/surface file {data}/square.stl type 2")
    assert sim.v[0, 2] == pytest.approx(E12, rel=0.005)


def test_two_meshes_each_with_its_material(data, tmp_path):
    """Two meshes, one of type 2 (e = 0.7 against type 1) at z = 0 and one of type 1 (e = 0.9) at
    z = 3 turned over: a sphere bouncing between them loses speed by 0.7 then 0.9."""
    sim = bounce("hooke", "mesh n_meshes 2 meshes low high", (0.3, -0.2, 0.51), (0, 0, -1),
                 steps=400 + int((2.0 / E12 + 1.0) / (hooke_time() / 100)),
                 extra=f"fix low all mesh/surface file {data}/square.stl type 2\n"
                       f"fix high all mesh/surface file {data}/square.stl type 1 move 0 0 3")
    assert sim.v[0, 2] == pytest.approx(-E12 * 0.9, rel=0.01)


def test_a_sliding_plane_drags_a_resting_sphere():
    """zplane with shear x 0.5 under gravity: a sphere that cannot spin is dragged up to the wall's
    speed (0.5 along x) by friction, and stays on the wall."""
    sim = make_box(f"""
        create_particle 1 single 0 0 0.499 diameter 1 density 1
        {MATERIAL}
        fix 1 all test/nve_sphere rotate no
        fix 2 all test/wall_gravity 0 0 -10
        fix w all wall/gran model hooke tangential history primitive type 2 zplane 0.0 shear x 0.5
        timestep {hooke_time() / 50}
    """, box="-6 6 -6 6 -6 6", particle_style="sphere", ntypes=2, boundary="f f f")
    sim.command(f"run {int(1.0 / (hooke_time() / 50))}")
    assert sim.v[0, 0] == pytest.approx(0.5, rel=0.01)
    assert sim.x[0, 2] == pytest.approx(0.5, abs=0.01)


def test_a_turning_cylinder_carries_a_sphere_at_its_surface_speed():
    """zcylinder of radius 2 turning at omega = 0.5 (shear x 0.5): a sphere that cannot spin,
    pressed onto its inside by a force along x, is dragged up to the wall's surface speed
    omega R_c = 1.0, along the wall (perpendicular to the radius)."""
    sim = make_box(f"""
        create_particle 1 single 1.5 0 0 diameter 1 density 1
        {MATERIAL}
        fix 1 all test/nve_sphere rotate no
        fix 2 all test/wall_gravity 10 0 0
        fix w all wall/gran model hooke tangential history primitive type 2 zcylinder 2.0 0 0 shear x 0.5
        timestep {hooke_time() / 50}
    """, box="-6 6 -6 6 -6 6", particle_style="sphere", ntypes=2, boundary="f f f")
    sim.command(f"run {int(0.4 / (hooke_time() / 50))}")
    assert np.linalg.norm(sim.v[0]) == pytest.approx(0.5 * 2.0, rel=0.01)
    assert sim.v[0] @ sim.x[0] == pytest.approx(0.0, abs=0.01)
    assert sim.v[0, 1] > 0.9          # counter-clockwise about +z


@pytest.mark.parametrize("words, message", [
    ("model hertz primitive type 2 zplane 0", "missing keyword tangential"),
    ("model jkr tangential history primitive type 2 zplane 0", "model must be one of 'hertz', 'hertz/stiffness', 'hooke', 'hooke/hysteresis' or 'hooke/stiffness' (got jkr)"),
    ("model hertz tangential history", "expected primitive or mesh (got neither); usage: "),
    ("model hertz tangential history primitive type 3 zplane 0",
     "type must be from 1 to 2, the number of types (got 3)"),
    ("model hertz tangential history primitive type 2 wplane 0", "primitive must be one of xplane, yplane, zplane, xcylinder, ycylinder, zcylinder (got wplane)"),
    ("model hertz tangential history primitive type 2 zcylinder 1 0", "primitive zcylinder takes 3 value(s): number number number (got 1 0)"),
    ("model hertz tangential history primitive type 2 zcylinder -1 0 0", "zcylinder radius must be > 0 (got -1)"),
    ("model hertz tangential history primitive type 2 zplane 0 shear z 1",
     "shear z would move a zplane wall along its own normal"),
    ("model hertz tangential history primitive type 2 zplane 0 shear q 1", "shear must be one of 'x', 'y' or 'z' (got q)"),
    ("model hertz tangential history primitive type 2 zplane 0 wiggle", "unknown keyword wiggle"),
    ("model hertz tangential history mesh n_meshes 1 meshes nothere", "fix nothere is not defined"),
    ("model hertz tangential history mesh n_meshes 2 meshes m1", "meshes needs 2 mesh ID(s) (got m1)"),
    ("model hertz tangential history mesh n_meshes 1 meshes m1", "fix m1 (property/global) is not a fix mesh/surface"),
    ("model hertz tangential history mesh n_meshes 0 meshes", "n_meshes must be > 0 (got 0)"),
    ("model hertz tangential history primitive type 2 zplane 0 store_force maybe", "store_force must be yes or no"),
    ("model hertz tangential history primitive type 2 zplane 0 mesh n_meshes 1 meshes m1",
     "expected primitive or mesh (got both)"),
])
def test_bad_words(words, message):
    sim = make_box(MATERIAL, box="-4 4 -4 4 -4 4", particle_style="sphere", ntypes=2, boundary="f f f")
    with pytest.raises(ScriptError) as info:
        sim.command("fix w all wall/gran " + words)
    assert message in str(info.value)
    assert "\n" not in str(info.value)


def test_the_keywords_stand_in_any_order():
    """LIGGGHTS writes the model keywords first; any order, and 2.x's settings after the geometry,
    give the same wall."""
    sim = make_box(MATERIAL, box="-4 4 -4 4 -4 4", particle_style="sphere", ntypes=2, boundary="f f f")
    sim.command("fix a all wall/gran model hooke tangential no_history limitForce on primitive type 2 zplane 0.5 "
                "store_force yes")
    sim.command("fix b all wall/gran primitive type 2 zplane 0.5 limitForce on store_force yes tangential no_history "
                "model hooke")
    a, b = sim.fixes["a"], sim.fixes["b"]
    assert a.args == b.args
    assert (a.args.model, a.args.tangential, a.args.limitForce) == ("hooke", "no_history", "on")
    assert [m.name for m in a.contact_model.sub_models] == ["default", "hooke", "no_history"]
    assert (a.wall_type, a.wallstyle, a.position) == (b.wall_type, b.wallstyle, b.position) == (2, 2, 0.5)
    assert a.store == "force_a" and b.store == "force_b"


def test_a_missing_material_is_named_at_the_run():
    sim = make_box("create_particle 1 single 0 0 0 diameter 1 density 1\n"
                   "fix w all wall/gran model hertz tangential history primitive type 1 zplane -3",
                   box="-4 4 -4 4 -4 4", particle_style="sphere", boundary="f f f")
    with pytest.raises(ScriptError, match="fix w \\(wall/gran\\) needs youngsModulus"):
        sim.command("run 0")


# ---- rolling friction and cohesion through the wall ---------------------------------------------
def one_type_material(extra):
    return liggghts_material(1.0e6, 0.3, 0.5, 0.8, characteristicVelocity=1.0) + extra


@pytest.mark.parametrize("rolling, lever", [("cdt", "arm"), ("epsd2", "radius")])
def test_a_sphere_rolling_on_a_plane_stops_where_its_rolling_torque_puts_it(rolling, lever):
    """A sphere rolling without slip at v0 = 0.5 on zplane with mu_r = 0.05 and gravity 10: the
    wall's rolling torque M (cdt: mu_r k_n delta (R - delta/2); epsd2: capped at mu_r |F_n| R, with
    k_n delta = m g at rest) decelerates it at M a_c / (I + m a_c^2), a_c = R - delta/2 the lever
    of the contact point (I = 2/5 m R^2): it stops after v0^2 / 2|a| within 2 %."""
    g, v0, mu_r, r = 10.0, 0.5, 0.05, 0.5
    sim = make_box(one_type_material(
        "fix m6 all property/global coefficientRollingFriction peratomtypepair 1 0.05") + f"""
        create_particle 1 single 0 0 0.5 diameter 1 density 1
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-g}
        fix w all wall/gran model hooke tangential history rolling_friction {rolling} primitive type 1 zplane 0.0
        timestep 0.0004
    """, box="-6 6 -6 6 -6 6", particle_style="sphere", boundary="f f f")
    sim.command("run 2500")                       # settle at rest on the plane (spring and overlap)
    delta = 0.5 - sim.x[0, 2]
    arm = r - 0.5 * delta
    sim.particles.v[0] = [v0, 0.0, 0.0]
    sim.particles.omega[0] = [0.0, v0 / arm, 0.0]
    start = sim.x[0, 0]
    sim.command("fix r all test/record\nrun 4500")
    x, v = sim.fixes["r"].series("x")[:, 0], sim.fixes["r"].series("v")[:, 0]
    stop = np.flatnonzero(v <= 0.0)[0]
    torque = mu_r * MASS * g * (arm if lever == "arm" else r)
    expected = v0 ** 2 / (2 * torque * arm / (0.4 * MASS * r * r + MASS * arm * arm))
    assert x[stop] - start == pytest.approx(expected, rel=0.02)


@pytest.mark.parametrize("cohesion, area", [
    ("sjkr", lambda d: math.pi * (0.25 - (0.5 - d) ** 2)),
    ("sjkr2", lambda d: 2 * math.pi * 0.5 * d),
])
def test_a_cohesive_sphere_rests_where_spring_cohesion_and_weight_balance(cohesion, area):
    """With cohesionEnergyDensity k the wall also pulls k A(delta): a sphere settled on zplane (hooke,
    so k_n delta is linear) rests where k_n delta - k A(delta) = m g, to 1e-6 of its weight; the
    overlap is larger than without cohesion."""
    k, g = 2000.0, 10.0
    sim = make_box(one_type_material(
        f"fix m6 all property/global cohesionEnergyDensity peratomtypepair 1 {k}") + f"""
        create_particle 1 single 0 0 0.5 diameter 1 density 1
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-g}
        fix 3 all viscous 1.0
        fix w all wall/gran model hooke tangential history cohesion {cohesion} primitive type 1 zplane 0.0
        timestep 0.0002
    """, box="-6 6 -6 6 -6 6", particle_style="sphere", boundary="f f f")
    sim.command("run 20000")
    delta = 0.5 - sim.x[0, 2]
    y_star = 1.0 / (2 * (1 - 0.3 ** 2) / 1.0e6)
    kn = 16 / 15 * math.sqrt(0.5) * y_star * (15 * MASS / (16 * math.sqrt(0.5) * y_star)) ** 0.2
    assert kn * delta - k * area(delta) == pytest.approx(MASS * g, rel=1e-6)
    assert kn * delta > MASS * g * 1.1


def test_store_force_keeps_each_particles_wall_force(data, tmp_path, liggghts_granular):
    """store_force yes: a sphere resting on the mesh floor and one resting on a zplane of another
    wall fix (and one in the air) carry their wall's force m g up in force_ID, which dump custom
    reads as LIGGGHTS's f_force_ID[k] (k from 1: [3] the z component) in the LIGGGHTS dialect; the wall
    fix without it has none."""
    sim = liggghts_granular(f"""
        region box block -4 4 -4 4 -4 4 units box
        create_box 2 box
        create_atoms 1 single 0.3 -0.2 0.499 units box
        create_atoms 1 single 3.0 3.0 -1.501 units box
        create_atoms 1 single 3.0 -3.0 2.0 units box
        set type 1 diameter 1 density 1
        {MATERIAL}
        fix cad all mesh/surface file {data}/square.stl type 2
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-10.0}
        fix w all wall/gran model hooke tangential history mesh n_meshes 1 meshes cad store_force yes
        fix low all wall/gran model hooke tangential history primitive type 2 zplane -2.0 store_force yes
        fix plain all wall/gran model hooke tangential history primitive type 2 zplane -3.9
        timestep {hooke_time() / 50}
        dump d all custom 100 {tmp_path}/forces.txt id f_force_w[3] f_force_low[3]
    """)
    sim.command("run 3000")
    mesh_force = sim.fixes["w"].peratom(sim)[np.argsort(sim.tag)]
    plane_force = sim.fixes["low"].peratom(sim)[np.argsort(sim.tag)]
    np.testing.assert_allclose(mesh_force[0], [0, 0, MASS * 10.0], rtol=1e-6, atol=1e-9)
    np.testing.assert_allclose(plane_force[1], [0, 0, MASS * 10.0], rtol=1e-6, atol=1e-9)
    np.testing.assert_array_equal(mesh_force[1:], 0.0)
    np.testing.assert_array_equal(plane_force[[0, 2]], 0.0)
    last = (tmp_path / "forces.txt").read_text().splitlines()[-3:]
    rows = sorted([float(w) for w in line.split()] for line in last)
    assert rows[0][1] == pytest.approx(MASS * 10.0, rel=1e-6) and rows[1][2] == pytest.approx(MASS * 10.0, rel=1e-6)
    with pytest.raises(ScriptError, match="has per-atom values only with store_force yes"):
        sim.fixes["plain"].peratom(sim)
