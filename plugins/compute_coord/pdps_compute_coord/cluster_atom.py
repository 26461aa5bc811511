r"""Compute ``cluster/atom``: the cluster each particle belongs to, particles closer than a cutoff
being in one cluster (LAMMPS's and LIGGGHTS's compute cluster/atom).

Two particles of the group are linked when :math:`|\mathbf{r}_i - \mathbf{r}_j| < r_c` (every
periodic image of j counts); a cluster is a set of particles joined by links, and each particle's
value is the smallest id in its cluster (its own id when it is alone). Particles outside the
group give 0. As LAMMPS finds them: every particle starts at its own id and takes, round after
round, the smallest id among its neighbors', its ghosts brought up to date between rounds, until no
value changes on any rank.

The neighbors come from an occasional full list the core builds when the compute is read (as
compute coord/atom's): the pair style's cutoff does not limit :math:`r_c`.

Output: per-atom values, ``c_ID``, read by dumps and compute reduce.

Syntax::

    compute ID GROUP cluster/atom RC

Example::

    compute clumps all cluster/atom 0.0125
    compute biggest all reduce max c_clumps
"""

import numpy as np
from numba import njit

from pdps_core.api import Compute, ScriptError, StyleArgs, param


@njit(cache=True)
def take_smallest(ids, x, mask, groupbit, offsets, neighbors, nlocal, cutsq):
    """One round: each owned particle of the group takes the smallest id among its neighbors' within
    the cutoff; returns how many changed."""
    changed = 0
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        smallest = ids[i]
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            if not mask[j] & groupbit:
                continue
            dx = x[i, 0] - x[j, 0]
            dy = x[i, 1] - x[j, 1]
            dz = x[i, 2] - x[j, 2]
            if dx * dx + dy * dy + dz * dz < cutsq and ids[j] < smallest:
                smallest = ids[j]
        if smallest < ids[i]:
            ids[i] = smallest
            changed += 1
    return changed


class ComputeClusterAtom(Compute):
    name = "cluster/atom"
    usage = "compute ID GROUP cluster/atom RC"
    neighbor_lists_needed = True

    class Args(StyleArgs):
        cutoff: float = param(gt=0, unit="distance")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.nlist = None
        self.ids_name = f"cluster_atom_{id}"
        sim.particles.request(self.ids_name)

    def init_run(self, sim):
        self.nlist = sim.request_neighbor_list("full", self.args.cutoff, occasional=True, group=self.group)

    def peratom(self, sim):
        if self.nlist is None:
            raise ScriptError(f"compute {self.id} (cluster/atom) is read before any run: run 0 first")
        nlist = sim.build_neighbor_list(self.nlist)
        p = sim.particles
        n = p.nlocal
        groupbit = np.uint32(sim.groups.bit(self.group))
        ids = p.arrays[self.ids_name]
        in_group = (p.mask[:n] & groupbit) != 0
        ids[:n] = np.where(in_group, p.tag[:n], 0)
        cutsq = self.args.cutoff ** 2
        while True:
            sim.comm.forward_comm(p, (self.ids_name,))
            changed = take_smallest(ids, p.x, p.mask, groupbit, nlist.offsets, nlist.neighbors, n, cutsq)
            if sim.comm.max(changed) == 0:
                return ids[:n].copy()
