r"""Fix ``shardlow``: the Shardlow splitting of the DPD equations of motion (LAMMPS's fix shardlow;
T. Shardlow, SIAM J. Sci. Comput. 24, 1267 (2003); M. Lisal, J. K. Brennan & J. Bonet Avalos,
J. Chem. Phys. 135, 204105 (2011); J. P. Larentzos et al., Comput. Phys. Commun. 185, 1987 (2014)).

The DPD step is split into a stochastic part, the dissipative and random forces of every pair
integrated one pair at a time, and a deterministic part, the conservative force of ``pair_style
dpd/fdt`` integrated by ``fix nve``. This fix does the stochastic part in ``initial_integrate``,
before the velocity-Verlet half-kick of the ``fix nve`` defined after it.

For each pair of the half neighbor list closer than :math:`r_c` (owned i; j owned or ghost), with
:math:`\mathbf{r}_{ij} = \mathbf{r}_i - \mathbf{r}_j`, :math:`\hat{\mathbf{r}}_{ij} =
\mathbf{r}_{ij}/r_{ij}`, :math:`w = 1 - r_{ij}/r_c`, :math:`\mu = 1/m_i + 1/m_j`, the current
velocities are updated in place, pair after pair, by the velocity-Verlet-like split of Shardlow's S1
scheme: two half steps of :math:`\Delta t/2`, the first explicit, the second implicit, sharing one
random number :math:`\xi_{ij}`,

.. math::

    s = \tfrac12\,\sigma\, w\, \sqrt{\Delta t}\,\xi_{ij}, \qquad
    g = \tfrac12\,\gamma\, w^2 \Delta t, \qquad \sigma^2 = 2 k_B T \gamma,

    \Delta p_A = s - g\,\hat{\mathbf{r}}_{ij}\cdot(\mathbf{v}_i - \mathbf{v}_j), \qquad
    \mathbf{v}_i \mathrel{+}= \frac{\Delta p_A}{m_i}\hat{\mathbf{r}}_{ij}, \quad
    \mathbf{v}_j \mathrel{-}= \frac{\Delta p_A}{m_j}\hat{\mathbf{r}}_{ij},

    \Delta p_B = \frac{s - g\,\hat{\mathbf{r}}_{ij}\cdot(\mathbf{v}_i - \mathbf{v}_j)}{1 + \mu g},
    \qquad
    \mathbf{v}_i \mathrel{+}= \frac{\Delta p_B}{m_i}\hat{\mathbf{r}}_{ij}, \quad
    \mathbf{v}_j \mathrel{-}= \frac{\Delta p_B}{m_j}\hat{\mathbf{r}}_{ij}

(LAMMPS ``FixShardlow::ssa_update_dpd``: ``halfsigma_ij``, ``halfgamma_ij = halfsigma_ij^2/(k_B T)
= gamma/2``, ``factorA``, ``factorB``, ``inv_1p_mu_gammaFactor``). In units other than lj an
impulse becomes a velocity through the unit system's ``ftm2v``: :math:`1/m` above stands for
``ftm2v``/m, also in :math:`\mu`. Each half step changes the two
velocities by opposite impulses along :math:`\hat{\mathbf{r}}_{ij}`, so it conserves the pair's
momentum exactly; together the two are the trapezoidal rule for the radial relative velocity
:math:`u = \hat{\mathbf{r}}_{ij}\cdot\mathbf{v}_{ij}`, :math:`u' = u + \mu\,[2s - g(u + u')]`, whose
damping factor :math:`(1 - \mu g)/(1 + \mu g)` has modulus below one for any :math:`\Delta t`
(unconditionally stable), and the random impulse over the step has variance
:math:`\sigma^2 w^2 \Delta t`, as the fluctuation-dissipation theorem asks. The result depends on
the order in which pairs are visited (any order is a valid splitting); pdps's order is given
below.

Accuracy: each pair update leaves the Maxwell-Boltzmann distribution of the velocities exactly
invariant, whatever the time step (the update of u above has stationary variance
:math:`\mu k_B T`), so an ideal DPD gas (a = 0) has :math:`\langle T\rangle = T` at any dt. The
temperature error left comes from velocity Verlet on the conservative force: for the Groot-Warren
fluid (rho = 3, a = 25, gamma = 4.5) at dt = 0.08, <T>/T = 1.05 against 1.12-1.14 for
``pair_style dpd`` with ``fix nve``.

Noise: :math:`\xi_{ij}` = ``pair_gaussian(key, step, tag_i, tag_j)``, with ``key`` the pair style's
seed XOR ``0x53484152444C4F57`` ("SHARDLOW" in ASCII). A different Philox key is an independent
stream. With the pair's own seed, a Shardlow run would reuse, number for number, the random forces
``pair_style dpd`` (or dpd/fdt without this fix) draws with that seed at the same step and pair, so
two runs meant to be independent samples would share their noise. A XOR with a large constant
rather than seed + 1, because seed + 1 is the seed a user is likely to type for the next run.

Order of the sweep, the same on any number of ranks (and parallel on several): the box is cut into
a global grid of cells at least the cutoff wide, n per axis (at most 32; n even, or 1 along a periodic
axis shorter than 4 cutoffs). A pair's two particles lie in the same or neighbouring cells, so every
pair belongs to one *block* of 2 x 2 x 2 cells, the one whose lowest cell along each axis holds one
of them. Blocks are swept colour by colour (the parity of the block's cell along x, y and z: 8
colours, 4 in 2-d); two blocks of one colour share no particle, so their order does not matter, and
within a block the pairs are swept in the order of their (lower, higher) particle ids (the two
periodic images of one pair in a box shorter than two cutoffs by the component of their separation
along which they lie a box length apart, never by round-off in the others). Each rank
sweeps the blocks whose first cell's centre lies in its sub-domain: the pairs of its half list go
to the block's rank, and before each colour every particle's owner sends its velocity where that
colour's block of the particle is swept and takes the result back. (LAMMPS sweeps sub-box by
sub-box of each rank's domain, so its result depends on the decomposition.) A particle's cell is
its owner's, from its position wrapped into the box, so ghosts agree with owners to the bit. A
particle paired with its own periodic image (boxes shorter than the cutoff) is skipped: its
relative velocity and net impulse are zero. Ghost velocities are left stale: with this fix the
pair style reads none.

Only pairs with both particles in the fix's group are updated (LAMMPS ignores the group).
``pair_style dpd/fdt`` must be the pair style; a deterministic integrator (``fix nve``) must be
defined after this fix, and no thermostatting fix (nvt, npt, gle, gld) may be present, as in LAMMPS.

Syntax::

    fix ID GROUP shardlow

Example::

    pair_style dpd/fdt 1.0 1.0 3442527
    pair_coeff * * 25.0 4.5
    fix 1 all shardlow
    fix 2 all nve
"""

