r"""Fix ``mesh/surface``: a triangulated surface read from a file, which walls act through (LIGGGHTS's
fix mesh/surface): ``fix wall/gran ... mesh n_meshes N meshes ID ...`` or ``fix wall/mesh mesh ID``
make it a granular wall, ``fix move/mesh`` moves it, ``dump vtk ... walls yes`` writes it.

Geometry: the triangles of the file (STL ascii or binary, VTK, OBJ, ...: anything meshio reads; quads
are split in two), placed once by ``scale S`` (about the origin), ``move DX DY DZ`` (distance) and
``rotate axis AX AY AZ angle DEG`` (about the axis through the origin, right-hand rule, degrees) in
the order given, each as often as it is given. ``type N`` is the wall's material type (LIGGGHTS: the atom type whose
``fix property/global`` material the wall has; default 1).

Surface motion without moving the mesh (LIGGGHTS's conveyor keywords):

- ``surface_vel VX VY VZ``: on each triangle, the velocity projected onto its plane, scaled back to
  the given speed (velocity units).
- ``surface_ang_vel origin OX OY OZ axis AX AY AZ omega W``: the surface moves as if it turned with
  angular velocity W (rad/time) about the axis through O: :math:`\mathbf{v}_w = W\hat{\mathbf{a}}
  \times (\mathbf{p} - \mathbf{O})` at the contact point p (a shear cell).

Moving meshes: each ``fix move/mesh`` on this mesh is a rigid motion :math:`T_k(t): \mathbf{x} \mapsto
R_k\mathbf{x} + \mathbf{d}_k`, and several are superposed as LIGGGHTS's manual gives: the frame of each
moves along with the motions defined before it, :math:`\mathbf{X}(t) = T_1(T_2(\dots T_n(\mathbf{X}_0)))`
(so the origin of a second ``rotate`` turns with the first). The whole is one rigid motion
:math:`\mathbf{X} = R\mathbf{X}_0 + \mathbf{d}`, and the wall's velocity at a point p is
:math:`\dot{\mathbf{d}} + \boldsymbol\Omega\times(\mathbf{p} - \mathbf{d})` with
:math:`[\boldsymbol\Omega]_\times = \dot R R^T`: the velocity the contact law sees.

``fix mesh/surface/stress`` is this fix plus the forces on the mesh: see its module.

Syntax::

    fix ID GROUP mesh/surface file FILE [type N] [verbose yes|no] [heal no] [curvature DEG]
        [scale S] [move DX DY DZ] [rotate axis AX AY AZ angle DEG]
        [surface_vel VX VY VZ | surface_ang_vel origin OX OY OZ axis AX AY AZ omega W]

``curvature DEG``: a contact that moves onto a neighbouring triangle keeps its history (tangential
spring, rolling spring) when the two contact normals are within DEG degrees (default 5.73, a cosine
of 0.995: LIGGGHTS's default of 0.256 degrees would restart the friction of a sphere rolling around a
drum tessellated in facets of a few degrees). LIGGGHTS also uses it to decide edge and corner
contacts; pdps finds those from the geometry alone (fix wall/mesh's docstring).

The group is not used (the wall fix's group says which particles see the mesh). LIGGGHTS keywords
pdps does not honour are refused by name: ``precision`` and ``heal auto_remove_duplicates`` (meshio
merges only identical nodes), ``temperature`` (no heat conduction with walls),
``element_exclusion_list`` (every triangle of the file is kept).

Example::

    fix cad all mesh/surface file hopper.stl type 2 scale 0.001 move 0 0 0.1
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, keyword

from .mesh import (PlacedMeshArgs, Vector, belt_on_face, check_placement, face_normals, placed_mesh, rigid_velocity,
                   unit)
from .wall_contact import TRANSFER_COS

REFUSED = {
    "precision": "pdps merges only identical nodes (meshio)",
    "temperature": "pdps has no heat conduction with walls",
    "element_exclusion_list": "pdps keeps every triangle of the file",
}


@njit(cache=True)
def place_vertices(placed, rotation, shift, triangles, vertices, face_normal):
    """vertices = rotation placed + shift, and the faces' unit normals, in place (no temporaries:
    a moving mesh is placed at every step)."""
    for k in range(placed.shape[0]):
        for d in range(3):
            vertices[k, d] = (rotation[d, 0] * placed[k, 0] + rotation[d, 1] * placed[k, 1]
                              + rotation[d, 2] * placed[k, 2] + shift[d])
    for t in range(triangles.shape[0]):
        a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
        ux, uy, uz = vertices[b, 0] - vertices[a, 0], vertices[b, 1] - vertices[a, 1], vertices[b, 2] - vertices[a, 2]
        wx, wy, wz = vertices[c, 0] - vertices[a, 0], vertices[c, 1] - vertices[a, 1], vertices[c, 2] - vertices[a, 2]
        nx, ny, nz = uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx
        size = math.sqrt(nx * nx + ny * ny + nz * nz)
        face_normal[t, 0], face_normal[t, 1], face_normal[t, 2] = nx / size, ny / size, nz / size


def skew_axis(matrix):
    """The vector w of an antisymmetric matrix [w]x."""
    return np.array([matrix[2, 1], matrix[0, 2], matrix[1, 0]])


class FixMeshSurface(Fix):
    name = "mesh/surface"
    usage = ("fix ID GROUP mesh/surface file FILE [type N] [scale S] [move DX DY DZ] "
             "[rotate axis AX AY AZ angle DEG] [surface_vel VX VY VZ | "
             "surface_ang_vel origin OX OY OZ axis AX AY AZ omega W]")
    refused = REFUSED

    class Args(PlacedMeshArgs):
        file: str = keyword(...)
        type: int = keyword(1, unit="1")
        verbose: Literal["yes", "no"] = keyword("no")
        heal: Literal["no", "auto_remove_duplicates"] = keyword("no")
        curvature: float | None = keyword(None, unit="degrees")
        surface_vel: Vector | None = keyword(None, unit="velocity")
        surface_ang_vel: tuple[Literal["origin"], float, float, float, Literal["axis"], float, float, float,
                               Literal["omega"], float] | None = keyword(None, unit=(
                                   "1", "distance", "distance", "distance", "1", "1", "1", "1", "1", "angle/time"))

    @classmethod
    def check_args(cls, args):
        if args.heal != "no":
            raise ScriptError(f"heal {args.heal} is not supported (heal no only): pdps merges "
                              "only identical nodes (meshio)")
        check_placement(args.placement)
        if args.surface_vel is not None and args.surface_ang_vel is not None:
            raise ScriptError("surface_vel and surface_ang_vel cannot both be given")
        if args.surface_ang_vel is not None:
            unit(args.surface_ang_vel[5:8], "surface_ang_vel axis")
        if args.curvature is not None and not 0.0 < args.curvature <= 90.0:
            raise ScriptError(f"curvature must be in (0, 90] degrees (got {args.curvature:g})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if not 1 <= args.type <= sim.ntypes:
            raise ScriptError(f"type must be from 1 to {sim.ntypes}, the number of types (got {args.type})")
        self.file = args.file
        self.material_type = args.type
        self.placed, self.triangles = placed_mesh(sim, args.file, args.placement)
        self.vertices = self.placed.copy()
        self.face_normal = face_normals(self.vertices, self.triangles)
        self.velocity, self.spin, self.pivot = np.zeros(3), np.zeros(3), np.zeros(3)
        self.conveyor = args.surface_vel is not None
        self.belt = np.array(args.surface_vel or (0.0, 0.0, 0.0))
        if args.surface_ang_vel is not None:
            words = args.surface_ang_vel
            self.pivot = np.array(words[1:4])
            self.spin = unit(words[5:8], "surface_ang_vel axis") * words[9]
        self.transfer_cos = TRANSFER_COS if args.curvature is None else math.cos(math.radians(args.curvature))
        self.surface_motion = self.conveyor or args.surface_ang_vel is not None
        self.moving = False
        self.movers = []
        self.extra_keywords(sim, args)

    def extra_keywords(self, sim, args):
        """What a derived style makes of its own keywords (mesh/surface/stress), or its checks of
        the mesh read (mesh/surface/planar)."""

    # ---- motion: fix move/mesh registers here and calls place() after each step's advance ----
    def add_mover(self, mover):
        if self.surface_motion:
            raise ScriptError(f"fix mesh/surface {self.id} has surface_vel or surface_ang_vel: a conveyor "
                              "cannot also be moved (LIGGGHTS)")
        self.movers.append(mover)
        self.moving = True

    def settle(self):
        """Its one motion unfixed: the mesh stays where it is, at rest, the base of later motions."""
        self.placed = self.vertices.copy()
        self.movers = []
        self.moving = False
        self.velocity, self.spin, self.pivot = np.zeros(3), np.zeros(3), np.zeros(3)

    def place(self):
        """Vertices, face normals and the wall's rigid velocity from the movers' poses now."""
        # X = T_1(T_2(...T_n(X0))): compose from the innermost (the last defined) outwards
        rotation, shift, turning, drift = self.movers[-1].pose()
        for mover in reversed(self.movers[:-1]):
            r_k, d_k, rdot_k, ddot_k = mover.pose()
            turning, drift = rdot_k @ rotation + r_k @ turning, rdot_k @ shift + r_k @ drift + ddot_k
            rotation, shift = r_k @ rotation, r_k @ shift + d_k
        place_vertices(self.placed, rotation, shift, self.triangles, self.vertices, self.face_normal)
        self.velocity = drift
        self.spin = skew_axis(turning @ rotation.T)
        self.pivot = shift

    def face_velocity(self):
        """The wall velocity at each triangle's centre (a conveyor's belt velocity on the face, or
        the rigid motion's), (m, 3)."""
        centre = self.vertices[self.triangles].mean(axis=1)
        out = np.empty_like(centre)
        for t in range(len(centre)):
            if self.conveyor:
                belt_on_face(self.belt, self.face_normal[t], out[t])
            else:
                rigid_velocity(centre[t], self.velocity, self.spin, self.pivot, out[t])
        return out

    def tally(self):
        """What a wall adds its forces on this mesh to: nothing (mesh/surface/stress sums them)."""
        return None

    def box_extent(self, sim):
        """A shrink-wrapped box encloses the mesh's nodes as they are now (LIGGGHTS's FixMesh)."""
        corners = self.vertices[self.triangles].reshape(-1, 3)
        return corners.min(axis=0), corners.max(axis=0)

    def face_areas(self):
        corners = self.vertices[self.triangles]
        return 0.5 * np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0],
                                             corners[:, 2] - corners[:, 0]), axis=1)

