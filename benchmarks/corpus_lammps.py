"""LAMMPS's own examples inside pdps's field, run as their users run them, in pdps and in LAMMPS
(issue 34).

    make corpus                                  # or:
    .venv/bin/python benchmarks/corpus_lammps.py [--only melt/in.melt ...] [--timeout 1800]
                                                 [--reference-seeds 5] [--pdps-seeds 2] [--print]

Where the scripts come from: Debian's ``lammps-examples`` (LAMMPS's examples/ tree as of January
2022), fetched with ``apt-get download`` and unpacked into build/corpus/lammps-examples when it is
not there yet (``--examples`` names another unpacked examples/ folder). The scripts are GPL: they are
read there and run in copies of their folders under build/corpus/runs/, never copied into the
project; benchmarks/results/corpus_lammps.json keeps the numbers only. FIELD lists the examples of
the field and OUT_OF_FIELD says why each other folder is out; docs/lammps.md shows both.

How each script runs, unmodified but for two things done alike in both programs:
- Long runs are cut: a ``run N`` with N above ``--steps`` (5000) runs that many steps (a literal N,
  or a ``${name}`` whose ``variable name equal|index`` line gives a number; where its line works it
  out from numbers and other such variables, ``floor(${tprod}/${dt})``, the run line itself is cut
  and the variable keeps its value for the script's other uses). Where LAMMPS refuses the
  cut script (an average falling due past the cut), both programs run it whole.
- Seed set k > 0 replaces each seed of the script (``velocity create``, ``fix langevin``, fix rigid*'s
  ``langevin`` keyword, ``fix
  pour``, ``pair_style dpd*``, ``create_atoms random``, ``fix wall/reflect/stochastic``, ...; where
  the seed is a ``${name}``, the number of its ``variable`` line) by a prime of its own; set 0 is
  the script's own seeds.

LAMMPS (``../shared/bench/lmp``, or ``$PDPS_LAMMPS_BENCH/lmp``) runs seed set 0 on one rank and on
two, and seed sets 1 .. ``--reference-seeds``-1; pdps (this checkout's ``.venv``, ``pdps -in SCRIPT``
as LAMMPS's ``lmp`` is called) runs set 0 and ``--pdps-seeds`` sets of its own (numbered from 100).
Where pdps stops at a line, LAMMPS runs set 0 only (the others wait until pdps runs the script).
The reference's runs are kept in the results file and made again only with ``--rerun-reference``.

What the table says, per script (between docs/lammps.md's ``corpus:begin`` and ``corpus:end``):
- runs: pdps ran it to its end (exit 0, its last ``Loop time`` line printed); else pdps's first
  ``ERROR`` line, or ``timeout``. Where LAMMPS itself fails, the script is out of the count.
- agrees, compared on the thermo rows both print, column by column by name (the wall clock's
  columns, CPU and its kin, left out):
  - printed digits: pdps's set 0 prints LAMMPS's set 0 to every digit (one unit in the last of
    LAMMPS's 8 significant digits, or 1e-12 of the column's largest value at round-off) on every row;
  - until chaos: else the step where they part is given beside the step where LAMMPS on two ranks
    parts from LAMMPS on one (its own round-off, summed in another order); a script without seeds
    agrees when pdps parts no earlier than half that step;
  - statistics: a script with seeds agrees when its runs pass the permutation test of
    benchmarks/corpus.py: every choice of two of all the runs (LAMMPS's sets and pdps's two) is
    measured against the others by the largest pooled two-sample t over rows and columns, and pdps
    agrees unless its two are among the most extreme (p > 0.05; with 5 LAMMPS sets there are 21
    choices, so pdps fails where its pair is the most extreme of all). A script that agrees fails
    that test one time in twenty: a flagged script is measured again on 10 LAMMPS seed sets and 4
    of pdps's (CONFIRM; the first runs kept, 1001 choices) and the larger test's verdict stands.
- time a step, both programs: the sum of the ``Loop time`` lines over the steps they count, the
  fastest of each program's runs on one rank.

Not part of ``make test``: a full run takes about an hour on this 2-core machine.
"""

