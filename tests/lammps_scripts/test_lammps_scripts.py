"""The benchmark kit's LAMMPS scripts (copies of the kit's bench/lammps/in.*, unmodified) run with
``pdps run`` and give LAMMPS's answers, recorded with LAMMPS itself by
benchmarks/lammps_references/lammps_scripts.py into reference/:

- in.lj_melt is deterministic (positions and velocities from the data file): the thermo lines at
  steps 0 and 100 equal LAMMPS's, digit for digit as printed (8 significant digits).
- in.dpd_water and in.dpd_gw are stochastic: f_avg[1] and f_avg[2] (mean T and P over the second half
  of a shortened run) lie within 3 standard deviations of LAMMPS's mean over independent runs (the
  deviation of one run against a mean of several: sqrt(sd^2 + sd^2 / n)).
"""

from pathlib import Path

import pytest

from pdps_core.testing import bench_data

HERE = Path(__file__).parent
REFERENCE = HERE / "reference"


def run_script(pdps_cli, tmp_path, script, kind, nsteps, navg):
    bench_data(kind, tmp_path / f"{kind}.data")
    done = pdps_cli((HERE / script).read_text(), "-var", "scenes", ".", "-var", "nsteps", str(nsteps),
                    "-var", "navg", str(navg), "-log", "none", "--no-progress", name=script)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "read as LAMMPS: atom_style on line 3"
    start = next(k for k, line in enumerate(lines) if line.split()[:1] == ["Step"])
    header = lines[start].split()
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("Loop time"):
            break
        if line.startswith("WARNING"):
            continue
        rows.append(line.split())
    return header, rows


def test_lj_melt_thermo_lines_equal_lammps_printed_digits(pdps_cli, tmp_path):
    reference = (REFERENCE / "lj_melt.txt").read_text().splitlines()
    header, rows = run_script(pdps_cli, tmp_path, "in.lj_melt", "lj_fcc", 100, 50)
    assert header == reference[0].split()
    expected = [line.split() for line in reference[1:]]
    assert [row[0] for row in rows] == [row[0] for row in expected] == ["0", "100"]
    for row, want in zip(rows, expected):
        assert [f"{float(v):.8g}" for v in row] == [f"{float(v):.8g}" for v in want], row[0]


@pytest.mark.parametrize("scene, script, nsteps, navg", [("dpd_water", "in.dpd_water", 300, 150),
                                                         ("dpd_gw", "in.dpd_gw", 100, 50)])
def test_dpd_scripts_average_as_lammps_does(pdps_cli, tmp_path, scene, script, nsteps, navg):
    reference = {}
    lines = (REFERENCE / f"{scene}.txt").read_text().splitlines()
    runs = int(lines[0].split(":")[1].split()[0])
    for line in lines:
        if not line.startswith("#"):
            name, mean, sd = line.split()
            reference[name] = (float(mean), float(sd))
    header, rows = run_script(pdps_cli, tmp_path, script, scene, nsteps, navg)
    last = dict(zip(header, rows[-1]))
    assert int(last["Step"]) == nsteps
    for name, (mean, sd) in reference.items():
        allowed = 3.0 * (sd * sd + sd * sd / runs) ** 0.5
        assert abs(float(last[name]) - mean) <= allowed, (name, float(last[name]), mean, allowed)
