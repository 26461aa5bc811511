"""The processor grid: how the box is cut into one sub-domain per rank.

``processors NX NY NZ`` fixes it (``*`` lets pdps choose that factor); otherwise, as in the PDPS
manual and LAMMPS, pdps picks the factorisation of the rank count with the least sub-domain surface,
which keeps the ghost layer (and so the communication) smallest.
"""

import itertools
import math

import numpy as np
from numba import njit

from ..errors import ScriptError


def choose_grid(nprocs, lengths, dimension=3, fixed=(None, None, None)):
    """(px, py, pz) with px*py*pz = nprocs, honouring fixed factors, least surface per sub-domain."""
    best, best_area = None, None
    for px, py in itertools.product(range(1, nprocs + 1), repeat=2):
        if nprocs % (px * py):
            continue
        pz = nprocs // (px * py)
        grid = (px, py, pz)
        if dimension == 2 and pz != 1:
            continue
        if any(f is not None and f != g for f, g in zip(fixed, grid)):
            continue
        sub = np.asarray(lengths, float) / grid
        area = sub[0] * sub[1] + sub[1] * sub[2] + sub[0] * sub[2]
        if dimension == 2:
            area = sub[0] + sub[1]
        if best is None or area < best_area - 1e-12:
            best, best_area = grid, area
    if best is None:
        raise ScriptError(f"no processor grid of {nprocs} ranks matches processors "
                          f"{' '.join('*' if f is None else str(f) for f in fixed)}")
    return best


@njit(cache=True)
def rank_of_position(x, i, lo, length, grid):
    """The rank whose sub-domain holds particle i's position (wrapped into the box): the one rule for
    ownership, which migration (comm/mpi.py) and Decomposition.owner both use."""
    rank = 0
    stride = 1
    for d in range(3):
        cell = int(math.floor((x[i, d] - lo[d]) / length[d] * grid[d]))
        cell = min(max(cell, 0), grid[d] - 1)
        rank += cell * stride
        stride *= grid[d]
    return rank


@njit(cache=True)
def _owners(x, lo, length, grid, out):
    for i in range(x.shape[0]):
        out[i] = rank_of_position(x, i, lo, length, grid)


class Decomposition:
    """Sub-domain bounds and the owner rank of any position."""

    def __init__(self, box, grid):
        self.box = box
        self.grid = np.asarray(grid, dtype=np.int64)
        self.nprocs = int(np.prod(grid))

    def coords(self, rank):
        px, py, _ = self.grid
        return np.array([rank % px, (rank // px) % py, rank // (px * py)])

    def bounds(self, rank):
        c = self.coords(rank)
        lo, length = self.box.lo, self.box.length
        return lo + length * c / self.grid, lo + length * (c + 1) / self.grid

    def all_bounds(self):
        """(lo, hi) of every rank's sub-domain, nprocs x 3 each."""
        rank = np.arange(self.nprocs)
        px, py, _ = self.grid
        c = np.stack([rank % px, (rank // px) % py, rank // (px * py)], axis=1)
        lo, length = np.asarray(self.box.lo, dtype=np.float64), np.asarray(self.box.length, dtype=np.float64)
        return lo + length * c / self.grid, lo + length * (c + 1) / self.grid

    def owner(self, x):
        """Rank owning each position (n x 3), positions already wrapped into the box."""
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1, 3)
        out = np.empty(len(x), dtype=np.int64)
        _owners(x, np.asarray(self.box.lo, dtype=np.float64), np.asarray(self.box.length, dtype=np.float64),
                self.grid, out)
        return out
