"""dump local/gran/vtk: the contact lines of compute pair/gran/local and wall/gran/local against
LIGGGHTS 3.8.0's frames of the same scene (recorded by benchmarks/liggghts_references/
local_gran_vtk.py: points, lines and every cell array, contacts across the periodic boundary
among them), the compute's group, two ranks, and the refusals at the dump line."""

import json
import os
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import meshio
import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import run_ranks

REFERENCE = json.loads((Path(__file__).parent / "data" / "liggghts_local_gran_vtk.json").read_text())
# LIGGGHTS writes points as Float32 (.vtp, .vtu: half a unit in the last place at |x| <= 0.02), or
# at 6 digits (legacy .vtk: half a unit of the sixth)
POINTS_ATOL, LEGACY_POINTS_RTOL = 2e-9, 5e-6
# arrays at 17 digits (.vtp, .vtu) or 11 (.vtk); an array's near-zero entries to 1e-9 of its largest
RTOL, SCALE_ATOL = 1e-8, 1e-9


def read_vtp(path):
    piece = ElementTree.parse(path).getroot().find("PolyData/Piece")

    def values(array):
        return np.array((array.text or "").split(), dtype=np.float64)

    points = values(piece.find("Points/DataArray")).reshape(-1, 3)
    lines = values(piece.find("Lines/DataArray[@Name='connectivity']")).astype(np.int64).reshape(-1, 2)
    data = {}
    for array in piece.find("CellData"):
        width = int(array.get("NumberOfComponents", "1"))
        data[array.get("Name")] = values(array).reshape(-1, width) if width > 1 else values(array)
    return points, lines, data


def read_frame(path):
    if str(path).endswith(".vtp"):
        return read_vtp(path)
    mesh = meshio.read(path)
    lines = mesh.cells[0].data if mesh.cells else np.zeros((0, 2), dtype=np.int64)
    return (np.asarray(mesh.points, dtype=np.float64), lines,
            {name: np.asarray(blocks[0], dtype=np.float64) for name, blocks in mesh.cell_data.items()})


def contacts(points, lines, data, wall):
    """{key: (point 1, point 2, {array: value})} of a frame, each pair contact turned so that id1 <
    id2 (the force then on the other particle: negated); wall contacts keyed by the particle's
    position (point 2)."""
    found = {}
    for k, (a, b) in enumerate(np.asarray(lines)):
        row = {name: np.array(values[k], dtype=np.float64) for name, values in data.items()}
        p1, p2 = np.asarray(points[a], dtype=np.float64), np.asarray(points[b], dtype=np.float64)
        if wall:
            found[tuple(np.round(p2, 4))] = (p1, p2, row)
            continue
        if row["id1"] > row["id2"]:
            p1, p2 = p2, p1
            row["id1"], row["id2"] = row["id2"], row["id1"]
            row["vel1"], row["vel2"] = row["vel2"], row["vel1"]
            row["force"] = -row["force"]
        found[(int(row["id1"]), int(row["id2"]))] = (p1, p2, row)
    return found


# what depends on the velocity of a contact's ghost copy (next test's docstring)
GHOST_VELOCITY = ("vel1", "vel2", "force", "torque")


def assert_same_contacts(mine, theirs, wall, what, across=()):
    """The same contacts, points and arrays; for the contacts ``across`` a periodic boundary, not
    the arrays of GHOST_VELOCITY."""
    ours = contacts(*mine, wall)
    reference = contacts(*theirs, wall)
    assert sorted(ours) == sorted(reference), what
    assert list(mine[2]) == list(theirs[2]), what
    for name in theirs[2]:
        scale = max((np.abs(row[name]).max() for _, _, row in reference.values()), default=0.0)
        for key, (p1, p2, row) in reference.items():
            q1, q2, other = ours[key]
            if key in across and name in GHOST_VELOCITY:
                continue
            rtol, atol = (LEGACY_POINTS_RTOL, 1e-12) if what.endswith(".vtk") else (0.0, POINTS_ATOL)
            np.testing.assert_allclose(q1, p1, rtol=rtol, atol=atol, err_msg=f"{what} {key} point 1")
            np.testing.assert_allclose(q2, p2, rtol=rtol, atol=atol, err_msg=f"{what} {key} point 2")
            np.testing.assert_allclose(other[name], row[name], rtol=RTOL, atol=SCALE_ATOL * scale,
                                       err_msg=f"{what} {key} {name}")


def scene(folder, script=None):
    (folder / "floor.stl").write_text(REFERENCE["floor.stl"])
    (folder / "in.lgv").write_text(script or REFERENCE["script"])
    return folder / "in.lgv"


def run_scene(folder, script=None):
    """The scene's script run by pdps (LIGGGHTS dialect) in ``folder``, where its frames go."""
    path = scene(folder, script)
    here = os.getcwd()
    os.chdir(folder)
    try:
        Simulation(screen=False, log=None, dialect="liggghts").file(str(path))
    finally:
        os.chdir(here)


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    folder = tmp_path_factory.mktemp("lgv")
    run_scene(folder)
    return folder


