"""Dump ``custom/vtk`` (LIGGGHTS's and LAMMPS's spelling): particles for ParaView with the per-atom
values named, one VTK file per frame and a ``.series`` file listing them, as dump vtk writes them.

Syntax::

    dump ID GROUP custom/vtk N FILE ATTRIBUTE ...

N is the interval in steps; FILE has one ``*`` (replaced by the step) and ends in ``.vtk`` (legacy
VTK, LIGGGHTS's default) or ``.vtu``. The particles are points, sorted by id (their positions always:
``x y z`` may be listed or not, as LIGGGHTS says), with point data for the attributes listed, in
LIGGGHTS's groups: ``id``, ``type``, ``mol`` (the molecule id: a multisphere clump's body id), ``mass``, ``radius``, ``diameter``, ``ix iy iz`` (as the vector
``image``), ``vx vy vz`` (``v``), ``fx fy fz`` (``f``), ``omegax omegay omegaz`` (``omega``),
``tqx tqy tqz`` (``torque``); a component listed alone is written alone (``vz``); computes', fixes'
and atom-style variables' per-atom values (``c_ID``, ``c_ID[k]``, ``f_ID``, ``f_ID[k]``, ``v_NAME``, and
LIGGGHTS's ``f_Temp[0]`` of a per-atom property, as dump custom reads them), each a scalar named as
written. Per-processor files (``%``) are refused by name.

In the LIGGGHTS dialect each legacy ``.vtk`` frame has LIGGGHTS's companion ``STEM_boundingBox_STEP.vtk``
beside it: the box of that step as a 2 x 2 x 2 rectilinear grid (ASCII), which ParaView shows as the
domain.

Example (LIGGGHTS's tutorials)::

    dump dmp all custom/vtk 800 post/packing_*.vtk id type x y z vx vy vz fx fy fz omegax omegay omegaz radius
    dump dmp all custom/vtk 800 post/heatGran_*.vtk id type x y z radius f_Temp[0] f_heatFlux[0]
"""

import numpy as np

from pdps_core.api import PERATOM_REFERENCE, PeratomReference, ScriptError, StyleArgs, param

from .frames import MeshDump, vertex_cells
from .vtk import DumpVTK, series_json

VECTORS = {"v": ("vx", "vy", "vz"), "f": ("fx", "fy", "fz"), "omega": ("omegax", "omegay", "omegaz"),
           "torque": ("tqx", "tqy", "tqz"), "image": ("ix", "iy", "iz")}
SCALARS = ("id", "type", "mol", "mass", "radius", "diameter")
POSITIONS = ("x", "y", "z")
OTHER_POSITIONS = ("xu", "yu", "zu", "xs", "ys", "zs")
COMPONENT = {word: (name, k) for name, words in VECTORS.items() for k, word in enumerate(words)}


