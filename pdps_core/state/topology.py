"""Bonds between particles and the special neighbors they define (LAMMPS's bond topology).

A particle style with molecule ids (bond, angle, molecular, full) may carry bonds: read from a data
file's Bonds section, made by fix bond/create, deleted by delete_bonds or fix bond/break. As in
LAMMPS with ``newton_bond on`` (its default), each bond is stored once, on its first particle:

    num_bond (n,) int32          bonds stored on the particle
    bond_type (n, B) int32       their types: > 0 computed, < 0 turned off (delete_bonds), 0 broken
    bond_atom (n, B) int64       the id of the other particle of each

B is the data file's largest count on one particle plus its ``extra bond per atom``. The arrays
exist only in a scene with bonds (or room for them), travel with their particle between ranks and
are not carried by ghosts.

Special neighbors. Particles one bond apart are 1-2 neighbors, two bonds apart (through a third)
1-3, three bonds apart 1-4, as LAMMPS's Special builds them from the bonds alone (special_bonds
``angle no`` ``dihedral no``, its default): every particle keeps the ids of its 1-2, 1-3 and 1-4
neighbors, each once and at the nearest level,

    nspecial (n, 3) int32        n12, n12 + n13, n12 + n13 + n14
    special (n, S) int64         the 1-2 ids, then the 1-3, then the 1-4

built when bonds are read, when special_bonds is given, and when delete_bonds (``special``), fix
bond/break or fix bond/create change them. A bond turned off by delete_bonds stays a special bond,
as in LAMMPS, until ``delete_bonds ... special``. special_bonds sets the weight of the pair
interaction between special neighbors: pdps takes 0.0 (the pair is left out of every neighbor list,
LAMMPS's default lj 0.0 0.0 0.0) or 1.0 (a pair like any other) and refuses weights in between.

The bond list. At every neighbor rebuild each computed bond (type > 0) stored on an owned particle
is listed with the row of its partner nearest to it, owned or ghost (LAMMPS's closest_image), so a
bond across a periodic boundary or a rank boundary is computed once; a partner that is nowhere on
the rank stops the run (LAMMPS's "Bond atoms missing").
"""

import numpy as np
from numba import njit

from ..errors import ScriptError, SimulationError

BOND_ARRAYS = ("num_bond", "bond_type", "bond_atom")
SPECIAL_ARRAYS = ("nspecial", "special")
LEVELS = ("1-2", "1-3", "1-4")


