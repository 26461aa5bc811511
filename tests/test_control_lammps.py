"""Groups, group functions, loops, index and format variables, if, run every/upto/start-stop and vector
variables print what LAMMPS prints (tests/data/lammps/control.txt, recorded with LAMMPS by
benchmarks/lammps_references/control.py)."""

import io
import sys
from pathlib import Path

from pdps_core.api import Simulation

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from control import SCRIPT  # noqa: E402


def test_the_script_prints_what_lammps_prints(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "in.control").write_text(SCRIPT)
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None)
    sim.file(str(tmp_path / "in.control"))
    mine = [line for line in screen.getvalue().splitlines() if line.startswith("@@ ")]
    assert mine == (ROOT / "tests" / "data" / "lammps" / "control.txt").read_text().splitlines()
