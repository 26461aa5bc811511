r"""Dump ``mesh/vtk`` (also spelled ``mesh/gran/VTK``): the surfaces of ``fix mesh/surface`` meshes,
one legacy VTK file per frame with values per triangle (LIGGGHTS's dump mesh/vtk).

Syntax::

    dump ID GROUP mesh/vtk N FILE [output face] [VALUE ...] [MESH_ID ...]

in that order (``output face``, then the values, then the mesh IDs).

N is the interval in steps; FILE has one ``*``, replaced by the step, and ends in ``.vtk`` (legacy
VTK) or ``.vtu``. The group is not used. Each frame holds the triangles of the meshes named (all
fix mesh/surface meshes when none is named), one after the other in the order named, as VTK
triangle cells, with the cell data chosen by the VALUE words (LIGGGHTS's names):

- ``stress``: :math:`|\mathbf{F}|/A`, the magnitude of the force the particles exert on the
  triangle per unit area (pressure units);
- ``stresscomponents``: :math:`\mathbf{F}/A` (3 values, written as ``stress_components``);

- ``wear``: the Finnie wear of each triangle so far (fix mesh/surface/stress ... wear finnie);

  these need a fix mesh/surface/stress among the meshes written, and are 0 on the triangles of
  meshes that do not sum them (plain mesh/surface, or no ``wear finnie``);
- ``id``: the triangle's index in its mesh file, from 0; ``area``: its area; ``vel``: the wall
  velocity at its centre (velocity units; from fix move/mesh or a conveyor);
- ``owner``: the rank writing it (always 0: rank 0 gathers every mesh).

``output face`` is the default and only form (per-triangle values; LIGGGHTS's ``interpolate`` is not
supported). As pdps's dump vtk, each file is written under a
temporary name and renamed, and ``STEM.vtk.series`` lists the frames for ParaView.

Example::

    dump stress all mesh/vtk 1000 post/mesh*.vtk stress stresscomponents vel cad
"""

import typing
from typing import Literal

import meshio
import numpy as np

from pdps_core.api import Dump, MeshSurface, ScriptError, StyleArgs, SurfaceValues, param

from .frames import Pattern, Series, replace_atomically
from .vtk import series_json

Value = Literal["stress", "stresscomponents", "wear", "id", "area", "vel", "owner"]
VALUES = typing.get_args(Value)


class DumpMeshVTK(Dump):
    name = "mesh/vtk"
    usage = ("dump ID GROUP mesh/vtk N FILE_*.vtk [output face] [stress] [stresscomponents] [id] [area] "
             "[vel] [owner] [MESH_ID ...]")

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        file: str
        output: tuple[Literal["output"], Literal["face"]] | None = param(None)
        values: list[Value] = param(default_factory=list)
        meshes: list[str] = param(default_factory=list, names="fix mesh/surface ID")

    @classmethod
    def check_args(cls, args):
        late = [ident for ident in args.meshes if ident in VALUES or ident == "output"]
        if late:
            raise ScriptError(f"{late[0]} stands after a mesh ID: output face, then the values, then the mesh IDs; "
                              f"usage: {cls.usage}")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.pattern = Pattern(args.file, (".vtk", ".vtu"), "post/mesh*.vtk")
        self.values, self.mesh_ids = list(args.values), list(args.meshes)
        for ident in self.mesh_ids:
            fix = sim.fixes.get(ident)
            if not isinstance(fix, MeshSurface):
                raise ScriptError(f"{ident} is neither a value ({', '.join(VALUES)}) nor the ID of a "
                                  "fix mesh/surface")
        self.series = Series(self.pattern.series() + ".series",
                             series_json)

    def meshes(self, sim):
        if self.mesh_ids:
            return [sim.fixes[ident] for ident in self.mesh_ids]
        return [fix for fix in sim.fixes.values() if isinstance(fix, MeshSurface)]

    def write(self, sim):
        meshes = self.meshes(sim)
        if not meshes:
            raise ScriptError(f"dump {self.id} ({self.name}): there is no fix mesh/surface to write")
        stressed = [name for name in self.values if name in ("stress", "stresscomponents", "wear")]
        if stressed and not any(isinstance(mesh, SurfaceValues) for mesh in meshes):
            raise ScriptError(f"dump {self.id} ({self.name}): {stressed[0]} needs a fix mesh/surface/stress "
                              f"(fix {meshes[0].id} is a {meshes[0].name})")
        points, cells, data, offset = [], [], {name: [] for name in self.values}, 0
        for mesh in meshes:
            faces = mesh.face_data(sim) if isinstance(mesh, SurfaceValues) else None
            area = mesh.face_areas()
            for name in self.values:
                data[name].append(self._value(sim, mesh, name, faces, area))
            points.append(mesh.vertices)
            cells.append(np.asarray(mesh.triangles, dtype=np.int64) + offset)
            offset += len(mesh.vertices)
        if not sim.comm.is_root:
            return
        cell_data = {}
        for name, blocks in data.items():
            column = "stress_components" if name == "stresscomponents" else name
            cell_data[column] = [np.concatenate(blocks)]
        path = self.pattern.frame(sim.step)
        mesh = (np.concatenate(points), [("triangle", np.concatenate(cells))])
        kind = "vtu" if self.pattern.tail.endswith(".vtu") else "vtk"

        def write(tmp):
            meshio.write(tmp, meshio.Mesh(*mesh, cell_data=cell_data), file_format=kind)
        replace_atomically(path, write)
        self.series.add(path, sim.time)

    def _value(self, sim, mesh, name, faces, area):
        if name == "wear":
            return faces["wear"] if faces is not None and "wear" in faces else np.zeros(len(mesh.triangles))
        if name in ("stress", "stresscomponents"):
            force = faces["force"] if faces is not None else np.zeros((len(mesh.triangles), 3))
            if name == "stress":
                return np.linalg.norm(force, axis=1) / area
            return force / area[:, None]
        if name == "id":
            return np.arange(len(mesh.triangles), dtype=np.int64)
        if name == "area":
            return area
        if name == "owner":
            return np.zeros(len(mesh.triangles), dtype=np.int64)
        return mesh.face_velocity()


class DumpMeshGranVTK(DumpMeshVTK):
    """LIGGGHTS's older spelling of dump mesh/vtk."""
    name = "mesh/gran/VTK"
    usage = DumpMeshVTK.usage.replace("mesh/vtk", "mesh/gran/VTK")
