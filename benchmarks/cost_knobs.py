"""Cost knobs that trade accuracy openly: what each saves and what it changes, on the benchmark scenes.

1. DPD noise: ``pair_style dpd ... noise uniform`` (Groot and Warren's choice) against the default
   Gaussian noise (LAMMPS's). The Groot-Warren fluid (dpd_gw, 31,944 particles, rho 3, a 25,
   gamma 4.5, kT 1, dt 0.04) for STEPS steps from SEEDS DPD seeds each: the pair stage's time per step,
   and temperature and pressure averaged over the second half of each run (mean +- standard error
   over seeds). The fluctuation-dissipation theorem needs only the noise's variance, so both should
   give kT = 1 and the same pressure within their errors (and within the time step's own bias, the
   same for both: docs/accuracy-dpd.md).
2. ``neighbor auto``: lj_melt (LAMMPS's in.lj, 32,000 atoms; as it is, rebuilding every 20 steps
   unchecked, and with LAMMPS's default schedule, checked at every step) and dpd_gw with their
   scripts' ``neighbor 0.3 bin`` replaced by ``neighbor auto``: the time per step of every candidate
   skin (the curve), the skin chosen, and the run's throughput against the fixed skin 0.3.

Both run pdps only (LAMMPS has neither knob); the scripts are benchmarks/scenes/lammps/'s. The tables
go into docs/performance.md between ``<!-- knobs:begin -->`` and ``<!-- knobs:end -->``
(``--print`` shows them only). Timings come from a shared machine: compare within a table.

    .venv/bin/python benchmarks/cost_knobs.py [--steps 300] [--seeds 3] [--print]
"""

import argparse
import datetime
import pathlib
import re
import statistics
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
SCRIPTS = HERE / "scenes" / "lammps"
PAGE = ROOT / "docs" / "performance.md"
BEGIN, END = "<!-- knobs:begin -->", "<!-- knobs:end -->"
PDPS = pathlib.Path(sys.executable).parent / "pdps"


def run(script_text, folder, variables):
    """Run a script with pdps in ``folder``; its screen text."""
    path = folder / "in.knob"
    path.write_text(script_text)
    command = [str(PDPS), "run", str(path), "-log", "none", "--no-progress"]
    for name, value in variables.items():
        command += ["-var", name, str(value)]
    result = subprocess.run(command, cwd=folder, capture_output=True, text=True)
    if result.returncode:
        sys.exit(f"pdps failed: {result.stdout[-2000:]}{result.stderr[-2000:]}")
    return result.stdout


def loop_rate(text):
    match = re.search(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+)", text)
    seconds, steps, particles = float(match.group(1)), int(match.group(2)), int(match.group(3))
    return particles * steps / seconds, seconds / steps


def stage(text, name):
    match = re.search(rf"^{name}\s+\|\s+([0-9.eE+-]+)", text, re.M)
    return float(match.group(1)) if match else 0.0


def thermo_averages(text, steps):
    rows = [line.split() for line in text.splitlines()]
    rows = [r for r in rows if len(r) == 5 and r[0].isdigit()]
    last = rows[-1]
    return float(last[3]), float(last[4])      # f_avg[1], f_avg[2]: T and P over the second half


def mean_error(values):
    if len(values) < 2:
        return values[0], float("nan")
    return statistics.fmean(values), statistics.stdev(values) / len(values) ** 0.5


