r"""Compute ``wall/gran/local``: one row per particle-wall contact of a ``fix wall/gran model ...``
(LIGGGHTS's compute wall/gran/local), for ``dump local``.

The compute finds the fix wall/gran of LIGGGHTS's spelling: the one mesh wall when there is one
(LIGGGHTS's reads mesh walls only, and leaves a primitive one beside it out), else the one wall
(several: name one with ``wall FIX_ID``), and, when read, recomputes the contacts of the current step without changing
forces or contact histories. For each contact of a particle of the compute's group, the columns
chosen by the keywords, always in LIGGGHTS's order whatever order they are given in:

- ``pos`` (6): the contact point on the wall, then the particle's position (distance);
- ``vel`` (6): the wall's velocity at the contact point, then the particle's velocity (LIGGGHTS's
  order of both, measured with dump local/gran/vtk);
- ``id`` (3): the mesh number (its place in ``meshes ...``, from 0; 0 for a primitive wall), the
  triangle's index in the mesh file (from 0; 0 for a primitive wall), the particle's id;
- ``force`` (3): the contact force on the particle (force);
- ``torque`` (3): the torque of the contact's tangential force on the particle about its centre
  (force*distance; as LIGGGHTS 3.8.0 writes it, measured with dump local/gran/vtk; without rolling
  friction);
- ``history``: the contact's history, as many values as its law keeps (tangential spring, 3
  values, with tangential history; the epsd/epsd2 rolling spring torque, 3 values; as pair gran's);
- ``contactArea`` (1): :math:`\pi(R^2 - d^2)`, the area of the circle where the sphere meets the
  wall's plane (distance^2);
- ``delta`` (1): the overlap :math:`R - d` (distance);
- ``heatFlux`` (1): the heat into the particle through the contact, :math:`\frac{4k_pk_w}{k_p +
  k_w}\sqrt{A}\,(T_w - T_p)` for a mesh with a ``temperature`` under fix heat/gran (its contact area
  model, the temperatures now), else 0 (energy/time).

No keyword: pos, vel, id, force, torque, history, contactArea. Rows of a parallel run come from the
rank owning the particle.

Syntax::

    compute ID GROUP wall/gran/local [pos] [vel] [id] [force] [torque] [history] [contactArea]
        [delta] [heatFlux] [wall FIX_ID]

Example::

    compute walls all wall/gran/local pos force contactArea
    dump contacts all local 1000 contacts.txt c_walls[1] c_walls[2] c_walls[3] c_walls[7]
"""

from typing import Literal

import numpy as np

from pdps_core.api import Compute, ContactRows, ScriptError, StyleArgs, keyword, param

from .wall_contact import LOG_COLUMNS
from .wall_gran_model import FixWallGranModel

# columns of each keyword; history's are as many as the wall's contact law keeps
KEYWORDS = {"pos": 6, "vel": 6, "id": 3, "force": 3, "torque": 3, "history": None, "contactArea": 1,
            "delta": 1, "heatFlux": 1}
DEFAULT = ("pos", "vel", "id", "force", "torque", "history", "contactArea")
COLUMN = {name: k for k, name in enumerate(LOG_COLUMNS)}
COLUMN_WORDS = tuple(KEYWORDS)


class ComputeWallGranLocal(Compute, ContactRows):
    name = "wall/gran/local"
    usage = ("compute ID GROUP wall/gran/local [pos] [vel] [id] [force] [torque] [history] [contactArea] "
             "[delta] [heatFlux] [wall FIX_ID]")

    class Args(StyleArgs):
        # LIGGGHTS's column words (its manual calls them keywords)
        columns: list[Literal[COLUMN_WORDS]] = param([])
        wall: str | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        words = list(args.columns)
        self.wall_id = args.wall
        chosen = set(words) or set(DEFAULT)
        self.keywords = [name for name in KEYWORDS if name in chosen]

    def wall(self, sim):
        if self.wall_id is not None:
            fix = sim.fixes.get(self.wall_id)
            if not isinstance(fix, FixWallGranModel):
                raise ScriptError(f"compute {self.id}: fix {self.wall_id} is not a fix wall/gran model ...")
            return fix
        walls = [fix for fix in sim.fixes.values() if isinstance(fix, FixWallGranModel)]
        meshes = [fix for fix in walls if fix.args.mesh is not None]
        if len(meshes) == 1:
            return meshes[0]
        if len(walls) != 1:
            found = ", ".join(fix.id for fix in walls) or "none"
            raise ScriptError(f"compute {self.id} (wall/gran/local) needs exactly one fix wall/gran model ... "
                              f"(found {found}); name one with wall FIX_ID")
        return walls[0]

    def contact_columns(self, sim):
        """[(keyword, width)] of the rows of ``local`` (ContactRows)."""
        history = self.wall(sim).contact_model.history_width
        return [(name, KEYWORDS[name] or history) for name in self.keywords]

    def local(self, sim):
        """This rank's contacts, one row each: (rows, columns) floats in the keywords' order."""
        p = sim.particles
        in_group = p.mask & sim.groups.bit(self.group)
        wall = self.wall(sim)
        columns = sum(KEYWORDS[name] or wall.contact_model.history_width for name in self.keywords)
        blocks = []
        for number, log in wall.contact_log(sim):
            rows = log[:, COLUMN["row"]].astype(np.int64)
            keep = in_group[rows] != 0
            log, rows = log[keep], rows[keep]
            parts = {
                "pos": [log[:, COLUMN["px"]:COLUMN["pz"] + 1], p.x[rows]],
                "vel": [log[:, COLUMN["vwx"]:COLUMN["vwz"] + 1], p.v[rows]],
                "id": [np.full((len(rows), 1), float(number)), log[:, [COLUMN["element"]]],
                       p.tag[rows].astype(np.float64)[:, None]],
                "force": [log[:, COLUMN["fx"]:COLUMN["fz"] + 1]],
                "torque": [log[:, COLUMN["tx"]:COLUMN["tz"] + 1]],
                "history": [log[:, len(LOG_COLUMNS):]],
                "contactArea": [log[:, [COLUMN["area"]]]],
                "delta": [log[:, [COLUMN["delta"]]]],
                "heatFlux": [
                    wall.contact_heat(sim, number, rows, p.radius[rows] - log[:, COLUMN["delta"]])[:, None]]
                if "heatFlux" in self.keywords else [],
            }
            blocks.append(np.hstack([part for name in self.keywords for part in parts[name]]))
        if not blocks:
            return np.zeros((0, columns))
        return np.vstack(blocks).reshape(-1, columns)
