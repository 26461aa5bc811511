"""Geometry commands: region and create_box."""

import numpy as np

from ..errors import ScriptError
from ..state import limits
from ..run.shrink_wrap import shrink_faces
from ..state.box import Box
from ..styles import registry
from . import command
from .words import count, integer


@command("region")
def region(sim, args):
    if len(args) < 2:
        raise ScriptError("expected: region ID STYLE args")
    ident, style = args[0], args[1]
    if style == "delete":
        # LAMMPS's region ID delete: styles that look the ID up when a run starts see the next one of that ID
        if len(args) > 2:
            raise ScriptError(f"region ID delete takes nothing more (got {' '.join(args[2:])})")
        if ident not in sim.system.regions:
            raise ScriptError(f"region {ident} is not defined: nothing to delete")
        sim.system.regions.pop(ident).deleted = True
        return
    if ident in sim.system.regions:
        raise ScriptError(f"region {ident} is already defined")
    cls = registry.lookup("region", style)
    sim.system.regions[ident] = cls(sim, ident, cls.parse(args[2:]))


@command("create_box")
def create_box(sim, args):
    count(args, 2, "create_box NTYPES REGION-ID")
    if sim.box is not None:
        raise ScriptError("the simulation box already exists")
    ntypes = integer(args[0], "ntypes", low=1, high=limits.MAX_TYPES)
    region = sim.region(args[1])
    if region.side_out:
        raise ScriptError(f"region {args[1]} has side out: it has no extent to make a box from")
    lo, hi = region.bounds()
    make_box(sim, lo, hi, ntypes)


def make_box(sim, lo, hi, ntypes):
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    if sim.dimension == 2:
        if sim.system.periodicity[2] != "p":
            raise ScriptError("a 2-d simulation needs a periodic z boundary (boundary x y p)")
        if not lo[2] < 0 < hi[2]:
            lo[2], hi[2] = -0.5, 0.5
    lo, hi = limits.check_box(lo, hi)
    limits.check_ntypes(ntypes)
    sim.system.box = Box(lo, hi, [p == "p" for p in sim.system.periodicity], sim.dimension)
    sim.system.shrink_faces = shrink_faces(sim.system.periodicity, lo, hi)
    sim.system.ntypes = ntypes
    sim.system.mass = np.full(ntypes + 1, np.nan)