def noise_table(folder, steps, seeds):
    base = (SCRIPTS / "in.dpd_gw").read_text()
    rows = []
    for noise in ("gaussian", "uniform"):
        temps, presses, pair_times = [], [], []
        for k in range(seeds):
            text = base.replace("pair_style dpd 1.0 1.0 928342", f"pair_style dpd 1.0 1.0 {928342 + 1000 * k} noise {noise}")
            out = run(text, folder, {"scenes": folder, "out": folder, "nsteps": steps, "navg": steps // 2})
            t, p = thermo_averages(out, steps)
            temps.append(t)
            presses.append(p)
            pair_times.append(stage(out, "Pair") / steps)
        rows.append((noise, mean_error(temps), mean_error(presses), statistics.median(pair_times)))
    lines = [f"Groot-Warren fluid (dpd_gw, 31,944 particles), {steps} steps from {seeds} DPD seeds each; "
             "T and P averaged over the second half of each run (mean +- standard error over seeds); "
             "the pair stage per step (median over seeds).", "",
             "| noise | kT | P | pair stage per step |", "|---|---|---|---|"]
    for noise, (t, dt), (p, dp), pair in rows:
        lines.append(f"| {noise} | {t:.4f} +- {dt:.4f} | {p:.3f} +- {dp:.3f} | {pair * 1e3:.2f} ms |")
    (gt, gdt), (ut, udt) = rows[0][1], rows[1][1]
    (gp, gdp), (up, udp) = rows[0][2], rows[1][2]
    lines += ["", f"Uniform minus Gaussian: kT {ut - gt:+.4f} +- {(gdt ** 2 + udt ** 2) ** 0.5:.4f}, "
                  f"P {up - gp:+.3f} +- {(gdp ** 2 + udp ** 2) ** 0.5:.3f}; the pair stage "
                  f"{100 * (1 - rows[1][3] / rows[0][3]):.0f} % shorter."]
    return lines


def auto_table(folder):
    lines = ["| scene | skin chosen | time per step by skin (the trial) | whole run, auto / fixed 0.3 |",
             "|---|---|---|---|"]
    checked = "neigh_modify delay 0 every 1 check yes"
    for scene, steps, schedule in (("lj_melt", 600, None), ("lj_melt", 600, checked), ("dpd_gw", 300, None)):
        base = (SCRIPTS / f"in.{scene}").read_text()
        if schedule is not None:
            base = re.sub(r"^neigh_modify .*$", schedule, base, flags=re.M)
        variables = {"scenes": folder, "out": folder, "nsteps": steps, "navg": steps // 2}
        fixed = run(base, folder, variables)
        auto = run(base.replace("neighbor 0.3 bin", "neighbor auto bin"), folder, variables)
        report = next(line for line in auto.splitlines() if line.startswith("neighbor auto: skin"))
        chosen = report.split()[3]
        curve = report[report.index("by skin: ") + 9:].rstrip(")")
        ratio = loop_rate(auto)[0] / loop_rate(fixed)[0]
        shown = re.search(r"^neigh_modify (.*)$", base, re.M).group(1)
        lines.append(f"| {scene} ({steps} steps, {shown}) | {chosen} | {curve} | {ratio:.2f} |")
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--print", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        folder = pathlib.Path(work)
        subprocess.run([sys.executable, "-c", "import sys; from pdps_core.testing import bench_data; "
                        "[bench_data(k, sys.argv[1] + '/' + k + '.data') for k in ('dpd_gw', 'lj_fcc')]",
                        str(folder)], check=True)
        stamp = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                                text=True).stdout.strip()
        lines = [f"Measured {stamp} on commit {commit} by benchmarks/cost_knobs.py.", "",
                 "### DPD noise: Gaussian (default, LAMMPS's) or uniform (Groot and Warren's)", ""]
        lines += noise_table(folder, args.steps, args.seeds)
        lines += ["", "### `neighbor auto`", ""]
        lines += auto_table(folder)
    text = "\n".join(lines)
    if args.print:
        print(text)
        return
    page = PAGE.read_text()
    if BEGIN not in page or END not in page:
        sys.exit(f"{PAGE} has no {BEGIN} ... {END} lines to write between")
    head, rest = page.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    PAGE.write_text(f"{head}{BEGIN}\n{text}\n{END}{tail}")
    print(f"wrote the cost knobs into {PAGE}")


if __name__ == "__main__":
    main()
