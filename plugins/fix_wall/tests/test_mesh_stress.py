"""fix mesh/surface/stress: the force a settled bed exerts on the floor is its weight; the torque of a
resting sphere about the reference point is r x (-m g); per-face pressure times area adds up to the
normal force; the vector reads from thermo in each dialect's index base.

Units lj; spheres of diameter 1, density 1 (m = pi/6); data/square.stl is [-1, 1]^2 at z = 0.
"""

import math

import meshio
import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import liggghts_material, make_box

MASS = math.pi / 6.0
KN, E, G = 1.0e4, 0.5, 10.0


PDPS_BED = f"""
    pair_style dem/lsd 0.5 1.0
    pair_coeff * * {KN} 20 {2 / 7 * KN} 10 0.5
    fix floor all mesh/surface/stress file {{data}}/square.stl scale 8 move 3 3 -0.6
    fix w all wall/mesh mesh floor model lsd {E} {KN} 0.5
"""
LIGGGHTS_BED = "\n" + liggghts_material(2.0e5, 0.3, 0.5, 0.5) + """\
    pair_style gran model hertz tangential history
    pair_coeff * *
    fix floor all mesh/surface/stress file {data}/square.stl type 1 scale 8 move 3 3 -0.6
    fix w all wall/gran model hertz tangential history mesh n_meshes 1 meshes floor
"""


@pytest.mark.parametrize("walls", [PDPS_BED, LIGGGHTS_BED], ids=["wall/mesh", "wall/gran-model"])
def test_the_floor_carries_the_weight_of_a_settled_bed(data, walls):
    """216 spheres poured in a box periodic in x and y onto a floor mesh wider than the box, settled
    with viscous damping and friction (PDPS's dem/lsd with wall/mesh, or LIGGGHTS's pair gran and
    wall/gran model hertz): the force on the floor (f_floor[2], PDPS index base) is N m g within
    0.5 %, pointing down, with no net sideways force; the per-face pressure times the face area
    sums to it."""
    sim = make_box(f"""
        neighbor 0.2 bin
        lattice sc 1.02
        region fill block 0 6 0 6 0 6 units lattice
        create_particle 1 region fill diameter 1 density 1
        {walls.format(data=data)}
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-G}
        fix 3 all viscous 2.0
        timestep 0.002
    """, box="0 6.12 0 6.12 -1 12", boundary="p p f", particle_style="sphere")
    n = sim.nlocal
    assert n == 216
    sim.command("run 3000")
    fz = []
    for _ in range(20):
        sim.command("run 10")
        fz.append(sim.fix_value("floor", (2,)))
    weight = n * MASS * G
    assert np.mean(fz) == pytest.approx(-weight, rel=0.005)
    force = sim.fixes["floor"].vector(sim)
    assert abs(force[0]) < 1e-3 * weight and abs(force[1]) < 1e-3 * weight
    faces = sim.fixes["floor"].face_data(sim)
    area = sim.fixes["floor"].face_areas()
    assert np.sum(faces["pressure"] * area) == pytest.approx(abs(force[2]), rel=1e-9)


def test_torque_of_a_resting_sphere_about_the_reference_point(data):
    """One sphere resting at (a, b) on the floor: force (0, 0, -m g) at the contact point (a, b, 0),
    torque (p - r0) x F about r0 = (1, -2, 3)."""
    a, b = 0.3, -0.4
    r0 = np.array([1.0, -2.0, 3.0])
    sim = make_box(f"""
        fix floor all mesh/surface/stress file {data}/square.stl scale 2 reference_point 1 -2 3
        create_particle 1 single {a} {b} {0.5 - MASS * G / KN} diameter 1 density 1
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-G}
        fix w all wall/mesh mesh floor model lsd {E} {KN} 0.5
        timestep 0.001
    """, box="-4 4 -4 4 -4 4", particle_style="sphere")
    sim.command("run 50")
    force = np.array([0.0, 0.0, -MASS * G])
    expected = np.concatenate([force, np.cross(np.array([a, b, 0.0]) - r0, force)])
    np.testing.assert_allclose(sim.fixes["floor"].vector(sim), expected, atol=1e-9)
    sim.command("thermo_style custom step f_floor[2]")      # PDPS: 0-based, [2] is z
    assert sim.fix_value("floor", (2,)) == pytest.approx(-MASS * G, abs=1e-9)


