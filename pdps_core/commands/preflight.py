"""A script read whole before its first line runs: what a later line would refuse for certain, an
unknown command or an unknown style, is refused at that line now, before hours of running.

Only what cannot change while the script runs is checked: command names (the core's table) and style
names (the installed plugins', by name, without importing them), and, for pair_style and fix lines,
what the style's ``respell`` makes of a dialect's spelling (LIGGGHTS 2.x's granular names: the
style's module is imported here, where it would be at its line). A line whose words depend on
variables (``$x``, ``${name}``, ``$(formula)``) is left to its turn, as are the lines of files the
script includes or jumps to, and everything a command checks against the simulation's state (groups,
types, arguments). LAMMPS reads a script line by line; this check adds to that, it never accepts
what the line itself would refuse.
"""

import difflib

from ..errors import ScriptError
from ..script.lexer import logical_lines, split_words, strip_comment
from ..script.unsupported import unsupported
from ..styles import registry
from . import COMMANDS


def unknown_command(name):
    """The one line for a command pdps does not have."""
    refused = unsupported(name)
    if refused is not None:
        return refused
    close = difflib.get_close_matches(name, COMMANDS, n=1)
    hint = f"; did you mean {close[0]}?" if close else ""
    return f"unknown command {name}{hint}"


def _style_named(sim, words):
    """(kind, style) a line defines, as its command will look it up, or None."""
    name, args = words[0], words[1:]
    if name == "pair_style" and args and args[0] != "none":
        return "pair", args[0]
    if name == "fix" and len(args) >= 3:
        return "fix", args[2]
    if name in ("compute", "analyze", "dump") and len(args) >= 3:
        return name, args[2]
    if name == "region" and len(args) >= 2 and args[1] != "delete":
        return "region", args[1]
    return None


def preflight(sim, text, source):
    """Refuse the first line of ``text`` naming an unknown command or style (module docstring)."""
    for number, raw in logical_lines(text):
        try:
            line = strip_comment(raw)
            words = [] if "$" in line else split_words(line)
        except ScriptError:
            continue                    # the line reports its own quoting when it runs
        if not words:
            continue
        if words[0] == "quit":
            return                      # the lines after an unconditional quit never run
        try:
            if words[0] not in COMMANDS:
                raise ScriptError(unknown_command(words[0]))
            named = _style_named(sim, words)
            if named is not None and named[1] not in registry.names(named[0]):
                registry.lookup(*named)         # raises the lookup's own one line
            if named is not None and named[0] in ("pair", "fix"):
                words_after = words[2:] if named[0] == "pair" else words[4:]
                registry.lookup(*named).respell(sim.dialect.name, words_after)
        except ScriptError as exc:
            raise exc.locate(source, number, words[0]) from None
