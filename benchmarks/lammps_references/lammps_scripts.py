"""Record LAMMPS's answers for the benchmark kit's LAMMPS scripts (tests/lammps_scripts/in.*, copies of
../shared/bench/lammps), which tests/lammps_scripts/test_lammps_scripts.py runs unmodified in pdps.

    python benchmarks/lammps_references/lammps_scripts.py [LMP]

- in.lj_melt (deterministic: positions and velocities from the data file): the thermo lines LAMMPS
  prints at steps 0 and 100, as printed.
- in.dpd_water, in.dpd_gw (stochastic): f_avg[1] and f_avg[2] (mean temperature and pressure over the
  second half of the run) from SEEDS runs of the script with its two seeds (pair_style dpd and
  velocity) replaced, so that the runs are independent; written as the mean and the standard
  deviation of one run. pdps's run of the unmodified script is one more independent sample.

The data files are written by pdps_core.testing.bench_data, byte for byte what the kit's
make_data.py writes. Results go to tests/lammps_scripts/reference/.
"""

import re
import statistics
import sys
import tempfile
from pathlib import Path

from pdps_core.testing import bench_data

sys.path.insert(0, str(Path(__file__).parent))
from lammps_run import run_lammps_file, thermo_table  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
SCRIPTS = ROOT / "tests" / "lammps_scripts"
OUT = SCRIPTS / "reference"
SEEDS = 6
# scene: (script, data kind, nsteps, navg) -- the lengths the tests run
STOCHASTIC = {"dpd_water": ("in.dpd_water", "dpd_water", 300, 150),
              "dpd_gw": ("in.dpd_gw", "dpd_gw", 100, 50)}


def run_script(lmp, folder, script, nsteps, navg):
    return run_lammps_file(lmp, folder, script, (("scenes", "."), ("nsteps", nsteps), ("navg", navg)))


def lj_melt(lmp):
    with tempfile.TemporaryDirectory() as folder:
        bench_data("lj_fcc", Path(folder) / "lj_fcc.data")
        (Path(folder) / "in.lj_melt").write_text((SCRIPTS / "in.lj_melt").read_text())
        header, rows = thermo_table(run_script(lmp, folder, "in.lj_melt", 100, 50))
    text = " ".join(header) + "\n" + "".join(" ".join(row) + "\n" for row in rows)
    (OUT / "lj_melt.txt").write_text(text)
    print(text)


def stochastic(lmp, scene):
    script, kind, nsteps, navg = STOCHASTIC[scene]
    source = (SCRIPTS / script).read_text()
    results = []
    with tempfile.TemporaryDirectory() as folder:
        bench_data(kind, Path(folder) / f"{kind}.data")
        for k in range(SEEDS):
            text = re.sub(r"^(pair_style dpd \S+ \S+) (\d+)", lambda m: f"{m[1]} {int(m[2]) + 7919 * (k + 1)}",
                          source, flags=re.M)
            text = re.sub(r"^(velocity all create \S+) (\d+)", lambda m: f"{m[1]} {int(m[2]) + 104729 * (k + 1)}",
                          text, flags=re.M)
            (Path(folder) / script).write_text(text)
            header, rows = thermo_table(run_script(lmp, folder, script, nsteps, navg))
            last = dict(zip(header, rows[-1]))
            results.append((float(last["f_avg[1]"]), float(last["f_avg[2]"])))
    temps, pressures = zip(*results)
    lines = [f"# {scene}: {SEEDS} LAMMPS runs of {script} (seeds varied), nsteps {nsteps}, navg {navg}",
             "# quantity mean sd_of_one_run",
             f"f_avg[1] {statistics.mean(temps):.10g} {statistics.stdev(temps):.6g}",
             f"f_avg[2] {statistics.mean(pressures):.10g} {statistics.stdev(pressures):.6g}"]
    (OUT / f"{scene}.txt").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    command = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp")
    OUT.mkdir(parents=True, exist_ok=True)
    lj_melt(command)
    for name in STOCHASTIC:
        stochastic(command, name)