def test_stress_off_sums_nothing(data):
    sim = make_box(f"""
        fix floor all mesh/surface/stress file {data}/square.stl scale 2 stress off
        create_particle 1 single 0 0 0.49 diameter 1 density 1
        fix w all wall/mesh mesh floor model lsd {E} {KN} 0.5
    """, box="-4 4 -4 4 -4 4", particle_style="sphere")
    sim.command("run 2")
    assert not np.any(sim.fixes["floor"].vector(sim))


@pytest.mark.parametrize("words, message", [
    ("stress maybe", "stress must be one of 'on' or 'off' (got maybe)"),
    ("wear archard", "wear must be one of 'finnie' or 'off' (got archard)"),
    ("reference_point 0 0", "keyword reference_point needs 3 value(s) (got 2)"),
])
def test_bad_stress_words(data, words, message):
    sim = make_box(box="-4 4 -4 4 -4 4", particle_style="sphere")
    with pytest.raises(ScriptError) as info:
        sim.command(f"fix floor all mesh/surface/stress file {data}/square.stl {words}")
    assert message in str(info.value)


def test_dump_vtk_writes_the_force_pressure_and_shear_of_each_face(data, tmp_path):
    """dump vtk ... walls yes writes the stress mesh every frame, with the cell data force, pressure
    and shear: for a sphere resting on the square (two triangles of area 2) the faces' forces sum to
    (0, 0, -m g), pressure x area to m g, and there is no shear."""
    sim = make_box(f"""
        fix floor all mesh/surface/stress file {data}/square.stl
        create_particle 1 single 0.4 -0.3 {0.5 - MASS * G / KN} diameter 1 density 1
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-G}
        fix w all wall/mesh mesh floor model lsd {E} {KN} 0.5
        timestep 0.001
        dump d all vtk 10 {tmp_path}/p_*.vtu walls yes
    """, box="-4 4 -4 4 -4 4", particle_style="sphere")
    sim.command("run 20")
    for step in (0, 10, 20):
        mesh = meshio.read(tmp_path / f"p_wall_floor_{step}.vtu")
        force = mesh.cell_data["force"][0]
        pressure, shear = mesh.cell_data["pressure"][0], mesh.cell_data["shear"][0]
        np.testing.assert_allclose(force.sum(axis=0), [0, 0, -MASS * G], atol=1e-9)
        assert np.sum(pressure * 2.0) == pytest.approx(MASS * G, rel=1e-9)
        np.testing.assert_allclose(shear, 0.0, atol=1e-9)
    assert (tmp_path / "p_wall_floor.vtu.series").exists()


@pytest.mark.parametrize("style", ["mesh/vtk", "mesh/gran/VTK"])
def test_dump_mesh_vtk_writes_the_meshes_with_liggghts_values(data, tmp_path, style):
    """LIGGGHTS's dump mesh/vtk: both meshes in one legacy VTK file per frame, per triangle the
    stress |F|/A (0 on the plain mesh/surface lid), the stress components F/A, the id, the area and
    the wall velocity (the moving mesh's linear velocity; 0 on the still one)."""
    sim = make_box(f"""
        fix floor all mesh/surface/stress file {data}/square.stl
        fix lid all mesh/surface file {data}/square.stl move 0 0 3
        fix up all move/mesh mesh lid linear 0 0 0.5
        create_particle 1 single 0.4 -0.3 {0.5 - MASS * G / KN} diameter 1 density 1
        fix 1 all test/nve_sphere
        fix 2 all test/wall_gravity 0 0 {-G}
        fix w all wall/mesh mesh floor model lsd {E} {KN} 0.5
        timestep 0.001
        dump d all {style} 10 {tmp_path}/mesh*.vtk stress stresscomponents id area vel floor lid
    """, box="-4 4 -4 4 -4 4", particle_style="sphere")
    sim.command("run 20")
    mesh = meshio.read(tmp_path / "mesh20.vtk")
    assert len(mesh.cells_dict["triangle"]) == 4
    stress = mesh.cell_data["stress"][0]
    components = mesh.cell_data["stress_components"][0]
    area = mesh.cell_data["area"][0]
    np.testing.assert_allclose(area, 2.0)
    np.testing.assert_array_equal(mesh.cell_data["id"][0], [0, 1, 0, 1])
    assert np.sum(stress * area) == pytest.approx(MASS * G, rel=1e-9)
    np.testing.assert_array_equal(stress[2:], 0.0)            # the lid sums no forces
    np.testing.assert_allclose(np.sum(components * area[:, None], axis=0), [0, 0, -MASS * G], atol=1e-9)
    np.testing.assert_allclose(mesh.cell_data["vel"][0], [[0, 0, 0]] * 2 + [[0, 0, 0.5]] * 2, atol=1e-12)
    np.testing.assert_allclose(mesh.points[4:, 2], 3.0 + 0.5 * 20 * 0.001, atol=1e-12)


