"""Neighbor lists: who builds them, when, and with what cutoff.

``neighbor SKIN [single|multi|bin]`` sets the skin; ``neigh_modify every N delay M check yes|no``
(also spelled ``neighbor_modify``) sets when a rebuild is considered, with LAMMPS's semantics:
a rebuild is considered only when ``ago >= delay`` and ``ago % every == 0`` (``ago`` = steps since the
last build); with ``check yes`` it happens only if some particle moved more than half the skin since
then. A rebuild taken on the first step it was allowed is counted as *dangerous*: an interaction may
have been missed, and the run reports how many there were.

A style asks for a list with ``Neighbor.request``; a scene with no request builds no list at all.

Owned particles are re-sorted by cell every ``sort_every`` steps at a rebuild (LAMMPS's
``atom_modify sort``, default 1000), so neighbors sit close in memory. Per-particle state a style
keeps must therefore live in ``particles.request(...)`` arrays, which move with their particles.
"""

from dataclasses import dataclass, field

import numpy as np

from ..errors import ScriptError
from .kernels import bin_particles, build_list, max_displacement_sq


@dataclass
class NeighborList:
    """CSR list: the neighbors of owned particle i are ``neighbors[offsets[i]:offsets[i+1]]``."""
    kind: str                    # "half" or "full"
    cutoff: np.ndarray           # interaction cutoff per type pair, (ntypes+1) x (ntypes+1)
    offsets: np.ndarray = field(default_factory=lambda: np.zeros(1, dtype=np.int64))
    neighbors: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))

    @property
    def half_list(self):
        return self.kind == "half"


class Neighbor:
    def __init__(self, skin=0.3):
        self.skin = skin
        self.style = "single"
        self.every = 1
        self.delay = 0
        self.check = True
        self.requests = []
        self.ago = 0
        self.xhold = None
        self.builds = 0
        self.dangerous = 0
        self.overrun = 0.0          # largest move beyond the whole skin between builds, this run
        self.moved = (0.0, -1)      # (largest move since the last build, owned index), at the last decision
        self.sort_every = 1000
        self.last_sort = None
        self._capacity = 0

    def modify(self, every=None, delay=None, check=None):
        if every is not None:
            self.every = every
        if delay is not None:
            self.delay = delay
        if check is not None:
            self.check = check

    def clear_requests(self):
        self.requests = []

    def request(self, kind, cutoff):
        """A style asks for a list; ``cutoff`` is a (ntypes+1)^2 matrix or a number."""
        if kind not in ("half", "full"):
            raise ValueError(f"neighbor list kind must be half or full (got {kind})")
        nlist = NeighborList(kind, np.asarray(cutoff, dtype=np.float64))
        self.requests.append(nlist)
        return nlist

    @property
    def active(self):
        return bool(self.requests)

    def cutghost(self):
        """How far beyond the box ghosts are needed: the largest cutoff plus the skin."""
        if not self.requests:
            return 0.0
        return max(float(r.cutoff.max()) for r in self.requests) + self.skin

    # ---- rebuild decision ---------------------------------------------------------------------
    def decide(self, particles):
        """Called once per step before forces: True when particles must be re-wrapped and the lists
        rebuilt now. Without any list it still decides when to wrap, so lost particles are caught."""
        self.ago += 1
        if self.ago < self.delay or self.ago % self.every:
            return False
        moved_sq, who = max_displacement_sq(particles.x, self.xhold, len(self.xhold))
        self.moved = (float(np.sqrt(moved_sq)), who)
        if self.check:
            limit = 0.5 * self.skin
            if moved_sq <= limit * limit:
                return False
            if self.requests and moved_sq > self.skin * self.skin:
                self.overrun = max(self.overrun, self.moved[0])
        if self.ago == max(self.every, self.delay) and self.check:
            self.dangerous += 1
        return True

    # ---- spatial sort ---------------------------------------------------------------------------
    def sort_due(self, step):
        if not self.requests or self.sort_every <= 0:
            return False
        return self.last_sort is None or step - self.last_sort >= self.sort_every

    def spatial_order(self, particles, box, step):
        """Permutation of owned particles that groups them by cell (cells of half the cutoff)."""
        self.last_sort = step
        binsize = max(self.cutghost(), 1e-12) * 0.5
        nbins = np.maximum(1, np.floor(box.length / binsize)).astype(np.int64)
        if box.dimension == 2:
            nbins[2] = 1
        cell, _, order = bin_particles(particles.x, particles.nlocal, box.lo, box.length / nbins, nbins)
        return order

    # ---- build ----------------------------------------------------------------------------------
    def build(self, particles, box):
        """Build every requested list; with none, only remember positions for the next decision."""
        p = particles
        self.xhold = p.x[:p.nlocal].copy()
        self.ago = 0
        if not self.requests:
            return
        x, nall, nlocal = p.x, p.nall, p.nlocal
        ntypes_plus_one = self.requests[0].cutoff.shape[0]
        cutmax = max(float(r.cutoff.max()) for r in self.requests) + self.skin
        if cutmax <= 0:
            raise ScriptError("neighbor list cutoff must be > 0")
        lo = box.lo - cutmax
        extent = box.length + 2 * cutmax
        nbins = np.maximum(1, np.floor(extent / cutmax)).astype(np.int64)
        if box.dimension == 2:
            nbins[2] = 1
            extent[2] = max(extent[2], 1.0)
        binsize = extent / nbins
        cell, start, order = bin_particles(x, nall, lo, binsize, nbins)
        for nlist in self.requests:
            cutneighsq = (nlist.cutoff + self.skin) ** 2
            if cutneighsq.shape[0] != ntypes_plus_one:
                raise ScriptError("neighbor requests disagree on the number of types")
            capacity = max(self._capacity, 64 * max(nlocal, 1))
            while True:
                offsets, neighbors, total = build_list(
                    x, p.type, nlocal, cutneighsq, cell, start, order, nbins,
                    nlist.half_list, capacity)
                if total >= 0:
                    break
                capacity *= 2
            self._capacity = capacity
            nlist.offsets, nlist.neighbors = offsets, neighbors[:total]
        self.builds += 1
