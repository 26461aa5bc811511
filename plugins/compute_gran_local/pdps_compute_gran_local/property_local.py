r"""Compute ``property/local``: one row per pair of particles of the group near each other, with
the IDs and types of the two (LAMMPS's and LIGGGHTS's compute property/local, its pair part).

- ``natom1 natom2 ntype1 ntype2``: the pairs the neighbor list holds: those that were within
  :math:`r_{c,ij} + s` (the pair style's cutoff of the two types plus the skin ``neighbor SKIN``)
  when the lists were last built, wherever they are now (LIGGGHTS 3.8.0 reads its pair list so);
- ``patom1 patom2 ptype1 ptype2``: the pairs within the pair style's cutoff, :math:`r_{ij} <
  r_{c,ij}`.

``*atom1``/``*atom2`` are the two particles' IDs, ``*type1``/``*type2`` their types; the two kinds
cannot be mixed in one compute. Each pair is one row over all ranks (a periodic image's pair too),
built from the positions of the moment the compute is read, in no fixed order; for dump local and
compute reduce. With one value the compute is a local vector, with more a local array (``c_ID[k]``).
The bond, angle, dihedral and improper values (``batom1`` ... ``itype``) are refused: pdps has no
bonds. Differences: LIGGGHTS 3.8.0 and LAMMPS need a pair style with a ``single`` function (not
pair gran); pdps takes any pair style's cutoffs. With ``newton off`` LIGGGHTS 3.8.0 leaves out the
pairs with a particle of another rank or a periodic image (its source); pdps counts them.

Syntax::

    compute ID GROUP property/local VALUE ...

Example::

    compute pairs all property/local patom1 patom2 ptype1 ptype2
    dump d all local 100 pairs.txt c_pairs[1] c_pairs[2]
"""

from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Compute, ScriptError, StyleArgs, param

NEIGHBOR_WORDS = ("natom1", "natom2", "ntype1", "ntype2")
PAIR_WORDS = ("patom1", "patom2", "ptype1", "ptype2")
BONDED_WORDS = ("batom1", "batom2", "btype", "aatom1", "aatom2", "aatom3", "atype", "datom1", "datom2",
                "datom3", "datom4", "dtype", "iatom1", "iatom2", "iatom3", "iatom4", "itype")
Value = Literal["natom1", "natom2", "ntype1", "ntype2", "patom1", "patom2", "ptype1", "ptype2",
                "batom1", "batom2", "btype", "aatom1", "aatom2", "aatom3", "atype", "datom1", "datom2",
                "datom3", "datom4", "dtype", "iatom1", "iatom2", "iatom3", "iatom4", "itype"]


@njit(cache=True)
def near_pairs(x, type_, mask, groupbit, offsets, neighbors, nlocal, limit_sq, rows):
    """The (i, j) rows of the half list's pairs of the group closer than limit_sq of their types;
    returns how many (rows is grown by the caller when it is their length)."""
    n = 0
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            if not mask[j] & groupbit:
                continue
            d0 = x[i, 0] - x[j, 0]
            d1 = x[i, 1] - x[j, 1]
            d2 = x[i, 2] - x[j, 2]
            if d0 * d0 + d1 * d1 + d2 * d2 >= limit_sq[type_[i], type_[j]]:
                continue
            if n < len(rows):
                rows[n, 0] = i
                rows[n, 1] = j
            n += 1
    return n


class ComputePropertyLocal(Compute):
    name = "property/local"
    usage = "compute ID GROUP property/local natom1|natom2|ntype1|ntype2|patom1|patom2|ptype1|ptype2 ..."

    class Args(StyleArgs):
        values: list[Value] = param(min_length=1, names="value")

    @classmethod
    def check_args(cls, args):
        bonded = next((word for word in args.values if word in BONDED_WORDS), None)
        if bonded is not None:
            raise ScriptError(f"{bonded}: pdps has no bonds, angles, dihedrals or impropers; "
                              f"the pair values are {' '.join(NEIGHBOR_WORDS + PAIR_WORDS)}")
        kinds = {word in PAIR_WORDS for word in args.values}
        if len(kinds) > 1:
            raise ScriptError("the neighbor values (natom1 ... ntype2) and the pair values (patom1 ... ptype2) "
                              "cannot be used together (LAMMPS's rule)")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.within_pair = args.values[0] in PAIR_WORDS
        self.nlist = None
        self.rows = np.zeros((64, 2), dtype=np.int64)
        if not self.within_pair:
            # each particle's move since the lists were built, carried to its ghosts
            self.moved_name = f"property_local_{id}_moved"
            sim.particles.request(self.moved_name, width=3)

    def init_run(self, sim):
        if sim.pair is None:
            raise ScriptError(f"compute {self.id} (property/local) needs a pair style: its pairs are those within "
                              "the pair cutoff (or the neighbor list's)")
        cutoff = np.sqrt(np.asarray(sim.pair.cutsq, dtype=np.float64))
        reach = cutoff if self.within_pair else cutoff + sim.neighbor.skin
        self.limit_sq = np.ascontiguousarray(reach * reach)
        # a pair listed at the build may since have parted by up to twice half the skin
        listed = reach if self.within_pair else reach + sim.neighbor.skin
        self.nlist = sim.request_neighbor_list("half", listed, occasional=True, group=self.group)

    def local(self, sim):
        if self.nlist is None:
            raise ScriptError(f"compute {self.id} (property/local) is read before any run: run 0 first")
        nlist = sim.build_neighbor_list(self.nlist)
        p = sim.particles
        x = p.x
        if not self.within_pair:
            moved = p.arrays[self.moved_name]
            hold = sim.neighbor.xhold
            moved[: p.nlocal] = p.x[: p.nlocal] - hold if (hold is not None and len(hold) == p.nlocal) else 0.0
            sim.comm.forward_comm(p, (self.moved_name,))
            x = p.x - moved
        args = (x, p.type, p.mask, np.uint32(sim.groups.bit(self.group)), nlist.offsets, nlist.neighbors,
                p.nlocal, self.limit_sq)
        n = near_pairs(*args, self.rows)
        if n > len(self.rows):
            self.rows = np.zeros((n + n // 4, 2), dtype=np.int64)
            near_pairs(*args, self.rows)
        i, j = self.rows[:n, 0], self.rows[:n, 1]
        columns = []
        for word in self.args.values:
            second = word.endswith("2")
            rows = j if second else i
            columns.append((p.tag if "atom" in word else p.type)[rows].astype(np.float64))
        return columns[0] if len(columns) == 1 else np.column_stack(columns)
