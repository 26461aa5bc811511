"""Dumps vtk and xdmf, read back with meshio (its VTU, legacy VTK and XDMF time-series readers) and
checked against the simulation state: points, ids, types, v, f, radius, omega, times, the series
files, mesh walls, and what a run that stops (or a write that fails) leaves behind.
"""

import json
import os
import re
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import pytest

from pdps_core.api import ScriptError, SimulationError
from pdps_core.testing import build

LO = np.array([0.0, 0.0, 0.0])
HI = np.array([4.0, 5.0, 4.5])


def particles(n=30, seed=5):
    """Positions, types and ids (written in shuffled order, not contiguous)."""
    rng = np.random.default_rng(seed)
    ids = rng.permutation(np.arange(1, n + 1) * 7)
    x = LO + rng.random((n, 3)) * (HI - LO)
    return x, 1 + ids % 2, ids


@pytest.fixture
def fluid(tmp_path, monkeypatch):
    """A small DPD fluid (no radius, no omega) in a temporary folder."""
    monkeypatch.chdir(tmp_path)
    x, types, ids = particles()
    sim = build(tmp_path, x, types=types, tags=ids, masses={1: 1.0, 2: 2.0}, lo=LO, hi=HI,
                name="data.in", setup="""
        pair_style dpd 1.0 1.0 77
        pair_coeff * * 25.0 4.5
        velocity all create 1.0 3
        timestep 0.02
        fix 1 all nve
    """)
    return sim, ids


def state(sim):
    """The owned particles' arrays, sorted by id."""
    order = np.argsort(sim.tag)
    p = sim.particles
    out = {"x": sim.x[order], "id": sim.tag[order], "type": sim.type[order], "v": sim.v[order],
           "f": sim.f[order]}
    for name in ("radius", "omega"):
        if p.has(name):
            out[name] = p.arrays[name][: sim.nlocal][order]
    return out


def check_frame(points, cells, point_data, expected):
    np.testing.assert_array_equal(points, expected["x"])
    assert [block.type for block in cells] == ["vertex"]
    np.testing.assert_array_equal(cells[0].data.ravel(), np.arange(len(points)))
    assert sorted(point_data) == sorted(k for k in expected if k != "x")
    for name, values in point_data.items():
        np.testing.assert_array_equal(np.asarray(values).reshape(expected[name].shape), expected[name],
                                      err_msg=name)


def read_xdmf_frame(path):
    """(time, points, cells, point data) of one frame, through meshio's XDMF time-series reader."""
    with meshio.xdmf.TimeSeriesReader(path) as reader:
        assert reader.num_steps == 1
        points, cells = reader.read_points_cells()
        time, point_data, _ = reader.read_data(0)
    return time, points, cells, point_data


def xdmf_series(path):
    """(frame file, time) of every grid in an XDMF series, checking that each XInclude resolves in
    its frame file (its xpointer paths are of the kind ElementTree's find understands)."""
    root = ET.parse(path).getroot()
    collection = root.find("Domain/Grid")
    assert (collection.get("GridType"), collection.get("CollectionType")) == ("Collection", "Temporal")
    frames = []
    for grid in collection.findall("Grid"):
        includes = grid.findall("{http://www.w3.org/2001/XInclude}include")
        hrefs = {inc.get("href") for inc in includes}
        assert len(hrefs) == 1
        href = hrefs.pop()
        target = ET.parse(os.path.join(os.path.dirname(path), href)).getroot()
        tags = []
        for inc in includes:
            xpath = re.fullmatch(r"xpointer\((.*)\)", inc.get("xpointer")).group(1)
            tags += [element.tag for element in target.findall("." + xpath)]
        assert {"Geometry", "Topology"} <= set(tags)
        frames.append((href, float(grid.find("Time").get("Value"))))
    return frames


