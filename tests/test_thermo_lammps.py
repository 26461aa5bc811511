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


# LAMMPS's default thermo line is its thermo_style one, step temp epair emol etotal press, with
# Volume added where the box changes in a run (a fix deform here, a shrink-wrapped face below; its
# Thermo::init). LAMMPS 22 Jul 2025 on these scripts, the header and rows it printed.
DEFAULT_LINE = """units lj
{boundary}atom_style atomic
lattice fcc 0.8
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
mass 1 1
velocity all create 1.0 87287
pair_style lj/cut 2.5
pair_coeff * * 1 1
fix 1 all nve
thermo 5
run 10
{deform}run 10
"""
HEADER = ["Step", "Temp", "E_pair", "E_mol", "TotEng", "Press"]
DEFAULT_LINE_LAMMPS = {
    "deform": ("", "fix 2 all deform 1 x scale 1.1\n", [
        (HEADER, [[0, 1, -6.3647465, 0, -4.8786354, -5.416374]]),
        (HEADER + ["Volume"], [[10, 0.86577011, -6.1540052, 0, -4.8673747, -4.200268, 135]])]),
    "shrink-wrapped": ("boundary p p s\n", "", [
        (HEADER + ["Volume"], [[0, 1, -5.693671, 0, -4.2055757, -5.5070233, 135.027],
                               [5, 0.98516499, -5.6712539, 0, -4.2052346, -5.1904164, 135.027],
                               [10, 0.89401696, -5.5279222, 0, -4.1975398, -4.0989061, 135.027]]),
        (HEADER + ["Volume"], [[10, 0.89401696, -5.5279222, 0, -4.1975398, -3.9918452, 138.64841],
                               [15, 0.67382459, -5.1948582, 0, -4.192143, -2.062795, 138.64841]])]),
}


def _blocks(log):
    """[(header, {step: row})] of each run, as the log shows them."""
    blocks = []
    for line in log.read_text().splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            blocks.append((words, {}))
        elif blocks and blocks[-1][0] and len(words) == len(blocks[-1][0]) and words[0].isdigit():
            blocks[-1][1].setdefault(int(words[0]), [float(w) for w in words])
        elif line.startswith("Loop time"):
            blocks.append((None, {}))
    return [block for block in blocks if block[0]]


@pytest.mark.parametrize("case", list(DEFAULT_LINE_LAMMPS))
def test_default_thermo_line_is_lammps_thermo_style_one(tmp_path, case):
    boundary, deform, want = DEFAULT_LINE_LAMMPS[case]
    sim = Simulation(screen=False, log=str(tmp_path / "log.lammps"), dialect="lammps")
    sim.command(DEFAULT_LINE.format(boundary=boundary, deform=deform))
    sim.close()
    printed = _blocks(tmp_path / "log.lammps")
    assert len(printed) == 2
    for (header, rows), (got_header, got_rows) in zip(want, printed):
        assert got_header == header
        for row in rows:
            assert got_rows[row[0]] == pytest.approx(row, rel=2e-8, abs=1e-12), (case, row[0])


def test_pdps_dialect_keeps_its_default_line(tmp_path):
    one_run = DEFAULT_LINE.format(boundary="", deform="").replace("run 10\nrun 10", "run 0")
    for log, script, header in (("log.pdps", one_run, ["Step", "Temp", "PotEng", "KinEng", "TotEng", "Press"]),
                                ("log.one", one_run.replace("thermo 5", "thermo_style one"), HEADER)):
        sim = Simulation(screen=False, log=str(tmp_path / log), dialect="pdps")
        sim.command(script)
        sim.close()
        assert _blocks(tmp_path / log)[0][0] == header
