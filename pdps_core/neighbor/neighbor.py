"""Neighbor lists: who builds them, when, and with what cutoff.

``neighbor SKIN [single|multi|bin]`` sets the skin; ``neigh_modify every N delay M check yes|no``
(also spelled ``neighbor_modify``) sets when a rebuild is considered, with LAMMPS's semantics:
a rebuild is considered only when ``ago >= delay`` and ``ago % every == 0`` (``ago`` = steps since the
last build); with ``check yes`` it happens only if some particle moved more than half the skin since
then. A rebuild taken on the first step it was allowed is counted as *dangerous*: an interaction may
have been missed, and the run reports how many there were.

``neigh_modify one N`` (default 2000, LAMMPS's) bounds the lists: a build needing more than N
neighbors per particle on average stops with "neighbor list overflow" (LAMMPS applies N to each
particle; pdps to the mean, so a dense cluster in a dilute gas that LAMMPS refuses still runs).

A style asks for a list with ``Neighbor.request``; a scene with no request builds no list at all.

Owned particles are re-sorted by cell every ``sort_every`` steps at a rebuild (LAMMPS's
``atom_modify sort``, default 1000), so neighbors sit close in memory. Per-particle state a style
keeps must therefore live in ``particles.request(...)`` arrays, which move with their particles.

Resuming. The rebuild schedule (``ago``, ``xhold``) and the lists carry over from one run to the next
(and through a restart file): when nothing that the lists depend on has changed since the last run
ended, the next run re-creates the lists of the last build from ``xhold`` instead of wrapping, sorting
and building afresh (``can_resume``). A wrap, a sort or a rebuild at a run's start would change
positions, particle order or summation order in the last bits and shift every later rebuild; resuming
keeps all of them, so with forces that depend on positions only ``run N`` + ``run M`` is ``run N+M``.
"""

from dataclasses import dataclass, field

import numpy as np

from ..errors import ScriptError
from ..state import limits
from .kernels import bin_particles, build_list, max_displacement_sq

ONE_DEFAULT = 2000
NO_MOLECULES = np.zeros(0, dtype=np.int64)      # build_list's molecule ids when there are none


