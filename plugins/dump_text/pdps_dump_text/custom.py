"""Dump ``custom``: chosen per-particle columns, in LAMMPS's text format.

Syntax::

    dump ID GROUP custom N FILE column...

Columns: ``id type mol q mass x y z xs ys zs xu yu zu ix iy iz vx vy vz fx fy fz radius diameter
omegax omegay omegaz tqx tqy tqz`` and ``step`` (``mol`` with the particle styles that have molecule
ids, ``q`` with charge and full) (the PDPS manual's: the timestep, on every row).
``x y z`` are wrapped into the box, ``xs ys zs`` scaled to 0..1, ``xu yu zu`` unwrapped through
periodic images.

References (the header shows them as written):

- ``c_ID``: the per-atom values of a compute with one value per particle (``compute ke``,
  ``compute property/atom`` of one attribute); ``c_ID[k]``: column k of one with several. k counts
  from 0, as every pdps index (``c_ID[i]`` in thermo; LAMMPS's dump counts from 1: its ``c_p[1]`` is
  pdps's ``c_p[0]``).
- ``f_ID``, ``f_ID[k]``: the same for a fix (or analyze style) that offers per-atom values. In the
  LIGGGHTS dialect ``f_NAME[k]`` also names column k (from 0, as LIGGGHTS) of a per-atom property
  a fix made: ``f_Temp[0]``, ``f_heatFlux[0]`` of fix heat/gran.
- ``v_NAME``: an atom-style variable's value of each particle (LAMMPS's), another variable's value on
  every row.

The computes, fixes and variables named must exist when the dump is defined and when it writes.

Example::

    dump 2 all custom 10 traj.txt id type x y z vx vy vz
    compute k all ke
    compute p all property/atom xu radius
    variable t equal temp
    dump 3 all custom 100 grains.txt id c_k c_p[0] c_p[1] v_t
"""

import re

import numpy as np
from pydantic import field_validator

from pdps_core.api import PeratomReference, ScriptError, StyleArgs, observables, param

from .frame import TextDump

VECTOR = {"x": ("x", 0), "y": ("x", 1), "z": ("x", 2), "vx": ("v", 0), "vy": ("v", 1), "vz": ("v", 2),
          "fx": ("f", 0), "fy": ("f", 1), "fz": ("f", 2), "ix": ("image", 0), "iy": ("image", 1),
          "iz": ("image", 2), "omegax": ("omega", 0), "omegay": ("omega", 1), "omegaz": ("omega", 2),
          "tqx": ("torque", 0), "tqy": ("torque", 1), "tqz": ("torque", 2)}
SPECIAL = ("id", "type", "mol", "q", "mass", "xs", "ys", "zs", "xu", "yu", "zu", "radius", "diameter", "step")
INTEGER = {"id", "type", "mol", "ix", "iy", "iz", "step"}
# columns that read a per-particle array only some particle styles have
NEEDED = {"radius": ("radius", "sphere"), "diameter": ("radius", "sphere"),
          "mol": ("molecule", "molecular, bond, angle or full"), "q": ("q", "charge or full")}
REFERENCE = re.compile(r"^(c|f|v)_([A-Za-z0-9_]+)(?:\[(\d+)\])?$")


class DumpCustom(TextDump):
    name = "custom"
    usage = "dump ID GROUP custom N FILE column..."

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        file: str
        columns: list[str] = param(min_length=1, names="column")

        @field_validator("columns")
        @classmethod
        def _known(cls, columns):
            for column in columns:
                if column not in VECTOR and column not in SPECIAL and not REFERENCE.match(column):
                    raise ValueError(f"unknown dump column {column} (known: {', '.join([*SPECIAL, *VECTOR])}, "
                                     "c_ID, c_ID[k], f_ID, f_ID[k], v_NAME)")
                if column.startswith("v_") and column.endswith("]"):
                    raise ValueError(f"dump column {column}: a variable has one value, no [k]")
            return columns

    def __init__(self, sim, id, group, args):
        self.columns = tuple(args.columns)
        for column in self.columns:
            needed, styles = NEEDED.get(column, (VECTOR.get(column, (None,))[0], "sphere"))
            if needed and not sim.particles.has(needed):
                raise ScriptError(f"dump column {column} needs per-particle {needed} "
                                  f"(particle_style {styles})")
        self.references = {column: PeratomReference(sim, column, f"dump column {column}")
                           for column in self.columns if REFERENCE.match(column)}
        super().__init__(sim, id, group, args)

    @property
    def needs(self):
        """Energy and virial on the steps this dump writes, when a compute or variable reads them."""
        return set().union(*(reference.needs(self.sim) for reference in self.references.values()))

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
            elif column == "mol":
                value = p.molecule[chosen]
            elif column == "q":
                value = p.q[chosen]
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
            elif column == "diameter":
                value = 2.0 * p.radius[chosen]
            else:
                value = self.references[column].values(sim)[chosen]
            values.append(value)
            formats.append("%d" if column in INTEGER else "%.10g")
        return values, formats
