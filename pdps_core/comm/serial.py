"""Communication on one rank: periodic ghosts made through the interface the MPI version implements.

- ``exchange``: owned particles that left the box are wrapped back (periodic) or stop the run (fixed).
- ``borders``: ghosts are copies of owned particles within ``cutghost`` of a periodic face, displaced by
  the box length; a box thinner than the cutoff gets several images, so no pair is missed.
- ``forward_comm``: ghosts take their owner's current value (x with its shift; v, omega as is).
- ``reverse_comm``: what the pair style added to a ghost (f, torque) is summed onto its owner.
"""

import math

import numpy as np
from numba import njit

from ..errors import SimulationError
from ..state.finite import first_non_finite


@njit(cache=True)
def _sum_onto_owners(values, source, nlocal):
    for g in range(len(source)):
        owner = source[g]
        for d in range(values.shape[1]):
            values[owner, d] += values[nlocal + g, d]


@njit(cache=True)
def _copy_to_ghosts(values, source, nlocal):
    for g in range(len(source)):
        for d in range(values.shape[1]):
            values[nlocal + g, d] = values[source[g], d]


@njit(cache=True)
def _copy_pair_to_ghosts(first, second, source, nlocal):
    """Two vectors per particle at once (v and omega of a granular step: one call fewer a step)."""
    for g in range(len(source)):
        i = source[g]
        for d in range(3):
            first[nlocal + g, d] = first[i, d]
            second[nlocal + g, d] = second[i, d]


@njit(cache=True)
def _sum_pair_onto_owners(first, second, source, nlocal):
    """f and torque summed back at once (one call fewer a step)."""
    for g in range(len(source)):
        owner = source[g]
        for d in range(3):
            first[owner, d] += first[nlocal + g, d]
            second[owner, d] += second[nlocal + g, d]


@njit(cache=True)
def _positions_to_ghosts(x, source, shift, nlocal):
    for g in range(len(source)):
        i = source[g]
        x[nlocal + g, 0] = x[i, 0] + shift[g, 0]
        x[nlocal + g, 1] = x[i, 1] + shift[g, 1]
        x[nlocal + g, 2] = x[i, 2] + shift[g, 2]


@njit(cache=True)
def _periodic_images(x, nlocal, lo, hi, cutghost, periodic, source, shift):
    """Ghosts of periodic images, one axis after the other (images of images make the edges and
    corners): every copy of a particle (or of an earlier ghost) displaced by k box lengths along a
    periodic axis that lands within ``cutghost`` of the box. Writes (owned index, shift) into the
    buffers; returns how many ghosts, or -1 when they are too small."""
    n = nlocal
    capacity = len(source)
    for d in range(3):
        if not periodic[d]:
            continue
        length = hi[d] - lo[d]
        images = int(math.ceil(cutghost / length))
        current = n
        for m in range(current):
            if m < nlocal:
                owner = m
                base0, base1, base2 = 0.0, 0.0, 0.0
            else:
                owner = source[m - nlocal]
                base0, base1, base2 = shift[m - nlocal, 0], shift[m - nlocal, 1], shift[m - nlocal, 2]
            position = x[owner, d] + (base0, base1, base2)[d]
            for k in range(1, images + 1):
                for sign in (1.0, -1.0):
                    moved = position + sign * k * length
                    if moved < hi[d] + cutghost and moved >= lo[d] - cutghost:
                        if n - nlocal >= capacity:
                            return -1
                        g = n - nlocal
                        source[g] = owner
                        shift[g, 0], shift[g, 1], shift[g, 2] = base0, base1, base2
                        shift[g, d] += sign * k * length
                        n += 1
    return n - nlocal


@njit(cache=True)
def _owner_rows(nlocal, source, owners):
    """owners = 0 .. nlocal-1, then the owned particle each ghost copies."""
    for i in range(nlocal):
        owners[i] = i
    for k in range(len(source)):
        owners[nlocal + k] = source[k]


def _ghost_estimate(nlocal, box, cutghost, periodic):
    """Room for the ghosts of a uniform fluid, a tenth more: the layer of width cutghost around the
    box along its periodic axes, at the particles' density."""
    grown = 1.0
    for d in range(3):
        if periodic[d]:
            grown *= 1.0 + 2.0 * cutghost / box.length[d]
    return int(1.1 * nlocal * (grown - 1.0)) + 64


def _vector(array):
    return array.ndim == 2 and array.shape[1] == 3 and array.dtype == np.float64


def forward_to_images(particles, names, source, shift):
    """Ghost values from their owners when every ghost is a periodic image of an owned particle on
    this rank: ghost g copies particle ``source[g]`` (positions displaced by ``shift[g]``)."""
    p = particles
    if not len(source):
        return
    pending = None          # a vector waiting for a second one, to copy both in one call
    for name in names:
        array = p.arrays[name]
        if name == "x":
            _positions_to_ghosts(array, source, shift, p.nlocal)
        elif _vector(array):
            if pending is None:
                pending = array
            else:
                _copy_pair_to_ghosts(pending, array, source, p.nlocal)
                pending = None
        elif array.ndim == 2:
            _copy_to_ghosts(array, source, p.nlocal)
        else:
            array[p.nlocal:] = array[source]
    if pending is not None:
        _copy_to_ghosts(pending, source, p.nlocal)


