"""What the arguments of LIGGGHTS's insertion fixes share: counts and seeds as its scripts write them
(its atoi reads "1." as 1), and required keywords named when a line lacks one."""

import math
from typing import Annotated

from pydantic import BeforeValidator

from pdps_core.api import ScriptError


def _whole(word):
    """A word written as a float with no fraction ("1.", as LIGGGHTS's tutorials write seeds, which
    its atoi reads) is that integer; any other word is left for pydantic to judge."""
    if isinstance(word, str):
        try:
            value = float(word)
        except ValueError:
            return word
        if math.isfinite(value) and value == int(value):
            return int(value)
    return word


WholeNumber = Annotated[int, BeforeValidator(_whole)]


def require(cls, args, *names):
    """A one-line error for the first of ``names`` (LIGGGHTS's required keywords) the line lacks."""
    for needed in names:
        if getattr(args, needed) is None:
            raise ScriptError(f"missing keyword {needed}; usage: {cls.usage}")
