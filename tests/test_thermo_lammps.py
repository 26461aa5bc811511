"""LAMMPS's thermo keywords in pdps give LAMMPS's values on a short Lennard-Jones run in lj units (with and
without thermo_modify norm) and in metal units (tests/data/lammps/thermo.txt, recorded with LAMMPS by
benchmarks/lammps_references/thermo.py)."""

import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import lj_fcc

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


# An fcc LJ crystal whose lower layers start at rest: thermo_modify temp names a compute of the moving
# group only (LAMMPS's examples/crack does this). LAMMPS 22 Jul 2025 on this script, steps 0-100:
# temp, pe, ke, etotal, press. ke and the kinetic part of press use the compute's degrees of freedom;
# pdps counted every particle's (TotEng 0.15 % and Press 13 % off from step 0 in crack).
SUBSET_TEMP = lj_fcc(5) + """mass 1 1.0
region lowr block INF INF INF INF INF 1.5
group low region lowr
group mobile subtract all low
velocity mobile create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
neighbor 0.3 bin
compute new mobile temp
thermo_style custom step temp pe ke etotal press
thermo_modify temp new
thermo 25
fix 1 all nve
run 100
"""
SUBSET_TEMP_LAMMPS = [
    [0, 1.5, -6.7733681, 1.3455, -5.4278681, -5.4780699],
    [25, 0.67687492, -6.0871581, 0.60715681, -5.4800013, -1.9187217],
    [50, 0.64740505, -6.1246157, 0.58072233, -5.5438934, -1.9748741],
    [75, 0.66469407, -6.1739275, 0.59623058, -5.5776969, -1.8887276],
    [100, 0.57694965, -6.1091369, 0.51752384, -5.591613, -1.1848562],
]


def test_thermo_modify_temp_of_a_subset_sets_ke_and_press_as_lammps(pdps_cli):
    from pdps_core.testing import thermo_rows
    result = pdps_cli(SUBSET_TEMP, name="in.subset")
    assert result.returncode == 0, result.stderr
    rows = thermo_rows(result.stdout)
    assert len(rows) == len(SUBSET_TEMP_LAMMPS)
    for row, expected in zip(rows, SUBSET_TEMP_LAMMPS):
        assert row == pytest.approx(expected, rel=5e-8)