def reverse_from_images(particles, names, source):
    """Ghost values summed onto their owners, every ghost a periodic image (forward_to_images), in
    the order of the ghosts."""
    p = particles
    if not len(source):
        return
    arrays = [p.arrays[name] for name in names]
    if len(arrays) == 2 and _vector(arrays[0]) and _vector(arrays[1]):
        _sum_pair_onto_owners(arrays[0], arrays[1], source, p.nlocal)
        return
    for array in arrays:
        # a per-atom scalar (1-d) as a column, as MPIComm.reverse_comm reads it
        _sum_onto_owners(array.reshape(len(array), -1), source, p.nlocal)


class SerialComm:
    nprocs = 1
    rank = 0
    is_root = True

    def __init__(self):
        self.ghost_source = np.zeros(0, dtype=np.int64)
        self.ghost_shift = np.zeros((0, 3))
        self._source = np.zeros(0, dtype=np.int64)      # buffers the ghosts' lists are written into
        self._shift = np.zeros((0, 3))
        self._owners = None
        self._owner_rows = np.zeros(0, dtype=np.int64)     # kept between rebuilds
        self._rank_zero = np.zeros(0, dtype=np.int64)      # send_rows(..., kept=True): every row's rank

    def exchange(self, particles, box, step):
        p = particles
        p.clear_ghosts()
        x = p.x
        i = first_non_finite(x, p.nlocal)
        if i >= 0:
            raise SimulationError(
                f"particle {int(p.tag[i])} has a non-finite position {tuple(x[i])} at step {step}")
        gone = box.wrap(x, p.image, p.tag, step, box.lost)
        if gone is not None:
            p.keep(np.flatnonzero(~gone))

    def migrate(self, particles, box):
        """Every particle is the only rank's (MPIComm.migrate moves them to their sub-domains)."""
        particles.clear_ghosts()

    def decompose(self, box):
        """One sub-domain, the box."""
        return (1, 1, 1)

    def borders(self, particles, box, cutghost):
        p = particles
        nlocal = p.nlocal
        p.clear_ghosts()
        count = 0
        if cutghost > 0:
            periodic = np.array([box.periodic[d] and not (box.dimension == 2 and d == 2) for d in range(3)])
            while True:
                count = _periodic_images(p.x, nlocal, box.lo, box.hi, cutghost, periodic, self._source,
                                         self._shift)
                if count >= 0:
                    break
                # the estimate for this cutoff, or a quarter more when it fell short: doubling when
                # direct mode widens the skin held twice the ghosts (dpd_gw: 28,104 rows for 15,002)
                size = max(len(self._source) + len(self._source) // 4,
                           _ghost_estimate(nlocal, box, cutghost, periodic))
                self._source, self._shift = np.empty(size, dtype=np.int64), np.empty((size, 3))
        self.ghost_source = self._source[:count]
        self.ghost_shift = self._shift[:count]
        self._owners = None
        p.set_ghosts(self.ghost_source, self.ghost_shift)

    def owners(self, particles):
        """Owned index of every particle, owned or ghost (ghost -> the particle it copies). On one
        rank every ghost's owner is local; the MPI version maps only its own ghosts. Kept until the
        ghosts are made again."""
        n = particles.nlocal + len(self.ghost_source)
        if self._owners is None or len(self._owners) != n:
            if len(self._owner_rows) < n:
                self._owner_rows = np.empty(n + n // 4 + 16, dtype=np.int64)
            self._owners = self._owner_rows[:n]
            _owner_rows(particles.nlocal, self.ghost_source, self._owners)
        return self._owners

    def send_rows(self, rows, ranks, kept=False):
        """On one rank every row stays: (rows, the rank each came from); ``kept``: the ranks in a
        kept array (the rows are the caller's own)."""
        rows = np.asarray(rows, dtype=np.float64)       # (n, width), n = len(ranks)
        if not kept:
            return rows, np.zeros(len(rows), dtype=np.int64)
        if len(self._rank_zero) < len(rows):
            self._rank_zero = np.zeros(len(rows) + len(rows) // 4 + 16, dtype=np.int64)
        return rows, self._rank_zero[:len(rows)]

    def rank_of(self, points):
        return np.zeros(len(points), dtype=np.int64)

    def reverse_rows(self, rows, ghosts=None):
        """Rows of ghost values (of the ghosts ``ghosts``, or of every ghost), with the owned index
        each ghost copies."""
        return (self.ghost_source if ghosts is None else self.ghost_source[ghosts]), rows

    def forward_comm(self, particles, names=("x",)):
        forward_to_images(particles, names, self.ghost_source, self.ghost_shift)

    def reverse_comm(self, particles, names=("f",)):
        reverse_from_images(particles, names, self.ghost_source)

    def set_grid(self, fixed):
        """Validated by the processors command: on one rank every factor is 1."""

    def distribute(self, particles, box):
        """Every particle created belongs to the only rank."""

    def gather_rows(self, rows):
        return rows

    def bcast(self, value):
        return value

    def allgather_rows(self, rows):
        return rows

    def agree(self, message, count=0):
        """The MPI version agrees across ranks; on one rank a message is simply the error."""
        if message:
            error = SimulationError(message.format(count=count) if "{count}" in message else message)
            error.agreed = True
            raise error

    # global reductions: identity on one rank, the MPI version sums over ranks
    def sum(self, value):
        return value

    def max(self, value):
        return value

    def min(self, value):
        return value