# ---- particles ----------------------------------------------------------------------------------
def test_vtk_frames_and_series_hold_the_particles(fluid, tmp_path):
    sim, ids = fluid
    sim.command("dump 1 all vtk 5 out_*.vtu\nrun 10")
    series = json.loads((tmp_path / "out.vtu.series").read_text())
    assert series["file-series-version"] == "1.0"
    assert series["files"] == [{"name": f"out_{s}.vtu", "time": pytest.approx(s * 0.02, abs=1e-12)}
                               for s in (0, 5, 10)]
    frames = [meshio.read(tmp_path / f"out_{s}.vtu") for s in (0, 5, 10)]
    for mesh in frames:
        np.testing.assert_array_equal(mesh.point_data["id"], np.sort(ids))
    last = frames[-1]
    check_frame(last.points, last.cells, last.point_data, state(sim))
    assert not np.allclose(frames[0].points, last.points)       # the particles moved


def test_legacy_vtk_and_a_group(fluid, tmp_path):
    sim, ids = fluid
    (tmp_path / "frames").mkdir()
    sim.command("group odd type 2\ndump 1 odd vtk 4 frames/odd.*.vtk\nrun 4")
    series = json.loads((tmp_path / "frames" / "odd.vtk.series").read_text())
    assert [f["name"] for f in series["files"]] == ["odd.0.vtk", "odd.4.vtk"]
    mesh = meshio.read(tmp_path / "frames" / "odd.4.vtk")
    expected = state(sim)
    odd = expected["type"] == 2
    check_frame(mesh.points, mesh.cells, mesh.point_data, {k: v[odd] for k, v in expected.items()})
    assert set(mesh.point_data["id"]) == {i for i in ids if i % 2 == 1}


def test_xdmf_frames_and_series_hold_the_particles(fluid, tmp_path):
    sim, ids = fluid
    sim.command("dump 2 all xdmf 5 traj_*.xdmf\nrun 10")
    assert xdmf_series(tmp_path / "traj.xdmf") == [
        (f"traj_{s}.xdmf", pytest.approx(s * 0.02, abs=1e-12)) for s in (0, 5, 10)]
    for s in (0, 5):
        time, _, _, point_data = read_xdmf_frame(tmp_path / f"traj_{s}.xdmf")
        assert time == pytest.approx(s * 0.02, abs=1e-12)
        np.testing.assert_array_equal(point_data["id"], np.sort(ids))
    time, points, cells, point_data = read_xdmf_frame(tmp_path / "traj_10.xdmf")
    check_frame(points, cells, point_data, state(sim))       # full precision survives the text


def two_spheres(make_sim, velocity, dumps):
    """Spheres of diameters 1 and 0.6 (types 1 and 2) moving at ``velocity`` under nve/sphere, with
    the ``dumps`` lines."""
    sim = make_sim()
    sim.command(f"""
        particle_style sphere
        region box block -3 3 -3 3 -3 3
        create_box 2 box
        create_particle 1 single 0 0 0 diameter 1 density 1
        create_particle 2 single 1.5 0.5 -1 diameter 0.6 density 2
        velocity all set {velocity}
        fix 1 all nve/sphere
    """)
    sim.command(dumps)
    return sim


def test_spheres_carry_radius_and_omega(tmp_path, make_sim):
    sim = two_spheres(make_sim, "0.1 0 0", "dump 1 all vtk 3 s_*.vtu\ndump 2 all xdmf 3 s_*.xdmf")
    sim.particles.omega[: sim.nlocal] = [[1.0, 2.0, 3.0], [-1.0, 0.5, 0.0]]
    sim.command("run 3")
    expected = state(sim)
    np.testing.assert_array_equal(expected["radius"], [0.5, 0.3])
    mesh = meshio.read(tmp_path / "s_3.vtu")
    check_frame(mesh.points, mesh.cells, mesh.point_data, expected)
    _, points, cells, point_data = read_xdmf_frame(tmp_path / "s_3.xdmf")
    check_frame(points, cells, point_data, expected)


# ---- mesh walls ---------------------------------------------------------------------------------
SQUARE = np.array([[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 1.0, 0.0]])
TRIANGLES = np.array([[0, 1, 2], [0, 2, 3]])