@pytest.mark.parametrize("words, message", [
    ("stress cad", "stress needs a fix mesh/surface/stress (fix cad is a mesh/surface)"),
    ("wear", "wear needs a fix mesh/surface/stress (fix cad is a mesh/surface)"),
    ("output interpolate", "output must be one of 'face' (got interpolate)"),
    ("stress nothere", "nothere is neither a value"),
    ("cad stress", "stress stands after a mesh ID: output face, then the values, then the mesh IDs"),
])
def test_bad_dump_mesh_vtk(data, tmp_path, words, message):
    sim = make_box(f"fix cad all mesh/surface file {data}/square.stl", box="-4 4 -4 4 -4 4",
                   particle_style="sphere")
    with pytest.raises(ScriptError) as info:
        sim.command(f"dump d all mesh/vtk 10 {tmp_path}/m*.vtk {words}")
        sim.command("run 0")
    assert message in str(info.value)


def test_dump_mesh_stl_writes_where_the_meshes_are(data, tmp_path):
    """LIGGGHTS's dump mesh/stl: one ASCII STL file per frame with the triangles of the meshes named
    (all when none is), at their vertices of that step (the lid moving up at 0.5), each facet's unit
    normal right-handed over its vertices; ``region`` keeps the triangles whose centre it holds."""
    sim = make_box(f"""
        fix floor all mesh/surface file {data}/square.stl
        fix lid all mesh/surface file {data}/square.stl move 0 0 3
        fix up all move/mesh mesh lid linear 0 0 0.5
        create_particle 1 single 0.4 -0.3 2 diameter 1 density 1
        fix 1 all test/nve_sphere
        timestep 0.001
        region high block INF INF INF INF 2.5 INF
        dump a all mesh/stl 10 {tmp_path}/all*.stl
        dump b all mesh/stl 10 {tmp_path}/lid*.stl local lid
        dump c all mesh/stl 10 {tmp_path}/high*.stl region high
    """, box="-4 4 -4 4 -4 4", particle_style="sphere")
    sim.command("run 20")
    square = meshio.read(f"{data}/square.stl")
    for step in (0, 10, 20):
        text = (tmp_path / f"all{step}.stl").read_text()
        assert text.startswith("solid ") and text.rstrip().endswith("endsolid LIGGGHTS_STL_EXPORT")
        facets = [[float(w) for w in line.split()[2:]] for line in text.splitlines() if "facet normal" in line]
        vertices = np.array([[float(w) for w in line.split()[1:]] for line in text.splitlines()
                             if line.split()[:1] == ["vertex"]]).reshape(-1, 3, 3)
        expected = square.points[square.cells_dict["triangle"]]
        lifted = expected + [0.0, 0.0, 3.0 + 0.5 * step * 0.001]
        np.testing.assert_allclose(vertices, np.concatenate([expected, lifted]), atol=1e-9)
        normals = np.cross(vertices[:, 1] - vertices[:, 0], vertices[:, 2] - vertices[:, 0])
        np.testing.assert_allclose(facets, normals / np.linalg.norm(normals, axis=1)[:, None], atol=1e-9)
        lid = (tmp_path / f"lid{step}.stl").read_text()
        high = (tmp_path / f"high{step}.stl").read_text()
        assert lid == high and lid.count("facet normal") == 2
        assert f"{3.0 + 0.5 * step * 0.001:.9e}" in lid


