"""Errors a user sees as one line: ``ERROR: in.water:12: pair_coeff: gamma must be >= 0 (got -4.5)``.

A command or style raises ``ScriptError("gamma must be >= 0 (got -4.5)")``; the script reader adds the
file, the line and the command on its way out, so styles never need to know where they were called from.
"""


class ScriptError(Exception):
    """Bad input: a command, a style argument or the state a command needs is wrong."""

    def __init__(self, message, *, source=None, line=None, command=None):
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
