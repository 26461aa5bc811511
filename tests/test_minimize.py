"""``minimize`` (LAMMPS's cg, sd and fire) on an overlapping Lennard-Jones start: the same start energy as
LAMMPS, and a final energy LAMMPS's own run reaches (tests/data/lammps/minimize.txt, recorded by
benchmarks/lammps_references/minimize.py)."""

import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

DATA = Path(__file__).parent / "data" / "lammps"
REFERENCE = {row.split("\t")[0]: row.split("\t")[1:] for row in (DATA / "minimize.txt").read_text().splitlines()
             if not row.startswith("#")}
MINIMIZE = (DATA / "minimize.txt").read_text().splitlines()[0].split(";")[0].lstrip("# ")


def minimized(tmp_path, monkeypatch, style, extra=""):
    shutil.copy(DATA / "min_start.data", tmp_path / "min_start.data")
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\natom_style atomic\nread_data min_start.data\nmass 1 1.0\npair_style lj/cut 2.5\n"
                "pair_coeff 1 1 1.0 1.0 2.5\nneighbor 0.3 bin\nneigh_modify every 1 delay 0 check yes\n"
                f"min_style {style}\nthermo 0\n{extra}{MINIMIZE}")
    return sim


@pytest.mark.parametrize("style", sorted(REFERENCE))
def test_minimize_reaches_the_energy_lammps_reaches(tmp_path, monkeypatch, style):
    initial, final, iterations, _, criterion = REFERENCE[style]
    sim = minimized(tmp_path, monkeypatch, style)
    result = sim.minimize_result
    assert result["initial"] == pytest.approx(float(initial), rel=1e-12)
    # a few hundred iterations of floating-point paths apart: the same basin, the same minimum
    assert result["final"] == pytest.approx(float(final), rel=1e-6), (result, final, iterations, criterion)
    assert result["final"] < result["initial"]
    assert sim.step == result["iterations"]


def test_cg_lowers_the_energy_every_iteration_and_ends_near_zero_force(tmp_path, monkeypatch):
    sim = minimized(tmp_path, monkeypatch, "cg")
    result = sim.minimize_result
    energies = np.array(result["energies"])
    assert len(energies) == result["iterations"] + 1
    assert np.all(np.diff(energies) <= 1e-12)                 # each line search only goes down
    assert result["fnorm"] / np.sqrt(sim.nlocal) < 1e-3       # per-atom force near zero at the end


@pytest.mark.parametrize("line, message", [
    ("minimize 1e-4 1e-6 100", "expected 4 argument(s), got 3; usage: minimize ETOL FTOL MAXITER MAXEVAL"),
    ("minimize -1 1e-6 100 1000", "etol must be >= 0 (got -1)"),
    ("minimize 0 0 0 1000", "maxiter must be >= 1 (got 0)"),
    ("min_style hftn", "min_style must be one of cg, sd, fire (got hftn)"),
    ("min_modify dmax 0", "dmax must be > 0 (got 0)"),
])
def test_minimize_errors(line, message):
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1")
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert caught.value.message == message
