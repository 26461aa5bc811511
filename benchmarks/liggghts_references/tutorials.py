"""LIGGGHTS's cohesion and contactModels tutorials in LIGGGHTS 3.8.0 and in pdps: the translational and
rotational kinetic energies (thermo's ke and c_rke) at every thermo row, pdps's against the spread of
LIGGGHTS's over insertion seeds (issue 32).

    python benchmarks/liggghts_references/tutorials.py record [--liggghts PATH] [--steps N]
    python benchmarks/liggghts_references/tutorials.py compare [--seeds M] [--steps N]

The scripts are read from Debian's liggghts-doc (TUTORIALS below; never copied here: they are GPL),
with two changes: the seeds of fix particletemplate/sphere, particledistribution/discrete and
insert/pack are replaced by one triple of primes per run (LIGGGHTS_SEEDS, PDPS_SEEDS; LIGGGHTS's
first run keeps the tutorial's own), and the dump lines are dropped (the VTK files are not compared).
``--steps N`` shortens the last ``run 50000 upto`` to N (the comparison and the slow test use the
full length: a run takes 10-20 s in LIGGGHTS, 20-70 s in pdps on this 2-core machine).

``record`` runs each tutorial in LIGGGHTS once per LIGGGHTS_SEEDS triple and writes every run's thermo
rows (step, atoms, ke, rke; steps that are multiples of 1000) to RESULTS, which the slow test
tests/test_liggghts_tutorials.py reads. ``compare`` runs pdps with
the first M triples of PDPS_SEEDS (other primes: pdps's insertion draws its own random numbers, so a
shared seed would not give LIGGGHTS's packing anyway) and prints, per tutorial and row, LIGGGHTS's
band over its first three seeds (min..max), its mean and standard deviation over all its seeds, and
pdps's values, marked ``<`` or ``>`` where outside the three-seed band and ``!`` where more than 3
standard deviations from LIGGGHTS's mean (on log10 of the energy, which spans six decades and is
skewed). The same count is made for LIGGGHTS's own seeds beyond the third (against the band of the
first three, and leave-one-out for the 3-sd criterion): how often LIGGGHTS itself leaves the band
says how often pdps may. Last, the criterion of tests/test_liggghts_tutorials.py (slow), for every
pair of pdps runs and, held out two at a time, of LIGGGHTS's: the geometric mean of the two runs
within the range of the others (log10) widened by that range on each side.
"""

import argparse
import itertools
import json
import math
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
RESULTS = ROOT / "benchmarks" / "results" / "liggghts_tutorials.json"
DOC = Path("/usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public")
TUTORIALS = {"cohesion": DOC / "cohesion" / "in.cohesion", "contactModels": DOC / "contactModels" / "in.newModels"}
# the tutorials' own seeds: particletemplate/sphere, particledistribution/discrete, insert/pack
OWN_SEEDS = (15485863, 15485867, 32452843)
LIGGGHTS_SEEDS = [OWN_SEEDS, (20000003, 20000023, 20000033), (30000001, 30000023, 30000037),
                  (40000003, 40000021, 40000033), (50000017, 50000021, 50000047), (60000011, 60000013, 60000023),
                  (70000027, 70000037, 70000043), (80000023, 80000027, 80000059)]
PDPS_SEEDS = [(110000017, 110000039, 110000057), (120000007, 120000031, 120000043),
              (130000001, 130000007, 130000009), (140000041, 140000053, 140000059),
              (150000001, 150000029, 150000047), (160000003, 160000037, 160000063)]
BAND_SEEDS = 3
SIGMAS = 3.0
SAME = 4e-4         # log10 of 1.001: the range of rows where all reference runs agree
EVERY = 1000


def tutorial_script(name, seeds, steps=None):
    """The tutorial's text with ``seeds`` in place of its own, no dumps, and its last run ending at
    ``steps`` when given."""
    text = TUTORIALS[name].read_text()
    for own, new in zip(OWN_SEEDS, seeds):
        text, count = re.subn(rf"\b{own}\b", str(new), text)
        if count != 1:
            sys.exit(f"{TUTORIALS[name]}: seed {own} found {count} times")
    lines = [line for line in text.splitlines() if not line.split()[:1] == ["dump"]]
    if steps is not None:
        last = max(k for k, line in enumerate(lines) if line.split()[:1] == ["run"])
        lines[last] = f"run {steps} upto"
    return "\n".join(lines) + "\n"


