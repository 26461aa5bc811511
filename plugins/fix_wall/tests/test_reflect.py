"""fix wall/reflect: each style's position, velocity and force after a crossing, in exact numbers.

One particle of mass 1 under the constant force g = (0.5, -1, 2), time step 0.25, starts at
x0 = (1, 5, 5) with v0 = (-4.0625, 2.125, 0.75): the half-kick gives v = (-4, 2, 1) and the drift
x1 = (0, 5.5, 5.25), beyond the wall xlo 0.25 (every number is exact in binary). A probe fix defined
after the wall records x, v, f in post_integrate, right after the wall acted; the force there is the
previous step's, m g.
"""

import weakref

import numpy as np
import pytest

from pdps_core.api import Fix, ScriptError, Simulation
from pdps_core.testing import make_box, register_styles

# what the test styles record, per simulation (a Simulation takes no attributes of its own)
NOTES = weakref.WeakKeyDictionary()


def notes(sim):
    return NOTES.setdefault(sim, {})


class Probe(Fix):
    name = "test/wall_reflect_probe"

    def post_integrate(self, sim):
        notes(sim).setdefault("probe", []).append(
            tuple(sim.particles.arrays[k][0].copy() for k in ("x", "v", "f")))


register_styles(Probe)


def crossing(wall, x0=(1, 5, 5), v0=(-4.0625, 2.125, 0.75), box="-2 10 0 10 0 10"):
    sim = make_box(f"""
        mass 1 1
        create_particle 1 single {x0[0]} {x0[1]} {x0[2]}
        velocity all set {v0[0]} {v0[1]} {v0[2]}
        timestep 0.25
        fix 1 all test/nve_sphere rotate no
        fix 2 all test/wall_gravity 0.5 -1 2
        fix 3 all {wall}
        fix 4 all test/wall_reflect_probe
        run 1
    """, box=box, boundary="f f f")
    (x, v, f), = notes(sim)["probe"]
    return sim, x, v, f


G = np.array([0.5, -1.0, 2.0])


def test_specular_mirrors_the_position_and_reverses_normal_velocity_and_force():
    sim, x, v, f = crossing("wall/reflect specular xlo 0.25")
    np.testing.assert_array_equal(x, [0.5, 5.5, 5.25])
    np.testing.assert_array_equal(v, [4.0, 2.0, 1.0])
    np.testing.assert_array_equal(f, [-0.5, -1.0, 2.0])
    # the loop then recomputes the force (m g) and the second half-kick uses it
    np.testing.assert_array_equal(sim.v[0], np.array([4.0, 2.0, 1.0]) + 0.125 * G)
    np.testing.assert_array_equal(sim.x[0], [0.5, 5.5, 5.25])


def test_bounce_forward_mirrors_the_position_and_reverses_every_component():
    sim, x, v, f = crossing("wall/reflect bounce_forward xlo 0.25")
    np.testing.assert_array_equal(x, [0.5, 5.5, 5.25])
    np.testing.assert_array_equal(v, [4.0, -2.0, -1.0])
    np.testing.assert_array_equal(f, [-0.5, 1.0, -2.0])
    np.testing.assert_array_equal(sim.v[0], np.array([4.0, -2.0, -1.0]) + 0.125 * G)


def test_bounce_back_retraces_the_path_past_the_crossing_point():
    """The path (1, 5, 5) -> (0, 5.5, 5.25) crosses x = 0.25 at c = (0.25, 5.375, 5.1875); the
    particle goes back to 2c - x1 = (0.5, 5.25, 5.125), on its own path, and every velocity and
    force component is reversed."""
    sim, x, v, f = crossing("wall/reflect bounce_back xlo 0.25")
    np.testing.assert_array_equal(x, [0.5, 5.25, 5.125])
    np.testing.assert_array_equal(v, [4.0, -2.0, -1.0])
    np.testing.assert_array_equal(f, [-0.5, 1.0, -2.0])
    # on the path, and heading back the way it came
    x0, x1 = np.array([1.0, 5.0, 5.0]), np.array([0.0, 5.5, 5.25])
    np.testing.assert_array_equal(np.cross(x - x1, x0 - x1), 0.0)
    np.testing.assert_array_equal(v, -(x1 - x0) / 0.25)