@pytest.mark.parametrize("style, ext", [("vtk", "vtu"), ("xdmf", "xdmf")])
def test_mesh_walls_moving_per_frame_static_once(tmp_path, make_sim, style, ext):
    meshio.write("square.stl", meshio.Mesh(SQUARE, [("triangle", TRIANGLES)]), file_format="stl")
    sim = make_sim()
    sim.command(f"""
        particle_style sphere
        boundary f f f
        region box block -3 3 -3 3 -3 3
        create_box 1 box
        create_particle 1 single 0 0 1.5 diameter 1 density 1
        fix 1 all nve/sphere
        fix lift all wall/mesh file square.stl velocity 0 0 0.5 model lsd 0.8 1e4 0.3
        fix floor all wall/mesh file square.stl move 0 0 -2 model lsd 0.8 1e4 0.3
        timestep 0.01
        dump 1 all {style} 10 p_*.{ext} walls yes
        run 20
    """)
    floor = meshio.read(tmp_path / f"p_wall_floor.{ext}") if style == "vtk" else None
    if style == "xdmf":
        _, points, cells, _ = read_xdmf_frame(tmp_path / f"p_wall_floor.{ext}")
        floor = meshio.Mesh(points, cells)
    np.testing.assert_allclose(floor.points, SQUARE + [0, 0, -2], atol=1e-6)   # STL is float32
    np.testing.assert_array_equal(floor.cells[0].data, TRIANGLES)
    assert not list(tmp_path.glob(f"p_wall_floor_*.{ext}"))                      # once: it is static
    if style == "vtk":
        frames = [(f["name"], f["time"])
                  for f in json.loads((tmp_path / "p_wall_lift.vtu.series").read_text())["files"]]
    else:
        frames = xdmf_series(tmp_path / "p_wall_lift.xdmf")
    assert [name for name, _ in frames] == [f"p_wall_lift_{s}.{ext}" for s in (0, 10, 20)]
    for name, time in frames:
        if style == "vtk":
            mesh = meshio.read(tmp_path / name)
            points, cells = mesh.points, mesh.cells
        else:
            _, points, cells, _ = read_xdmf_frame(tmp_path / name)
        assert [block.type for block in cells] == ["triangle"]
        np.testing.assert_allclose(points, SQUARE + [0, 0, 0.5 * time], atol=1e-6)
    np.testing.assert_array_equal(points, sim.fixes["lift"].vertices)


def test_a_group_that_empties_gives_empty_frames_paraview_reads(tmp_path, make_sim):
    """Groups are re-evaluated at each run: the second run's frames hold no particle. An empty
    XDMF data item makes ParaView's reader abort, so such a frame is a grid with a time alone (and
    its series entry includes nothing); meshio cannot read an empty VTU, so it is read as XML."""
    sim = make_sim()
    sim.command("""
        region box block 0 4 0 4 0 4
        create_box 1 box
        mass 1 1
        create_particle 1 single 1 1 1
        create_particle 1 single 3.5 3.5 3.5
        region corner block 3 4 3 4 3 4
        group g region corner
        dump 1 g vtk 5 e_*.vtu
        dump 2 g xdmf 5 e_*.xdmf
        run 5
    """)
    sim.x[:] = [[1.0, 1.0, 1.0], [2.0, 2.0, 2.0]]
    sim.command("run 5")
    assert len(meshio.read(tmp_path / "e_5.vtu").points) == 1
    piece = ET.parse(tmp_path / "e_10.vtu").getroot().find("UnstructuredGrid/Piece")
    assert (piece.get("NumberOfPoints"), piece.get("NumberOfCells")) == ("0", "0")
    grids = ET.parse(tmp_path / "e.xdmf").getroot().findall("Domain/Grid/Grid")
    assert [len(grid.findall("{http://www.w3.org/2001/XInclude}include")) for grid in grids] == [2, 2, 0]
    assert [float(grid.find("Time").get("Value")) for grid in grids] == pytest.approx([0, 0.025, 0.05])
    empty = ET.parse(tmp_path / "e_10.xdmf").getroot()
    assert float(empty.find(".//Time").get("Value")) == pytest.approx(0.05)
    assert empty.find(".//Geometry") is None and empty.find(".//DataItem") is None
    _, points, _, point_data = read_xdmf_frame(tmp_path / "e_5.xdmf")
    np.testing.assert_array_equal(points, [[3.5, 3.5, 3.5]])
    np.testing.assert_array_equal(point_data["id"], [2])


