"""Bonds: bond_style harmonic against its formula and the gradient of its energy, compute bond/local
against LAMMPS's rows (data/bond_local.txt, recorded by benchmarks/lammps_references/bonds.py), and
the refusals. The thermo of bonded chains against LAMMPS's (harmonic, hybrid, none, special_bonds,
delete_bonds; 2 ranks for some) is checked by tests/test_recorded_thermo.py from data/bonds.cases.json."""

import math
import re
import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation, SimulationError
from pdps_core.testing import assert_force_is_minus_gradient

DATA = Path(__file__).parent / "data"

TRIMER = """three beads, two bonds

3 atoms
1 atom types
2 bonds
2 bond types

0 10 xlo xhi
0 10 ylo yhi
0 10 zlo zhi

Masses

1 1.0

Atoms # bond

1 1 1 5.0 5.0 5.0
2 1 1 6.3 5.2 4.9
3 1 1 9.8 5.5 5.1

Bonds

1 1 1 2
2 2 2 3
"""


def trimer(tmp_path, lines, data=TRIMER):
    """The trimer under a pair style of no force (its neighbor list makes the ghosts bonds need) and ``lines``."""
    (tmp_path / "trimer.data").write_text(data)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"atom_style bond\nread_data {tmp_path / 'trimer.data'}\npair_style zero 4.0\npair_coeff * *\n"
                f"{lines}\nthermo_style custom step pe ebond\nthermo_modify norm no")
    return sim


def test_harmonic_energy_and_forces_are_its_formula(tmp_path):
    sim = trimer(tmp_path, "bond_style harmonic\nbond_coeff 1 30.0 1.0\nbond_coeff 2 5.0 3.0\nrun 0")
    x = {int(t): sim.particles.x[k] for k, t in enumerate(sim.tag)}
    r12, r23 = np.linalg.norm(x[1] - x[2]), np.linalg.norm(x[2] - x[3])
    expected = 30.0 * (r12 - 1.0) ** 2 + 5.0 * (r23 - 3.0) ** 2
    assert sim.variables.evaluate("ebond") == pytest.approx(expected, rel=1e-13)
    assert sim.variables.evaluate("pe") == pytest.approx(expected, rel=1e-13)
    f1 = sim.f[list(sim.tag).index(1)]
    np.testing.assert_allclose(f1, -2 * 30.0 * (r12 - 1.0) * (x[1] - x[2]) / r12, rtol=1e-13)
    assert_force_is_minus_gradient(sim, rel=1e-6, abs=1e-7, largest=1.0)


def test_hybrid_none_type_has_no_force(tmp_path):
    # LAMMPS 22 Jul 2025 stops on bond_coeff N none under hybrid ("Invoked bond equil distance on
    # bond style none", measured); the manual's meaning: type 2 bonds are not computed
    sim = trimer(tmp_path, "bond_style hybrid harmonic\nbond_coeff 1 harmonic 30.0 1.0\nbond_coeff 2 none\nrun 0")
    x = {int(t): sim.particles.x[k] for k, t in enumerate(sim.tag)}
    r12 = np.linalg.norm(x[1] - x[2])
    assert sim.variables.evaluate("ebond") == pytest.approx(30.0 * (r12 - 1.0) ** 2, rel=1e-13)
    np.testing.assert_allclose(sim.f[list(sim.tag).index(3)], 0.0, atol=0)


def test_bonded_pairs_leave_the_pair_style_by_default(tmp_path):
    # special_bonds lj/coul 0 0 0 (LAMMPS's default): beads 1-2 and 2-3 feel no soft repulsion
    lines = "pair_style soft 4.0\npair_coeff * * 2.0\nbond_style harmonic\nbond_coeff * 0.0 1.0\n"
    sim = trimer(tmp_path, lines + "run 0")
    assert sim.variables.evaluate("pe") == 0.0
    sim.command("special_bonds lj/coul 1.0 1.0 1.0\nrun 0")
    x = {int(t): sim.particles.x[k] for k, t in enumerate(sim.tag)}
    soft = sum(2.0 * (1 + math.cos(math.pi * np.linalg.norm(x[a] - x[b]) / 4.0)) for a, b in ((1, 2), (2, 3), (1, 3))
               if np.linalg.norm(x[a] - x[b]) < 4.0)
    assert sim.variables.evaluate("pe") == pytest.approx(soft, rel=1e-12)


def _blocks(path):
    out = []
    for block in Path(path).read_text().split("ITEM: TIMESTEP\n")[1:]:
        lines = block.splitlines()
        start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ENTRIES")) + 1
        rows = np.array([[float(w) for w in line.split()] for line in lines[start:]])
        rows[np.abs(rows) < 1e-300] = 0.0        # LAMMPS's uninitialised values of turned-off bonds
        out.append(rows[np.lexsort((rows[:, 4], rows[:, 1]))][:, 1:])
    return out


