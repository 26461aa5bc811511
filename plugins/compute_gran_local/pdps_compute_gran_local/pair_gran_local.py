r"""Compute ``pair/gran/local``: one row per contact between two particles of the group, with what
LIGGGHTS's compute pair/gran/local gives (its columns and their order), for ``dump local``.

Columns, in this order whatever the order of the keywords (LIGGGHTS's):

- ``pos`` (6): :math:`\mathbf{x}_i`, :math:`\mathbf{x}_j` (distance), each wrapped into the box along
  periodic axes (a contact across a periodic boundary has j's own position, not its image's, as
  LIGGGHTS's; measured with dump local/gran/vtk);
- ``vel`` (6): :math:`\mathbf{v}_i`, :math:`\mathbf{v}_j` (velocity);
- ``id`` (3): the ids of i and j, and 1 when the contact crosses a periodic boundary (0 else);
- ``force`` (3): the contact force on i (force; :math:`-` on j);
- ``torque`` (3): :math:`-(R_i - \delta/2)\,\mathbf{n}\times\mathbf{F}_t`, the torque of the
  tangential force on i about its centre, lever arm :math:`R_i - \delta/2` (force*distance; as
  LIGGGHTS 3.8.0 writes it, measured with dump local/gran/vtk; rolling friction torques are not
  included);
- ``history``: the values the contact keeps, as i sees them: the tangential spring (3, tangential
  history), then the rolling spring torque (3, rolling_friction epsd or epsd2); none with
  no_history and no spring of rolling (as LIGGGHTS's contact history, read from its source);
- ``contactArea`` (1): :math:`\pi a^2`, the circle where the spheres intersect (area; the smaller
  sphere's cross-section once its centre is inside the other);
- ``delta`` (1): the overlap :math:`R_i + R_j - r` (distance);
- ``heatFlux`` (1): the conductive heat flux into i, :math:`h(T_j - T_i)` of fix heat/gran
  (energy/time; needs that fix).

Without keywords: all but delta and heatFlux (LIGGGHTS's default). The forces are those of the
moment the compute is read (current velocities, spins and springs; nothing advanced), as LIGGGHTS
evaluates the pair style again for it; ``dump local`` reads them at its output steps. Rows hold
the contacts of owned particles i (each contact once over all ranks), in no fixed order.

Syntax::

    compute ID GROUP pair/gran/local [pos] [vel] [id] [force] [torque] [history] [contactArea] [delta]
                                     [heatFlux]

Needs ``pair_style gran``. Example::

    compute cpgl all pair/gran/local pos id force contactArea
    dump contacts all local 1000 contacts.txt c_cpgl[1] c_cpgl[2] c_cpgl[3] c_cpgl[7] c_cpgl[8]
"""


from typing import Literal

import numpy as np

from pdps_core.api import Compute, ContactRows, ContactTable, HeatTransport, ScriptError, StyleArgs, param
from pdps_granular_contact.contact_models import intersection_area

# keyword -> columns, in LIGGGHTS's order
COLUMNS = {"pos": 6, "vel": 6, "id": 3, "force": 3, "torque": 3, "history": None, "contactArea": 1, "delta": 1,
           "heatFlux": 1}
DEFAULT = ("pos", "vel", "id", "force", "torque", "history", "contactArea")


class ComputePairGranLocal(Compute, ContactRows):
    name = "pair/gran/local"
    usage = "compute ID GROUP pair/gran/local [pos] [vel] [id] [force] [torque] [history] [contactArea] [delta] [heatFlux]"

    class Args(StyleArgs):
        # LIGGGHTS's column words (its manual calls them keywords)
        columns: list[Literal[tuple(COLUMNS)]] = param([])

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.keywords = [k for k in COLUMNS if k in args.columns] if args.columns else list(DEFAULT)
        self.width = None           # columns of the last rows given

    def local(self, sim):
        pair = sim.pair
        if not isinstance(pair, ContactTable):
            raise ScriptError(f"compute {self.id} (pair/gran/local) needs pair_style gran")
        found = pair.contacts(sim, self.group)
        if not {"tangential", "history"} <= set(found):
            raise ScriptError(f"compute {self.id} (pair/gran/local) needs pair_style gran (pair style "
                              f"{pair.name} lists no tangential forces and histories)")
        p = sim.particles
        i, j = found["i"], found["j"]
        xi, xj = p.x[i], p.x[j]
        d = xi - xj
        r = np.sqrt((d * d).sum(axis=1))
        ri, rj = p.radius[i], p.radius[j]
        blocks = []
        for key in self.keywords:
            start = len(blocks)
            if key == "pos":
                blocks += [self._wrapped(sim, xi), self._wrapped(sim, xj)]
            elif key == "vel":
                blocks += [p.v[i], p.v[j]]
            elif key == "id":
                blocks.append(np.column_stack([p.tag[i], p.tag[j], self._periodic(sim, xj)]))
            elif key == "force":
                blocks.append(found["force"])
            elif key == "torque":
                n = d / r[:, None]
                arm = ri - 0.5 * (ri + rj - r)
                blocks.append(-arm[:, None] * np.cross(n, found["tangential"]))
            elif key == "history":
                blocks.append(found["history"])
            elif key == "contactArea":
                blocks.append(intersection_area(r, ri, rj))
            elif key == "delta":
                blocks.append(ri + rj - r)
            else:
                blocks.append(self._heat_flux(sim, i, j, r))
            # no contacts (a bed not yet formed) is a table of no rows, as wide as with contacts
            for k in range(start, len(blocks)):
                b = np.asarray(blocks[k], dtype=np.float64)
                blocks[k] = b.reshape(len(i), b.shape[1] if b.ndim == 2 else 1)
        table = np.column_stack(blocks) if len(i) else np.hstack(blocks)
        self.width = table.shape[1]
        return table

    def contact_columns(self, sim):
        """[(keyword, width)] of the rows of ``local`` (ContactRows); history's width is the pair
        style's."""
        if self.width is None:
            self.local(sim)
        fixed = sum(COLUMNS[k] for k in self.keywords if k != "history")
        return [(k, COLUMNS[k] if k != "history" else self.width - fixed) for k in self.keywords]

    @staticmethod
    def _wrapped(sim, x):
        """Positions wrapped into the box along its periodic axes."""
        box = sim.box
        x = np.array(x, dtype=np.float64)
        for d in range(3):
            if box.periodic[d]:
                x[:, d] = box.lo[d] + np.mod(x[:, d] - box.lo[d], box.length[d])
        return x

    @staticmethod
    def _periodic(sim, xj):
        """1 where j is a periodic image: outside the box along a periodic axis."""
        box = sim.box
        flag = np.zeros(len(xj), dtype=bool)
        for d in range(3):
            if box.periodic[d]:
                flag |= (xj[:, d] < box.lo[d]) | (xj[:, d] >= box.hi[d])
        return flag.astype(np.float64)

    def _heat_flux(self, sim, i, j, r):
        heat = sim.fix_with(HeatTransport)
        if heat is None:
            raise ScriptError(f"compute {self.id} (pair/gran/local): heatFlux needs a fix heat/gran (and a run)")
        return heat.contact_heat_flux(sim, i, j, r)
