"""Neighbor lists: who builds them, when, and with what cutoff.

``neighbor SKIN [single|multi|bin]`` sets the skin; ``neigh_modify every N delay M check yes|no``
(also spelled ``neighbor_modify``) sets when a rebuild is considered, with LAMMPS's semantics:
a rebuild is considered only when ``ago >= delay`` and ``ago % every == 0`` (``ago`` = steps since the
last build); with ``check yes`` it happens only if some particle moved more than half the skin since
then. A rebuild taken on the first step it was allowed is counted as *dangerous*: an interaction may
have been missed, and the run reports how many there were. Where a fix changes radii during the
run (``Fix.varies_radius``: fix adapt), a particle's move counts its radius growth since the build
too (LIGGGHTS's rule with radii that vary).

``neigh_modify one N`` (default 2000, LAMMPS's) bounds the lists: a build needing more than N
neighbors per particle on average stops with "neighbor list overflow" (LAMMPS applies N to each
particle; pdps to the mean, so a dense cluster in a dilute gas that LAMMPS refuses still runs).

A style asks for a list with ``Neighbor.request``; a scene with no request builds no list at all.

Owned particles are re-sorted by cell every ``sort_every`` steps at a rebuild (LAMMPS's
``atom_modify sort``, default 1000; 100 in direct mode unless atom_modify gave it), so neighbors sit
close in memory. Per-particle state a style
keeps must therefore live in ``particles.request(...)`` arrays, which move with their particles.

Direct mode (``NeighborList``): where nearly every decision rebuilds, a force-law pair style is computed
from cell bins made at every step, and the skin only keeps the ghosts valid; it then widens to
``DIRECT_SKIN`` cutoffs (``choose_skin``), so migration and ghosts are made every few steps. ``skin``
is the skin in effect, ``requested_skin`` the script's (which decides direct mode and comes back with
the lists).

Resuming. The rebuild schedule (``ago``, ``xhold``) and the lists carry over from one run to the next
(and through a restart file): when nothing that the lists depend on has changed since the last run
ended, no particle is beyond a fixed face and no face is shrink-wrapped (LAMMPS's setup drops the
former and fits the latter), the next run re-creates the lists of the last build from ``xhold``
instead of wrapping, sorting and building afresh (``can_resume``). A wrap, a sort or a rebuild at a run's start would change
positions, particle order or summation order in the last bits and shift every later rebuild; resuming
keeps all of them, so with forces that depend on positions only ``run N`` + ``run M`` is ``run N+M``.
"""

import numpy as np

from ..errors import ScriptError
from ..state import limits
from .skin_trial import SkinTrial
from .kernels import (bin_into, build_list, cell_order, extent, largest_displacement_sq, largest_reach_sq,
                      max_displacement_sq)

ONE_DEFAULT = 2000
# Rows of neighbors in a list: 32 bits (half the memory and the bandwidth of 64; a rank holds fewer
# than 2^31 particles and ghosts).
NEIGHBOR_INDEX = np.int32
# bin heads, bin of each particle, particles in bin order: rows and bins of one rank fit in 32 bits
BIN_INDEX = np.int32
# Direct mode (NeighborList) from the next build on when at least DIRECT_AT of the last 16 rebuild
# decisions rebuilt: a list that lives one step costs more to write and read than the pairs it saves.
HISTORY_MASK = 0xFFFF
DIRECT_AT = 14
# In direct mode particles are re-sorted by cell every DIRECT_SORT_EVERY steps (unless atom_modify
# sort says otherwise): a fluid whose lists live one step also diffuses fast, and the cell loops read
# partners in cell order (dpd_gw's cell loop 17.7 ms 300 steps after a sort, 12.0 ms right after one).
DIRECT_SORT_EVERY = 100
# In direct mode the skin is half a cutoff (unless the script's is wider): it only keeps the ghosts
# valid, and a wider one trades rebuilds (a migration and a ghost exchange) for ghosts to copy and
# hold. dpd_gw (cutoff 1, skin 0.3, dt 0.04), 300 steps: 301 rebuilds -> 163, Comm 0.37 -> 0.26 s on
# one rank and 0.48 -> 0.35 s on two; a whole cutoff (112 rebuilds) is no faster and holds 8,000 more
# ghosts (peak memory growth from dpd_water to dpd_gw 285 -> 296 bytes a particle; 411 with a cutoff).
DIRECT_SKIN = 0.5
# Room for one particle's candidate partners in the cell loops (the particles of its stencil's bins;
# about 100 in dense LJ or DPD): a denser bin makes the loop allocate more for that call
DIRECT_PARTNERS = 1024
NO_MOLECULES = np.zeros(0, dtype=np.int64)      # build_list's molecule ids when there are none
NO_SPECIAL = np.zeros((0, 1), dtype=np.int64)   # and its special neighbors (pdps_core/state/topology.py)
NO_NSPECIAL = np.zeros((0, 3), dtype=np.int32)