def test_walls_are_not_written_unless_asked(fluid, tmp_path):
    sim, _ = fluid
    sim.command("dump 1 all vtk 5 out_*.vtu\nrun 5")
    assert not list(tmp_path.glob("*wall*"))


# ---- what a stopped run leaves ------------------------------------------------------------------
def test_run_stopped_by_an_error_leaves_complete_frames(tmp_path, make_sim):
    sim = make_sim()
    sim.command("""
        boundary f f f
        region box block 0 10 0 10 0 10
        create_box 1 box
        mass 1 1.0
        create_particle 1 single 5.0 5.0 5.0
        create_particle 1 single 9.0 5.0 5.0
        timestep 0.01
        fix 1 all nve
        dump 1 all vtk 2 lost_*.vtu
        dump 2 all xdmf 2 lost_*.xdmf
    """)
    sim.v[sim.tag == 2] = [10.0, 0.0, 0.0]
    with pytest.raises(SimulationError, match="lost through the fixed x boundary"):
        sim.command("run 100")
    names = [f["name"] for f in json.loads((tmp_path / "lost.vtu.series").read_text())["files"]]
    assert len(names) >= 3
    assert sorted(p.name for p in tmp_path.glob("*.vtu")) == sorted(names)
    assert [name for name, _ in xdmf_series(tmp_path / "lost.xdmf")] == [
        n.replace(".vtu", ".xdmf") for n in names]
    for name in names:
        mesh = meshio.read(tmp_path / name)
        assert len(mesh.points) == 2
        read_xdmf_frame(tmp_path / name.replace(".vtu", ".xdmf"))
    assert not list(tmp_path.glob(".*"))                     # no temporary file left


def test_a_frame_that_fails_midway_is_not_listed(fluid, tmp_path, monkeypatch):
    """The writer dies after writing part of the third frame: the frames before it and the series
    are whole, the broken frame never appears under its name, and its temporary file is gone."""
    sim, _ = fluid
    sim.command("dump 1 all vtk 5 out_*.vtu")
    dump = sim.output.dumps["1"]
    real = dump.write_mesh
    calls = []

    def dies_on_the_third(tmp, *args):
        calls.append(tmp)
        if len(calls) == 3:
            with open(tmp, "w") as handle:
                handle.write("<?xml version")              # cut short
            raise OSError(28, "No space left on device")
        real(tmp, *args)

    monkeypatch.setattr(dump, "write_mesh", dies_on_the_third)
    with pytest.raises(OSError):
        sim.command("run 20")
    series = json.loads((tmp_path / "out.vtu.series").read_text())
    assert [f["name"] for f in series["files"]] == ["out_0.vtu", "out_5.vtu"]
    assert sorted(p.name for p in tmp_path.glob("out_*")) == ["out_0.vtu", "out_5.vtu"]
    assert not os.path.exists(calls[2])
    for name in ("out_0.vtu", "out_5.vtu"):
        assert len(meshio.read(tmp_path / name).points) == 30


# ---- bad input ----------------------------------------------------------------------------------
@pytest.mark.parametrize("line, words", [
    ("dump 1 all vtk 5 out.vtu", ("needs one *", "frames_*.vtu")),
    ("dump 1 all vtk 5 out_*_*.vtu", ("needs one *",)),
    ("dump 1 all vtk 5 out_*.xdmf", ("must end in * and .vtu or .vtk",)),
    ("dump 1 all xdmf 5 out_*.vtu", ("must end in * and .xdmf or .xmf",)),
    ("dump 1 all vtk 5 no/such/dir/out_*.vtu", ("cannot write dump files in no/such/dir",)),
    ("dump 1 all vtk 5 out_*.vtu walls maybe", ("walls must be yes or no",)),
    ("dump 1 all vtk 5 out_*.vtu colour red", ("unknown keyword colour",)),
])
def test_bad_dump_commands(fluid, line, words):
    sim, _ = fluid
    with pytest.raises(ScriptError) as info:
        sim.command(line)
    for word in words:
        assert word in str(info.value)


