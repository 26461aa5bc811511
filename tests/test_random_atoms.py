"""create_atoms random and displace_atoms random in the LAMMPS dialect place and move the particles
LAMMPS (22 Jul 2025) does: the scripts of benchmarks/lammps_references/random_atoms.py, run by pdps on
1 and 2 ranks, write LAMMPS's data files (tests/data/lammps/random_atoms/NAME.data: the same ids,
types and image flags, positions to 1e-12) and print LAMMPS's ``Created N atoms`` and ``WARNING:
Only inserted M particles out of N`` lines (NAME.messages)."""

import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "lammps" / "random_atoms"
MPIEXEC = Path(sys.executable).parent / "mpiexec"
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from random_atoms import SCRIPTS, messages  # noqa: E402


def atoms(path):
    """(id, type, x, y, z, ix, iy, iz) rows of a data file's Atoms section, by id."""
    text = Path(path).read_text()
    section = re.split(r"\n(?=[A-Z][A-Za-z ]+(?:#.*)?\n)", text.split("Atoms", 1)[1], maxsplit=1)[0]
    rows = [line.split() for line in section.splitlines()[1:] if line.strip() and not line.startswith("#")]
    table = np.array([[float(v) for v in row[:8]] for row in rows]).reshape(-1, 8)
    return table[np.argsort(table[:, 0])]


