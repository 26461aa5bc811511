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

Migration and the ghost counts are collectives (Alltoall); the ghost values themselves, at borders,
at every step and back to the owners, travel point to point between the ranks that share ghosts, so
a rank whose ghosts are all its own periodic images (or that holds nothing) waits for no one.

Errors found on one rank (a lost particle, a non-finite force) are agreed on collectively with
``agree`` so that every rank stops with the same one-line message and none hangs.
"""

import math

import numpy as np
from numba import njit

from ..errors import SimulationError
from ..state.finite import first_non_finite
from .grid import Decomposition, choose_grid, rank_of_position
from .serial import forward_to_images, reverse_from_images


@njit(cache=True)
def _near_faces(x, nlocal, lo, hi, reach, dims, near):
    """Owned particles within ``reach`` of a face of this rank's sub-domain [lo, hi) (or outside it),
    written into ``near``; returns how many. Only these can be anyone's ghost: a particle farther
    from every face is farther than ``reach`` from every other sub-domain and periodic image.
    Branch-free: every index is written, the count advances only for a near one."""
    m = 0
    for i in range(nlocal):
        inner = np.inf
        for d in range(dims):
            inner = min(inner, min(x[i, d] - lo[d], hi[d] - x[i, d]))
        near[m] = i
        m += inner <= reach
    return m


@njit(cache=True)
def _image_range(x, lo, hi, length, periodic, few):
    """(first, last) k with lo <= x + k length < hi along one axis (first > last: none). ``few``:
    the grown sub-domain is at most three box lengths wide and x is in the box, so k is -1, 0 or 1
    and comparisons decide it; otherwise (a box thinner than the ghost cutoff) by division."""
    if not periodic:
        return (0, 0) if lo <= x < hi else (1, 0)
    if few:
        first = -1 if x - length >= lo else (0 if x >= lo else 1)
        last = 1 if x + length < hi else (0 if x < hi else -1)
        return first, last
    return math.ceil((lo - x) / length), math.ceil((hi - x) / length) - 1


@njit(cache=True)
def ghost_sends(x, candidates, sublo, subhi, cutghost, length, periodic, me, two_d, few, ranks, index,
                shift, counts):
    """(rank, particle, image shift) of every ghost this rank must send, in rank order: particle i
    (of ``candidates``), displaced by a whole number of box lengths along periodic axes, inside rank
    r's sub-domain grown by cutghost. Written into the buffers ``ranks, index, shift``, with the
    count for every rank in ``counts``; returns how many, or -1 when the buffers are too small."""
    capacity = len(ranks)
    m = 0
    for r in range(sublo.shape[0]):
        counts[r] = 0
        for c in range(len(candidates)):
            i = candidates[c]
            kx0, kx1 = _image_range(x[i, 0], sublo[r, 0] - cutghost, subhi[r, 0] + cutghost, length[0],
                                    periodic[0], few[0])
            if kx0 > kx1:
                continue
            ky0, ky1 = _image_range(x[i, 1], sublo[r, 1] - cutghost, subhi[r, 1] + cutghost, length[1],
                                    periodic[1], few[1])
            if ky0 > ky1:
                continue
            kz0, kz1 = 0, 0
            if not two_d:
                kz0, kz1 = _image_range(x[i, 2], sublo[r, 2] - cutghost, subhi[r, 2] + cutghost,
                                        length[2], periodic[2], few[2])
                if kz0 > kz1:
                    continue
            for kx in range(kx0, kx1 + 1):
                for ky in range(ky0, ky1 + 1):
                    for kz in range(kz0, kz1 + 1):
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
                        counts[r] += 1
    return m


@njit(cache=True)
def _leavers(x, nlocal, lo, length, grid, me, gone, dest, counts, start, order):
    """Owned particles now in another rank's sub-domain (positions wrapped into the box): flagged in
    ``gone``, counted by new owner in ``counts`` and listed in ``order`` grouped by new owner (in
    particle order within each group); returns how many. ``dest`` (twice the particles) and
    ``start`` (one per rank) are scratch."""
    counts[:] = 0
    m = 0
    for i in range(nlocal):
        rank = rank_of_position(x, i, lo, length, grid)
        gone[i] = rank != me
        if rank != me:
            order[m] = i
            dest[m] = rank
            counts[rank] += 1
            m += 1
    # a stable counting sort of the leavers by destination, through ``dest`` as scratch
    if m:
        total = 0
        for r in range(len(counts)):
            start[r] = total
            total += counts[r]
        for k in range(m):
            rank = dest[k]
            dest[k] = start[rank]
            start[rank] += 1
        placed = dest[m:2 * m]
        for k in range(m):
            placed[dest[k]] = order[k]
        order[:m] = placed
    return m


_NO_SHIFT = np.zeros((0, 3))


def _kept(buffer, rows, width):
    """``buffer``, or a new one a quarter larger when it has fewer than ``rows`` rows or another
    width (the caller keeps what this returns and uses its first rows)."""
    if buffer.shape[0] < rows or buffer.shape[1] != width:
        buffer = np.empty((rows + rows // 4 + 16, width))
    return buffer
_GHOST_TAG = 17         # point-to-point ghost messages (forward, reverse, borders, rows to owners)
_COUNT_TAG = 18


@njit(cache=True)
def _copy_rows(array, index, shift, first, last, out, start):
    """out[start + k - first] = array[index[k]] (+ shift[k]) for k in [first, last), rows of the
    flat buffer ``out``; vectors of three have a loop of their own (a loop over a width known only
    at run time is several times slower)."""
    width = array.shape[1]
    shifted = len(shift) > 0
    for k in range(first, last):
        i = index[k]
        row = (start + k - first) * width
        if width == 3:
            out[row] = array[i, 0] + (shift[k, 0] if shifted else 0.0)
            out[row + 1] = array[i, 1] + (shift[k, 1] if shifted else 0.0)
            out[row + 2] = array[i, 2] + (shift[k, 2] if shifted else 0.0)
        else:
            for d in range(width):
                out[row + d] = array[i, d] + (shift[k, d] if shifted else 0.0)


@njit(cache=True)
def _pack_rows(array, index, shift, out, own_first, own_count, own_out):
    """Rows ``index`` of ``array`` (plus ``shift``, positions) into the flat buffer ``out``, except
    rows own_first .. own_first + own_count, this rank's images of its own particles, written
    straight into ``own_out`` (the ghost rows they become): they need no message."""
    own_last = own_first + own_count
    _copy_rows(array, index, shift, 0, own_first, out, 0)
    _copy_rows(array, index, shift, own_first, own_last, own_out, 0)
    _copy_rows(array, index, shift, own_last, len(index), out, own_last)


@njit(cache=True)
def _add_range(array, index, rows, first, last, start):
    width = array.shape[1]
    for k in range(first, last):
        i = index[k]
        row = start + k - first
        if width == 3:
            array[i, 0] += rows[row, 0]
            array[i, 1] += rows[row, 1]
            array[i, 2] += rows[row, 2]
        else:
            for d in range(width):
                array[i, d] += rows[row, d]


@njit(cache=True)
def _add_rows(array, index, rows, own_first, own_count, own_rows):
    """array[index[k]] += rows[k] (ghost forces summed onto their owners), the rows own_first ..
    own_first + own_count (this rank's own images) read from ``own_rows`` (its ghost rows): in
    the order of k throughout, so the sums are the same however the rows arrived."""
    own_last = own_first + own_count
    _add_range(array, index, rows, 0, own_first, 0)
    _add_range(array, index, own_rows, own_first, own_last, 0)
    _add_range(array, index, rows, own_last, len(index), own_last)

@njit(cache=True)
def _rows_by_rank(rows, ranks, counts, out):
    """The rows in the order of the rank each goes to (stable), into ``out``; ``counts`` per rank."""
    counts[:] = 0
    for i in range(len(ranks)):
        counts[ranks[i]] += 1
    first = 0
    for r in range(len(counts)):
        first, counts[r] = first + counts[r], first
    for i in range(len(ranks)):
        k = counts[ranks[i]]
        counts[ranks[i]] = k + 1
        for d in range(rows.shape[1]):
            out[k, d] = rows[i, d]
    # each rank's running slot ended at the next rank's start: the differences are the counts
    for r in range(len(counts) - 1, 0, -1):
        counts[r] -= counts[r - 1]


@njit(cache=True)
def _count_up(out, n):
    """out[i] = i for i < n."""
    for i in range(n):
        out[i] = i


@njit(cache=True)
def _rank_of_each(counts, out):
    """out[k]: the rank row k came from, ``counts`` rows from each rank in rank order."""
    k = 0
    for r in range(len(counts)):
        for _ in range(counts[r]):
            out[k] = r
            k += 1


class MPIComm:
    def __init__(self, world=None):
        from mpi4py import MPI
        self.MPI = MPI
        self.world = world if world is not None else MPI.COMM_WORLD
        self.rank = self.world.Get_rank()
        self.nprocs = self.world.Get_size()
        self.decomposition = None
        self.grid_request = (None, None, None)
        self._send_index = np.zeros(0, dtype=np.int64)
        self._send_shift = np.zeros((0, 3))
        self._send_counts = np.zeros(self.nprocs, dtype=np.int64)
        self._recv_counts = np.zeros(self.nprocs, dtype=np.int64)
        self._bounds = None         # borders' geometry: (its key, what _geometry gives)
        self._layouts = {}          # ghost row layouts by width, for the current ghosts
        self._owners = None
        self._owner_rows = np.zeros(0, dtype=np.int64)      # owners' buffer, kept between rebuilds
        self._send_buffer = self._recv_buffer = self._back_buffer = np.zeros(0)
        self._ghost_rows = (np.zeros(0), np.zeros(0))       # borders' send and receive rows
        self._ghost_rank = self._ghost_index = np.zeros(0, dtype=np.int64)
        self._ghost_shift = np.zeros((0, 3))
        self._near = np.zeros(0, dtype=np.int64)             # owned particles near a face
        self._gone = np.zeros(0, dtype=np.uint8)             # exchange's flags and lists
        self._leave_index = self._leave_dest = np.zeros(0, dtype=np.int64)
        self._exchange_counts = np.zeros((self.nprocs, 2), dtype=np.int64)     # (rows, error flag)
        self._exchange_received = np.zeros((self.nprocs, 2), dtype=np.int64)
        self._requests = []
        self._rows_out = self._rows_in = np.zeros((0, 0))     # reverse_rows' messages, kept
        # send_rows(..., kept=True): counts and values to and from each rank, the rows, their ranks
        self._row_counts = tuple(np.zeros(self.nprocs, dtype=np.int64) for _ in range(4))
        self._kept_rows = {}        # width: (rows sent, rows received)
        self._row_displ = (np.zeros(self.nprocs, dtype=np.int64), np.zeros(self.nprocs, dtype=np.int64))
        self._received_from = np.zeros(0, dtype=np.int64)
        self._own = (0, 0, 0)
        self._ghost_owners, self._ghost_takers = [], []
        self._shares_ghosts = False     # with any other rank (set by borders)

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
                if gone is not None:
                    p.keep(np.flatnonzero(~gone))
            except SimulationError as exc:
                message, count = exc.template, exc.count
        n = p.nlocal
        if len(self._gone) < n:
            size = n + n // 4 + 16
            self._gone = np.empty(size, dtype=np.uint8)
            self._leave_index, self._leave_dest = np.empty(size, dtype=np.int64), np.empty(2 * size, dtype=np.int64)
        # the counts to every rank carry this rank's error flag: one collective finds both
        counts = self._exchange_counts
        m = 0
        if message is None:
            m = _leavers(p.x, n, box.lo, box.length, self.decomposition.grid, self.rank, self._gone,
                         self._leave_dest, counts[:, 0], self._exchange_received[:, 0], self._leave_index)
        else:
            counts[:, 0] = 0
        counts[:, 1] = message is not None
        self.world.Alltoall(counts, self._exchange_received)
        if self._exchange_received[:, 1].any():
            self.agree(message, count)
        # remove and append run with nothing to move too: the run's setup then loads every kernel its
        # exchanges call (numba's cache, 20-40 ms) rather than the first rebuild that moves particles
        rows = p.pack(self._leave_index[:m])
        p.remove(self._gone[:n])
        arrived = self._alltoall_rows(rows, counts[:, 0], self._exchange_received[:, 0])
        p.append_owned(arrived)

    def migrate(self, particles, box):
        """Every owned particle to the rank whose sub-domain holds its position (clamped into the
        box: none is lost, LAMMPS's Irregular::migrate_atoms), between runs: a command that moved
        particles or changed the box (change_box, replicate) leaves each where it belongs, and the
        next run's setup decides what has left the box."""
        p = particles
        p.clear_ghosts()
        if self.decomposition is None or self.decomposition.box is not box:
            self.decompose(box)
        owner = self.rank_of(p.x[:p.nlocal])
        leaving = np.flatnonzero(owner != self.rank)
        received, _ = self.send_rows(p.pack(leaving), owner[leaving])
        p.keep(np.flatnonzero(owner == self.rank))
        p.append_owned(received)

    # ---- ghosts -------------------------------------------------------------------------------
    def borders(self, particles, box, cutghost):
        p = particles
        p.clear_ghosts()
        nlocal = p.nlocal
        counts = self._send_counts
        counts[:] = 0
        m = 0
        if cutghost > 0:
            # the box may change in place (barostats, fix deform, change_box): its bounds and
            # periodic axes are part of the key
            key = (self.decomposition, cutghost, box.lo.tobytes(), box.hi.tobytes(), box.periodic)
            if self._bounds is None or self._bounds[0] != key:
                self._bounds = (key,) + self._geometry(box, cutghost)
            _, sublo, subhi, periodic, few, reach = self._bounds
            if len(self._near) < nlocal:
                self._near = np.empty(nlocal + nlocal // 4 + 16, dtype=np.int64)
            dims = 2 if box.dimension == 2 else 3
            near = self._near[:_near_faces(p.x, nlocal, sublo[self.rank], subhi[self.rank], reach, dims,
                                           self._near)]
            while True:
                m = ghost_sends(p.x, near, sublo, subhi, cutghost, box.length, periodic, self.rank, dims == 2,
                                few, self._ghost_rank, self._ghost_index, self._ghost_shift, counts)
                if m >= 0:
                    break
                size = 2 * len(self._ghost_rank) + nlocal + 64
                self._ghost_rank = np.empty(size, dtype=np.int64)
                self._ghost_index = np.empty(size, dtype=np.int64)
                self._ghost_shift = np.empty((size, 3))
        index, shift = self._ghost_index[:m], self._ghost_shift[:m]
        self._send_index = index
        self._send_shift = shift
        self._layouts = {}
        self._owners = None
        width = p.row_width(ghost=True)
        send, receive = self._ghost_rows
        if send.size < m * width:
            send = np.empty(int(1.25 * m * width) + 64)
        p.pack_ghosts(index, counts, send, shift)
        self.world.Alltoall(counts, self._recv_counts)
        me = self.rank
        self._own = (int(counts[:me].sum()), int(self._recv_counts[:me].sum()), int(counts[me]))
        # the ranks this one shares ghosts with: those that sent it ghosts, those it sent ghosts to
        self._ghost_owners = [r for r in range(self.nprocs) if r != me and self._recv_counts[r]]
        self._ghost_takers = [r for r in range(self.nprocs) if r != me and counts[r]]
        self._shares_ghosts = bool(self._ghost_owners or self._ghost_takers)
        total = int(self._recv_counts.sum())
        if receive.size < total * width:
            receive = np.empty(int(1.25 * total * width) + 64)
        self._ghost_rows = (send, receive)
        send_counts, send_displ, recv_counts, recv_displ = self._layout(width)
        self._neighbour_blocks(send, send_counts, send_displ, receive, recv_counts, recv_displ)
        p.set_ghost_blocks(receive, self._recv_counts)

    def _neighbour_blocks(self, send, send_counts, send_displ, receive, recv_counts, recv_displ):
        """Blocks of doubles to and from the ranks that share ghosts with this one, as Alltoallv lays
        them out (``*_counts``, ``*_displ`` in values), point to point: a rank talks to its
        neighbours only, and not at all when it shares no ghost with another rank (a rank whose
        ghosts are all its own periodic images, an empty rank). This rank's own block is left to
        the caller, which copies it directly."""
        me = self.rank
        if self._shares_ghosts:
            requests = self._requests
            requests.clear()
            double = self.MPI.DOUBLE
            for r in range(self.nprocs):
                if r != me and recv_counts[r]:
                    first = recv_displ[r]
                    requests.append(self.world.Irecv([receive[first:first + recv_counts[r]], double], r,
                                                     _GHOST_TAG))
            for r in range(self.nprocs):
                if r != me and send_counts[r]:
                    first = send_displ[r]
                    requests.append(self.world.Isend([send[first:first + send_counts[r]], double], r,
                                                     _GHOST_TAG))
            self.MPI.Request.Waitall(requests)
        if send_counts[me]:
            first, into = send_displ[me], recv_displ[me]
            receive[into:into + send_counts[me]] = send[first:first + send_counts[me]]

    def _geometry(self, box, cutghost):
        """What borders needs of the sub-domains, fixed while the box and the ghost cutoff are: every
        rank's bounds, the periodic axes, the axes where a particle in the box has at most the images
        -1, 0, 1 within reach (the cutoff under half the box), and the reach of the face test."""
        sublo, subhi = self.decomposition.all_bounds()
        periodic = np.array(box.periodic, dtype=np.bool_)
        few = np.array([cutghost < 0.5 * length for length in box.length], dtype=np.bool_)
        # a margin of round-off: ghost_sends decides, the face test only skips the certain
        reach = cutghost + 1e-9 * float(np.max(box.length))
        return sublo, subhi, periodic, few, reach

    def owners(self, particles):
        """Owned index of every local particle; ghosts owned by another rank map to -1. Kept until
        the ghosts are made again."""
        n = particles.nlocal + int(self._recv_counts.sum())
        if self._owners is None or len(self._owners) != n:
            if len(self._owner_rows) < n:
                self._owner_rows = np.empty(n + n // 4 + 16, dtype=np.int64)
            owners = self._owner_rows[:n]
            owners[:] = -1
            _count_up(owners, particles.nlocal)
            # the ghosts this rank sent to itself (periodic self-images) arrive in its own slot
            sent = self._send_counts[: self.rank].sum()
            received = particles.nlocal + self._recv_counts[: self.rank].sum()
            own = self._send_counts[self.rank]
            owners[received:received + own] = self._send_index[sent:sent + own]
            self._owners = owners
        return self._owners

    def _layout(self, width, own=True):
        """Send and receive counts and displacements (in values) of ghost rows of ``width`` values,
        fixed between rebuilds; without this rank's images of its own particles (``own=False``),
        which forward and reverse communication copy directly."""
        layout = self._layouts.get((width, own))
        if layout is None:
            send, recv = self._send_counts * width, self._recv_counts * width
            layout = (send, np.concatenate([[0], np.cumsum(send)[:-1]]),
                      recv, np.concatenate([[0], np.cumsum(recv)[:-1]]))
            if not own:
                layout[0][self.rank] = layout[2][self.rank] = 0
            self._layouts[width, own] = layout
        return layout

    def _own_images(self):
        """(first row among those sent, first ghost row, how many) of this rank's images of its own
        particles: sent to itself, they arrive in its own slot of the ghost rows (set by borders)."""
        return self._own

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
        if not self._shares_ghosts:
            # every ghost is an image of this rank's own particles, in the order they were sent
            forward_to_images(p, names, index, self._send_shift)
            return
        for name in names:
            array = p.arrays[name]
            if array.dtype != np.float64 or array.ndim != 2:
                self._forward_any(p, name)
                continue
            width = array.shape[1]
            send, recv = self._buffers(width)
            send_counts, send_displ, recv_counts, recv_displ = self._layout(width, own=False)
            ghosts = array[p.nlocal:]
            # the ghost rows of a row-major per-atom array are one block: received in place
            target = ghosts.reshape(-1) if ghosts.flags.c_contiguous else recv
            sent_first, ghost_first, own = self._own_images()
            _pack_rows(array, index, self._send_shift if name == "x" else _NO_SHIFT, send, sent_first, own,
                       target[ghost_first * width:(ghost_first + own) * width])
            self._neighbour_blocks(send, send_counts, send_displ, target, recv_counts, recv_displ)
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
        if not self._shares_ghosts:
            reverse_from_images(p, names, index)
            return
        for name in names:
            array = p.arrays[name]
            width = 1 if array.ndim == 1 else array.shape[1]
            ghosts = array[p.nlocal:].reshape(p.nghost, width)
            if array.dtype != np.float64:
                ghosts = ghosts.astype(np.float64)
            # back from every ghost to its owner: the forward layout reversed
            recv_counts, recv_displ, send_counts, send_displ = self._layout(width, own=False)
            back = self._reverse_buffer(len(index) * width)
            ghosts = np.ascontiguousarray(ghosts)
            self._neighbour_blocks(ghosts.reshape(-1), send_counts, send_displ, back, recv_counts, recv_displ)
            sent_first, ghost_first, own = self._own_images()
            _add_rows(array.reshape(len(array), width), index, back.reshape(len(index), width), sent_first,
                      own, ghosts[ghost_first:ghost_first + own])

    def _reverse_buffer(self, size):
        if len(self._back_buffer) < size:
            self._back_buffer = np.empty(int(1.25 * size) + 64)
        return self._back_buffer[:size]

    def send_rows(self, rows, ranks, kept=False):
        """Each row (float64) to the rank named in ``ranks``: (rows received, in the order of the
        ranks that sent them, and the rank each came from). ``kept``: both live in buffers this
        communicator keeps, valid until its next ``send_rows(..., kept=True)`` (a style sending rows
        at every step allocates nothing)."""
        rows = np.asarray(rows, dtype=np.float64)       # (n, width), n = len(ranks)
        if kept:
            return self._send_kept_rows(rows, np.asarray(ranks, dtype=np.int64))
        order = np.argsort(ranks, kind="stable")
        counts = np.bincount(np.asarray(ranks)[order], minlength=self.nprocs)
        received, sources = self._alltoall_rows(rows[order], counts, return_counts=True)
        return received.reshape(len(received), rows.shape[1]), np.repeat(np.arange(self.nprocs), sources)

    def _send_kept_rows(self, rows, ranks):
        width = rows.shape[1]
        counts, recv_counts, send_values, recv_values = self._row_counts
        # buffers by width: a style may send rows of two widths at every step
        if len(ranks) and (ranks.min() < 0 or ranks.max() >= self.nprocs):
            raise ValueError(f"send_rows: ranks must lie in 0..{self.nprocs - 1} (got {ranks.min()}..{ranks.max()})")
        if width not in self._kept_rows:
            self._kept_rows[width] = (np.zeros((0, width)), np.zeros((0, width)))
        sent, received = self._kept_rows[width]
        sent = _kept(sent, len(rows), width)
        _rows_by_rank(rows, ranks, counts, sent)
        self.world.Alltoall(counts, recv_counts)
        total = int(recv_counts.sum())
        received = _kept(received, total, width)
        self._kept_rows[width] = (sent, received)
        if len(self._received_from) < total:
            self._received_from = np.empty(total + total // 4 + 16, dtype=np.int64)
        np.multiply(counts, width, out=send_values)
        np.multiply(recv_counts, width, out=recv_values)
        received = received[:total]
        self._alltoallv(sent[:len(rows)], send_values, received, recv_values, self._row_displ)
        _rank_of_each(recv_counts, self._received_from)
        return received, self._received_from[:total]

    def rank_of(self, points):
        """The rank whose sub-domain holds each point (inside the box)."""
        return self.decomposition.owner(np.asarray(points, dtype=np.float64).reshape(-1, 3))

    def reverse_rows(self, rows, ghosts=None):
        """Rows of ghost values back to the ranks owning the ghosts: (owned indices, rows) there,
        for values a style merges itself rather than sums. ``ghosts``: the rows are those of these
        ghosts only (their indices among the ghosts, ascending); by default one row a ghost. With
        ``ghosts`` the rows returned are valid until the next such call (buffers kept)."""
        if ghosts is None:
            back = self._alltoall_rows(rows, self._recv_counts, self._send_counts)
            return self._send_index, back
        if not (len(ghosts) or self._shares_ghosts):
            return self._send_index[:0], np.empty((0, rows.shape[1]))
        # ghosts arrive in blocks by the rank that sent them, each in the order of its _send_index:
        # a ghost's place in its block names the owned particle there
        ends = np.cumsum(self._recv_counts)
        source = np.searchsorted(ends, ghosts, side="right")
        counts = np.bincount(source, minlength=self.nprocs)
        # messages and what arrives go through buffers kept between calls (a granular step sends
        # back its touched ghosts' slots: tens of kB)
        self._rows_out = _kept(self._rows_out, len(ghosts), rows.shape[1] + 1)
        message = self._rows_out[:len(ghosts)]
        message[:, 0] = ghosts - (ends - self._recv_counts)[source]
        message[:, 1:] = rows
        received, senders = self._rows_to_owners(message, counts)
        first_sent = np.cumsum(self._send_counts) - self._send_counts
        place = np.repeat(first_sent, senders) + received[:, 0].astype(np.int64)
        return self._send_index[place], received[:, 1:]

    def _rows_to_owners(self, rows, counts):
        """Rows of ghost values to the ranks that own the ghosts (``counts`` per rank, in rank
        order), point to point: a rank sends to the ranks its ghosts came from and hears from those
        it sent ghosts to, a count and then the rows; one sharing no ghost with another rank sends
        and waits for nothing. Returns (rows received, in rank order; how many from each rank)."""
        me, world, MPI = self.rank, self.world, self.MPI
        owners, askers = self._ghost_owners, self._ghost_takers
        incoming = np.zeros(self.nprocs, dtype=np.int64)
        incoming[me] = counts[me]
        requests = [world.Irecv([incoming[r:r + 1], MPI.INT64_T], r, _COUNT_TAG) for r in askers]
        requests += [world.Isend([counts[r:r + 1], MPI.INT64_T], r, _COUNT_TAG) for r in owners]
        if requests:
            MPI.Request.Waitall(requests)
        total, width = int(incoming.sum()), rows.shape[1]
        self._rows_in = _kept(self._rows_in, total, width)
        received = self._rows_in[:total]
        send, recv = counts * width, incoming * width
        self._neighbour_blocks(rows.reshape(-1), send, np.cumsum(send) - send, received.reshape(-1), recv,
                               np.cumsum(recv) - recv)
        return received, incoming

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

    def _alltoallv(self, send, send_counts, receive, recv_counts, displ=None):
        """Doubles to every rank: ``send_counts`` values to each, in rank order, ``recv_counts``
        from each into ``receive``; ``displ``: two arrays of nprocs for the displacements, kept by
        the caller."""
        send_displ, recv_displ = displ if displ is not None else (np.zeros(self.nprocs, dtype=np.int64),
                                                                  np.zeros(self.nprocs, dtype=np.int64))
        send_displ[0] = recv_displ[0] = 0
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
