r"""Compute ``coord/atom``: the coordination number of each particle, the number of neighbors within a
cutoff (LAMMPS's compute coord/atom, cutoff style).

.. math::

    c_i = \#\{\, j \ne i : |\mathbf{r}_i - \mathbf{r}_j| < r_c,\ j \in G_2,\ \mathrm{type}_j \in T \,\}

counted over every periodic image of j within :math:`r_c` (images of i itself included, as LAMMPS's
ghosts are), for i in the compute's group (0 for particles outside it). With type ranges
:math:`T_1, T_2, \ldots` the compute gives one column per range; without, one value per particle
counting all types.

The neighbors come from an occasional full list the core builds when the compute is read (no list
of its own, no skin): the pair style's cutoff does not limit :math:`r_c`, and ghosts are extended to
reach it.

Parameters:

- ``cutoff RC``: the cutoff (> 0, distance).
- ``T1 T2 ...`` (optional): type ranges, each a type or a LAMMPS range (``*``, ``2*``, ``*3``, ``1*2``).
- ``group G2`` (optional): count only neighbors in group G2 (default all).

Output: per-atom values, read by dumps as ``c_ID`` (one range or none) or ``c_ID[k]`` (range k,
from 0), and by ``compute reduce``.

Syntax::

    compute ID GROUP coord/atom cutoff RC [T1 T2 ...] [group G2]

Example::

    compute c all coord/atom cutoff 1.5 1 2
    dump 1 all custom 100 coord.txt id type c_c[0] c_c[1]
"""

from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Compute, ScriptError, StyleArgs, keyword, param, type_range


@njit(cache=True)
def count_neighbors(x, type_, mask, groupbit2, offsets, neighbors, nlocal, cutsq, lows, highs, counts):
    for i in range(nlocal):
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            if not mask[j] & groupbit2:
                continue
            dx = x[i, 0] - x[j, 0]
            dy = x[i, 1] - x[j, 1]
            dz = x[i, 2] - x[j, 2]
            if dx * dx + dy * dy + dz * dz >= cutsq:
                continue
            for m in range(len(lows)):
                if lows[m] <= type_[j] <= highs[m]:
                    counts[i, m] += 1.0


class ComputeCoordAtom(Compute):
    name = "coord/atom"
    usage = "compute ID GROUP coord/atom cutoff RC [T1 T2 ...] [group G2]"
    neighbor_lists_needed = True

    class Args(StyleArgs):
        style: Literal["cutoff"]
        cutoff: float = param(gt=0, unit="distance")
        types: list[str] = param(default_factory=list, names="type range (I, I*J, *)")
        group: str = keyword("all")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_group(args.group)
        ranges = [type_range(word, sim.ntypes) for word in args.types] or [(1, sim.ntypes)]
        self.lows = np.array([r[0] for r in ranges], dtype=np.int32)
        self.highs = np.array([r[1] for r in ranges], dtype=np.int32)
        self.nlist = None

    def init_run(self, sim):
        self.nlist = sim.request_neighbor_list("full", self.args.cutoff, occasional=True, group=self.group)

    def peratom(self, sim):
        if self.nlist is None:
            raise ScriptError(f"compute {self.id} (coord/atom) is read before any run: run 0 first")
        nlist = sim.build_neighbor_list(self.nlist)
        p = sim.particles
        counts = np.zeros((p.nlocal, len(self.lows)))
        count_neighbors(p.x, p.type, p.mask, np.uint32(sim.groups.bit(self.args.group)), nlist.offsets,
                        nlist.neighbors, p.nlocal, self.args.cutoff ** 2, self.lows, self.highs, counts)
        return counts[:, 0] if len(self.lows) == 1 else counts
