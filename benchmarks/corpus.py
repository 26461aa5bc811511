"""Scripts nobody here wrote, run as their users run them, in pdps and in the program they were
written for: LIGGGHTS 3.8.0's tutorials (issue 33).

    make corpus                                  # or:
    .venv/bin/python benchmarks/corpus.py [--only cohesion/in.cohesion ...] [--timeout 3600]
                                          [--reference-seeds 3] [--pdps-seeds 2] [--print]

Where the scripts come from: Debian's ``liggghts-doc``, fetched with ``apt-get download`` and unpacked
into build/corpus/ when it is not there yet (``--doc`` names another unpacked copy). The scripts are
GPL: they are read there and run in copies of their folders under build/corpus/runs/, never copied
into the project; benchmarks/results/corpus_liggghts.json keeps the numbers only.

How each script runs, unmodified but for its seeds:
- The reference program (``../shared/bench/liggghts``, or ``$PDPS_LAMMPS_BENCH/liggghts``) runs it
  once per seed set; the first set is the script's own seeds. A script's seeds are the numbers after
  ``particletemplate/*`` and ``particledistribution/discrete`` and after an insertion's ``seed``
  keyword; set k replaces each by a prime of its own (``seed_set``), the same one wherever the same
  seed appears.
- The reference's runs are kept in the results file and run again only with ``--rerun-reference``;
  asking for more seed sets than it holds runs the missing ones. pdps's runs are made again each
  time unless ``--keep-pdps``.
- pdps (this checkout's ``.venv``) runs it with ``--pdps-seeds`` other sets: its insertion draws its
  own random numbers, so the reference's seeds would not give the reference's packing anyway.
- The scripts of one folder run in order of name in one copy of it (insert_stream's second script
  reads the restart file its first writes), ``-in SCRIPT -echo none -log log.NAME``, with
  ``--timeout`` seconds each.

What the table says, per script (written into docs/liggghts.md between its ``corpus:begin`` and
``corpus:end`` lines):
- runs: pdps ran it to its end (exit 0, its last ``Loop time`` line printed); else the first line
  pdps printed that says why (``ERROR: ...``), or ``timeout``. Where the reference program itself
  fails, the script is out of the count, with its reason.
- agrees: the thermo rows compared column by column (by position, in the script's order: LIGGGHTS's
  header drops the c_ and f_ of a column's name and cuts it at 8 letters; steps that both print). Where the reference's seed sets print the same rows, the script is deterministic: pdps's
  rows agree when every value lies within the reference's printed precision (relative 1e-5, or 1e-12
  of the column's largest value for values at round-off), else the step where they part is given.
  Where the seed sets differ, statistically: at every row and column, the mean of pdps's runs
  (of log10 where every value is positive) lies within the range of the reference's runs widened by
  that range on each side; the excess is the distance outside it in units of the range (a count,
  such as the particles, resolved to one), the worst over rows and columns. LIGGGHTS's own seed
  sets do not pass that with a few sets (a pair of them against the others: median 1-4, worst
  3-40), so with 4 or more sets the verdict is a permutation test: every choice of two of all the
  runs (LIGGGHTS's n and pdps's two) is measured against the others by the largest pooled two-sample
  t over rows and columns (the standard deviation no smaller than the printed precision, or one for
  a count), and pdps agrees unless its two are the most extreme (p = the share of choices at least
  as extreme, > 0.05; with 6 LIGGGHTS sets 28 choices, so pdps fails only where its two stand out
  beyond every other pair: a pdps that were two more LIGGGHTS runs would fail 1 time in 28). With
  fewer sets: an excess of at most 1.
- time a step, both programs: the sum of the ``Loop time`` lines over the steps they count, the
  fastest of each program's seed sets (pdps's first run compiles what its caches lack).

Not part of ``make test``: a full run takes about an hour on this 2-core machine. Run it on an idle
machine if the times matter.
"""