import argparse
import itertools
import json
import math
import re
import shutil
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from corpus import (BEGIN, BUILD, END, P_VALUE, PDPS_FIRST_SEED, REFERENCE, ROUNDOFF, largest_t, loop_time,
                    resolution, seed_set, unpacked, why_failed)

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
PAGE = ROOT / "docs" / "lammps.md"
RESULTS = HERE / "results" / "corpus_lammps.json"
EXAMPLES = Path("usr/share/lammps/examples")
DIGITS = 8                  # LAMMPS's thermo prints 8 significant digits (%.8g)
STEPS = 5000
# the seed sets (LAMMPS's, pdps's) a script the first permutation test flags is measured again on
CONFIRM = (10, 4)
# thermo columns of the wall clock, which no two runs share
CLOCK = {"CPU", "T/CPU", "S/CPU", "CPULeft"}

# The examples of the field: LJ, soft and table pairs, DPD, granular, rigid bodies, walls,
# thermostats and barostats, minimization, deformation, transport.
FIELD = [
    "melt/in.melt",
    "min/in.min", "min/in.min.box",
    *(f"rigid/in.rigid{tail}" for tail in ("", ".atomfile", ".atomvar", ".early", ".gravity", ".nve",
                                            ".nve.early", ".property", ".tnr")),
    "pour/in.pour", "pour/in.pour.2d", "pour/in.pour.2d.molecule",
    "granregion/in.granregion.box", "granregion/in.granregion.funnel", "granregion/in.granregion.mixer",
    "granular/in.pour.drum", "granular/in.pour.flatwall",
    "multi/in.granular", "multi/in.powerlaw",
    "wall/in.wall.ccl", "wall/in.wall.diffusive", "wall/in.wall.maxwell", "wall/in.wall.specular",
    "UNITS/in.ar.lj", "UNITS/in.ar.metal", "UNITS/in.ar.real",
    "DIFFUSE/in.msd.2d", "DIFFUSE/in.vacf.2d",
    "VISCOSITY/in.einstein.2d", "VISCOSITY/in.gk.2d", "VISCOSITY/in.mp.2d", "VISCOSITY/in.nemd.2d",
    "VISCOSITY/in.wall.2d",
    "KAPPA/in.ehex", "KAPPA/in.heat", "KAPPA/in.heatflux", "KAPPA/in.langevin", "KAPPA/in.mp",
    "HEAT/in.lj.ehex", "HEAT/in.lj.hex",
    "flow/in.flow.couette", "flow/in.flow.pois",
    "friction/in.friction",
    "indent/in.indent", "indent/in.indent.min",
    "obstacle/in.obstacle",
    "nemd/in.nemd",
    "crack/in.crack",
    "micelle/in.micelle", "micelle/in.micelle-rigid",
    "balance/in.balance",
    "numdiff/in.numdiff",
    "PACKAGES/dpd-basic/dpdext/in.dpdext", "PACKAGES/dpd-basic/dpdext_tstat/in.cg_spce",
]

