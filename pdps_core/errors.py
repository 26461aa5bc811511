"""Errors a user sees as one line: ``ERROR: in.water:12: pair_coeff: gamma must be >= 0 (got -4.5)``.

A command or style raises ``ScriptError("gamma must be >= 0 (got -4.5)")``; the script reader adds the
file, the line and the command on its way out, so styles never need to know where they were called from.

Messages quote the offending value, and a value may be anything a script holds: a 100,000-character
word or formula. ``clip`` keeps every message readable on one line; ScriptError applies it to each
message, so no raise site needs to.
"""

import re

LONG_RUN = 120          # a word (no white space) or a quoted text longer than this is shown as its ends
RUN_HEAD, RUN_TAIL = 60, 20
LONG_MESSAGE = 4000     # the last resort: a message longer than this keeps its start and its end
MESSAGE_HEAD, MESSAGE_TAIL = 3000, 600
_RUN = re.compile(r"\S{%d,}" % (LONG_RUN + 1))
# a quoted value ('...' or "..." as repr writes it), its opening quote after a space or (: an
# apostrophe inside a word never opens one
_QUOTED = re.compile(r"""(?<=[\s(])(['"])([^'"\n]{%d,})\1(?=[\s),:;.]|$)""" % (LONG_RUN + 1))


def _ends(text):
    return f"{text[:RUN_HEAD]}...{text[-RUN_TAIL:]}"


def clip(message):
    """``message`` with each quoted text and each word over LONG_RUN characters shortened to its
    first RUN_HEAD and last RUN_TAIL characters around an ellipsis (a file's name stays readable at
    the end of its path); a message still over LONG_MESSAGE characters loses its middle."""
    message = _QUOTED.sub(lambda m: f"{m.group(1)}{_ends(m.group(2))}{m.group(1)}", message)
    message = _RUN.sub(lambda m: _ends(m.group()), message)
    if len(message) > LONG_MESSAGE:
        message = f"{message[:MESSAGE_HEAD]} ... {message[-MESSAGE_TAIL:]}"
    return message


class ScriptError(Exception):
    """Bad input: a command, a style argument or the state a command needs is wrong."""

    def __init__(self, message, *, source=None, line=None, command=None):
        message = clip(str(message))
        super().__init__(message)
        self.message = message
        self.source = source
        self.line = line
        self.command = command

    def locate(self, source, line, command):
        """Fill in where the error happened, keeping the innermost location already set."""
        if self.source is None:
            self.source, self.line = source, line
        if self.command is None:
            self.command = command
        return self

    def __str__(self):
        where = ""
        if self.source is not None:
            where = f"{self.source}:{self.line}: " if self.line is not None else f"{self.source}: "
        what = f"{self.command}: " if self.command else ""
        return f"{where}{what}{self.message}"


class SimulationError(ScriptError):
    """The run itself went wrong: a particle lost, a non-finite force, an unstable setting."""


def got(value):
    """How an offending value is quoted in a message."""
    return f"(got {value})"


class ScriptQuit(Exception):
    """``quit [STATUS]`` ran: the script ends here, and the program with STATUS (LAMMPS's quit)."""

    def __init__(self, status=0):
        super().__init__(f"quit {status}")
        self.status = status
