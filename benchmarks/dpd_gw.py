"""dpd_gw: pdps against LAMMPS on the Groot-Warren fluid (same initial particles, same machine).

Runs scenes/in.dpd_gw for several DPD seeds, averages temperature and pressure over the second half
of each run (as the LAMMPS scene's fix ave/time does), and prints mean +- standard error over seeds
next to LAMMPS's figures, plus particle-steps per second.

    .venv/bin/python benchmarks/dpd_gw.py [--steps 500] [--seeds 4] [--lammps]

--lammps also runs ../shared/bench/run_lammps.sh dpd_gw on this machine for the speed ratio.
"""

import argparse
import io
import pathlib
import statistics
import subprocess
import sys
import time

from pdps_core.api import Simulation

HERE = pathlib.Path(__file__).parent
BENCH = HERE.parents[1] / "shared" / "bench"
DATA = pathlib.Path("/tmp/pdps-bench-data")
LAMMPS = {"T": (1.028, 0.002), "P": (23.847, 0.006), "literature P": 23.65}


def data_file():
    DATA.mkdir(parents=True, exist_ok=True)
    path = DATA / "dpd_gw.data"
    if not path.exists():
        subprocess.run([sys.executable, str(BENCH / "make_data.py"), "dpd_gw", str(path)], check=True)
    return path


def run(seed, steps):
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None,
                     variables={"data": data_file(), "seed": seed, "nsteps": steps})
    t0 = time.perf_counter()
    sim.file(str(HERE / "scenes" / "in.dpd_gw"))
    wall = time.perf_counter() - t0
    rows = [line.split() for line in screen.getvalue().splitlines()]
    rows = [r for r in rows if len(r) == 3 and r[0].isdigit()]
    second_half = [r for r in rows if int(r[0]) > steps // 2]
    temp = statistics.fmean(float(r[1]) for r in second_half)
    press = statistics.fmean(float(r[2]) for r in second_half)
    return temp, press, sim.nlocal * steps / wall, screen.getvalue()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--steps", type=int, default=500)
    parser.add_argument("--seeds", type=int, default=4)
    parser.add_argument("--lammps", action="store_true")
    args = parser.parse_args()
    temps, presses, speeds = [], [], []
    for k in range(args.seeds):
        temp, press, speed, _ = run(928342 + 1000 * k, args.steps)
        temps.append(temp)
        presses.append(press)
        speeds.append(speed)
        print(f"seed {k}: T = {temp:.4f}  P = {press:.4f}  {speed / 1e6:.3f} M particle-steps/s", flush=True)

    def summary(values):
        error = statistics.stdev(values) / len(values) ** 0.5 if len(values) > 1 else float("nan")
        return statistics.fmean(values), error
    (t, te), (p, pe) = summary(temps), summary(presses)
    print(f"pdps   : T = {t:.4f} +- {te:.4f}   P = {p:.4f} +- {pe:.4f}   "
          f"{statistics.fmean(speeds) / 1e6:.3f} M particle-steps/s (1 core)")
    print(f"LAMMPS : T = {LAMMPS['T'][0]} +- {LAMMPS['T'][1]}   P = {LAMMPS['P'][0]} +- {LAMMPS['P'][1]}"
          f"   (literature P = {LAMMPS['literature P']})")
    if args.lammps:
        out = subprocess.run(["bash", str(BENCH / "run_lammps.sh"), "dpd_gw", str(args.steps)],
                             capture_output=True, text=True).stdout
        print("LAMMPS on this machine:\n" + out)


if __name__ == "__main__":
    main()
