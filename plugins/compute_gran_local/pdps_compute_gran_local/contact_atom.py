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

from pdps_core.api import Compute, ScriptError, StyleArgs, keyword

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

    def require_contacts(self, sim):
        """Radii and a pair style's list, which the counts read."""
        if not sim.particles.has("radius"):
            raise ScriptError(f"compute {self.id} ({self.name}) needs particles with radii (atom_style sphere "
                              "or granular)")
        if sim.pair_list is None:
            raise ScriptError(f"compute {self.id} ({self.name}) needs a pair style (its neighbor list holds the "
                              "contacts)")

    def peratom(self, sim):
        p = sim.particles
        self.require_contacts(sim)
        counts = p.arrays[COUNT]
        count_contacts(p.x, p.radius, sim.pair_list.offsets, sim.pair_list.neighbors, p.nlocal, counts)
        sim.comm.reverse_comm(p, (COUNT,))
        n = p.nlocal
        selected = sim.groups.select(sim, self.group)
        return np.where(selected, counts[:n], 0.0)


@njit(cache=True)
def count_gran_contacts(x, radius, tag, mask, groupbit, offsets, neighbors, nlocal, skin, partner, counts):
    """LIGGGHTS's contact/atom/gran: a pair of the half list whose first particle is in the group
    counts on both when the gap is at most ``skin`` or the pair holds a contact history (partner:
    the tags each particle keeps a history with; empty without one)."""
    for i in range(len(counts)):
        counts[i] = 0.0
    history = partner.shape[0] > 0
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            dx = x[i, 0] - x[j, 0]
            dy = x[i, 1] - x[j, 1]
            dz = x[i, 2] - x[j, 2]
            reach = radius[i] + radius[j] + skin
            touching = dx * dx + dy * dy + dz * dz <= reach * reach
            if not touching and history:
                for s in range(partner.shape[1]):
                    if partner[i, s] == tag[j]:
                        touching = True
                        break
            if touching:
                counts[i] += 1.0
                counts[j] += 1.0


NO_PARTNERS = np.zeros((0, 1), dtype=np.int64)


class ComputeContactAtomGran(ComputeContactAtom):
    """Compute ``contact/atom/gran`` (LIGGGHTS 3.8.0's): for each particle, the pairs of the granular
    pair style's list that touch, within ``skin`` (a distance, default 0), or that hold a contact
    history (with ``tangential history``: a pair that touched since the list was last built keeps
    it until then, as LIGGGHTS's touch flags), counted on both particles of each pair whose first
    particle (in the list) is in the group, every particle's count given (LIGGGHTS's: use group
    all for counts that do not depend on the list's order). Recorded with LIGGGHTS 3.8.0 (case
    contacts_gran, plugins/compute_gran_local/tests/data/liggghts.cases.json)::

        compute ID GROUP contact/atom/gran [skin S]
    """
    name = "contact/atom/gran"
    usage = "compute ID GROUP contact/atom/gran [skin S]"

    class Args(StyleArgs):
        skin: float = keyword(0.0, unit="distance")

    def peratom(self, sim):
        p = sim.particles
        self.require_contacts(sim)
        partners = getattr(sim.pair, "history_partners", None)
        partner = partners() if partners is not None else None
        counts = p.arrays[COUNT]
        count_gran_contacts(p.x, p.radius, p.tag, p.mask, np.uint32(sim.groups.bit(self.group)),
                            sim.pair_list.offsets, sim.pair_list.neighbors, p.nlocal, self.args.skin,
                            NO_PARTNERS if partner is None else partner, counts)
        sim.comm.reverse_comm(p, (COUNT,))
        return counts[:p.nlocal]
