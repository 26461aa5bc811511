"""Regions block (inside test with faces, INF, EDGE, bounds) and polygon (normal, planarity)."""

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import make_box


def sim_with_box(box="0 10 0 10 0 10"):
    return make_box("mass 1 1", box=box)


# ---- block --------------------------------------------------------------------------------------
def test_block_inside_outside_and_faces(make_sim):
    sim = make_sim()
    sim.command("region r block -1 2 0.5 3 -4 -2")
    r = sim.region("r")
    points = np.array([
        [0.0, 1.0, -3.0],            # interior
        [-1.0, 1.0, -3.0],           # on the xlo face
        [2.0, 3.0, -2.0],            # on an edge/corner of the hi faces
        [-1.0, 0.5, -4.0],           # the lo corner
        [2.0 + 1e-12, 1.0, -3.0],    # just beyond xhi
        [0.0, 0.5 - 1e-12, -3.0],    # just below ylo
        [0.0, 1.0, -1.9],            # beyond zhi
        [5.0, 5.0, 5.0],
    ])
    np.testing.assert_array_equal(r.inside(points),
                                  [True, True, True, True, False, False, False, False])
    lo, hi = r.bounds()
    np.testing.assert_array_equal(lo, [-1, 0.5, -4])
    np.testing.assert_array_equal(hi, [2, 3, -2])


def test_block_faces_count_in_a_region_group(make_sim):
    """On a unit lattice, the block 2..4 on each axis holds 3 x 3 x 3 sites (faces included)."""
    sim = make_sim()
    sim.command("""
        lattice spacing x 1 y 1 z 1
        region box block 0 10 0 10 0 10
        create_box 1 box
        create_particle 1 box
        region cube block 2 4 2 4 2 4
        group cube region cube
        compute n cube centroid
    """)
    member = sim.groups.select(sim, "cube")
    assert member.sum() == 27
    assert np.all((sim.x[member] >= 2) & (sim.x[member] <= 4))
    assert sim.compute_value("n", (0,)) == pytest.approx(3.0)


def test_block_inf_bounds_are_unbounded(make_sim):
    sim = make_sim()
    sim.command("region slab block -INF INF -INF INF 1 2\nregion half block 0 INF -1 1 -1 1")
    slab, half = sim.region("slab"), sim.region("half")
    points = np.array([[1e250, -1e250, 1.5], [-3.0, 7.0, 1.0], [0.0, 0.0, 2.5]])
    np.testing.assert_array_equal(slab.inside(points), [True, True, False])
    np.testing.assert_array_equal(half.inside(np.array([[1e200, 0, 0], [-1e-9, 0, 0]])), [True, False])
    for region in (slab, half):
        with pytest.raises(ScriptError, match="unbounded"):
            region.bounds()
    with pytest.raises(ScriptError, match="unbounded"):
        sim.command("create_box 1 slab")


def test_block_edge_takes_the_box_faces():
    sim = sim_with_box("-1 9 0 5 2 6")
    sim.command("region r block EDGE 3 1 EDGE EDGE EDGE")
    lo, hi = sim.region("r").bounds()
    np.testing.assert_array_equal(lo, [-1, 1, 2])
    np.testing.assert_array_equal(hi, [3, 5, 6])
    inside = sim.region("r").inside(np.array([[-1, 5, 2], [3, 1, 6], [-1.001, 2, 3], [0, 0.99, 3]]))
    np.testing.assert_array_equal(inside, [True, True, False, False])


def test_block_edge_needs_a_box(make_sim):
    sim = make_sim()
    with pytest.raises(ScriptError, match="EDGE needs the simulation box"):
        sim.command("region r block EDGE 1 0 1 0 1")