@pytest.mark.parametrize("words, message", [
    ("ghost", "ghost: every rank holds whole meshes, there are no ghost triangles to write"),
    ("nothere", "nothere is not the ID of a fix mesh/surface"),
    ("region nothere", "region nothere"),
])
def test_bad_dump_mesh_stl(data, tmp_path, words, message):
    sim = make_box(f"fix cad all mesh/surface file {data}/square.stl", box="-4 4 -4 4 -4 4",
                   particle_style="sphere")
    with pytest.raises(ScriptError) as info:
        sim.command(f"dump d all mesh/stl 10 {tmp_path}/m*.stl {words}")
    assert message in str(info.value)
    with pytest.raises(ScriptError, match="per-processor files"):
        sim.command(f"dump e all mesh/stl 10 {tmp_path}/m%*.stl")


@pytest.mark.parametrize("velocity", [(1.0, 0.0, -0.2), (1.0, 0.0, -1.0), (0.0, 0.3, -0.5)],
                         ids=["grazing", "45-degrees", "steep"])
def test_finnie_wear_of_a_sphere_driven_into_the_floor(data, velocity):
    """A sphere held at a fixed overlap with a fixed velocity towards the floor (the force on the
    face constant) wears its triangle by 2 k |v| |F| f(gamma) dt / A a step, Finnie's f: sin 2g -
    3 sin^2 g for tan g <= 1/3, cos^2 g / 3 above; the other triangle not at all, and the setup
    force computation not either. k_finnie of the type pair (particle 1, mesh 2) = 0.3."""
    v = np.array(velocity)
    sim = make_box(f"""
        fix m all property/global k_finnie peratomtypepair 2 0.1 0.3 0.3 0.2
        fix floor all mesh/surface/stress file {data}/square.stl type 2 wear finnie
        create_particle 1 single 0.4 -0.3 0.49 diameter 1 density 1
        velocity all set {v[0]} {v[1]} {v[2]}
        fix 1 all test/nve_sphere translate no rotate no
        fix w all wall/mesh mesh floor model lsd {E} {KN} 0
        timestep 0.001
        run 0
    """, box="-4 4 -4 4 -4 4", particle_style="sphere", ntypes=2)
    floor = sim.fixes["floor"]
    assert not np.any(floor.face_data(sim)["wear"])
    sim.command("run 25")
    speed = np.linalg.norm(v)
    sin_g = abs(v[2]) / speed
    cos_g = math.sqrt(1 - sin_g ** 2)
    shape = 2 * sin_g * cos_g - 3 * sin_g ** 2 if 3 * sin_g <= cos_g else cos_g ** 2 / 3
    force = np.linalg.norm(floor.face_data(sim)["force"][0])
    expected = 25 * 0.001 * 2 * 0.3 * speed * force * shape / 2.0
    wear = floor.face_data(sim)["wear"]
    assert wear[0] == pytest.approx(expected, rel=1e-12)
    assert wear[1] == 0.0 and expected > 0


def test_wear_needs_k_finnie(data):
    sim = make_box(f"""
        fix floor all mesh/surface/stress file {data}/square.stl wear finnie
    """, box="-4 4 -4 4 -4 4", particle_style="sphere")
    with pytest.raises(ScriptError, match="fix floor \\(wear finnie\\) needs k_finnie: fix ID all property/global "
                                          "k_finnie peratomtypepair 1 V11 ... V11"):
        sim.command("run 0")


def test_a_saved_wear_of_another_size_is_one_line(data):
    """A damaged restart file's wear (one value where the mesh has two triangles) is refused by name,
    not handed to the wear kernel."""
    sim = make_box(f"fix floor all mesh/surface/stress file {data}/square.stl wear finnie", box="-4 4 -4 4 -4 4",
                   particle_style="sphere")
    with pytest.raises(ScriptError, match=r"^fix floor \(mesh/surface/stress\): the saved wear holds 1 value\(s\) "
                                          r"for 2 triangles$"):
        sim.fixes["floor"].restore({"face_wear": np.array(True)})
