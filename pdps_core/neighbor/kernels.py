"""numba kernels for neighbor lists: cell binning and half/full Verlet lists in CSR form, built much as
LAMMPS builds them (npair_half_bin_newton, npair_full_bin).

Bins are whole fractions of the box, about half the neighbor cutoff wide, over the region the
particles occupy; owned particles and ghosts are binned apart. A list is built from each owned
particle's bin and a *stencil*, the bins whose nearest point lies within the neighbor cutoff, taken a
row along x at a time (one contiguous run of binned particles per row instead of one per bin).

A half list holds each pair once. Two owned particles are paired from the upper half of the stencil
and, in the particle's own bin, from the particles after it. An owned particle and a ghost are
paired, from the whole stencil, when the ghost lies "above" (larger z, then y, then x): LAMMPS's
newton-on rule, which keeps exactly one of the two periodic images of a pair (and one of the two
ranks' copies under MPI) whatever bins rounding puts a particle on a bin boundary in.
"""

import math

import numpy as np
from numba import njit


@njit(cache=True)
def cell_order(x, nall, lo, binsize, nbins):
    """The particles ordered by cell (z slowest), each cell's in their own order: a counting sort
    with one 32-bit count per cell. The sort's cells are small (half the cutoff) and, in a box
    with walls, mostly empty: 423,000 for 20,000 beads, whose three 64-bit arrays (cells, starts,
    fill) were a 10 MB transient at each sort."""
    ncells = nbins[0] * nbins[1] * nbins[2]
    cell = np.empty(nall, dtype=np.int64)
    fill = np.zeros(ncells + 1, dtype=np.int32)
    for i in range(nall):
        index = 0
        for d in range(2, -1, -1):
            k = int((x[i, d] - lo[d]) / binsize[d])
            if k < 0:
                k = 0
            elif k >= nbins[d]:
                k = nbins[d] - 1
            index = index * nbins[d] + k
        cell[i] = index
        fill[index + 1] += 1
    for c in range(ncells):
        fill[c + 1] += fill[c]
    order = np.empty(nall, dtype=np.int64)
    for i in range(nall):
        order[fill[cell[i]]] = i
        fill[cell[i]] += 1
    return order


@njit(cache=True)
def extent(x, nlocal, nall):
    """Lowest and highest coordinates of the owned particles and of all of them, (4, 3)."""
    out = np.empty((4, 3))
    for d in range(3):
        out[0, d] = out[2, d] = np.inf
        out[1, d] = out[3, d] = -np.inf
    for i in range(nall):
        row = 0 if i < nlocal else 2
        for d in range(3):
            v = x[i, d]
            if v < out[row, d]:
                out[row, d] = v
            if v > out[row + 1, d]:
                out[row + 1, d] = v
    for d in range(3):
        out[2, d] = min(out[2, d], out[0, d])
        out[3, d] = max(out[3, d], out[1, d])
    return out


@njit(cache=True)
def bin_into(x, nall, nlocal, lo, binsize, nbins, keep_off, cell, start, ghost_start, order, slot):
    """Counting sort of particles into bins, owned and ghosts apart: ``cell[i]`` the bin of particle
    i; ``order[start[c]:start[c+1]]`` the owned particles of bin c in index order, and
    ``order[ghost_start[c]:ghost_start[c+1]]`` its ghosts; ``slot[i]`` where owned particle i sits in
    ``order``. A particle beyond the grid goes to its edge bin, and owned ones stay ``keep_off[d]``
    bins inside, so that their stencils stay in the grid (clamping keeps the bins' order, so no pair
    is lost)."""
    ncells = nbins[0] * nbins[1] * nbins[2]
    for c in range(ncells + 1):
        start[c] = 0
        ghost_start[c] = 0
    for i in range(nall):
        index = 0
        for d in range(2, -1, -1):
            u = (x[i, d] - lo[d]) / binsize[d]
            low = keep_off[d] if i < nlocal else 0
            high = nbins[d] - 1 - low
            if u < low:
                k = low
            elif u >= high:
                k = high
            else:
                k = int(u)
            index = index * nbins[d] + k
        cell[i] = index
        if i < nlocal:
            start[index + 1] += 1
        else:
            ghost_start[index + 1] += 1
    ghost_start[0] = nlocal
    for c in range(ncells):
        start[c + 1] += start[c]
        ghost_start[c + 1] += ghost_start[c]
    for i in range(nall):
        c = cell[i]
        if i < nlocal:
            p = start[c]
            start[c] = p + 1
            slot[i] = p
        else:
            p = ghost_start[c]
            ghost_start[c] = p + 1
        order[p] = i
    for c in range(ncells, 0, -1):
        start[c] = start[c - 1]
        ghost_start[c] = ghost_start[c - 1]
    start[0] = 0
    ghost_start[0] = nlocal


