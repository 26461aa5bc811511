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

import math

import numpy as np
from numba import njit

from ..errors import SimulationError
from ..state.finite import first_non_finite
from .grid import Decomposition, choose_grid, rank_of_position


@njit(cache=True)
def _near_faces(x, nlocal, lo, hi, reach, two_d, near):
    """Owned particles within ``reach`` of a face of this rank's sub-domain [lo, hi) (or outside it),
    written into ``near``; returns how many. Only these can be anyone's ghost: a particle farther
    from every face is farther than ``reach`` from every other sub-domain and periodic image."""
    m = 0
    dims = 2 if two_d else 3
    for i in range(nlocal):
        for d in range(dims):
            if x[i, d] - lo[d] <= reach or hi[d] - x[i, d] <= reach:
                near[m] = i
                m += 1
                break
    return m


@njit(cache=True)
def ghost_sends(x, candidates, sublo, subhi, cutghost, length, periodic, me, two_d, ranks, index, shift):
    """(rank, particle, image shift) of every ghost this rank must send, in rank order: particle i
    (of ``candidates``), displaced by a whole number of box lengths along periodic axes, inside rank
    r's sub-domain grown by cutghost. Written into the buffers ``ranks, index, shift``; returns how
    many, or -1 when the buffers are too small."""
    capacity = len(ranks)
    k_lo = np.zeros(3, dtype=np.int64)
    k_hi = np.zeros(3, dtype=np.int64)
    m = 0
    for r in range(sublo.shape[0]):
        for c in range(len(candidates)):
            i = candidates[c]
            empty = False
            for d in range(3):
                lo = sublo[r, d] - cutghost
                hi = subhi[r, d] + cutghost
                if two_d and d == 2:
                    k_lo[d] = 0
                    k_hi[d] = 0
                elif periodic[d]:
                    # images x + k L with lo <= x + k L < hi
                    k_lo[d] = math.ceil((lo - x[i, d]) / length[d])
                    k_hi[d] = math.ceil((hi - x[i, d]) / length[d]) - 1
                    if k_lo[d] > k_hi[d]:
                        empty = True
                else:
                    k_lo[d] = 0
                    k_hi[d] = 0
                    if not (lo <= x[i, d] < hi):
                        empty = True
            if empty:
                continue
            for kx in range(k_lo[0], k_hi[0] + 1):
                for ky in range(k_lo[1], k_hi[1] + 1):
                    for kz in range(k_lo[2], k_hi[2] + 1):
                        if r == me and kx == 0 and ky == 0 and kz == 0:
                            continue
                        if m >= capacity:
                            return -1
                        ranks[m] = r
                        index[m] = i
                        shift[m, 0] = kx * length[0]
                        shift[m, 1] = ky * length[1]
                        shift[m, 2] = kz * length[2]
                        m += 1
    return m


@njit(cache=True)
def _leavers(x, nlocal, lo, length, grid, me, gone, index, dest):
    """Owned particles now in another rank's sub-domain (positions wrapped into the box): flagged in
    ``gone``, listed with their new owner in ``index, dest``; returns how many."""
    m = 0
    for i in range(nlocal):
        rank = rank_of_position(x, i, lo, length, grid)
        if rank == me:
            gone[i] = 0
        else:
            gone[i] = 1
            index[m] = i
            dest[m] = rank
            m += 1
    return m



_NO_SHIFT = np.zeros((0, 3))


@njit(cache=True)
def _pack_rows(array, index, shift, out):
    """Rows ``index`` of ``array`` into the flat buffer ``out``, plus ``shift`` (positions) if given."""
    width = array.shape[1]
    shifted = len(shift) > 0
    for k in range(len(index)):
        i = index[k]
        for d in range(width):
            out[k * width + d] = array[i, d] + (shift[k, d] if shifted else 0.0)


