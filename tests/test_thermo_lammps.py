"""LAMMPS's thermo keywords in pdps give LAMMPS's values on a short Lennard-Jones run in lj units (with and
without thermo_modify norm) and in metal units (tests/data/lammps/thermo.txt, recorded with LAMMPS by
benchmarks/lammps_references/thermo.py)."""

import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from thermo import CASES, KEYWORDS, script  # noqa: E402

ROWS = [line.split("\t") for line in (ROOT / "tests" / "data" / "lammps" / "thermo.txt").read_text().splitlines()]


@pytest.mark.parametrize("case", list(CASES))
def test_thermo_keywords_as_lammps_prints_them(tmp_path, monkeypatch, case):
    shutil.copy(ROOT / "plugins" / "pair_simple" / "tests" / "data" / "fluid.data", tmp_path / "fluid.data")
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log="log.thermo", dialect="lammps")
    sim.command(script(case))
    sim.close()
    mine = [[float(v) for v in line.split(",")] for line in (tmp_path / "log.thermo.csv").read_text().splitlines()[1:]]
    reference = [[float(v) for v in row[1:]] for row in ROWS if row[0] == case]
    assert len(mine) == len(reference) == 3
    names = KEYWORDS.split()
    for got, want in zip(mine, reference):
        for name, a, b in zip(names, got, want):
            assert a == pytest.approx(b, rel=1e-9, abs=1e-12), (case, int(got[0]), name)
