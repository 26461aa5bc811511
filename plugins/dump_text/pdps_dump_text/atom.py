"""Dump ``atom``: LAMMPS's atom format, ``id type xs ys zs`` with positions scaled to the box (0..1).

Syntax::

    dump ID GROUP atom N FILE

N is the interval in steps; the file is written in LAMMPS's text format, which OVITO, VMD and
MDAnalysis read. Rows are sorted by id.

Example::

    dump 1 all atom 50 dump.atom
"""

from pdps_core.api import StyleArgs, param

from .frame import TextDump


class DumpAtom(TextDump):
    name = "atom"
    usage = "dump ID GROUP atom N FILE"
    columns = ("id", "type", "xs", "ys", "zs")

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        file: str

    def column_values(self, sim, chosen):
        p, box = sim.particles, sim.box
        scaled = (p.x[chosen] - box.lo) / box.length
        return [p.tag[chosen], p.type[chosen], *scaled.T], ["%d", "%d", "%.8g", "%.8g", "%.8g"]
