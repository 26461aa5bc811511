"""Molecule ids (the molecular, bond, angle and full particle styles): read_data's molecule and charge
columns, group molecule, set mol, delete_atoms mol yes, neigh_modify exclude molecule/intra and
molecule/inter, the mol and q columns of dump custom and of formulas, write_data.

The LAMMPS comparison runs the script of benchmarks/lammps_references/molecules.py: its thermo table
over 100 NVE steps equals LAMMPS's printed 15 digits (tests/data/lammps/molecules.txt), and its data
file LAMMPS's (tests/data/lammps/molecules.data)."""

import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import thermo_rows

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "lammps"
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from molecules import SCRIPT  # noqa: E402


def atoms(path):
    """The rows of a data file's Atoms section (id, molecule, type, x, y, z, ix, iy, iz), by id."""
    section = Path(path).read_text().split("Atoms", 1)[1].split("Velocities", 1)[0]
    rows = [line.split() for line in section.splitlines()[1:] if line.strip()]
    table = np.array([[float(v) for v in row] for row in rows])
    return table[np.argsort(table[:, 0])]


def lj(r):
    return 4.0 * (r ** -12 - r ** -6)


@pytest.fixture(scope="module")
def lammps_script_run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("molecules")
    (folder / "in.molecules").write_text(SCRIPT)
    log = folder / "log.pdps"
    sim = Simulation(screen=False, log=str(log))
    sim.script.directory = str(folder)
    sim.file(str(folder / "in.molecules"))
    sim.close()
    return folder, log.read_text()


def test_the_molecule_script_prints_lammps_thermo(lammps_script_run):
    _, log = lammps_script_run
    mine, lammps = np.array(thermo_rows(log)), np.array(thermo_rows((DATA / "molecules.txt").read_text()))
    assert mine.shape == lammps.shape == (11, 7)
    np.testing.assert_array_equal(mine[:, :2], lammps[:, :2])             # steps, 252 atoms
    np.testing.assert_allclose(mine[:, 2:], lammps[:, 2:], rtol=1e-12, atol=1e-13)


def test_the_molecule_script_writes_lammps_data_file(lammps_script_run):
    folder, _ = lammps_script_run
    mine, lammps = atoms(folder / "out.data"), atoms(DATA / "molecules.data")
    assert len(mine) == len(lammps) == 252
    # id, molecule, type; molecule 43 (ids 169-172, one of them inside the ball) deleted whole
    np.testing.assert_array_equal(mine[:, :3], lammps[:, :3])
    np.testing.assert_array_equal(np.setdiff1d(np.arange(1, 257), mine[:, 0]), [169, 170, 171, 172])
    # unwrapped: LAMMPS writes positions as they are between neighbor list builds, pdps wraps them
    length = 4 * (4 / 0.8442) ** (1 / 3)
    np.testing.assert_allclose(mine[:, 3:6] + length * mine[:, 6:9], lammps[:, 3:6] + length * lammps[:, 6:9],
                               rtol=0, atol=1e-10)


DIMER = """LAMMPS data file: two molecules of two particles

4 atoms
1 atom types
2 bonds
1 bond types
1 extra bond per atom

0 6 xlo xhi
0 6 ylo yhi
0 6 zlo zhi

Masses

1 1.0

Atoms # full

1 7 1 0.5 2.0 2.0 2.0
2 7 1 -0.5 3.1 2.0 2.0
3 8 1 0.25 2.0 3.2 2.0 0 0 0
4 8 1 -0.25 3.1 3.2 2.0 0 0 0

Bond Coeffs

1 100.0 1.1

Bonds

1 1 1 2
2 1 3 4
"""
# pair distances: 1-2 and 3-4 = 1.1 (inside molecules); 1-3 and 2-4 = 1.2; 1-4 and 2-3 = hypot(1.1, 1.2)
INTRA, INTER = 2 * lj(1.1), 2 * lj(1.2) + 2 * lj(math.hypot(1.1, 1.2))


