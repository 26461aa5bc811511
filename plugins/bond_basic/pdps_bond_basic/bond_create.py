r"""Fix ``bond/create``: particles that come close are bonded as the run goes (LAMMPS's fix
bond/create; LIGGGHTS's page is the same command).

Every ``NEVERY`` steps, after the particles moved, a particle of type ``ITYPE`` and one of type
``JTYPE``, both in the group, not bonded to each other already and closer than ``RMIN``,

.. math::  r_{ij} < R_\mathrm{min},

may be bonded by a bond of type ``BONDTYPE``. Each particle picks the closest of the partners it
may bond with; a bond is made when each of the two picked the other, so a particle gains at most
one bond a check. ``iparam MAXBOND NEWTYPE``: an ITYPE particle takes part only while it has fewer
than MAXBOND bonds of BONDTYPE (0: no limit), and becomes type NEWTYPE on reaching MAXBOND;
``jparam`` the same for JTYPE particles. The count starts, at the first run, from the bonds of
BONDTYPE the particle already has (either end), and counts the bonds this fix made; bonds deleted
later (fix bond/break, delete_bonds) are not taken off it, as in LAMMPS. ``prob FRACTION SEED``
makes an eligible bond only with probability FRACTION.

A new bond is stored on its particle of the smaller id; the special lists (1-2, 1-3, 1-4) are made
again and the neighbor lists rebuilt that same step, so special_bonds' weights apply to the new
neighbors at once (pdps accepts any of its weights 0 or 1 at each level; pairs left out of the
lists, special weight 0, are not candidates, as in LAMMPS's lists). Room for more bonds per
particle is made as needed (LAMMPS stops at its data file's extra bond per atom).

The fix's vector: [1] the bonds made at the last check, [2] all it made (in the LAMMPS dialect,
counted from 1).

Random numbers. With ``prob``, pdps draws one number per eligible pair from its counter-based
generator, keyed by SEED, the step and the two ids, so a run is the same on any number of ranks;
LAMMPS's per-rank Marsaglia stream depends on the order of its particles: the fraction agrees in
the mean, not bond by bond.

Syntax::

    fix ID GROUP bond/create NEVERY ITYPE JTYPE RMIN BONDTYPE [iparam MAXBOND NEWTYPE]
        [jparam MAXBOND NEWTYPE] [prob FRACTION SEED]

Examples::

    fix 5 all bond/create 10 1 2 0.8 1
    fix 5 all bond/create 1 3 3 0.8 1 prob 0.5 123457 iparam 2 3
"""

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, pair_uniform, param


