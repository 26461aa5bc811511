"""fix mesh/surface's reading checks and repairs (precision, heal, element_exclusion_list,
curvature_tolerant, min_feature_length), extrude_planar with fix MESH_ID, and a mesh's temperature
under fix heat/gran: each against its formula or LIGGGHTS 3.8.0's behaviour (measured on this
machine; the thermo of the scenes is in data/liggghts.cases.json: mesh_heal, mesh_exclusion_*,
mesh_tolerant, mesh_extrude, mesh_temperature, mesh_mass_temperature)."""

import io
import math
import struct

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import liggghts_material, make_box

SQUARE = ((-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0))


def stl(triangles, name="m"):
    """An ASCII STL of triangles given by their 3-d corners: facet k starts on line 2 + 7k."""
    text = f"solid {name}\n"
    for corners in triangles:
        text += "  facet normal 0 0 1\n    outer loop\n"
        text += "".join(f"      vertex {x!r} {y!r} {z!r}\n" for x, y, z in corners)
        text += "    endloop\n  endfacet\n"
    return text + f"endsolid {name}\n"


def flat(points, z=0.0):
    return [(x, y, z) for x, y in points]


def square_triangles(z=0.0):
    a, b, c, d = flat(SQUARE, z)
    return [(a, b, c), (a, c, d)]


def mesh_box(tmp_path, triangles, words="", name="m.stl", screen=False):
    path = tmp_path / name
    path.write_text(stl(triangles))
    return make_box(f"fix cad all mesh/surface file {path} type 1 {words}", box="-4 4 -4 4 -4 4",
                    particle_style="sphere", screen=screen)


def refusal(tmp_path, triangles, words=""):
    with pytest.raises(ScriptError) as info:
        mesh_box(tmp_path, triangles, words)
    assert "\n" not in str(info.value)
    return str(info.value)


def with_duplicate(shift=1e-9):
    """The square and its first triangle again, one node moved by ``shift`` in z (line 16)."""
    first = square_triangles()[0]
    moved = ((first[0][0], first[0][1], first[0][2] + shift), first[1], first[2])
    return square_triangles() + [moved]


# ---- duplicates, precision, heal --------------------------------------------------------------------
def test_a_duplicate_triangle_stops_as_in_liggghts(tmp_path):
    # LIGGGHTS: "elements 2 and 0 (lines 16 and 2) are duplicate ... try re-running with 'heal
    # auto_remove_duplicates'" for the same file
    message = refusal(tmp_path, with_duplicate())
    assert message.endswith(f"fix cad: mesh file {tmp_path}/m.stl: the triangles of lines 2 and 16 are duplicate "
                            "(nodes within precision 1e-08); heal auto_remove_duplicates leaves the later out")


def test_heal_leaves_the_later_duplicate_out(tmp_path):
    sim = mesh_box(tmp_path, with_duplicate(), "heal auto_remove_duplicates")
    mesh = sim.fixes["cad"]
    assert len(mesh.triangles) == 2
    np.testing.assert_array_equal(mesh.vertices[mesh.triangles].reshape(-1, 3), np.array(square_triangles()).reshape(-1, 3))


def test_precision_decides_what_is_a_duplicate(tmp_path):
    # nodes 1e-6 apart: two triangles at the default precision 1e-8, duplicates at 1e-5
    mesh_box(tmp_path, with_duplicate(1e-6))
    assert "are duplicate (nodes within precision 1e-05)" in refusal(tmp_path, with_duplicate(1e-6), "precision 1e-5")
    sim = mesh_box(tmp_path, with_duplicate(1e-6), "precision 1e-5 heal auto_remove_duplicates")
    assert len(sim.fixes["cad"].triangles) == 2


def test_duplicates_placed_within_precision_after_a_scale(tmp_path):
    # heal compares the file's nodes; scaled by 1e-3 the 1e-6 apart ones come within 1e-8
    assert "lower the precision" in refusal(tmp_path, with_duplicate(1e-6), "heal auto_remove_duplicates scale 1e-3")


# ---- element exclusion lists ------------------------------------------------------------------------
def test_the_written_list_names_the_earlier_duplicate_and_the_run_goes_on(tmp_path):
    listing = tmp_path / "written.txt"
    screen = io.StringIO()
    sim = mesh_box(tmp_path, with_duplicate(), f"element_exclusion_list write {listing}", screen=screen)
    # LIGGGHTS 3.8.0 wrote "2" twice for this file, and went on with the three triangles
    assert listing.read_text() == "2\n"
    assert len(sim.fixes["cad"].triangles) == 2
    assert "has 1 duplicate triangle(s), listed in" in screen.getvalue()


