"""Bookkeeping of the contact history slots of the granular pair styles, between steps.

A pair style marks, in ``touched`` (one flag per slot of ``pdps_core.api.ContactHistory``), every
contact its force computation saw; at the end of the step the contacts it did not see (the spheres
came apart) are forgotten. Each particle's open slots are kept first in its row, so that sweep reads
a row only up to its first free slot: most particles touch nothing, and a step costs one read per
particle rather than one per slot. Between two list builds on one rank, a pair style that knows the
rows it touched sweeps only those and the rows that kept contacts (``free_stale_of``). The core's
``open_slot`` fills the first free slot, which keeps the rows packed; ``pack_slots`` packs rows
written by anything else (a restart file, an older run) at the start of a run.
"""

from numba import njit


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
def free_stale_of(partner, history, touched, held, nheld, fresh, nfresh, mark):
    """free_stale for the rows that can hold a contact, on one rank between two list builds: the
    ``nheld`` rows ``held`` that kept contacts after the last step and the ``nfresh`` rows
    ``fresh`` this step touched (repeats allowed). Leaves in ``held`` the rows keeping contacts and
    returns their number; ``mark`` (one flag per row, all False) is left all False."""
    n = 0
    for c in range(nheld):
        mark[held[c]] = True
        n += 1
    for c in range(nfresh):
        r = fresh[c]
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