class Topology:
    """The bonds' settings and the bond list of a simulation (System.topology)."""

    def __init__(self):
        self.nbondtypes = 0
        self.extra_bonds = 0            # room reserved per particle for bonds made later
        # special_bonds: weights of the lj and coul interactions of 1-2, 1-3, 1-4 neighbors
        self.special_lj = [0.0, 0.0, 0.0]
        self.special_coul = [0.0, 0.0, 0.0]
        self.bond_list = np.zeros((0, 3), dtype=np.int64)   # rows (i, j, type) of this rank's bonds
        self.nbondlist = 0
        self._sorted = np.zeros(0, dtype=np.int64)           # the bond list build's work arrays
        self._order = np.zeros(0, dtype=np.int64)

    # ---- arrays --------------------------------------------------------------------------------
    @staticmethod
    def has_bonds(particles):
        return particles.has("num_bond")

    def make_arrays(self, particles, per_atom):
        """The bond and special arrays, ``per_atom`` bonds wide (kept wider when they are)."""
        # two at least: a per-atom array one wide is a plain vector, and the bond loops index slots
        width = max(per_atom, 2)
        if particles.has("bond_type"):
            width = max(width, particles.bond_type.shape[1])
            if width == particles.bond_type.shape[1]:
                return
            raise ScriptError("bonds per particle cannot grow once bonds exist: give extra bond per atom "
                              "in the data file (or extra/bond/per/atom to create_box)")
        particles.request("num_bond", 1, np.int32, 0, ghost=False)
        particles.request("bond_type", width, np.int32, 0, ghost=False)
        particles.request("bond_atom", width, np.int64, 0, ghost=False)
        particles.request("nspecial", 3, np.int32, 0, ghost=False)
        particles.request("special", max(4 * width, 4), np.int64, 0, ghost=False)

    def check_types(self, what="bond type"):
        if self.nbondtypes < 1:
            raise ScriptError(f"{what}: the box has no bond types (give bond types in the data file, or "
                              "bond/types to create_box)")

    # ---- special neighbors ---------------------------------------------------------------------
    def left_out_levels(self):
        """(3,) bool: the special levels whose pairs leave the neighbor lists (both weights 0)."""
        return np.array([self.special_lj[k] == 0.0 and self.special_coul[k] == 0.0 for k in range(3)])

    def build_special(self, sim):
        """The 1-2, 1-3 and 1-4 neighbors of every owned particle, from every bond stored on any
        rank (turned-off ones too, broken ones not), as LAMMPS's Special::build."""
        p = sim.particles
        if not self.has_bonds(p):
            return
        n = p.nlocal
        counts = p.num_bond[:n]
        owners = np.repeat(p.tag[:n], counts)
        width = p.bond_type.shape[1]
        slots = np.arange(width)[None, :] < counts[:, None]
        partners = p.bond_atom[:n][slots]
        kinds = p.bond_type[:n][slots]
        pairs = np.stack([owners, partners], axis=1)[kinds != 0]
        every = sim.comm.allgather_rows(pairs.astype(np.float64)).astype(np.int64).reshape(-1, 2)
        bonded = {}
        for a, b in every.tolist():
            bonded.setdefault(a, set()).add(b)
            bonded.setdefault(b, set()).add(a)
        lists = []
        for tag in p.tag[:n].tolist():
            one_two = sorted(bonded.get(tag, ()))
            seen = {tag, *one_two}
            one_three = sorted({c for b in one_two for c in bonded.get(b, ())} - seen)
            seen.update(one_three)
            one_four = sorted({d for c in one_three for d in bonded.get(c, ())} - seen)
            lists.append((one_two, one_three, one_four))
        # room for the longest list on any rank (bonds made by fix bond/create lengthen them)
        longest = int(sim.comm.max(max((sum(map(len, levels)) for levels in lists), default=0)))
        if longest > p.special.shape[1]:
            p.widen("special", longest + 4)
        for row, (one_two, one_three, one_four) in enumerate(lists):
            listed = one_two + one_three + one_four
            p.special[row, :len(listed)] = listed
            p.special[row, len(listed):] = 0
            p.nspecial[row] = (len(one_two), len(one_two) + len(one_three), len(listed))

    # ---- bonds made and broken during a run (fix bond/create, fix bond/break) ------------------
    def create_bonds(self, sim, pairs, bond_type):
        """Bonds of ``bond_type`` between the id pairs ``pairs`` (k, 2), the same rows on every rank,
        each stored on the particle of the smaller id (LAMMPS's newton_bond), the special lists made
        again. Room for more bonds per particle is made as needed, on every rank alike."""
        p = sim.particles
        pairs = np.sort(np.asarray(pairs, dtype=np.int64).reshape(-1, 2), axis=1)
        rows = p.owned_rows(pairs[:, 0])
        mine = rows >= 0
        counts = np.bincount(rows[mine], minlength=p.nlocal) if mine.any() else np.zeros(p.nlocal, np.int64)
        need = int(sim.comm.max(int((p.num_bond[:p.nlocal] + counts[:p.nlocal]).max(initial=0))))
        if need > p.bond_type.shape[1]:
            p.widen("bond_type", need)
            p.widen("bond_atom", need)
        for row, partner in zip(rows[mine].tolist(), pairs[mine, 1].tolist()):
            slot = p.num_bond[row]
            p.bond_type[row, slot] = bond_type
            p.bond_atom[row, slot] = partner
            p.num_bond[row] = slot + 1
        self.build_special(sim)

    def break_bonds(self, sim, pairs):
        """Delete the bonds between the id pairs ``pairs`` (k, 2), the same rows on every rank, from
        whichever of their particles stores them, and make the special lists again."""
        p = sim.particles
        pairs = np.asarray(pairs, dtype=np.int64).reshape(-1, 2)
        both = np.concatenate([pairs, pairs[:, ::-1]])
        for row, partner in zip(p.owned_rows(both[:, 0]).tolist(), both[:, 1].tolist()):
            if row < 0:
                continue
            count = int(p.num_bond[row])
            slots = [k for k in range(count) if p.bond_atom[row, k] == partner]
            if not slots:
                continue
            keep = [k for k in range(count) if k != slots[0]]
            p.bond_type[row, :len(keep)] = p.bond_type[row, keep]
            p.bond_atom[row, :len(keep)] = p.bond_atom[row, keep]
            p.bond_type[row, len(keep):count] = 0
            p.bond_atom[row, len(keep):count] = 0
            p.num_bond[row] = len(keep)
        self.build_special(sim)

    # ---- the bond list -------------------------------------------------------------------------
    def build_bond_list(self, sim):
        """This rank's computed bonds as rows (i, j, type) for the bond loop (after each rebuild)."""
        p = sim.particles
        nall = p.nall
        if len(self._sorted) < nall:
            size = int(1.25 * nall) + 16
            self._sorted, self._order = np.empty(size, dtype=np.int64), np.empty(size, dtype=np.int64)
        order = np.argsort(p.tag[:nall], kind="stable")
        self._order[:nall] = order
        self._sorted[:nall] = p.tag[:nall][order]
        total = int(p.num_bond[:p.nlocal].sum())
        if len(self.bond_list) < total:
            self.bond_list = np.empty((int(1.25 * total) + 16, 3), dtype=np.int64)
        found = _list_bonds(p.x, p.nlocal, p.num_bond, p.bond_type, p.bond_atom, self._sorted[:nall],
                            self._order[:nall], self.bond_list)
        message = None
        if found < 0:
            i, b = divmod(-found - 1, p.bond_type.shape[1])
            message = (f"bond atoms {int(p.tag[i])} {int(p.bond_atom[i, b])} missing at step {sim.step}: the "
                       "partner is out of this rank's reach (a bond longer than the ghost cutoff: a longer pair "
                       "cutoff or comm_modify cutoff; or a particle lost or deleted)")
        # every rank learns of one rank's missing partner (collective, once per rebuild)
        sim.comm.agree(message)
        self.nbondlist = found

    def bonds(self):
        return self.bond_list[:self.nbondlist]

    def stored_bonds(self, sim):
        """Every bond stored on an owned particle, turned off ones too (type < 0), broken ones not,
        as rows (i, j, type) with j the partner's copy nearest to i (compute bond/local)."""
        p = sim.particles
        nall = p.nall
        order = np.argsort(p.tag[:nall], kind="stable")
        kinds = np.where(p.bond_type == 0, 0, 1).astype(np.int32)
        rows = np.empty((int(p.num_bond[:p.nlocal].sum()), 3), dtype=np.int64)
        found = _list_bonds(p.x, p.nlocal, p.num_bond, kinds, p.bond_atom, p.tag[:nall][order], order, rows)
        if found < 0:
            i, b = divmod(-found - 1, p.bond_type.shape[1])
            raise SimulationError(f"bond atoms {int(p.tag[i])} {int(p.bond_atom[i, b])} missing at step {sim.step}")
        rows = rows[:found]
        slots = np.arange(p.bond_type.shape[1])[None, :] < p.num_bond[:p.nlocal, None]
        stored = p.bond_type[:p.nlocal][slots]
        rows[:, 2] = stored[stored != 0]
        return rows


