"""Bookkeeping of the contact history slots of the granular pair styles, between steps.

A pair style marks, in ``touched`` (one flag per slot of ``pdps_core.api.ContactHistory``), every
contact its force computation saw; at the end of the step the contacts it did not see (the spheres
came apart) are forgotten. Each particle's open slots are kept first in its row, so that sweep reads
a row only up to its first free slot: most particles touch nothing, and a step costs one read per
particle rather than one per slot. The core's ``open_slot`` fills the first free slot, which keeps
the rows packed; ``pack_slots`` packs rows written by anything else (a restart file, an older run)
at the start of a run.
"""

from numba import njit


@njit(cache=True)
def free_stale(partner, history, touched, nlocal, nall):
    """Forget the contacts of owned particles no force computation touched this step (the last open
    slot moves into a freed one) and clear every flag, so that all are False between steps."""
    capacity = partner.shape[1]
    width = history.shape[1] // capacity
    for i in range(nlocal):
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
    for i in range(nlocal, nall):
        for s in range(capacity):
            touched[i, s] = False


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