def thermo_rows(screen):
    """[step, atoms, ke, rke] of every thermo row whose step is a multiple of EVERY, the first
    printing of each step (a run's first row repeats the last of the run before)."""
    rows = {}
    for line in screen.splitlines():
        words = line.split()
        if len(words) != 5 or not (words[0].isdigit() and words[1].isdigit()):
            continue
        step = int(words[0])
        if step % EVERY == 0 and step not in rows:
            rows[step] = [step, int(words[1]), float(words[2]), float(words[3])]
    return [rows[step] for step in sorted(rows)]


def run(command, script, label):
    """The thermo rows of ``command`` run on ``script`` in a temporary folder (with its post/)."""
    with tempfile.TemporaryDirectory() as folder:
        (Path(folder) / "post").mkdir()
        (Path(folder) / "in.tutorial").write_text(script)
        start = time.perf_counter()
        done = subprocess.run(command + ["-in", "in.tutorial", "-log", "none", "-echo", "none"], cwd=folder,
                              capture_output=True, text=True)
        seconds = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"{label} failed:\n{done.stdout[-2000:]}\n{done.stderr[-2000:]}")
    print(f"  {label}: {seconds:.1f} s", file=sys.stderr)
    return thermo_rows(done.stdout)


def record(liggghts, steps):
    runs = {name: [run([liggghts], tutorial_script(name, seeds, steps), f"LIGGGHTS {name} {seeds}")
                   for seeds in LIGGGHTS_SEEDS] for name in TUTORIALS}
    with tempfile.TemporaryDirectory() as folder:
        version = subprocess.run([liggghts, "-h"], cwd=folder, capture_output=True, text=True).stdout.splitlines()
    write_results({
        "program": next((line.strip() for line in version if "LIGGGHTS" in line), "LIGGGHTS"),
        "scripts": {name: str(path) for name, path in TUTORIALS.items()},
        "steps": steps, "seeds": LIGGGHTS_SEEDS, "columns": ["step", "atoms", "ke", "rke"],
        "runs": runs})
    print(f"wrote {RESULTS}")


def write_results(results):
    """RESULTS as JSON with one line per run (its thermo rows)."""
    head = {key: value for key, value in results.items() if key != "runs"}
    lines = ["{"] + [f" {json.dumps(key)}: {json.dumps(value)}," for key, value in head.items()] + [' "runs": {']
    for k, (name, runs) in enumerate(results["runs"].items()):
        lines.append(f"  {json.dumps(name)}: [")
        lines += ["   " + json.dumps(run) + ("," if r < len(runs) - 1 else "") for r, run in enumerate(runs)]
        lines.append("  ]" + ("," if k < len(results["runs"]) - 1 else ""))
    RESULTS.write_text("\n".join(lines + [" }", "}"]) + "\n")


def log_stats(values):
    """Mean and standard deviation of log10 of the positive values (None for fewer than two)."""
    logs = [math.log10(v) for v in values if v > 0.0]
    if len(logs) < 2:
        return None
    return statistics.fmean(logs), statistics.stdev(logs)


def verdict(value, band, stats):
    """'<' or '>' outside the band, '!' beyond SIGMAS standard deviations (log10), joined."""
    mark = "<" if value < band[0] else ">" if value > band[1] else ""
    if stats is not None and stats[1] > 0.0:
        if value <= 0.0 or abs(math.log10(value) - stats[0]) > SIGMAS * stats[1]:
            mark += "!"
    return mark


def compare_runs(reference, candidates, column):
    """Per row: (step, band, stats, [(value, mark)...]) for ``candidates``' runs against the reference
    runs (band: the first BAND_SEEDS; stats: all of them), and per candidate the number of rows outside
    the band and beyond the sigmas. Rows where all reference runs are 0 (before any contact) are left
    out."""
    table, outside, beyond = [], [0] * len(candidates), [0] * len(candidates)
    for k, row in enumerate(reference[0]):
        values = [r[k][column] for r in reference]
        if max(values) == 0.0:
            continue
        band = (min(values[:BAND_SEEDS]), max(values[:BAND_SEEDS]))
        stats = log_stats(values)
        marks = []
        for c, cand in enumerate(candidates):
            value = cand[k][column]
            mark = verdict(value, band, stats)
            outside[c] += "<" in mark or ">" in mark
            beyond[c] += "!" in mark
            marks.append((value, mark))
        table.append((row[0], band, stats, marks))
    return table, outside, beyond