def dimers(tmp_path, style="full", data=DIMER):
    (tmp_path / "dimers.data").write_text(data)
    sim = Simulation(screen=False, log=None)
    # the bonds (at their rest length: no bond energy) leave the pairs in, as special_bonds 1 1 1 says
    sim.command(f"atom_style {style}\nbond_style harmonic\nread_data {tmp_path / 'dimers.data'}\n"
                "special_bonds lj/coul 1.0 1.0 1.0\npair_style lj/cut 2.5\npair_coeff * * 1.0 1.0\n"
                "thermo_style custom step pe\nthermo_modify norm no")
    return sim


def pe(sim, exclusions=""):
    sim.command(f"neigh_modify exclude none {exclusions}\nrun 0")
    return sim.variables.evaluate("pe")


def test_read_data_full_style_reads_molecules_charges_and_bonds(tmp_path):
    sim = dimers(tmp_path)
    order = np.argsort(sim.tag)
    np.testing.assert_array_equal(sim.particles.molecule[:4][order], [7, 7, 8, 8])
    np.testing.assert_array_equal(sim.particles.q[:4][order], [0.5, -0.5, 0.25, -0.25])
    assert sim.warnings == []
    assert sorted(zip(sim.tag.tolist(), sim.particles.num_bond[:4].tolist())) == [(1, 1), (2, 0), (3, 1), (4, 0)]


def test_exclude_molecule_intra_and_inter(tmp_path):
    sim = dimers(tmp_path)
    assert pe(sim) == pytest.approx(INTRA + INTER, rel=1e-12)
    assert pe(sim, "exclude molecule/intra all") == pytest.approx(INTER, rel=1e-12)
    assert pe(sim, "exclude molecule/inter all") == pytest.approx(INTRA, rel=1e-12)
    # only pairs with both particles in the group: particle 1 alone in it leaves everything
    sim.command("group one id 1")
    assert pe(sim, "exclude molecule/intra one") == pytest.approx(INTRA + INTER, rel=1e-12)
    sim.command("group first molecule 7")
    assert pe(sim, "exclude molecule/intra first") == pytest.approx(lj(1.1) + INTER, rel=1e-12)


def test_group_set_delete_and_formulas_read_molecule_ids(tmp_path):
    sim = dimers(tmp_path)
    sim.command("group m8 molecule 8\nset group m8 mol 3\ngroup m3 molecule <> 1 3")
    assert sim.variables.evaluate("count(m8)") == 2 and sim.variables.evaluate("count(m3)") == 2
    sim.command("variable m atom mol*10+q\nvariable total equal mol[1]+mol[3]+q[2]")
    assert sim.variables.evaluate("v_total") == pytest.approx(7 + 3 - 0.5)
    sim.command("set atom 2 charge 2.5\ngroup one id 1\ndelete_atoms group one mol yes compress no")
    assert sim.particles.nlocal == 2
    np.testing.assert_array_equal(np.sort(sim.tag), [3, 4])


def test_delete_atoms_mol_yes_leaves_particles_of_molecule_zero(tmp_path):
    sim = dimers(tmp_path, data=DIMER.replace("1 7 1 0.5", "1 0 1 0.5").replace("2 7 1", "2 0 1"))
    sim.command("group one id 1\ndelete_atoms group one mol yes compress no")
    np.testing.assert_array_equal(np.sort(sim.tag), [2, 3, 4])


def test_write_data_and_dump_carry_molecules(tmp_path):
    sim = dimers(tmp_path)
    sim.command(f"write_data {tmp_path / 'again.data'}\n"
                f"dump d all custom 1 {tmp_path / 'd.txt'} id mol q\nrun 0")
    again = dimers(tmp_path, data=(tmp_path / "again.data").read_text())
    np.testing.assert_array_equal(again.particles.molecule[:4], sim.particles.molecule[:4])
    np.testing.assert_array_equal(again.particles.q[:4], sim.particles.q[:4])
    rows = np.loadtxt(tmp_path / "d.txt", skiprows=9)
    rows = rows[np.argsort(rows[:, 0])]
    np.testing.assert_array_equal(rows, [[1, 7, 0.5], [2, 7, -0.5], [3, 8, 0.25], [4, 8, -0.25]])


