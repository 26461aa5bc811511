"""Script control and output commands: dialect, echo, variable, next, print, if, label, jump, clear,
include, quit, shell, run, reset_timestep, thermo, thermo_style, thermo_modify, log (LAMMPS's semantics)."""

import os
import subprocess

from ..errors import ScriptError, ScriptQuit
from ..state import limits
from ..script.lexer import split_words, substitute
from . import command
from .words import choice, count, integer


@command("dialect")
def dialect(sim, args):
    """``dialect lammps|liggghts|pdps``: read by the top script before its first command (see
    pdps_core.script.dialect); run here it only confirms, or, typed from Python before any box
    exists, chooses."""
    from ..script.dialect import dialect_named
    count(args, 1, "dialect lammps|liggghts|pdps")
    chosen = dialect_named(args[0])
    if chosen is sim.dialect:
        sim.script.dialect_fixed = True
        return
    if sim.script.dialect_fixed or sim.box is not None:
        raise ScriptError(f"this script is read as {sim.dialect.label}; the dialect cannot change "
                          "midway (give it first, or pdps run --dialect)")
    sim.script.dialect, sim.script.dialect_fixed = chosen, True
    sim.output.message(f"read as {chosen.label}: dialect command")


@command("echo")
def echo(sim, args):
    count(args, 1, "echo none|screen|log|both")
    sim.output.echo_to = choice(args[0], "echo", ("none", "screen", "log", "both"))


@command("variable")
def variable(sim, args):
    sim.variables.define(args)


@command("next")
def next_(sim, args):
    """Step the variables; when one is exhausted it is deleted and the next jump is skipped (LAMMPS)."""
    if not args:
        raise ScriptError("expected: next NAME...")
    exhausted = False
    for name in args:
        exhausted |= not sim.variables.next(name)
    flow = sim.script.flow
    if exhausted and flow is not None:
        flow.skip_jump = True


@command("label")
def label(sim, args):
    count(args, 1, "label ID")


@command("jump")
def jump(sim, args):
    """``jump FILE [LABEL]``: go on reading FILE (SELF: this script) from the line after
    ``label LABEL``, or from its start."""
    count(args, 1, "jump FILE|SELF [LABEL]", at_most=2)
    flow = sim.script.flow
    if flow is None:
        raise ScriptError("jump works in a script file, not in commands typed from Python")
    if flow.skip_jump:
        flow.skip_jump = False
        return
    flow.jump = (args[0], args[1] if len(args) == 2 else None)


@command("if")
def if_(sim, args):
    """``if BOOLEAN then C1 C2 ... [elif BOOLEAN C...]... [else C...]``: each C a quoted command."""
    usage = 'if "BOOLEAN" then "COMMAND" ... [elif "BOOLEAN" "COMMAND" ...] [else "COMMAND" ...]'
    if len(args) < 2 or args[1] != "then":
        raise ScriptError(f"expected a Boolean and then; usage: {usage}")
    branches, current = [], None
    k = 0
    while k < len(args):
        word = args[k]
        if k == 0:
            current = (args[0], [])
            k += 2
            continue
        if word == "elif":
            if k + 1 >= len(args):
                raise ScriptError(f"elif needs a Boolean; usage: {usage}")
            branches.append(current)
            current = (args[k + 1], [])
            k += 2
            continue
        if word == "else":
            branches.append(current)
            current = (None, [])
            k += 1
            continue
        current[1].append(word)
        k += 1
    branches.append(current)
    for condition, commands in branches:
        if condition is None or _truth(sim, condition):
            for text in commands:
                line = substitute(text, sim.variables.text)
                words = split_words(line)
                if words:
                    sim.output.echo(line.strip())
                    sim.execute(words)
            return


def _truth(sim, condition):
    """LAMMPS's Boolean of if: numbers compared as numbers, other words as strings (== and !=)."""
    text = substitute(condition, sim.variables.text).strip()
    for op in ("==", "!="):
        left, found, right = text.partition(op)
        if found and not _numeric(left) and left.strip() and right.strip() and "(" not in text:
            same = left.strip() == right.strip()
            return same if op == "==" else not same
    return sim.variables.evaluate(text) != 0.0


