"""Communication over MPI (mpi4py): spatial decomposition, migration, ghosts, forward/reverse comm.

The box is cut into a processor grid (``grid.py``); each rank owns the particles inside its
sub-domain. The interface is the serial one:

- ``distribute``: after particles are created (identically on every rank), each keeps its own.
- ``exchange``: at a rebuild, particles that left the sub-domain move to their new owner (all their
  per-atom arrays travel as one row: contact histories and fix state go with them).
- ``borders``: every rank receives as ghosts the particles (and periodic images) within ``cutghost``
  of its sub-domain, from whichever rank owns them. Ghosts are sent directly by their owner, so a
  sub-domain thinner than the cutoff still gets every ghost it needs (no multi-hop relay).
- ``forward_comm`` / ``reverse_comm``: ghost values refreshed from owners / ghost forces summed back.

Errors found on one rank (a lost particle, a non-finite force) are agreed on collectively with
``agree`` so that every rank stops with the same one-line message and none hangs.
"""

import numpy as np

from ..errors import SimulationError
from .grid import Decomposition, choose_grid


class MPIComm:
    def __init__(self, world=None):
        from mpi4py import MPI
        self.MPI = MPI
        self.world = world if world is not None else MPI.COMM_WORLD
        self.rank = self.world.Get_rank()
        self.nprocs = self.world.Get_size()
        self.decomposition = None
        self.grid_request = (None, None, None)
        self._send = []          # per destination rank: (local indices, shift rows)
        self._recv_counts = np.zeros(self.nprocs, dtype=np.int64)
        self._self_ghost = np.zeros(0, dtype=np.int64)

    @property
    def is_root(self):
        return self.rank == 0

    # ---- decomposition ------------------------------------------------------------------------
    def set_grid(self, fixed):
        self.grid_request = tuple(fixed)

    def decompose(self, box):
        grid = choose_grid(self.nprocs, box.length, box.dimension, self.grid_request)
        self.decomposition = Decomposition(box, grid)
        return grid

    def distribute(self, particles, box):
        """Keep the owned particles of this sub-domain (creation commands run on every rank)."""
        self.decompose(box)
        if particles.nlocal:
            x = particles.x[: particles.nlocal].copy()
            image = np.zeros((len(x), 3), dtype=np.int32)
            box.wrap(x, image, particles.tag[: particles.nlocal], 0)
            particles.keep(self.decomposition.owner(x) == self.rank)

    # ---- migration ----------------------------------------------------------------------------
    def exchange(self, particles, box, step):
        p = particles
        p.clear_ghosts()
        if self.decomposition is None or self.decomposition.box is not box:
            self.decompose(box)
        message = None
        x = p.x
        bad = ~np.isfinite(x).all(axis=1)
        if bad.any():
            i = int(np.flatnonzero(bad)[0])
            message = f"particle {int(p.tag[i])} has a non-finite position {tuple(x[i])} at step {step}"
        else:
            try:
                box.wrap(x, p.image, p.tag, step)
            except SimulationError as exc:
                message = exc.message
        self.agree(message)
        owner = self.decomposition.owner(p.x[: p.nlocal])
        leaving = np.flatnonzero(owner != self.rank)
        order = leaving[np.argsort(owner[leaving], kind="stable")]
        counts = np.bincount(owner[order], minlength=self.nprocs)
        rows = p.pack(order)
        p.keep(np.setdiff1d(np.arange(p.nlocal), leaving, assume_unique=True))
        arrived = self._alltoall_rows(rows, counts)
        if len(arrived):
            p.append_owned(arrived)

    # ---- ghosts -------------------------------------------------------------------------------
    def borders(self, particles, box, cutghost):
        p = particles
        p.clear_ghosts()
        nlocal = p.nlocal
        x = p.x[:nlocal]
        shifts = [np.zeros(3)]
        if cutghost > 0:
            per_axis = []
            for d in range(3):
                if box.periodic[d] and not (box.dimension == 2 and d == 2):
                    k = int(np.ceil(cutghost / box.length[d]))
                    per_axis.append([j * box.length[d] for j in range(-k, k + 1)])
                else:
                    per_axis.append([0.0])
            shifts = [np.array([a, b, c]) for a in per_axis[0] for b in per_axis[1] for c in per_axis[2]]
        self._send = []
        counts = np.zeros(self.nprocs, dtype=np.int64)
        blocks = []
        for rank in range(self.nprocs):
            lo, hi = self.decomposition.bounds(rank)
            lo, hi = lo - cutghost, hi + cutghost
            indices, offsets = [], []
            if cutghost > 0:
                for shift in shifts:
                    if rank == self.rank and not shift.any():
                        continue
                    moved = x + shift
                    inside = np.all((moved >= lo) & (moved < hi), axis=1)
                    if box.dimension == 2:
                        inside = np.all((moved[:, :2] >= lo[:2]) & (moved[:, :2] < hi[:2]), axis=1)
                    chosen = np.flatnonzero(inside)
                    indices.append(chosen)
                    offsets.append(np.repeat(shift[None, :], len(chosen), axis=0))
            index = np.concatenate(indices) if indices else np.zeros(0, dtype=np.int64)
            shift = np.concatenate(offsets) if offsets else np.zeros((0, 3))
            self._send.append((index, shift))
            counts[rank] = len(index)
            rows = p.pack(index)
            rows[:, :3] += shift          # x is the first property: the rows carry the image position
            blocks.append(rows)
        rows = np.concatenate(blocks) if blocks else np.zeros((0, p.row_width()))
        received, self._recv_counts = self._alltoall_rows(rows, counts, return_counts=True)
        p.set_ghost_rows(received)
        # ghosts this rank sent to itself (periodic self-images), for owners()
        start = int(self._recv_counts[: self.rank].sum())
        self._self_ghost = np.full(p.nghost, -1, dtype=np.int64)
        own_index, _ = self._send[self.rank]
        self._self_ghost[start:start + len(own_index)] = own_index

    def owners(self, particles):
        """Owned index of every local particle; ghosts owned by another rank map to -1."""
        return np.concatenate([np.arange(particles.nlocal, dtype=np.int64), self._self_ghost])

    def forward_comm(self, particles, names=("x",)):
        p = particles
        for name in names:
            array = p.arrays[name]
            width = 1 if array.ndim == 1 else array.shape[1]
            blocks = []
            for index, shift in self._send:
                values = array[index].reshape(len(index), width).astype(np.float64)
                if name == "x":
                    values = values + shift
                blocks.append(values)
            sent = np.concatenate(blocks) if blocks else np.zeros((0, width))
            counts = np.array([len(index) for index, _ in self._send], dtype=np.int64)
            received = self._alltoall_rows(sent, counts)
            ghost = array[p.nlocal:]
            ghost[...] = received.reshape(ghost.shape).astype(array.dtype)

    def reverse_comm(self, particles, names=("f",)):
        p = particles
        for name in names:
            array = p.arrays[name]
            width = 1 if array.ndim == 1 else array.shape[1]
            ghost_values = array[p.nlocal:].reshape(p.nghost, width).astype(np.float64)
            back = self._alltoall_rows(ghost_values, self._recv_counts)
            index = np.concatenate([i for i, _ in self._send]) if self._send else np.zeros(0, np.int64)
            np.add.at(array.reshape(len(array), width) if width > 1 else array[:, None], index,
                      back.reshape(len(index), width))

    def reverse_rows(self, rows):
        """Rows of ghost values back to the ranks owning the ghosts: (owned indices, rows) there,
        for values a style merges itself rather than sums."""
        back = self._alltoall_rows(rows, self._recv_counts)
        index = np.concatenate([i for i, _ in self._send]) if self._send else np.zeros(0, np.int64)
        return index, back

    # ---- collectives --------------------------------------------------------------------------
    def _alltoall_rows(self, rows, counts, return_counts=False):
        width = rows.shape[1] if rows.ndim == 2 else 1
        counts = np.asarray(counts, dtype=np.int64)
        recv_counts = np.empty(self.nprocs, dtype=np.int64)
        self.world.Alltoall(counts, recv_counts)
        received = np.empty((int(recv_counts.sum()), width))
        send = np.ascontiguousarray(rows, dtype=np.float64).reshape(-1)
        send_counts = counts * width
        recv_counts_values = recv_counts * width
        send_displ = np.concatenate([[0], np.cumsum(send_counts)[:-1]])
        recv_displ = np.concatenate([[0], np.cumsum(recv_counts_values)[:-1]])
        self.world.Alltoallv([send, (send_counts, send_displ), self.MPI.DOUBLE],
                             [received.reshape(-1), (recv_counts_values, recv_displ), self.MPI.DOUBLE])
        if return_counts:
            return received, recv_counts
        return received

    def sum(self, value):
        return self.world.allreduce(value, op=self.MPI.SUM)

    def max(self, value):
        return self.world.allreduce(value, op=self.MPI.MAX)

    def min(self, value):
        return self.world.allreduce(value, op=self.MPI.MIN)

    def gather_rows(self, rows):
        """All ranks' rows on rank 0 (None elsewhere), in rank order."""
        gathered = self.world.gather(rows, root=0)
        return np.concatenate(gathered) if self.is_root else None

    def allgather_rows(self, rows):
        return np.concatenate(self.world.allgather(rows))

    def agree(self, message):
        """Raise the same SimulationError on every rank when any rank found one (lowest rank's)."""
        messages = self.world.allgather(message)
        first = next((m for m in messages if m), None)
        if first is not None:
            error = SimulationError(first)
            error.agreed = True
            raise error