# Why every other folder of LAMMPS's examples is out of the field (scripts of a folder in FIELD
# that are not listed there: the reason under "folder/").
OUT_OF_FIELD = {
    "rigid/": "in.rigid.poems, in.rigid.poems2: fix poems needs the POEMS library, which the reference "
              "LAMMPS build lacks",
    "VISCOSITY/": "in.cos.1000SPCE: SPC/E water, charges with a long-range solver",
    "HEAT/": "in.spce.ehex, in.spce.hex: SPC/E water, charges with a long-range solver",
    "multi/": "in.colloid: pair colloid (integrated colloid-colloid potentials)",
    "balance/": "the other eleven are in.balance's scene balanced by other weights (clock, group, "
                "neighbors, a variable), with bonds or with a long-range solver: on one rank, "
                "balancing changes no number, and in.balance stands for them",
    "ASPHERE": "ellipsoids, lines, triangles and stochastic rotation dynamics (fix srd)",
    "COUPLE": "LAMMPS as a library driven by other programs",
    "ELASTIC": "Stillinger-Weber silicon (a three-body potential)",
    "ELASTIC_T": "Stillinger-Weber silicon (a three-body potential)",
    "MC": "Monte Carlo moves (fix bond/swap and the like)",
    "SPIN": "magnetic spins",
    "airebo": "AIREBO hydrocarbon many-body potential",
    "atm": "Axilrod-Teller-Muto three-body potential",
    "body": "body particles (polygons, polyhedra)",
    "cmap": "CHARMM force field with CMAP corrections",
    "colloid": "pair colloid (integrated colloid potentials)",
    "comb": "COMB charge-optimized many-body potentials",
    "controller": "fix controller (feedback control of a variable)",
    "coreshell": "core-shell ions with a long-range solver",
    "deposit": "fix deposit (atoms and molecules deposited onto a substrate)",
    "dipole": "point dipoles",
    "dreiding": "DREIDING force field with hydrogen bonds",
    "eim": "embedded-ion method potential",
    "ellipse": "Gay-Berne and RE-squared ellipsoids",
    "fire": "FIRE minimization and nudged elastic band of silicon vacancies",
    "gcmc": "grand canonical Monte Carlo",
    "gjf": "Gronbech-Jensen-Farago Langevin on a molecular force field with charges",
    "hugoniostat": "shock Hugoniostat (fix nphug) for metals",
    "hyper": "hyperdynamics",
    "kim": "OpenKIM models",
    "latte": "LATTE tight-binding quantum chemistry",
    "meam": "MEAM metal potentials",
    "message": "client-server coupling to other codes",
    "mliap": "machine-learned potentials",
    "mscg": "multiscale coarse-graining fits",
    "msst": "multi-scale shock technique",
    "nb3b": "non-bonded three-body potential",
    "neb": "nudged elastic band (multiple replicas)",
    "peptide": "CHARMM peptide with charges and a long-range solver",
    "peri": "peridynamics",
    "prd": "parallel replica dynamics",
    "python": "Python-defined styles and callbacks inside LAMMPS",
    "qeq": "charge equilibration",
    "rdf-adf": "SPC/E water, charges with a long-range solver",
    "reaxff": "ReaxFF reactive force field",
    "relres": "RelRes multiscale coarse-grained potential",
    "rerun": "rerun and read_dump of dump files of another run",
    "shear": "EAM metal potentials",
    "snap": "SNAP machine-learned potentials",
    "srd": "stochastic rotation dynamics (fix srd)",
    "steinhardt": "Steinhardt-Nelson bond-orientational order of metals",
    "streitz": "Streitz-Mintmire potential with charge equilibration",
    "tad": "temperature-accelerated dynamics",
    "template": "molecular templates of a molecular force field",
    "tersoff": "Tersoff three-body potentials",
    "threebody": "three-body potentials (SW, Tersoff, ...)",
    "tracker": "fix pair/tracker (contact lifetimes of pair/tracker)",
    "ttm": "two-temperature model of electrons and ions",
    "vashishta": "Vashishta three-body potential",
    "voronoi": "Voronoi tessellation (the VORONOI library)",
    "PACKAGES": "the optional packages' examples: force fields, methods and couplings outside the field "
                "(machine-learned and many-body potentials, quantum and electronic methods, Drude "
                "oscillators, path integrals, coupling to other programs, smoothed-particle and "
                "Lattice-Boltzmann hydrodynamics, mesoscopic DPD variants with extra state); in the "
                "field: dpd-basic",
}

# A seed, by command: (first word, the word that names the style and its index, the seed's index)
SEEDS = [
    ("velocity", 2, "create", 4),
    ("create_atoms", 2, "random", 4),
    ("displace_atoms", 2, "random", 6),
    ("fix", 3, "langevin", 7),
    ("fix", 3, "temp/csvr", 7),
    ("fix", 3, "temp/csld", 7),
    ("fix", 3, "pour", 6),
    ("fix", 3, "deposit", 7),
    ("fix", 3, "evaporate", 7),
    ("fix", 3, "wall/reflect/stochastic", 5),
]
# seeds after a keyword: (command, style word's index, style prefix, keyword, the seed's index after it)
KEYWORD_SEEDS = [
    ("fix", 3, "rigid", "langevin", 4),         # fix rigid* ... langevin TSTART TSTOP TPERIOD SEED
    ("fix", 3, "bond/", "prob", 2),             # fix bond/create, bond/break ... prob P SEED
    ("set", 0, "set", "type/fraction", 3),      # set ... type/fraction TYPE FRACTION SEED
    ("set", 0, "set", "type/ratio", 3),
    ("set", 0, "set", "type/subset", 3),
]
# pair styles with a seed: the seed's index after the style's name
PAIR_SEEDS = {"dpd": 3, "dpd/tstat": 4, "dpd/ext": 3, "dpd/ext/tstat": 4}
VARIABLE = re.compile(r"^\$\{(\w+)\}$|^\$(\w)$")


