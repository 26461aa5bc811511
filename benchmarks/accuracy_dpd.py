"""What DPD accuracy costs: temperature, pressure and structure error against wall time, per
integrator and time step, on the Groot-Warren fluid (rho = 3, a = 25, gamma = 4.5, kT = 1).

For each integrator (fix nve; fix mvv/dpd 0.65; fix shardlow with pair dpd/fdt) and each dt it
equilibrates, then measures over a production run: <T> - 1, <P>, the distance of g(r) to a dt = 0.005
reference, and wall seconds per unit of simulated time. A run "fails" when it stops with an error or
its temperature is off by more than 20 %; larger dt are not tried for that integrator.

    .venv/bin/pip install -e '.[bench]'           # matplotlib, for the plot
    .venv/bin/python benchmarks/accuracy_dpd.py   # ~10 minutes on one core

Writes benchmarks/results/accuracy_dpd.json and docs/accuracy-dpd.png.
"""

import argparse
import io
import json
import pathlib
import statistics
import time

import numpy as np

from pdps_core.api import ScriptError, Simulation

HERE = pathlib.Path(__file__).parent
RESULTS = HERE / "results" / "accuracy_dpd.json"
PLOT = HERE.parent / "docs" / "accuracy-dpd.png"
INTEGRATORS = {
    "nve": ("dpd", "fix 1 all nve"),
    "mvv/dpd 0.65": ("dpd", "fix 1 all mvv/dpd 0.65"),
    "shardlow": ("dpd/fdt", "fix 1 all shardlow\nfix 2 all nve"),
}
TIMESTEPS = tuple(float(t) for t in __import__("os").environ.get("PDPS_DTS", "0.01 0.02 0.04 0.06 0.08 0.10 0.12").split())
R_MAX, DR = 2.5, 0.05


def scene(pair, integrator, dt, length, seed):
    return f"""
units lj
region box block 0 {length} 0 {length} 0 {length}
create_box 1 box
mass 1 1
create_particle 1 random_no_overlap {int(round(3 * length ** 3))} box 0.0 {seed}
pair_style {pair} 1.0 1.0 {seed + 17}
pair_coeff * * 25.0 4.5 1.0
velocity all create 1.0 {seed + 3} gaussian
neighbor 0.3
neigh_modify every 1 delay 0 check yes
timestep {dt}
{integrator}
thermo_style custom step temp press
"""


def rdf(frames, length):
    """g(r) averaged over frames (minimum image), bins of DR up to R_MAX."""
    edges = np.arange(0.0, R_MAX + DR / 2, DR)
    counts = np.zeros(len(edges) - 1)
    n = len(frames[0])
    for x in frames:
        for i in range(n - 1):
            d = x[i + 1:] - x[i]
            d -= length * np.round(d / length)
            counts += np.histogram(np.sqrt((d * d).sum(axis=1)), bins=edges)[0]
    shell = 4.0 / 3.0 * np.pi * (edges[1:] ** 3 - edges[:-1] ** 3)
    ideal = shell * n / length ** 3 * n / 2 * len(frames)
    return 0.5 * (edges[1:] + edges[:-1]), counts / ideal


def read_frames(path):
    frames, lines = [], path.read_text().splitlines()
    i = 0
    while i < len(lines):
        n = int(lines[i + 3])
        frames.append(np.array([[float(v) for v in row.split()[1:4]] for row in lines[i + 9:i + 9 + n]]))
        i += 9 + n
    return frames


def measure(name, dt, length, equilibrate, produce, seed, workdir):
    pair, integrator = INTEGRATORS[name]
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None)
    sim.command(scene(pair, integrator, dt, length, seed))
    steps_eq, steps = int(round(equilibrate / dt)), int(round(produce / dt))
    every = max(1, int(round(1.0 / dt)))
    dump = workdir / f"frames_{name.replace('/', '_').replace(' ', '_')}_{dt}.txt"
    try:
        sim.command(f"thermo {steps_eq}\nrun {steps_eq}")
        sim.command(f"thermo 5\ndump f all custom {every} {dump} id x y z")
        screen.seek(0)
        screen.truncate()
        t0 = time.perf_counter()
        sim.command(f"run {steps}")
        wall = time.perf_counter() - t0
    except ScriptError as exc:
        return {"integrator": name, "dt": dt, "failed": str(exc)}
    finally:
        sim.close()
    rows = [r.split() for r in screen.getvalue().splitlines()]
    rows = [r for r in rows if len(r) == 3 and r[0].isdigit()]
    temps = [float(r[1]) for r in rows]
    press = [float(r[2]) for r in rows]
    r, g = rdf(read_frames(dump)[1:], length)
    dump.unlink()
    return {"integrator": name, "dt": dt, "T": statistics.fmean(temps), "P": statistics.fmean(press),
            "T_sem": block_error(temps), "P_sem": block_error(press),
            "wall_per_time": wall / (steps * dt), "r": r.tolist(), "g": g.tolist(),
            "warnings": list(sim.warnings)}