def test_custom_vtk_writes_the_listed_values(tmp_path, make_sim):
    """LIGGGHTS's dump custom/vtk: positions as points, sorted by id, vx vy vz as the vector v, a lone
    component alone, radius and id as listed; c_ID and unknown words refused."""
    sim = two_spheres(make_sim, "0.1 0.2 -0.3", "dump 1 all custom/vtk 3 post_*.vtk id type x y z vx vy vz fz radius")
    sim.command("run 3")
    expected = state(sim)
    mesh = meshio.read(tmp_path / "post_3.vtk")
    np.testing.assert_array_equal(mesh.points, expected["x"])
    assert sorted(mesh.point_data) == ["fz", "id", "radius", "type", "v"]
    np.testing.assert_array_equal(mesh.point_data["v"], expected["v"])
    np.testing.assert_array_equal(np.ravel(mesh.point_data["fz"]), expected["f"][:, 2])
    np.testing.assert_array_equal(np.ravel(mesh.point_data["radius"]), expected["radius"])
    np.testing.assert_array_equal(np.ravel(mesh.point_data["id"]), expected["id"])
    assert (tmp_path / "post.vtk.series").exists()
    with pytest.raises(ScriptError, match="custom/vtk: c_ke: compute ke is not defined"):
        sim.command("dump 2 all custom/vtk 3 q_*.vtk id c_ke")
    with pytest.raises(ScriptError, match="custom/vtk: unknown attribute colour"):
        sim.command("dump 3 all custom/vtk 3 q_*.vtk id colour")
    with pytest.raises(ScriptError, match="custom/vtk: xu: the points are the wrapped positions x y z"):
        sim.command("dump 4 all custom/vtk 3 q_*.vtk id xu yu zu")


def test_custom_vtk_writes_computes_fixes_and_variables(tmp_path, make_sim):
    """c_ID[k], v_NAME of an atom-style variable and a fix's per-atom values (LIGGGHTS's heat
    tutorials write f_Temp[0]) as scalars named as written, the values dump custom writes."""
    lines = """compute p all property/atom vx radius
        variable twice atom 2*vz+x
        dump 1 all custom/vtk 3 q_*.vtk id c_p[1] v_twice
        dump 2 all custom 3 q_*.txt id c_p[1] v_twice"""
    sim = two_spheres(make_sim, "0.1 0.2 -0.3", lines)
    sim.command("run 3")
    expected = state(sim)
    mesh = meshio.read(tmp_path / "q_3.vtk")
    assert sorted(mesh.point_data) == ["c_p[1]", "id", "v_twice"]
    np.testing.assert_array_equal(np.ravel(mesh.point_data["c_p[1]"]), expected["radius"])
    np.testing.assert_allclose(np.ravel(mesh.point_data["v_twice"]), 2 * expected["v"][:, 2] + expected["x"][:, 0],
                               rtol=1e-15)
    rows = np.loadtxt(tmp_path / "q_3.txt", skiprows=9)
    rows = rows[np.argsort(rows[:, 0])]
    np.testing.assert_allclose(rows[:, 2], 2 * expected["v"][:, 2] + expected["x"][:, 0], rtol=1e-9)
    with pytest.raises(ScriptError, match=r"custom/vtk: v_nope: variable nope is not defined"):
        sim.command("dump 3 all custom/vtk 3 r_*.vtk id v_nope")
    with pytest.raises(ScriptError, match=r"custom/vtk: c_p\[2\]: column 2 is out of range"):
        sim.command("dump 4 all custom/vtk 3 r_*.vtk id c_p[2]")
        sim.command("run 3")


@pytest.mark.parametrize("style", ["vtk", "custom/vtk"])
def test_a_frame_without_particles_is_an_empty_legacy_grid(tmp_path, make_sim, style):
    """Before an insertion fix has added anything: a legacy VTK frame with no points, not an error."""
    sim = make_sim()
    sim.command(f"""
        particle_style sphere
        region box block -3 3 -3 3 -3 3
        create_box 1 box
        dump 1 all {style} 1 e_*.vtk{' id radius' if style == 'custom/vtk' else ''}
        run 0
    """)
    assert b"POINTS 0 double" in (tmp_path / "e_0.vtk").read_bytes()
