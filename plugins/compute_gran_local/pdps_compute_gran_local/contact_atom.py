r"""Compute ``contact/atom``: the number of particles each particle touches (LIGGGHTS's and LAMMPS's
compute contact/atom).

.. math::

    c_i = \#\{\, j \ne i : |\mathbf{x}_i - \mathbf{x}_j| < R_i + R_j \,\}

for i in the compute's group (0 for particles outside it), counting partners of any group and
periodic images; the same test as the granular pair styles' contacts. The pairs come from the pair
style's neighbor list (so a pair style is needed, and its cutoff covers every contact).

Output: per-atom values, read by dumps as ``c_ID`` and by ``compute reduce``.

Syntax::

    compute ID GROUP contact/atom

Example::

    compute c all contact/atom
    compute z all reduce ave c_c
    dump 1 all custom 100 contacts.txt id c_c
"""

import numpy as np
from numba import njit

from pdps_core.api import Compute, ScriptError, StyleArgs

COUNT = "contact_atom_count"


@njit(cache=True)
def count_contacts(x, radius, offsets, neighbors, nlocal, counts):
    """Contacts of a half list, counted on both particles (ghost rows too: the caller sums them
    onto their owners)."""
    for i in range(len(counts)):
        counts[i] = 0.0
    for i in range(nlocal):
        xi0 = x[i, 0]
        xi1 = x[i, 1]
        xi2 = x[i, 2]
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            dx = xi0 - x[j, 0]
            dy = xi1 - x[j, 1]
            dz = xi2 - x[j, 2]
            radsum = radius[i] + radius[j]
            if dx * dx + dy * dy + dz * dz < radsum * radsum:
                counts[i] += 1.0
                counts[j] += 1.0


class ComputeContactAtom(Compute):
    name = "contact/atom"
    usage = "compute ID GROUP contact/atom"
    per_atom = ((COUNT, 1),)

    class Args(StyleArgs):
        pass

    def peratom(self, sim):
        p = sim.particles
        if not p.has("radius"):
            raise ScriptError(f"compute {self.id} (contact/atom) needs particles with radii (atom_style sphere "
                              "or granular)")
        if sim.pair_list is None:
            raise ScriptError(f"compute {self.id} (contact/atom) needs a pair style (its neighbor list holds the "
                              "contacts)")
        counts = p.arrays[COUNT]
        count_contacts(p.x, p.radius, sim.pair_list.offsets, sim.pair_list.neighbors, p.nlocal, counts)
        sim.comm.reverse_comm(p, (COUNT,))
        n = p.nlocal
        selected = sim.groups.select(sim, self.group)
        return np.where(selected, counts[:n], 0.0)


class ComputeContactAtomGran(ComputeContactAtom):
    """Compute ``contact/atom/gran`` (LIGGGHTS): the contacts of each particle as its granular pair
    counts them, overlaps (LIGGGHTS adds contacts its history flags, which only bonded models set; pdps
    has none), so contact/atom's count. LIGGGHTS 3.8.0 gives the two alike (measured, 12-02: a chain
    of spheres with an overlap, a gap inside the skin and one outside)::

        compute ID GROUP contact/atom/gran
    """
    name = "contact/atom/gran"
    usage = "compute ID GROUP contact/atom/gran"