@pytest.mark.parametrize("args, words", [
    ("2 1 0 1 0 1", "xlo must be <= xhi (got 2 1)"),
    ("0 1 0 1 5 -5", "zlo must be <= zhi"),
    ("0 1 0 abc 0 1", "yhi must be a number, INF, -INF or EDGE (got abc)"),
    ("0 1 0 1 0", "missing argument zhi"),
    ("0 1 0 1 0 1 7", "unknown keyword 7 (known: side, units, move, rotate, volume_limit, open)"),
    ("0 1 0 1 0 1 side sideways", "side must be one of"),
    ("0 1 0 1 0 nan", "zhi must be a number, INF, -INF or EDGE (got nan)"),
    ("inf 1 0 1 0 1", "xlo must be a number, INF, -INF or EDGE (got inf)"),
    ("0 1e999 0 1 0 1", "xhi must be a number, INF, -INF or EDGE (got 1e999)"),
])
def test_block_bad_arguments(args, words, make_sim):
    sim = make_sim()
    with pytest.raises(ScriptError) as info:
        sim.command(f"region r block {args}")
    assert words in str(info.value)
    assert "r" not in sim.system.regions


def test_block_defines_the_box(make_sim):
    sim = make_sim()
    sim.command("region box block -2 3 0 4 1 1.5\ncreate_box 2 box")
    np.testing.assert_array_equal(sim.box.lo, [-2, 0, 1])
    np.testing.assert_array_equal(sim.box.hi, [3, 4, 1.5])


# ---- polygon ------------------------------------------------------------------------------------
def test_polygon_normal_from_the_first_three_points(make_sim):
    """The PDPS manual's wall: p1 (15,0,0) p2 (15,10,0) p3 (10,10,0): n = (p2-p1) x (p3-p1) / |.|
    = +z; listing the points the other way round flips it."""
    sim = make_sim()
    sim.command("region w polygon p1 15 0 0 p2 15 10 0 p3 10 10 0 p4 10 0 0")
    w = sim.region("w")
    np.testing.assert_allclose(w.normal, [0, 0, 1], atol=1e-15)
    assert list(w.labels) == ["p1", "p2", "p3", "p4"]
    np.testing.assert_array_equal(w.points, [[15, 0, 0], [15, 10, 0], [10, 10, 0], [10, 0, 0]])
    sim.command("region back polygon p1 10 10 0 p2 15 10 0 p3 15 0 0")
    np.testing.assert_allclose(sim.region("back").normal, [0, 0, -1], atol=1e-15)


def test_polygon_normal_of_a_tilted_plane(make_sim):
    p = np.array([[0.1, 0.2, 0.3], [1.3, 0.7, -0.2], [0.4, 1.9, 0.8]])
    expected = np.cross(p[1] - p[0], p[2] - p[0])
    expected /= np.linalg.norm(expected)
    # a fourth point in the plane, built from the first three with round-off
    p4 = p[0] + 0.7 * (p[1] - p[0]) + 1.3 * (p[2] - p[0])
    words = " ".join(f"q{k} {float(x)!r} {float(y)!r} {float(z)!r}"
                     for k, (x, y, z) in enumerate([*p, p4]))
    sim = make_sim()
    sim.command(f"region t polygon {words}")
    normal = sim.region("t").normal
    np.testing.assert_allclose(normal, expected, rtol=1e-14, atol=1e-15)
    assert np.linalg.norm(normal) == pytest.approx(1.0, abs=1e-15)
    assert abs((p4 - p[0]) @ normal) < 1e-12


def test_polygon_point_off_the_plane_is_an_error(make_sim):
    sim = make_sim()
    with pytest.raises(ScriptError, match="point p4 is not in the plane of the first three"):
        sim.command("region w polygon p1 15 0 0 p2 15 10 0 p3 10 10 0 p4 10 0 0.001")
    assert "w" not in sim.system.regions


