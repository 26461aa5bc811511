"""The ``pdps`` command.

    pdps run [SCRIPT] [-in SCRIPT] [-var NAME VALUE...]... [-log FILE|none] [-screen FILE|none]
             [-echo none|screen|log|both] [--dialect lammps|liggghts|pdps] [--no-progress] [--debug]
                                a script (or standard input, as lmp reads it when no -in is given)
    pdps -in SCRIPT ...         the same, spelled as LAMMPS's lmp is called
    pdps plot LOG [-o PNG] [--columns COLUMN...]   thermo columns against step, one panel each
    pdps styles [-v]            every installed style, by kind, with its distribution and version, marked
                                broken, incompatible or disabled where it is; -v: hooks, needs, contributions
    pdps doc KIND STYLE         a style's manual page (imports only that style)
    pdps new-plugin NAME [--kind pair|fix|compute|region|dump|contact] [--style STYLE]
                                a working, tested plugin skeleton in plugins/KIND_NAME
"""

import argparse
import os
import sys
import traceback

from .errors import ScriptError, clip


def _parser():
    parser = argparse.ArgumentParser(prog="pdps", description="particle dynamics, PDPS/LAMMPS scripts")
    sub = parser.add_subparsers(dest="action", required=True)
    run = sub.add_parser("run", help="run an input script")
    run.add_argument("script", nargs="?", help="the input script (or -in SCRIPT; standard input if neither)")
    run.add_argument("-in", "-i", dest="script_in", metavar="SCRIPT", help="the input script, as LAMMPS's -in")
    run.add_argument("-var", "-v", nargs="+", action="append", default=[], metavar="NAME VALUE",
                     help="define an index variable with one or more values, as LAMMPS's -var")
    run.add_argument("-log", "-l", default="log.pdps", help="log file (default log.pdps; none for no log)")
    run.add_argument("-screen", "-sc", default=None, metavar="FILE|none",
                     help="screen output to FILE, or none (default: the terminal)")
    run.add_argument("-echo", "-e", choices=["none", "screen", "log", "both"], default=None,
                     help="where commands are echoed as read (default log), as LAMMPS's -echo")
    run.add_argument("--dialect", choices=["lammps", "liggghts", "pdps"], default=None,
                     help="read the script as LAMMPS, LIGGGHTS or PDPS (default: as its lines say; docs/lammps.md)")
    run.add_argument("--no-progress", action="store_true",
                     help="no progress line (percent done, steps/s, time left) on stderr")
    run.add_argument("--debug", action="store_true", help="show the traceback of an error")
    plot = sub.add_parser("plot", help="plot thermo columns against step into a PNG")
    plot.add_argument("log", help="a thermo CSV (log.pdps.csv) or a log file (its thermo tables)")
    plot.add_argument("-o", dest="output", metavar="PNG", help="the PNG to write (default LOG.png)")
    plot.add_argument("--columns", nargs="+", metavar="COLUMN",
                      help="header names (Temp) or thermo keywords (temp); default: all but Step")
    styles = sub.add_parser("styles", help="list installed styles; each is loaded to check it")
    styles.add_argument("-v", "--verbose", action="store_true",
                        help="also each style's hooks, needs and contributions")
    doc = sub.add_parser("doc", help="show a style's documentation")
    doc.add_argument("kind", help="pair, fix, compute, analyze, dump, region, or a sub-model kind such as "
                                   "gran.cohesion (pdps styles lists them)")
    doc.add_argument("style")
    new = sub.add_parser("new-plugin", help="write a working, tested plugin skeleton")
    new.add_argument("name", help="the plugin: distribution pdps-KIND-NAME, package pdps_KIND_NAME")
    new.add_argument("--kind", default="fix", choices=["pair", "fix", "compute", "region", "dump", "contact"],
                     help="the kind of style (default fix; contact: a granular contact sub-model)")
    new.add_argument("--style", help="the style name scripts use (default NAME; may contain /)")
    new.add_argument("--dir", default="plugins", help="where to put it (default plugins/)")
    return parser


LMP_FLAGS = ("-in", "-i", "-var", "-v", "-log", "-l", "-screen", "-sc", "-echo", "-e")


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    if argv and argv[0] in LMP_FLAGS:
        argv = ["run", *argv]       # pdps -in in.melt ...: called as LAMMPS's lmp is
    args = _parser().parse_args(argv)
    if args.action in ("styles", "doc"):
        try:
            return _styles(args.verbose) if args.action == "styles" else _doc(args.kind, args.style)
        except BrokenPipeError:
            # the reader stopped early (pdps styles | head): not an error of ours, and no traceback
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            return 0
    if args.action == "new-plugin":
        return _new_plugin(args.name, args.dir, args.kind, args.style)
    if args.action == "plot":
        return _plot(args)
    return _run(args)


def _plot(args):
    from .output.plot import plot_thermo
    try:
        path = plot_thermo(args.log, args.output, args.columns)
    except ScriptError as exc:
        print(f"ERROR: {exc}", file=sys.stderr)
        return 1
    print(path)
    return 0


def _new_plugin(name, directory, kind, style):
    from .skeleton import new_plugin
    try:
        root, example = new_plugin(name, directory, kind=kind, style=style)
    except ScriptError as exc:
        print(f"ERROR: {exc}", file=sys.stderr)
        return 1
    print(f"wrote {root}: pip install -e {root}, then '{example}' in a script")
    return 0