class DumpCustomVTK(MeshDump):
    name = "custom/vtk"
    usage = "dump ID GROUP custom/vtk N FILE_*.vtk ATTRIBUTE ..."
    extensions = (".vtk", ".vtu")
    example = "post/particles_*.vtk"
    series_suffix = ".series"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        file: str
        attributes: list[str] = param([], names="attribute")

    def __init__(self, sim, id, group, args):
        if "%" in args.file:
            raise ScriptError("per-processor files (%) are not supported: pdps writes one file per frame")
        super().__init__(sim, id, group, args)
        self.columns = []           # (name in the file, array name, component or None)
        self.references = {}
        for word in args.attributes:
            if PERATOM_REFERENCE.match(word):
                self.references[word] = PeratomReference(sim, word, f"custom/vtk: {word}")
                continue
            if word in POSITIONS:
                continue
            if word in OTHER_POSITIONS:
                raise ScriptError(f"custom/vtk: {word}: the points are the wrapped positions x y z; write unwrapped "
                                  "or scaled ones with dump custom")
            if word in SCALARS:
                self.columns.append((word, word, None))
            elif word in COMPONENT:
                self.columns.append(COMPONENT[word] + (None,))
            else:
                raise ScriptError(f"custom/vtk: unknown attribute {word} (known: {', '.join(SCALARS)}, "
                                  f"{', '.join(w for words in VECTORS.values() for w in words)}, x y z)")
        needs_sphere = {"radius", "diameter", "omega", "torque"}
        for name, *_ in self.columns:
            if name in needs_sphere and not sim.particles.has("radius" if name == "diameter" else name):
                raise ScriptError(f"custom/vtk: {name} needs spheres (atom_style sphere or granular)")
            if name == "mol" and not sim.particles.has("molecule"):
                raise ScriptError("custom/vtk: mol needs molecule ids (atom_style molecular, bond, angle or full, "
                                  "or a fix multisphere defined before the dump)")

    def write(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = np.flatnonzero(sim.groups.select(sim, self.group))
        blocks = [np.asarray(p.tag[:n][chosen], dtype=np.float64).reshape(-1, 1), p.x[:n][chosen]]
        layout = []                 # (name, width)
        for name in self._vector_names():
            values = np.asarray(self._values(sim, name)[chosen], dtype=np.float64)
            blocks.append(values if values.ndim == 2 else values[:, None])
            layout.append((name, blocks[-1].shape[1]))
        table = sim.comm.gather_rows(np.column_stack(blocks) if blocks else np.zeros((0, 4)))
        if not sim.comm.is_root:
            return
        table = table[np.argsort(table[:, 0], kind="stable")]
        data, start = {}, 4
        for name, width in layout:
            block = table[:, start:start + width]
            data[name] = np.ascontiguousarray(block[:, 0] if width == 1 else block)
            start += width
        for name in ("id", "type", "mol", "image"):
            if name in data:
                data[name] = data[name].astype(np.int64)
        path = self.pattern.frame(sim.step)
        points = np.ascontiguousarray(table[:, 1:4])
        self.write_frame(path, points, vertex_cells(len(points)), data, sim.time)
        if sim.dialect.name == "liggghts" and path.endswith(".vtk"):
            self._write_bounding_box(sim)
        self.series.add(path, sim.time, empty=len(points) == 0)

    def _write_bounding_box(self, sim):
        """LIGGGHTS's STEM_boundingBox_STEP.vtk: the box now, as a rectilinear grid of 2 x 2 x 2 points."""
        lo, hi = sim.box.lo, sim.box.hi
        lines = ["# vtk DataFile Version 5.1", "Generated by pdps", "ASCII", "DATASET RECTILINEAR_GRID",
                 "DIMENSIONS 2 2 2"]
        for axis, name in enumerate("XYZ"):
            lines += [f"{name}_COORDINATES 2 double", f"{lo[axis]:.11g} {hi[axis]:.11g} "]
        with open(self.pattern.frame(f"boundingBox_{sim.step}"), "w") as handle:
            handle.write("\n".join(lines) + "\n")

    def _vector_names(self):
        """Point data names in the order first listed: a vector whose three components are all listed
        is one entry; a lone component is an entry of its own."""
        names = []
        for word in self.args.attributes:
            if (word in SCALARS or word in self.references) and word not in names:
                names.append(word)
            elif word in COMPONENT:
                vector, _ = COMPONENT[word]
                whole = all(w in self.args.attributes for w in VECTORS[vector])
                entry = vector if whole else word
                if entry not in names:
                    names.append(entry)
        return names

    @property
    def needs(self):
        """Energy and virial on the steps this dump writes, when a compute or variable reads them."""
        return set().union(*(reference.needs(self.sim) for reference in self.references.values()))

    def _values(self, sim, name):
        p = sim.particles
        n = p.nlocal
        if name in self.references:
            return self.references[name].values(sim)
        if name in VECTORS:
            return p.arrays[name][:n]
        if name in COMPONENT:
            vector, k = COMPONENT[name]
            return p.arrays[vector][:n, k]
        if name == "id":
            return p.tag[:n]
        if name == "mass":
            return p.rmass[:n] if p.has("rmass") else sim.mass[p.type[:n]]
        if name == "diameter":
            return 2.0 * p.radius[:n]
        if name == "mol":
            return p.molecule[:n]
        return p.arrays[name][:n]

    write_mesh = DumpVTK.write_mesh

    def render_series(self, frames, surface):
        return series_json(frames)
