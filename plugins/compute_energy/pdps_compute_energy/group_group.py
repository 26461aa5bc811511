r"""Compute ``group/group``: the pair energy between two groups and the force of the second on the
first (LAMMPS's ``compute group/group``, its pair part).

.. math::

    E_{AB} = \sum_{(i, j)} E_{ij}(r_{ij}), \qquad
    \mathbf{F}_{AB} = \sum_{(i, j)} \pm\, f_{ij}\, \mathbf{r}_{ij}

over every pair (i, j) within the pair style's cutoff with one particle in group A (the compute's
group) and the other in group B (``GROUP2``), each pair once; :math:`f_{ij} = F/r` and
:math:`E_{ij}` are the pair style's own, from ``Pair.single`` (for dpd its conservative part, as
LAMMPS), and :math:`\mathbf{r}_{ij} = \mathbf{r}_i - \mathbf{r}_j`, the sign + where i is in A and j
in B, - where i is in B and j in A. A pair with both particles in both groups counts once, as A-B.

Syntax::

    compute ID GROUP group/group GROUP2 [pair yes] [kspace no] [boundary yes|no] [molecule off]

- ``GROUP2``: the other group (a group ID).
- ``c_ID``: :math:`E_{AB}` (energy); ``c_ID[1]``, ``c_ID[2]``, ``c_ID[3]`` (LAMMPS dialect; [0]..[2]
  in PDPS's): :math:`\mathbf{F}_{AB}` (force). Both are totals over particles (extensive): thermo
  divides them by N under ``thermo_modify norm yes`` (lj units' default), as LAMMPS.
- The keywords are LAMMPS's; pdps has no long-range solver and no molecule filter, so only their
  defaults are taken (``kspace no``, ``molecule off``; ``boundary`` matters to kspace only).

Example (tests/test_group_group.py has it beside LAMMPS)::

    group lower region low
    group upper subtract all lower
    compute between lower group/group upper
    thermo_style custom step pe c_between c_between[3]
"""

from typing import Literal

import numpy as np
from pdps_core.api import Compute, ScriptError, StyleArgs, keyword, param


class ComputeGroupGroup(Compute):
    name = "group/group"
    usage = "compute ID GROUP group/group GROUP2 [pair yes] [kspace no] [boundary yes|no] [molecule off]"
    extensive = True                    # E and F are totals over particles

    class Args(StyleArgs):
        group2: str = param()
        pair: Literal["yes"] = keyword("yes")
        kspace: Literal["no"] = keyword("no")
        boundary: Literal["yes", "no"] = keyword("yes")
        molecule: Literal["off"] = keyword("off")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_group(args.group2)
        self.nlist = None
        self.values = np.zeros(4)       # E, Fx, Fy, Fz
        self.step = None                # the step the values belong to

    def init_run(self, sim):
        if sim.pair is None:
            raise ScriptError(f"compute {self.id} (group/group) needs a pair style")
        # its own list, built when read: the pair style's may be in cell mode, or hold a skin's pairs
        self.nlist = sim.request_neighbor_list("half", np.sqrt(sim.pair.cutsq), occasional=True)
        self.step = None

    def _tally(self, sim):
        if self.step == sim.step:
            return self.values
        if self.nlist is None:
            raise ScriptError(f"compute {self.id} (group/group) is read before a run: run 0 first")
        nlist = sim.build_neighbor_list(self.nlist)
        p = sim.particles
        i = np.repeat(np.arange(p.nlocal), np.diff(nlist.offsets))     # each pair once
        j = nlist.neighbors[: len(i)].astype(np.int64)
        in_a = (p.mask & sim.groups.bit(self.group)) != 0
        in_b = (p.mask & sim.groups.bit(self.args.group2)) != 0
        a_b = in_a[i] & in_b[j]
        b_a = ~a_b & in_b[i] & in_a[j]
        chosen = a_b | b_a
        i, j, sign = i[chosen], j[chosen], np.where(a_b[chosen], 1.0, -1.0)
        delta = p.x[i] - p.x[j]
        fpair, energy = sim.pair.single(sim, i, j, delta)
        force = ((sign * fpair)[:, None] * delta).sum(axis=0)          # on A, from B
        self.values = sim.comm.sum(np.array([energy.sum(), *force]))
        self.step = sim.step
        return self.values

    def scalar(self, sim):
        return float(self._tally(sim)[0])

    def vector(self, sim):
        return self._tally(sim)[1:]
