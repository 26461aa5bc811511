"""The example scripts run as shipped (shortened) and leave what their headers promise."""

import math
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


def test_hopper_example_spheres_fall_freely_until_the_first_contact(tmp_path):
    """The 2312 spheres start at rest on a lattice of spacing 1.1 (no contacts), 2 above the funnel:
    at step 500 (t = 0.1) each falls at g t, so the kinetic energy per sphere (thermo normalises by
    N in lj units) is m (g t)^2 / 2 = 0.005 with m = 1, and none is lost."""
    _, result = run_example(tmp_path, "hopper", "hopper.in", 500)
    rows = [line.split() for line in result.stdout.splitlines() if line.strip()[:1].isdigit()]
    assert rows[0] == ["0", "2312", "0"]
    assert rows[-1][:2] == ["500", "2312"] and float(rows[-1][2]) == pytest.approx(0.005, rel=1e-6)


def dump_frames(path):
    """(step, ids, x) for every frame of a text dump with columns id type x y z ..."""
    lines = path.read_text().splitlines()
    frames, i = [], 0
    while i < len(lines):
        n = int(lines[i + 3])
        assert lines[i + 8].split()[2:5] == ["id", "type", "x"]
        rows = np.array([line.split() for line in lines[i + 9:i + 9 + n]], dtype=float)
        frames.append((int(lines[i + 1]), rows[:, 0].astype(int), rows[:, 2:5]))
        i += 9 + n
    return frames


def beverloo_rate(outlet_side, C, k, d=1.0, g=1.0, packing=0.6):
    """Spheres per time unit through a square outlet, Beverloo's W = C rho_b sqrt(g) (D - k d)^(5/2)
    with D the diameter of a circle of the outlet's area and rho_b the bulk number density."""
    diameter = math.sqrt(4.0 * outlet_side ** 2 / math.pi)
    bulk = packing / (math.pi * d ** 3 / 6.0)
    return C * bulk * math.sqrt(g) * (diameter - k * d) ** 2.5


@pytest.mark.slow
def test_hopper_example_drains_through_its_outlet_at_the_beverloo_rate(tmp_path):
    """What the example is about: the spheres fall into the funnel and discharge through its 8 x 8
    outlet at z = 0, none lost and none through the mesh. Shortened from 50,000 to 40,000 steps
    (8 time units): free fall from the lowest layer (z = 12) reaches the outlet at t = 4.9, so the
    frames at t = 5 to 8 hold the onset and three time units of steady flow, which decide the rate;
    the last 2 time units of the example only continue it. The rate lies within Beverloo's law
    over its usual constants (C = 0.55-0.65, k = 1.2-3: 56-128 spheres per time unit); 103 for
    C = 0.58, k = 1.5."""
    work, result = run_example(tmp_path, "hopper", "hopper.in", 40000)
    rows = [line.split() for line in result.stdout.splitlines() if line.strip()[:1].isdigit()
            and len(line.split()) == 3]
    assert [int(r[0]) for r in rows] == list(range(0, 40001, 5000))
    assert all(r[1] == "2312" for r in rows) and all(math.isfinite(float(r[2])) for r in rows)
    frames = dump_frames(work / "dump.hopper")
    assert [step for step, _, _ in frames] == list(range(0, 40001, 5000))
    below = []
    for _, ids, x in frames:
        assert sorted(ids) == list(range(1, 2313))                  # none lost, none duplicated
        in_hopper = x[:, 2] >= 0.0
        # the mesh: |x|, |y| <= 4 + 0.6 z in the funnel (z < 10), <= 10 in the bin; centres inside
        half_width = np.where(x[in_hopper, 2] < 10.0, 4.0 + 0.6 * x[in_hopper, 2], 10.0)
        assert (np.abs(x[in_hopper, :2]).max(axis=1) <= half_width).all()
        assert (x[:, 2] > -30.0).all() and (np.abs(x[:, :2]) < 12.0).all()     # above the floor
        below.append(int((~in_hopper).sum()))
    assert below[:4] == [0, 0, 0, 0] and below[5] > 0, below       # free fall from z = 12 takes t = 4.9
    assert all(b2 >= b1 for b1, b2 in zip(below, below[1:])), below
    rate = (below[8] - below[6]) / 2.0                                   # t = 6 to 8
    assert beverloo_rate(8.0, C=0.55, k=3.0) < rate < beverloo_rate(8.0, C=0.65, k=1.2), rate


def test_liggghts_example_fills_the_cylinder_and_the_floor_feels_the_beads(tmp_path):
    """2,000 beads inserted at the first step, none lost; after 2,000 steps (0.02 s; the lowest ones
    start 5 mm above the floor at 0.5 m/s) the floor is pushed down, and the VTK series are written."""
    work, result = run_example(tmp_path, "liggghts", "in.liggghts", 2000)
    assert "read as LIGGGHTS" in result.stdout
    rows = [line.split() for line in result.stdout.splitlines() if line.strip()[:1].isdigit()]
    assert rows[0][:2] == ["0", "0"] and rows[-1][:2] == ["2000", "2000"]
    force_z = float(rows[-1][6])
    assert force_z < -0.1
    assert (work / "post" / "beads.vtu.series").exists() and (work / "post" / "floor_0.vtk").exists()
