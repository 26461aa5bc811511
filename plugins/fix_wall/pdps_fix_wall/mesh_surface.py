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

    fix ID GROUP mesh/surface file FILE | fix MESH_ID
        [type N] [verbose yes|no] [heal no|auto_remove_duplicates] [precision P]
        [element_exclusion_list read|write LIST] [min_feature_length L]
        [scale S] [move DX DY DZ] [rotate axis AX AY AZ angle DEG]
        [temperature T0] [mass_temperature M] [extrude_planar L]
        [surface_vel VX VY VZ | surface_ang_vel origin OX OY OZ axis AX AY AZ omega W]
        [curvature DEG] [curvature_tolerant yes|no]

The keywords stand in any order (LIGGGHTS wants them in the order above).

``fix MESH_ID`` instead of ``file FILE``: the mesh is the walls a ``fix mesh/surface ...
extrude_planar L`` swept from its planar mesh (LIGGGHTS makes them at a ``run 0`` in between, which
pdps does not need). ``extrude_planar`` needs a planar mesh.

Reading checks (``precision``, ``heal``, ``element_exclusion_list``, ``min_feature_length``,
``curvature_tolerant``) and the extrusion are LIGGGHTS's: ``pdps_fix_wall.mesh_quality``'s
docstring. ``curvature DEG`` (in (0, 60], as LIGGGHTS): a contact that moves onto a neighbouring
triangle keeps its history (tangential spring, rolling spring) when the two contact normals are
within DEG degrees (default 5.73, a cosine of 0.995: LIGGGHTS's default of 0.256 degrees would restart
the friction of a sphere rolling around a drum tessellated in facets of a few degrees); the reading
check compares the triangles' angles with the DEG given, or with LIGGGHTS's 0.256 degrees. LIGGGHTS
also uses it to decide edge and corner contacts; pdps finds those from the geometry alone (fix
wall/mesh's docstring).

``temperature T0``: the wall's temperature (temperature units) for the heat conduction of fix
heat/gran: each contact of a wall/gran wall on this mesh carries :math:`Q = \frac{4k_pk_w}{k_p +
k_w}\sqrt{A}\,(T_0 - T_p)` into the particle (k of the particle's and of the mesh's type, A by fix
heat/gran's contact_area: overlap :math:`\pi(R^2 - d^2)` at centre distance d, projection
:math:`\pi R^2`, or the constant). ``mass_temperature M`` (mass units, > 0) is read and has no effect,
as in LIGGGHTS 3.8.0 (it warms the wall by the heat flux summed into the mesh, which nothing sums
there: measured, the run is the same without it); pdps says so in a warning.

The group is not used (the wall fix's group says which particles see the mesh).

Example::

    fix cad all mesh/surface file hopper.stl type 2 scale 0.001 move 0 0 0.1
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pydantic import PositiveFloat

from pdps_core.api import Fix, ScriptError, keyword

from . import mesh_quality
from .mesh import (PlacedMeshArgs, Vector, apply_placement, belt_on_face, check_placement, face_normals, mesh_fix,
                   read_triangles, rigid_velocity, unit)
from .wall_contact import TRANSFER_COS

PLANAR_TOLERANCE = 1e-8


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
    usage = ("fix ID GROUP mesh/surface file FILE|fix MESH_ID [type N] [heal no|auto_remove_duplicates] "
             "[precision P] [element_exclusion_list read|write LIST] [scale S] [move DX DY DZ] "
             "[rotate axis AX AY AZ angle DEG] [temperature T0] [extrude_planar L] [surface_vel VX VY VZ | "
             "surface_ang_vel origin OX OY OZ axis AX AY AZ omega W] [curvature DEG] [curvature_tolerant yes|no]")

    class Args(PlacedMeshArgs):
        file: str | None = keyword(None)
        fix: str | None = keyword(None, names="fix mesh/surface ID")
        type: int = keyword(1, unit="1")
        verbose: Literal["yes", "no"] = keyword("no")
        heal: Literal["no", "auto_remove_duplicates"] = keyword("no")
        precision: float | None = keyword(None, unit="distance")
        element_exclusion_list: tuple[Literal["read", "write"], str] | None = keyword(None)
        min_feature_length: float | None = keyword(None, unit="distance")
        temperature: float | None = keyword(None, unit="temperature")
        mass_temperature: float | None = keyword(None, unit="mass")
        extrude_planar: PositiveFloat | None = keyword(None, unit="distance")
        curvature: float | None = keyword(None, unit="degrees")
        curvature_tolerant: bool = keyword(False)
        surface_vel: Vector | None = keyword(None, unit="velocity")
        surface_ang_vel: tuple[Literal["origin"], float, float, float, Literal["axis"], float, float, float,
                               Literal["omega"], float] | None = keyword(None, unit=(
                                   "1", "distance", "distance", "distance", "1", "1", "1", "1", "1", "angle/time"))

    @classmethod
    def check_args(cls, args):
        if (args.file is None) == (args.fix is None):
            given = "both" if args.file is not None else "neither"
            raise ScriptError(f"expected file FILE or fix MESH_ID (got {given}); usage: {cls.usage}")
        if args.precision is not None and not 0.0 < args.precision <= mesh_quality.LARGEST_PRECISION:
            raise ScriptError(f"precision must be in (0, 0.001] (got {args.precision:g})")
        if args.min_feature_length is not None:
            if not args.min_feature_length > 0.0:
                raise ScriptError(f"min_feature_length must be > 0 (got {args.min_feature_length:g})")
            if args.element_exclusion_list is None or args.element_exclusion_list[0] != "write":
                raise ScriptError("min_feature_length needs element_exclusion_list write FILE (LIGGGHTS)")
            raise ScriptError("min_feature_length is not supported: LIGGGHTS 3.8.0 has no feature removal either "
                              "('surface mesh feature remove not available in this version')")
        if args.element_exclusion_list is not None and args.fix is not None:
            raise ScriptError("element_exclusion_list numbers the lines of a mesh file: not with fix MESH_ID")
        if args.mass_temperature is not None and not args.mass_temperature > 0.0:
            raise ScriptError(f"mass_temperature must be > 0 (got {args.mass_temperature:g})")
        check_placement(args.placement)
        if args.surface_vel is not None and args.surface_ang_vel is not None:
            raise ScriptError("surface_vel and surface_ang_vel cannot both be given")
        if args.surface_ang_vel is not None:
            unit(args.surface_ang_vel[5:8], "surface_ang_vel axis")
        if args.curvature is not None and not 0.0 < args.curvature <= 60.0:
            raise ScriptError(f"curvature must be in (0, 60] degrees (got {args.curvature:g})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if not 1 <= args.type <= sim.ntypes:
            raise ScriptError(f"type must be from 1 to {sim.ntypes}, the number of types (got {args.type})")
        self.file = args.file if args.file is not None else f"fix {args.fix}"
        self.material_type = args.type
        self.placed, self.triangles = self.read_mesh(sim, args)
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
        self.temperature = args.temperature
        if args.mass_temperature is not None:
            sim.warn(f"fix {id} ({self.name}): mass_temperature has no effect, as in LIGGGHTS 3.8.0 (nothing sums "
                     "the heat flux into a mesh there): the wall stays at its temperature")
        self.extrusion_length = args.extrude_planar
        if self.extrusion_length is not None:
            self.check_planar()
        self.extra_keywords(sim, args)

    def read_mesh(self, sim, args):
        """(vertices, triangles) of the file or of the walls another fix extruded, with LIGGGHTS's
        reading checks and repairs (mesh_quality)."""
        precision = self.precision = (mesh_quality.DEFAULT_PRECISION if args.precision is None
                                      else args.precision)
        listing = args.element_exclusion_list
        if args.fix is not None:
            source = mesh_fix(sim, args.fix)
            if getattr(source, "extrusion_length", None) is None:
                raise ScriptError(f"fix {args.fix} extrudes no walls (give it extrude_planar L)")
            corners = source.extruded_corners()
            points = corners.reshape(-1, 3)
            triangles = np.arange(len(points), dtype=np.int64).reshape(-1, 3)
            lines, numbered = np.arange(1, len(triangles) + 1, dtype=np.int64), False
        else:
            path = sim.resolve(args.file)
            points, triangles, index = read_triangles(path, args.file, with_index=True)
            try:
                lines = mesh_quality.element_lines(path, args.file, int(index.max()) + 1)[index]
                numbered = True
            except ScriptError:
                if listing is not None:
                    raise
                lines, numbered = index + 1, False
            if listing is not None and listing[0] == "read":
                excluded = mesh_quality.read_exclusion_list(sim.resolve(listing[1]), listing[1])
                kept = ~np.isin(lines, excluded)
                triangles, lines = triangles[kept], lines[kept]
                if len(triangles) == 0:
                    raise ScriptError(f"element exclusion list {listing[1]} leaves no triangle of {args.file}")
        if args.heal == "auto_remove_duplicates":
            kept = mesh_quality.healed(points[triangles], precision)
            triangles, lines = triangles[kept], lines[kept]
        points = apply_placement(points, args.placement)
        writing = listing is not None and listing[0] == "write"
        curvature_cos = (mesh_quality.DEFAULT_CURVATURE_COS if args.curvature is None
                         else math.cos(math.radians(args.curvature)))
        pairs = mesh_quality.check_mesh(self.id, self.file, points[triangles], lines, precision, curvature_cos,
                                args.curvature_tolerant, args.heal != "no", numbered,
                                (listing[1], sim.resolve(listing[1]) if sim.comm.rank == 0 else None) if writing
                                else None, sim.warn)
        if len(pairs):
            triangles = triangles[mesh_quality.first_of_duplicates(len(triangles), pairs)]
        return points, triangles

    def check_planar(self, remedy="extrude_planar needs a planar mesh"):
        """A ScriptError when a vertex lies farther than 1e-8 of the mesh's size from the plane of its
        first triangle."""
        origin = self.placed[self.triangles[0, 0]]
        distance = np.abs((self.placed[self.triangles].reshape(-1, 3) - origin) @ self.face_normal[0])
        size = float(np.ptp(self.placed, axis=0).max())
        if distance.max() > PLANAR_TOLERANCE * size:
            raise ScriptError(f"mesh file {self.file} is not planar: a vertex lies {distance.max():.3g} from the "
                              f"plane of its first triangle ({remedy})")

    def extruded_corners(self):
        """The walls extrude_planar sweeps from the mesh's boundary, as the mesh is now."""
        return mesh_quality.extruded_corners(self.vertices[self.triangles], self.extrusion_length, self.precision)

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