import argparse
import itertools
import json
import math
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
BUILD = ROOT / "build" / "corpus"
REFERENCE = Path(os.environ.get("PDPS_LAMMPS_BENCH", ROOT.parent / "shared" / "bench"))
PAGE = ROOT / "docs" / "liggghts.md"
RESULTS = HERE / "results" / "corpus_liggghts.json"
BEGIN, END = "<!-- corpus:begin -->", "<!-- corpus:end -->"
TUTORIALS = Path("usr/share/doc/liggghts/examples/LIGGGHTS/Tutorials_public")
# the CFD-DEM coupling (ParScale) needs a CFD program beside LIGGGHTS: out of the field (issue 33)
COUPLED = ("ParScale/",)
SEED = re.compile(r"(particletemplate/\S+\s+|particledistribution/discrete\s+|\bseed\s+)(\d+)")
DETERMINISTIC = 1e-5        # LIGGGHTS's thermo prints 6 significant digits (%g)
ROUNDOFF = 1e-12
SAME = 4e-4                 # log10 of 1.001: energies that all runs print alike
P_VALUE = 0.05              # the statistical verdict's level
# pdps's seed sets are numbered from here on (the reference's from 0), so that asking for more
# reference seed sets later never gives the reference one of pdps's
PDPS_FIRST_SEED = 100
LOOP = re.compile(r"^Loop time of (\S+) on \d+ procs for (\d+) steps")


def is_prime(n):
    if n < 2 or n % 2 == 0:
        return n == 2
    return all(n % d for d in range(3, int(n ** 0.5) + 1, 2))


def seed_set(k, count):
    """``count`` primes for seed set k >= 1: LIGGGHTS wants its seeds prime and above 10,000."""
    primes, n = [], 10_000_000 * (k + 1)
    while len(primes) < count:
        n += 1
        if is_prime(n):
            primes.append(n)
    return primes


def with_seeds(text, k):
    """The script with seed set k (0: its own)."""
    own = list(dict.fromkeys(match.group(2) for match in SEED.finditer(text)))
    if k == 0 or not own:
        return text
    new = dict(zip(own, map(str, seed_set(k, len(own)))))
    return SEED.sub(lambda match: match.group(1) + new[match.group(2)], text)


def unpacked(package, target):
    """Debian's ``package`` unpacked into ``target`` (``apt-get download``, an ``apt-get update``
    first when the list has not got it)."""
    target.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as folder:
        fetched = subprocess.run(["apt-get", "download", package], cwd=folder, capture_output=True, text=True)
        if fetched.returncode != 0:
            subprocess.run(["apt-get", "update", "-qq"], check=True)
            subprocess.run(["apt-get", "download", package], cwd=folder, check=True)
        deb = next(Path(folder).glob(f"{package}_*.deb"))
        subprocess.run(["dpkg-deb", "-x", str(deb), str(target)], check=True)


def doc_folder(given):
    """The unpacked tutorials: ``given``, or build/corpus/liggghts-doc, fetched when missing."""
    if given is not None:
        return Path(given)
    target = BUILD / "liggghts-doc"
    if not (target / TUTORIALS).is_dir():
        unpacked("liggghts-doc", target)
    return target / TUTORIALS


def scripts(tutorials):
    """{folder: [script names in order]} of every tutorial outside COUPLED."""
    found = {}
    for path in sorted(tutorials.rglob("in.*")):
        relative = path.relative_to(tutorials).as_posix()
        if relative.startswith(COUPLED) or "pascal" in path.parts:
            continue
        found.setdefault(path.parent.relative_to(tutorials).as_posix(), []).append(path.name)
    return found


def thermo(text):
    """The thermo rows a run printed: {step: [values]} (a row repeated at a run's start keeps its
    first printing) and the column names."""
    rows, names, columns = {}, [], None
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            columns = len(words)
            names = names or words[1:]
            continue
        if line.startswith("Loop time"):
            columns = None
            continue
        if columns and len(words) == columns:
            try:
                values = [float(word) for word in words]
            except ValueError:
                continue
            rows.setdefault(int(values[0]), values[1:])
    return rows, names


def loop_time(text):
    """(seconds, steps) summed over the Loop time lines."""
    seconds = steps = 0
    for line in text.splitlines():
        match = LOOP.match(line)
        if match:
            seconds += float(match.group(1))
            steps += int(match.group(2))
    return seconds, steps