class FixBondCreate(Fix):
    name = "bond/create"
    usage = ("fix ID GROUP bond/create NEVERY ITYPE JTYPE RMIN BONDTYPE [iparam MAXBOND NEWTYPE] "
             "[jparam MAXBOND NEWTYPE] [prob FRACTION SEED]")

    class Args(StyleArgs):
        nevery: int = param(gt=0, unit="timesteps")
        itype: int = param(ge=1, unit="1")
        jtype: int = param(ge=1, unit="1")
        rmin: float = param(ge=0, unit="distance")
        bondtype: int = param(ge=1, unit="1")
        iparam: tuple[int, int] | None = keyword(None, unit=("1", "1"))
        jparam: tuple[int, int] | None = keyword(None, unit=("1", "1"))
        prob: tuple[float, int] | None = keyword(None, unit=("1", "1"))

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        a = self.args
        p = sim.particles
        if not p.has("num_bond"):
            raise ScriptError(f"fix {id} (bond/create) needs a particle_style with bonds and room for them "
                              "(a data file's bond types, or create_box's bond/types)")
        ntypes, nbondtypes = sim.ntypes, sim.nbondtypes
        for what, value in (("itype", a.itype), ("jtype", a.jtype)):
            if value > ntypes:
                raise ScriptError(f"fix {id} (bond/create): {what} {value} is more than the {ntypes} particle types")
        if a.bondtype > nbondtypes:
            raise ScriptError(f"fix {id} (bond/create): bond type {a.bondtype} is more than the {nbondtypes} "
                              "bond types of the box")
        self.imax, self.inew = a.iparam if a.iparam is not None else (0, a.itype)
        self.jmax, self.jnew = a.jparam if a.jparam is not None else (0, a.jtype)
        for what, (most, new) in (("iparam", (self.imax, self.inew)), ("jparam", (self.jmax, self.jnew))):
            if most < 0:
                raise ScriptError(f"fix {id} (bond/create): {what}'s maxbond must be >= 0 (got {most})")
            if not 1 <= new <= ntypes:
                raise ScriptError(f"fix {id} (bond/create): {what}'s newtype {new} is not a particle type (1-{ntypes})")
        if a.itype == a.jtype and (self.imax, self.inew) != (self.jmax, self.jnew):
            raise ScriptError(f"fix {id} (bond/create): iparam and jparam differ while itype = jtype")
        self.fraction, self.seed = 1.0, 0
        if a.prob is not None:
            self.fraction, self.seed = a.prob
            if not 0.0 <= self.fraction <= 1.0:
                raise ScriptError(f"fix {id} (bond/create): prob's fraction must be from 0 to 1 (got {self.fraction:g})")
            if self.seed <= 0:
                raise ScriptError(f"fix {id} (bond/create): prob's seed must be a positive integer (got {self.seed})")
        # bonds of BONDTYPE on each particle, ghosts too (the partner's count decides as well)
        self.count_name = f"bond_create_count:{id}"
        p.request(self.count_name, 1, np.int32, 0, ghost=True)
        self.counted = False
        self.made = 0
        self.made_total = 0
        self.nlist = None

    def vector(self, sim):
        return np.array([self.made, self.made_total], dtype=float)

    def init_run(self, sim):
        cutoff = np.full((sim.ntypes + 1, sim.ntypes + 1), self.args.rmin)
        self.nlist = sim.request_neighbor_list("half", cutoff, occasional=True)

    def setup(self, sim):
        if self.counted:
            return
        # the bonds of BONDTYPE each particle has when the first run starts (LAMMPS's setup)
        self.counted = True
        p = sim.particles
        n = p.nlocal
        width = p.bond_type.shape[1]
        slots = (np.arange(width)[None, :] < p.num_bond[:n, None]) & (p.bond_type[:n] == self.args.bondtype)
        ends = np.concatenate([np.repeat(p.tag[:n], slots.sum(axis=1)), p.bond_atom[:n][slots]])
        every = sim.comm.allgather_rows(ends.astype(np.float64).reshape(-1, 1)).reshape(-1).astype(np.int64)
        tags, counts = np.unique(every, return_counts=True)
        rows = p.owned_rows(tags)
        count = p.arrays[self.count_name]
        count[:n] = 0
        count[rows[rows >= 0]] = counts[rows >= 0]

    def post_integrate(self, sim):
        step = sim.step
        if step % self.args.nevery:
            return
        p = sim.particles
        # positions moved since the ghosts were made, and ghosts need their particles' counts
        sim.comm.forward_comm(p, ("x", self.count_name))
        nlist = sim.build_neighbor_list(self.nlist)
        count = p.arrays[self.count_name]
        a = self.args
        found = _candidates(p.x, p.type, p.mask, np.uint32(sim.groups.bit(self.group)), p.tag, count,
                            p.special, p.nspecial, p.nlocal, nlist.offsets, nlist.neighbors, a.rmin ** 2,
                            a.itype, a.jtype, self.imax, self.jmax)
        every = sim.comm.allgather_rows(found).reshape(-1, 3)
        pairs = _mutual_closest(every)
        if self.fraction < 1.0 and len(pairs):
            draws = np.array([pair_uniform(self.seed, step, x, y) for x, y in pairs.tolist()])
            pairs = pairs[draws < self.fraction]
        self.made = len(pairs)
        self.made_total += self.made
        if not self.made:
            return
        sim.create_bonds(pairs, a.bondtype)
        # the count of each owned particle of a new bond, and its new type at its limit
        p = sim.particles
        count = p.arrays[self.count_name]
        ends, times = np.unique(pairs.reshape(-1), return_counts=True)
        at = p.owned_rows(ends)
        rows, times = at[at >= 0], times[at >= 0]
        count[rows] += times
        for row in rows.tolist():
            if p.type[row] == a.itype:
                if count[row] == self.imax:
                    p.type[row] = self.inew
            elif count[row] == self.jmax:
                p.type[row] = self.jnew
        self.next_reneighbor = step


@njit(cache=True)
def _candidates(x, kind, mask, bit, tag, count, special, nspecial, nlocal, offsets, neighbors, cutsq,
                itype, jtype, imax, jmax):
    """Rows (tag, tag of its closest possible partner, r^2) for every particle, owned or ghost, that
    a pair of the list may bond (LAMMPS's first pass, before the ranks merge what they found)."""
    nall = len(tag)
    best = np.full(nall, np.inf)
    partner = np.zeros(nall, dtype=np.int64)
    for i in range(nlocal):
        if not mask[i] & bit:
            continue
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            if not mask[j] & bit:
                continue
            possible = False
            if kind[i] == itype and kind[j] == jtype:
                possible = (imax == 0 or count[i] < imax) and (jmax == 0 or count[j] < jmax)
            elif kind[i] == jtype and kind[j] == itype:
                possible = (jmax == 0 or count[i] < jmax) and (imax == 0 or count[j] < imax)
            if not possible:
                continue
            bonded = False
            for s in range(nspecial[i, 0]):
                if special[i, s] == tag[j]:
                    bonded = True
            if bonded:
                continue
            dx = x[i, 0] - x[j, 0]
            dy = x[i, 1] - x[j, 1]
            dz = x[i, 2] - x[j, 2]
            rsq = dx * dx + dy * dy + dz * dz
            if rsq >= cutsq:
                continue
            if rsq < best[i]:
                best[i], partner[i] = rsq, tag[j]
            if rsq < best[j]:
                best[j], partner[j] = rsq, tag[i]
    m = 0
    for i in range(nall):
        if partner[i] != 0:
            m += 1
    out = np.empty((m, 3))
    m = 0
    for i in range(nall):
        if partner[i] != 0:
            out[m, 0], out[m, 1], out[m, 2] = tag[i], partner[i], best[i]
            m += 1
    return out


def _mutual_closest(rows):
    """The id pairs (a < b) of the rows (tag, tag, r^2) that are the closest row of both their ids."""
    closest = {}
    for a, b, rsq in rows.tolist():
        a, b = int(a), int(b)
        if rsq < closest.get(a, (0, np.inf))[1]:
            closest[a] = (b, rsq)
    pairs = sorted({(min(a, o), max(a, o)) for a, (o, _) in closest.items() if closest.get(o, (0,))[0] == a})
    return np.array(pairs, dtype=np.int64).reshape(-1, 2)