@pytest.mark.parametrize("name", sorted(REFERENCE["frames"]))
def test_frames_match_liggghts(written, name):
    """Every frame of both computes (pair: .vtp, .vtu; wall: legacy .vtk) holds LIGGGHTS's contacts:
    the same lines between the same points, the same arrays in the same order, the same values;
    the pairs include the contact of spheres 1 and 4 across the periodic boundary, both at their own
    (wrapped) positions. Of that contact, after step 0, the velocities and the force are not
    compared: both programs read the velocity of the ghost copy as last communicated (before the
    step's second half-kick, as LIGGGHTS's pair/gran/local re-evaluates the pair at the dump), and
    LIGGGHTS's ghost is sphere 1, pdps's sphere 4 (the particles themselves agree: the bed's thermo
    matches to 1e-14)."""
    theirs = REFERENCE["frames"][name]
    reference = (np.array(theirs["points"]), np.array(theirs["lines"], dtype=np.int64),
                 {k: np.array(v) for k, v in theirs["cell_data"].items()})
    across = {(1, 4)} if not name.startswith(("wall", "pair_0.", "pairu_0.")) else set()
    assert_same_contacts(read_frame(written / name), reference, name.startswith("wall"), name, across)


def test_the_periodic_contact_spans_the_box(written):
    points, lines, data = read_frame(written / "pair_0.vtp")
    found = contacts(points, lines, data, wall=False)
    p1, p2, _ = found[(1, 4)]
    assert p1[0] == pytest.approx(-0.014985) and p2[0] == pytest.approx(0.014985)
    assert len(found) == 5


def test_the_compute_group_selects_the_contacts(tmp_path):
    """compute pair/gran/local of the group low (the four small spheres): the ring's four contacts,
    none with sphere 5, their values those of the group all."""
    script = REFERENCE["script"].replace("compute pl all pair/gran/local", "compute pl low pair/gran/local")
    run_scene(tmp_path, script)
    mine = contacts(*read_frame(tmp_path / "pair_0.vtp"), wall=False)
    theirs = REFERENCE["frames"]["pair_0.vtp"]
    every = contacts(np.array(theirs["points"]), np.array(theirs["lines"]),
                     {k: np.array(v) for k, v in theirs["cell_data"].items()}, wall=False)
    assert all(5 not in key for key in mine)
    assert set(mine) == {key for key in every if 5 not in key}
    for key, (_, _, row) in mine.items():
        np.testing.assert_allclose(row["delta"], every[key][2]["delta"], rtol=RTOL)


def test_two_ranks_write_the_same_contacts(written, tmp_path):
    """mpiexec -n 2: rank 0 gathers every contact; the frames equal the serial ones."""
    script = REFERENCE["script"].replace("region box block", "processors 2 1 1\nregion box block")
    scene(tmp_path, script)
    run_ranks(script, 2, tmp_path, name="in.lgv", dialect="liggghts")
    for name in ("pair_0.vtp", "pair_200.vtp", "wall_100.vtk", "pairu_200.vtu"):
        assert_same_contacts(read_frame(tmp_path / name), read_frame(written / name), name.startswith("wall"),
                             name)


PREAMBLE = """atom_style granular
atom_modify map array
boundary p p f
units si
region box block -0.02 0.02 -0.01 0.01 0 0.04 units box
create_box 1 box
compute k all ke
"""


@pytest.mark.parametrize("line, message", [
    ("dump d all local/gran/vtk 10 c_*.vtp k",
     "local/gran/vtk: compute k (ke) is not a compute pair/gran/local or wall/gran/local"),
    ("dump d all local/gran/vtk 10 c_*.vtp nope", "local/gran/vtk: no compute nope"),
    ("dump d all local/gran/vtk 10 c_*.pvtp k",
     "local/gran/vtk: parallel piece files (.pvtp, .pvtu) are not supported: pdps writes one file per frame "
     "from rank 0; use .vtp or .vtu (got c_*.pvtp)"),
    ("group low id 1\ndump d low local/gran/vtk 10 c_*.vtp k",
     "local/gran/vtk: the compute's group selects the contacts (LIGGGHTS reads no dump group): use group all "
     "(got low)"),
    ("dump d all local/gran/vtk 10 c.vtp k", "the file name needs one * (replaced by the step)"),
    ("dump d all local/gran/vtk 10 c_*.xyz k", "the file name must end in * and .vtp or .vtu or .vtk"),
    ("compute b all pair/gran/local/bond", "compute pair/gran/local (pdps has no cohesion bond model"),
])
def test_refused_at_the_dump_line(tmp_path, monkeypatch, line, message):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    for command in PREAMBLE.splitlines():
        sim.command(command)
    with pytest.raises(ScriptError) as info:
        for command in line.splitlines():
            sim.command(command)
    assert message in str(info.value)


def test_a_compute_without_positions_is_refused(tmp_path):
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    for command in PREAMBLE.splitlines():
        sim.command(command)
    sim.command("pair_style gran model hertz tangential history")
    sim.command("compute pl all pair/gran/local force")
    with pytest.raises(ScriptError, match=r"local/gran/vtk: compute pl writes no positions \(add pos\)"):
        sim.command(f"dump d all local/gran/vtk 10 {tmp_path}/c_*.vtp pl")