@njit(cache=True)
def _add_rows(array, index, rows):
    """array[index[k]] += rows[k] (ghost forces summed onto their owners)."""
    for k in range(len(index)):
        i = index[k]
        for d in range(array.shape[1]):
            array[i, d] += rows[k, d]

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
        self._send_index = np.zeros(0, dtype=np.int64)
        self._send_shift = np.zeros((0, 3))
        self._send_counts = np.zeros(self.nprocs, dtype=np.int64)
        self._recv_counts = np.zeros(self.nprocs, dtype=np.int64)
        self._self_ghost = np.zeros(0, dtype=np.int64)
        self._layouts = {}          # ghost row layouts by width, for the current ghosts
        self._owners = None
        self._send_buffer = self._recv_buffer = self._back_buffer = np.zeros(0)
        self._ghost_rows = (np.zeros(0), np.zeros(0))       # borders' send and receive rows
        self._ghost_rank = self._ghost_index = np.zeros(0, dtype=np.int64)
        self._ghost_shift = np.zeros((0, 3))
        self._near = np.zeros(0, dtype=np.int64)             # owned particles near a face
        self._gone = np.zeros(0, dtype=np.uint8)             # exchange's flags and lists
        self._leave_index = self._leave_dest = np.zeros(0, dtype=np.int64)
        self._exchange_counts = np.zeros((self.nprocs, 2), dtype=np.int64)     # (rows, error flag)
        self._exchange_received = np.zeros((self.nprocs, 2), dtype=np.int64)

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
        x = particles.x[: particles.nlocal].copy()
        image = np.zeros((len(x), 3), dtype=np.int32)
        try:
            box.wrap(x, image, particles.tag[: particles.nlocal], 0)
            message = None
        except SimulationError as exc:
            message = exc.message
        # every rank holds every new particle here (no count to sum): agree, so it is printed once
        self.agree(message)
        if particles.nlocal:
            particles.keep(self.decomposition.owner(x) == self.rank)

    # ---- migration ----------------------------------------------------------------------------
    def exchange(self, particles, box, step):
        p = particles
        p.clear_ghosts()
        if self.decomposition is None or self.decomposition.box is not box:
            self.decompose(box)
        message = None
        x = p.x
        bad = first_non_finite(x, p.nlocal)
        if bad >= 0:
            message = f"particle {int(p.tag[bad])} has a non-finite position {tuple(x[bad])} at step {step}"
        count = 0
        if bad < 0:
            try:
                gone = box.wrap(x, p.image, p.tag, step, box.lost)
                if gone.any():
                    p.keep(np.flatnonzero(~gone))
            except SimulationError as exc:
                message, count = exc.template, exc.count
        n = p.nlocal
        if len(self._gone) < n:
            size = n + n // 4 + 16
            self._gone = np.empty(size, dtype=np.uint8)
            self._leave_index, self._leave_dest = np.empty(size, dtype=np.int64), np.empty(size, dtype=np.int64)
        m = 0
        if message is None:
            m = _leavers(p.x, n, box.lo, box.length, self.decomposition.grid, self.rank, self._gone,
                         self._leave_index, self._leave_dest)
        dest = self._leave_dest[:m]
        # the counts to every rank carry this rank's error flag: one collective finds both
        counts = self._exchange_counts
        counts[:, 0] = np.bincount(dest, minlength=self.nprocs)
        counts[:, 1] = message is not None
        self.world.Alltoall(counts, self._exchange_received)
        if self._exchange_received[:, 1].any():
            self.agree(message, count)
        order = self._leave_index[:m][np.argsort(dest, kind="stable")]
        rows = p.pack(order)
        if m:
            p.remove(self._gone[:n])
        arrived = self._alltoall_rows(rows, counts[:, 0], self._exchange_received[:, 0])
        if len(arrived):
            p.append_owned(arrived)

    # ---- ghosts -------------------------------------------------------------------------------
    def borders(self, particles, box, cutghost):
        p = particles
        p.clear_ghosts()
        nlocal = p.nlocal
        m = 0
        if cutghost > 0:
            sublo, subhi = self.decomposition.all_bounds()
            periodic = np.array(box.periodic, dtype=np.bool_)
            if len(self._near) < nlocal:
                self._near = np.empty(nlocal + nlocal // 4 + 16, dtype=np.int64)
            # a margin of round-off: the test below decides, this one only skips the certain
            reach = cutghost + 1e-9 * float(np.max(box.length))
            near = self._near[:_near_faces(p.x, nlocal, sublo[self.rank], subhi[self.rank], reach,
                                           box.dimension == 2, self._near)]
            while True:
                m = ghost_sends(p.x, near, sublo, subhi, cutghost, box.length, periodic, self.rank,
                                box.dimension == 2, self._ghost_rank, self._ghost_index, self._ghost_shift)
                if m >= 0:
                    break
                size = 2 * len(self._ghost_rank) + nlocal + 64
                self._ghost_rank = np.empty(size, dtype=np.int64)
                self._ghost_index = np.empty(size, dtype=np.int64)
                self._ghost_shift = np.empty((size, 3))
        ranks, index, shift = self._ghost_rank[:m], self._ghost_index[:m], self._ghost_shift[:m]
        counts = np.bincount(ranks, minlength=self.nprocs).astype(np.int64)
        starts = np.concatenate([[0], np.cumsum(counts)])
        self._send = [(index[starts[r]:starts[r + 1]], shift[starts[r]:starts[r + 1]])
                      for r in range(self.nprocs)]
        self._send_index = index
        self._send_shift = shift
        self._send_counts = counts
        self._layouts = {}
        self._owners = None
        width = p.row_width(ghost=True)
        send, receive = self._ghost_rows
        if send.size < m * width:
            send = np.empty(int(1.25 * m * width) + 64)
        rows = p.pack(index, out=send[:m * width].reshape(m, width), ghost=True, shift=shift)
        self._recv_counts = np.empty(self.nprocs, dtype=np.int64)
        self.world.Alltoall(counts, self._recv_counts)
        total = int(self._recv_counts.sum())
        if receive.size < total * width:
            receive = np.empty(int(1.25 * total * width) + 64)
        self._ghost_rows = (send, receive)
        received = receive[:total * width].reshape(total, width)
        self._alltoallv(rows, counts * width, received, self._recv_counts * width)
        p.set_ghost_rows(received)
        # ghosts this rank sent to itself (periodic self-images), for owners()
        start = int(self._recv_counts[: self.rank].sum())
        self._self_ghost = np.full(p.nghost, -1, dtype=np.int64)
        own_index, _ = self._send[self.rank]
        self._self_ghost[start:start + len(own_index)] = own_index

    def owners(self, particles):
        """Owned index of every local particle; ghosts owned by another rank map to -1. Kept until
        the ghosts are made again."""
        if self._owners is None or len(self._owners) != particles.nlocal + len(self._self_ghost):
            self._owners = np.concatenate([np.arange(particles.nlocal, dtype=np.int64), self._self_ghost])
        return self._owners

    def _layout(self, width):
        """Send and receive counts and displacements (in values) of ghost rows of ``width`` values,
        fixed between rebuilds."""
        layout = self._layouts.get(width)
        if layout is None:
            send, recv = self._send_counts * width, self._recv_counts * width
            layout = (send, np.concatenate([[0], np.cumsum(send)[:-1]]),
                      recv, np.concatenate([[0], np.cumsum(recv)[:-1]]))
            self._layouts[width] = layout
        return layout

    def _buffers(self, width):
        """Send and receive buffers for rows of ``width`` values, kept between steps."""
        send_size = len(self._send_index) * width
        recv_size = int(self._recv_counts.sum()) * width
        if len(self._send_buffer) < send_size:
            self._send_buffer = np.empty(int(1.25 * send_size) + 64)
        if len(self._recv_buffer) < recv_size:
            self._recv_buffer = np.empty(int(1.25 * recv_size) + 64)
        return self._send_buffer[:send_size], self._recv_buffer[:recv_size]

    def forward_comm(self, particles, names=("x",)):
        p = particles
        index = self._send_index
        for name in names:
            array = p.arrays[name]
            if array.dtype != np.float64 or array.ndim != 2:
                self._forward_any(p, name)
                continue
            width = array.shape[1]
            send, recv = self._buffers(width)
            send_counts, send_displ, recv_counts, recv_displ = self._layout(width)
            _pack_rows(array, index, self._send_shift if name == "x" else _NO_SHIFT, send)
            ghosts = array[p.nlocal:]
            # the ghost rows of a row-major per-atom array are one block: received in place
            target = ghosts.reshape(-1) if ghosts.flags.c_contiguous else recv
            self.world.Alltoallv([send, (send_counts, send_displ), self.MPI.DOUBLE],
                                 [target, (recv_counts, recv_displ), self.MPI.DOUBLE])
            if target is recv:
                ghosts[...] = recv.reshape(p.nghost, width)

    def _forward_any(self, p, name):
        array = p.arrays[name]
        index = self._send_index
        width = 1 if array.ndim == 1 else array.shape[1]
        values = array[index].reshape(len(index), width).astype(np.float64)
        received = self._alltoall_rows(values, self._send_counts, self._recv_counts)
        ghost = array[p.nlocal:]
        ghost[...] = received.reshape(ghost.shape).astype(array.dtype)

    def reverse_comm(self, particles, names=("f",)):
        p = particles
        index = self._send_index
        for name in names:
            array = p.arrays[name]
            width = 1 if array.ndim == 1 else array.shape[1]
            ghosts = array[p.nlocal:].reshape(p.nghost, width)
            if array.dtype != np.float64:
                ghosts = ghosts.astype(np.float64)
            # back from every ghost to its owner: the forward layout reversed
            recv_counts, recv_displ, send_counts, send_displ = self._layout(width)
            back = self._reverse_buffer(len(index) * width)
            self.world.Alltoallv([np.ascontiguousarray(ghosts).reshape(-1), (send_counts, send_displ), self.MPI.DOUBLE],
                                 [back, (recv_counts, recv_displ), self.MPI.DOUBLE])
            _add_rows(array.reshape(len(array), width), index, back.reshape(len(index), width))

    def _reverse_buffer(self, size):
        if len(self._back_buffer) < size:
            self._back_buffer = np.empty(int(1.25 * size) + 64)
        return self._back_buffer[:size]

    def send_rows(self, rows, ranks):
        """Each row (float64) to the rank named in ``ranks``: (rows received, in the order of the
        ranks that sent them, and the rank each came from)."""
        rows = np.asarray(rows, dtype=np.float64)       # (n, width), n = len(ranks)
        order = np.argsort(ranks, kind="stable")
        counts = np.bincount(np.asarray(ranks)[order], minlength=self.nprocs)
        received, sources = self._alltoall_rows(rows[order], counts, return_counts=True)
        return received.reshape(len(received), rows.shape[1]), np.repeat(np.arange(self.nprocs), sources)

    def rank_of(self, points):
        """The rank whose sub-domain holds each point (inside the box)."""
        return self.decomposition.owner(np.asarray(points, dtype=np.float64).reshape(-1, 3))

    def reverse_rows(self, rows):
        """Rows of ghost values back to the ranks owning the ghosts: (owned indices, rows) there,
        for values a style merges itself rather than sums."""
        back = self._alltoall_rows(rows, self._recv_counts, self._send_counts)
        return self._send_index, back

    # ---- collectives --------------------------------------------------------------------------
    def _alltoall_rows(self, rows, counts, recv_counts=None, return_counts=False):
        """Rows to every rank (``counts`` per destination, in rank order); the receive counts are
        exchanged unless known (ghost lists between rebuilds)."""
        width = rows.shape[1] if rows.ndim == 2 else 1
        counts = np.asarray(counts, dtype=np.int64)
        if recv_counts is None:
            recv_counts = np.empty(self.nprocs, dtype=np.int64)
            self.world.Alltoall(counts, recv_counts)
        received = np.empty((int(recv_counts.sum()), width))
        self._alltoallv(np.ascontiguousarray(rows, dtype=np.float64), counts * width, received,
                        recv_counts * width)
        if return_counts:
            return received, recv_counts
        return received

    def _alltoallv(self, send, send_counts, receive, recv_counts):
        """Doubles to every rank: ``send_counts`` values to each, in rank order, ``recv_counts``
        from each into ``receive``."""
        send_displ = np.zeros(self.nprocs, dtype=np.int64)
        recv_displ = np.zeros(self.nprocs, dtype=np.int64)
        np.cumsum(send_counts[:-1], out=send_displ[1:])
        np.cumsum(recv_counts[:-1], out=recv_displ[1:])
        self.world.Alltoallv([send.reshape(-1), (send_counts, send_displ), self.MPI.DOUBLE],
                             [receive.reshape(-1), (recv_counts, recv_displ), self.MPI.DOUBLE])

    def sum(self, value):
        return self.world.allreduce(value, op=self.MPI.SUM)

    def max(self, value):
        return self._reduce(value, self.MPI.MAX)

    def min(self, value):
        return self._reduce(value, self.MPI.MIN)

    def _reduce(self, value, op):
        """Numbers by mpi4py's object reduction; numpy arrays element by element (its object MAX and
        MIN compare whole arrays, which raised on one rank and left the others waiting)."""
        if isinstance(value, np.ndarray):
            data = np.ascontiguousarray(value)
            out = np.empty_like(data)
            self.world.Allreduce(data, out, op=op)
            return out
        return self.world.allreduce(value, op=op)

    def gather_rows(self, rows):
        """All ranks' rows on rank 0 (None elsewhere), in rank order."""
        gathered = self.world.gather(rows, root=0)
        return np.concatenate(gathered) if self.is_root else None

    def bcast(self, value):
        """Rank 0's value on every rank."""
        return self.world.bcast(value, root=0)

    def allgather_rows(self, rows):
        return np.concatenate(self.world.allgather(rows))

    def agree(self, message, count=0):
        """Raise the same SimulationError on every rank when any rank found one (lowest rank's).
        A message with ``{count}`` in it gets ``count`` summed over ranks (particles lost)."""
        # a one-integer reduction on every step; the messages are gathered only when one exists
        flag = np.array([1 if message else 0], dtype=np.int64)
        found = np.empty(1, dtype=np.int64)
        self.world.Allreduce(flag, found, op=self.MPI.MAX)
        if not found[0]:
            return
        gathered = self.world.allgather((message, count))
        first = next((m for m, _ in gathered if m), None)
        if first is not None:
            if "{count}" in first:
                first = first.format(count=sum(c for _, c in gathered))
            error = SimulationError(first)
            error.agreed = True
            raise error
