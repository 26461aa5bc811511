"""Bookkeeping of the contact history slots of the granular pair styles, between steps.

A pair style marks, in ``touched`` (one flag per slot of ``pdps_core.api.ContactHistory``), every
contact its force computation saw; at the end of the step the contacts it did not see (the spheres
came apart) are forgotten. Each particle's open slots are kept first in its row, so that sweep reads
a row only up to its first free slot: most particles touch nothing, and a step costs one read per
particle rather than one per slot. Between two list builds, a pair style that knows the rows it
touched sweeps only those and the rows that kept contacts (``HeldRows``, ``free_stale_of``:
pair gran's styles from their touching list entries, pair dem's from their contact log). The core's
``open_slot`` fills the first free slot, which keeps the rows packed; ``pack_slots`` packs rows
written by anything else (a restart file, an older run) at the start of a run. On several ranks a
contact's mirror written into the row of a ghost owned elsewhere goes back to its owner after the
force computation (``Mirrors``).
"""

import numpy as np
from numba import njit

from pdps_core.api import find_slot, open_slot

# the per-particle arrays of a granular pair style's contact springs (ContactHistory's name), one
# name for pair gran's and pair dem's: the wall fixes keep their own, as the sweep of stale slots
# frees only the pair style's
PAIR_SHEAR = "pair_shear"


@njit(cache=True)
def forget_untouched(partner, history, touched, i):
    """Forget the contacts of row i no force computation touched this step (the last open slot
    moves into a freed one) and clear its flags; returns how many contacts it keeps."""
    capacity = partner.shape[1]
    width = history.shape[1] // capacity
    count = 0
    while count < capacity and partner[i, count] >= 0:
        count += 1
    s = 0
    while s < count:
        if touched[i, s]:
            touched[i, s] = False
            s += 1
            continue
        count -= 1
        partner[i, s] = partner[i, count]
        touched[i, s] = touched[i, count]
        for h in range(width):
            history[i, s * width + h] = history[i, count * width + h]
        partner[i, count] = -1
        touched[i, count] = False
    return count


# _nrt=False, here and below: forget_untouched stores under branches, where numba would keep an
# atomic reference count of its arrays at every call (numba issue #2350); nothing here allocates
@njit(cache=True, _nrt=False)
def free_stale(partner, history, touched, nlocal, nall):
    """Forget the contacts of owned particles no force computation touched this step and clear
    every flag, so that all are False between steps."""
    for i in range(nlocal):
        forget_untouched(partner, history, touched, i)
    for i in range(nlocal, nall):
        for s in range(partner.shape[1]):
            touched[i, s] = False


@njit(cache=True, _nrt=False)
def free_stale_of(partner, history, touched, held, nheld, fresh, nfresh, merged, mark):
    """free_stale for the rows that can hold a contact, between two list builds: the ``nheld`` rows
    ``held`` that kept contacts after the last step, the ``nfresh`` rows ``fresh`` this step's
    force computation touched and the rows ``merged`` that mirrors from other ranks touched
    (repeats allowed). Leaves in ``held`` the rows keeping contacts and returns their number;
    ``mark`` (one flag per row, all False) is left all False. A ghost row among them loses its
    untouched slots too, where free_stale only clears its flags: a ghost's slots carry nothing
    from one step to the next (forces read the owned particle's), only room for mirrors."""
    n = 0
    for c in range(nheld):
        mark[held[c]] = True
        n += 1
    for c in range(nfresh + len(merged)):
        r = fresh[c] if c < nfresh else merged[c - nfresh]
        if not mark[r]:
            mark[r] = True
            held[n] = r
            n += 1
    kept = 0
    for c in range(n):
        r = held[c]
        mark[r] = False
        if forget_untouched(partner, history, touched, r) > 0:
            held[kept] = r
            kept += 1
    return kept


@njit(cache=True)
def pack_slots(partner, history, nall):
    """Move each particle's open slots first, in their order (the layout free_stale keeps)."""
    capacity = partner.shape[1]
    width = history.shape[1] // capacity
    for i in range(nall):
        count = 0
        for s in range(capacity):
            if partner[i, s] < 0:
                continue
            if s != count:
                partner[i, count] = partner[i, s]
                partner[i, s] = -1
                for h in range(width):
                    history[i, count * width + h] = history[i, s * width + h]
            count += 1


@njit(cache=True)
def rows_holding(partner, nlocal, held):
    """The owned rows with an open contact slot (slots are packed: the first one tells) into
    ``held``; returns how many."""
    n = 0
    for i in range(nlocal):
        if partner[i, 0] >= 0:
            held[n] = i
            n += 1
    return n


