r"""Compute ``bond/local``: one row per bond, with its length, energy or force (LAMMPS's and
LIGGGHTS's compute bond/local).

- ``dist``: the bond's length r (distance); ``dx dy dz`` its components, r_1 - r_2;
- ``eng`` (or ``engpot``): its energy under the bond style (energy);
- ``force``: r F/r = the force along the bond, positive when it pulls the two apart... as LAMMPS
  signs it: F/r times r (force); ``fx fy fz`` the force on the bond's first particle.

A bond is listed when both its particles are in the group; a broken bond (type 0) is not; a bond
turned off by delete_bonds (type < 0) is, with energy and force 0, as in LAMMPS. Rows come in no
fixed order, one per bond over all ranks, for dump local and compute reduce; with one value the
compute is a local vector, with more a local array.

Syntax::

    compute ID GROUP bond/local VALUE ...

Example::

    compute b all bond/local dist eng force
    dump d all local 100 bonds.txt index c_b[1] c_b[2] c_b[3]
"""

from typing import Literal

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, param

Value = Literal["dist", "dx", "dy", "dz", "eng", "engpot", "force", "fx", "fy", "fz"]


class ComputeBondLocal(Compute):
    name = "bond/local"
    usage = "compute ID GROUP bond/local dist|dx|dy|dz|eng|engpot|force|fx|fy|fz ..."

    class Args(StyleArgs):
        values: list[Value] = param(min_length=1, names="value")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if not sim.particles.has("num_bond"):
            raise ScriptError(f"compute {id} (bond/local) needs bonds (a particle_style with bonds, a data "
                              "file's Bonds)")

    def local(self, sim):
        p = sim.particles
        rows = sim.bonds()
        bit = np.uint32(sim.groups.bit(self.group))
        keep = ((p.mask[rows[:, 0]] & bit) != 0) & ((p.mask[rows[:, 1]] & bit) != 0)
        rows = rows[keep]
        delta = p.x[rows[:, 0]] - p.x[rows[:, 1]]
        rsq = np.einsum("ij,ij->i", delta, delta)
        fbond = np.zeros(len(rows))
        energy = np.zeros(len(rows))
        for k, (t, r2) in enumerate(zip(rows[:, 2].tolist(), rsq.tolist())):
            if t > 0:
                fbond[k], energy[k] = sim.bond_single(t, r2)
        columns = {"dist": np.sqrt(rsq), "dx": delta[:, 0], "dy": delta[:, 1], "dz": delta[:, 2],
                   "eng": energy, "engpot": energy, "force": np.sqrt(rsq) * fbond,
                   "fx": delta[:, 0] * fbond, "fy": delta[:, 1] * fbond, "fz": delta[:, 2] * fbond}
        values = np.stack([columns[name] for name in self.args.values], axis=1)
        return values[:, 0] if len(self.args.values) == 1 else values