def block_error(values, blocks=10):
    size = len(values) // blocks
    means = [statistics.fmean(values[k * size:(k + 1) * size]) for k in range(blocks)]
    return statistics.stdev(means) / blocks ** 0.5


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--length", type=float, default=10.0, help="box edge (rho = 3: 3000 particles)")
    parser.add_argument("--equilibrate", type=float, default=10.0, help="time units before measuring")
    parser.add_argument("--produce", type=float, default=40.0, help="time units measured")
    parser.add_argument("--seed", type=int, default=2024)
    parser.add_argument("--plot-only", action="store_true", help="redraw the plot from the results file")
    args = parser.parse_args()
    if args.plot_only:
        plot(json.loads(RESULTS.read_text()))
        return
    workdir = HERE / "results"
    workdir.mkdir(exist_ok=True)
    common = (args.length, args.equilibrate, args.produce, args.seed, workdir)
    reference = measure("nve", 0.005, *common)
    print(f"reference nve dt=0.005: T = {reference['T']:.4f} P = {reference['P']:.3f}", flush=True)
    results = [reference]
    for name in INTEGRATORS:
        for dt in TIMESTEPS:
            row = measure(name, dt, *common)
            if "failed" not in row:
                row["rdf_distance"] = float(np.sqrt(np.sum((np.array(row["g"]) - reference["g"]) ** 2) * DR))
                if abs(row["T"] - 1.0) > 0.2:
                    row["failed"] = f"temperature {row['T']:.3g} is off by more than 20 %"
            results.append(row)
            print(summary(row), flush=True)
            if "failed" in row:
                break
    RESULTS.write_text(json.dumps(results, indent=1))
    plot(results)


def summary(row):
    if "failed" in row and "T" not in row:
        return f"{row['integrator']:<13} dt={row['dt']:<5} FAILED: {row['failed']}"
    return (f"{row['integrator']:<13} dt={row['dt']:<5} T-1 = {row['T'] - 1:+.4f} +- {row['T_sem']:.4f}  "
            f"P = {row['P']:.3f} +- {row['P_sem']:.3f}  rdf distance = {row.get('rdf_distance', 0):.4f}  "
            f"{row['wall_per_time']:.2f} s per time unit" + ("  FAILED" if "failed" in row else ""))


def plot(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for name in INTEGRATORS:
        rows = [r for r in results[1:] if r["integrator"] == name and "failed" not in r]
        cost = [r["wall_per_time"] for r in rows]
        left.errorbar(cost, [max(abs(r["T"] - 1.0), 1e-4) for r in rows], yerr=[r["T_sem"] for r in rows],
                      fmt="o-", capsize=2, label=name)
        right.loglog(cost, [max(r["rdf_distance"], 1e-4) for r in rows], "o-", label=name)
        for r in rows:
            left.annotate(f"{r['dt']:g}", (r["wall_per_time"], max(abs(r["T"] - 1.0), 1e-4)),
                          fontsize=7, xytext=(3, 3), textcoords="offset points")
    left.set_xscale("log")
    left.set_yscale("log")
    right.axhline(0.006, color="gray", lw=0.8, ls="--")
    right.annotate("statistical floor", (0.065, 0.0062), fontsize=7, color="gray")
    left.set(xlabel="wall seconds per unit of simulated time (3000 particles, 1 core)",
             ylabel="|<T> - kT|", title="temperature error (labels: dt)")
    right.set(xlabel="wall seconds per unit of simulated time", ylabel="||g - g_ref||",
              title="g(r) distance to dt = 0.005")
    for axis in (left, right):
        axis.grid(True, which="both", alpha=0.3)
        axis.legend()
    fig.tight_layout()
    fig.savefig(PLOT, dpi=110)


if __name__ == "__main__":
    main()
