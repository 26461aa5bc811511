"""lj/cut with ``pair_modify tail yes`` gives LAMMPS's thermo (pe and press with the long-range
corrections) step for step on a 200-particle two-type fluid (data/tail.txt, recorded with LAMMPS by
benchmarks/lammps_references/pair_tail.py); the corrections are the formula's.

The thermo against LAMMPS's (with 2 ranks and restarts for the cases marked so) is checked by
tests/test_recorded_thermo.py from data/tail.cases.json; this file holds the rest."""

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation, observables
from pdps_core.testing import build

DATA = Path(__file__).parent / "data"
CASES = {
    "tail": "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.2 2.0\npair_modify tail yes",
    "tail_arithmetic": "pair_style lj/cut 2.2\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.2\n"
                       "pair_coeff 1 2 0.8 1.05 2.6\npair_modify mix arithmetic tail yes",
}


def test_the_corrections_are_the_formula(tmp_path):
    """Two particles 4.5 apart in a periodic 10^3 box, cutoff 2.5: no pair inside, so pe and the virial are the
    tail terms alone, 8 pi N^2 eps sig^6 (sig^6 - 3 rc^6) / (9 rc^9 V) and 3 times 16 pi N^2 ..."""
    sim = build(tmp_path, [[1.0, 1.0, 1.0], [5.5, 1.0, 1.0]],
                setup="pair_style lj/cut 2.5\npair_coeff * * 1.5 1.1\npair_modify tail yes\nrun 0")
    eps, sig, rc, n, volume = 1.5, 1.1, 2.5, 2.0, 1000.0
    etail = 8 * math.pi * n * n * eps * sig ** 6 * (sig ** 6 - 3 * rc ** 6) / (9 * rc ** 9) / volume
    ptail = 16 * math.pi * n * n * eps * sig ** 6 * (2 * sig ** 6 - 3 * rc ** 6) / (9 * rc ** 9) / volume
    assert observables.potential_energy(sim) == pytest.approx(etail, rel=1e-13)
    assert observables.virial_trace(sim) == pytest.approx(3 * ptail, rel=1e-13)


def test_shift_and_tail_together_are_refused(tmp_path):
    with pytest.raises(ScriptError, match="pair_modify shift yes and tail yes cannot both be set"):
        build(tmp_path, [[1.0, 1.0, 1.0]], setup="pair_style lj/cut 2.5\npair_coeff * * 1 1\n"
                                                   "pair_modify shift yes tail yes\nrun 0")


def test_a_style_without_a_tail_correction_refuses_it():
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 5 0 5 0 5\ncreate_box 1 box\npair_style dpd 1.0 1.0 1")
    with pytest.raises(ScriptError, match="pair style dpd has no tail correction"):
        sim.command("pair_modify tail yes")


def test_minimize_reports_lammps_energies_with_the_tail(tmp_path, monkeypatch):
    shutil.copy(DATA / "fluid.data", tmp_path / "fluid.data")
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log="log.min", dialect="lammps")
    sim.command(f"units lj\natom_style atomic\nread_data fluid.data\n{CASES['tail']}\nthermo 10\n"
                "minimize 1e-6 1e-8 60 1000")
    sim.close()
    lines = (tmp_path / "log.min").read_text().splitlines()
    mine = lines[next(k for k, line in enumerate(lines) if "Energy initial" in line) + 1].split()
    want = (DATA / "tail_minimize.txt").read_text().split()
    np.testing.assert_allclose([float(v) for v in mine], [float(v) for v in want], rtol=1e-10)