def test_restart_keeps_molecule_ids(tmp_path):
    # without the bonds: restart files refuse them (plugins/bond_basic/tests/test_bonds.py)
    unbonded = DIMER.replace("2 bonds\n1 bond types\n1 extra bond per atom\n", "").split("\nBond Coeffs")[0] + "\n"
    sim = dimers(tmp_path, data=unbonded)
    sim.command(f"write_restart {tmp_path / 'r.pdps'}")
    again = Simulation(screen=False, log=None)
    again.command(f"read_restart {tmp_path / 'r.pdps'}")
    assert again.particle_style == "full"
    np.testing.assert_array_equal(again.particles.molecule[:4], sim.particles.molecule[:4])


@pytest.mark.parametrize("style, line, message", [
    ("atomic", "neigh_modify exclude molecule/intra all",
     "exclude molecule/intra needs molecule ids (particle_style molecular, bond, angle or full; this is atomic)"),
    ("molecular", "neigh_modify exclude molecule/inter", "exclude molecule/inter needs a group; usage: "
     "neigh_modify [every N] [delay N] [check yes|no] [once yes|no] [one N] [exclude type I J | group G1 G2 | molecule/intra G | "
     "molecule/inter G | none]"),
    ("sphere", "group g molecule 1", "group molecule needs molecule ids (particle_style molecular, bond, angle or "
                                     "full; this is sphere)"),
    ("atomic", "set mol 1 type 1", "set mol needs molecule ids (particle_style molecular, bond, angle or full; "
                                   "this is atomic)"),
    ("molecular", "set atom 1 charge 1", "set charge needs charges (particle_style charge or full; this is "
                                         "molecular)"),
    ("molecular", "set atom * mol -1", "molecule id must be >= 0 (got -1)"),
    ("atomic", "delete_atoms group all mol yes", "delete_atoms mol yes needs molecule ids (particle_style "
                                                 "molecular, bond, angle or full; this is atomic)"),
    ("charge", "dump d all custom 1 d.txt id mol", "dump column mol needs per-particle molecule (particle_style "
                                                   "molecular, bond, angle or full)"),
])
def test_molecule_errors(style, line, message):
    sim = Simulation(screen=False, log=None)
    sim.command(f"particle_style {style}\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\n"
                "create_particle 1 single 1 1 1")
    with pytest.raises(ScriptError, match=": " + re.escape(message) + "$"):
        sim.command(line)


@pytest.mark.parametrize("style, old, new, message", [
    ("atomic", "Atoms # full", "Atoms", "dimers.data:5: 2 bonds need a particle_style with molecule ids "
                                        "(molecular, bond, angle or full), not atomic"),
    ("full", "1 7 1 0.5", "1 -7 1 0.5", "dimers.data:19: molecule id must be from 0 to 4611686018427387904 (got -7)"),
    ("full", "2 7 1 -0.5", "2 7 1 nan", "dimers.data:20: charge must be finite (got nan)"),
    ("full", "2 7 1 -0.5 3.1", "2 7 1 3.1", "dimers.data:20: expected 7 or 10 values per full atom (got 6)"),
    ("molecular", "Atoms # full", "Atoms", "dimers.data:19: expected 6 or 9 values per molecular atom (got 7)"),
    ("full", "1 7 1 0.5", "1 9223372036854775808 1 0.5",
     "dimers.data:19: molecule id must be from 0 to 4611686018427387904 (got 9223372036854775808)"),
    # a header line of one word (the fuzz suite's: "6\f atoms" splits at the form feed)
    ("full", "4 atoms", "4\f atoms", "dimers.data:3: unrecognised header line: 4"),
])
def test_data_file_errors(tmp_path, style, old, new, message):
    (tmp_path / "dimers.data").write_text(DIMER.replace(old, new, 1))
    sim = Simulation(screen=False, log=None)
    sim.command(f"particle_style {style}")
    with pytest.raises(ScriptError, match=re.escape(message) + "$"):
        sim.command(f"read_data {tmp_path / 'dimers.data'}")
