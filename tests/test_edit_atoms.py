"""set, delete_atoms, displace_atoms and write_data as LAMMPS does them: the script of
benchmarks/lammps_references/edit_atoms.py, run by pdps, writes the data file LAMMPS wrote
(tests/data/lammps/edit_atoms.data): the same particles (ids after compress), types (set type/fraction
with LAMMPS's Park-Miller numbers), positions to 1e-12 and image flags."""

import re
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import script_error

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from edit_atoms import SCRIPT  # noqa: E402


def atoms(path):
    """(id, type, x, y, z, ix, iy, iz) rows of a data file's Atoms section, by id."""
    text = Path(path).read_text()
    section = re.split(r"\n(?=[A-Z][A-Za-z ]+(?:#.*)?\n)", text.split("Atoms", 1)[1], maxsplit=1)[0]
    rows = [line.split() for line in section.splitlines()[1:] if line.strip() and not line.startswith("#")]
    table = np.array([[float(v) for v in row[:8]] for row in rows])
    return table[np.argsort(table[:, 0])]


def test_the_edited_lattice_is_lammps_one(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None)
    (tmp_path / "in.edit").write_text(SCRIPT)
    sim.file(str(tmp_path / "in.edit"))
    mine, lammps = atoms(tmp_path / "out.data"), atoms(ROOT / "tests" / "data" / "lammps" / "edit_atoms.data")
    assert len(mine) == len(lammps) == 231
    np.testing.assert_array_equal(mine[:, :2], lammps[:, :2])           # ids 1..231 and types
    np.testing.assert_allclose(mine[:, 2:5], lammps[:, 2:5], rtol=0, atol=1e-12)
    np.testing.assert_array_equal(mine[:, 5:], lammps[:, 5:])


def test_write_data_reads_back(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None)
    sim.command("particle_style sphere\nregion box block 0 4 0 4 0 4\ncreate_box 2 box\n"
                "create_particle 1 single 1 1 1 diameter 0.5 density 2\ncreate_particle 2 single 3 1 1\n"
                "velocity all set 0.25 -1 0.5\nwrite_data sphere.data")
    again = Simulation(screen=False, log=None)
    again.command("particle_style sphere\nread_data sphere.data")
    np.testing.assert_array_equal(again.x, sim.x)
    np.testing.assert_array_equal(again.v, sim.v)
    np.testing.assert_allclose(again.particles.rmass[:2], sim.particles.rmass[:2], rtol=1e-15)
    np.testing.assert_allclose(again.particles.radius[:2], sim.particles.radius[:2], rtol=1e-15)


@pytest.mark.parametrize("order, mass", [
    # LAMMPS 22 Jul 2025 on this script prints these masses: set diameter keeps the mass, set density
    # sets it from the present diameter (1.2 x 4/3 pi 0.25^3 = 0.0785398)
    ("density 1.2\nset atom 1 diameter 0.5", 1.2 * 4.0 / 3.0 * np.pi * 0.5 ** 3),
    ("diameter 0.5\nset atom 1 density 1.2", 1.2 * 4.0 / 3.0 * np.pi * 0.25 ** 3),
])
def test_set_diameter_keeps_the_mass_as_lammps(order, mass):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("atom_style sphere\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\ncreate_atoms 1 single 1 1 1\n"
                f"set atom 1 {order}")
    assert sim.particles.radius[0] == 0.25
    assert sim.particles.rmass[0] == pytest.approx(mass, rel=1e-15)


@pytest.mark.parametrize("line, message", [
    ("set type 1 colour 2", "unknown set keyword colour (supported: type, type/fraction, x, y, z, vx, vy, vz, "
                            "mass, diameter, density, image, omega, omegax, omegay, omegaz, charge, mol, property/atom, "
                            "property/peratom)"),
    ("set type 1 type 3", "type must be <= 2 (got 3)"),
    ("set type 1 type/fraction 2 1.5 7", "fraction must be <= 1 (got 1.5)"),
    ("set atom 1 mass 2", "set mass needs per-particle masses (atom_style sphere)"),
    ("delete_atoms porosity box 0.5 7", "delete_atoms porosity is not supported (supported: group, region, overlap)"),
    ("delete_atoms group all compress maybe", "compress must be one of yes, no (got maybe)"),
    ("displace_atoms all move 1 0", "displace_atoms move needs 3 values; usage: displace_atoms G move DX DY DZ | "
                                    "ramp DDIM DLO DHI DIM CLO CHI | random DX DY DZ SEED | rotate PX PY PZ RX RY RZ "
                                    "THETA [units box|lattice]"),
    ("displace_atoms all rotate 0 0 0 0 0 0 30", "the rotation axis must not be zero"),
])
def test_edit_errors(line, message):
    one = "region box block 0 4 0 4 0 4\ncreate_box 2 box\nmass * 1\ncreate_particle 1 single 1 1 1"
    assert script_error(one, line).message == message
