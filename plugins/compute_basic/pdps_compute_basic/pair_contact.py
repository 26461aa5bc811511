r"""Compute ``pair/contact``: the current contacts of a granular pair style (``dem/lsd``,
``dem/hertz``), one row per contact (LIGGGHTS's compute pair/gran/local, LAMMPS's pair/local).

For spheres i and j (radii :math:`R_i, R_j`, centres :math:`\mathbf{x}_i, \mathbf{x}_j`, distance
:math:`r > 0`) in contact, :math:`r < R_i + R_j`, with both in the group:

.. math::

    \delta = R_i + R_j - r, \qquad \mathbf{n} = \frac{\mathbf{x}_i - \mathbf{x}_j}{r}, \qquad
    \mathbf{x}_c = \mathbf{x}_i - \big(R_i - \tfrac{\delta}{2}\big)\,\mathbf{n}
                 = \mathbf{x}_j + \big(R_j - \tfrac{\delta}{2}\big)\,\mathbf{n}

the overlap, the normal from j to i and the contact point, the midpoint of the overlap on the line
between the centres (the point where the granular pair styles apply the contact force). Row layout
(``c_ID[row][column]``, both 0-based):

====== ======= ======= ========= ==== ==== ==== ==== ==== ====
column 0       1       2         3    4    5    6    7    8
value  tag_i   tag_j   overlap   fx   fy   fz   xc   yc   zc
====== ======= ======= ========= ==== ==== ==== ==== ==== ====

with tag_i < tag_j, rows sorted by (tag_i, tag_j), so the table is the same on any number of ranks;
(fx, fy, fz) is the contact force on tag_i from tag_j (force units), and the contact point is wrapped
into the box along periodic axes (distance units). ``c_ID`` is the number of contacts.

Forces come from the pair style's contact table (the api's ``ContactTable``: rows i, j and the force
on i of each contact; dem/lsd and dem/hertz give their last force computation's); a pair style
without one leaves them NaN, with a warning when the compute is defined. Overlap and contact point are always exact geometry.

Contacts are found in the pair style's neighbor list, so the compute is read after a run
(``run 0`` is enough) and sees the positions of the last force computation. The table is gathered
on every rank.

Syntax::

    compute ID GROUP pair/contact

Example::

    compute contacts all pair/contact
    thermo_style custom step c_contacts
    analyze 1 all ave/time 100 1 100 c_contacts file contacts.txt
"""

import numpy as np

from pdps_core.api import Compute, ContactTable, ScriptError

COLUMNS = ("tag_i", "tag_j", "overlap", "fx", "fy", "fz", "xc", "yc", "zc")


class ComputePairContact(Compute):
    name = "pair/contact"
    usage = "compute ID GROUP pair/contact"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.warned = False
        self._warn_without_forces(sim)

    def _warn_without_forces(self, sim):
        if sim.pair is not None and not isinstance(sim.pair, ContactTable) and not self.warned:
            self.warned = True
            sim.warn(f"compute {self.id} pair/contact: pair style {sim.pair.name} reports no "
                     "per-contact forces; the force columns are NaN (overlap and contact point are exact)")

    def _pair(self, sim):
        pair = sim.pair
        if pair is None or "radius" not in pair.per_atom:
            raise ScriptError(f"compute {self.id} pair/contact needs a granular pair style "
                              f"(dem/lsd, dem/hertz; got {pair.name if pair else 'none'})")
        if sim.pair_list is None:
            raise ScriptError(f"compute {self.id} pair/contact reads the pair's neighbor list: "
                              "run first (run 0 is enough)")
        self._warn_without_forces(sim)
        return pair

    def _local_rows(self, sim):
        """This rank's contacts, from the half list: every pair appears on one rank only."""
        pair, nlist, p = self._pair(sim), sim.pair_list, sim.particles
        nlocal = p.nlocal
        if len(nlist.offsets) != nlocal + 1:
            raise ScriptError(f"compute {self.id} pair/contact: particles changed since the last run; "
                              "run first (run 0 is enough)")
        i = np.repeat(np.arange(nlocal), np.diff(nlist.offsets))
        j = nlist.neighbors[nlist.offsets[0]:nlist.offsets[-1]]
        member = (p.mask & sim.groups.bit(self.group)) != 0
        delta = p.x[i] - p.x[j]
        r = np.sqrt(np.einsum("ij,ij->i", delta, delta))
        touching = (r < p.radius[i] + p.radius[j]) & (r > 0.0) & member[i] & member[j]
        i, j, delta, r = i[touching], j[touching], delta[touching], r[touching]
        overlap = p.radius[i] + p.radius[j] - r
        normal = delta / r[:, None]
        point = p.x[i] - (p.radius[i] - 0.5 * overlap)[:, None] * normal
        box = sim.box
        for d in range(3):
            if box.periodic[d]:
                point[:, d] = box.lo[d] + np.mod(point[:, d] - box.lo[d], box.length[d])
        # the smaller tag first: a row does not depend on which rank or side computed the pair
        low = np.minimum(p.tag[i], p.tag[j])
        high = np.maximum(p.tag[i], p.tag[j])
        force = self._forces(sim, pair, low, high)
        return np.column_stack([low.astype(np.float64), high.astype(np.float64), overlap, force,
                                point]).reshape(len(overlap), len(COLUMNS))

    @staticmethod
    def _forces(sim, pair, low, high):
        """Force on ``low`` from ``high`` per contact, from the pair's contact table if it has one."""
        force = np.full((len(low), 3), np.nan)
        if not isinstance(pair, ContactTable) or not len(low):
            return force
        found = pair.contacts(sim)
        tag = sim.particles.tag
        known_i, known_j, known_force = tag[found["i"]], tag[found["j"]], np.asarray(found["force"])
        if not len(known_i):
            return force
        width = int(max(high.max(), known_i.max(), known_j.max())) + 1
        keys = np.minimum(known_i, known_j) * width + np.maximum(known_i, known_j)
        # a report with the larger tag first gives the reaction: turn it round
        sign = np.where(known_i < known_j, 1.0, -1.0)
        order = np.argsort(keys)
        wanted = low * width + high
        where = np.minimum(np.searchsorted(keys[order], wanted), len(keys) - 1)
        found = keys[order[where]] == wanted
        rows = order[where[found]]
        force[found] = known_force[rows] * sign[rows][:, None]
        return force

    def array(self, sim):
        rows = sim.comm.allgather_rows(self._local_rows(sim))
        return rows[np.lexsort((rows[:, 1], rows[:, 0]))]

    def scalar(self, sim):
        return float(sim.comm.sum(len(self._local_rows(sim))))