import math

import numpy as np

from numba import njit

from pdps_core.api import Fix, ScriptError, observables, pair_gaussian

from .dpd import EPSILON
from .dpd_fdt import PairDPDfdt

SHARDLOW_KEY = 0x53484152444C4F57


@njit(cache=True)
def pair_impulse(v, i, j, ex, ey, ez, impulse, inv_mi, inv_mj):
    v[i, 0] += ex * impulse * inv_mi
    v[i, 1] += ey * impulse * inv_mi
    v[i, 2] += ez * impulse * inv_mi
    v[j, 0] -= ex * impulse * inv_mj
    v[j, 1] -= ey * impulse * inv_mj
    v[j, 2] -= ez * impulse * inv_mj


@njit(cache=True)
def radial_relative_velocity(v, i, j, ex, ey, ez):
    return ex * (v[i, 0] - v[j, 0]) + ey * (v[i, 1] - v[j, 1]) + ez * (v[i, 2] - v[j, 2])


@njit(cache=True)
def cells_of(x, n, lo, length, ncell, periodic, out):
    """The global sweep cell (x, y, z indices) of each of the first n particles, from its position
    wrapped into the box along periodic axes (clamped to the grid along others)."""
    for i in range(n):
        for d in range(3):
            u = x[i, d] - lo[d]
            if periodic[d]:
                u -= length[d] * math.floor(u / length[d])
            out[i, d] = min(max(int(math.floor(u / length[d] * ncell[d])), 0), ncell[d] - 1)


@njit(cache=True)
def _block_axis(ca, cb, n, periodic):
    """The block's cell along one axis: the lower of two equal or neighbouring cells."""
    if n == 1 or ca == cb:
        return ca
    if cb == ca + 1 or (periodic and ca == n - 1 and cb == 0):
        return ca
    return cb


