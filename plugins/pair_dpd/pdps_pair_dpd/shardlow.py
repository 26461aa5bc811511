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
= gamma/2``, ``factorA``, ``factorB``, ``inv_1p_mu_gammaFactor``). Each half step changes the two
velocities by opposite impulses along :math:`\hat{\mathbf{r}}_{ij}`, so it conserves the pair's
momentum exactly; together the two are the trapezoidal rule for the radial relative velocity
:math:`u = \hat{\mathbf{r}}_{ij}\cdot\mathbf{v}_{ij}`, :math:`u' = u + \mu\,[2s - g(u + u')]`, whose
damping factor :math:`(1 - \mu g)/(1 + \mu g)` has modulus below one for any :math:`\Delta t`
(unconditionally stable), and the random impulse over the step has variance
:math:`\sigma^2 w^2 \Delta t`, as the fluctuation-dissipation theorem asks. The result depends on
the order in which pairs are visited (any order is a valid splitting); pdps visits the half list
in storage order.

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

Order of the sweep: every pair within the cutoff, both particles in the group, is updated once per
step in one global order, sorted by the pair's two particle ids; each update reads the velocities the
previous ones left (a sequential sweep). Each rank collects the pairs of its half list, rank 0 sweeps
them all over the velocities of all particles and sends the result back, so the trajectory is the
same on any number of ranks and does not depend on how particles are stored. The sweep itself is
serial: it costs a counting sort of the pairs per step (by the lower tag, then each particle's
partners by the higher), and on several ranks a gather. (LAMMPS sweeps its SSA sub-boxes in
parallel instead; its result depends on the decomposition.) A particle paired with its own periodic
image (boxes shorter than the cutoff) is skipped: its relative velocity and net impulse are zero.
Ghost velocities are left stale: with this fix the pair style reads none.

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
def collect_pairs(x, type_, tag, number, mask, groupbit, offsets, neighbors, nlocal, cut):
    """The pairs this rank's half list holds within the cutoff, both particles in the group, as the
    ``number`` (any per-particle label, owned and ghost) of the lower-tag particle, that of the other,
    and the separation vector from the other to the lower-tag particle."""
    total = offsets[nlocal]
    a = np.empty(total, dtype=np.int64)
    b = np.empty(total, dtype=np.int64)
    d = np.empty((total, 3))
    m = 0
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
            sign = 1.0 if tag[i] < tag[j] else -1.0
            a[m] = number[i] if tag[i] < tag[j] else number[j]
            b[m] = number[j] if tag[i] < tag[j] else number[i]
            d[m, 0] = sign * delx
            d[m, 1] = sign * dely
            d[m, 2] = sign * delz
            m += 1
    return a[:m], b[:m], d[:m]


@njit(cache=True)
def sort_pairs(a, b, d, count):
    """The pairs sorted by (a, b), numbers below ``count``: a counting sort by a, then each
    particle's few partners by b. Copies, so that the sweep reads memory in order."""
    start = np.zeros(count + 1, dtype=np.int64)
    for m in range(len(a)):
        start[a[m] + 1] += 1
    for k in range(count):
        start[k + 1] += start[k]
    fill = start[:-1].copy()
    sorted_a, sorted_b, sorted_d = np.empty_like(a), np.empty_like(b), np.empty_like(d)
    for m in range(len(a)):
        slot = fill[a[m]]
        fill[a[m]] += 1
        sorted_a[slot] = a[m]
        sorted_b[slot] = b[m]
        sorted_d[slot, 0] = d[m, 0]
        sorted_d[slot, 1] = d[m, 1]
        sorted_d[slot, 2] = d[m, 2]
    for k in range(count):
        lo, hi = start[k], start[k + 1]
        if hi - lo > 1:
            by_b = np.argsort(sorted_b[lo:hi], kind="mergesort") + lo
            sorted_b[lo:hi] = sorted_b[by_b]
            sorted_d[lo:hi] = sorted_d[by_b]
    return sorted_a, sorted_b, sorted_d