def test_a_read_list_leaves_its_lines_out(tmp_path):
    listing = tmp_path / "excluded.txt"
    listing.write_text("2\n\n  9\n")
    sim = mesh_box(tmp_path, with_duplicate(), f"element_exclusion_list read {listing}")
    mesh = sim.fixes["cad"]
    np.testing.assert_allclose(mesh.vertices[mesh.triangles], [with_duplicate()[2]])


def test_a_list_that_is_not_line_numbers(tmp_path):
    listing = tmp_path / "excluded.txt"
    listing.write_text("2\nsecond\n")
    assert refusal(tmp_path, with_duplicate(), f"element_exclusion_list read {listing}").endswith(
        f"element exclusion list {listing}, line 2: expected a line number (got 'second')")


def test_a_list_that_leaves_nothing(tmp_path):
    listing = tmp_path / "excluded.txt"
    listing.write_text("2\n9\n")
    assert "leaves no triangle" in refusal(tmp_path, square_triangles(), f"element_exclusion_list read {listing}")


def test_lines_of_a_binary_stl_and_a_vtk_file(tmp_path):
    from pdps_fix_wall.mesh_quality import element_lines
    binary = tmp_path / "b.stl"
    body = b"".join(struct.pack("<12fH", 0, 0, 1, *np.array(t).ravel(), 0) for t in square_triangles())
    binary.write_bytes(b"\0" * 80 + struct.pack("<I", 2) + body)
    np.testing.assert_array_equal(element_lines(str(binary), "b.stl", 2), [1, 2])
    vtk = tmp_path / "m.vtk"
    vtk.write_text("# vtk DataFile Version 2.0\nmesh\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
                   "-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n\nCELLS 2 8\n3 0 1 2\n\n3 0 2 3\nCELL_TYPES 2\n5\n5\n")
    # LIGGGHTS counts every line, the blank ones too
    assert element_lines(str(vtk), "m.vtk", 2).tolist() == [12, 14]
    obj = tmp_path / "m.obj"
    with pytest.raises(ScriptError, match="element_exclusion_list needs an STL or legacy ASCII VTK mesh file"):
        element_lines(str(obj), "m.obj", 2)


# ---- bad triangles ------------------------------------------------------------------------------------
def test_an_angle_at_the_hard_limit_stops_even_with_a_list(tmp_path):
    sliver = [((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 5e-4, 0.0))]     # 0.0286 degrees at the first node
    message = refusal(tmp_path, square_triangles(1.0) + sliver)
    assert "the triangle of line 16 has an angle of 0.0286 degrees (at most 0.0573: 1 such)" in message
    listing = tmp_path / "written.txt"
    refusal(tmp_path, square_triangles(1.0) + sliver, f"element_exclusion_list write {listing}")
    assert listing.read_text() == "16\n"


def test_more_than_five_neighbours_stop(tmp_path):
    # seven fins on one edge: each has six neighbours
    fins = [((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.5, math.cos(a), math.sin(a))) for a in np.linspace(0, 3, 7)]
    message = refusal(tmp_path, fins)
    assert "the triangle of line 2 has 6 neighbours (at most 5: 7 such)" in message