@pytest.mark.parametrize("words, message", [
    ("p1 0 0 0 p2 1 0 0", "point takes at least 3 entries (got 2)"),
    ("p1 0 0 0", "point takes at least 3 entries (got 1)"),
    ("p1 0 0 0 p2 1 0 0 p3 0 1", "point p3 needs x y z (got 0 1)"),
    ("p1 0 0 0 p2 1 0 0 p3 2 0 0", "the first three points are on one line"),
    ("p1 0 0 0 p2 1 0 0 p3 0 x 0", "point p3: y must be a finite number (got x)"),
])
def test_polygon_bad_points(words, message, make_sim):
    sim = make_sim()
    with pytest.raises(ScriptError) as info:
        sim.command(f"region w polygon {words}")
    assert message in str(info.value)


def test_bad_point_message_is_one_clean_line(make_sim):
    sim = make_sim()
    with pytest.raises(ScriptError) as info:
        sim.command("region w polygon p1 0 0 0 p2 1 0 0 p3 0 x 0")
    assert str(info.value) == "<command>:1: region: point p3: y must be a finite number (got x)"


def test_polygon_is_a_surface_without_inside_or_extent():
    sim = sim_with_box()
    sim.command("create_particle 1 single 1 1 1\nregion w polygon p1 0 0 5 p2 1 0 5 p3 0 1 5")
    with pytest.raises(ScriptError, match="has no inside"):
        sim.command("group g region w")
    with pytest.raises(ScriptError, match="no extent"):
        sim.region("w").bounds()


# ---- surfaces for walls -------------------------------------------------------------------------
def contacts_by_point(region, x, reach):
    index, distance, normal, element = region.surface_contacts(np.asarray(x, dtype=float), reach)
    rows = {}
    for i, d, n, e in zip(index, distance, normal, element):
        rows.setdefault(int(i), []).append((int(e), float(d), tuple(float(c) for c in n)))
    return {i: sorted(r) for i, r in rows.items()}


def test_block_surface_from_inside_touches_each_near_face(make_sim):
    """Inside (a container): one contact per face within reach, normal into the block; a point in a
    corner touches three faces; a point in the middle none."""
    sim = make_sim()
    sim.command("region r block 0 4 0 6 0 8")
    found = contacts_by_point(sim.region("r"), [[0.25, 3, 4], [3.5, 5.75, 0.5], [2, 3, 4]], 0.6)
    assert found[0] == [(0, 0.25, (1.0, 0.0, 0.0))]
    assert found[1] == [(1, 0.5, (-1.0, 0.0, 0.0)), (3, 0.25, (0.0, -1.0, 0.0)),
                        (4, 0.5, (0.0, 0.0, 1.0))]
    assert 2 not in found


def test_block_surface_from_outside_is_one_contact_at_the_closest_point(make_sim):
    """Outside (an obstacle): face, edge and corner contacts, each once, element 6, with the normal
    from the block's closest point to the point."""
    sim = make_sim()
    sim.command("region r block 0 4 0 6 0 8")
    s = 0.3 / np.sqrt(2.0)
    c = 0.3 / np.sqrt(3.0)
    points = [[2, 3, 8.3], [4 + s, 3, 8 + s], [-c, -c, -c], [2, 3, 9.0]]
    index, distance, normal, element = sim.region("r").surface_contacts(np.array(points), 0.5)
    np.testing.assert_array_equal(index, [0, 1, 2])
    np.testing.assert_allclose(distance, [0.3, 0.3, 0.3], rtol=1e-14)
    r2, r3 = 1 / np.sqrt(2.0), 1 / np.sqrt(3.0)
    np.testing.assert_allclose(normal, [[0, 0, 1], [r2, 0, r2], [-r3, -r3, -r3]], rtol=1e-14,
                               atol=1e-15)
    np.testing.assert_array_equal(element, [6, 6, 6])