def assert_lammps_particles(data_file, name):
    mine, lammps = atoms(data_file), atoms(DATA / f"{name}.data")
    assert mine.shape == lammps.shape
    np.testing.assert_array_equal(mine[:, :2], lammps[:, :2])        # ids and types
    np.testing.assert_allclose(mine[:, 2:5], lammps[:, 2:5], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(mine[:, 5:], lammps[:, 5:])        # image flags


def lammps_messages(name):
    return (DATA / f"{name}.messages").read_text().splitlines()


@pytest.mark.parametrize("name", list(SCRIPTS))
def test_one_rank_makes_lammps_particles(tmp_path, name):
    (tmp_path / "in.random").write_text(SCRIPTS[name])
    log = tmp_path / "log.pdps"
    sim = Simulation(screen=False, log=str(log))
    sim.script.directory = str(tmp_path)
    sim.file(str(tmp_path / "in.random"))
    sim.close()
    assert_lammps_particles(tmp_path / "out.data", name)
    assert messages(log.read_text()) == lammps_messages(name)


def test_the_scenes_reach_what_they_are_for():
    # the recorded scenes: the overlap and maxtry paths taken, particles moved across periodic faces
    assert lammps_messages("maxtry")[0].startswith("WARNING: Only inserted ")
    inserted = int(lammps_messages("maxtry")[0].split()[3])
    assert 0 < inserted < 500 and lammps_messages("maxtry")[1] == f"Created {inserted} atoms"
    assert lammps_messages("sphere_seeds") == ["Created 300 atoms"] * 3 + ["Created 50 atoms"]
    moved = atoms(DATA / "displace.data")
    assert len(moved) == 256 and np.any(moved[:, 5:] != 0)
    # overlap 0.9 (box units): no two particles closer, periodic images counted
    placed = atoms(DATA / "block_overlap.data")[:, 2:5]
    d = placed[:, None, :] - placed[None, :, :]
    d -= 10.0 * np.round(d / 10.0)
    r = np.sqrt((d ** 2).sum(axis=2)) + np.eye(len(placed)) * 1e9
    assert len(placed) == 250 and r.min() >= 0.9


def run_ranks(tmp_path, script, ranks):
    (tmp_path / "in.random").write_text(script)
    assert MPIEXEC.exists(), "mpiexec missing: make test installs mpich with the core's [mpi] extra"
    return subprocess.run([str(MPIEXEC), "-n", str(ranks), sys.executable, "-m", "pdps_core.cli", "run", "in.random",
                           "-log", "none"], cwd=tmp_path, capture_output=True, text=True, timeout=900)


@pytest.mark.parametrize("name", ["block_overlap", "maxtry", "displace"])
def test_two_ranks_make_the_same_particles(tmp_path, name):
    result = run_ranks(tmp_path, SCRIPTS[name], 2)
    assert result.returncode == 0, result.stderr
    assert_lammps_particles(tmp_path / "out.data", name)
    assert messages(result.stdout) == lammps_messages(name)


def lammps_sim():
    sim = Simulation(dialect="lammps", screen=False, log=None)
    sim.command("units lj\natom_style atomic\nregion box block 0 5 0 5 0 5 units box\ncreate_box 1 box\nmass 1 1.0")
    return sim


def test_the_pdps_dialect_keeps_its_own_numbers():
    sim = Simulation(screen=False, log=None)
    sim.command("units lj\natom_style atomic\nregion box block 0 5 0 5 0 5 units box\ncreate_box 1 box\nmass 1 1.0\n"
                "create_atoms 1 random 20 31415 NULL")
    lammps = lammps_sim()
    lammps.command("create_atoms 1 random 20 31415 NULL")
    assert sim.dialect.name == "pdps" and len(sim.x) == len(lammps.x) == 20
    assert not np.allclose(np.sort(sim.x, axis=0), np.sort(lammps.x, axis=0))


def test_seed_and_position_decide_a_random_displacement():
    # LAMMPS's numbers are seeded from each particle's position: two particles at the same place move
    # alike, whatever their ids and storage order
    sim = lammps_sim()
    sim.command("create_atoms 1 single 1 1 1\ncreate_atoms 1 single 3 3 3\ncreate_atoms 1 single 1 1 1\n"
                "displace_atoms all random 0.4 0.4 0.4 5 units box")
    order = np.argsort(sim.tag)
    x = sim.x[order]
    np.testing.assert_array_equal(x[0], x[2])
    assert np.all(np.abs(x[0] - 1.0) <= 0.4) and np.all(np.abs(x[1] - 3.0) <= 0.4)
    assert not np.allclose(x[0] - 1.0, x[1] - 3.0)


def test_remap_counts_each_box_length_crossed():
    sim = lammps_sim()
    sim.command("create_atoms 1 single 1 1 1 units box\ndisplace_atoms all move 12.5 -7.25 0 units box")
    np.testing.assert_allclose(sim.x[0], [3.5, 3.75, 1.0], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(sim.particles.image[0], [2, -2, 0])


@pytest.mark.parametrize("line, message", [
    ("create_atoms 1 random 10 7 far", "region far does not overlap the box (LAMMPS: no overlap of box and region)"),
    ("create_atoms 1 random 10 2147483647 NULL", "seed must be <= 2147483646 (got 2147483647)"),
    ("create_atoms 1 random 100 7 NULL overlap 4.5 maxtry 1000000 units box",
     "create_atoms: random: 0 of 100 particles placed after 20000000 tries (maxtry 1000000 each); ask for fewer "
     "particles, a smaller overlap or a smaller maxtry"),
    ("displace_atoms all random 0.1 0.1 0.1 2147483648", "seed must be <= 2147483647 (got 2147483648)"),
])
def test_bad_random_input_is_one_line(line, message):
    sim = lammps_sim()
    sim.command("region far sphere 20 20 20 1 units box\ncreate_atoms 1 single 1 1 1")
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert str(error.value).endswith(message)


@pytest.mark.parametrize("line, message", [
    ("displace_atoms all random 0.3 0.3 0.3 555", "a 2-d system's particles cannot be displaced in z (dz = 0.3)"),
    ("displace_atoms all ramp z 0 1 x 0 4", "a 2-d system's particles cannot be displaced in z (ramp z)"),
])
def test_a_2d_system_is_not_displaced_in_z(line, message):
    # LAMMPS: "Must not displace atoms in z-direction with 2d system"; with dz 0 it moves them (as in the
    # disk_2d scene)
    sim = Simulation(dialect="lammps", screen=False, log=None)
    sim.command("units lj\ndimension 2\natom_style atomic\nlattice sq 0.8\nregion box block 0 4 0 4 -0.5 0.5\n"
                "create_box 1 box\ncreate_atoms 1 box\nmass 1 1.0")
    before = sim.x.copy()
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert str(error.value).endswith(message)
    assert np.array_equal(sim.x, before)
    sim.command("displace_atoms all random 0.3 0.3 0 555")
    assert np.all(sim.x[:, 2] == 0.0) and not np.array_equal(sim.x, before)


def test_overlap_extremes():
    # a vanishing overlap rejects nothing: the tries of no overlap; an overlap wider than the box keeps the
    # first particle only, and says so as LAMMPS does
    plain, tiny, huge = lammps_sim(), lammps_sim(), lammps_sim()
    plain.command("create_atoms 1 random 50 7 NULL")
    tiny.command("create_atoms 1 random 50 7 NULL overlap 1e-300")
    huge.command("create_atoms 1 random 50 7 NULL overlap 1e300 maxtry 20")
    np.testing.assert_array_equal(tiny.x, plain.x)
    np.testing.assert_array_equal(huge.x, plain.x[:1])
    assert huge.warnings == ["Only inserted 1 particles out of 50"]