@njit(cache=True)
def collect_pairs(x, type_, tag, cell, owner, inv_mass, mask, groupbit, offsets, neighbors, nlocal, cut, ncell,
                  periodic, block_rank, me, ends, ids, separation, key, away, away_rank):
    """The pairs this rank's half list holds within the cutoff, both particles in the group, split by
    the rank sweeping their block. Those swept here, written into ``ends, ids, separation, key``
    (at least as long as the list): the ``owner`` row of each end (the lower tag's first; -1 for a
    particle owned by another rank), their tags, the separation from the higher- to the lower-tag
    particle, the sweep key (colour, then block). Those swept elsewhere: rows (lower tag, higher
    tag, separation (3), types (2), inverse masses (2), key) and their rank, into ``away,
    away_rank``. Returns (pairs here, pairs away), pairs away -1 when ``away`` is too short (the
    caller grows it and calls again: arrays replaced inside the loop would cost numba reference
    counting at every pair)."""
    nblocks = ncell[0] * ncell[1] * ncell[2]
    m = 0
    sent = 0
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        ti = type_[i]
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            # a particle's own periodic image is not a partner
            if tag[j] == tag[i] or not mask[j] & groupbit:
                continue
            delx = x[i, 0] - x[j, 0]
            dely = x[i, 1] - x[j, 1]
            delz = x[i, 2] - x[j, 2]
            rsq = delx * delx + dely * dely + delz * delz
            rc = cut[ti, type_[j]]
            if rsq >= rc * rc or rsq < EPSILON * EPSILON:
                continue
            lower, upper, sign = (i, j, 1.0) if tag[i] < tag[j] else (j, i, -1.0)
            bx = _block_axis(int(cell[lower, 0]), int(cell[upper, 0]), ncell[0], periodic[0])
            by = _block_axis(int(cell[lower, 1]), int(cell[upper, 1]), ncell[1], periodic[1])
            bz = _block_axis(int(cell[lower, 2]), int(cell[upper, 2]), ncell[2], periodic[2])
            block = bx + ncell[0] * (by + ncell[1] * bz)
            sweep_key = ((bx & 1) + 2 * (by & 1) + 4 * (bz & 1)) * nblocks + block
            rank = block_rank[block]
            if rank != me:
                if sent == len(away):
                    return m, -1
                row = away[sent]
                row[0], row[1] = tag[lower], tag[upper]
                row[2], row[3], row[4] = sign * delx, sign * dely, sign * delz
                row[5], row[6] = type_[lower], type_[upper]
                row[7], row[8] = inv_mass[lower], inv_mass[upper]
                row[9] = sweep_key
                away_rank[sent] = rank
                sent += 1
                continue
            ends[m, 0] = owner[lower]
            ends[m, 1] = owner[upper]
            ids[m, 0] = tag[lower]
            ids[m, 1] = tag[upper]
            separation[m, 0] = sign * delx
            separation[m, 1] = sign * dely
            separation[m, 2] = sign * delz
            key[m] = sweep_key
            m += 1
    return m, sent


@njit(cache=True)
def _image_after(q0, q1, q2, s0, s1, s2, apart):
    """Of two periodic images of one pair (a box shorter than two cutoffs), the one with separation
    (q0, q1, q2) comes after the one with (s0, s1, s2): by the first axis where they lie a box length
    apart (more than ``apart``). The other components are equal but for round-off, which differs
    between ranks: they must not decide."""
    if abs(q0 - s0) > apart:
        return q0 > s0
    if abs(q1 - s1) > apart:
        return q1 > s1
    return q2 > s2


