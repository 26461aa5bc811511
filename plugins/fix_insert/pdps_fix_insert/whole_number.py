"""Counts and seeds as LIGGGHTS's insertion fixes read them: its atoi reads "1." as 1."""

import math
from typing import Annotated

from pydantic import BeforeValidator


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