def test_bounce_back_from_a_high_wall_and_the_particle_keeps_bouncing_inside():
    """Bounce back from zhi: the mirror rule in z, the path rule in x and y; over many steps the
    particle stays between the walls and its speed is kept."""
    sim, x, v, f = crossing("wall/reflect bounce_back zhi 5.25 zlo 4", x0=(1, 5, 5),
                            v0=(1.9375, 2.125, 3.75))
    # half-kick: v = (2, 2, 4); drift: x1 = (1.5, 5.5, 6) beyond zhi 5.25 -> z* = 4.5; going back
    # along the path to z = 4.5 is 1.5 times the step: x1 + 1.5 (x0 - x1)
    np.testing.assert_array_equal(x, [0.75, 4.75, 4.5])
    np.testing.assert_array_equal(v, [-2.0, -2.0, -4.0])
    np.testing.assert_array_equal(f, [-0.5, 1.0, -2.0])
    sim.command("unfix 2\nrun 200")
    assert 4.0 <= sim.x[0, 2] <= 5.25
    assert np.linalg.norm(sim.v[0]) == pytest.approx(np.linalg.norm([-2.0, -2.0, -4.0] + 0.125 * G))


def test_lammps_form_is_specular_at_the_box_edge_and_leaves_forces_alone():
    sim, x, v, f = crossing("wall/reflect xhi EDGE", x0=(9.5, 5, 5), v0=(3.9375, 2.125, 0.75))
    # v = (4, 2, 1), x1 = (10.5, 5.5, 5.25) beyond the box face 10 -> 9.5
    np.testing.assert_array_equal(x, [9.5, 5.5, 5.25])
    np.testing.assert_array_equal(v, [-4.0, 2.0, 1.0])
    np.testing.assert_array_equal(f, G)


@pytest.mark.parametrize("units, wall", [("", 0.5), ("units lattice", 0.5), ("units box", 0.25)])
def test_lammps_form_coordinates_are_in_lattice_units(units, wall):
    """LAMMPS's default units lattice: with lattice spacing 2 the wall xlo 0.25 is at x = 0.5."""
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        lattice spacing x 2 y 2 z 2
        region box block -2 10 0 10 0 10
        create_box 1 box
        fix 3 all wall/reflect xlo 0.25 {units}
    """)
    assert sim.fixes["3"].coords.tolist() == [wall]


def test_pdps_form_ignores_the_lattice():
    sim = Simulation(screen=False, log=None)
    sim.command("lattice spacing x 2 y 2 z 2\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\n"
                "fix 3 all wall/reflect specular xlo 0.25 xhi EDGE")
    assert sim.fixes["3"].coords.tolist() == [0.25, 10.0]


def test_only_the_group_is_reflected():
    sim = make_box("""
        mass * 1
        create_particle 1 single 1 5 5
        create_particle 2 single 1 6 5
        group one type 1
        velocity all set -4 0 0
        timestep 0.25
        fix 1 all test/nve_sphere rotate no
        fix 3 one wall/reflect specular xlo 0.25
        run 1
    """, box="-5 10 0 10 0 10", boundary="f f f", ntypes=2)
    order = np.argsort(sim.tag)
    np.testing.assert_array_equal(sim.x[order, 0], [0.5, 0.0])
    np.testing.assert_array_equal(sim.v[order, 0], [4.0, -4.0])


@pytest.mark.parametrize("words, message", [
    ("sideways xlo 0", "unknown keyword sideways (known: xlo, xhi, ylo, yhi, zlo, zhi, units)"),
    ("specular", "missing argument wall"),
    ("specular xlo", "wall xlo needs number|v_NAME|EDGE (got nothing)"),
    ("specular xlo 1 xlo 2", "wall xlo is given twice"),
    ("specular xlo abc", "wall xlo must be number | v_NAME or EDGE (got abc)"),
    ("specular xlo 5 xhi 3", "xlo must be below xhi (got 5 3)"),
    ("bounce_back xlo 1 units box", "unknown keyword units"),
    ("xlo 1 units metres", "units must be one of 'box' or 'lattice' (got metres)"),
])
def test_bad_arguments(words, message):
    sim = make_box()
    with pytest.raises(ScriptError) as info:
        sim.command(f"fix 3 all wall/reflect {words}")
    assert message in str(info.value)
    assert "\n" not in str(info.value)


def test_z_wall_in_two_dimensions_is_an_error():
    sim = make_box(box="0 10 0 10 -0.5 0.5", dimension=2)
    with pytest.raises(ScriptError, match="wall zlo in a 2-d simulation"):
        sim.command("fix 3 all wall/reflect specular zlo 0")


def test_a_variable_wall_is_lammps_s_form_and_must_be_defined():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("boundary p p f\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\nmass 1 1\n"
                "create_atoms 1 single 1 1 1\nfix 1 all nve")
    with pytest.raises(ScriptError) as bad_form:
        sim.command("fix w all wall/reflect specular zhi v_top")
    assert bad_form.value.message.endswith(
        "a wall at v_top with style specular: variable walls are LAMMPS's form, without a style word")
    sim.command("fix w all wall/reflect zhi v_top")
    with pytest.raises(ScriptError) as undefined:
        sim.command("run 1")
    assert undefined.value.message == "fix w wall/reflect: variable top is not defined"
