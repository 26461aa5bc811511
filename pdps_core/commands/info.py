"""``info``: what the simulation holds now, in LIGGGHTS's categories and lines.

    info CATEGORY... [out screen|log|append FILE|overwrite FILE]

CATEGORY is one or more of all, system, communication, computes, dumps, fixes, groups, regions,
variables, time, configuration; as in LIGGGHTS 3.8.0 (its Info, 3.8.0 source) a word is known by
its first letters (``comm``, ``config``, ``var``: four for communication and computes, three for
the others) and a word it does not know draws a warning and is skipped. ``out`` sends the lines to
the screen (the default), the log, or a file appended to or overwritten; the last ``out`` given
holds. Only rank 0 prints. The lines are LIGGGHTS's, between two ``Info-Info-...`` rulers:

- system: units, particle style, the number of particles and of types and the pair style (none
  without one), no k-space style, the dimension, box lengths, boundary letters of each face and bounds;
- communication: the MPI level, brick decomposition and single cutoff (pdps's only ones), whether
  ghosts carry velocities, the ghost cutoff (that of the
  neighbor lists requested so far, or comm_modify's cutoff), the number of ranks, the processor grid;
- groups (in the order defined), regions (id, style, side in/out), computes and fixes (id, style,
  group), dumps (id, file, style, group, every), variables (name, style, definition);
- time: the processor and wall time since the simulation began; configuration: pdps's version, the
  Python and operating system, and the largest resident memory of the process.

Checked against LIGGGHTS 3.8.0 (tests/test_info.py: the facts it printed for a small granular
script, recorded in tests/data/liggghts_info.txt, compared one by one). Where pdps differs, openly:
LIGGGHTS calls the particle style ``granular``, pdps ``sphere`` (the same style: LIGGGHTS's name is
read as it); LIGGGHTS lists the two computes its thermo makes (thermo_temp, thermo_kin_eng), pdps's
thermo keeps none; LIGGGHTS 3.8.0 writes "Xlo, zhi" and "Ylo, zhi" where pdps writes "Xlo, xhi" and
"Ylo, yhi", and it prints each variable's style one place off in its table of names (an equal-style
variable as "format", an atom-style one as "equal", measured), pdps the style given; pdps has no
atom map, molecule templates, bonds or threads, and prints no line for them;
the MPI level is mpi4py's library's; configuration and time describe pdps and Python, not a C++
build.

Example::

    info system groups
    info all out append info.txt
"""

import platform
import resource
import sys
import time
from importlib import metadata
from typing import Literal

from ..errors import ScriptError
from ..styles import StyleArgs, keyword, param, parse_args
from . import command

USAGE = ("info CATEGORY... [out screen|log|append FILE|overwrite FILE]; categories: all system communication "
         "computes dumps fixes groups regions variables time configuration")
CATEGORIES = ("system", "communication", "computes", "dumps", "fixes", "groups", "regions", "variables", "time",
              "configuration")
# the letters LIGGGHTS's info compares (strncmp)
PREFIX = {"all": 3, "communication": 4, "computes": 4, "dumps": 3, "fixes": 3, "groups": 3, "regions": 3,
          "configuration": 3, "time": 3, "variables": 3, "system": 3}
# LIGGGHTS's order of the categories printed
ORDER = ("configuration", "communication", "system", "groups", "regions", "computes", "dumps", "fixes",
         "variables", "time")
RULER = "\nInfo-Info-Info-Info-Info-Info-Info-Info-Info-Info-Info\n"


class Args(StyleArgs):
    categories: list[Literal["all", *CATEGORIES]] = param(default_factory=list)
    out: tuple[Literal["screen", "log", "append", "overwrite"], str] | Literal["screen", "log"] = keyword("screen")


def _known(word):
    return next((name for name, n in PREFIX.items() if word[:n] == name[:n]), None)


def _words(sim, args):
    """The categories and the last ``out`` (LIGGGHTS's reading: out takes 1 or 2 words, the rest are
    categories by their first letters, an unknown one warned about and skipped)."""
    categories, out, i = [], None, 0
    while i < len(args):
        word = args[i]
        if word[:3] == "out" and i + 1 < len(args) and args[i + 1][:3] in ("scr", "log"):
            out, i = [args[i + 1][:3].replace("scr", "screen")], i + 2
        elif word[:3] == "out" and i + 2 < len(args) and args[i + 1][:3] in ("app", "ove"):
            out, i = [{"app": "append", "ove": "overwrite"}[args[i + 1][:3]], args[i + 2]], i + 3
        elif _known(word):
            categories.append(_known(word))
            i += 1
        else:
            sim.warn(f"Ignoring unknown or incorrect info command flag {word}")
            i += 1
    return categories + (["out", *out] if out else [])


