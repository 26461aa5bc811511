r"""Compute ``chunk/atom``: each particle's chunk, an integer from 1 to N (0: in none), for fix
ave/chunk and anything that reads per-atom values (``c_ID`` in dumps and atom-style variables), as
LAMMPS's compute chunk/atom.

Styles:

- ``bin/1d DIM ORIGIN DELTA`` (``bin/2d``, ``bin/3d``: two or three such triples): slabs (columns,
  cells) of width DELTA along DIM. ORIGIN (``lower``, ``center``, ``upper`` of the box, or a
  coordinate) is a bin boundary, and bins are laid from it to cover the box: ``z center 3`` in a box
  0..10 gives -1..2, 2..5, 5..8, 8..11 (four chunks; the outer ones stick out of the box). A
  particle's coordinate is wrapped into the box on a periodic axis; a chunk ``i*n2*n3 + j*n3 + k + 1``
  with the first axis slowest; its coordinates the bin's centre.
- ``type``: the particle's type, N = the number of types.
- ``molecule``: its molecule id, N = the largest id in the group (particles of molecule 0 are in none).

Keywords (LAMMPS's, with its defaults):

- ``units lattice|box|reduced`` (default lattice): DELTA and a coordinate ORIGIN in lattice spacings
  (1 where no lattice is defined), in distance, or as fractions of the box (0..1 along each axis, and
  so are the chunk coordinates);
- ``nchunk once|every``: the bins (or N) set up once, the first time the compute is used, or again
  at each use (each window of fix ave/chunk). Default: once for ``type``, ``molecule`` and
  ``units reduced``, every for other bins, every with ``compress yes``;
- ``compress yes|no`` (default no): the chunks holding no particle of the group are dropped and the
  others renumbered 1..N in order (``OrigID``: the number each had before; molecule 0 is one of
  them when the group holds particles of molecule 0, as in LAMMPS);
- ``discard yes|no|mixed``: a particle outside every chunk (beyond the bins on a non-periodic axis, a
  molecule id above N) is in none (``yes``) or in the nearest bin (``no``; for type and molecule:
  in chunk N). ``mixed`` (bins only) is LAMMPS's default for bins and, with no ``bound`` keyword,
  means ``no``; ``yes`` is the default for type and molecule.

Each chunk's volume (fix ave/chunk's densities) is the whole bin's, :math:`V_\mathrm{box}
\prod_d \delta_d / L_d`, as LAMMPS takes it, even for a bin that sticks out of the box (analyze
ave/space divides by the part inside). The scalar ``c_ID`` in thermo and equal-style variables is N.

LAMMPS's ``region``, ``limit``, ``ids``, ``bound`` and ``pbc`` keywords, its ``bin/sphere``,
``bin/cylinder`` and ``c_ID``/``f_ID``/``v_NAME`` styles are refused at the line.

Syntax::

    compute ID GROUP chunk/atom bin/1d|bin/2d|bin/3d DIM ORIGIN DELTA [DIM ORIGIN DELTA]... [keywords]
    compute ID GROUP chunk/atom type|molecule [keywords]

Examples::

    compute layers all chunk/atom bin/1d z lower 0.05 units reduced
    compute cells all chunk/atom bin/2d x lower 2 y center 2 units box
    compute mols all chunk/atom molecule compress yes
"""

import math
from typing import Literal

import numpy as np
from pydantic import model_validator

from pdps_core.api import Compute, ScriptError, StyleArgs, check_bins, keyword, param

from .ave_space import AXES, Bins, bin_centres, bin_index, lay_bins

DIMENSIONS = {"bin/1d": 1, "bin/2d": 2, "bin/3d": 3, "type": 0, "molecule": 0}
NOT_IN_PDPS = "not in pdps (LAMMPS's compute chunk/atom has it)"


