r"""Fix ``property/global``: a named global value, list or table that other styles read (LIGGGHTS's
fix property/global). LIGGGHTS's granular models take their material from such fixes: Young's
modulus and Poisson's ratio per particle type, restitution and friction per pair of types, a
characteristic velocity as a scalar.

Syntax::

    fix ID GROUP property/global NAME scalar VALUE
    fix ID GROUP property/global NAME vector|atomtype|peratomtype V1 V2 ...
    fix ID GROUP property/global NAME matrix|atomtypepair|peratomtypepair N V11 V12 ... VNN

- ``NAME``: the property's name (``youngsModulus``, ``poissonsRatio``, ``coefficientRestitution``,
  ``coefficientFriction``, ``coefficientRollingFriction``, ``coefficientRollingViscousDamping``,
  ``cohesionEnergyDensity``, ``characteristicVelocity``, ``thermalConductivity``,
  ``thermalCapacity``, ...). The style that reads it says its unit and range.
- ``scalar``: one value. ``vector``, ``atomtype``, ``peratomtype`` (one name for one thing in
  LIGGGHTS: "atomtype is just provided to make input scripts more readable"): one value per particle
  type, type 1 first. ``matrix``, ``atomtypepair``, ``peratomtypepair``: ``N`` columns, then the
  rows; a per-type-pair table is N x N and symmetric (:math:`V_{IJ} = V_{JI}`), row I giving
  :math:`V_{I1} \dots V_{IN}`.
- ``GROUP`` is ignored (the values are global), as in LIGGGHTS.

Checked here: every value a finite number, a per-type-pair table square and symmetric, the
columns of a matrix dividing its values. Checked by the style that reads it, at the start of a run:
that it exists, that it has one value per particle type (or N = the number of types), its range.
Two fixes giving the same NAME: the later one holds, as a LIGGGHTS fix redefined with the same ID.

Example (LIGGGHTS's material block for two types)::

    fix m1 all property/global youngsModulus peratomtype 5.e6 5.e6
    fix m2 all property/global poissonsRatio peratomtype 0.45 0.45
    fix m3 all property/global coefficientRestitution peratomtypepair 2 0.3 0.3 0.3 0.3
    fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
    fix m5 all property/global characteristicVelocity scalar 2.
"""

from typing import Annotated, Literal, NewType

import numpy as np
from pydantic import BeforeValidator
from pydantic_core import PydanticCustomError

from pdps_core.api import Fix, ScriptError, StyleArgs, param

PER_TYPE = ("vector", "atomtype", "peratomtype")
PER_TYPE_PAIR = ("atomtypepair", "peratomtypepair")
MAX_COLUMNS = 10000


def _columns(word):
    try:
        value = int(word)
    except (TypeError, ValueError):
        raise PydanticCustomError("columns", "the number of columns must be an integer") from None
    if not 1 <= value <= MAX_COLUMNS:
        raise PydanticCustomError("columns", f"the number of columns must be from 1 to {MAX_COLUMNS}")
    return value


# the number of columns of a table, its values following (not a count of the words after it)
Columns = Annotated[NewType("columns", int), BeforeValidator(_columns)]
Table = (tuple[Literal[("scalar",) + PER_TYPE], tuple[float, ...]]
         | tuple[Literal[("matrix",) + PER_TYPE_PAIR], Columns, tuple[float, ...]])


class FixPropertyGlobal(Fix):
    name = "property/global"
    usage = ("fix ID GROUP property/global NAME scalar V | vector|atomtype|peratomtype V1 V2 ... | "
             "matrix|atomtypepair|peratomtypepair N V11 ... VNN")

    class Args(StyleArgs):
        variable: str = param(description="the property's name")
        values: Table = param(unit="as the property", description="the style word, then its values")

        @property
        def style(self):
            """The style word as written (LIGGGHTS's spellings: atomtype, peratomtype, ...)."""
            return self.values[0]

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        name, style = args.variable, args.style
        values = args.values[-1]
        if not values:
            raise ScriptError(f"{name} {style}: expected at least one value; usage: {cls.usage}")
        if style == "scalar" and len(values) != 1:
            raise ScriptError(f"{name} scalar takes one value (got {len(values)})")
        if style == "matrix" and len(values) % args.values[1]:
            raise ScriptError(f"{name} matrix: {len(values)} values do not fill rows of {args.values[1]} columns")
        if style in PER_TYPE_PAIR:
            n = args.values[1]
            if len(values) != n * n:
                raise ScriptError(f"{name} {style} {n}: expected {n} x {n} = {n * n} values (got {len(values)})")
            table = np.array(values).reshape(n, n)
            if not np.array_equal(table, table.T):
                i, j = (int(k) + 1 for k in np.argwhere(table != table.T)[0])
                raise ScriptError(f"{name} {style}: the table must be symmetric (value {i},{j} is "
                                  f"{table[i - 1, j - 1]:g}, value {j},{i} is {table[j - 1, i - 1]:g})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        style = args.style
        self.variable = args.variable
        self.columns = args.values[1] if len(args.values) == 3 else 1
        self.style = "scalar" if style == "scalar" else (
            "per_type" if style in PER_TYPE else "per_type_pair" if style in PER_TYPE_PAIR else "matrix")
        self.values = np.array(args.values[-1], dtype=float, ndmin=1)