def why_failed(text, code):
    for line in text.splitlines():
        if line.startswith(("ERROR", "Traceback")) or "error" in line.lower().split(":")[0]:
            # the line, without the list of installed styles an unknown style's message ends with
            return line.strip().split(" (installed:")[0][:300]
    return f"exit {code}: " + (text.strip().splitlines() or ["(no output)"])[-1][:200]


def run_folder(command, tutorials, folder, names, k, timeout, label):
    """Every script of ``folder`` with seed set k in one copy: {name: result}."""
    work = BUILD / "runs" / f"{label}-{k}" / folder
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(tutorials / folder, work)
    results = {}
    for name in names:
        script = work / name
        script.write_text(with_seeds(script.read_text(), k))
        start = time.perf_counter()
        try:
            done = subprocess.run(command + ["-in", name, "-echo", "none", "-log", f"log.{name}"], cwd=work,
                                  capture_output=True, text=True, errors="replace", timeout=timeout,
                                  stdin=subprocess.DEVNULL)
            text, code = done.stdout + done.stderr, done.returncode
        except subprocess.TimeoutExpired as stopped:
            text, code = (stopped.stdout or b"").decode(errors="replace"), None
        wall = time.perf_counter() - start
        rows, columns = thermo(text)
        seconds, steps = loop_time(text)
        ended = code == 0 and "Loop time" in text
        result = {"ok": ended, "wall": round(wall, 2), "loop": round(seconds, 4), "steps": steps,
                  "columns": columns, "rows": {str(step): values for step, values in rows.items()}}
        if not ended:
            result["why"] = f"timeout ({timeout:g} s)" if code is None else why_failed(text, code)
        results[name] = result
        print(f"  {label} {folder}/{name} seeds {k}: {'ok' if ended else result['why']} ({wall:.0f} s)",
              file=sys.stderr, flush=True)
    return results


def excess(reference, candidates, steps, columns):
    """The largest distance, over rows and columns, of the mean of the ``candidates``' values (of
    log10 where every value is positive) outside the range of the ``reference``'s, in units of that
    range; at most 1 lies within the range widened by itself on each side. With where it is."""
    worst, where = 0.0, ""
    for s in steps:
        for c, name in enumerate(columns):
            values = [run["rows"][s][c] for run in reference]
            ours = [run["rows"][s][c] for run in candidates]
            raw = values + ours
            logarithmic = min(raw) > 0.0
            if logarithmic:
                values, ours = [math.log10(v) for v in values], [math.log10(v) for v in ours]
            mean = statistics.fmean(ours)
            # rows where every run agrees to round-off (free fall before the first contact); a count
            # (particles, contacts) is resolved to one
            counts = all(float(v).is_integer() for v in raw)
            if counts:
                floor = math.log10(1.0 + 1.0 / min(raw)) if logarithmic else 1.0
            else:
                floor = SAME if logarithmic else ROUNDOFF * max(1.0, max(map(abs, values)))
            distance = max(min(values) - mean, mean - max(values)) / max(max(values) - min(values), floor)
            if distance > worst:
                worst, where = distance, f"step {s} {name}"
    return worst, where


