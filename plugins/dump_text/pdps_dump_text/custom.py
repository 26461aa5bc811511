"""Dump ``custom``: chosen per-particle columns, in LAMMPS's text format.

Syntax::

    dump ID GROUP custom N FILE column...

Columns: ``id type mass x y z xs ys zs xu yu zu ix iy iz vx vy vz fx fy fz radius diameter
omegax omegay omegaz tqx tqy tqz`` and ``step`` (the PDPS manual's: the timestep, on every row).
``x y z`` are wrapped into the box, ``xs ys zs`` scaled to 0..1, ``xu yu zu`` unwrapped through
periodic images.

Example::

    dump 2 all custom 10 traj.txt id type x y z vx vy vz
"""

import numpy as np
from pydantic import Field, field_validator

from pdps_core.api import ScriptError, StyleArgs, observables

from .frame import TextDump

VECTOR = {"x": ("x", 0), "y": ("x", 1), "z": ("x", 2), "vx": ("v", 0), "vy": ("v", 1), "vz": ("v", 2),
          "fx": ("f", 0), "fy": ("f", 1), "fz": ("f", 2), "ix": ("image", 0), "iy": ("image", 1),
          "iz": ("image", 2), "omegax": ("omega", 0), "omegay": ("omega", 1), "omegaz": ("omega", 2),
          "tqx": ("torque", 0), "tqy": ("torque", 1), "tqz": ("torque", 2)}
SPECIAL = ("id", "type", "mass", "xs", "ys", "zs", "xu", "yu", "zu", "radius", "diameter", "step")
INTEGER = {"id", "type", "ix", "iy", "iz", "step"}


class DumpCustom(TextDump):
    name = "custom"
    usage = "dump ID GROUP custom N FILE column..."

    class Args(StyleArgs):
        every: int = Field(ge=1)
        file: str
        columns: list[str] = Field(min_length=1)

        @field_validator("columns")
        @classmethod
        def _known(cls, columns):
            for column in columns:
                if column not in VECTOR and column not in SPECIAL:
                    raise ValueError(f"unknown dump column {column} (known: {', '.join([*SPECIAL, *VECTOR])})")
            return columns

    def __init__(self, sim, id, group, args):
        self.columns = tuple(args.columns)
        for column in self.columns:
            needed = VECTOR.get(column, (None,))[0] or ("radius" if column in ("radius", "diameter") else None)
            if needed and not sim.particles.has(needed):
                raise ScriptError(f"dump column {column} needs per-particle {needed} "
                                  "(particle_style sphere)")
        super().__init__(sim, id, group, args)

    def column_values(self, sim, chosen):
        p, box = sim.particles, sim.box
        values, formats = [], []
        for column in self.columns:
            if column in VECTOR:
                name, d = VECTOR[column]
                value = p.arrays[name][chosen, d]
            elif column == "id":
                value = p.tag[chosen]
            elif column == "type":
                value = p.type[chosen]
            elif column == "step":
                value = np.full(len(chosen), sim.step)
            elif column == "mass":
                value = observables.masses(sim)[chosen]
            elif column in ("xs", "ys", "zs"):
                d = "xyz".index(column[0])
                value = (p.x[chosen, d] - box.lo[d]) / box.length[d]
            elif column in ("xu", "yu", "zu"):
                d = "xyz".index(column[0])
                value = p.x[chosen, d] + p.image[chosen, d] * box.length[d]
            elif column == "radius":
                value = p.radius[chosen]
            else:
                value = 2.0 * p.radius[chosen]
            values.append(value)
            formats.append("%d" if column in INTEGER else "%.10g")
        return values, formats
