r"""Region ``block``: an axis-aligned box, :math:`x_{lo} \le x \le x_{hi}` (and so for y, z).

Syntax::

    region ID block xlo xhi ylo yhi zlo zhi

Each bound is a number (distance units), ``INF`` or ``-INF`` (unbounded on that side, whichever
sign is written, as in LAMMPS) or ``EDGE`` (the simulation box's
face, which must exist then), as in LAMMPS. Points on the faces are inside.

Example::

    region box block 0 10 0 10 0 10
    create_box 1 box
"""

import math

import numpy as np
from pydantic import model_validator

from pdps_core.api import Region, ScriptError, StyleArgs

HUGE = 1e300


UNBOUNDED = ("INF", "-INF")
Bound = float | str


class RegionBlock(Region):
    name = "block"
    usage = "region ID block xlo xhi ylo yhi zlo zhi"

    class Args(StyleArgs):
        xlo: Bound
        xhi: Bound
        ylo: Bound
        yhi: Bound
        zlo: Bound
        zhi: Bound

        @model_validator(mode="after")
        def _words(self):
            for name in ("xlo", "xhi", "ylo", "yhi", "zlo", "zhi"):
                value = getattr(self, name)
                if isinstance(value, str) and value not in ("EDGE", *UNBOUNDED):
                    try:
                        finite = math.isfinite(float(value))
                    except ValueError:
                        finite = False
                    # float() also reads "nan", "inf" and "1e999": only INF/-INF may be unbounded
                    if not finite:
                        raise ValueError(f"{name} must be a number, INF, -INF or EDGE (got {value})")
            return self

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        bounds = []
        for k, name in enumerate(("xlo", "xhi", "ylo", "yhi", "zlo", "zhi")):
            value = getattr(args, name)
            is_lo = k % 2 == 0
            if value in UNBOUNDED:
                value = -HUGE if is_lo else HUGE       # LAMMPS: INF opens the block on that side
            elif value == "EDGE":
                if sim.box is None:
                    raise ScriptError(f"{name} EDGE needs the simulation box to exist")
                value = (sim.box.lo if is_lo else sim.box.hi)[k // 2]
            bounds.append(float(value))
        self.lo = np.array(bounds[0::2])
        self.hi = np.array(bounds[1::2])
        for axis, lo, hi in zip("xyz", self.lo, self.hi):
            if not lo <= hi:
                raise ScriptError(f"{axis}lo must be <= {axis}hi (got {lo:g} {hi:g})")

    def inside(self, x):
        return np.all((x >= self.lo) & (x <= self.hi), axis=1)

    def bounds(self):
        if np.any(np.abs(self.lo) >= HUGE) or np.any(np.abs(self.hi) >= HUGE):
            raise ScriptError(f"region {self.id} is unbounded (INF) and cannot define a box")
        return self.lo.copy(), self.hi.copy()