def compare(reference, mine):
    """The agreement of pdps's runs with the reference's: (kind, verdict, detail)."""
    steps = sorted(set.intersection(*(set(run["rows"]) for run in reference + mine)), key=int)
    columns = reference[0]["columns"]
    if not steps:
        return "none", False, "no thermo row both print"
    # by position: LIGGGHTS's header drops c_ and f_ and cuts names at 8 letters (rke for c_rke)
    if any(len(run["columns"]) != len(columns) for run in mine):
        return "none", False, f"other thermo columns: {mine[0]['columns']} against {columns}"
    if all(run["rows"][s] == reference[0]["rows"][s] for run in reference[1:] for s in steps):
        scale = [max(abs(reference[0]["rows"][s][c]) for s in steps) for c in range(len(columns))]
        for s in steps:
            for c, (want, got) in enumerate(zip(reference[0]["rows"][s], mine[0]["rows"][s])):
                if abs(got - want) > max(DETERMINISTIC * abs(want), ROUNDOFF * scale[c]):
                    return "deterministic", False, f"part at step {s}: {columns[c]} {want:g} against {got:g}"
        return "deterministic", True, f"{len(steps)} rows to the printed digits"
    worst, where = excess(reference, mine, steps, columns)
    if len(reference) < 4:
        return "statistical", worst <= 1.0, f"worst {worst:.2f} of the seeds' range ({where or 'none'})"
    # a permutation test: every choice of as many runs as pdps made, among all the runs, measured
    # against the others by the largest t over rows and columns; were pdps's runs more LIGGGHTS
    # runs, their choice would be as likely as any to be the most extreme
    runs = reference + mine
    chosen = tuple(range(len(reference), len(runs)))
    table = np.array([[run["rows"][s] for s in steps] for run in runs], dtype=np.float64)
    values, floor = resolution(table)
    measured = {group: largest_t(values, floor, group) for group in
                itertools.combinations(range(len(runs)), len(mine))}
    ours, (row, column) = measured[chosen]
    p_value = sum(value >= ours for value, _ in measured.values()) / len(measured)
    theirs = [value for group, (value, _) in measured.items() if max(group) < len(reference)]
    return "statistical", p_value > P_VALUE, (
        f"t = {ours:.1f} at step {steps[row]} {columns[column]} (worst {worst:.2f} of LIGGGHTS's range); "
        f"as extreme as {round(p_value * len(measured))} of the {len(measured)} choices of {len(mine)} of all "
        f"{len(runs)} runs (p = {p_value:.2f}; LIGGGHTS's own pairs: median t {statistics.median(theirs):.1f})")


def resolution(table, precision=DETERMINISTIC):
    """Per row and column, the smallest difference that counts: one for a count (particles), the
    printed precision (relative ``precision``) or round-off (ROUNDOFF of the column's largest) else,
    on log10 of positive values as the t test reads them."""
    logarithmic = (table > 0).all(axis=0)
    values = np.where(logarithmic, np.log10(np.where(logarithmic, table, 1.0)), table)
    counts = (table == np.round(table)).all(axis=0)
    smallest = np.where(table > 0, table, np.inf).min(axis=0)
    scale = np.abs(table).max(axis=(0, 1))
    floor = np.where(logarithmic, np.log10(1.0 + precision), np.maximum(precision * np.abs(table).max(axis=0),
                                                                        ROUNDOFF * scale))
    floor = np.where(counts & logarithmic, np.log10(1.0 + 1.0 / smallest), floor)
    floor = np.where(counts & ~logarithmic, 1.0, floor)
    return values, floor


def largest_t(values, floor, group):
    """(the largest pooled two-sample t of the runs ``group`` against the others over rows and
    columns, (row, column) where it is); the standard deviation no smaller than ``floor``."""
    inside = np.zeros(len(values), dtype=bool)
    inside[list(group)] = True
    a, b = values[inside], values[~inside]
    spread = ((a - a.mean(axis=0)) ** 2).sum(axis=0) + ((b - b.mean(axis=0)) ** 2).sum(axis=0)
    sd = np.maximum(np.sqrt(spread / (len(values) - 2)), floor)
    t = np.abs(a.mean(axis=0) - b.mean(axis=0)) / (sd * math.sqrt(1.0 / len(a) + 1.0 / len(b)))
    where = np.unravel_index(int(np.argmax(t)), t.shape)
    return float(t[where]), (int(where[0]), int(where[1]))


def per_step(run):
    return run["loop"] / run["steps"] if run.get("steps") else None


def table(results):
    lines = ["| script | LIGGGHTS | pdps runs unmodified | agrees | how compared | time a step, LIGGGHTS / pdps |",
             "|---|---|---|---|---|---|"]
    counted = ran = agreed = 0
    for script, entry in results["scripts"].items():
        reference, mine = entry["reference"], entry["pdps"]
        if not reference[0]["ok"]:
            lines.append(f"| {script} | fails: {reference[0]['why']} | (out of the count) | | | |")
            continue
        counted += 1
        if not all(run["ok"] for run in mine):
            why = next(run["why"] for run in mine if not run["ok"]).split(" (installed:")[0]
            lines.append(f"| {script} | runs | no: `{why}` | | | |")
            continue
        ran += 1
        kind, ok, detail = entry["agreement"]
        agreed += ok
        times = [min(filter(None, map(per_step, runs)), default=None) for runs in (reference, mine)]
        cell = " / ".join(f"{t * 1e6:.0f} us" if t else "-" for t in times)
        lines.append(f"| {script} | runs | yes | {'yes' if ok else 'no'} | {kind}: {detail} | {cell} |")
    lines.append("")
    lines.append(f"{ran} of the {counted} scripts LIGGGHTS runs run unmodified in pdps; {agreed} agree "
                 f"({results['date']}, {results['reference_seeds']} LIGGGHTS seed sets, {results['pdps_seeds']} pdps).")
    return "\n".join(lines)


