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

- ``cutoff RC``: the cutoff (> 0, distance); LIGGGHTS writes ``RC`` alone.
- ``T1 T2 ...`` (optional): type ranges, each a type or a LAMMPS range (``*``, ``2*``, ``*3``, ``1*2``).
- ``mix yes|no`` (optional, LIGGGHTS, instead of type ranges): with ``yes`` count only neighbors of
  the particle's own type (default no).
- ``group G2`` (optional): count only neighbors in group G2 (default all).

Output: per-atom values, read by dumps as ``c_ID`` (one range or none) or ``c_ID[k]`` (range k,
from 0), and by ``compute reduce``.

Syntax::

    compute ID GROUP coord/atom [cutoff] RC [T1 T2 ...] [mix yes|no] [group G2]

Example::

    compute c all coord/atom cutoff 1.5 1 2
    compute same all coord/atom 0.0125 mix yes
    dump 1 all custom 100 coord.txt id type c_c[0] c_c[1]
"""

from typing import Literal

import numpy as np
from numba import njit
from pydantic import model_validator

from pdps_core.api import Compute, ScriptError, StyleArgs, keyword, param, type_range


@njit(cache=True)
def count_neighbors(x, type_, mask, groupbit2, offsets, neighbors, nlocal, cutsq, lows, highs, same_type, counts):
    for i in range(nlocal):
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            if not mask[j] & groupbit2 or (same_type and type_[j] != type_[i]):
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
    usage = "compute ID GROUP coord/atom [cutoff] RC [T1 T2 ...] [mix yes|no] [group G2]"
    neighbor_lists_needed = True

    class Args(StyleArgs):
        style: Literal["cutoff"] | None = param(None)        # LIGGGHTS leaves the word out
        cutoff: float = param(gt=0, unit="distance")
        types: list[str] = param(default_factory=list, names="type range (I, I*J, *)")
        mix: Literal["yes", "no"] = keyword("no")
        group: str = keyword("all")

        @model_validator(mode="after")
        def _mix_or_ranges(self):
            if self.mix == "yes" and self.types:
                raise ValueError("mix yes counts neighbors of the particle's own type: give it without type ranges")
            return self

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
                        nlist.neighbors, p.nlocal, self.args.cutoff ** 2, self.lows, self.highs, self.args.mix == "yes",
                        counts)
        return counts[:, 0] if len(self.lows) == 1 else counts