def test_block_with_inf_faces_is_a_floor(make_sim):
    sim = make_sim()
    sim.command("region floor block INF INF INF INF -5 0")
    index, distance, normal, element = sim.region("floor").surface_contacts(
        np.array([[1e6, -3e5, 0.4], [0.0, 0.0, -4.8]]), 0.5)
    np.testing.assert_array_equal(index, [0, 1])
    np.testing.assert_allclose(distance, [0.4, 0.2], rtol=1e-12)
    np.testing.assert_allclose(normal, [[0, 0, 1], [0, 0, 1]])
    np.testing.assert_array_equal(element, [6, 4])


def test_polygon_surface_face_edge_and_corner_from_both_sides(make_sim):
    """The PDPS manual's square wall (normal +z): above and below the face, beside an edge, beyond a
    corner; farther than reach gives nothing."""
    sim = make_sim()
    sim.command("region w polygon p1 15 0 0 p2 15 10 0 p3 10 10 0 p4 10 0 0")
    points = [[12, 5, 0.4], [12, 5, -0.3], [15.3, 5, 0.4], [9.7, -0.4, 0.0], [12, 5, 0.6],
              [16, 5, 0]]
    index, distance, normal, element = sim.region("w").surface_contacts(np.array(points), 0.55)
    np.testing.assert_array_equal(index, [0, 1, 2, 3])
    np.testing.assert_allclose(distance, [0.4, 0.3, 0.5, 0.5], rtol=1e-14)
    np.testing.assert_allclose(normal, [[0, 0, 1], [0, 0, -1], [0.6, 0, 0.8], [-0.6, -0.8, 0]],
                               rtol=1e-14, atol=1e-15)
    np.testing.assert_array_equal(element, [0, 0, 0, 0])


def test_polygon_surface_of_a_non_convex_polygon(make_sim):
    """An L-shaped polygon: the foot in the notch is outside the polygon, so the contact is with the
    nearest edge, not with the plane."""
    sim = make_sim()
    sim.command("region L polygon a 0 0 0 b 2 0 0 c 2 1 0 d 1 1 0 e 1 2 0 f 0 2 0")
    index, distance, normal, _ = sim.region("L").surface_contacts(
        np.array([[0.5, 1.5, 0.2], [1.5, 1.3, 0.4]]), 0.6)
    np.testing.assert_array_equal(index, [0, 1])
    np.testing.assert_allclose(distance, [0.2, 0.5], rtol=1e-14)
    np.testing.assert_allclose(normal[1], [0, 0.6, 0.8], rtol=1e-14, atol=1e-15)


def test_cylinder_surface_curved_wall_and_caps(make_sim):
    """A cylinder about z (axis at x=1, y=2, radius 3, from z=0 to 10): inside near the wall (normal
    towards the axis), outside near the wall (normal away from it), near a cap from inside (normal
    along the axis), in a corner (wall and cap); the middle and a point beyond reach nothing."""
    sim = make_sim()
    sim.command("region c cylinder z 1 2 3 0 10 units box")
    points = [[3.8, 2, 5], [1, 5.4, 5], [1, 2, 0.3], [1, 4.75, 9.8], [1, 2, 5], [5, 2, 5]]
    found = contacts_by_point(sim.region("c"), points, 0.5)
    assert set(found) == {0, 1, 2, 3}
    ((element, gap, normal),) = found[0]
    assert element == 0 and gap == pytest.approx(0.2, abs=1e-14) and normal == pytest.approx((-1.0, 0.0, 0.0))
    ((element, gap, normal),) = found[1]
    assert element == 0 and gap == pytest.approx(0.4, abs=1e-14) and normal == pytest.approx((0.0, 1.0, 0.0))
    assert found[2] == [(1, 0.3, (0.0, 0.0, 1.0))]
    (wall, cap) = found[3]
    assert wall[0] == 0 and wall[1] == pytest.approx(0.25, abs=1e-14) and wall[2] == pytest.approx((0.0, -1.0, 0.0))
    assert cap[0] == 2 and cap[1] == pytest.approx(0.2, abs=1e-12) and cap[2] == (0.0, 0.0, -1.0)