def write_page(text):
    page = PAGE.read_text()
    head, rest = page.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    PAGE.write_text(head + BEGIN + "\n" + text + "\n" + END + tail)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", nargs="*", help="folder/script names (default: all)")
    parser.add_argument("--doc", help="an unpacked Tutorials_public folder instead of build/corpus's")
    parser.add_argument("--timeout", type=float, default=3600.0, help="seconds a run (default 3600)")
    parser.add_argument("--reference-seeds", type=int, default=4)
    parser.add_argument("--pdps-seeds", type=int, default=2)
    parser.add_argument("--rerun-reference", action="store_true",
                        help="run the reference program again (default: keep its recorded runs)")
    parser.add_argument("--keep-pdps", action="store_true",
                        help="keep pdps's recorded runs too (default: run pdps again)")
    parser.add_argument("--print", action="store_true", help="print the table, leave docs/ as it is")
    args = parser.parse_args()
    tutorials = doc_folder(args.doc)
    liggghts = ["bash", str(REFERENCE / "liggghts")]
    pdps = [str(Path(sys.executable).parent / "pdps"), "run", "--no-progress"]
    old = json.loads(RESULTS.read_text()) if RESULTS.exists() else {"scripts": {}}
    results = {"date": time.strftime("%Y-%m-%d"), "reference_seeds": args.reference_seeds,
               "pdps_seeds": args.pdps_seeds, "scripts": old["scripts"]}
    for folder, names in scripts(tutorials).items():
        if args.only and not any(item in (folder, f"{folder}/{name}") for item in args.only for name in names):
            continue
        # a folder's scripts run together, in order: the later ones read what the earlier ones wrote
        recorded = [old["scripts"].get(f"{folder}/{name}", {}) for name in names]
        held = 0 if args.rerun_reference else min(len(entry.get("reference", [])) for entry in recorded)
        # the seed sets recorded already, then the ones asked for beyond them
        reference = [{name: entry["reference"][k] for name, entry in zip(names, recorded)}
                     for k in range(min(held, args.reference_seeds))]
        reference += [run_folder(liggghts, tutorials, folder, names, k, args.timeout, "liggghts")
                      for k in range(len(reference), args.reference_seeds)]
        first = max(args.reference_seeds, PDPS_FIRST_SEED)
        if not any(runs[name]["ok"] for runs in reference for name in names):
            # the reference cannot run them: out of the count, nothing to compare pdps with
            mine = [{name: {"ok": False, "why": "not run: the reference program fails"} for name in names}]
        elif args.keep_pdps and min(len(entry.get("pdps", [])) for entry in recorded) >= args.pdps_seeds:
            mine = [{name: entry["pdps"][k] for name, entry in zip(names, recorded)} for k in range(args.pdps_seeds)]
        else:
            mine = [run_folder(pdps, tutorials, folder, names, k, args.timeout, "pdps")
                    for k in range(first, first + args.pdps_seeds)]
        for name in names:
            entry = {"reference": [runs[name] for runs in reference], "pdps": [runs[name] for runs in mine]}
            if entry["reference"][0]["ok"] and all(run["ok"] for run in entry["pdps"]):
                good = [run for run in entry["reference"] if run["ok"]]
                entry["agreement"] = compare(good, entry["pdps"])
            results["scripts"][f"{folder}/{name}"] = entry
        # after each folder: a long corpus run stopped half way keeps what it measured
        results["scripts"] = dict(sorted(results["scripts"].items()))
        RESULTS.write_text(json.dumps(results, indent=None, separators=(",", ":")) + "\n")
    text = table(results)
    print(text)
    if not args.print:
        write_page(text)


if __name__ == "__main__":
    main()
