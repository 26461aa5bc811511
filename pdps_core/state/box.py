"""The simulation box: an orthogonal block with periodic (p) or fixed (f) faces.

A particle leaving through an ``f`` face is lost, and the run stops (PDPS manual, ``boundary``).
Positions of particles that cross a periodic face are wrapped and their image counters updated.

The bounds may change during a run (``Simulation.change_box``: barostats, fix deform); they change in
place (``set_bounds``), so every holder of the box sees the new ones.
"""

import math

import numpy as np
from numba import njit

from ..errors import SimulationError


@njit(cache=True)
def _wrap_periodic(x, image, n, lo, hi, periodic):
    """Along the periodic axes, positions moved back into [lo, hi) by whole lengths, image flags
    counting; every axis in one pass over the particles."""
    for i in range(n):
        for d in range(3):
            if not periodic[d] or lo[d] <= x[i, d] < hi[d]:
                continue
            length = hi[d] - lo[d]
            shift = math.floor((x[i, d] - lo[d]) / length)
            if shift != 0:
                x[i, d] -= shift * length
                image[i, d] += np.int32(shift)
                # floor() rounding can leave x == hi; hi belongs to the next image
                if x[i, d] >= hi[d]:
                    x[i, d] = lo[d]
                    image[i, d] += 1


@njit(cache=True)
def _inside_axis(x, n, d, lo, hi):
    """True when every position lies within [lo, hi] on fixed axis d (and is finite)."""
    for i in range(n):
        if not (lo <= x[i, d] <= hi):
            return False
    return True

MAX_PERIODS = 1000      # remap: box lengths walked one at a time, as LAMMPS, before jumping instead


@njit(cache=True)
def remap(x, shifts, lo, hi, periodic):
    """LAMMPS's Domain::remap: across each periodic axis add or subtract the box length until
    lo <= x < hi, counting image shifts, then no lower than lo (x - length can round below it).
    A position more than MAX_PERIODS lengths away jumps most of the way first instead of looping."""
    for i in range(len(x)):
        for d in range(3):
            if not periodic[d]:
                continue
            length = hi[d] - lo[d]
            c = x[i, d]
            if abs(c - lo[d]) > MAX_PERIODS * length:
                jump = min(max(np.floor((c - lo[d]) / length), -2.0 ** 62), 2.0 ** 62)
                c = lo[d] + np.mod(c - lo[d], length)
                shifts[i, d] += np.int64(jump)
            while c < lo[d]:
                c += length
                shifts[i, d] -= 1
            while c >= hi[d]:
                c -= length
                shifts[i, d] += 1
            x[i, d] = max(c, lo[d])


class Box:
    def __init__(self, lo, hi, periodic, dimension=3):
        self.lo = np.asarray(lo, dtype=np.float64)
        self.hi = np.asarray(hi, dtype=np.float64)
        self.periodic = tuple(bool(p) for p in periodic)
        self._periodic_axes = np.array(self.periodic, dtype=np.bool_)     # for the numba kernels
        self.lost = "error"             # LAMMPS's thermo_modify lost: error, warn or ignore
        self.dimension = dimension

    def set_bounds(self, lo, hi):
        """New bounds, in place; lo < hi on every axis, finite (else a one-line SimulationError)."""
        lo = np.asarray(lo, dtype=np.float64)
        hi = np.asarray(hi, dtype=np.float64)
        if not (np.isfinite(lo).all() and np.isfinite(hi).all() and (hi > lo).all()):
            raise SimulationError(f"the box cannot become [{', '.join(f'{v:.6g}' for v in lo)}] to "
                                  f"[{', '.join(f'{v:.6g}' for v in hi)}]: every side must stay finite "
                                  "and longer than 0 (the barostat or deformation ran away)")
        self.lo[:] = lo
        self.hi[:] = hi

    def set_periodic(self, periodic):
        """New periodic axes (change_box boundary), in place as set_bounds."""
        self.periodic = tuple(bool(p) for p in periodic)
        self._periodic_axes[:] = self.periodic

    @property
    def length(self):
        return self.hi - self.lo

    @property
    def volume(self):
        """Volume in 3-d, area in 2-d (LAMMPS's convention for pressure)."""
        lengths = self.length
        return float(np.prod(lengths[: self.dimension]))

    def bounds_label(self, periodicity=None):
        """A dump header's boundary label: "pp" or the boundary command's two letters per axis
        (``periodicity``, its words: "ff", "mm", "fs", ...), or "ff" for every non-periodic axis."""
        if periodicity is None:
            return " ".join("pp" if p else "ff" for p in self.periodic)
        return " ".join("pp" if p else word[0] + word[-1] for p, word in zip(self.periodic, periodicity))

    def wrap(self, x, image, tag, step, lost="error"):
        """Bring owned particles back into the box. One that has left through a fixed face raises
        (``lost="error"``, the default and the PDPS manual's rule) or, with LAMMPS's
        ``thermo_modify lost warn|ignore``, is returned in the mask of lost rows for the caller to
        delete (None when no particle is lost)."""
        if any(self.periodic):
            _wrap_periodic(x, image, len(x), self.lo, self.hi, self._periodic_axes)
        gone = None
        for d in range(3):
            if self.periodic[d] or _inside_axis(x, len(x), d, self.lo[d], self.hi[d]):
                continue
            else:
                out = (x[:, d] < self.lo[d]) | (x[:, d] > self.hi[d]) | ~np.isfinite(x[:, d])
                if out.any() and lost != "error":
                    gone = out if gone is None else gone | out
                    continue
                if out.any():
                    i = int(np.flatnonzero(out)[0])
                    axis = "xyz"[d]
                    template = (f"particle {int(tag[i])} lost through the fixed {axis} boundary at step "
                                f"{step}: {axis} = {x[i, d]:.6g} outside [{self.lo[d]:g}, {self.hi[d]:g}]"
                                " ({count} particle(s) outside)")
                    error = SimulationError(template.format(count=int(out.sum())))
                    # a parallel run reports the count summed over ranks (Comm.agree)
                    error.template, error.count = template, int(out.sum())
                    raise error
        return gone

    def inside(self, x):
        """Mask of positions inside [lo, hi) on every axis."""
        return np.all((x >= self.lo) & (x < self.hi), axis=1)