@njit(cache=True)
def sweep_order(key, ends, ids, separation, nkeys, apart, sorted_ends, sorted_ids, sorted_separation, first):
    """The pairs in sweep order, written into ``sorted_ends, sorted_ids, sorted_separation``: by key
    (colour, then block: a stable counting sort, reading the pairs in memory order), then within a
    key by their ids (a block holds a few dozen pairs: insertion sort), two images of one pair by the
    component of their separation that differs by more than ``apart`` (half the shortest periodic
    box length). ``first`` (nkeys + 1) gets where each key's pairs start.

    The insertion sort moves a pair's ids and its index only (kept in ``sorted_ends[:, 0]`` until
    the pairs are put in their places at the end): three numbers, not seven."""
    m = len(key)
    first[:] = 0
    for k in range(m):
        first[key[k] + 1] += 1
    for k in range(nkeys):
        first[k + 1] += first[k]
    for k in range(m):
        slot = first[key[k]]
        first[key[k]] = slot + 1
        sorted_ends[slot, 0] = k
        sorted_ids[slot, 0], sorted_ids[slot, 1] = ids[k, 0], ids[k, 1]
    # each key's start moved to the next key's: shift back
    for k in range(nkeys, 0, -1):
        first[k] = first[k - 1]
    first[0] = 0
    for c in range(nkeys):
        lo, hi = first[c], first[c + 1]
        for p in range(lo + 1, hi):
            a0, a1, at = sorted_ids[p, 0], sorted_ids[p, 1], sorted_ends[p, 0]
            q = p - 1
            while q >= lo:
                qa, qb = sorted_ids[q, 0], sorted_ids[q, 1]
                if qa != a0:
                    after = qa > a0
                elif qb != a1:
                    after = qb > a1
                else:
                    qt = sorted_ends[q, 0]
                    after = _image_after(separation[qt, 0], separation[qt, 1], separation[qt, 2],
                                         separation[at, 0], separation[at, 1], separation[at, 2], apart)
                if not after:
                    break
                sorted_ids[q + 1, 0], sorted_ids[q + 1, 1] = qa, qb
                sorted_ends[q + 1, 0] = sorted_ends[q, 0]
                q -= 1
            sorted_ids[q + 1, 0], sorted_ids[q + 1, 1] = a0, a1
            sorted_ends[q + 1, 0] = at
    for p in range(m):
        k = sorted_ends[p, 0]
        sorted_ends[p, 0], sorted_ends[p, 1] = ends[k, 0], ends[k, 1]
        for d in range(3):
            sorted_separation[p, d] = separation[k, d]


@njit(cache=True)
def sweep_pairs(v, inv_mass, type_, ends, ids, d, lo, hi, cut, gamma, sigma, dt, key, step):
    """Shardlow's S1 update pair after pair, pairs lo to hi; v, inv_mass and type_ are indexed by
    the numbers of each pair's ends (the lower tag's first; d from the second to the first)."""
    sqrt_dt = math.sqrt(dt)
    for m in range(lo, hi):
        i, j = ends[m, 0], ends[m, 1]
        ti, tj = type_[i], type_[j]
        r = math.sqrt(d[m, 0] * d[m, 0] + d[m, 1] * d[m, 1] + d[m, 2] * d[m, 2])
        ex, ey, ez = d[m, 0] / r, d[m, 1] / r, d[m, 2] / r
        w = 1.0 - r / cut[ti, tj]
        s = 0.5 * sigma[ti, tj] * w * sqrt_dt * pair_gaussian(key, step, ids[m, 0], ids[m, 1])
        g = 0.5 * gamma[ti, tj] * w * w * dt
        inv_mi, inv_mj = inv_mass[i], inv_mass[j]
        implicit = 1.0 / (1.0 + (inv_mi + inv_mj) * g)
        explicit_half = s - g * radial_relative_velocity(v, i, j, ex, ey, ez)
        pair_impulse(v, i, j, ex, ey, ez, explicit_half, inv_mi, inv_mj)
        implicit_half = (s - g * radial_relative_velocity(v, i, j, ex, ey, ez)) * implicit
        pair_impulse(v, i, j, ex, ey, ez, implicit_half, inv_mi, inv_mj)


@njit(cache=True)
def inverse_type_masses(mass, type_, count, ftm2v, out):
    """out[i] = ftm2v / mass[type_[i]] for the first ``count`` particles."""
    for i in range(count):
        out[i] = ftm2v / mass[type_[i]]


def require_dpd_fdt(sim):
    if not isinstance(sim.pair, PairDPDfdt):
        got = "none" if sim.pair is None else sim.pair.name
        raise ScriptError(f"fix shardlow needs pair_style dpd/fdt (got pair_style {got})")


def check_fix_order(sim):
    """LAMMPS's FixShardlow::setup: no thermostat, and fix nve (or nph) defined after shardlow."""
    for fix in sim.fixes.values():
        if any(word in fix.name for word in ("nvt", "npt", "gle", "gld")):
            raise ScriptError(f"fix shardlow cannot be used with the thermostat fix {fix.id} "
                              f"({fix.name}): the DPD pair forces are the thermostat")
    shardlow_seen = False
    for fix in sim.fixes.values():
        if fix.name.startswith("shardlow"):
            shardlow_seen = True
        elif fix.name.startswith(("nve", "nph")):
            if shardlow_seen:
                return
            raise ScriptError(f"fix {fix.id} {fix.name} is defined before fix shardlow: the "
                              "deterministic integrator must follow fix shardlow in the script")
    raise ScriptError("fix shardlow needs a deterministic integrator defined after it "
                      "(e.g. fix 2 all nve)")