def examples_folder(given):
    """The unpacked examples/ folder: ``given``, or build/corpus/lammps-examples's, fetched when missing."""
    if given is not None:
        return Path(given)
    target = BUILD / "lammps-examples"
    if not (target / EXAMPLES).is_dir():
        unpacked("lammps-examples", target)
    return target / EXAMPLES


def unlisted(examples):
    """Folders of the examples neither in FIELD nor explained by OUT_OF_FIELD: the list must stay whole."""
    inside = {script.split("/")[0] for script in FIELD}
    return sorted(path.name for path in examples.iterdir() if path.is_dir() and path.name not in inside
                  and path.name not in OUT_OF_FIELD and any(path.rglob("in.*")))


def variables(lines):
    """{name: line index} of the ``variable NAME equal|index NUMBER`` lines."""
    found = {}
    for i, line in enumerate(lines):
        words = line.split("#")[0].split()
        if len(words) >= 4 and words[0] == "variable" and words[2] in ("equal", "index") and \
                re.fullmatch(r"-?\d+(\.\d*)?([eE][-+]?\d+)?", words[3]):
            found.setdefault(words[1], i)
    return found


def evaluated(lines, name, depth=0):
    """The number a ``variable NAME equal EXPRESSION`` line gives where its expression is
    arithmetic of numbers and other such variables (``floor(${tprod}/${dt})``), else None."""
    rows = [line.split("#")[0].split() for line in lines]
    row = next((words for words in rows if len(words) >= 4 and words[0] == "variable" and words[1] == name
                and words[2] in ("equal", "index")), None)
    if row is None or depth > 20:
        return None
    expression = " ".join(row[3:]).strip("\"'")

    def value(match):
        found = evaluated(lines, match.group(1) or match.group(2), depth + 1)
        if found is None:
            raise ValueError(match.group(0))
        return repr(found)

    try:
        expression = re.sub(r"\$\{(\w+)\}|\$(\w)", value, expression)
        if not re.fullmatch(r"[-+*/^().\deE\s]*", re.sub(r"\b(floor|ceil|sqrt)\(", "(", expression)):
            return None
        return float(eval(expression.replace("^", "**"), {"__builtins__": {}},
                          {"floor": math.floor, "ceil": math.ceil, "sqrt": math.sqrt}))
    except (ValueError, SyntaxError, ZeroDivisionError, TypeError, OverflowError):
        return None


def seed_places(lines):
    """(line index, word index) of every seed of the script, a ``${name}`` resolved to its variable."""
    places, named = [], variables(lines)
    for i, line in enumerate(lines):
        words = line.split("#")[0].split()
        spots = [index for command, style_at, style, index in SEEDS
                 if words[:1] == [command] and len(words) > index and words[style_at] == style]
        for command, style_at, prefix, keyword, offset in KEYWORD_SEEDS:
            if words[:1] == [command] and len(words) > style_at and words[style_at].startswith(prefix):
                spots += [at + offset for at, word in enumerate(words) if word == keyword and len(words) > at + offset]
        if words[:1] == ["pair_style"]:
            spots += [at + PAIR_SEEDS[word] for at, word in enumerate(words)
                      if word in PAIR_SEEDS and len(words) > at + PAIR_SEEDS[word]]
        for index in spots:
            match = VARIABLE.match(words[index])
            if match and (match.group(1) or match.group(2)) in named:
                places.append((named[match.group(1) or match.group(2)], 3))
            elif re.fullmatch(r"\d+", words[index]):
                places.append((i, index))
    return list(dict.fromkeys(places))


