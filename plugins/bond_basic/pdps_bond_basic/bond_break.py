r"""Fix ``bond/break``: bonds stretched past a length are deleted as the run goes (LAMMPS's fix
bond/break; LIGGGHTS's page is the same command).

Every ``NEVERY`` steps, after the particles moved, a bond of type ``BONDTYPE`` whose two particles
are both in the group and farther apart than ``RMAX``,

.. math::  r_{ij} > R_\mathrm{max},

may break. Each particle picks the longest of its bonds that may break; a bond breaks when each
of its two particles picked it, so a particle loses at most one bond a check. With ``prob
FRACTION SEED`` such a bond breaks only with probability FRACTION. A broken bond is deleted, the
special lists (1-2, 1-3, 1-4) are made again and the neighbor lists are rebuilt that same step,
so the pair then interacts as any other pair does (within special_bonds' weights).

The fix's vector: [1] the bonds broken at the last check, [2] all it broke (in the LAMMPS
dialect, counted from 1).

Random numbers. With ``prob``, pdps draws one number per eligible bond from its counter-based
generator, keyed by SEED, the step and the two ids, so a run breaks the same bonds on any number of
ranks; LAMMPS draws from a Marsaglia generator per rank, so its choice depends on the order of
its particles. The fraction broken agrees in the mean, not bond by bond (tested statistically).

Syntax::

    fix ID GROUP bond/break NEVERY BONDTYPE RMAX [prob FRACTION SEED]

Examples::

    fix 5 all bond/break 10 2 1.2
    fix 5 polymer bond/break 1 1 2.0 prob 0.5 123457
"""

import numpy as np

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, pair_uniform, param


class FixBondBreak(Fix):
    name = "bond/break"
    usage = "fix ID GROUP bond/break NEVERY BONDTYPE RMAX [prob FRACTION SEED]"

    class Args(StyleArgs):
        nevery: int = param(gt=0, unit="timesteps")
        bondtype: int = param(ge=1, unit="1")
        rmax: float = param(ge=0, unit="distance")
        prob: tuple[float, int] | None = keyword(None, unit=("1", "1"))

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        p = sim.particles
        if not p.has("num_bond"):
            raise ScriptError(f"fix {id} (bond/break) needs bonds (a particle_style with bonds, a data file's Bonds)")
        ntypes = sim.nbondtypes
        if self.args.bondtype > ntypes:
            raise ScriptError(f"fix {id} (bond/break): bond type {self.args.bondtype} is more than the {ntypes} "
                              "bond types of the box")
        self.fraction, self.seed = 1.0, 0
        if self.args.prob is not None:
            self.fraction, self.seed = self.args.prob
            if not 0.0 <= self.fraction <= 1.0:
                raise ScriptError(f"fix {id} (bond/break): prob's fraction must be from 0 to 1 (got {self.fraction:g})")
            if self.seed <= 0:
                raise ScriptError(f"fix {id} (bond/break): prob's seed must be a positive integer (got {self.seed})")
        self.broken = 0
        self.broken_total = 0

    def vector(self, sim):
        return np.array([self.broken, self.broken_total], dtype=float)

    def post_integrate(self, sim):
        step = sim.step
        if step % self.args.nevery:
            return
        p = sim.particles
        # positions moved since the ghosts were made (LAMMPS's forward_comm in its post_integrate)
        sim.comm.forward_comm(p, ("x",))
        rows = sim.bonds()
        rows = rows[rows[:, 2] == self.args.bondtype]
        bit = np.uint32(sim.groups.bit(self.group))
        rows = rows[((p.mask[rows[:, 0]] & bit) != 0) & ((p.mask[rows[:, 1]] & bit) != 0)]
        delta = p.x[rows[:, 0]] - p.x[rows[:, 1]]
        rsq = np.einsum("ij,ij->i", delta, delta)
        stretched = rsq > self.args.rmax ** 2
        candidates = np.column_stack([p.tag[rows[stretched, 0]], p.tag[rows[stretched, 1]],
                                      rsq[stretched]]).astype(np.float64)
        every = sim.comm.allgather_rows(candidates).reshape(-1, 3)
        pairs = _mutual_longest(every)
        if self.fraction < 1.0 and len(pairs):
            draws = np.array([pair_uniform(self.seed, step, a, b) for a, b in pairs.tolist()])
            pairs = pairs[draws < self.fraction]
        self.broken = len(pairs)
        self.broken_total += self.broken
        if self.broken:
            sim.break_bonds(pairs)
            self.next_reneighbor = step


def _mutual_longest(rows):
    """The id pairs (a < b) of the rows (tag, tag, r^2) that are the longest row of both their ids."""
    longest = {}
    for a, b, rsq in rows.tolist():
        a, b = int(a), int(b)
        for me, other in ((a, b), (b, a)):
            if rsq > longest.get(me, (0, 0.0))[1]:
                longest[me] = (other, rsq)
    pairs = sorted({(min(a, o), max(a, o)) for a, (o, _) in longest.items() if longest[o][0] == a})
    return np.array(pairs, dtype=np.int64).reshape(-1, 2)
