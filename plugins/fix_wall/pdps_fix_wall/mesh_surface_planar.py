r"""Fix ``mesh/surface/planar``: a ``fix mesh/surface`` whose triangles all lie in one plane
(LIGGGHTS's fix mesh/surface/planar), as an insertion face (``fix insert/stream ... insertion_face``)
or a flat wall.

The mesh is read and placed as by fix mesh/surface (``pdps doc fix mesh/surface``: file, type,
scale, move, rotate, surface_vel, precision, heal, element_exclusion_list, temperature,
extrude_planar, curvature ...: every keyword of that fix); it is refused, with the distance of the farthest vertex, when
a vertex lies farther than :math:`10^{-8}` of the mesh's size from the plane of its first triangle.

Syntax::

    fix ID GROUP mesh/surface/planar file FILE|fix MESH_ID [the keywords of fix mesh/surface]

Example::

    fix inface all mesh/surface/planar file insertion_face.stl type 1
    fix top all mesh/surface/planar file lid.stl type 1 extrude_planar 0.06
    fix sides all mesh/surface fix top type 1
"""

from .mesh_surface import FixMeshSurface


class FixMeshSurfacePlanar(FixMeshSurface):
    name = "mesh/surface/planar"
    usage = FixMeshSurface.usage.replace("mesh/surface", "mesh/surface/planar", 1)

    def extra_keywords(self, sim, args):
        self.check_planar("use fix mesh/surface")
