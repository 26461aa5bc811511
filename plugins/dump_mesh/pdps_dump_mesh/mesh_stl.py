"""Dump ``mesh/stl``: the triangles of ``fix mesh/surface`` meshes where they are now, one ASCII STL
file per frame (LIGGGHTS's dump mesh/stl), to watch a mesh that fix move/mesh moves.

Syntax::

    dump ID GROUP mesh/stl N FILE [local|owned|all] [region REGION_ID] [MESH_ID ...]

N is the interval in steps; FILE has one ``*``, replaced by the step, and ends in ``.stl``. The
group is not used (LIGGGHTS: the dump writes meshes, not particles). Each frame holds the triangles
of the meshes named, in the order named (every fix mesh/surface mesh when none is named), as one
``solid`` with each facet's unit normal (right-handed over its vertices, as the file gave them).

- ``local``, ``owned``, ``all``: which of each rank's triangles LIGGGHTS writes. Every pdps rank holds
  whole meshes and rank 0 writes the file, so all three write every triangle, as LIGGGHTS does
  without ``%`` in the file name; ``ghost`` (LIGGGHTS's halo triangles) and per-processor files (``%``)
  have no meaning here and are refused.
- ``region ID``: only the triangles whose centre (the mean of the three vertices) the region holds.

As the other mesh dumps, each file is written under a temporary name and renamed.

Example (LIGGGHTS's meshGran tutorial)::

    dump dmpstl all mesh/stl 300 post/dump*.stl
"""

from typing import Literal

import numpy as np

from pdps_core.api import Dump, MeshSurface, ScriptError, StyleArgs, keyword, param

from .frames import Pattern, replace_atomically


class DumpMeshSTL(Dump):
    name = "mesh/stl"
    usage = "dump ID GROUP mesh/stl N FILE_*.stl [local|owned|all] [region REGION_ID] [MESH_ID ...]"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        file: str
        part: Literal["local", "owned", "all"] | None = param(None)
        region: str | None = keyword(None)
        meshes: list[str] = param(default_factory=list, names="fix mesh/surface ID")

    def __init__(self, sim, id, group, args):
        if "%" in args.file:
            raise ScriptError("per-processor files (%) are not supported: rank 0 writes every triangle")
        super().__init__(sim, id, group, args)
        self.pattern = Pattern(args.file, (".stl",), "post/dump*.stl")
        for ident in args.meshes:
            if ident == "ghost":
                raise ScriptError("ghost: every rank holds whole meshes, there are no ghost triangles to write "
                                  "(local, owned and all write every triangle)")
            if not isinstance(sim.fixes.get(ident), MeshSurface):
                raise ScriptError(f"{ident} is not the ID of a fix mesh/surface")
        if args.region is not None:
            sim.region(args.region)

    def meshes(self, sim):
        if self.args.meshes:
            return [sim.fixes[ident] for ident in self.args.meshes]
        return [fix for fix in sim.fixes.values() if isinstance(fix, MeshSurface)]

    def write(self, sim):
        meshes = self.meshes(sim)
        if not meshes:
            raise ScriptError(f"dump {self.id} ({self.name}): there is no fix mesh/surface to write")
        if not sim.comm.is_root:
            return
        corners = np.concatenate([np.asarray(mesh.vertices)[np.asarray(mesh.triangles)] for mesh in meshes])
        if self.args.region is not None:
            corners = corners[np.asarray(sim.region(self.args.region).match(corners.mean(axis=1)), dtype=bool)]
        normals = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
        length = np.linalg.norm(normals, axis=1)
        normals /= np.where(length > 0.0, length, 1.0)[:, None]

        def write(tmp):
            with open(tmp, "w") as out:
                out.write("solid LIGGGHTS_STL_EXPORT\n")
                for normal, triangle in zip(normals, corners):
                    out.write("  facet normal {:.9e} {:.9e} {:.9e}\n    outer loop\n".format(*normal))
                    for vertex in triangle:
                        out.write("      vertex {:.9e} {:.9e} {:.9e}\n".format(*vertex))
                    out.write("    endloop\n  endfacet\n")
                out.write("endsolid LIGGGHTS_STL_EXPORT\n")
        replace_atomically(self.pattern.frame(sim.step), write)
