"""Reading command words into values, with the one-line errors every command shares."""

import math

from ..errors import ScriptError
from ..state import limits


def count(args, n, usage, at_most=None):
    """Require n words (or n..at_most)."""
    high = n if at_most is None else at_most
    if not n <= len(args) <= high:
        wanted = f"{n}" if high == n else f"{n} to {high}" if high < 99 else f"at least {n}"
        raise ScriptError(f"expected {wanted} argument(s), got {len(args)}; usage: {usage}")


def number(word, name, low=None, high=None, strict_low=False, representable=False):
    """A finite number; ``representable``: also 0 or of a magnitude from MIN_SIZE to MAX_SIZE, the
    rule style arguments are held to (StyleArgs)."""
    try:
        value = float(word)
    except ValueError:
        raise ScriptError(f"{name} must be a number (got {word})") from None
    if not math.isfinite(value):
        raise ScriptError(f"{name} must be finite (got {word})")
    if representable and value != 0.0 and not limits.MIN_SIZE <= abs(value) <= limits.MAX_SIZE:
        raise ScriptError(f"{name} must be 0 or of magnitude from {limits.MIN_SIZE:g} to {limits.MAX_SIZE:g} "
                          f"(got {word})")
    if low is not None and (value <= low if strict_low else value < low):
        raise ScriptError(f"{name} must be {'>' if strict_low else '>='} {low:g} (got {word})")
    if high is not None and value > high:
        raise ScriptError(f"{name} must be <= {high:g} (got {word})")
    return value


def integer(word, name, low=None, high=None):
    try:
        value = int(word)
    except ValueError:
        raise ScriptError(f"{name} must be an integer (got {word})") from None
    if low is not None and value < low:
        raise ScriptError(f"{name} must be >= {low} (got {word})")
    if high is not None and value > high:
        raise ScriptError(f"{name} must be <= {high} (got {word})")
    return value


def choice(word, name, options):
    if word not in options:
        raise ScriptError(f"{name} must be one of {', '.join(options)} (got {word})")
    return word


def yes_no(word, name):
    return choice(word, name, ("yes", "no")) == "yes"


def type_range(word, ntypes, name="type"):
    """``3``, ``*``, ``2*``, ``*4``, ``2*4`` -> (lo, hi), checked against 1..ntypes."""
    if ntypes < 1:
        raise ScriptError(f"{name} range {word} given before any type exists (create the box first)")
    if "*" in word:
        lo_text, _, hi_text = word.partition("*")
        lo = integer(lo_text, name) if lo_text else 1
        hi = integer(hi_text, name) if hi_text else ntypes
    else:
        lo = hi = integer(word, name)
    if not 1 <= lo <= hi <= ntypes:
        raise ScriptError(f"{name} {word} is out of range 1..{ntypes}")
    return lo, hi