def own_spread(runs, column):
    """How often LIGGGHTS's seeds beyond the band's leave it, and (leave-one-out) how often each of
    its seeds is beyond SIGMAS standard deviations of the others: [(outside, beyond, rows)]."""
    counts = []
    for held in range(len(runs)):
        others = runs[:held] + runs[held + 1:]
        rows = outside = beyond = 0
        for k in range(len(runs[0])):
            values = [r[k][column] for r in others]
            if max(values) == 0.0:
                continue
            rows += 1
            band = (min(values[:BAND_SEEDS]), max(values[:BAND_SEEDS]))
            mark = verdict(runs[held][k][column], band, log_stats(values))
            outside += held >= BAND_SEEDS and ("<" in mark or ">" in mark)
            beyond += "!" in mark
        counts.append((outside, beyond, rows))
    return counts


def widened_excess(reference, runs, column):
    """The largest distance, over the rows where the reference runs move, of the log10 geometric
    mean of ``runs`` outside the reference runs' range, in units of that range (at least SAME: rows
    of free fall agree to round-off); at most 1 passes tests/test_liggghts_tutorials.py."""
    worst = 0.0
    for k in range(len(reference[0])):
        values = [r[k][column] for r in reference]
        if min(values) <= 0.0:
            continue
        logs = [math.log10(v) for v in values]
        mine = statistics.fmean(math.log10(r[k][column]) if r[k][column] > 0.0 else -math.inf for r in runs)
        spread = max(max(logs) - min(logs), SAME)
        worst = max(worst, (min(logs) - mine) / spread, (mine - max(logs)) / spread)
    return worst


def compare(nseeds, steps):
    recorded = json.loads(RESULTS.read_text())
    if recorded["steps"] != steps:
        sys.exit(f"{RESULTS} holds runs to step {recorded['steps'] or 'end'}: compare with the same --steps")
    pdps = [str(Path(sys.executable).parent / "pdps"), "run", "--no-progress"]
    for name in TUTORIALS:
        reference = recorded["runs"][name]
        mine = [run(pdps, tutorial_script(name, seeds, steps), f"pdps {name} {seeds}")
                for seeds in PDPS_SEEDS[:nseeds]]
        if len({len(r) for r in reference + mine}) != 1:
            sys.exit(f"{name}: thermo tables of different lengths")
        for column, label in ((2, "ke"), (3, "rke")):
            table, outside, beyond = compare_runs(reference, mine, column)
            print(f"\n{name} {label}: LIGGGHTS band over seeds 1-{BAND_SEEDS}, mean and sd of log10 over "
                  f"{len(reference)} seeds; pdps seeds 1-{nseeds} ('<' '>' outside the band, '!' beyond "
                  f"{SIGMAS:g} sd)")
            for step, band, stats, marks in table:
                mean = f"{10 ** stats[0]:.3e} x/ {10 ** stats[1]:.3f}" if stats else "-"
                print(f"{step:6d}  {band[0]:.3e}..{band[1]:.3e}  {mean:>22s}  "
                      + "  ".join(f"{v:.3e}{m:<2s}" for v, m in marks))
            rows = len(table)
            print(f"pdps rows outside the band: {outside} of {rows}; beyond {SIGMAS:g} sd: {beyond}")
            spread = own_spread(reference, column)
            print(f"LIGGGHTS's seeds {BAND_SEEDS + 1}-{len(reference)} outside the band: "
                  f"{[c[0] for c in spread[BAND_SEEDS:]]} of {rows}; each seed beyond {SIGMAS:g} sd of the "
                  f"others: {[c[1] for c in spread]}")
            pairs = [widened_excess(reference, [mine[a], mine[b]], column)
                     for a, b in itertools.combinations(range(len(mine)), 2)]
            held = [widened_excess([r for k, r in enumerate(reference) if k not in (a, b)],
                                   [reference[a], reference[b]], column)
                    for a, b in itertools.combinations(range(len(reference)), 2)]
            print(f"geometric mean of two runs against LIGGGHTS's range widened by itself (the slow test): "
                  f"worst {max(pairs):.2f} of the range over the {len(pairs)} pairs of pdps seeds, "
                  f"{sum(x > 1.0 for x in pairs)} fail; LIGGGHTS's held-out pairs against its other "
                  f"{len(reference) - 2} seeds: {sum(x > 1.0 for x in held)} of {len(held)} fail")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("action", choices=("record", "compare"))
    parser.add_argument("--liggghts", default="liggghts", help="the LIGGGHTS executable (Debian: liggghts)")
    parser.add_argument("--steps", type=int, default=None, help="end the last run at this step")
    parser.add_argument("--seeds", type=int, default=2, help="pdps runs per tutorial (compare)")
    args = parser.parse_args()
    if args.action == "record":
        record(args.liggghts, args.steps)
    else:
        compare(args.seeds, args.steps)


if __name__ == "__main__":
    main()