def replace_word(line, index, value):
    """The line with its word ``index`` replaced, its spacing kept."""
    parts = re.split(r"(\s+)", line.split("#")[0])
    words = [k for k, part in enumerate(parts) if part and not part.isspace()]
    parts[words[index]] = value
    return "".join(parts) + (line[len(line.split("#")[0]):])


def prepared(text, k, steps):
    """The script with seed set k (0: its own) and its long runs cut to ``steps`` (None: uncut)."""
    lines = text.splitlines()
    if k:
        places = seed_places(lines)
        values = {}
        for place, prime in zip(places, seed_set(k, len(places))):
            values[place] = str(prime)
        for (i, index), value in values.items():
            lines[i] = replace_word(lines[i], index, value)
    named = variables(lines)
    for i, line in enumerate(lines):
        words = line.split("#")[0].split()
        if steps is None or words[:1] != ["run"] or len(words) < 2:
            continue
        word, match = words[1], VARIABLE.match(words[1])
        if match and (match.group(1) or match.group(2)) in named:
            at = named[match.group(1) or match.group(2)]
            value = float(lines[at].split()[3])
            if value > steps:
                lines[at] = replace_word(lines[at], 3, str(steps))
        elif re.fullmatch(r"\d+", word) and int(word) > steps:
            lines[i] = replace_word(line, 1, str(steps))
        elif match and (evaluated(lines, match.group(1) or match.group(2)) or 0.0) > steps:
            # a length worked out from other variables: the run line itself is cut, the variable
            # keeps its value for the script's other uses
            lines[i] = replace_word(line, 1, str(steps))
    return "\n".join(lines) + "\n"


def thermo(text):
    """The thermo rows a run printed: {"RUN:STEP": {column: value}}, RUN counting the runs (and
    minimizations) from 1, so that a run after reset_timestep keeps its rows apart."""
    rows, names, run = {}, None, 0
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            names, run = words, run + 1
            continue
        if line.startswith("Loop time") or not words:
            names = None
            continue
        if names and len(words) == len(names):
            try:
                values = [float(word) for word in words]
            except ValueError:
                continue
            rows.setdefault(f"{run}:{int(values[0])}", {name: value for name, value in zip(names[1:], values[1:])
                                                       if name not in CLOCK})
    return rows


def order(key):
    """Sort key of a row's "RUN:STEP"."""
    run, step = key.split(":")
    return int(run), int(step)


def shown(key):
    """A row's "RUN:STEP" as the table says it: step S (of run R after the first)."""
    run, step = key.split(":")
    return f"step {step}" + (f" of run {run}" if run != "1" else "")


def run_script(command, examples, script, k, steps, timeout, label):
    """One script with seed set k in a fresh copy of its folder: its result."""
    folder, name = script.rsplit("/", 1)
    work = BUILD / "runs" / f"lammps-{label}-{k}" / folder
    shutil.rmtree(work, ignore_errors=True)
    shutil.copytree(examples / folder, work)
    (work / name).write_text(prepared((examples / script).read_text(errors="replace"), k, steps))
    start = time.perf_counter()
    try:
        done = subprocess.run(command + ["-in", name, "-echo", "none", "-log", f"log.{name}"], cwd=work,
                              capture_output=True, text=True, errors="replace", timeout=timeout,
                              stdin=subprocess.DEVNULL)
        text, code = done.stdout + done.stderr, done.returncode
    except subprocess.TimeoutExpired as stopped:
        text, code = (stopped.stdout or b"").decode(errors="replace"), None
    wall = time.perf_counter() - start
    seconds, counted = loop_time(text)
    ended = code == 0 and "Loop time" in text
    result = {"ok": ended, "wall": round(wall, 2), "loop": round(seconds, 4), "steps": counted,
              "rows": thermo(text)}
    warnings = [line.strip()[:200] for line in text.splitlines() if line.startswith("WARNING")]
    if warnings:
        result["warnings"] = list(dict.fromkeys(warnings))[:5]
    if not ended:
        result["why"] = f"timeout ({timeout:g} s)" if code is None else why_failed(text, code)
    print(f"  {label} {script} seeds {k}: {'ok' if ended else result['why']} ({wall:.0f} s)", file=sys.stderr,
          flush=True)
    return result


