"""fix massflow/mesh: spheres moving at constant velocity through data/square.stl (the square
[-1, 1]^2 at z = 0, two triangles) are counted as they pass, once or each time, with their mass,
the rate between readings, a property summed and the counted deleted; bad input gets one line.
LIGGGHTS 3.8.0's numbers for a bed falling through a tilted face are in data/liggghts.cases.json
(massflow, massflow_delete, massflow_outlet), checked by tests/test_recorded_thermo.py."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError

MASS = 4.0 / 3.0 * math.pi * 0.05 ** 3          # diameter 0.1, density 1
DT = 0.01


def crossing(scene, data, flow, particles, steps, walls=""):
    """Spheres of diameter 0.1 at ``particles`` [(x, y, z, vz)], moving freely; the flow fix's vector
    after ``steps``."""
    sim = scene(skin=0.5)
    for x, y, z, vz in particles:
        sim.command(f"create_particle 1 single {x} {y} {z} diameter 0.1 density 1")
        sim.particles.v[sim.particles.nlocal - 1] = (0.0, 0.0, vz)
    sim.command(f"fix face all mesh/surface file {data}/square.stl type 1\n"
                f"fix 1 all test/nve_sphere rotate no\n{walls}\nfix flow all massflow/mesh mesh face {flow}\n"
                f"timestep {DT}\nrun {steps}")
    return sim, sim.fixes["flow"].vector(sim)


def test_spheres_through_the_face_are_counted_with_their_mass(scene, data):
    """Two pass inside the square, one beside it, one the other way, one never reaches it."""
    inside = [(-0.5, 0.3, 0.505, -1.0), (0.6, -0.7, 0.805, -1.0)]
    others = [(1.5, 0.0, 0.505, -1.0), (0.2, 0.2, -0.495, 1.0), (0.0, 0.5, 2.005, -1.0)]
    _, flow = crossing(scene, data, "vec_side 0 0 -1", inside + others, 100)
    assert flow[:2].tolist() == pytest.approx([2 * MASS, 2])
    # the rate since the last reading (none before: the whole run, 100 steps)
    assert flow[2:4].tolist() == pytest.approx([2 * MASS / (100 * DT), 2 / (100 * DT)])
    # and upwards, the one going up
    _, up = crossing(scene, data, "vec_side 0 0 1", inside + others, 100)
    assert up[:2].tolist() == pytest.approx([MASS, 1])


def test_count_multiple_counts_each_pass_and_once_the_first(scene, data):
    """Between reflecting walls at z = -0.5 and 0.5 a sphere at speed 1 passes down through z = 0
    every 2 time units: at t = 0.255, 2.255, ..., 8.255 in 10."""
    ball = [(0.1, 0.2, 0.255, -1.0)]
    walls = "fix box all wall/reflect zlo -0.5 zhi 0.5"
    _, many = crossing(scene, data, "vec_side 0 0 -1 count multiple", ball, 1000, walls)
    _, once = crossing(scene, data, "vec_side 0 0 -1 count once", ball, 1000, walls)
    assert (many[1], once[1]) == (5, 1)


def test_the_rate_is_over_the_time_since_the_vector_was_last_read(scene, data):
    sim, first = crossing(scene, data, "vec_side 0 0 -1", [(0.0, 0.0, 0.205, -1.0)], 10)
    assert first[:4].tolist() == [0.0, 0.0, 0.0, 0.0]
    sim.command("run 30")
    assert sim.fixes["flow"].vector(sim)[2] == pytest.approx(MASS / (30 * DT))
    # read again with no step since: the same rate (LIGGGHTS's), then over the steps since
    sim.command("run 0")
    assert sim.fixes["flow"].vector(sim)[2] == pytest.approx(MASS / (30 * DT))
    sim.command("run 5")
    assert sim.fixes["flow"].vector(sim)[2:4].tolist() == [0.0, 0.0]


def test_delete_atoms_removes_the_counted_and_sums_a_property(scene, data):
    sim = scene(skin=0.5)
    for k, z in enumerate((0.205, 0.405, 1.5)):
        sim.command(f"create_particle 1 single {0.2 * k} 0.1 {z} diameter 0.1 density 1")
    sim.particles.v[:3] = (0.0, 0.0, -1.0)
    sim.command(f"fix face all mesh/surface file {data}/square.stl type 1\nfix 1 all test/nve_sphere\n"
                "fix mark all property/atom mark scalar yes no no 2.5\n"
                "fix flow all massflow/mesh mesh face vec_side 0 0 -1 count once delete_atoms yes sum_property mark\n"
                f"timestep {DT}\nrun 60")
    flow = sim.fixes["flow"].vector(sim)
    assert flow.tolist() == pytest.approx([2 * MASS, 2, 2 * MASS / (60 * DT), 2 / (60 * DT), 2 * MASS, 2, 5.0])
    assert sorted(sim.particles.tag[:sim.particles.nlocal].tolist()) == [3]


def test_the_file_lists_each_sphere_counted(scene, data, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    crossing(scene, data, f"vec_side 0 0 -1 file {tmp_path}/flow.txt writeTime", [(0.25, -0.5, 0.105, -1.0)], 20)
    lines = (tmp_path / "flow.txt").read_text().splitlines()
    assert lines[0] == "# ID time  diameter x y z u v w  (ex ey ez, color)"
    # counted at step 11 (its centre at z = 0.105 - 0.11 < 0), the %4.4g columns of LIGGGHTS
    assert lines[1:] == ["1  0.11   0.1 0.25 -0.5 -0.005    0    0   -1"]


def test_point_at_outlet_counts_spheres_leaving_towards_the_point(scene, data):
    inside = [(-0.5, 0.3, 0.205, -1.0), (0.5, 0.5, -0.205, 1.0)]
    _, down = crossing(scene, data, "count once point_at_outlet 0 0 -5", inside, 60)
    _, up = crossing(scene, data, "count once point_at_outlet 0 0 5 inside_out", inside, 60)
    assert (down[1], up[1]) == (1, 1)


@pytest.mark.parametrize("words, message", [
    ("mesh face", "expected keyword vec_side (or point_at_outlet)"),
    ("mesh face vec_side 0 0 0", "vec_side must not be the zero vector"),
    ("mesh face vec_side 0 0 1 delete_atoms yes", "delete_atoms yes needs count once"),
    ("mesh face point_at_outlet 0 0 1", "point_at_outlet needs count once"),
    ("mesh face vec_side 0 0 1 inside_out", "inside_out has no meaning without point_at_outlet"),
    ("mesh other vec_side 0 0 1", "fix other is not defined (expected the ID of a fix mesh/surface)"),
    ("mesh face vec_side 1 0 0", "fix flow massflow/mesh: vec_side lies in (or too close to) the plane of mesh face"),
    ("mesh face vec_side 0 0 1 sum_property face", "sum_property face: no fix property/atom of that ID"),
    ("mesh face vec_side 0 0 1 file a.txt append b.txt", "file and append name the same output: give one"),
    ("vec_side 0 0 1", "missing keyword mesh"),
])
def test_bad_arguments(scene, data, words, message):
    sim = scene()
    sim.command(f"fix face all mesh/surface file {data}/square.stl type 1")
    with pytest.raises(ScriptError) as caught:
        sim.command(f"fix flow all massflow/mesh {words}")
    assert message in caught.value.message


def test_a_face_that_is_not_planar_needs_point_at_outlet(scene, data):
    sim = scene()
    sim.command(f"create_particle 1 single 0 0 2 diameter 0.1 density 1\n"
                f"fix funnel all mesh/surface file {data}/hopper.stl type 1\nfix 1 all test/nve_sphere\n"
                "fix flow all massflow/mesh mesh funnel vec_side 0 0 -1")
    with pytest.raises(ScriptError) as caught:
        sim.command("run 1")
    assert caught.value.message.startswith("fix flow massflow/mesh: mesh funnel is not planar (a node lies ")
    sim.command("unfix flow\nfix flow all massflow/mesh mesh funnel count once point_at_outlet 0 0 -3\nrun 1")
