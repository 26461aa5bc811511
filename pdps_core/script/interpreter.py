"""The script part of a simulation: its dialect, its variables, and where in which script it is
(LAMMPS's Input). ``execute(words)`` is the one path script lines and typed calls share: it looks
the command up in ``pdps_core.commands.COMMANDS``. Errors raise ``ScriptError`` naming the file,
line and command."""

import os

import numpy as np

from ..commands import COMMANDS
from ..commands.preflight import preflight, unknown_command
from ..errors import ScriptError, ScriptQuit
from ..state import limits
from .context import FormulaContext
from .dialect import DIALECTS, detect, dialect_named
from .lexer import logical_lines, read_text, split_words, strip_comment, substitute
from .variables import Variables


class ScriptFlow:
    """Where a script is: its lines, the next one, a jump asked for by the line just run, the state
    (variables, step, particle count) each backward jump last left from (a loop that comes back to
    the same state can never end), and whether the next jump is skipped (an exhausted ``next``, as
    LAMMPS)."""

    def __init__(self, source, lines, path=None):
        self.source, self.lines, self.at = source, lines, 0
        self.path = path            # the file read (None for commands typed from Python)
        self.jump = None
        self.seen = {}
        self.skip_jump = False


class Script:
    __slots__ = ("sim", "dialect", "dialect_fixed", "variables", "source", "line", "directory", "flow",
                 "include_depth", "error_location", "exit_status")

    def __init__(self, sim, dialect=None, variables=None):
        """``dialect``: "lammps", "pdps" or "liggghts" for every script, or None: the first script
        file's own lines decide (pdps_core.script.dialect), commands typed from Python are read as
        PDPS until then. ``variables``: {name: value} defined as index variables (``-var``)."""
        self.sim = sim
        self.dialect = DIALECTS["pdps"] if dialect is None else dialect_named(dialect, "dialect")
        self.dialect_fixed = dialect is not None   # given, or settled by the first script
        self.variables = Variables(lambda per_atom=False, vector=False: FormulaContext(sim, per_atom, vector))
        for name, value in (variables or {}).items():
            values = [str(v) for v in value] if isinstance(value, (list, tuple)) else [str(value)]
            self.variables.define([name, "index", *values], from_command_line=True)
        self.source = None          # the script being read: its name as errors show it
        self.line = None
        self.directory = None       # the folder its file names are relative to
        self.flow = None            # ScriptFlow of the script being read
        self.include_depth = 0
        self.error_location = None  # (source, line) where a bug surfaced, for the one-line internal error
        self.exit_status = 0        # what a script's quit asked pdps run to exit with

    def file(self, path):
        """Run a whole script file."""
        top = self.source is None
        shown = os.path.basename(path) if top else path
        self.include_depth += 1
        try:
            if self.include_depth > limits.MAX_INCLUDE_DEPTH:
                raise ScriptError(f"scripts include each other more than {limits.MAX_INCLUDE_DEPTH} deep "
                                  f"({path} includes itself?)")
            text = read_text(path, "input script", shown, top=top)
            here = os.path.dirname(os.path.abspath(path))
            if top:
                self._settle_dialect(text, shown, here)
                preflight(self.sim, text, shown)
            self.text(text, shown, here, path)
        except ScriptQuit as exc:
            if not top:
                raise
            self.exit_status = exc.status
        finally:
            self.include_depth -= 1

    def _settle_dialect(self, text, shown, directory):
        """The top script's dialect: given, or read off its lines and those of the files it includes;
        named on the first output line."""
        found, reason = detect(text, shown, directory)
        if self.dialect_fixed:
            if reason.startswith("dialect on line") and found is not self.dialect:
                raise ScriptError(f"dialect {found.name} ({reason}) contradicts the dialect given "
                                  f"({self.dialect.name})", source=shown)
            reason = "as asked"
        else:
            self.dialect, self.dialect_fixed = found, True
        self.sim.output.message(f"read as {self.dialect.label}: {reason}")

    def dialect_index(self, index, what):
        """A script's index (c_ID[i], f_ID[i], a per-atom column) as a 0-based one."""
        base = self.dialect.index_base
        if index < base:
            raise ScriptError(f"{what}: indices count from {base} in the {self.dialect.label} dialect "
                              f"(got {index})")
        return index - base

    def text(self, text, source, directory, path=None):
        """Run the lines of ``text``, read from ``source`` (a file name, or "<command>")."""
        outer = self.source, self.line, self.directory, self.flow
        self.source, self.directory = source, directory
        self.flow = flow = ScriptFlow(source, list(logical_lines(text)), path)
        try:
            while flow.at < len(flow.lines):
                number, raw = flow.lines[flow.at]
                flow.at += 1
                self._line(number, raw, source)
                if flow.jump is not None:
                    source, directory = self._take_jump(flow, source, directory)
        finally:
            self.source, self.line, self.directory, self.flow = outer

    def _line(self, number, raw, source):
        """Run one logical line of a script (substituted, echoed), located in errors."""
        self.line = number
        first = raw.split(maxsplit=1)
        name = first[0] if first else None      # known even if the line cannot be read
        try:
            line = substitute(strip_comment(raw), self.variables.text)
            words = split_words(line)
            if not words:
                return
            self.sim.output.echo(line.strip())
            self.execute(words)
        except ScriptError as exc:
            raise exc.locate(source, number, name)
        except ScriptQuit:
            raise
        except MemoryError as exc:
            # a valid scene too large for this machine is the user's to resize, not a bug
            message = str(exc).split(" for an array")[0].rstrip(".") or "an allocation failed"
            raise ScriptError(f"out of memory ({message}): the scene needs more memory "
                              "than this machine gives").locate(source, number, name) from None
        except Exception:
            # the innermost place a bug surfaced, for the one-line internal error
            if self.error_location is None:
                self.error_location = (source, number)
            raise

    def _take_jump(self, flow, source, directory):
        line = self.line
        try:
            return self._jump_to(flow, source, directory)
        except ScriptError as exc:
            raise exc.locate(source, line, "jump") from None

    def _jump_to(self, flow, source, directory):
        """Carry out ``jump FILE [LABEL]``: this script from its label, or another file in its place
        (LAMMPS's jump); a backward jump with nothing changed since the last one is an endless loop.
        Jumping to the script's own file by name is jumping to SELF: the same loop, the same check."""
        target, label = flow.jump
        flow.jump = None
        path = None if target == "SELF" else self.resolve(target)
        same_file = target == "SELF" or (flow.path is not None and _same_file(path, flow.path))
        if not same_file:
            text = read_text(path, "input script", path)
            source, directory = path, os.path.dirname(os.path.abspath(path))
            self.source, self.directory = source, directory
            flow.source, flow.lines, flow.at, flow.path = source, list(logical_lines(text)), 0, path
            flow.seen = {}
        if label is None:
            start = 0
        else:
            start = next((k + 1 for k, (_, raw) in enumerate(flow.lines)
                          if raw.split()[:2] == ["label", label]), None)
            if start is None:
                raise ScriptError(f"label {label} is not in {source}", source=source, line=self.line,
                                  command="jump")
        backward = same_file and start <= flow.at
        if backward:
            state = (self.variables.signature(), self.sim.step, self.sim.particles.nlocal)
            if flow.seen.get(start) == state:
                raise ScriptError(f"jump {target} {label or ''}: an endless loop (variables, step and particles "
                                  "are as they were at the last jump back)".replace("  ", " "),
                                  source=source, line=self.line, command="jump")
            flow.seen[start] = state
        flow.at = start
        return source, directory

    def execute(self, words):
        """Run one command given as words: the single path scripts and typed calls share."""
        name, args = words[0], list(words[1:])
        entry = COMMANDS.get(name)
        if entry is None:
            raise ScriptError(unknown_command(name), command=name)
        try:
            # numpy's floating-point warnings never reach the screen raw: the checks that matter
            # (non-finite positions and forces, lost particles) report in the core's own words
            with np.errstate(all="ignore"):
                entry(self.sim, args)
        except ScriptError as exc:
            if exc.command is None:
                exc.command = name
            raise

    def resolve(self, path):
        """A file path named in a script, relative to the directory of that script."""
        if os.path.isabs(path) or self.directory is None:
            return path
        candidate = os.path.join(self.directory, path)
        return candidate if os.path.exists(candidate) or not os.path.exists(path) else path

    def substitute(self, text):
        """``text`` with ``$x``, ``${name}`` and ``$(formula)`` replaced now, as a script line is."""
        return substitute(text, self.variables.text)


def _same_file(a, b):
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False