@dataclass
class NeighborList:
    """CSR list: the neighbors of owned particle i are ``neighbors[offsets[i]:offsets[i+1]]``, row
    indices into the particle arrays (owned ``< nlocal``, ghosts after).

    ``kind`` "half" holds each pair once (newton on: a pair with a ghost once over all ranks),
    "full" holds it for both particles. ``cutoff`` is the interaction cutoff per type pair,
    (ntypes+1) x (ntypes+1); perpetual lists hold every pair within cutoff + skin (so they stay
    right until the next rebuild), occasional lists the pairs within the cutoff at the moment
    they were built. ``groupbit``: only owned particles of that group have neighbors."""
    kind: str
    cutoff: np.ndarray
    occasional: bool = False
    groupbit: int = 0xFFFFFFFF
    offsets: np.ndarray = field(default_factory=lambda: np.zeros(1, dtype=np.int64))
    neighbors: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    built_step: int | None = None

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
        self.one = ONE_DEFAULT
        self.comm_cutoff = 0.0          # comm_modify cutoff
        self.excluded_type_pairs = []   # neigh_modify exclude type I J
        self.excluded_group_pairs = []  # neigh_modify exclude group G1 G2 (group names)
        self.excluded_molecules = []    # neigh_modify exclude molecule/intra|inter G: (group, "intra"|"inter")
        self._capacity = 0
        self.built_with = None      # (skin, [(kind, cutoff)], box lo, hi, periodic) of the last build
        self.current_for = None     # (x, tag) of owned particles the lists and schedule are current for

    def modify(self, every=None, delay=None, check=None, one=None):
        if one is not None:
            self.one = one
        if every is not None:
            self.every = every
        if delay is not None:
            self.delay = delay
        if check is not None:
            self.check = check

    def clear_requests(self):
        self.requests = []

    def request(self, kind, cutoff, ntypes=None, occasional=False, groupbit=0xFFFFFFFF):
        """A style asks for a list; ``cutoff`` is a (ntypes+1)^2 matrix or a number (the same for
        every type pair: ``ntypes`` is then needed)."""
        if kind not in ("half", "full"):
            raise ScriptError(f"neighbor list kind must be half or full (got {kind})")
        cutoff = np.asarray(cutoff, dtype=np.float64)
        if cutoff.ndim == 0:
            cutoff = np.full((ntypes + 1, ntypes + 1), float(cutoff))
        if not (np.isfinite(cutoff).all() and cutoff.max() > 0):
            raise ScriptError(f"neighbor list cutoff must be a finite number > 0 (got {cutoff.max():g})")
        nlist = NeighborList(kind, cutoff, occasional=occasional, groupbit=groupbit)
        self.requests.append(nlist)
        return nlist

    @property
    def perpetual(self):
        return [r for r in self.requests if not r.occasional]

    @property
    def active(self):
        return bool(self.requests)

    def cutghost(self):
        """The largest list cutoff plus the skin (0 without lists)."""
        if not self.requests:
            return 0.0
        return max(float(r.cutoff.max()) for r in self.requests) + self.skin

    def ghost_cutoff(self):
        """How far beyond the box ghosts are made: cutghost, or LAMMPS's ``comm_modify cutoff`` when
        that is larger (and there are lists to use them)."""
        reach = self.cutghost()
        return max(reach, self.comm_cutoff) if reach > 0 else 0.0

    # ---- rebuild decision ---------------------------------------------------------------------
    def decide(self, particles, comm):
        """Called once per step before forces: True when particles must be re-wrapped and the lists
        rebuilt now. Without any list it still decides when to wrap, so lost particles are caught."""
        self.ago += 1
        if self.ago < self.delay or self.ago % self.every:
            return False
        local_sq, who = max_displacement_sq(particles.x, self.xhold, len(self.xhold))
        self.moved = (float(np.sqrt(local_sq)), who)          # this rank's, for naming a particle
        moved_sq = comm.max(local_sq)                          # every rank decides alike
        if self.check:
            limit = 0.5 * self.skin
            if moved_sq <= limit * limit:
                return False
            if self.requests and moved_sq > self.skin * self.skin:
                self.overrun = max(self.overrun, float(np.sqrt(moved_sq)))
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
        nbins = limits.bin_grid(box.length, binsize)
        if box.dimension == 2:
            nbins[2] = 1
        cell, _, order = bin_particles(particles.x, particles.nlocal, box.lo, box.length / nbins, nbins)
        return order

    # ---- resuming -------------------------------------------------------------------------------
    def mark_current(self, particles):
        """The lists and the rebuild schedule are current for these particles (a run ended, or a
        restart is written): remember their positions and order, so the next run can resume."""
        n = particles.nlocal
        self.current_for = (particles.x[:n].copy(), particles.tag[:n].copy())

    def is_current(self, particles):
        """True when no particle moved, appeared, vanished or changed place since ``mark_current``."""
        if self.current_for is None or self.xhold is None:
            return False
        x, tag = self.current_for
        n = particles.nlocal
        return (len(tag) == n and len(self.xhold) == n and np.array_equal(particles.tag[:n], tag)
                and np.array_equal(particles.x[:n], x))

    def can_resume(self, particles, box, comm):
        """Called at the start of a run, after the styles made their requests: True when the lists of
        the last build are still right (same particles, positions, box, skin and cutoffs), so the run
        continues the schedule instead of starting afresh. Answers once per mark; all ranks agree."""
        current = self.is_current(particles)
        self.current_for = None
        same = current and self.built_with is not None
        if same:
            skin, lists, lo, hi, periodic = self.built_with
            same = (skin == self.skin and np.array_equal(lo, box.lo) and np.array_equal(hi, box.hi)
                    and periodic == box.periodic and len(lists) == len(self.requests)
                    and all(kind == r.kind and np.array_equal(cutoff, r.cutoff)
                            for (kind, cutoff), r in zip(lists, self.requests)))
        return bool(comm.min(int(same)))

    # ---- build ----------------------------------------------------------------------------------
    def build(self, particles, box, resume=False):
        """Build every perpetual list; with none, only remember positions for the next decision.
        ``resume``: owned positions are ``xhold`` and the lists of the last build are made again;
        the rebuild schedule goes on."""
        p = particles
        if not resume:
            self.xhold = p.x[:p.nlocal].copy()
            self.ago = 0
        self.built_with = (self.skin, [(r.kind, r.cutoff.copy()) for r in self.requests],
                           box.lo.copy(), box.hi.copy(), box.periodic)
        lists = self.perpetual
        if not lists:
            return
        binned = self._bin(p, box)
        for nlist in lists:
            self._fill(nlist, p, binned, self.skin)
        self.builds += 1

    def build_occasional(self, nlist, particles, box, step):
        """Build an occasional list now, from the current positions of owned particles and ghosts
        (pairs within its cutoff, no skin); once per step however often it is asked for."""
        if nlist.built_step == step:
            return nlist
        self._fill(nlist, particles, self._bin(particles, box), 0.0)
        nlist.built_step = step
        return nlist

    def _bin(self, p, box):
        cutmax = self.cutghost()
        if cutmax <= 0:
            raise ScriptError("neighbor list cutoff must be > 0")
        reach = self.ghost_cutoff()
        lo = box.lo - reach
        extent = box.length + 2 * reach
        nbins = limits.bin_grid(extent, cutmax)
        if box.dimension == 2:
            nbins[2] = 1
            extent[2] = max(extent[2], 1.0)
        binsize = extent / nbins
        cell, start, order = bin_particles(p.x, p.nall, lo, binsize, nbins)
        return cell, start, order, nbins

    def exclusions(self, ntypes, groups):
        """The tables build_list reads, from neigh_modify exclude (called at a run's start)."""
        table = np.zeros((ntypes + 1, ntypes + 1), dtype=np.bool_)
        for (ilo, ihi), (jlo, jhi) in self.excluded_type_pairs:
            table[ilo:ihi + 1, jlo:jhi + 1] = True
            table[jlo:jhi + 1, ilo:ihi + 1] = True
        self._excluded_types = table
        self._excluded_groups = np.array([[groups.bit(a), groups.bit(b)] for a, b in self.excluded_group_pairs],
                                         dtype=np.uint32).reshape(-1, 2)
        self._excluded_molecules = np.array([[groups.bit(g), kind == "intra"] for g, kind in self.excluded_molecules],
                                            dtype=np.uint32).reshape(-1, 2)

    def _fill(self, nlist, p, binned, skin):
        cell, start, order, nbins = binned
        if getattr(self, "_excluded_types", None) is None or self._excluded_types.shape[0] != nlist.cutoff.shape[0]:
            self._excluded_types = np.zeros(nlist.cutoff.shape, dtype=np.bool_)
            self._excluded_groups = np.zeros((0, 2), dtype=np.uint32)
            self._excluded_molecules = np.zeros((0, 2), dtype=np.uint32)
        molecule = p.molecule if p.has("molecule") else NO_MOLECULES
        cutneighsq = (nlist.cutoff + skin) ** 2
        if cutneighsq.shape[0] != self.requests[0].cutoff.shape[0]:
            raise ScriptError("neighbor requests disagree on the number of types")
        # LAMMPS's neigh_modify one, taken as a mean: a list that would outgrow it is a mistake
        # (overlapping particles, a typo in a lattice), not something to allocate gigabytes for
        most = self.one * max(p.nlocal, 1)
        capacity = min(max(self._capacity, 64 * max(p.nlocal, 1)), most)
        while True:
            offsets, neighbors, total = build_list(
                p.x, p.type, p.mask, np.uint32(nlist.groupbit), p.nlocal, cutneighsq, cell, start,
                order, nbins, nlist.half_list, capacity, self._excluded_types, self._excluded_groups,
                molecule, self._excluded_molecules)
            if total >= 0:
                break
            if capacity >= most:
                raise ScriptError(f"neighbor list overflow: more than {self.one} neighbors per particle "
                                  f"on average within {float(np.sqrt(cutneighsq.max())):g} of "
                                  f"{p.nlocal} particles (overlapping particles?); "
                                  "raise neigh_modify one if that is meant")
            capacity = min(2 * capacity, most)
        self._capacity = capacity
        nlist.offsets, nlist.neighbors = offsets, neighbors[:total]