# neigh_modify exclude molecule/inter, molecule/intra, and within bodies (molecule ids > 0): the codes the
# list kernels read
MOLECULE_EXCLUSIONS = ("inter", "intra", "body")

class NeighborList:
    """CSR list: the neighbors of owned particle i are ``neighbors[offsets[i]:offsets[i+1]]``, row
    indices into the particle arrays (owned ``< nlocal``, ghosts after).

    ``kind`` "half" holds each pair once (newton on: a pair with a ghost once over all ranks),
    "full" holds it for both particles. ``cutoff`` is the interaction cutoff per type pair,
    (ntypes+1) x (ntypes+1); perpetual lists hold every pair within cutoff + skin (so they stay
    right until the next rebuild), occasional lists the pairs within the cutoff at the moment
    they were built. ``groupbit``: only owned particles of that group have neighbors.

    Direct mode (``direct``, for a list requested with ``direct_ok``, when the lists are rebuilt at
    nearly every step): the pair style computes forces from the cell bins ``cells`` made at every
    step, and the list itself is built only if something reads ``offsets`` or ``neighbors``: from
    that step's bins, the pairs within the cutoff at that step (no skin: it is made again at the next
    step it is read). Read it before positions move on (fix shardlow reads it at initial_integrate,
    before the integrator that follows it; computes at output): the bins are those of the step's
    forces.

    ``version`` grows by one at every build: a style that keeps something made from the list (the
    row of each entry, say) makes it again when the version it was made from is not the list's."""

    def __init__(self, kind, cutoff, occasional=False, groupbit=0xFFFFFFFF, direct_ok=False):
        self.kind = kind
        self.cutoff = cutoff
        self.occasional = occasional
        self.groupbit = groupbit
        self.direct_ok = direct_ok
        self.direct = False
        self.cells = None           # direct mode: the bins, as the core's cell loops read them
        self.built_step = None
        self.buffer = np.zeros(0, dtype=NEIGHBOR_INDEX)
        self.offset_buffer = np.zeros(0, dtype=np.int64)
        self._offsets = np.zeros(1, dtype=np.int64)
        self._neighbors = np.zeros(0, dtype=NEIGHBOR_INDEX)
        self._pending = None        # builds the list when it is read (direct mode)
        self.version = 0            # one more at every build: what a style derived from the list is stale

    def _current(self):
        if self._pending is not None:
            build, self._pending = self._pending, None
            build()

    @property
    def offsets(self):
        self._current()
        return self._offsets

    @offsets.setter
    def offsets(self, value):
        self._offsets = value

    @property
    def neighbors(self):
        self._current()
        return self._neighbors

    @neighbors.setter
    def neighbors(self, value):
        self._neighbors = value
        self.version += 1

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
        self.once = False           # neigh_modify once yes: lists built at a run's start only
        self.once_overrun = 0.0     # with once: the largest move beyond half the skin, this run
        self.requests = []
        self.ago = 0
        self.xhold = None
        self.radii_vary = False     # a fix changes radii in the run: the decision counts their growth
        self.rhold = None           # the owned radii at the last build, where radii vary
        self.builds = 0
        self.dangerous = 0
        self.overrun = 0.0          # largest move beyond the whole skin between builds, this run
        self.moved_everywhere = 0.0  # the largest move over all ranks since the last build (inf: not measured)
        self._moved_sq = np.zeros(1)
        self.sort_every = 1000
        self.sort_set = False       # atom_modify sort given: its interval holds in direct mode too
        self.last_sort = None
        self.one = ONE_DEFAULT
        self.comm_cutoff = 0.0          # comm_modify cutoff
        self.excluded_type_pairs = []   # neigh_modify exclude type I J
        self.excluded_group_pairs = []  # neigh_modify exclude group G1 G2 (group names)
        self.excluded_molecules = []    # neigh_modify exclude molecule/intra|inter G: (group, "intra"|"inter")
        self._cell = self._order = self._slot = self._start = self._ghost_start = np.zeros(0, dtype=BIN_INDEX)
        self._last_grid = {}
        self._direct = {name: np.zeros(0, dtype=BIN_INDEX) for name in ("cell", "start", "ghost_start", "order", "slot")}
        # the cell loops' scratch (pdps_core.pair_loop): runs of a stencil, partners of one particle
        self._direct.update(run_begin=np.zeros(0, dtype=np.int64), run_end=np.zeros(0, dtype=np.int64),
                            hits=np.empty(DIRECT_PARTNERS, dtype=np.int64))
        self.history = 0            # the last rebuild decisions, one bit each (1: rebuilt)
        self.skin_trial = None      # neighbor auto: a SkinTrial until it has chosen
        self.moved_at_build = 0.0   # the largest move since the last build seen at a rebuild (the trial's)
        self._stencils = {}
        self.built_with = None      # (skin, [(kind, cutoff)], box lo, hi, periodic) of the last build
        self.current_for = None     # (x, tag) of owned particles the lists and schedule are current for

    def exclude_molecules(self, group, kind="intra"):
        """Leave out of the lists the pairs of ``group`` in one molecule (intra) or in two (inter), as
        ``neigh_modify exclude molecule/intra|inter GROUP`` does; or (body) in one molecule of id
        > 0, the particles of molecule 0 belonging to none (a fix whose bodies have molecule ids:
        LIGGGHTS's fix multisphere, whose exclusion leaves its loose spheres in the lists)."""
        if kind not in MOLECULE_EXCLUSIONS:
            raise ValueError(f"exclude_molecules: kind must be one of {', '.join(MOLECULE_EXCLUSIONS)} (got {kind})")
        if (group, kind) not in self.excluded_molecules:
            self.excluded_molecules.append((group, kind))

    @property
    def skin(self):
        """The skin in effect since the last build (what the rebuild decision, the ghosts and every
        list built then use): the script's (``requested_skin``), or in direct mode the wider
        ``direct_skin``. Setting it sets the script's."""
        return self._skin

    @skin.setter
    def skin(self, value):
        self.requested_skin = self._skin = value

    def choose_skin(self, box):
        """Called before each build, ghosts included: the skin the coming build uses. In direct mode
        the list is made again at every step anyway and the skin only keeps the ghosts valid, so a
        wider one (``direct_skin``) rebuilds less often, at the price of more ghosts to copy."""
        lists = self.perpetual
        direct = (self._direct_due() and bool(lists) and all(r.direct_ok for r in lists) and self.check
                  and not self.once and self.skin_trial is None)
        self._skin = self.direct_skin(box) if direct else self.requested_skin

    def _direct_due(self):
        """Direct mode for the lists that allow it at the coming build: nearly every recent decision
        rebuilt, and no exclusions (the cell loops know none: such a scene keeps its lists)."""
        levels = getattr(self, "_special_levels", None)
        excluding = bool(self.excluded_type_pairs or self.excluded_group_pairs or self.excluded_molecules
                         or (levels is not None and levels.any()))
        return bin(self.history).count("1") >= DIRECT_AT and not excluding

    def use_built_skin(self):
        """The skin of the last build in effect again until the next one (a restart read in direct
        mode: its lists and ghosts were made with the wider skin)."""
        self._skin = self.built_with[0]

    def direct_skin(self, box):
        """DIRECT_SKIN cutoffs, not under the script's skin, and short enough that the ghost cutoff
        stays under half of every periodic box length (a particle then has at most one image on each
        side, as with the script's skin in any box where direct mode pays)."""
        cutoff = max(float(r.cutoff.max()) for r in self.requests)
        skin = DIRECT_SKIN * cutoff
        lengths = [float(box.length[d]) for d in range(box.dimension) if box.periodic[d]]
        if lengths:
            skin = min(skin, 0.5 * min(lengths) - cutoff)
        return max(skin, self.requested_skin)

    def start_skin_trial(self):
        """``neighbor auto``: the next run tries skins first (skin_trial.py)."""
        self.skin_trial = SkinTrial(self.skin)

    def modify(self, every=None, delay=None, check=None, one=None, once=None):
        if once is not None:
            self.once = once
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

    def request(self, kind, cutoff, ntypes=None, occasional=False, groupbit=0xFFFFFFFF, direct_ok=False):
        """A style asks for a list; ``cutoff`` is a (ntypes+1)^2 matrix or a number (the same for
        every type pair: ``ntypes`` is then needed). ``direct_ok``: the style can compute from the
        cell bins instead (a half list; NeighborList's direct mode)."""
        if kind not in ("half", "full"):
            raise ScriptError(f"neighbor list kind must be half or full (got {kind})")
        cutoff = np.asarray(cutoff, dtype=np.float64)
        if cutoff.ndim == 0:
            cutoff = np.full((ntypes + 1, ntypes + 1), float(cutoff))
        # a zero cutoff is a granular pair with no particle present or to come (its reach is their
        # radii): the skin still sizes the bins
        if not (np.isfinite(cutoff).all() and cutoff.min() >= 0 and cutoff.max() + self.skin > 0):
            raise ScriptError(f"neighbor list cutoff must be a finite number >= 0, and > 0 without a skin "
                              f"(got {cutoff.max():g}, skin {self.skin:g})")
        nlist = NeighborList(kind, cutoff, occasional=occasional, groupbit=groupbit,
                             direct_ok=direct_ok and kind == "half" and not occasional)
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
        that is larger. A script that sets it gets ghosts without any list too (fix rigid/small's
        bodies reach their particles on other ranks through them, as in LAMMPS); without either,
        none are made."""
        return max(self.cutghost(), self.comm_cutoff)

    # ---- rebuild decision ---------------------------------------------------------------------
    def decide(self, particles, comm):
        """Called once per step before forces: True when particles must be re-wrapped and the lists
        rebuilt now. Without any list it still decides when to wrap, so lost particles are caught."""
        rebuild, rebuild_at_requested = self._decide(particles, comm)
        # direct mode is decided by the script's skin, not by the wider one it brings
        self.history = ((self.history << 1) | int(rebuild_at_requested)) & HISTORY_MASK
        return rebuild

    def moved(self, particles):
        """(largest move of this rank's particles since the last build, its owned index): for naming
        a particle that ran away, so only looked for then."""
        if self.xhold is None:
            return 0.0, -1
        local_sq, who = max_displacement_sq(particles.x, self.xhold, len(self.xhold))
        return float(np.sqrt(local_sq)), who

    def _decide(self, particles, comm):
        self.ago += 1
        if self.ago < self.delay or self.ago % self.every:
            self.moved_everywhere = np.inf
            return False, False
        # every rank decides alike; an array is reduced by MPI's own reduction (4 us), a Python
        # float by mpi4py's pickled one (17 us), at every step
        if self.radii_vary:
            self._moved_sq[0] = largest_reach_sq(particles.x, self.xhold, particles.radius,
                                                 self._radius_hold(particles), len(self.xhold))
        else:
            self._moved_sq[0] = largest_displacement_sq(particles.x, self.xhold, len(self.xhold))
        moved_sq = float(comm.max(self._moved_sq)[0])
        self.moved_everywhere = float(np.sqrt(moved_sq))
        if self.once:
            # LAMMPS builds no list after the run's first; pdps still says when pairs may be missed
            if self.requests and moved_sq > (0.5 * self.skin) ** 2:
                self.once_overrun = max(self.once_overrun, self.moved_everywhere)
            return False, False
        if self.check:
            limit = 0.5 * self.skin
            if moved_sq <= limit * limit:
                return False, moved_sq > (0.5 * self.requested_skin) ** 2
            if self.requests and moved_sq > self.skin * self.skin:
                self.overrun = max(self.overrun, float(np.sqrt(moved_sq)))
        if self.ago == max(self.every, self.delay) and self.check:
            self.dangerous += 1
        self.moved_at_build = max(self.moved_at_build, float(np.sqrt(moved_sq)))
        return True, True

    def _radius_hold(self, particles):
        """The radii of the last build (the current ones where none were kept for these particles:
        a run resumed from a restart file, which keeps the positions of the last build only)."""
        if self.rhold is None or len(self.rhold) != len(self.xhold):
            self.rhold = particles.radius[:len(self.xhold)].copy()
        return self.rhold

    # ---- spatial sort ---------------------------------------------------------------------------
    def sort_due(self, step):
        if not self.requests or self.sort_every <= 0:
            return False
        every = self.sort_every
        if not self.sort_set and any(nlist.direct for nlist in self.requests):
            every = min(every, DIRECT_SORT_EVERY)
        return self.last_sort is None or step - self.last_sort >= every

    def spatial_order(self, particles, box, step):
        """Permutation of owned particles that groups them by cell (cells of half the cutoff)."""
        self.last_sort = step
        binsize = max(self.cutghost(), 1e-12) * 0.5
        nbins = limits.bin_grid(box.length, binsize)
        if box.dimension == 2:
            nbins[2] = 1
        return cell_order(particles.x, particles.nlocal, box.lo, box.length / nbins, nbins)

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

    def can_resume(self, particles, box, comm, wrap=False):
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
        if same:
            # a run's setup drops what crossed a fixed face since the last build, as LAMMPS's does;
            # with ``wrap`` (the LAMMPS dialect) it also wraps what crossed a periodic one, as
            # LAMMPS's setup does, so that region tests and positions read after it see the wrapped
            # positions (a temp/region compute); without, split runs go on as one run to the last bit
            x = particles.x[:particles.nlocal]
            for d in range(3):
                if (wrap or not box.periodic[d]) and len(x) and (x[:, d].min() < box.lo[d]
                                                                 or x[:, d].max() >= box.hi[d]):
                    same = False
        return bool(comm.min(int(same)))

    # ---- build ----------------------------------------------------------------------------------
    def build(self, particles, box, resume=False):
        """Build every perpetual list; with none, only remember positions for the next decision.
        ``resume``: owned positions are ``xhold`` and the lists of the last build are made again;
        the rebuild schedule goes on."""
        p = particles
        if not resume:
            if self.xhold is not None and self.xhold.shape == (p.nlocal, 3):
                self.xhold[:] = p.x[:p.nlocal]
            else:
                self.xhold = p.x[:p.nlocal].copy()
            self.ago = 0
            if self.radii_vary:
                self.rhold = p.radius[:p.nlocal].copy()
        # resuming, positions are current and the moves since xhold not measured on every rank
        self.moved_everywhere = np.inf if resume else 0.0
        self.built_with = (self.skin, [(r.kind, r.cutoff.copy()) for r in self.requests],
                           box.lo.copy(), box.hi.copy(), box.periodic)
        lists = self.perpetual
        if not lists:
            return
        direct = self._direct_due()
        binned = None
        for nlist in lists:
            # a list read in direct mode was made from the bins of its step: none is owed any more
            nlist._pending = None
            going_direct = direct and nlist.direct_ok and not nlist.direct
            nlist.direct = direct and nlist.direct_ok
            if going_direct:
                # the list's memory back (it is built again only if something reads it)
                nlist.buffer = np.zeros(0, dtype=NEIGHBOR_INDEX)
                nlist.offsets, nlist.neighbors = np.zeros(1, dtype=np.int64), np.zeros(0, dtype=NEIGHBOR_INDEX)
            if not nlist.direct:
                binned = binned or self._bin(p, box)
                self._fill(nlist, p, binned, self.skin)
        if binned is None and any(nlist.direct for nlist in lists) and len(self._cell):
            self._cell = self._order = self._slot = self._start = self._ghost_start = np.zeros(0, dtype=BIN_INDEX)
        self.builds += 1
        self.refresh(p, box)

    def refresh(self, particles, box):
        """Direct mode, at every step once ghosts are current: bin the particles where they are now
        for the cell loops, and let a direct list be built from them if something reads it."""
        for nlist in self.perpetual:
            if nlist.direct:
                nlist.cells = self._direct_bins(particles, box, nlist)
                # a list read in direct mode is made for this step only (the next refresh replaces
                # it): the pairs within the cutoff now, from this step's bins, with no skin
                nlist._pending = lambda nlist=nlist, p=particles: \
                    self._fill(nlist, p, self._direct_grid, 0.0, bins=nlist.cells[:5], moved=self.moved_everywhere)

    def _direct_bins(self, p, box, nlist):
        """Bins of half the interaction cutoff (no skin: they are made afresh at every step) with
        their stencils and the interior box (where no ghost is within the cutoff), in buffers of
        their own (other lists' builds must not overwrite them)."""
        cut = float(nlist.cutoff.max())
        grid = self._direct_grid = self._grid(box, cut, p, cache="direct")
        lo, binsize, nbins, keep_off = grid
        bins = self._direct
        ncells = int(np.prod(nbins))
        if len(bins["start"]) < ncells + 1:
            size = ncells + ncells // 4 + 16
            bins["start"] = np.empty(size, dtype=BIN_INDEX)
            bins["ghost_start"] = np.empty(size, dtype=BIN_INDEX)
        if len(bins["cell"]) < p.nall:
            size = int(1.25 * p.nall) + 16
            bins["cell"], bins["order"] = np.empty(size, dtype=BIN_INDEX), np.empty(size, dtype=BIN_INDEX)
        if len(bins["slot"]) < p.nlocal:
            bins["slot"] = np.empty(int(1.25 * p.nlocal) + 16, dtype=BIN_INDEX)
        bin_into(p.x, p.nall, p.nlocal, lo, binsize, nbins, keep_off, bins["cell"], bins["start"],
                 bins["ghost_start"], bins["order"], bins["slot"])
        # at the last build the ghosts lay outside the owned particles' bounding box; since then every
        # particle moved up to d, so the ghosts lie outside the box of the owned ones now shrunk by 2d
        owned_lo_hi = extent(p.x, p.nlocal, p.nlocal)
        margin = cut + 2.0 * self.moved_everywhere
        inner_lo, inner_hi = owned_lo_hi[0] + margin, owned_lo_hi[1] - margin
        if box.dimension == 2:
            inner_lo[2], inner_hi[2] = -np.inf, np.inf
        owned_rows, ghost_rows = self._stencil(grid, cut, True), self._stencil(grid, cut, "above")
        # the cell loops' scratch: the runs of one particle's stencil and its partners within the cutoff
        runs = 1 + len(owned_rows) + len(ghost_rows)
        if len(bins["run_begin"]) < runs:
            bins["run_begin"], bins["run_end"] = np.empty(runs, dtype=np.int64), np.empty(runs, dtype=np.int64)
        return (bins["cell"], bins["start"], bins["ghost_start"], bins["order"], bins["slot"], owned_rows,
                ghost_rows, inner_lo, inner_hi, bins["run_begin"], bins["run_end"], bins["hits"])

    def build_occasional(self, nlist, particles, box, step):
        """Build an occasional list now, from the current positions of owned particles and ghosts
        (pairs within its cutoff, no skin); once per step however often it is asked for."""
        if nlist.built_step == step:
            return nlist
        self._fill(nlist, particles, self._bin(particles, box), 0.0, moved=self.moved_everywhere)
        nlist.built_step = step
        return nlist

    def _bin(self, p, box):
        """Bin every particle, owned and ghost, on the grid of the current cutoffs (``_grid``); the
        buffers are kept from build to build."""
        cutneigh = self.cutghost()
        if cutneigh <= 0:
            raise ScriptError("neighbor list cutoff must be > 0")
        grid = self._grid(box, cutneigh, p)
        lo, binsize, nbins, keep_off = grid
        ncells = int(np.prod(nbins))
        if len(self._start) < ncells + 1:
            # a quarter more: a grid that follows the particles along a fixed boundary grows often
            size = ncells + ncells // 4 + 16
            self._start = np.empty(size, dtype=BIN_INDEX)
            self._ghost_start = np.empty(size, dtype=BIN_INDEX)
        if len(self._cell) < p.nall:
            size = int(1.25 * p.nall) + 16
            self._cell, self._order = np.empty(size, dtype=BIN_INDEX), np.empty(size, dtype=BIN_INDEX)
        if len(self._slot) < p.nlocal:
            self._slot = np.empty(int(1.25 * p.nlocal) + 16, dtype=BIN_INDEX)
        bin_into(p.x, p.nall, p.nlocal, lo, binsize, nbins, keep_off, self._cell, self._start,
                 self._ghost_start, self._order, self._slot)
        return grid

    def _grid(self, box, cutneigh, p, cache="lists"):
        """(lo, binsize, nbins, keep_off) of the bins: whole fractions of the box length at least half
        the neighbor cutoff wide (LAMMPS's default binsize), over the particles' extent, with room for
        the stencil (``keep_off`` bins, its reach) around the owned particles. A grid of more than
        about 8 bins per particle, or beyond limits.bin_grid, gets wider bins, and past that is cut
        to size: particles beyond it share its edge bins (correct, only slower)."""
        two_d = box.dimension == 2
        low_high = extent(p.x, p.nlocal, p.nall)
        most = min(limits.MAX_CELLS, 8 * p.nall + 4096)
        target = 0.5 * cutneigh
        while True:
            per_box = limits.bin_grid(box.length, target)
            binsize = box.length / per_box
            reach = np.ceil(cutneigh / binsize).astype(np.int64)
            # a cutoff far wider than the box (absurd radii): bins one cutoff wide, a stencil of one
            # bin each way (a stencil wider than any grid would index bins that do not exist)
            wide = 2 * reach + 1 > limits.MAX_BINS_PER_AXIS
            if wide.any():
                binsize = np.where(wide, cutneigh, binsize)
                reach = np.where(wide, 1, reach)
            with np.errstate(invalid="ignore", over="ignore"):
                first = np.floor((np.minimum(low_high[2], low_high[0] - reach * binsize) - box.lo) / binsize) - 1
                last = np.floor((np.maximum(low_high[3], low_high[1] + reach * binsize) - box.lo) / binsize) + 1
            first = np.where(np.isfinite(first), first, 0.0)
            last = np.where(np.isfinite(last), last, 0.0)
            span = np.clip(last - first + 1, 2 * reach + 1, float(limits.MAX_BINS_PER_AXIS))
            if two_d:
                first[2], span[2], binsize[2], reach[2] = 0.0, 1.0, max(box.length[2], 1.0), 0
            if float(np.prod(span)) <= most or (per_box == 1).all():
                break
            target *= 2.0
        while float(np.prod(span)) > most and span.max() > 2 * reach.max() + 1:
            widest = int(np.argmax(span - 2 * reach))
            span[widest] = max(span[widest] // 2, 2 * reach[widest] + 1)
        # the last grid, when it still covers the particles and is not much larger, keeps its
        # stencils (a new grid shape costs a new stencil)
        last_grid = self._last_grid.get(cache)
        if last_grid is not None and np.array_equal(last_grid[1], binsize) and \
                np.array_equal(last_grid[3], reach) and (last_grid[0] <= first).all() and \
                (last_grid[0] + last_grid[2] >= first + span).all() and \
                float(np.prod(last_grid[2])) <= 2.0 * float(np.prod(span)) + 64:
            first, span = last_grid[0], last_grid[2]
        else:
            pad = np.where(reach > 0, 2, 0)      # a little room, so that the next builds fit too
            first, span = first - pad, span + 2 * pad
            if float(np.prod(span)) > most:
                first, span = first + pad, span - 2 * pad
            self._last_grid[cache] = (first.copy(), binsize.copy(), span.copy(), reach.copy())
        lo = box.lo + first * binsize
        if two_d:
            lo[2] = box.lo[2]
        return lo, binsize, span.astype(np.int64), reach

    def _stencil(self, grid, cutneigh, half):
        """The bins within ``cutneigh`` of a bin (nearest points), as rows along x: (first, last)
        linear offsets of each row's bins, whose particles are contiguous in the binned order.
        ``half`` True: the upper half without the bin itself (owned partners in a half list); "above":
        the rows not below it in z (where a ghost above a particle can be, bins keeping the
        coordinates' order); False: all."""
        _, binsize, nbins, reach = grid
        key = (tuple(binsize), tuple(nbins), cutneigh, half)
        cached = self._stencils.get(key)
        if cached is not None:
            return cached
        sx, sy, sz = (int(r) for r in reach)
        rows = []
        for k in range(-sz, sz + 1):
            for j in range(-sy, sy + 1):
                if half and (k < 0 or (k == 0 and j < 0 and half is True)):
                    continue
                gap_yz = (max(abs(j) - 1, 0) * binsize[1]) ** 2 + (max(abs(k) - 1, 0) * binsize[2]) ** 2
                inside = [i for i in range(-sx, sx + 1)
                          if gap_yz + (max(abs(i) - 1, 0) * binsize[0]) ** 2 < cutneigh * cutneigh
                          and not (half is True and k == 0 and j == 0 and i <= 0)]
                if inside:
                    base = (k * int(nbins[1]) + j) * int(nbins[0])
                    rows.append((base + inside[0], base + inside[-1]))
        if len(self._stencils) > 16:        # a box or a grid that changes every build
            self._stencils.clear()
        self._stencils[key] = np.array(rows, dtype=np.int64).reshape(-1, 2)
        return self._stencils[key]

    def exclusions(self, ntypes, groups):
        """The tables build_list reads, from neigh_modify exclude (called at a run's start)."""
        table = np.zeros((ntypes + 1, ntypes + 1), dtype=np.bool_)
        for (ilo, ihi), (jlo, jhi) in self.excluded_type_pairs:
            table[ilo:ihi + 1, jlo:jhi + 1] = True
            table[jlo:jhi + 1, ilo:ihi + 1] = True
        self._excluded_types = table
        self._excluded_groups = np.array([[groups.bit(a), groups.bit(b)] for a, b in self.excluded_group_pairs],
                                         dtype=np.uint32).reshape(-1, 2)
        self._excluded_molecules = np.array([[groups.bit(g), MOLECULE_EXCLUSIONS.index(kind)]
                                             for g, kind in self.excluded_molecules], dtype=np.uint32).reshape(-1, 2)

    def special_exclusions(self, particles, topology):
        """The special levels (1-2, 1-3, 1-4) whose pairs leave every list: those special_bonds weighs
        0 (called at a run's start; none without bonds)."""
        levels = topology.left_out_levels() if topology.has_bonds(particles) else np.zeros(3, dtype=np.bool_)
        self._special_levels = levels.astype(np.bool_)

    def _special(self, p):
        levels = getattr(self, "_special_levels", None)
        if levels is None or not levels.any() or not p.has("special"):
            return NO_SPECIAL, NO_NSPECIAL, np.zeros(3, dtype=np.bool_)
        return p.special, p.nspecial, levels

    def _fill(self, nlist, p, grid, skin, bins=None, moved=0.0):
        """Build ``nlist`` from particles binned on ``grid``: the lists' bins, or ``bins`` (cell,
        start, ghost_start, order, slot) binned on that grid. ``moved``: the largest move since the
        ghosts were made (a list built between rebuilds)."""
        if getattr(self, "_excluded_types", None) is None or self._excluded_types.shape[0] != nlist.cutoff.shape[0]:
            self._excluded_types = np.zeros(nlist.cutoff.shape, dtype=np.bool_)
            self._excluded_groups = np.zeros((0, 2), dtype=np.uint32)
            self._excluded_molecules = np.zeros((0, 2), dtype=np.uint32)
        molecule = p.molecule if p.has("molecule") else NO_MOLECULES
        cutneighsq = (nlist.cutoff + skin) ** 2
        if cutneighsq.shape[0] != self.requests[0].cutoff.shape[0]:
            raise ScriptError("neighbor requests disagree on the number of types")
        reach = float(np.sqrt(cutneighsq.max()))
        owned_rows = self._stencil(grid, reach, nlist.half_list)
        ghost_rows = self._stencil(grid, reach, "above" if nlist.half_list else False)
        # LAMMPS's neigh_modify one, taken as a mean: a list that would outgrow it is a mistake
        # (overlapping particles, a typo in a lattice), not something to allocate gigabytes for
        most = self.one * max(p.nlocal, 1)
        binned = bins if bins is not None else (self._cell, self._start, self._ghost_start, self._order, self._slot)
        if len(nlist.offset_buffer) < p.nlocal + 1:
            nlist.offset_buffer = np.empty(int(1.25 * p.nlocal) + 16, dtype=np.int64)
        offsets = nlist.offset_buffer[:p.nlocal + 1]
        if len(nlist.buffer) == 0:
            nlist.buffer = np.empty(min(self._first_capacity(nlist, p, grid, cutneighsq), most), dtype=NEIGHBOR_INDEX)
        while True:
            total = build_list(p.x, p.type, p.mask, np.uint32(nlist.groupbit), p.nlocal, cutneighsq, *binned,
                               owned_rows, ghost_rows,
                               nlist.half_list, grid[2][2] == 1, offsets, nlist.buffer, self._excluded_types,
                               self._excluded_groups, molecule, self._excluded_molecules, float(moved),
                               p.tag, *self._special(p))
            if total >= 0:
                break
            if len(nlist.buffer) >= most:
                raise ScriptError(f"neighbor list overflow: more than {self.one} neighbors per particle "
                                  f"on average within {float(np.sqrt(cutneighsq.max())):g} of "
                                  f"{p.nlocal} particles (overlapping particles?); "
                                  "raise neigh_modify one if that is meant")
            nlist.buffer = np.empty(min(2 * len(nlist.buffer), most), dtype=NEIGHBOR_INDEX)
        # a list that shrank a lot (particles deleted, a melt turned gas) gives its memory back
        if len(nlist.buffer) > 4 * total + 4096:
            nlist.buffer = nlist.buffer[:int(1.25 * total) + 1024].copy()
        nlist.offsets, nlist.neighbors = offsets, nlist.buffer[:total]

    def _first_capacity(self, nlist, p, grid, cutneighsq):
        """Room for a list's first build: the pairs a uniform fluid of this density would have, with a
        margin (a denser clump grows the buffer by doubling)."""
        _, binsize, nbins, _ = grid
        # the owned particles' density (a grid's margins would dilute it and a first build overflow)
        low_high = extent(p.x, p.nlocal, p.nlocal)
        sides = np.maximum(low_high[1] - low_high[0], binsize)
        if nbins[2] == 1:
            sides[2] = 1.0
        density = p.nlocal / max(float(np.prod(sides)), 1e-300)
        reach = float(np.sqrt(cutneighsq.max()))
        ball = np.pi * reach * reach if nbins[2] == 1 else 4.0 / 3.0 * np.pi * reach ** 3
        per_particle = density * ball * (0.5 if nlist.half_list else 1.0)
        return int(min(1.3 * per_particle, 1e9) * p.nlocal) + 1024
