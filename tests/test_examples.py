"""The example scripts run as shipped (shortened) and leave what their headers promise."""

import pathlib
import shutil
import subprocess
import sys

import numpy as np
import pytest

EXAMPLES = pathlib.Path(__file__).parents[1] / "examples"


def run_example(tmp_path, folder, script, steps):
    work = tmp_path / folder
    shutil.copytree(EXAMPLES / folder, work)
    text = (work / script).read_text()
    lines = [f"run {steps}" if line.startswith("run ") else line for line in text.splitlines()]
    (work / script).write_text("\n".join(lines) + "\n")
    result = subprocess.run([sys.executable, "-m", "pdps_core.cli", "run", script, "--no-progress"],
                            cwd=work, capture_output=True, text=True, timeout=900)
    assert result.returncode == 0, result.stderr
    return work, result


def test_analysis_example_writes_thermo_csv_rdf_density_profile_and_vtk_series(tmp_path):
    work, _ = run_example(tmp_path, "analysis", "analysis.in", 100)
    csv = np.genfromtxt(work / "log.pdps.csv", delimiter=",", names=True)
    assert list(csv["Step"]) == list(range(0, 101, 20))
    profile = np.loadtxt(work / "density_z.txt", skiprows=4)
    assert profile.shape == (20, 4)
    assert np.mean(profile[:, 3]) == pytest.approx(4.0, rel=1e-12)    # 4000 particles in 10^3
    rdf = np.loadtxt(work / "rdf.txt", skiprows=4)
    assert rdf.shape == (50, 4) and abs(rdf[-5:, 2].mean() - 1.0) < 0.05   # g(r) -> 1 far away
    series = (work / "water.vtu.series").read_text()
    assert '"water_100.vtu"' in series and (work / "water_50.vtu").exists()


def test_hopper_example_starts_and_falls(tmp_path):
    _, result = run_example(tmp_path, "hopper", "hopper.in", 500)
    rows = [line.split() for line in result.stdout.splitlines() if line.strip()[:1].isdigit()]
    assert rows[0][:2] == ["0", "2312"] and float(rows[-1][2]) > 0.0