MAX_CELLS = 32
CELL = "shardlow_cell"        # each particle's sweep cell, its owner's, copied to ghosts


class FixShardlow(Fix):
    name = "shardlow"
    usage = "fix ID GROUP shardlow"
    per_atom = ((CELL, 3),)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        require_dpd_fdt(sim)

    def setup(self, sim):
        require_dpd_fdt(sim)
        check_fix_order(sim)

    def initial_integrate(self, sim):
        p, pair, comm = sim.particles, sim.pair, sim.comm
        n, everyone = p.nlocal, p.nlocal + p.nghost
        box = sim.box
        periodic = np.array([box.periodic[d] and d < sim.dimension for d in range(3)], dtype=np.bool_)
        ncell = np.ones(3, dtype=np.int64)
        for d in range(sim.dimension):
            # cells at least the cutoff wide, at most MAX_CELLS a side: the sweep's sort and the block
            # table grow with the blocks, and a few dozen a side leave every rank many
            count = min(int(box.length[d] // float(pair.cut.max())), MAX_CELLS)
            if periodic[d]:
                count = 1 if count < 4 else count - count % 2
            ncell[d] = max(count, 1)
        nblocks = int(np.prod(ncell))
        cell = p.arrays[CELL]
        cells_of(p.x, n, box.lo, box.length, ncell, periodic, cell)
        comm.forward_comm(p, (CELL,))
        nlist = sim.pair_list
        table = self._block_ranks(sim, ncell)
        owner = comm.owners(p)
        inv_mass = self._inverse_masses(sim, everyone)
        buffers = self._pair_buffers(nlist.offsets[n], 8 * nblocks + 1)
        ends, ids, separation, keys = buffers[:4]
        offsets, neighbors = nlist.offsets, nlist.neighbors
        while True:
            m, sent = collect_pairs(p.x, p.type, p.tag, cell, owner, inv_mass, p.mask, sim.groups.bit(self.group),
                                    offsets, neighbors, n, pair.cut, ncell, periodic, table, comm.rank, ends, ids,
                                    separation, keys, self._away, self._away_rank)
            if sent >= 0:
                break
            size = 2 * len(self._away) + 64
            self._away, self._away_rank = np.empty((size, 10)), np.empty(size, dtype=np.int64)
        ends, ids, separation, keys = ends[:m], ids[:m], separation[:m], keys[:m]
        sweep = (pair.cut, pair.gamma, pair.sigma, sim.dt, sim.random_key(pair.args.seed) ^ SHARDLOW_KEY, sim.step)
        if comm.nprocs == 1:
            self.pairs_swept = m
            sorted_ends, sorted_ids, sorted_separation, first = buffers[4:]
            sweep_order(keys, ends, ids, separation, 8 * nblocks, self._apart(sim), sorted_ends, sorted_ids,
                        sorted_separation, first)
            sweep_pairs(p.v, inv_mass, p.type, sorted_ends, sorted_ids, sorted_separation, 0, m, *sweep)
            return
        self._sweep_in_parallel(sim, m, self._away[:sent], self._away_rank[:sent], inv_mass, ncell, periodic, table,
                                sweep)

    def pre_neighbor(self, sim):
        """Owned particles moved rows at this build: their order by tag is made now (in the step
        that builds, which may allocate) rather than at the next sweep."""
        if sim.comm.nprocs > 1:
            self._owned_by_tag(sim.particles.tag, sim.particles.nlocal)

    def _pair_buffers(self, pairs, nfirst, keep=0):
        """The pair arrays of the sweep, kept between steps and grown by a quarter when too short:
        (ends, ids, separation, key) as collected (their first ``keep`` rows kept when they grow),
        their sorted copies, and the key starts."""
        kept = getattr(self, "_buffers", None)
        if kept is None or len(kept[0]) < pairs or len(kept[7]) < nfirst:
            size = max(pairs + pairs // 4 + 64, len(kept[0]) if kept is not None else 0)
            grown = (np.empty((size, 2), dtype=np.int64), np.empty((size, 2), dtype=np.int64),
                     np.empty((size, 3)), np.empty(size, dtype=np.int64),
                     np.empty((size, 2), dtype=np.int64), np.empty((size, 2), dtype=np.int64),
                     np.empty((size, 3)), np.empty(max(nfirst, len(kept[7]) if kept is not None else 0),
                                                   dtype=np.int64))
            for old, new in zip(kept[:4] if keep else (), grown):
                new[:keep] = old[:keep]
            kept = self._buffers = grown
            if getattr(self, "_away", None) is None:
                self._away, self._away_rank = np.empty((64, 10)), np.empty(64, dtype=np.int64)
        return kept[:7] + (kept[7][:nfirst],)

    def _inverse_masses(self, sim, count):
        """ftm2v/m of owned particles and ghosts, in a kept array: the velocity an impulse gives, so
        the sweep is right in every unit system (ftm2v is 1 in lj)."""
        p = sim.particles
        out = self._rows("_inv_mass", (count,), np.float64)
        if p.has("rmass"):
            np.divide(sim.units.ftm2v, p.rmass[:count], out=out)
        else:
            # not np.take: it converts the 32-bit types to a temporary of 64-bit indices
            inverse_type_masses(sim.mass, p.type, count, sim.units.ftm2v, out)
        return out

    def _sweep_in_parallel(self, sim, m_local, outgoing, rank, inv_mass, ncell, periodic, table, sweep):
        """Pairs go to the rank sweeping their block; a particle's velocity goes where each colour's
        block of it is swept and comes back to its owner after the last.

        Particles are numbered for the sweep: owned rows first, then the particles owned elsewhere
        (remote ghosts and the partners of pairs sent here), by tag. A velocity travels with its
        itinerary (the rank of each colour's block): each owner sends it to where the first colour
        sweeps it; after each colour it moves on to the next colour's rank, and after the last back
        home. Most never leave their owner."""
        p, comm = sim.particles, sim.comm
        n, me = p.nlocal, comm.rank
        nblocks = int(np.prod(ncell))
        incoming, _ = comm.send_rows(outgoing, rank, kept=True)
        m = m_local + len(incoming)
        ends, ids, separation, keys, sorted_ends, sorted_ids, sorted_separation, first = self._pair_buffers(
            m, 8 * nblocks + 1, keep=m_local)
        owned_tags, by_tag = self._owned_by_tag(p.tag, n)
        append_incoming(incoming, m_local, ends, ids, separation, keys, owned_tags, by_tag)
        remote_tags = self._remote_tags(ends, ids, m)
        number_remote(ends, ids, m, remote_tags, n)
        nremote = len(remote_tags)
        types, inverse, velocities = self._remote_rows(n + nremote)
        types[:n] = p.type[:n]
        inverse[:n] = inv_mass[:n]
        velocities[:n] = p.v[:n]
        velocities[n:] = 0.0
        remote_properties(comm.owners(p), p.tag, p.type, inv_mass, n, p.nlocal + p.nghost, incoming, ends, m_local,
                          remote_tags, types, inverse)
        self.pairs_swept = m          # this rank's share of the step's sweep
        sweep_order(keys[:m], ends, ids, separation, 8 * nblocks, self._apart(sim), sorted_ends, sorted_ids,
                    sorted_separation, first)
        route = self._rows("_route", (n, 9), np.int64)
        itineraries(p.arrays[CELL], n, ncell, periodic, table, me, route)
        visitors, held = getattr(self, "_visitors", None), 0
        if visitors is None:
            visitors = self._visitors = np.empty((64, 14))
        for c in range(9):
            out = self._rows("_leaving", (n + held, 14), np.float64)
            dest = self._rows("_leaving_rank", (n + held,), np.int64)
            sent, held = leaving_rows(route, velocities, p.tag, n, me, c, visitors, held, remote_tags, out, dest)
            arrived, _ = comm.send_rows(out[:sent], dest[:sent], kept=True)
            if len(visitors) < held + len(arrived):
                grown = np.empty((2 * (held + len(arrived)) + 64, 14))
                grown[:held] = visitors[:held]
                visitors = self._visitors = grown
            held = arrive(arrived, me, visitors, held, velocities, n, owned_tags, by_tag, remote_tags)
            if c < 8:
                sweep_pairs(velocities, inverse, types, sorted_ends, sorted_ids, sorted_separation, first[c * nblocks],
                            first[(c + 1) * nblocks], *sweep)
        p.v[:n] = velocities[:n]

    def _rows(self, name, shape, dtype):
        """A kept array of at least ``shape[0]`` rows (a quarter more when it grows), cut to it."""
        kept = getattr(self, name, None)
        if kept is None or len(kept) < shape[0]:
            kept = np.empty((shape[0] + shape[0] // 4 + 16,) + tuple(shape[1:]), dtype=dtype)
            setattr(self, name, kept)
        return kept[:shape[0]]

    def _owned_by_tag(self, tag, n):
        """(owned tags sorted, the owned row of each): kept while the owned particles are the same
        ones in the same rows (between neighbor list builds), checked at every step."""
        kept = getattr(self, "_by_tag", None)
        if kept is None or len(kept[0]) != n or not same_order(tag, kept[0], kept[1]):
            by_tag = np.argsort(tag[:n], kind="stable")
            kept = self._by_tag = (tag[:n][by_tag], by_tag)
        return kept

    def _remote_tags(self, ends, ids, m):
        """The tags, sorted and each once, of the pairs' ends owned by other ranks."""
        scratch = self._rows("_remote_scratch", (2 * m,), np.int64)
        return scratch[:distinct_remote_tags(ends, ids, m, scratch)]

    def _remote_rows(self, count):
        """Types, inverse masses and velocities of the particles numbered for the sweep."""
        return (self._rows("_sweep_types", (count,), np.int32), self._rows("_sweep_inverse", (count,), np.float64),
                self._rows("_sweep_velocities", (count, 3), np.float64))

    @staticmethod
    def _apart(sim):
        """Half the shortest periodic box length: two images of a pair differ by at least a box
        length in some component of their separation, round-off by far less."""
        box = sim.box
        lengths = [box.length[d] for d in range(sim.dimension) if box.periodic[d]]
        return 0.5 * float(min(lengths)) if lengths else math.inf

    def _block_ranks(self, sim, ncell):
        """The rank sweeping each block: the one whose sub-domain holds the centre of the block's
        first cell (kept while the box and the grid stay)."""
        box = sim.box
        state = (tuple(box.lo), tuple(box.length), tuple(ncell))
        if getattr(self, "_table_for", None) != state:
            nx, ny, nz = ncell
            index = np.arange(nx * ny * nz)
            first = np.column_stack([index % nx, (index // nx) % ny, index // (nx * ny)])
            self._table = sim.comm.rank_of(box.lo + (first + 0.5) * (box.length / ncell))
            self._table_for = state
        return self._table


@njit(cache=True)
def itineraries(cell, n, ncell, periodic, table, me, out):
    """out[i, c]: the rank sweeping the colour-c block of owned particle i (the block among the 2 x 2
    x 2 whose first cell is the particle's cell or one below, of that parity), ``me`` where the
    particle has none of that colour; out[i, 8] = me (home again)."""
    first = np.empty(3, dtype=np.int64)
    for i in range(n):
        for c in range(8):
            valid = True
            for d in range(3):
                parity = (c >> d) & 1
                k = int(cell[i, d])
                if ncell[d] == 1:
                    if parity:
                        valid = False
                    first[d] = 0
                    continue
                if k % 2 != parity:
                    k -= 1
                    if k < 0:
                        if periodic[d]:
                            k += ncell[d]
                        else:
                            valid = False
                first[d] = k
            out[i, c] = table[first[0] + ncell[0] * (first[1] + ncell[1] * first[2])] if valid else me
        out[i, 8] = me


@njit(cache=True)
def _find(sorted_values, value):
    """Where ``value`` sits in ``sorted_values``, -1 when absent."""
    slot = np.searchsorted(sorted_values, value)
    return slot if slot < len(sorted_values) and sorted_values[slot] == value else -1


@njit(cache=True)
def same_order(tag, owned_tags, by_tag):
    """Whether ``by_tag`` still sorts the owned particles' tags into ``owned_tags``."""
    for k in range(len(by_tag)):
        if tag[by_tag[k]] != owned_tags[k]:
            return False
    return True


@njit(cache=True)
def append_incoming(incoming, m_local, ends, ids, separation, keys, owned_tags, by_tag):
    """The pairs sent here (rows of collect_pairs' ``away``) after this rank's own: ids, separation,
    key, and each end's owned row (-1 for a particle owned elsewhere)."""
    for r in range(len(incoming)):
        q = m_local + r
        for c in range(2):
            tag = np.int64(incoming[r, c])
            ids[q, c] = tag
            slot = _find(owned_tags, tag)
            ends[q, c] = by_tag[slot] if slot >= 0 else -1
        for d in range(3):
            separation[q, d] = incoming[r, 2 + d]
        keys[q] = np.int64(incoming[r, 9])


@njit(cache=True)
def distinct_remote_tags(ends, ids, m, out):
    """The tags of the ends owned elsewhere (row -1) of the first m pairs, sorted and each once,
    into ``out``; returns how many."""
    k = 0
    for q in range(m):
        for c in range(2):
            if ends[q, c] < 0:
                out[k] = ids[q, c]
                k += 1
    out[:k].sort()
    distinct = 0
    for i in range(k):
        if distinct == 0 or out[i] != out[distinct - 1]:
            out[distinct] = out[i]
            distinct += 1
    return distinct


@njit(cache=True)
def number_remote(ends, ids, m, remote_tags, n):
    """The ends owned elsewhere get the numbers after the owned rows, in the order of their tags."""
    for q in range(m):
        for c in range(2):
            if ends[q, c] < 0:
                ends[q, c] = n + _find(remote_tags, ids[q, c])


@njit(cache=True)
def remote_properties(owner, tag, type_, inv_mass, n, nall, incoming, ends, m_local, remote_tags, types, inverse):
    """Type and inverse mass of each particle owned elsewhere: from its ghost here, or from the
    pairs sent here."""
    for g in range(n, nall):
        if owner[g] < 0:
            slot = _find(remote_tags, tag[g])
            if slot >= 0:
                types[n + slot] = type_[g]
                inverse[n + slot] = inv_mass[g]
    for r in range(len(incoming)):
        for c in range(2):
            number = ends[m_local + r, c]
            if number >= n:
                types[number] = np.int32(incoming[r, 5 + c])
                inverse[number] = incoming[r, 7 + c]


@njit(cache=True)
def leaving_rows(route, velocities, tag, n, me, c, visitors, held, remote_tags, out, dest):
    """Before colour c (8: home): rows (tag, velocity, owner, route) of the velocities that leave
    this rank, into ``out`` with their rank in ``dest``: owned particles here until now whose
    colour-c block another rank sweeps, and visitors (rows like these of particles owned elsewhere)
    moving on, with the velocity this rank's sweep left them. The visitors that stay are packed at
    the front. Returns (rows out, visitors held)."""
    sent = 0
    for i in range(n):
        here = c == 0 or route[i, c - 1] == me
        if here and route[i, c] != me:
            out[sent, 0] = tag[i]
            for d in range(3):
                out[sent, 1 + d] = velocities[i, d]
            out[sent, 4] = me
            for k in range(9):
                out[sent, 5 + k] = route[i, k]
            dest[sent] = route[i, c]
            sent += 1
    stay = 0
    for v in range(held):
        slot = _find(remote_tags, np.int64(visitors[v, 0]))
        if slot >= 0:
            for d in range(3):
                visitors[v, 1 + d] = velocities[n + slot, d]
        going = np.int64(visitors[v, 5 + c])
        if going != me:
            out[sent, :] = visitors[v, :]
            dest[sent] = going
            sent += 1
        else:
            visitors[stay, :] = visitors[v, :]
            stay += 1
    return sent, stay


@njit(cache=True)
def arrive(arrived, me, visitors, held, velocities, n, owned_tags, by_tag, remote_tags):
    """Velocities that came here: an owned particle's back into its row, another's kept as a
    visitor; every visitor's velocity in its place among the numbered particles. Returns the
    visitors held."""
    for r in range(len(arrived)):
        if np.int64(arrived[r, 4]) == me:
            row = by_tag[_find(owned_tags, np.int64(arrived[r, 0]))]
            for d in range(3):
                velocities[row, d] = arrived[r, 1 + d]
        else:
            visitors[held, :] = arrived[r, :]
            held += 1
    for v in range(held):
        slot = _find(remote_tags, np.int64(visitors[v, 0]))
        if slot >= 0:
            for d in range(3):
                velocities[n + slot, d] = visitors[v, 1 + d]
    return held
