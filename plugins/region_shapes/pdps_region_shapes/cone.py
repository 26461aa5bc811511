r"""Region ``cone``: a truncated cone along x, y or z (LAMMPS's region cone).

Syntax::

    region ID cone DIM C1 C2 RADLO RADHI LO HI [side in|out] [units box|lattice]

As ``cylinder``, with the radius going linearly from RADLO at LO to RADHI at HI (LO and HI finite
numbers or ``EDGE``). Points on the surface are inside. Example::

    region funnel cone z 5 5 1.0 4.0 0 6 units box
"""

import numpy as np
from pydantic import model_validator

from pdps_core.api import Region, RegionArgs, ScriptError, param

from .cylinder import OTHER, bound


class RegionCone(Region):
    name = "cone"
    usage = "region ID cone x|y|z C1 C2 RADLO RADHI LO HI [side in|out] [units box|lattice]"

    class Args(RegionArgs):
        dim: str = param()
        c1: float = param(unit="distance")
        c2: float = param(unit="distance")
        radlo: float = param(ge=0, unit="distance")
        radhi: float = param(ge=0, unit="distance")
        lo: str = param(unit="distance")
        hi: str = param(unit="distance")

        @model_validator(mode="after")
        def _words(self):
            if self.dim not in OTHER:
                raise ValueError(f"dim must be x, y or z (got {self.dim})")
            for name in ("lo", "hi"):
                if getattr(self, name) in ("INF", "-INF"):
                    raise ValueError(f"{name} of a cone must be a number or EDGE (got {getattr(self, name)})")
                bound(getattr(self, name), name)
            if self.radlo == 0 and self.radhi == 0:
                raise ValueError("radlo and radhi cannot both be 0")
            return self

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        self.axis = "xyz".index(args.dim)
        self.across = OTHER[args.dim]
        self.c = np.array([args.c1 * self.scale[self.across[0]], args.c2 * self.scale[self.across[1]]])
        self.radlo = args.radlo * self.scale[self.across[0]]
        self.radhi = args.radhi * self.scale[self.across[0]]
        ends = []
        for value, is_lo in ((args.lo, True), (args.hi, False)):
            if value == "EDGE":
                if sim.box is None:
                    raise ScriptError(f"{'lo' if is_lo else 'hi'} EDGE needs the simulation box to exist")
                ends.append(float((sim.box.lo if is_lo else sim.box.hi)[self.axis]))
            else:
                ends.append(float(value) * self.scale[self.axis])
        self.lo, self.hi = ends
        if not self.lo < self.hi:
            raise ScriptError(f"lo must be < hi (got {self.lo:g} {self.hi:g})")

    def inside(self, x):
        x = np.asarray(x, dtype=np.float64)
        a, b = self.across
        along = x[:, self.axis]
        radius = self.radlo + (along - self.lo) * (self.radhi - self.radlo) / (self.hi - self.lo)
        d1, d2 = x[:, a] - self.c[0], x[:, b] - self.c[1]
        return (along >= self.lo) & (along <= self.hi) & (np.sqrt(d1 * d1 + d2 * d2) <= radius)

    def bounds(self):
        reach = max(self.radlo, self.radhi)
        lo, hi = np.empty(3), np.empty(3)
        for k, d in enumerate(self.across):
            lo[d], hi[d] = self.c[k] - reach, self.c[k] + reach
        lo[self.axis], hi[self.axis] = self.lo, self.hi
        return lo, hi
