r"""Fix ``mesh/surface/planar``: a ``fix mesh/surface`` whose triangles all lie in one plane
(LIGGGHTS's fix mesh/surface/planar), as an insertion face (``fix insert/stream ... insertion_face``)
or a flat wall.

The mesh is read and placed as by fix mesh/surface (``pdps doc fix mesh/surface``: file, type,
scale, move, rotate, surface_vel ...); it is refused, with the distance of the farthest vertex, when
a vertex lies farther than :math:`10^{-8}` of the mesh's size from the plane of its first triangle.

Syntax::

    fix ID GROUP mesh/surface/planar file FILE [type N] [scale S] [move DX DY DZ] [rotate axis AX AY AZ angle DEG]

Example::

    fix inface all mesh/surface/planar file insertion_face.stl type 1
"""

import numpy as np

from pdps_core.api import ScriptError

from .mesh_surface import FixMeshSurface

PLANAR_TOLERANCE = 1e-8


class FixMeshSurfacePlanar(FixMeshSurface):
    name = "mesh/surface/planar"
    usage = ("fix ID GROUP mesh/surface/planar file FILE [type N] [scale S] [move DX DY DZ] "
             "[rotate axis AX AY AZ angle DEG]")

    def extra_keywords(self, sim, args):
        origin = self.placed[self.triangles[0, 0]]
        distance = np.abs((self.placed - origin) @ self.face_normal[0])
        size = float(np.ptp(self.placed, axis=0).max())
        if distance.max() > PLANAR_TOLERANCE * size:
            raise ScriptError(f"mesh file {self.file} is not planar: a vertex lies {distance.max():.3g} from the "
                              "plane of its first triangle (use fix mesh/surface)")
