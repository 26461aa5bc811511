r"""Fix ``aveforce``: every particle of the group gets the group's average force, plus an extra force
(LAMMPS's fix aveforce): the group moves as one along the components given.

.. math::  F_{i,d} \leftarrow \frac{1}{N}\sum_{j} F_{j,d} + F^\mathrm{extra}_d

over the N particles of the group (inside the region, when given, at this step), for each
component d not given as NULL (a NULL component is left as it is). The extra force (force units)
is a number or ``v_NAME``, an equal-style variable evaluated every step. Applied in ``post_force``,
at setup and in each minimization step.

Syntax::

    fix ID GROUP aveforce FX FY FZ [region RID]

Examples::

    fix pressdown topwall aveforce 0.0 -1.0 0.0
    fix 2 bottom aveforce NULL 0.0 0.0
    fix 2 bottom aveforce NULL 0.0 v_oscillate
"""

import math
from typing import Annotated

import numpy as np
from pydantic import BeforeValidator

from pdps_core.api import StyleArgs, VariableRef, keyword, param

from ._common import ForceFix, chosen


def _number_variable_or_null(word):
    if word is None or word == "NULL":
        return None
    if isinstance(word, VariableRef):
        return word
    if isinstance(word, str) and word.startswith("v_") and len(word) > 2:
        return VariableRef(word[2:])
    try:
        value = float(word)
    except (TypeError, ValueError):
        value = math.nan
    if not math.isfinite(value):
        raise ValueError("must be a finite number, v_NAME or NULL")
    return value


Component = Annotated[float | VariableRef | None, BeforeValidator(_number_variable_or_null)]


class FixAveForce(ForceFix):
    name = "aveforce"
    usage = "fix ID GROUP aveforce FX FY FZ [region RID]"

    class Args(StyleArgs):
        fx: Component = param(unit="force")
        fy: Component = param(unit="force")
        fz: Component = param(unit="force")
        region: str | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if args.region is not None:
            sim.region(args.region)
        self.components = [(d, value) for d, value in enumerate((args.fx, args.fy, args.fz)) if value is not None]
        self._sums = np.zeros(4)
        self.original = np.zeros(3)

    def vector(self, sim):
        return self.original_force(sim)

    def post_force(self, sim):
        p = sim.particles
        selected = chosen(sim, self.group, self.args.region)
        f = p.f[: p.nlocal]
        self._sums[:3] = f[selected].sum(axis=0)
        self.original[:] = self._sums[:3]
        self._sums[3] = float(selected.sum())
        total = sim.comm.sum(self._sums)
        if total[3] == 0:
            return
        for d, extra in self.components:
            f[selected, d] = total[d] / total[3] + sim.evaluate(extra)