def digit(value):
    """One unit in the last of the DIGITS significant digits LAMMPS prints of ``value``."""
    return 10.0 ** (np.floor(np.log10(abs(value))) - (DIGITS - 1)) if value else 0.0


def parting(reference, other):
    """(the first row, "RUN:STEP", where ``other`` parts from ``reference`` beyond the printed digits,
    or None, the column, the two values, the row's index), over the rows and columns both print."""
    steps = sorted(set(reference["rows"]) & set(other["rows"]), key=order)
    scale = {}
    for s in steps:
        for c, value in reference["rows"][s].items():
            scale[c] = max(scale.get(c, 0.0), abs(value))
    for index, s in enumerate(steps):
        for c, want in reference["rows"][s].items():
            got = other["rows"][s].get(c)
            if got is not None and abs(got - want) > max(1.01 * digit(want), ROUNDOFF * scale[c]):
                return s, c, want, got, index
    return None, None, None, None, None


def statistics_verdict(reference, mine):
    """(agrees, detail) of the permutation test over the values (row and column) every run prints."""
    runs = reference + mine
    steps = sorted(set.intersection(*(set(run["rows"]) for run in runs)), key=order)
    features = [(s, c) for s in steps for c in reference[0]["rows"][s] if all(c in run["rows"][s] for run in runs)]
    if not features:
        return False, "no thermo value every run prints"
    table = np.array([[[run["rows"][s][c] for s, c in features]] for run in runs], dtype=np.float64)
    values, floor = resolution(table, 10.0 ** -(DIGITS - 1))
    # round-off is judged against the column's largest value over every row, not the row's own (a
    # mean square displacement of 1e-28 at a run's start is 0 printed another way); a count's
    # resolution is never finer than the printed digits (1e20, LAMMPS's BIG, is a count too)
    largest = {}
    for (s, c), column in zip(features, table[:, 0, :].T):
        largest[c] = max(largest.get(c, 0.0), float(np.abs(column).max()))
    logarithmic = (table > 0).all(axis=0)[0]
    roundoff = np.array([ROUNDOFF * largest[c] for _, c in features])
    floor[0] = np.where(logarithmic, np.maximum(floor[0], np.log10(1.0 + 10.0 ** -(DIGITS - 1))),
                        np.maximum(floor[0], roundoff))
    chosen = tuple(range(len(reference), len(runs)))
    measured = {group: largest_t(values, floor, group) for group in
                itertools.combinations(range(len(runs)), len(mine))}
    ours, (_, at) = measured[chosen]
    p_value = sum(value >= ours for value, _ in measured.values()) / len(measured)
    theirs = [value for group, (value, _) in measured.items() if max(group) < len(reference)]
    s, c = features[at]
    return p_value > P_VALUE, (
        f"t = {ours:.1f} at {shown(s)} {c}, as extreme as {round(p_value * len(measured))} "
        f"of the {len(measured)} choices of {len(mine)} of {len(runs)} runs (p = {p_value:.2f}; LAMMPS's own "
        f"pairs: median t {statistics.median(theirs):.1f})")


def compare(entry, seeded):
    """(how, agrees, detail) of pdps's runs against LAMMPS's."""
    own, twin = entry["reference"][0], entry.get("twin")
    mine = entry["pdps"][0]
    common = sorted(set(own["rows"]) & set(mine["rows"]), key=order)
    if not common:
        return "none", False, "no thermo row both print"
    for s in common:
        missing = [c for c in own["rows"][s] if c not in mine["rows"][s]]
        if missing:
            return "none", False, f"pdps prints no {', '.join(missing)} at {shown(s)} ({', '.join(mine['rows'][s])})"
    step, column, want, got, index = parting(own, mine)
    if step is None:
        return "printed digits", True, f"{len(common)} rows to every printed digit"
    chaos, *_, chaos_index = parting(own, twin) if twin and twin["ok"] else (None, None, None, None, None)
    parted = f"part at {shown(step)} ({column} {want:.8g} against {got:.8g})"
    parted += f"; LAMMPS on 2 ranks parts at {shown(chaos)}" if chaos is not None else \
        "; LAMMPS on 2 ranks prints every digit of 1"
    if seeded and len(entry["reference"]) > 1:
        ok, detail = statistics_verdict(entry["reference"], entry["pdps"][1:] or entry["pdps"])
        return "statistics", ok, parted + "; " + detail
    ok = chaos is not None and index >= chaos_index / 2
    return "until chaos", ok, parted


