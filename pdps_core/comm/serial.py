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


@njit(cache=True)
def _sum_onto_owners(values, source, nlocal):
    for g in range(len(source)):
        owner = source[g]
        for d in range(values.shape[1]):
            values[owner, d] += values[nlocal + g, d]


class SerialComm:
    nprocs = 1
    rank = 0
    is_root = True

    def __init__(self):
        self.ghost_source = np.zeros(0, dtype=np.int64)
        self.ghost_shift = np.zeros((0, 3))

    def exchange(self, particles, box, step):
        p = particles
        p.clear_ghosts()
        x = p.x
        bad = ~np.isfinite(x).all(axis=1)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            raise SimulationError(
                f"particle {int(p.tag[i])} has a non-finite position {tuple(x[i])} at step {step}")
        gone = box.wrap(x, p.image, p.tag, step, box.lost)
        if gone.any():
            p.keep(np.flatnonzero(~gone))

    def borders(self, particles, box, cutghost):
        p = particles
        nlocal = p.nlocal
        position = p.x[:nlocal].copy()
        source = np.arange(nlocal, dtype=np.int64)
        shift = np.zeros((nlocal, 3))
        if cutghost > 0:
            for d in range(3):
                if not box.periodic[d] or (box.dimension == 2 and d == 2):
                    continue
                length = box.hi[d] - box.lo[d]
                images = math.ceil(cutghost / length)
                new_pos, new_src, new_shift = [position], [source], [shift]
                for k in range(1, images + 1):
                    for sign in (1.0, -1.0):
                        moved = position[:, d] + sign * k * length
                        keep = (moved < box.hi[d] + cutghost) & (moved >= box.lo[d] - cutghost)
                        if keep.any():
                            delta = np.zeros(3)
                            delta[d] = sign * k * length
                            new_pos.append(position[keep] + delta)
                            new_src.append(source[keep])
                            new_shift.append(shift[keep] + delta)
                position = np.concatenate(new_pos)
                source = np.concatenate(new_src)
                shift = np.concatenate(new_shift)
        self.ghost_source = source[nlocal:]
        self.ghost_shift = shift[nlocal:]
        p.set_ghosts(self.ghost_source, self.ghost_shift)

    def owners(self, particles):
        """Owned index of every particle, owned or ghost (ghost -> the particle it copies). On one
        rank every ghost's owner is local; the MPI version maps only its own ghosts."""
        return np.concatenate([np.arange(particles.nlocal, dtype=np.int64), self.ghost_source])

    def reverse_rows(self, rows):
        """Rows of ghost values, with the owned index each ghost copies."""
        return self.ghost_source, rows

    def forward_comm(self, particles, names=("x",)):
        p = particles
        src = self.ghost_source
        if not len(src):
            return
        for name in names:
            array = p.arrays[name]
            if name == "x":
                array[p.nlocal:] = array[src] + self.ghost_shift
            else:
                array[p.nlocal:] = array[src]

    def reverse_comm(self, particles, names=("f",)):
        p = particles
        if not len(self.ghost_source):
            return
        for name in names:
            _sum_onto_owners(p.arrays[name], self.ghost_source, p.nlocal)

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