def test_bond_local_gives_lammps_rows(tmp_path):
    shutil.copy(DATA / "chains.data", tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"units lj\natom_style bond\nread_data {tmp_path / 'chains.data'}\npair_style soft 2.5\n"
                "pair_coeff * * 5.0\nbond_style harmonic\nbond_coeff 1 100.0 1.0\nbond_coeff 2 80.0 0.95\n"
                "delete_bonds all bond 2\ncompute b all bond/local dist engpot force dx fx\n"
                f"dump d all local 100 {tmp_path / 'bonds.txt'} index c_b[1] c_b[2] c_b[3] c_b[4] c_b[5]\n"
                "fix 1 all nve\ntimestep 0.002\nrun 200")
    sim.close()
    mine, lammps = _blocks(tmp_path / "bonds.txt"), _blocks(DATA / "bond_local.txt")
    assert len(mine) == len(lammps) == 3
    for ours, theirs in zip(mine, lammps):
        assert ours.shape == theirs.shape == (140, 5)
        np.testing.assert_allclose(ours, theirs, rtol=1e-11, atol=1e-12)
        assert (ours[:, 1] == 0).sum() == 80          # the 80 type-2 bonds turned off: no energy


@pytest.mark.parametrize("lines, message", [
    ("bond_coeff 1 1.0 1.0", "bond_coeff before bond_style"),
    ("special_bonds lj 0.0 0.5 1.0", "special_bonds lj: weight 0.5 between 0 and 1 is not supported: pdps's pair "
                                     "styles do not scale the forces of special pairs (give 0.0, left out, or 1.0)"),
    ("special_bonds angle yes", "special_bonds angle yes counts 1-3 neighbors by angles, and pdps has no angle styles"),
    ("bond_style harmonic\nbond_coeff 3 1.0 1.0", "bond type 3 is out of range 1..2"),
    ("bond_style harmonic\nbond_coeff 1 1.0 1.0\nrun 0", "bond coefficients are not set for bond type 2 (bond_coeff 2 ...)"),
    ("bond_style hybrid harmonic\nbond_coeff 1 fene 1 1", "bond_coeff 1: fene is not a sub-style of bond_style hybrid "
                                                          "(harmonic or none)"),
    ("delete_bonds all angle 1", "unknown delete_bonds style angle (multi, atom, bond, stats) (pdps has no angles, "
                                 "dihedrals or impropers)"),
    ("delete_bonds all multi keep", "unknown delete_bonds keyword keep (any, undo, remove, special)"),
])
def test_refusals(tmp_path, lines, message):
    sim = trimer(tmp_path, "")
    with pytest.raises(ScriptError, match=re.escape(message) + "$"):
        sim.command(lines)


def test_bonds_without_a_neighbor_list_are_refused(tmp_path):
    (tmp_path / "trimer.data").write_text(TRIMER)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"atom_style bond\nread_data {tmp_path / 'trimer.data'}\nbond_style harmonic\nbond_coeff * 1 1")
    with pytest.raises(ScriptError, match="no neighbor list makes ghosts here: define a pair style"):
        sim.command("run 0")


def test_bonds_in_an_atomic_data_file_are_refused(tmp_path):
    (tmp_path / "trimer.data").write_text(TRIMER.replace("Atoms # bond", "Atoms # atomic").replace("1 1 1 5.0", "1 1 5.0")
                                          .replace("2 1 1 6.3", "2 1 6.3").replace("3 1 1 9.8", "3 1 9.8"))
    sim = Simulation(screen=False, log=None, dialect="lammps")
    with pytest.raises(ScriptError, match="2 bonds need a particle_style with molecule ids"):
        sim.command(f"atom_style atomic\nread_data {tmp_path / 'trimer.data'}")


def test_write_data_keeps_the_bonds_and_restart_files_refuse_them(tmp_path):
    shutil.copy(DATA / "chains.data", tmp_path)
    script = (f"units lj\natom_style bond\nread_data {tmp_path / 'chains.data'}\npair_style soft 2.5\n"
              "pair_coeff * * 5.0\nbond_style harmonic\nbond_coeff 1 100.0 1.0\nbond_coeff 2 80.0 0.95\n"
              "thermo_style custom step pe ebond\nthermo_modify norm no\n")
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(script + f"delete_bonds all bond 2\nrun 0\nwrite_data {tmp_path / 'out.data'}")
    energy = (sim.variables.evaluate("pe"), sim.variables.evaluate("ebond"))
    again = Simulation(screen=False, log=None, dialect="lammps")
    again.command(script.replace(str(tmp_path / "chains.data"), str(tmp_path / "out.data")) + "run 0")
    assert (again.variables.evaluate("pe"), again.variables.evaluate("ebond")) == pytest.approx(energy, rel=1e-14)
    assert int((again.particles.bond_type[:again.particles.nlocal] < 0).sum()) == 80
    with pytest.raises(ScriptError, match="restart files do not keep bonds yet"):
        again.command(f"write_restart {tmp_path / 'r.restart'}")


def test_a_deleted_partner_stops_the_run_with_lammps_message(tmp_path):
    sim = trimer(tmp_path, "bond_style harmonic\nbond_coeff * 1.0 1.0\ngroup last id 3\ndelete_atoms group last")
    with pytest.raises(SimulationError, match=re.escape("bond atoms 2 3 missing at step 0: the partner is out of "
                                                        "this rank's reach")):
        sim.command("run 0")