def per_step(run):
    return run["loop"] / run["steps"] if run.get("ok") and run.get("steps") else None


def table(results):
    lines = ["| example | LAMMPS | pdps runs unmodified | agrees | how compared | time a step, LAMMPS / pdps |",
             "|---|---|---|---|---|---|"]
    counted = ran = agreed = pending = 0
    for script in FIELD:
        entry = results["scripts"].get(script)
        if entry is None:
            pending += 1
            lines.append(f"| {script} | not run yet | | | | |")
            continue
        reference, mine = entry["reference"], entry["pdps"]
        if not reference[0]["ok"]:
            lines.append(f"| {script} | fails: {reference[0]['why']} | (out of the count) | | | |")
            continue
        counted += 1
        if not all(run["ok"] for run in mine):
            why = next(run["why"] for run in mine if not run["ok"]).split(" (installed:")[0].replace("|", "\\|")
            lines.append(f"| {script} | runs | no: `{why}` | | | |")
            continue
        ran += 1
        how, ok, detail = entry["agreement"]
        agreed += ok
        times = [min(filter(None, map(per_step, runs)), default=None) for runs in (reference, mine)]
        cell = " / ".join(f"{t * 1e6:.0f} us" if t else "-" for t in times)
        whole = " (run whole)" if entry.get("steps", results["steps"]) is None else ""
        lines.append(f"| {script} | runs{whole} | yes | {'yes' if ok else 'no'} | {how}: {detail} | {cell} |")
    lines.append("")
    lines.append(f"{ran} of the {counted} examples LAMMPS runs run unmodified in pdps; {agreed} agree "
                 f"({results['date']}, runs cut to {results['steps']} steps, {results['reference_seeds']} LAMMPS "
                 f"seed sets, {results['pdps_seeds']} of pdps's; {CONFIRM[0]} and {CONFIRM[1]} where the first test flagged "
                 f"a script)" + (f"; {pending} of the {len(FIELD)} not run yet." if pending
                                                                  else "."))
    lines.append("")
    lines.append("Out of the field, by folder of LAMMPS's examples:")
    lines.append("")
    lines += [f"- {folder.rstrip('/')}{' (the others)' if folder.endswith('/') else ''}: {reason}"
              for folder, reason in sorted(OUT_OF_FIELD.items())]
    return "\n".join(lines)


def write_page(text):
    page = PAGE.read_text()
    head, rest = page.split(BEGIN, 1)
    tail = rest.split(END, 1)[1]
    PAGE.write_text(head + BEGIN + "\n" + text + "\n" + END + tail)