def _styles(verbose):
    """One row per style: kind, name, distribution and version, and what is wrong with it. Unlike
    ``registry.listing()``, each style is loaded, so a broken or incompatible one shows here."""
    from .styledoc import verbose_lines
    from .styles import DISABLE_VARIABLE, IN_PROCESS, PluginError, registry
    entries = registry.entries()
    if not entries:
        print("no styles installed")
        return 0
    claims = {}
    for e in entries:
        if not e.disabled:
            claims.setdefault((e.kind, e.name), []).append(e.dist)
    kind_w = max(len(e.kind) for e in entries)
    name_w = max(len(e.name) for e in entries)
    origin_w = max(len(f"{e.dist} {e.version}".strip()) for e in entries)
    for e in entries:
        origin = f"{e.dist} {e.version}".strip()
        row, cls = f"{e.kind:<{kind_w}}  {e.name:<{name_w}}  {origin:<{origin_w}}", None
        others = [d for d in claims.get((e.kind, e.name), []) if d != e.dist]
        if e.disabled:
            status = f"disabled ({DISABLE_VARIABLE})"
        else:
            try:
                cls, status = registry.load(e), ""
            except PluginError as exc:
                status = f"{exc.status}: {exc.reason}"
            except ScriptError as exc:
                status = f"broken: {exc}"
        if others and e.dist != IN_PROCESS:
            status = "; ".join(filter(None, [status, f"conflict: also provided by {', '.join(others)}"]))
        print(f"{row}  {status}".rstrip())
        if verbose and cls is not None:
            print("\n".join(verbose_lines(cls)))
    return 0


def _doc(kind, style):
    from .styledoc import document
    from .styles import IN_PROCESS, StyleEntry, registry
    if kind not in registry.kinds():
        print(f"ERROR: unknown kind {kind} (installed: {', '.join(registry.kinds())})", file=sys.stderr)
        return 1
    try:
        cls = registry.lookup(kind, style)
    except ScriptError as exc:
        print(f"ERROR: {exc}", file=sys.stderr)
        return 1
    found = [e for e in registry.entries() if (e.kind, e.name) == (kind, style) and not e.disabled]
    local = [e for e in found if e.dist == IN_PROCESS]
    entry = (local or found or [StyleEntry(kind, style, IN_PROCESS, "", "")])[0]
    print(document(entry, cls), end="")
    return 0


def _run(args):
    from .simulation import Simulation
    log = None if args.log == "none" else args.log
    sim = screen = None
    try:
        script = _script_path(args)
        variables = {}
        for words in args.var:
            if len(words) < 2:
                raise ScriptError(f"-var {words[0]} needs a value")
            variables[words[0]] = words[1:]
        screen = _screen(args.screen)
        sim = Simulation(log=log, variables=variables, dialect=args.dialect, screen=screen)
        if args.no_progress:
            sim.output.progress = None
        if args.echo:
            sim.output.echo_to = args.echo
        sim.file(script)
        return sim.script.exit_status
    except ScriptError as exc:
        _fail(sim, f"ERROR: {exc}", args.debug, alone=_found_alone(sim, exc))
        return 1
    except KeyboardInterrupt:
        _fail(sim, "ERROR: interrupted", args.debug)
        return 1
    except Exception as exc:  # a bug in pdps or a plugin: still one line unless --debug
        location = sim.script.error_location if sim is not None else None
        where = f" at {location[0]}:{location[1]}" if location else ""
        # in a parallel run the other ranks may not have met it and would wait in their next
        # collective call: the rank that did stops them all
        _fail(sim, f"ERROR: internal error{where}: {type(exc).__name__}: {exc} "
                   "(run with --debug for the traceback)", args.debug,
              alone=sim is not None and sim.comm.nprocs > 1)
        return 1
    finally:
        if sim is not None:
            sim.close()
        if screen not in (None, False):
            screen.close()


def _script_path(args):
    if args.script and args.script_in and args.script != args.script_in:
        raise ScriptError(f"two scripts given: {args.script} and -in {args.script_in}")
    script = args.script or args.script_in
    if script:
        return script
    if sys.stdin.isatty():
        raise ScriptError("no input script: give one (pdps run in.melt, pdps -in in.melt) or pipe it in")
    return "/dev/stdin"


def _screen(where):
    if where is None:
        return None
    if where == "none":
        return False
    try:
        return open(where, "w")
    except OSError as exc:
        raise ScriptError(f"cannot open screen file {where}: {exc.strerror}") from None


def _found_alone(sim, exc):
    """True for an error one rank of a parallel run found by itself (the others would wait)."""
    from .errors import SimulationError
    parallel = sim is not None and sim.comm.nprocs > 1
    return parallel and isinstance(exc, SimulationError) and not getattr(exc, "agreed", False)


def _fail(sim, message, debug, alone=False):
    """Print the error once: every rank of a parallel run meets a script error, rank 0 reports it;
    an error one rank found alone is reported by that rank, which then stops all of them."""
    if debug:
        traceback.print_exc()
    message = clip(" ".join(message.splitlines()))      # one line, whatever a style put in its message
    if sim is not None and not sim.comm.is_root and not alone:
        return
    print(message, file=sys.stderr)
    if alone:
        sys.stderr.flush()
        sim.comm.world.Abort(1)
    if sim is not None and sim.output.log is not None:
        print(message, file=sim.output.log)
        sim.output.log.flush()


def entry():
    sys.exit(main())


if __name__ == "__main__":
    entry()