@njit(cache=True)
def contact_rows(pairs, npairs, owner, fresh):
    """The rows whose contact slots the contacts (i, j) of ``pairs`` used: i, and j's owner (j where
    it has none), two per contact into ``fresh``."""
    for h in range(npairs):
        j = pairs[h, 1]
        fresh[2 * h] = pairs[h, 0]
        fresh[2 * h + 1] = owner[j] if owner[j] >= 0 else j


class HeldRows:
    """The end-of-step sweep of a pair style's contact slots: between two builds of the list, only
    the rows that kept contacts after the last step and the rows touched now can hold a contact, so
    only those are swept (``sweep_of``, when ``ready``); otherwise every row is (``sweep_all``), and
    the rows keeping contacts are noted for the next step. The rows touched now are those of this
    step's contacts (a ghost owned elsewhere among them) and, on several ranks, the owned rows its
    mirrors came back to (``Mirrors.merged``). ::

        if held.ready(nlist):
            held.sweep_of(partner, values, touched, fresh, nfresh, mirrors.merged)
        else:
            held.sweep_all(sim, nlist, partner, values, touched)
    """

    def __init__(self):
        self.rows = np.empty(0, dtype=np.int64)
        self.count = 0
        self._mark = np.zeros(0, dtype=np.bool_)
        self._of = None         # (list, its version) the rows are valid for

    def invalidate(self):
        """The next sweep reads every row (the slots changed outside a step: setup, an error)."""
        self._of = None

    def ready(self, nlist):
        return self._of == (nlist, nlist.version)

    def sweep_of(self, partner, values, touched, fresh, nfresh, merged):
        """Forget the contacts this step did not see; ``fresh[:nfresh]`` are the rows its contacts
        touched, ``merged`` those its mirrors from other ranks did."""
        self.count = free_stale_of(partner, values, touched, self.rows, self.count, fresh, nfresh, merged,
                                   self._mark)

    def sweep_all(self, sim, nlist, partner, values, touched):
        p = sim.particles
        free_stale(partner, values, touched, p.nlocal, p.nall)
        # rows swept later: owned ones, and ghosts owned elsewhere that a contact touches
        if len(self.rows) < p.nall:
            self.rows = np.empty(p.nall + p.nall // 4, dtype=np.int64)
            self._mark = np.zeros(len(self.rows), dtype=np.bool_)
        self.count = rows_holding(partner, p.nlocal, self.rows)
        self._of = (nlist, nlist.version)


@njit(cache=True)
def remote_touched_ghosts(touched, owner, nlocal, nall, ghosts):
    """The ghosts (indices among the ghosts, ascending) owned on another rank with a slot touched
    this step, into ``ghosts``; returns how many."""
    m = 0
    for i in range(nlocal, nall):
        if owner[i] >= 0:
            continue
        for s in range(touched.shape[1]):
            if touched[i, s]:
                ghosts[m] = i - nlocal
                m += 1
                break
    return m


@njit(cache=True)
def pack_mirrors(touched, partner, history, nlocal, ghosts, count, rows):
    """Row k of ``rows``: (touched flags, partner tags, values) of ghost ``ghosts[k]``."""
    capacity = partner.shape[1]
    for k in range(count):
        i = nlocal + ghosts[k]
        for s in range(capacity):
            rows[k, s] = 1.0 if touched[i, s] else 0.0
            rows[k, capacity + s] = partner[i, s]
        for h in range(history.shape[1]):
            rows[k, 2 * capacity + h] = history[i, h]


@njit(cache=True)
def merge_mirrors(partner, history, touched, index, rows, capacity):
    """Springs written into ghost rows on other ranks, now back on their owners ``index``: each row
    is (touched flags, partner tags, values) of one ghost. Returns a row with no free slot, or -1."""
    width = history.shape[1] // capacity
    for r in range(len(index)):
        i = index[r]
        for k in range(capacity):
            if rows[r, k] > 0.5:
                key = np.int64(rows[r, capacity + k])
                slot = open_slot(partner, history, i, key, width)
                if slot < 0:
                    return i
                touched[i, slot] = True
                for d in range(width):
                    history[i, width * slot + d] = rows[r, 2 * capacity + width * k + d]
    return -1


class Mirrors:
    """A contact's values are kept on both particles (i's in its row, the mirror in j's owner's row).
    When j is a ghost of a particle owned on another rank, its mirror was written into the ghost's
    row: ``collect`` sends the rows of the ghosts touched this step back to their owners, only those
    (a granular step touches few), in buffers kept between steps."""

    def __init__(self):
        self._ghosts = np.empty(0, dtype=np.int64)
        self._rows = np.empty((0, 0))
        self.merged = np.empty(0, dtype=np.int64)      # the owned rows the last collect wrote into

    def collect(self, sim, history, owner, touched):
        """Returns -1, or the tag of a particle left with no free slot."""
        if sim.comm.nprocs == 1:
            return -1
        p = sim.particles
        width = 2 * history.capacity + history.values.shape[1]
        if len(self._ghosts) < p.nghost or self._rows.shape[1] != width:
            size = p.nghost + p.nghost // 4 + 16
            self._ghosts, self._rows = np.empty(size, dtype=np.int64), np.empty((size, width))
        count = remote_touched_ghosts(touched, owner, p.nlocal, p.nall, self._ghosts)
        pack_mirrors(touched, history.partner, history.values, p.nlocal, self._ghosts, count, self._rows)
        index, back = sim.comm.reverse_rows(self._rows[:count], self._ghosts[:count])
        self.merged = index
        bad = merge_mirrors(history.partner, history.values, touched, index, back, history.capacity)
        return -1 if bad < 0 else int(p.tag[bad])


@njit(cache=True)
def load_history(partner, history, touched, owner, tag, i, j, update, hist):
    """The contact's values as i sees them (its spring, and whatever else the law keeps) into
    ``hist``; returns (slot on i, slot on j's owner). When ``update`` the slots are made if new and
    marked as seen this step (a negative slot: no free slot); in setup only existing slots are read
    (-1 when there is none)."""
    width = len(hist)
    jo = owner[j] if owner[j] >= 0 else j
    if not update:
        slot = find_slot(partner, i, tag[j])
        for d in range(width):
            hist[d] = history[i, width * slot + d] if slot >= 0 else 0.0
        return slot, find_slot(partner, jo, tag[i]) if slot >= 0 else -1
    slot_i = open_slot(partner, history, i, tag[j], width)
    slot_j = open_slot(partner, history, jo, tag[i], width)
    if slot_i < 0 or slot_j < 0:
        return slot_i, slot_j
    touched[i, slot_i] = True
    touched[jo, slot_j] = True
    for d in range(width):
        hist[d] = history[i, width * slot_i + d]
    return slot_i, slot_j


@njit(cache=True, inline="always")
def wall_slots(i, start, end, distance, normal, key, reach, partner, values, normal_at, update,
               used, slots, transfer_cos):
    """The history slot of each of particle i's wall contacts ``start..end`` into
    ``slots[c - start]`` (-1: none, for contacts at distance >= reach). A contact keeps the slot of
    its wall element (``key``); with ``update`` a new one continues a contact that just ended with
    nearly the same normal (cosine above ``transfer_cos``; the normal is stored at ``normal_at`` in
    each slot's values), the slots of contacts
    that ended are freed, and the remaining new contacts open zeroed slots. Returns False when
    particle i has no free slot."""
    capacity = partner.shape[1]
    width = values.shape[1] // capacity
    for s in range(capacity):
        used[s] = False
    # contacts already known keep their slot
    for c in range(start, end):
        slots[c - start] = -1
        if distance[c] < reach:
            s = -1
            for k in range(capacity):
                if partner[i, k] == key[c]:
                    s = k
            slots[c - start] = s
            if s >= 0:
                used[s] = True
    if not update:
        return True
    # a new contact continues one that just ended with nearly the same normal
    for c in range(start, end):
        if distance[c] < reach and slots[c - start] < 0:
            best, best_cos = -1, transfer_cos
            for k in range(capacity):
                if partner[i, k] >= 0 and not used[k]:
                    at = k * width + normal_at
                    cos = (normal[c, 0] * values[i, at] + normal[c, 1] * values[i, at + 1]
                           + normal[c, 2] * values[i, at + 2])
                    if cos > best_cos:
                        best, best_cos = k, cos
            if best >= 0:
                partner[i, best] = key[c]
                used[best] = True
                slots[c - start] = best
    # contacts that ended free their slot, then the remaining new ones open one
    for k in range(capacity):
        if partner[i, k] >= 0 and not used[k]:
            partner[i, k] = -1
    for c in range(start, end):
        if distance[c] < reach and slots[c - start] < 0:
            s = -1
            for k in range(capacity):
                if partner[i, k] < 0:
                    s = k
                    break
            if s < 0:
                return False
            partner[i, s] = key[c]
            for h in range(width):
                values[i, s * width + h] = 0.0
            used[s] = True
            slots[c - start] = s
    return True
