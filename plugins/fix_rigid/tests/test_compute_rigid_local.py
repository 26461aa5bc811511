"""compute rigid/local: the values of fix rigid/small's bodies against what the bodies must have (mass
the sum of their particles', centre of mass that of the particles, unit quaternions, the principal
moments of a known shape, angular momentum I omega of a spinning body), written with dump local; the
same values for fix rigid's bodies; bad input one line."""

import io
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

sys.path.insert(0, str(Path(__file__).parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from rigid import lj_bodies  # noqa: E402  (the LAMMPS scenes' bodies)
from test_rigid_small import molecular_data  # noqa: E402

# an octahedron of six unit masses on its principal axes: I = 2 (b^2 + c^2), 2 (a^2 + c^2), 2 (a^2 + b^2)
A, B, C = 1.0, 0.7, 0.4
MOMENTS = np.array([2 * (B * B + C * C), 2 * (A * A + C * C), 2 * (A * A + B * B)])
OCTAHEDRON = np.array([[A, 0, 0], [-A, 0, 0], [0, B, 0], [0, -B, 0], [0, 0, C], [0, 0, -C]])
SPIN = 0.3          # the octahedron's angular velocity about z
INPUTS = ("id mol mass x y z xu yu zu ix iy iz vx vy vz fx fy fz omegax omegay omegaz angmomx angmomy angmomz "
          "quatw quati quatj quatk tqx tqy tqz inertiax inertiay inertiaz").split()


def scene(tmp_path, style):
    """The octahedron spinning about z at (5, 5, 5) (molecule 4), a triangle across the x face of the
    periodic box (molecule 9, image flags of the whole body), a dimer at rest (molecule 2)."""
    octahedron = OCTAHEDRON + 5.0
    triangle = np.array([[19.5, 10, 10], [0.5, 10, 10], [19.8, 11, 10.5]])
    dimer = np.array([[10, 3, 3], [11, 3, 3]])
    x = np.vstack([octahedron, triangle, dimer])
    images = np.zeros((11, 3), dtype=int)
    images[7, 0] = 1
    v = np.zeros((11, 3))
    v[:6] = np.cross([0, 0, SPIN], OCTAHEDRON) + [0.1, 0.0, -0.2]
    v[6:9] = [0.0, 0.25, 0.0]
    path = molecular_data(tmp_path / "bodies.data", x, [4] * 6 + [9] * 3 + [2] * 2, v=v, images=images)
    sim = Simulation(screen=io.StringIO(), log=None)
    sim.command(f"units lj\natom_style molecular\nread_data {path}\nfix rb all {style} molecule\n"
                f"compute 1 all rigid/local rb {' '.join(INPUTS)}\n"
                f"dump 1 all local 1 {tmp_path / 'rigid.dump'} c_1[1] c_1[2] c_1[3] c_1[4] c_1[5] c_1[6]\n"
                "run 0")
    return sim, x, images, v


def by_mol(rows):
    return {int(row[INPUTS.index("mol")]): dict(zip(INPUTS, row)) for row in rows}


@pytest.mark.parametrize("style", ["rigid/small", "rigid"])
def test_values_are_the_bodies(tmp_path, style):
    sim, x, images, v = scene(tmp_path, style)
    rows = sim.computes["1"].local(sim)
    assert rows.shape == (3, len(INPUTS))
    bodies = by_mol(rows)
    unwrapped = x + images * 20.0
    for mol, members in ((4, slice(0, 6)), (9, slice(6, 9)), (2, slice(9, 11))):
        body = bodies[mol]
        count = members.stop - members.start
        assert body["mass"] == count
        centre = unwrapped[members].mean(axis=0)
        assert [body["xu"], body["yu"], body["zu"]] == pytest.approx(centre, abs=1e-12)
        wrapped = [body["x"], body["y"], body["z"]]
        assert wrapped == pytest.approx(centre - 20.0 * np.floor(centre / 20.0), abs=1e-12)
        assert [body["ix"], body["iy"], body["iz"]] == list(np.floor(centre / 20.0))
        assert [body["vx"], body["vy"], body["vz"]] == pytest.approx(v[members].mean(axis=0), abs=1e-12)
        quat = np.array([body["quatw"], body["quati"], body["quatj"], body["quatk"]])
        assert np.linalg.norm(quat) == pytest.approx(1.0, abs=1e-14)
        # no forces: no pair style, no fix pushing
        assert [body[k] for k in ("fx", "fy", "fz", "tqx", "tqy", "tqz")] == [0.0] * 6
    octahedron = bodies[4]
    assert [octahedron["inertiax"], octahedron["inertiay"], octahedron["inertiaz"]] == pytest.approx(MOMENTS, rel=1e-12)
    assert [octahedron["angmomx"], octahedron["angmomy"], octahedron["angmomz"]] == pytest.approx(
        [0, 0, MOMENTS[2] * SPIN], abs=1e-12)
    assert [octahedron["omegax"], octahedron["omegay"], octahedron["omegaz"]] == pytest.approx([0, 0, SPIN], abs=1e-12)
    # the dimer: a linear body, one moment 0, the other two m d^2 / 2 each
    dimer = bodies[2]
    assert [dimer["inertiax"], dimer["inertiay"], dimer["inertiaz"]] == pytest.approx([0.0, 0.5, 0.5], abs=1e-12)
    if style == "rigid/small":
        # the owner: the particle nearest the bounding box's centre, the lower id on a tie
        assert octahedron["id"] == 5 and dimer["id"] == 10 and bodies[9]["id"] == 9
    else:
        assert sorted(body["id"] for body in bodies.values()) == [1, 2, 3]
    # dump local writes the same rows
    lines = (tmp_path / "rigid.dump").read_text().splitlines()
    assert lines[3] == "3" and lines[8].split()[2:] == ["c_1[1]", "c_1[2]", "c_1[3]", "c_1[4]", "c_1[5]", "c_1[6]"]
    written = np.array([[float(w) for w in line.split()] for line in lines[9:12]])
    # c_1[k] counts from the dialect's first index
    assert written == pytest.approx(rows[:, [sim.dialect_index(k, "c_1[k]") for k in range(1, 7)]], rel=1e-12)


def test_group_chooses_by_owner_and_one_input_is_a_vector(tmp_path):
    sim, *_ = scene(tmp_path, "rigid/small")
    sim.command("group owners id 5 10\ncompute m owners rigid/local rb mass\nrun 0")
    assert sorted(sim.computes["m"].local(sim)) == [2.0, 6.0]


@pytest.mark.parametrize("line, message", [
    ("compute 2 all rigid/local rb", "compute rigid/local needs at least one input"),
    ("compute 2 all rigid/local rb mass colour", "unknown input colour"),
])
def test_bad_input_is_one_line(tmp_path, line, message):
    sim, *_ = scene(tmp_path, "rigid/small")
    with pytest.raises(ScriptError, match=message):
        sim.command(line)


def test_the_fix_must_be_a_rigid_fix(tmp_path):
    sim, *_ = scene(tmp_path, "rigid/small")
    sim.command("fix 2 all nve\ncompute 2 all rigid/local 2 mass\ncompute 3 all rigid/local none mass")
    with pytest.raises(ScriptError, match=r"compute 2: fix 2 \(nve\) is not a rigid/small fix"):
        sim.computes["2"].local(sim)
    with pytest.raises(ScriptError, match="compute 3: fix none is not defined"):
        sim.computes["3"].local(sim)


def test_the_same_rows_on_one_and_two_ranks(tmp_path):
    """27 bodies drifting across ranks for 1000 steps (the LAMMPS scene of rigid/small): the rows
    dump local gathers, sorted by owner id, are those of one rank."""
    import shutil

    from pdps_core.testing import run_ranks
    shutil.copy(Path(__file__).with_name("data") / "rigid_small_lj.data", tmp_path)
    script = lj_bodies("rigid_small_lj.data") + """timestep 0.001
fix rb all rigid/nve/small molecule
compute 1 all rigid/local rb id mol mass xu yu zu vx vy vz quatw quati quatj quatk tqx tqy tqz
dump 1 all local 1000 rows.{ranks} COLUMNS
run 1000
""".replace("COLUMNS", " ".join(f"c_1[{k}]" for k in range(1, 17)))
    tables = {}
    for ranks in (1, 2):
        run_ranks(script.format(ranks=ranks), ranks, tmp_path)
        lines = (tmp_path / f"rows.{ranks}").read_text().splitlines()
        last = len(lines) - 1 - lines[::-1].index("ITEM: NUMBER OF ENTRIES")
        count = int(lines[last + 1])
        rows = np.array([[float(w) for w in line.split()] for line in lines[last + 7:last + 7 + count]])
        tables[ranks] = rows[np.argsort(rows[:, 0])]
    assert tables[1].shape == tables[2].shape == (27, 16)
    assert tables[2] == pytest.approx(tables[1], rel=1e-10, abs=1e-12)