def test_curvature_against_the_smallest_angle(tmp_path):
    sliver = [((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (1.0, 0.03, 0.0))]     # 1.72 degrees
    mesh_box(tmp_path, sliver)                                        # LIGGGHTS's default 0.256 degrees
    message = refusal(tmp_path, sliver, "curvature 5")
    assert message.endswith("the triangle of line 2 has an angle of 1.72 degrees, smaller than the curvature 5 "
                            "(1 such); lower curvature or give curvature_tolerant yes")
    mesh_box(tmp_path, sliver, "curvature 1")
    screen = io.StringIO()
    mesh_box(tmp_path, sliver, "curvature 5 curvature_tolerant yes", screen=screen)
    assert "smaller than the curvature 5 (1 such)" in screen.getvalue()


# ---- extrusion --------------------------------------------------------------------------------------------
def test_extrusion_sweeps_the_boundary_edges(tmp_path):
    length = 0.25
    sim = mesh_box(tmp_path, square_triangles(1.0), f"extrude_planar {length}")
    sim.command("fix sides all mesh/surface fix cad type 1")
    sides = sim.fixes["sides"]
    corners = sides.vertices[sides.triangles]
    # four edges of the square (the diagonal is shared), two triangles each, down by the length
    assert corners.shape == (8, 3, 3)
    top = np.array(square_triangles(1.0))
    expected = []
    for triangle in top:
        for e in range(3):
            a, b = triangle[e], triangle[(e + 1) % 3]
            if abs(a[0] - b[0]) > 0 and abs(a[1] - b[1]) > 0:
                continue                                     # the diagonal
            v = np.array([0.0, 0.0, -length])
            expected += [(b, a, b + v), (a, a + v, b + v)]
    np.testing.assert_allclose(corners, np.array(expected), atol=1e-15)
    # each side wall stands upright, normal in the plane of the square
    np.testing.assert_allclose(sides.face_normal[:, 2], 0.0, atol=1e-15)


def test_extrusion_needs_a_planar_mesh_and_a_source(tmp_path):
    bent = square_triangles() + [((1.0, -1.0, 0.0), (2.0, -1.0, 1.0), (1.0, 1.0, 0.0))]
    assert "is not planar" in refusal(tmp_path, bent, "extrude_planar 0.1")
    sim = mesh_box(tmp_path, square_triangles())
    with pytest.raises(ScriptError, match=r"fix cad extrudes no walls \(give it extrude_planar L\)"):
        sim.command("fix sides all mesh/surface fix cad")


# ---- a wall with a temperature -------------------------------------------------------------------------
R, DELTA, RHO, KP, KW, TP, TW = 0.005, 2e-4, 2500.0, 5.0, 20.0, 300.0, 500.0


def hot_floor(tmp_path, area="", mesh_words=""):
    """One sphere (type 1) resting DELTA deep in a mesh floor of type 2 at temperature TW."""
    path = tmp_path / "floor.stl"
    path.write_text(stl([[(10 * R * x, 10 * R * y, 0.0) for x, y, _ in t] for t in square_triangles()]))
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(f"""
atom_style granular
boundary f f f
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 2 reg
{liggghts_material((5.e6, 5.e6), (0.45, 0.45), [0.5] * 4, [0.5] * 4, thermalConductivity=(KP, KW),
                   thermalCapacity=(10.0, 30.0))}
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-6
create_atoms 1 single 0 0 {R - DELTA!r} units box
set type 1 diameter {2 * R} density {RHO}
fix cad all mesh/surface file {path} type 2 temperature {TW} {mesh_words}
fix floor all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad
fix heat all heat/gran initial_temperature {TP} {area} store_contact_data yes
run 0
""")
    return sim


@pytest.mark.parametrize("area, spot", [
    ("", math.pi * (R ** 2 - (R - DELTA) ** 2)),
    ("contact_area projection", math.pi * R ** 2),
    ("contact_area constant 1e-6", 1e-6),
])
def test_a_hot_floor_heats_a_sphere_by_the_conduction_law(tmp_path, area, spot):
    sim = hot_floor(tmp_path, area)
    conductance = 4 * KP * KW / (KP + KW) * math.sqrt(spot)
    a = sim.particles.arrays
    assert a["heatFlux"][0] == pytest.approx(conductance * (TW - TP), rel=1e-12)
    assert a["wallHeattransferCoeff"][0] == pytest.approx(conductance, rel=1e-12)


def test_mass_temperature_is_read_and_warned_about(tmp_path):
    screen = io.StringIO()
    sim = mesh_box(tmp_path, square_triangles(), "temperature 400 mass_temperature 0.5", screen=screen)
    assert "mass_temperature has no effect, as in LIGGGHTS 3.8.0" in screen.getvalue()
    assert sim.fixes["cad"].temperature == 400.0


def test_a_hot_mesh_without_heat_gran_stops_the_run(tmp_path):
    path = tmp_path / "m.stl"
    path.write_text(stl(square_triangles()))
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(f"""
atom_style granular
boundary f f f
units si
region reg block -2 2 -2 2 -2 2 units box
create_box 1 reg
{liggghts_material((5.e6,), (0.45,), [0.5], [0.5])}
pair_style gran model hertz tangential history
pair_coeff * *
fix cad all mesh/surface file {path} type 1 temperature 400
fix floor all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad
""")
    with pytest.raises(ScriptError, match="mesh cad has a temperature, which needs a fix heat/gran"):
        sim.command("run 0")
