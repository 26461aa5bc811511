"""Fixes temp/rescale, temp/berendsen, momentum, print, addforce (a variable component), setforce
(NULL), viscous (scale) and gravity give LAMMPS's thermo (and printed lines) on a 200-particle
Lennard-Jones fluid (data/fixes.txt, recorded with LAMMPS by
benchmarks/lammps_references/fixes.py); enforce2d keeps a 2-d run in its plane.

The thermo against LAMMPS's (with 2 ranks and restarts for the cases marked so) is checked by
tests/test_recorded_thermo.py from data/fixes.cases.json; this file holds the rest."""

import io
import shutil
import sys
from pathlib import Path

import pytest

from pdps_core.api import Simulation
from pdps_core.testing import script_error, total_momentum

DATA = Path(__file__).parent / "data"
ROWS = [line.split("\t") for line in (DATA / "fixes.txt").read_text().splitlines()]
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from fixes import CASES, SETUP  # noqa: E402


def run_case(tmp_path, monkeypatch, case):
    shutil.copy(DATA / "fluid.data", tmp_path / "fluid.data")
    monkeypatch.chdir(tmp_path)
    screen = io.StringIO()
    sim = Simulation(screen=screen, log="log.case", dialect="lammps")
    sim.command("\n".join(SETUP + [CASES[case], "thermo 25", "thermo_style custom step temp pe press", "run 100"]))
    sim.close()
    rows = [line.split(",") for line in (tmp_path / "log.case.csv").read_text().splitlines()[1:]]
    return sim, rows, screen.getvalue()


def test_fix_print_prints_the_lines_lammps_prints(tmp_path, monkeypatch):
    """(the thermo of every case is tests/test_recorded_thermo.py's, from data/fixes.cases.json)"""
    _, _, screen = run_case(tmp_path, monkeypatch, "print")
    printed = [line.split()[1:] for line in screen.splitlines() if line.startswith("PRINTED")]
    assert printed == [row[2:] for row in ROWS if row[0] == "print" and row[1] == "print"]
    assert len(printed) == 5


def test_momentum_zeroes_the_flagged_components(tmp_path, monkeypatch):
    sim, _, _ = run_case(tmp_path, monkeypatch, "momentum")
    assert sim.step == 100
    p = total_momentum(sim)
    assert abs(p[0]) < 1e-11 and abs(p[1]) < 1e-11 and abs(p[2]) > 1e-3    # linear 1 1 0


def test_enforce2d_keeps_particles_in_the_plane():
    sim = Simulation(screen=False, log=None)
    sim.command("dimension 2\nlattice sq 0.7\nregion box block 0 5 0 5 -0.5 0.5 units lattice\ncreate_box 1 box\nmass 1 1\n"
                "create_atoms 1 box\nvelocity all set 0.3 -0.2 0.0\n"
                "pair_style lj/cut 2.5\npair_coeff * * 1 1\nfix 1 all nve\nfix 2 all enforce2d\nrun 50")
    assert not sim.x[:, 2].any() and not sim.v[:, 2].any() and not sim.f[:, 2].any()


@pytest.mark.parametrize("line, message", [
    ("fix 2 all momentum 10", "fix momentum needs linear and/or angular"),
    ("fix 2 all momentum 10 linear 1 2 0", "linear must be one of '0' or '1' (got 2)"),
    ("fix 2 all temp/rescale 10 1 1 0.1 1.5", "fraction must be <= 1 (got 1.5)"),
    ("fix 2 all temp/berendsen 1 1 0", "damp must be > 0 (got 0)"),
    ("fix 2 all enforce2d", "fix enforce2d needs a 2-d simulation (dimension 2)"),
    ('fix 2 all print 10 "x" colour red', "unknown keyword colour (known: file, append, screen, title)"),
])
def test_bad_fixes(line, message):
    assert script_error("region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1", line).message == message
