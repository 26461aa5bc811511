"""Parallel efficiency on 2 ranks for dpd_gw and gran_box, beside LAMMPS's on the same machine.

Runs each scene with `mpiexec -n 1` and `-n 2` (the mpich wheel the [mpi] extra installs), reads the
"Loop time" line, and prints speed-up and efficiency = t1 / (2 t2); with --lammps it runs
../shared/bench/run_lammps.sh SCENE STEPS 1 and 2 for the same figures from LAMMPS.

    .venv/bin/python benchmarks/parallel_efficiency.py [--lammps] [--dpd-steps 100] [--gran-steps 2000]

Run it on an otherwise idle machine: the two ranks need the two cores.
"""

import argparse
import pathlib
import re
import subprocess
import sys

HERE = pathlib.Path(__file__).parent
BENCH = HERE.parents[1] / "shared" / "bench"
DATA = pathlib.Path("/tmp/pdps-bench-data")
MPIEXEC = pathlib.Path(sys.executable).parent / "mpiexec"
LOOP = re.compile(r"Loop time of ([0-9.eE+-]+)")


def data(kind):
    DATA.mkdir(parents=True, exist_ok=True)
    path = DATA / f"{kind}.data"
    if not path.exists():
        subprocess.run([sys.executable, str(BENCH / "make_data.py"), kind, str(path)], check=True)
    return path


def pdps_loop_time(scene, steps, ranks):
    out = subprocess.run([str(MPIEXEC), "-n", str(ranks), sys.executable, "-m", "pdps_core.cli", "run",
                          str(HERE / "scenes" / f"in.{scene}"), "-log", "none", "-var", "data", str(data(scene)),
                          "-var", "seed", "928342", "-var", "nsteps", str(steps)],
                         capture_output=True, text=True, check=True).stdout
    return float(LOOP.search(out).group(1))


def lammps_loop_time(scene, steps, ranks):
    out = subprocess.run(["bash", str(BENCH / "run_lammps.sh"), scene, str(steps), str(ranks)],
                         capture_output=True, text=True, check=True).stdout
    return float(LOOP.search(out).group(1))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--lammps", action="store_true")
    parser.add_argument("--dpd-steps", type=int, default=100)
    parser.add_argument("--gran-steps", type=int, default=2000)
    args = parser.parse_args()
    for scene, steps in (("dpd_gw", args.dpd_steps), ("gran_box", args.gran_steps)):
        codes = [("pdps", pdps_loop_time)] + ([("LAMMPS", lammps_loop_time)] if args.lammps else [])
        for code, timer in codes:
            t1, t2 = timer(scene, steps, 1), timer(scene, steps, 2)
            print(f"{scene:<9} {code:<7} {steps} steps: 1 rank {t1:.3f} s, 2 ranks {t2:.3f} s, "
                  f"speed-up {t1 / t2:.2f}x, efficiency {100 * t1 / (2 * t2):.0f} %", flush=True)


if __name__ == "__main__":
    main()