@njit(cache=True)
def build_list(x, type_, mask, groupbit, nlocal, cutneighsq, cell, start, ghost_start, order, slot,
               owned_rows, ghost_rows, half, two_d, offsets, neighbors, excluded_types, excluded_groups,
               molecule, excluded_molecules, moved, tag, special, nspecial, special_levels):
    """Neighbors of each owned particle of the group (``mask & groupbit``) within
    cutneighsq[type_i, type_j], into ``offsets`` (nlocal + 1) and ``neighbors``; particles outside the
    group have none. ``owned_rows`` and ``ghost_rows``: the stencil's rows of bins along x, (first,
    last) linear bin offsets, where owned partners and ghost partners are looked for (for a half
    list the upper half without the own bin, and the rows not below in z); ``two_d``: z is not
    searched. Pairs of excluded types (``excluded_types[ti, tj]``), of excluded groups (rows of two
    mask bits, either order) or, for rows (group bit, 0 inter, 1 intra or 2 body) of
    ``excluded_molecules``, pairs of the group in different molecules (inter), in the same one
    (intra) or in the same one of id > 0 (body) are left out (neigh_modify exclude; fix
    multisphere's bodies), and so are an owned particle's special neighbors (``special[i]``, ids,
    ``nspecial[i]`` the ends of its 1-2, 1-3 and 1-4 runs) of the levels ``special_levels`` marks
    (special_bonds weights 0). ``moved``: the largest move of any particle since
    the ghosts were made (0 right after). Returns the number of pairs, or -1 when ``neighbors`` is
    too small.

    The pair test is written once, inline: a helper function taking the arrays would cost numba
    reference counting on every candidate (20 times slower, measured)."""
    screen = excluded_groups.shape[0] > 0
    screen_molecules = excluded_molecules.shape[0] > 0
    screen_special = nspecial.shape[0] > 0
    capacity = len(neighbors)
    # ghosts made now lie outside the owned particles' bounding box (outside the box or this rank's
    # part of it), and those made earlier outside that box shrunk by twice the largest move since: a
    # particle at least the cutoff inside it has none to look at
    inner_lo = np.empty(3)
    inner_hi = np.empty(3)
    for d in range(3):
        inner_lo[d] = np.inf
        inner_hi[d] = -np.inf
    for i in range(nlocal):
        for d in range(3):
            inner_lo[d] = min(inner_lo[d], x[i, d])
            inner_hi[d] = max(inner_hi[d], x[i, d])
    reach = np.sqrt(cutneighsq.max()) + 2.0 * moved
    for d in range(3):
        if two_d and d == 2:
            inner_lo[d], inner_hi[d] = -np.inf, np.inf
        else:
            inner_lo[d] += reach
            inner_hi[d] -= reach
    run_begin = np.empty(1 + len(owned_rows) + len(ghost_rows), dtype=np.int64)
    run_end = np.empty_like(run_begin)
    k = 0
    for i in range(nlocal):
        offsets[i] = k
        if not mask[i] & groupbit:
            continue
        ci = cell[i]
        xi, yi, zi = x[i, 0], x[i, 1], x[i, 2]
        ti = type_[i]
        # runs of candidates: owned ones (the rest of i's own bin first, for a half list), then ghosts
        nruns = 0
        if half:
            run_begin[0] = slot[i] + 1
            run_end[0] = start[ci + 1]
            nruns = 1
        for r in range(len(owned_rows)):
            run_begin[nruns] = start[ci + owned_rows[r, 0]]
            run_end[nruns] = start[ci + owned_rows[r, 1] + 1]
            nruns += 1
        first_ghost_run = nruns
        if not (inner_lo[0] <= xi <= inner_hi[0] and inner_lo[1] <= yi <= inner_hi[1]
                and inner_lo[2] <= zi <= inner_hi[2]):
            for r in range(len(ghost_rows)):
                run_begin[nruns] = ghost_start[ci + ghost_rows[r, 0]]
                run_end[nruns] = ghost_start[ci + ghost_rows[r, 1] + 1]
                nruns += 1
        for s in range(nruns):
            ghost = s >= first_ghost_run
            begin = run_begin[s]
            end = run_end[s]
            for p in range(begin, end):
                j = order[p]
                if j == i:
                    continue
                if ghost and half:
                    if x[j, 2] < zi:
                        continue
                    if x[j, 2] == zi:
                        if x[j, 1] < yi:
                            continue
                        if x[j, 1] == yi and x[j, 0] <= xi:
                            continue
                delx = xi - x[j, 0]
                dely = yi - x[j, 1]
                delz = zi - x[j, 2]
                tj = type_[j]
                if delx * delx + dely * dely + delz * delz >= cutneighsq[ti, tj]:
                    continue
                if excluded_types[ti, tj]:
                    continue
                if screen:
                    left_out = False
                    for g in range(excluded_groups.shape[0]):
                        a, b = excluded_groups[g, 0], excluded_groups[g, 1]
                        if ((mask[i] & a) and (mask[j] & b)) or ((mask[i] & b) and (mask[j] & a)):
                            left_out = True
                            break
                    if left_out:
                        continue
                if screen_molecules:
                    left_out = False
                    for g in range(excluded_molecules.shape[0]):
                        bit = excluded_molecules[g, 0]
                        kind = excluded_molecules[g, 1]
                        same = molecule[i] == molecule[j]
                        if (mask[i] & bit) and (mask[j] & bit) and \
                                ((kind == 0 and not same) or (kind == 1 and same) or (kind == 2 and same and molecule[i] > 0)):
                            left_out = True
                            break
                    if left_out:
                        continue
                if screen_special:
                    left_out = False
                    first = 0
                    for level in range(3):
                        last = nspecial[i, level]
                        if special_levels[level]:
                            for e in range(first, last):
                                if special[i, e] == tag[j]:
                                    left_out = True
                                    break
                        if left_out:
                            break
                        first = last
                    if left_out:
                        continue
                if k >= capacity:
                    return -1
                neighbors[k] = j
                k += 1
    offsets[nlocal] = k
    return k