class ChunkAtomArgs(StyleArgs):
    # two choices, so that another style word is named at once (LAMMPS's bin/sphere, bin/cylinder, c_ID)
    style: Literal["bin/1d", "bin/2d", "bin/3d"] | Literal["type", "molecule"] = param(...)
    bins: list[Bins] = param(default_factory=list, max_length=3, unit=("1", "distance", "distance"))
    units: Literal["box", "lattice", "reduced"] = keyword("lattice")
    nchunk: Literal["once", "every"] | None = keyword(None)
    compress: bool = keyword(False)
    discard: Literal["yes", "no", "mixed"] | None = keyword(None)

    @model_validator(mode="after")
    def _combination(self):
        wanted = DIMENSIONS[self.style]
        if len(self.bins) != wanted:
            raise ValueError(f"style {self.style} takes {wanted} DIM ORIGIN DELTA triple(s) (got {len(self.bins)})")
        if wanted == 0 and self.discard == "mixed":
            raise ValueError(f"discard mixed needs a bin style (got {self.style})")
        return self


class ComputeChunkAtom(Compute):
    name = "chunk/atom"
    usage = ("compute ID GROUP chunk/atom bin/1d|bin/2d|bin/3d DIM ORIGIN DELTA [DIM ORIGIN DELTA]... | type | "
             "molecule [units lattice|box|reduced] [nchunk once|every] [compress yes|no] [discard yes|no|mixed]")
    Args = ChunkAtomArgs
    refused = {word: NOT_IN_PDPS for word in ("region", "limit", "ids", "bound", "pbc")}

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.axes = []
        for axis, _, _ in args.bins:
            d = AXES.index(axis)
            if d in self.axes:
                raise ScriptError(f"compute {id} chunk/atom: axis {axis} is binned twice")
            if d == 2 and sim.dimension == 2:
                raise ScriptError(f"compute {id} chunk/atom: cannot bin along z in a 2-d simulation")
            self.axes.append(d)
        if args.style == "molecule" and not sim.particles.has("molecule"):
            raise ScriptError(f"compute {id} chunk/atom molecule needs molecule ids "
                              "(particle_style molecular, bond, angle or full)")
        self.binned = bool(self.axes)
        self.ncoord = len(self.axes)
        self.compress = args.compress
        # discard mixed with no bound keyword clamps as no does (LAMMPS's atom2bin rule)
        self.clamp = (args.discard or ("mixed" if self.binned else "yes")) != "yes"
        once = args.style in ("type", "molecule") or args.units == "reduced"
        self.once = args.nchunk == "once" if args.nchunk is not None else (once and not args.compress)
        self.nchunk = 0
        self.set_up = False
        self.locked = False         # fix ave/chunk holds the chunks for a window (LAMMPS's lock)
        self.holders = {}           # fix ID: how it holds them (its schedule and ave)
        self.coords = np.zeros((0, self.ncoord))
        self.original_ids = None    # with compress: the chunk number each compressed chunk had
        self.volume = 1.0

    # ---- chunks -----------------------------------------------------------------------------------
    def setup_chunks(self, sim):
        """N (and the bins, their coordinates and volume) for now, unless held or set up once."""
        if self.set_up and (self.locked or self.once):
            if self.binned and self.args.units == "reduced":
                # bins that follow the box: their volume follows it too (LAMMPS's bin_volumes)
                self.volume = float(sim.box.volume) * math.prod(self.deltas)
            return self.nchunk
        self.set_up = True
        box = sim.box
        if self.binned:
            self._setup_bins(sim)
        raw, inside = self._assign(sim)
        if self.args.style == "type":
            self.nchunk = sim.ntypes
        elif not self.binned:
            self.nchunk = max(1, int(sim.comm.max(int(raw[inside].max()) if inside.any() else -1)))
        if self.compress:
            # the numbers the group's particles hold, before any discard (LAMMPS's hash): molecule 0 too
            top = int(sim.comm.max(int(raw[inside].max()) if inside.any() else 0))
            check_bins(top + 1, f"compute {self.id} chunk/atom: chunk numbers up to {top}")
            held = np.asarray(sim.comm.sum(np.bincount(raw[inside], minlength=top + 1).astype(np.float64)))
            self.original_ids = np.flatnonzero(held > 0)
            self.renumber = np.zeros(top + 1, dtype=np.int64)
            self.renumber[self.original_ids] = np.arange(1, len(self.original_ids) + 1)
            self.nchunk = max(1, len(self.original_ids))
        if not self.binned:
            self.volume = float(box.volume)
        return self.nchunk

    def _setup_bins(self, sim):
        box = sim.box
        reduced = self.args.units == "reduced"
        offsets, deltas, layers = [], [], []
        for d, (axis, origin, delta) in zip(self.axes, self.args.bins):
            lo, hi = (0.0, 1.0) if reduced else (float(box.lo[d]), float(box.hi[d]))
            scale = float(sim.lattice.spacing[d]) if self.args.units == "lattice" and sim.lattice is not None else 1.0
            first, delta, n = lay_bins(lo, hi, origin, delta, scale, f"compute {self.id} chunk/atom", axis)
            offsets.append(first)
            deltas.append(delta)
            layers.append(n)
        self.offsets, self.deltas, self.layers = offsets, deltas, layers
        self.nchunk = math.prod(layers)
        self.coords = bin_centres(offsets, deltas, layers, f"compute {self.id} chunk/atom")
        lengths = np.ones(3) if reduced else np.asarray(box.length, dtype=np.float64)
        self.volume = float(box.volume) * math.prod(delta / lengths[d] for d, delta in zip(self.axes, deltas))

    def _assign(self, sim):
        """(chunk numbers before compress and discard, which particles are in the group and, for
        bins, within them or clamped into them)."""
        p = sim.particles
        n = p.nlocal
        inside = sim.groups.select(sim, self.group).copy()
        if self.args.style == "type":
            return p.type[:n].astype(np.int64), inside
        if self.args.style == "molecule":
            return p.arrays["molecule"][:n].astype(np.int64), inside
        box = sim.box
        reduced = self.args.units == "reduced"
        flat = np.zeros(n, dtype=np.int64)
        for d, first, delta, layers in zip(self.axes, self.offsets, self.deltas, self.layers):
            coord = p.x[:n, d]
            lo, length = float(box.lo[d]), float(box.length[d])
            if reduced:
                coord, lo, length = (coord - lo) / length, 0.0, 1.0
            where = bin_index(coord, lo, length, box.periodic[d], first, delta)
            if self.clamp:
                where = np.clip(where, 0, layers - 1)
            else:
                inside &= (where >= 0) & (where < layers)
                where = np.clip(where, 0, layers - 1)
            flat = flat * layers + where
        return flat + 1, inside

    def chunk_ids(self, sim):
        """Each owned particle's chunk, 1..N, 0 for none (int64, (nlocal,)), for the chunks set up last."""
        raw, inside = self._assign(sim)
        if self.compress:
            known = inside & (raw >= 0) & (raw < len(self.renumber))
            ids = np.zeros_like(raw)
            ids[known] = self.renumber[raw[known]]
            if self.clamp and not self.binned:
                ids[inside & (ids == 0)] = self.nchunk
            ids[~inside] = 0
            return ids
        outside = (raw < 1) | (raw > self.nchunk)
        ids = raw.copy()
        if self.clamp:
            ids[outside] = self.nchunk
        else:
            inside &= ~outside
        ids[~inside] = 0
        return ids

    def labels(self):
        """Per chunk: [OrigID with compress] then its coordinates (bins), as fix ave/chunk prints them."""
        columns = []
        if self.compress:
            columns.append(self.original_ids.astype(np.float64)[:, None])
            if self.binned:
                columns.append(self.coords[self.original_ids - 1])
        elif self.binned:
            columns.append(self.coords)
        return np.hstack(columns) if columns else np.zeros((self.nchunk, 0))

    # ---- what scripts read ------------------------------------------------------------------------
    def peratom(self, sim):
        self.setup_chunks(sim)
        return self.chunk_ids(sim).astype(np.float64)

    def scalar(self, sim):
        return float(self.setup_chunks(sim))
