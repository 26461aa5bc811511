r"""Fix ``setforce``: sets force components of a group to given values (PDPS manual's and LAMMPS's
fix setforce).

.. math::  F_{i,d} \leftarrow F_d \quad \text{for each component } d \text{ not given as NULL}

This erases the forces computed so far on those components (fixes defined later may add more). With
all three components 0 it stops the particles' acceleration; unlike ``fix freeze`` it leaves their
velocity and torque alone. Applied in ``post_force`` and at setup.

Parameters:

- ``FX FY FZ``: force components (force units), each a number or ``NULL`` (leave that component).
- ``region RID`` (optional, LAMMPS): act only on particles inside region RID.

Syntax::

    fix ID GROUP setforce FX FY FZ [region RID]

Examples::

    fix 3 freeze setforce 0.0 0.0 0.0
    fix 2 edge setforce NULL 0.0 0.0
"""

import math

import numpy as np
from typing import Annotated

from pydantic import BeforeValidator

from pdps_core.api import StyleArgs, keyword, param

from ._common import ForceFix, chosen


def _number_or_null(word):
    if word is None or word == "NULL":
        return None
    try:
        value = float(word)
    except (TypeError, ValueError):
        value = math.nan
    if not math.isfinite(value):
        raise ValueError("must be a finite number or NULL")
    return value


Component = Annotated[float | None, BeforeValidator(_number_or_null)]


class FixSetForce(ForceFix):
    name = "setforce"
    usage = "fix ID GROUP setforce FX FY FZ [region RID]"

    class Args(StyleArgs):
        fx: Component = param(unit="force")
        fy: Component = param(unit="force")
        fz: Component = param(unit="force")
        region: str | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.original = np.zeros(3)
        if args.region is not None:
            sim.region(args.region)
        self.components = [(d, value) for d, value in enumerate((args.fx, args.fy, args.fz))
                           if value is not None]

    def vector(self, sim):
        return self.original_force(sim)

    def post_force(self, sim):
        p = sim.particles
        selected = chosen(sim, self.group, self.args.region)
        f = p.f[: p.nlocal]
        self.keep_original(f, selected)
        for d, value in self.components:
            f[selected, d] = value