@njit(cache=True)
def largest_displacement_sq(x, xhold, nlocal):
    """The largest squared displacement since the last build (the rebuild decision, at every step):
    four running maxima, so that a particle's comparison need not wait for the last one's."""
    w0 = w1 = w2 = w3 = 0.0
    quads = nlocal - nlocal % 4
    for i in range(0, quads, 4):
        r = _displacement_sq(x, xhold, i)
        w0 = r if r > w0 else w0
        r = _displacement_sq(x, xhold, i + 1)
        w1 = r if r > w1 else w1
        r = _displacement_sq(x, xhold, i + 2)
        w2 = r if r > w2 else w2
        r = _displacement_sq(x, xhold, i + 3)
        w3 = r if r > w3 else w3
    for i in range(quads, nlocal):
        r = _displacement_sq(x, xhold, i)
        w0 = r if r > w0 else w0
    return max(max(w0, w1), max(w2, w3))


@njit(cache=True, inline="always")
def _displacement_sq(x, xhold, i):
    dx = x[i, 0] - xhold[i, 0]
    dy = x[i, 1] - xhold[i, 1]
    dz = x[i, 2] - xhold[i, 2]
    return dx * dx + dy * dy + dz * dz


@njit(cache=True)
def largest_reach_sq(x, xhold, radius, rhold, nlocal):
    """Where radii change during a run (Fix.varies_radius): the square of the largest displacement
    plus radius growth since the last build, max_i (|x_i - xhold_i| + max(r_i - rhold_i, 0)). A pair
    left out of the lists can touch only once this sum over its two particles passes the skin
    (LIGGGHTS's check_distance with radvary)."""
    worst = 0.0
    for i in range(nlocal):
        reach = math.sqrt(_displacement_sq(x, xhold, i)) + max(radius[i] - rhold[i], 0.0)
        worst = reach if reach > worst else worst
    return worst * worst


@njit(cache=True)
def max_displacement_sq(x, xhold, nlocal):
    """(largest squared displacement since the last build, index of the particle that made it)."""
    worst = 0.0
    who = -1
    for i in range(nlocal):
        dx = x[i, 0] - xhold[i, 0]
        dy = x[i, 1] - xhold[i, 1]
        dz = x[i, 2] - xhold[i, 2]
        r = dx * dx + dy * dy + dz * dz
        if r > worst:
            worst = r
            who = i
    return worst, who
