r"""Regions ``union`` and ``intersect``: points inside any (union) or all (intersect) of other regions,
each with its own side (LAMMPS's region union and intersect).

Syntax::

    region ID union N REGION-ID1 REGION-ID2 ... [side in|out]
    region ID intersect N REGION-ID1 REGION-ID2 ... [side in|out]

The regions must exist already; N is how many follow. ``units`` is accepted and, as in LAMMPS, does
nothing here (the regions named have their own). ``move`` and ``rotate`` are refused (LAMMPS's "cannot
be dynamic"); the regions combined may move.

As a granular wall (fix wall/gran/region, ``side in``): LAMMPS's surface_interior of each region in
turn, each with its own side and motion, keeping a contact where its surface point is inside all the
other regions (intersect) or none of them (union). Element ids are the region's, offset by 256 for
each region before it. The contacts have no wall velocity, even where the regions combined move: so
LAMMPS 22 Jul 2025 (measured: a sphere against a turning block in an intersect feels the force of a
still wall to 15 digits; the block alone, of a moving one), whose union and intersect take it from a
motion of their own, which they do not have. ``side out`` is not built. Example::

    region two union 2 left right
"""

import numpy as np
from pydantic import model_validator

from pdps_core.api import Region, RegionArgs, ScriptError, SurfaceContacts, param

ELEMENT_SHIFT = 8           # a region's element ids, offset by 256 per region before it


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

    @property
    def dynamic(self):
        return any(part.dynamic for part in self.parts)

    def own_wall_contacts(self, x, reach, out):
        if self.side_out:
            raise ScriptError(f"region {self.id} ({self.name}) with side out is not built as a granular wall")
        if not len(x):
            for part in self.parts:
                part.own_wall_contacts(x, reach, SurfaceContacts())
            return out.wall_rows(0)
        found = []
        for k, part in enumerate(self.parts):
            index, distance, normal, element, curvature = part.wall_contacts(x, reach)
            points = x[index] - normal * distance[:, None]
            others = [other.match(points) for other in self.parts if other is not part]
            keep = self.keeps(np.array(others, dtype=np.bool_).reshape(len(others), len(points)))
            found.append((index[keep], distance[keep], normal[keep], element[keep] + (k << ELEMENT_SHIFT),
                          curvature[keep]))
        columns = [np.concatenate(column) for column in zip(*found)]
        order = np.argsort(columns[0], kind="stable")      # point order, each point's contacts region by region
        count = len(order)
        out.room(count)
        index, distance, normal, element = out.rows(count)
        index[:], distance[:], normal[:], element[:] = (column[order] for column in columns[:4])
        out.curvature[:count] = columns[4][order]
        return out.wall_rows(count)

    def wall_velocity(self, rows, out):
        # LAMMPS 22 Jul 2025 takes a union's or intersect's wall velocity from its own motion, which is
        # none: its contacts stand still even where its regions move (measured, see the docstring)
        out[:] = 0.0

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

    @staticmethod
    def keeps(others):
        """A sub-region's contact stays where its point is inside none of the others."""
        return ~np.logical_or.reduce(others, axis=0) if len(others) else np.ones(others.shape[1], dtype=np.bool_)


class RegionIntersect(_Combined):
    name = "intersect"
    usage = "region ID intersect N REGION-ID... [side in|out]"

    def inside(self, x):
        return np.logical_and.reduce([part.match(x) for part in self.parts])

    @staticmethod
    def keeps(others):
        """A sub-region's contact stays where its point is inside all the others."""
        return np.logical_and.reduce(others, axis=0) if len(others) else np.ones(others.shape[1], dtype=np.bool_)