def confirm(entry, lammps, pdps, examples, script, steps, timeout):
    """A script the permutation test flags is measured again on more seed sets (CONFIRM: LAMMPS's,
    then pdps's), the first runs kept; the larger test's verdict stands (a script that agrees
    fails the first test one time in twenty)."""
    references, mine = CONFIRM
    reference = entry["reference"]
    reference += [run_script(lammps, examples, script, k, steps, timeout, "lammps")
                  for k in range(len(reference), references)]
    entry["pdps"] += [run_script(pdps, examples, script, k, steps, timeout, "pdps")
                      for k in range(PDPS_FIRST_SEED + len(entry["pdps"]) - 1, PDPS_FIRST_SEED + mine)]
    if all(run["ok"] for run in reference + entry["pdps"]):
        entry["agreement"] = compare(entry, True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", nargs="*", help="folder or folder/script names (default: all of FIELD)")
    parser.add_argument("--examples", help="an unpacked examples/ folder instead of build/corpus's")
    parser.add_argument("--timeout", type=float, default=1800.0, help="seconds a run (default 1800)")
    parser.add_argument("--steps", type=int, default=STEPS, help="the longest run kept (default 5000)")
    parser.add_argument("--reference-seeds", type=int, default=5)
    parser.add_argument("--pdps-seeds", type=int, default=2)
    parser.add_argument("--rerun-reference", action="store_true")
    parser.add_argument("--print", action="store_true", help="print the table, leave docs/ as it is")
    args = parser.parse_args()
    examples = examples_folder(args.examples)
    missing = unlisted(examples)
    if missing:
        sys.exit(f"corpus_lammps.py: folders neither in FIELD nor in OUT_OF_FIELD: {', '.join(missing)}")
    lammps = ["bash", str(REFERENCE / "lmp")]
    pdps = [str(Path(sys.executable).parent / "pdps")]
    old = json.loads(RESULTS.read_text()) if RESULTS.exists() else {"scripts": {}}
    if old.get("steps", args.steps) != args.steps:
        old["scripts"] = {}
    results = {"date": time.strftime("%Y-%m-%d"), "steps": args.steps, "reference_seeds": args.reference_seeds,
               "pdps_seeds": args.pdps_seeds, "scripts": old["scripts"]}
    for script in FIELD:
        if args.only and not any(script == item or script.startswith(item.rstrip("/") + "/") for item in args.only):
            continue
        seeded = bool(seed_places((examples / script).read_text(errors="replace").splitlines()))
        recorded = {} if args.rerun_reference else old["scripts"].get(script, {})
        wanted = args.reference_seeds if seeded else 1
        steps = recorded.get("steps", args.steps)
        reference = recorded.get("reference", [])[:wanted]
        if not reference:
            reference = [run_script(lammps, examples, script, 0, steps, args.timeout, "lammps")]
            if not reference[0]["ok"] and not reference[0]["why"].startswith("timeout"):
                # a cut run LAMMPS refuses (an average due past the cut): both programs run it whole
                uncut = run_script(lammps, examples, script, 0, None, args.timeout, "lammps")
                if uncut["ok"]:
                    steps, reference = None, [uncut]
        entry = {"seeded": seeded, "steps": steps, "reference": reference, "twin": recorded.get("twin")}
        if not reference[0]["ok"]:
            entry["pdps"] = [{"ok": False, "why": "not run: LAMMPS fails"}]
        else:
            # pdps's own seeds first: where pdps stops, LAMMPS's other seed sets and its run on
            # two ranks wait until it runs
            entry["pdps"] = [run_script(pdps, examples, script, 0, steps, args.timeout, "pdps")]
            if entry["pdps"][0]["ok"]:
                reference += [run_script(lammps, examples, script, k, steps, args.timeout, "lammps")
                              for k in range(len(reference), wanted)]
                if entry["twin"] is None:
                    entry["twin"] = run_script(["env", "NP=2"] + lammps, examples, script, 0, steps, args.timeout,
                                               "lammps-2")
                for k in range(PDPS_FIRST_SEED, PDPS_FIRST_SEED + args.pdps_seeds) if seeded else ():
                    entry["pdps"].append(run_script(pdps, examples, script, k, steps, args.timeout, "pdps"))
                    if not entry["pdps"][-1]["ok"]:
                        break
                if all(run["ok"] for run in entry["pdps"]):
                    entry["agreement"] = compare(entry, seeded)
                if seeded and entry.get("agreement", ("", True))[:2] == ("statistics", False):
                    confirm(entry, lammps, pdps, examples, script, steps, args.timeout)
        results["scripts"][script] = entry
        RESULTS.write_text(json.dumps(results, indent=None, separators=(",", ":")) + "\n")
    # the verdicts from the runs as recorded, by this version's rules
    for entry in results["scripts"].values():
        if entry["reference"][0]["ok"] and all(run["ok"] for run in entry["pdps"]):
            entry["agreement"] = compare(entry, entry["seeded"])
    RESULTS.write_text(json.dumps(results, indent=None, separators=(",", ":")) + "\n")
    text = table(results)
    print(text)
    if not args.print:
        write_page(text)


if __name__ == "__main__":
    main()
