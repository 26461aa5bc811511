r"""Regions ``union`` and ``intersect``: points inside any (union) or all (intersect) of other regions,
each with its own side (LAMMPS's region union and intersect).

Syntax::

    region ID union N REGION-ID1 REGION-ID2 ... [side in|out]
    region ID intersect N REGION-ID1 REGION-ID2 ... [side in|out]

The regions must exist already; N is how many follow. ``units`` is accepted and, as in LAMMPS, does
nothing here (the regions named have their own). Example::

    region two union 2 left right
"""

import numpy as np
from pydantic import model_validator

from pdps_core.api import Region, RegionArgs, ScriptError, param


class _Combined(Region):
    class Args(RegionArgs):
        count: int = param(ge=2, unit="1")
        regions: list[str] = param(names="region ID")

        @model_validator(mode="after")
        def _count(self):
            if len(self.regions) != self.count:
                raise ValueError(f"N is {self.count} but {len(self.regions)} region IDs follow")
            return self

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        if id in args.regions:
            raise ScriptError(f"region {id} cannot contain itself")
        if args.move or args.rotate:
            raise ScriptError(f"region {self.name} cannot move or rotate itself (as LAMMPS): give move or rotate "
                              "to the regions it combines")
        self.parts = [sim.region(name) for name in args.regions]

    def bounds(self):
        return self._combined("bounds")

    def extent(self):
        return self._combined("extent")

    def _combined(self, method):
        # LAMMPS's rule: a union has an extent when all its regions have one, an intersection when any has
        boxes = []
        for part in self.parts:
            if part.side_out:
                continue
            try:
                boxes.append(getattr(part, method)())
            except ScriptError:
                continue
        if not boxes or (self.name == "union" and len(boxes) < len(self.parts)):
            raise ScriptError(f"region {self.id} has no finite extent")
        los, his = np.array([b[0] for b in boxes]), np.array([b[1] for b in boxes])
        if self.name == "union":
            return los.min(axis=0), his.max(axis=0)
        return los.max(axis=0), his.min(axis=0)


class RegionUnion(_Combined):
    name = "union"
    usage = "region ID union N REGION-ID... [side in|out]"

    def inside(self, x):
        return np.logical_or.reduce([part.match(x) for part in self.parts])


class RegionIntersect(_Combined):
    name = "intersect"
    usage = "region ID intersect N REGION-ID... [side in|out]"

    def inside(self, x):
        return np.logical_and.reduce([part.match(x) for part in self.parts])