def _numeric(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


@command("print")
def print_(sim, args):
    """``print "TEXT" [file F | append F] [screen yes|no]``: quoted text is substituted here, as in
    LAMMPS."""
    words, target, mode, screen = list(args), None, None, True
    while len(words) >= 3 and words[-2] in ("file", "append", "screen", "universe"):
        key, value = words[-2], words[-1]
        if key == "screen":
            screen = value == "yes" if value in ("yes", "no") else _bad(f"screen must be yes or no (got {value})")
        elif key in ("file", "append"):
            target, mode = sim.resolve(value), "w" if key == "file" else "a"
        words = words[:-2]
    text = substitute(" ".join(words), sim.variables.text)
    if screen:
        sim.output.message(text)
    elif sim.output.log is not None:
        print(text, file=sim.output.log)
    if target is not None and sim.comm.is_root:
        try:
            with open(target, mode) as handle:
                handle.write(text + "\n")
        except OSError as exc:
            raise ScriptError(f"cannot write {target}: {exc.strerror}") from None


def _bad(message):
    raise ScriptError(message)


@command("clear")
def clear(sim, args):
    """Everything but variables, the log and the dialect back to how a new simulation starts."""
    count(args, 0, "clear")
    sim.clear()


@command("include")
def include(sim, args):
    count(args, 1, "include FILE")
    sim.file(sim.resolve(args[0]))


@command("quit")
def quit_(sim, args):
    """``quit [STATUS]``: the script ends here, and ``pdps run`` with exit code STATUS, the output
    written so far kept (LAMMPS's quit; without STATUS 0, in the LIGGGHTS dialect 1: LIGGGHTS 3.8.0's
    quit takes no status and exits with 1, measured)."""
    if sim.dialect.quit_status is not None:
        count(args, 0, f"quit (the {sim.dialect.label} dialect's quit takes no status)")
        raise ScriptQuit(sim.dialect.quit_status)
    count(args, 0, "quit [STATUS]", at_most=1)
    status = integer(args[0], "quit STATUS") if args else 0
    if not 0 <= status <= 255:
        raise ScriptError(f"quit STATUS is an exit code from 0 to 255 (got {status})")
    raise ScriptQuit(status)


SHELL_ARGUMENTS = {"cd": (1, 1), "mkdir": (1, None), "mv": (2, 2), "rm": (1, None), "rmdir": (1, None),
                   "putenv": (1, None)}


@command("shell")
def shell(sim, args):
    """``shell cd DIR | mkdir DIR... | mv OLD NEW | rm FILE... | rmdir DIR... | putenv NAME=VALUE... |
    COMMAND WORDS...`` (LAMMPS's and LIGGGHTS's shell): paths are the working directory's, and
    after ``shell cd`` the files the script names are the new directory's; files
    are made, moved and removed by the first rank, the directory and the environment change on
    every rank; any other words run as one shell command on the first rank. A failure is a
    warning, as in LAMMPS: the script goes on."""
    if not args:
        raise ScriptError("expected: shell cd|mkdir|mv|rm|rmdir|putenv ARGS, or a shell command")
    action, operands = args[0], args[1:]
    if action in SHELL_ARGUMENTS:
        least, most = SHELL_ARGUMENTS[action]
        if len(operands) < least or (most is not None and len(operands) > most):
            shape = {"cd": "DIR", "mv": "OLD NEW", "putenv": "NAME=VALUE..."}.get(action, "PATH...")
            raise ScriptError(f"expected: shell {action} {shape} (got {len(operands)} words)")
    first = sim.comm.rank == 0
    try:
        if action == "cd":
            os.chdir(operands[0])
            # the files the script names from here on are the new directory's, as in LAMMPS
            sim.script.directory = os.getcwd()
        elif action == "putenv":
            for assignment in operands:
                name, equals, value = assignment.partition("=")
                if not name or not equals:
                    raise ScriptError(f"shell putenv takes NAME=VALUE (got {assignment!r})")
                os.environ[name] = value
        elif not first:
            return
        elif action == "mkdir":
            for path in operands:
                os.makedirs(path, exist_ok=True)
        elif action == "mv":
            os.replace(operands[0], operands[1])
        elif action == "rm":
            for path in operands:
                os.remove(path)
        elif action == "rmdir":
            for path in operands:
                os.rmdir(path)
        else:
            status = subprocess.call(" ".join(args), shell=True)
            if status != 0:
                sim.warn(f"shell {' '.join(args)}: the command exited with status {status}")
    except OSError as exc:
        sim.warn(f"shell {action}: {exc.strerror} ({exc.filename})")


@command("run")
def run(sim, args):
    """``run N [upto] [start S] [stop E] [pre yes|no] [post yes|no] [every M COMMAND...]`` (LAMMPS)."""
    usage = "run N [upto] [start S] [stop E] [pre yes|no] [post yes|no] [every M COMMAND...]"
    if not args:
        raise ScriptError(f"expected a number of steps; usage: {usage}")
    upto = "upto" in args[1:]
    nsteps = integer(args[0], "N", low=0, high=limits.MAX_STEP if upto else limits.MAX_RUN)
    start, stop, every, commands = None, None, 0, []
    k = 1
    while k < len(args):
        word = args[k]
        if word == "upto":
            k += 1
        elif word in ("start", "stop", "pre", "post") and k + 1 < len(args):
            if word in ("start", "stop"):
                value = integer(args[k + 1], word, low=0, high=limits.MAX_STEP)
                start, stop = (value, stop) if word == "start" else (start, value)
            else:
                choice(args[k + 1], word, ("yes", "no"))
            k += 2
        elif word == "every" and k + 1 < len(args):
            every = integer(args[k + 1], "every", low=1, high=limits.MAX_RUN)
            commands = [] if args[k + 2:] == ["NULL"] else list(args[k + 2:])
            k = len(args)
        else:
            raise ScriptError(f"unexpected {word}; usage: {usage}")
    if upto:
        if nsteps < sim.step:
            raise ScriptError(f"run {nsteps} upto: the step is already {sim.step}")
        nsteps -= sim.step
    if nsteps > limits.MAX_RUN:
        raise ScriptError(f"N must be <= {limits.MAX_RUN} (got {nsteps})")
    if sim.step + nsteps > limits.MAX_STEP:
        raise ScriptError(f"run {nsteps} from step {sim.step} goes past the last step a 64-bit "
                          f"counter holds ({limits.MAX_STEP})")
    last = sim.step + nsteps
    if start is not None and start > sim.step:
        raise ScriptError(f"start {start} is after this run's first step {sim.step}")
    if stop is not None and stop < last:
        raise ScriptError(f"stop {stop} is before this run's last step {last}")
    bounds = (sim.step if start is None else start, last if stop is None else stop)
    if not every:
        sim.run_steps(nsteps, ramp_bounds=bounds)
        return
    done = 0
    while done < nsteps:
        chunk = min(every, nsteps - done)
        sim.run_steps(chunk, ramp_bounds=bounds)
        done += chunk
        for text in commands:
            line = substitute(text, sim.variables.text)
            words = split_words(line)
            if words:
                sim.execute(words)


@command("reset_timestep")
def reset_timestep(sim, args):
    count(args, 1, "reset_timestep N")
    old = sim.step
    sim.run_state.reset_step(integer(args[0], "timestep", low=0, high=limits.MAX_STEP))
    sim.run_state.energy_step = sim.run_state.virial_step = None
    # styles that keep a schedule in steps move it with the clock (LIGGGHTS's fix insert)
    for style in [*sim.fixes.values(), *sim.analyzes.values()]:
        moved = getattr(style, "reset_timestep", None)
        if callable(moved):
            moved(sim, sim.step, old)


@command("thermo")
def thermo(sim, args):
    count(args, 1, "thermo N")
    sim.output.thermo.every = integer(args[0], "N", low=0)


@command("thermo_style")
def thermo_style(sim, args):
    sim.output.thermo.set_style(args)


@command("thermo_modify")
def thermo_modify(sim, args):
    sim.output.thermo.modify(args)


@command("log")
def log(sim, args):
    count(args, 1, "log FILE|none [append]", at_most=2)
    if len(args) == 2 and args[1] != "append":
        raise ScriptError(f"expected append after the file (got {args[1]})")
    if args[0] == "none":
        sim.output.close_log()
    else:
        sim.output.open_log(args[0], append=len(args) == 2)