@njit(cache=True)
def sweep_pairs(v, inv_mass, type_, tags, a, b, d, cut, gamma, sigma, dt, key, step):
    """Shardlow's S1 update pair after pair, in the order given; v, inv_mass, type_ and tags are
    indexed by the numbers a and b of each pair's particles (a the lower tag, d from b to a)."""
    sqrt_dt = math.sqrt(dt)
    for m in range(len(a)):
        i, j = a[m], b[m]
        ti, tj = type_[i], type_[j]
        r = math.sqrt(d[m, 0] * d[m, 0] + d[m, 1] * d[m, 1] + d[m, 2] * d[m, 2])
        ex, ey, ez = d[m, 0] / r, d[m, 1] / r, d[m, 2] / r
        w = 1.0 - r / cut[ti, tj]
        s = 0.5 * sigma[ti, tj] * w * sqrt_dt * pair_gaussian(key, step, tags[i], tags[j])
        g = 0.5 * gamma[ti, tj] * w * w * dt
        inv_mi, inv_mj = inv_mass[i], inv_mass[j]
        implicit = 1.0 / (1.0 + (inv_mi + inv_mj) * g)
        explicit_half = s - g * radial_relative_velocity(v, i, j, ex, ey, ez)
        pair_impulse(v, i, j, ex, ey, ez, explicit_half, inv_mi, inv_mj)
        implicit_half = (s - g * radial_relative_velocity(v, i, j, ex, ey, ez)) * implicit
        pair_impulse(v, i, j, ex, ey, ez, implicit_half, inv_mi, inv_mj)


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


class FixShardlow(Fix):
    name = "shardlow"
    usage = "fix ID GROUP shardlow"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        require_dpd_fdt(sim)

    def setup(self, sim):
        require_dpd_fdt(sim)
        check_fix_order(sim)

    def initial_integrate(self, sim):
        """Pairs are swept in one global order, sorted by their two tags, on rank 0 over the
        velocities of all particles: the same sequence of updates on any number of ranks (LAMMPS
        instead sweeps sub-box by sub-box in parallel, and its result depends on the decomposition)."""
        p, pair, comm = sim.particles, sim.pair, sim.comm
        nlist = sim.pair_list
        n, everyone = p.nlocal, p.nlocal + p.nghost
        key = sim.random_key(pair.args.seed) ^ SHARDLOW_KEY
        groupbit = sim.groups.bit(self.group)
        if comm.nprocs == 1:
            # one rank owns every tag: number the particles (ghosts too) by their tag's rank
            by_tag = np.argsort(p.tag[:n], kind="stable")
            tags = p.tag[by_tag]
            a, b, d = collect_pairs(p.x, p.type, p.tag, np.searchsorted(tags, p.tag[:everyone]), p.mask,
                                    groupbit, nlist.offsets, nlist.neighbors, n, pair.cut)
            velocities = p.v[by_tag]
            self._sweep(sim, tags, observables.masses(sim)[by_tag], p.type[by_tag], velocities, a, b, d,
                        key)
            p.v[by_tag] = velocities
            return
        a, b, d = collect_pairs(p.x, p.type, p.tag, p.tag, p.mask, groupbit, nlist.offsets,
                                nlist.neighbors, n, pair.cut)
        owned = np.column_stack([p.tag[:n], observables.masses(sim), p.type[:n], p.v[:n]])
        pairs = np.column_stack([a, b, d])
        owned, pairs = comm.gather_rows(owned), comm.gather_rows(pairs)
        velocities = None
        if comm.is_root:
            by_tag = np.argsort(owned[:, 0], kind="stable")
            tags = owned[by_tag, 0].astype(np.int64)
            velocities = np.ascontiguousarray(owned[by_tag, 3:6])
            self._sweep(sim, tags, owned[by_tag, 1], owned[by_tag, 2].astype(np.int64), velocities,
                        np.searchsorted(tags, pairs[:, 0].astype(np.int64)),
                        np.searchsorted(tags, pairs[:, 1].astype(np.int64)),
                        np.ascontiguousarray(pairs[:, 2:5]), key)
            velocities = (tags, velocities)
        tags, updated = comm.bcast(velocities)
        p.v[:n] = updated[np.searchsorted(tags, p.tag[:n])]

    @staticmethod
    def _sweep(sim, tags, masses, types, velocities, a, b, d, key):
        """Sweep every pair in the order of its (lower, higher) tags over ``velocities``: the
        particles' rows in the order of the sorted ``tags``, which a and b number."""
        a, b, d = sort_pairs(a, b, d, len(tags))
        sweep_pairs(velocities, 1.0 / masses, types, tags, a, b, d, sim.pair.cut, sim.pair.gamma,
                    sim.pair.sigma, sim.dt, key, sim.step)
