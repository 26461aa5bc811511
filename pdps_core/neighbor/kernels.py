"""numba kernels for neighbor lists: cell binning and half/full Verlet lists in CSR form.

A half list holds each pair once. Pairs of two owned particles are kept as (i, j > i); a pair of an
owned particle and a ghost is kept on the side where the ghost lies "above" (larger z, then y, then x),
LAMMPS's newton-on rule, so that of the two periodic images of one pair exactly one is listed.
"""

import numpy as np
from numba import njit


@njit(cache=True)
def bin_particles(x, nall, lo, binsize, nbins):
    """Counting sort of particles into cells; returns (cell of each particle, cell starts, order)."""
    ncells = nbins[0] * nbins[1] * nbins[2]
    cell = np.empty(nall, dtype=np.int64)
    count = np.zeros(ncells + 1, dtype=np.int64)
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
        count[cell[i] + 1] += 1
    for c in range(ncells):
        count[c + 1] += count[c]
    start = count.copy()
    order = np.empty(nall, dtype=np.int64)
    fill = count[:-1].copy()
    for i in range(nall):
        order[fill[cell[i]]] = i
        fill[cell[i]] += 1
    return cell, start, order


@njit(cache=True)
def build_list(x, type_, mask, groupbit, nlocal, cutneighsq, cell, start, order, nbins, half, capacity,
               excluded_types, excluded_groups, molecule, excluded_molecules):
    """Neighbors of each owned particle of the group (``mask & groupbit``) within
    cutneighsq[type_i, type_j]; particles outside the group have none. Pairs of excluded types
    (``excluded_types[ti, tj]``), of excluded groups (rows of two mask bits, either order) or, for
    rows (group bit, 1 for intra or 0 for inter) of ``excluded_molecules``, pairs of the group in the
    same molecule (intra) or in different ones (inter) are left out (neigh_modify exclude).
    -1 total on overflow."""
    screen = excluded_groups.shape[0] > 0
    screen_molecules = excluded_molecules.shape[0] > 0
    offsets = np.zeros(nlocal + 1, dtype=np.int64)
    neighbors = np.empty(capacity, dtype=np.int64)
    k = 0
    for i in range(nlocal):
        offsets[i] = k
        if not mask[i] & groupbit:
            continue
        ci = cell[i]
        cx = ci % nbins[0]
        cy = (ci // nbins[0]) % nbins[1]
        cz = ci // (nbins[0] * nbins[1])
        xi, yi, zi = x[i, 0], x[i, 1], x[i, 2]
        ti = type_[i]
        for dz in range(-1, 2):
            z = cz + dz
            if z < 0 or z >= nbins[2]:
                continue
            for dy in range(-1, 2):
                y = cy + dy
                if y < 0 or y >= nbins[1]:
                    continue
                for dx in range(-1, 2):
                    xc = cx + dx
                    if xc < 0 or xc >= nbins[0]:
                        continue
                    c = (z * nbins[1] + y) * nbins[0] + xc
                    for p in range(start[c], start[c + 1]):
                        j = order[p]
                        if j == i:
                            continue
                        if half:
                            if j < nlocal:
                                if j < i:
                                    continue
                            elif x[j, 2] < zi:
                                continue
                            elif x[j, 2] == zi:
                                if x[j, 1] < yi:
                                    continue
                                elif x[j, 1] == yi and x[j, 0] <= xi:
                                    continue
                        delx = xi - x[j, 0]
                        dely = yi - x[j, 1]
                        delz = zi - x[j, 2]
                        if delx * delx + dely * dely + delz * delz < cutneighsq[ti, type_[j]]:
                            if excluded_types[ti, type_[j]]:
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
                                    if (mask[i] & bit) and (mask[j] & bit) and \
                                            (molecule[i] == molecule[j]) == (excluded_molecules[g, 1] == 1):
                                        left_out = True
                                        break
                                if left_out:
                                    continue
                            if k >= capacity:
                                return offsets, neighbors, -1
                            neighbors[k] = j
                            k += 1
    offsets[nlocal] = k
    return offsets, neighbors, k


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