@njit(cache=True)
def _list_bonds(x, nlocal, num_bond, bond_type, bond_atom, sorted_tags, order, out):
    """Rows (i, j, type) of the bonds of type > 0 stored on owned particles, j the copy of the
    partner nearest to i; the count, or -(i * width + slot) - 1 for a partner not found."""
    width = bond_type.shape[1]
    k = 0
    nall = len(sorted_tags)
    for i in range(nlocal):
        for b in range(num_bond[i]):
            t = bond_type[i, b]
            if t <= 0:
                continue
            tag = bond_atom[i, b]
            lo, hi = 0, nall
            while lo < hi:
                mid = (lo + hi) // 2
                if sorted_tags[mid] < tag:
                    lo = mid + 1
                else:
                    hi = mid
            best, best_rsq = -1, np.inf
            while lo < nall and sorted_tags[lo] == tag:
                j = order[lo]
                dx = x[i, 0] - x[j, 0]
                dy = x[i, 1] - x[j, 1]
                dz = x[i, 2] - x[j, 2]
                rsq = dx * dx + dy * dy + dz * dz
                if rsq < best_rsq:
                    best, best_rsq = j, rsq
                lo += 1
            if best < 0:
                return -(i * width + b) - 1
            out[k, 0] = i
            out[k, 1] = best
            out[k, 2] = t
            k += 1
    return k
