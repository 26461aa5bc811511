r"""Compute ``centro/atom``: the centro-symmetry parameter of each particle (LAMMPS's and
LIGGGHTS's compute centro/atom; Kelchner, Plimpton and Hamilton, Phys. Rev. B 58, 11085 (1998)).

.. math::

    P_i = \sum_{k=1}^{N/2} |\mathbf{R}_{k} + \mathbf{R}_{k'}|^2

over the N nearest neighbors of i within the pair style's largest cutoff (:math:`\mathbf{R}` from
i to each; distance^2 units): of the N(N-1)/2 pairs of them, the N/2 whose sums are smallest. 0 in
a perfect centro-symmetric lattice, larger near defects and surfaces; 0 for a particle with fewer
than N neighbors within the cutoff, and for particles outside the group.

Parameters: ``fcc`` (N = 12), ``bcc`` (N = 8) or N itself (an even number). Where neighbors at one
distance are more than the N taken, which of them are taken is the list's order here and LAMMPS's
partial sort there: the values can differ (LIGGGHTS 3.8.0's numbers recorded with every neighbor
within the cutoff taken: plugins/compute_coord/tests/data/liggghts.cases.json, case centro).

Syntax::

    compute ID GROUP centro/atom fcc|bcc|N

Example::

    compute csym all centro/atom fcc
    dump 1 all custom 100 csym.dump id x y z c_csym
"""

import math

import numpy as np
from numba import njit
from pydantic import field_validator

from pdps_core.api import Compute, ScriptError, StyleArgs, param

NEIGHBORS = {"fcc": 12, "bcc": 8}


@njit(cache=True)
def centro_symmetry(x, mask, groupbit, offsets, neighbors, nlocal, cutsq, nnn, out):
    nhalf = nnn // 2
    for i in range(nlocal):
        out[i] = 0.0
        if not mask[i] & groupbit:
            continue
        start, stop = offsets[i], offsets[i + 1]
        dist = np.empty(stop - start)
        index = np.empty(stop - start, dtype=np.int64)
        n = 0
        for k in range(start, stop):
            j = neighbors[k]
            dx = x[i, 0] - x[j, 0]
            dy = x[i, 1] - x[j, 1]
            dz = x[i, 2] - x[j, 2]
            rsq = dx * dx + dy * dy + dz * dz
            if rsq < cutsq:
                dist[n] = rsq
                index[n] = j
                n += 1
        if n < nnn:
            continue
        nearest = index[:n][np.argsort(dist[:n], kind="mergesort")[:nnn]]
        pairs = np.empty(nnn * (nnn - 1) // 2)
        m = 0
        for a in range(nnn):
            ja = nearest[a]
            for b in range(a + 1, nnn):
                jb = nearest[b]
                dx = x[ja, 0] + x[jb, 0] - 2.0 * x[i, 0]
                dy = x[ja, 1] + x[jb, 1] - 2.0 * x[i, 1]
                dz = x[ja, 2] + x[jb, 2] - 2.0 * x[i, 2]
                pairs[m] = dx * dx + dy * dy + dz * dz
                m += 1
        out[i] = np.sort(pairs)[:nhalf].sum()


class ComputeCentroAtom(Compute):
    name = "centro/atom"
    usage = "compute ID GROUP centro/atom fcc|bcc|N"
    neighbor_lists_needed = True

    class Args(StyleArgs):
        lattice: str = param(names="fcc, bcc or N")

        @field_validator("lattice")
        @classmethod
        def _neighbors(cls, word):
            if word in NEIGHBORS:
                return word
            if not word.isdigit() or int(word) < 2 or int(word) % 2:
                raise ValueError(f"must be fcc, bcc or an even number of neighbors (got {word})")
            return word

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.nnn = NEIGHBORS.get(args.lattice) or int(args.lattice)
        self.nlist = None

    def init_run(self, sim):
        if sim.pair is None:
            raise ScriptError(f"compute {self.id} (centro/atom) needs a pair style: its neighbors are those "
                              "within the pair cutoff")
        self.cutoff = math.sqrt(float(np.max(sim.pair.cutsq)))
        self.nlist = sim.request_neighbor_list("full", self.cutoff, occasional=True, group=self.group)

    def peratom(self, sim):
        if self.nlist is None:
            raise ScriptError(f"compute {self.id} (centro/atom) is read before any run: run 0 first")
        nlist = sim.build_neighbor_list(self.nlist)
        p = sim.particles
        out = np.zeros(p.nlocal)
        centro_symmetry(p.x, p.mask, np.uint32(sim.groups.bit(self.group)), nlist.offsets, nlist.neighbors, p.nlocal,
                        self.cutoff ** 2, self.nnn, out)
        return out
