"""Overlap-free placement of new spheres among present ones (the insertion fixes' overlap check).

Candidate centres come in a pool, drawn uniformly over the insertion volume in the order of a
random stream every rank shares, each with a shift a sphere's radius moves it by (insert/stream's);
the spheres, largest first, take the first candidates that keep them the required share of their
radius inside the box and clear of every present sphere and of the spheres placed before them
(touching is allowed: distance >= r_i + r_j), the spheres sharing ``tries`` candidates. Spheres are binned on a
grid of cells at least as wide as the largest sum of two radii, so each test looks at 27 cells;
on a periodic axis the grid spans the box and wraps, and distances are minimum-image.
"""

import math

import numpy as np
from numba import njit

MAX_BINS_PER_AXIS = 64


@njit(cache=True)
def _bin_of(x, lo, width, nbins, periodic):
    index = 0
    for d in range(2, -1, -1):
        k = int(math.floor((x[d] - lo[d]) / width[d]))
        if periodic[d]:
            k %= nbins[d]
        else:
            k = min(max(k, 0), nbins[d] - 1)
        index = index * nbins[d] + k
    return index


@njit(cache=True)
def _clear(x, r, xs, rs, head, link, lo, width, nbins, periodic, length):
    """True when a sphere (x, r) overlaps none of the binned ones."""
    visit = np.empty((3, 3), dtype=np.int64)
    count = np.zeros(3, dtype=np.int64)
    for d in range(3):
        k = int(math.floor((x[d] - lo[d]) / width[d]))
        k = k % nbins[d] if periodic[d] else min(max(k, 0), nbins[d] - 1)
        if nbins[d] < 3:
            # fewer than three bins along the axis: each of them, once
            for m in range(nbins[d]):
                visit[d, m] = m
            count[d] = nbins[d]
            continue
        for offset in range(-1, 2):
            m = k + offset
            if periodic[d]:
                m %= nbins[d]
            elif m < 0 or m >= nbins[d]:
                continue
            visit[d, count[d]] = m
            count[d] += 1
    for a in range(count[2]):
        for b in range(count[1]):
            for c in range(count[0]):
                j = head[(visit[2, a] * nbins[1] + visit[1, b]) * nbins[0] + visit[0, c]]
                while j >= 0:
                    distance_sq = 0.0
                    for d in range(3):
                        delta = x[d] - xs[j, d]
                        if periodic[d]:
                            delta -= length[d] * round(delta / length[d])
                        distance_sq += delta * delta
                    reach = r + rs[j]
                    if distance_sq < reach * reach:
                        return False
                    j = link[j]
    return True


@njit(cache=True)
def _room_in_box(x, box_lo, box_hi):
    """The distance from x to the nearest face of the box (negative outside)."""
    room = np.inf
    for d in range(3):
        room = min(room, x[d] - box_lo[d], box_hi[d] - x[d])
    return room


@njit(cache=True)
def place(pool, shift, clearance, radius, old_x, old_r, lo, width, nbins, periodic, length, tries, check_overlap,
          box_lo, box_hi, border, placed, done, taken):
    """Place the spheres ``radius`` (largest first) at candidates of ``pool`` in order, a sphere of
    radius r at row j going to ``pool[j] + r shift[j]`` (insert/stream's depth counts from the
    sphere's own radius). A candidate is passed over, not tried, when ``clearance`` (its distance
    to the insertion volume's surface, for all_in) is less than r; a try fails when the centre lies
    less than ``border`` r inside the box (``box_lo``, ``box_hi``; LIGGGHTS's check against its
    subdomain's faces; -inf: no check) or, with ``check_overlap``, when the sphere overlaps a
    present (``old_x, old_r``) or earlier placed sphere. ``tries`` tries in all (the insertion's
    budget, FixInsert.tries): a sphere hard to place may use what the easy ones left. Writes
    ``placed``, ``done`` and ``taken`` (the pool row each sphere took); returns how many were placed."""
    n_old, n_new = len(old_r), len(radius)
    head = np.full(nbins[0] * nbins[1] * nbins[2], -1, dtype=np.int64)
    link = np.empty(n_old + n_new, dtype=np.int64)
    xs = np.empty((n_old + n_new, 3))
    rs = np.empty(n_old + n_new)
    for k in range(n_old):
        xs[k] = old_x[k]
        rs[k] = old_r[k]
        b = _bin_of(old_x[k], lo, width, nbins, periodic)
        link[k] = head[b]
        head[b] = k
    count = n_old
    used = 0
    tried = 0
    for k in range(n_new):
        done[k] = False
    candidate = np.empty(3)
    for k in range(n_new):
        while used < len(pool) and tried < tries:
            for d in range(3):
                candidate[d] = pool[used, d] + radius[k] * shift[used, d]
            room = clearance[used]
            used += 1
            if room < radius[k]:
                continue            # no try: LIGGGHTS draws again until the sphere fits inside
            tried += 1
            if _room_in_box(candidate, box_lo, box_hi) < border * radius[k]:
                continue
            if check_overlap and not _clear(candidate, radius[k], xs, rs, head, link, lo, width, nbins,
                                            periodic, length):
                continue
            placed[k] = candidate
            done[k] = True
            taken[k] = used - 1
            xs[count] = candidate
            rs[count] = radius[k]
            b = _bin_of(candidate, lo, width, nbins, periodic)
            link[count] = head[b]
            head[b] = count
            count += 1
            break
    return count - n_old


def grid(box, extent_lo, extent_hi, cell):
    """(lo, width, nbins, periodic, length) of a grid whose bins are at least ``cell`` wide: the whole
    box along periodic axes, the insertion extent grown by one cell along the others."""
    periodic = np.array(box.periodic, dtype=np.bool_)
    lo, width = np.empty(3), np.empty(3)
    nbins = np.empty(3, dtype=np.int64)
    for d in range(3):
        if periodic[d]:
            start, span = box.lo[d], box.length[d]
        else:
            start, span = extent_lo[d] - cell, extent_hi[d] - extent_lo[d] + 2.0 * cell
        count = int(min(MAX_BINS_PER_AXIS, max(1.0, math.floor(span / cell)))) if cell > 0 else 1
        lo[d], nbins[d], width[d] = start, count, span / count
    return lo, width, nbins, periodic, np.array(box.length, dtype=np.float64)