@command("info")
def info(sim, args):
    args = parse_args(Args, _words(sim, args), usage=USAGE)
    wanted = set(CATEGORIES) if "all" in args.categories else set(args.categories)
    lines = [RULER, f"Printed on {time.ctime()}\n"]
    for category in ORDER:
        if category in wanted:
            lines += [""] + SECTIONS[category](sim)
    lines.append(RULER)
    if not sim.comm.is_root:
        return
    text = "\n".join(lines)
    out = args.out if isinstance(args.out, tuple) else (args.out,)
    if out[0] == "screen":
        screen = sim.output.screen
        if screen is not False:
            print(text, file=screen, flush=True)
    elif out[0] == "log":
        if sim.output.log is not None:
            print(text, file=sim.output.log, flush=True)
    else:
        try:
            with open(out[1], "a" if out[0] == "append" else "w") as handle:
                print(text, file=handle)
        except OSError as exc:
            raise ScriptError(f"info out {out[0]}: cannot write {out[1]}: {exc.strerror}") from None


def _system(sim):
    lines = ["System information:", f"Units      = {sim.units.name}", f"Atom style = {sim.particle_style}"]
    box = sim.box
    natoms = int(sim.comm.sum(sim.particles.nlocal)) if box is not None else 0
    pair = sim.pair.name if sim.pair is not None else "none"
    lines.append(f"Atoms = {natoms},  types = {sim.ntypes if box is not None else 0},  style = {pair}")
    lines.append("Kspace style = none")
    if box is None:
        return lines + ["", "Box has not yet been created"]
    faces = [word if len(word) == 2 else word * 2 for word in sim.system.periodicity]
    lines += ["", f"Dimensions = {sim.dimension}",
              "Orthogonal box = {:g} x {:g} x {:g}".format(*box.length),
              "Boundaries = " + " ".join(f"{w[0]},{w[1]}" for w in faces)]
    lines += [f"{axis}lo, {axis.lower()}hi = {box.lo[d]:g}, {box.hi[d]:g}" for d, axis in enumerate("XYZ")]
    return lines


def _communication(sim):
    import mpi4py.MPI as MPI
    major, minor = MPI.Get_version()
    grid = getattr(getattr(sim.comm, "decomposition", None), "grid", (1, 1, 1))
    return ["Communication information:", f"MPI library level: MPI v{major}.{minor}", "Comm style = brick",
            f"Communicate velocities for ghost atoms = {'yes' if sim.system.ghost_velocity else 'no'}",
            "Communication style = single", f"Communication cutoff = {sim.neighbor.ghost_cutoff():g}",
            f"Nprocs = {sim.comm.nprocs}",
            "Processor grid = {} x {} x {}".format(*(int(g) for g in grid))]


def _groups(sim):
    return ["Group information:"] + [f"Group[{k:2d}]: {name}" for k, name in enumerate(sim.groups.names())]


def _regions(sim):
    return ["Region information:"] + [
        f"Region[{k:3d}]: {rid},  style = {region.name},  side = {'out' if region.side_out else 'in'}"
        for k, (rid, region) in enumerate(sim.system.regions.items())]


def _computes(sim):
    return ["Compute information:"] + [f"Compute[{k:3d}]: {cid},  style = {c.name},  group = {c.group}"
                                       for k, (cid, c) in enumerate(sim.computes.items())]


def _dumps(sim):
    return ["Dump information:"] + [
        f"Dump[{k:3d}]: {did},  file = {d.path},  style = {d.name},  group = {d.group},  every = {d.every}"
        for k, (did, d) in enumerate(sim.output.dumps.items())]


def _fixes(sim):
    return ["Fix information:"] + [f"Fix[{k:3d}]: {fid},  style = {f.name},  group = {f.group}"
                                   for k, (fid, f) in enumerate(sim.fixes.items())]


def _variables(sim):
    lines = ["Variable information:"]
    for k, name in enumerate(sim.variables.names()):
        var = sim.variables._get(name)
        definition = " ".join(str(v) for v in var.values)
        lines.append(f"Variable[{k:3d}]: {name:<11s} style = {var.style:<11s} def = {definition}")
    return lines


def _time(sim):
    wall = time.perf_counter() - sim.output.started
    cpu = time.process_time()
    return ["Total time information (MPI rank 0):", f"  CPU time:    {_clock(cpu)}", f" Wall time:    {_clock(wall)}"]


def _clock(seconds):
    seconds = int(seconds)
    return f"{seconds // 3600}:{seconds // 60 % 60:02d}:{seconds % 60:02d}"


def _configuration(sim):
    try:
        version = metadata.version("pdps-core")
    except metadata.PackageNotFoundError:
        version = "(not installed)"
    uname = platform.uname()
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return [f"pdps version: {version} (Python {sys.version.split()[0]})", "",
            f"OS information: {uname.system} {uname.release} on {uname.machine}", "",
            "Memory allocation information (MPI rank 0)", f"Maximum resident set size: {peak:.3g} Mbyte"]


SECTIONS = {"system": _system, "communication": _communication, "groups": _groups, "regions": _regions,
            "computes": _computes, "dumps": _dumps, "fixes": _fixes, "variables": _variables, "time": _time,
            "configuration": _configuration}
