r"""Fix ``wall/mesh``: granular walls from a triangulated surface file (STL, VTK, OBJ, ...: anything
meshio reads), fixed or moving (LIGGGHTS's fix mesh/surface with fix wall/gran, in one command).

Geometry. The file's triangles are the wall (quads are split in two; other cells are ignored). The
surface is two-sided: a sphere of radius :math:`R_i` touches it wherever a point :math:`\mathbf{p}`
of the mesh is closer than :math:`R_i` to its centre :math:`\mathbf{x}_i` and is a *local* closest
point: the closest point of every triangle that contains it (found per triangle with the
closest-point-on-triangle construction, face, edge or corner). Overlap :math:`\delta = R_i -
|\mathbf{x}_i - \mathbf{p}|`, normal :math:`\mathbf{n} = (\mathbf{x}_i - \mathbf{p})/|\mathbf{x}_i -
\mathbf{p}|`. So a sphere over an edge or a corner shared by several triangles gets one contact,
with the normal from that edge or corner (duplicates of one point are merged, and an edge point of
one triangle that lies on a neighbour whose closest point is elsewhere is no contact), while a sphere
in a valley touching two faces gets two. A sphere whose centre passes through the surface is pushed
out on the other side. Meshes are not repeated across periodic boundaries.

Contact law (``pdps_granular_contact.contact_models``, the wall being body j with infinite mass and
radius, so :math:`m^* = m_i`, :math:`R^* = R_i`):

- ``model lsd e kn Cn kt Ct mu``: linear spring-dashpot with Coulomb friction, as fix wall/dem (PDPS's
  parameter order; ``e`` is read and not used, the damping is ``Cn``); ``model lsd e kn mu``: ``Cn``
  from the restitution coefficient for each particle's mass, :math:`k_t = \tfrac27 k_n`,
  :math:`C_t = C_n/2` (LAMMPS's gran/hooke defaults). Units: kn, kt force/distance; Cn, Ct
  force/velocity.
- ``model hertz Y nu e mu``: Hertz-Mindlin with wall and particles of one material, Young's modulus
  ``Y`` (pressure), Poisson ratio ``nu``, :math:`E^* = Y/2(1-\nu^2)`, :math:`G^* = Y/4(2-\nu)(1+\nu)`,
  damping from the restitution coefficient ``e`` (LIGGGHTS's hertz model).

Relative velocity of the contact points :math:`\mathbf{v} = \mathbf{v}_i + \boldsymbol\omega_i \times
(-R_i\mathbf{n}) - \mathbf{v}_w(\mathbf{p})`; force on i from the law, torque :math:`(-R_i\mathbf{n})
\times \mathbf{F}`. The tangential spring of each contact is kept per particle and triangle, and
taken over by the next triangle as a sphere rolls across a tessellated surface.

Placement, applied once in the order given (LIGGGHTS), each as often as it is given: ``scale S``
(about the origin), ``move DX DY DZ`` (distance), ``rotate axis AX AY AZ angle DEG`` (about the axis
through the origin, right-hand rule, degrees).

Motion:

- ``velocity VX VY VZ``: the mesh translates (velocity units).
- ``omega WX WY WZ about PX PY PZ``: the mesh rotates with angular velocity :math:`\boldsymbol\omega`
  (rad/time; its direction is the axis, right-hand rule) about the axis through the point P (which
  moves with ``velocity`` if both are given): a stirrer. The wall's velocity at a contact point is
  :math:`\mathbf{v}_w = \mathbf{V} + \boldsymbol\omega\times(\mathbf{p} - \mathbf{P}(t))`.
- ``surface_vel VX VY VZ``: a conveyor belt (LIGGGHTS's ``surface_vel``): the mesh stays where it is,
  its surface moves: on each triangle, with the given velocity projected onto the triangle's plane and
  scaled back to the given speed. Not together with ``velocity`` or ``omega``.

A moving mesh's clock (the time it has moved for) is saved in restart files and restored with the
fix, also when a script gives the fix again after ``read_restart``.

Cost: triangles are binned on a grid of cells at least the largest radius plus the skin wide, and
each particle keeps the triangles whose bounding box is within its radius plus the skin; the lists
are rebuilt only when a particle or a mesh vertex has moved more than half the skin
(``neighbor SKIN``) since, or particles were re-sorted. Between rebuilds only the particles with
candidate triangles are visited (the wall contacts of the others are closed at the rebuild).

``mesh MESH_ID`` instead of ``file FILE`` (and no placement or motion keywords): the wall is the
surface of a ``fix mesh/surface`` (moved by ``fix move/mesh``; forces summed by
``fix mesh/surface/stress``).

Errors: a missing file, an empty file or a file with no triangles gives one line naming the file.
Particles need radii (``particle_style sphere``); with ``omega`` and ``torque`` they also spin.

Syntax::

    fix ID GROUP wall/mesh mesh MESH_ID model ...
    fix ID GROUP wall/mesh file FILE [scale S] [move DX DY DZ] [rotate axis AX AY AZ angle DEG]
        [velocity VX VY VZ] [omega WX WY WZ about PX PY PZ] [surface_vel VX VY VZ]
        model lsd e kn Cn kt Ct mu | model lsd e kn mu | model hertz Y nu e mu

The keywords stand in any order.

Example::

    fix chute all wall/mesh file chute.stl scale 0.001 rotate axis 0 1 0 angle 30 model lsd 0.8 2e5 0.3
    fix stir all wall/mesh file blade.stl omega 0 0 6.283 about 0 0 0 model hertz 5e6 0.3 0.7 0.5
"""

import contextlib
import io
import math
from types import SimpleNamespace
import os
from typing import Literal

import meshio
import numpy as np
from numba import njit

from pdps_core.api import ContactHistory, Fix, MeshSurface, ScriptError, StyleArgs, keyword, observables

from .wall_contact import HISTORY_WIDTH, TRANSFER_COS, ContactLaw, WallContactTable, check_law_numbers, forget_far

MAX_CELLS_PER_AXIS = 64
MERGE_TOLERANCE = 1e-9      # points this close (relative to the radius plus the coordinates) are one


# ---- reading and placing the mesh ---------------------------------------------------------------
def read_triangles(path, shown, with_index=False):
    """(vertices n x 3, triangles m x 3) of a surface mesh file; ScriptError naming ``shown``. With
    ``with_index``, also the place of each triangle among the file's (those of zero area are left
    out)."""
    if not os.path.isfile(path):
        raise ScriptError(f"mesh file {shown} does not exist")
    if os.path.getsize(path) == 0:
        raise ScriptError(f"mesh file {shown} is empty")
    try:
        # meshio reports format guesses on stderr; the user gets one line from us instead
        with contextlib.redirect_stderr(io.StringIO()), np.errstate(all="ignore"):
            mesh = meshio.read(path)
    except Exception as exc:
        reason = " ".join(str(exc).split()) or type(exc).__name__
        raise ScriptError(f"mesh file {shown} cannot be read as a surface mesh: {reason}") from None
    points = np.asarray(mesh.points, dtype=np.float64)
    if points.ndim == 2 and points.shape[1] == 2:
        points = np.column_stack([points, np.zeros(len(points))])
    blocks = []
    for cells in mesh.cells:
        data = np.asarray(cells.data, dtype=np.int64)
        if cells.type == "triangle":
            blocks.append(data)
        elif cells.type == "quad":
            blocks += [data[:, [0, 1, 2]], data[:, [0, 2, 3]]]
    triangles = np.concatenate(blocks) if blocks else np.zeros((0, 3), dtype=np.int64)
    index = np.arange(len(triangles))
    if len(triangles):
        corners = points[triangles]
        area = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]),
                              axis=1)
        triangles, index = triangles[area > 0.0], index[area > 0.0]
    if len(triangles) == 0:
        raise ScriptError(f"mesh file {shown} has no triangles: not a surface mesh")
    return (points, triangles, index) if with_index else (points, triangles)


def rotation_matrix(axis, angle):
    """Rodrigues' rotation by ``angle`` (rad) about the unit vector ``axis``."""
    ax, ay, az = axis
    k = np.array([[0.0, -az, ay], [az, 0.0, -ax], [-ay, ax, 0.0]])
    return np.eye(3) + math.sin(angle) * k + (1.0 - math.cos(angle)) * (k @ k)


def unit(vector, what):
    vector = np.asarray(vector, dtype=np.float64)
    length = float(np.linalg.norm(vector))
    if length == 0.0:
        raise ScriptError(f"{what} must not be zero")
    return vector / length


# ---- script words shared by the mesh styles ------------------------------------------------------
Placement = (tuple[Literal["scale"], float] | tuple[Literal["move"], float, float, float]
             | tuple[Literal["rotate"], Literal["axis"], float, float, float, Literal["angle"], float])
Vector = tuple[float, float, float]


class PlacedMeshArgs(StyleArgs):
    """``scale S``, ``move DX DY DZ``, ``rotate axis AX AY AZ angle DEG``: each may be given again,
    and all are applied once in the order written (LIGGGHTS)."""
    placement: list[Placement] = keyword(default_factory=list, spelled_by_entries=True, unit={
        "scale": "1", "move": "distance", "rotate": ("1", "degrees")})


def check_placement(placement):
    """A one-line error for a scale that is not > 0 or a rotation axis of zero length."""
    for word, *values in placement:
        if word == "scale" and not values[0] > 0.0:
            raise ScriptError(f"scale must be > 0 (got {values[0]:g})")
        if word == "rotate":
            unit(values[1:4], "rotate axis")


def placed_mesh(sim, shown, placement):
    """(vertices, triangles) of the mesh file ``shown``, scaled, moved and rotated once in the
    order given (LIGGGHTS's fix mesh/surface)."""
    points, triangles = read_triangles(sim.resolve(shown), shown)
    return apply_placement(points, placement), triangles


def apply_placement(points, placement):
    """``points`` scaled, moved and rotated in the order given."""
    for word, *values in placement:
        if word == "scale":
            points = points * values[0]
        elif word == "move":
            points = points + values
        else:
            axis = unit(values[1:4], "rotate axis")
            points = points @ rotation_matrix(axis, math.radians(values[5])).T
    return np.ascontiguousarray(points)


# the contact law: PDPS's lsd, lsd from the restitution coefficient, LIGGGHTS's hertz
LawWords = (tuple[Literal["lsd"], float, float, float, float, float, float]
            | tuple[Literal["lsd"], float, float, float] | tuple[Literal["hertz"], float, float, float, float])
LAW_UNITS = {"lsd e kn Cn kt Ct mu": ("1", "force/distance", "force/velocity", "force/distance", "force/velocity", "1"),
             "lsd e kn mu": ("1", "force/distance", "1"), "hertz Y nu e mu": ("pressure", "1", "1", "1")}


def contact_law(words):
    """The ContactLaw of ``model ...`` words read into LawWords; one-line errors for bad values."""
    model, *values = words
    if model == "lsd" and len(values) == 6:
        e, kn, cn, kt, ct, mu = values
        check_law_numbers(e=e, kn=kn, cn=cn, kt=kt, ct=ct, mu=mu)
        return ContactLaw.lsd(kn, mu, e=e, cn=cn, kt=kt, ct=ct)
    if model == "lsd":
        e, kn, mu = values
        check_law_numbers(e=e, kn=kn, mu=mu)
        return ContactLaw.lsd(kn, mu, e=e)
    youngs, poisson, e, mu = values
    if not youngs > 0.0:
        raise ScriptError(f"Y must be > 0 (got {youngs:g})")
    if not -1.0 < poisson < 0.5:
        raise ScriptError(f"nu must be in (-1, 0.5) (got {poisson:g})")
    check_law_numbers(e=e, mu=mu)
    return ContactLaw.hertz(youngs, poisson, e, mu)


def mesh_fix(sim, ident):
    """The fix mesh/surface (or mesh/surface/stress) named ``ident``, or a one-line error."""
    fix = sim.fixes.get(ident)
    if fix is None:
        raise ScriptError(f"fix {ident} is not defined (expected the ID of a fix mesh/surface)")
    if not isinstance(fix, MeshSurface):
        raise ScriptError(f"fix {ident} ({fix.name}) is not a fix mesh/surface")
    return fix


def face_normals(vertices, triangles):
    """Unit normals of the triangles (right-hand rule over their corners' order)."""
    corners = vertices[triangles]
    normal = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    return np.ascontiguousarray(normal / np.linalg.norm(normal, axis=1)[:, None])



# ---- geometry kernels ---------------------------------------------------------------------------
@njit(cache=True)
def closest_on_triangle(px, py, pz, a, b, c, out):
    """Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5) into
    ``out``; returns True when it is inside the face, False on an edge or a corner."""
    abx, aby, abz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
    acx, acy, acz = c[0] - a[0], c[1] - a[1], c[2] - a[2]
    apx, apy, apz = px - a[0], py - a[1], pz - a[2]
    d1 = abx * apx + aby * apy + abz * apz
    d2 = acx * apx + acy * apy + acz * apz
    if d1 <= 0.0 and d2 <= 0.0:
        out[0], out[1], out[2] = a[0], a[1], a[2]
        return False
    bpx, bpy, bpz = px - b[0], py - b[1], pz - b[2]
    d3 = abx * bpx + aby * bpy + abz * bpz
    d4 = acx * bpx + acy * bpy + acz * bpz
    if d3 >= 0.0 and d4 <= d3:
        out[0], out[1], out[2] = b[0], b[1], b[2]
        return False
    vc = d1 * d4 - d3 * d2
    if vc <= 0.0 and d1 >= 0.0 and d3 <= 0.0:
        t = d1 / (d1 - d3)
        out[0], out[1], out[2] = a[0] + t * abx, a[1] + t * aby, a[2] + t * abz
        return False
    cpx, cpy, cpz = px - c[0], py - c[1], pz - c[2]
    d5 = abx * cpx + aby * cpy + abz * cpz
    d6 = acx * cpx + acy * cpy + acz * cpz
    if d6 >= 0.0 and d5 <= d6:
        out[0], out[1], out[2] = c[0], c[1], c[2]
        return False
    vb = d5 * d2 - d1 * d6
    if vb <= 0.0 and d2 >= 0.0 and d6 <= 0.0:
        t = d2 / (d2 - d6)
        out[0], out[1], out[2] = a[0] + t * acx, a[1] + t * acy, a[2] + t * acz
        return False
    va = d3 * d6 - d5 * d4
    if va <= 0.0 and d4 - d3 >= 0.0 and d5 - d6 >= 0.0:
        t = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        out[0] = b[0] + t * (c[0] - b[0])
        out[1] = b[1] + t * (c[1] - b[1])
        out[2] = b[2] + t * (c[2] - b[2])
        return False
    scale = 1.0 / (va + vb + vc)
    v = vb * scale
    w = vc * scale
    out[0] = a[0] + v * abx + w * acx
    out[1] = a[1] + v * aby + w * acy
    out[2] = a[2] + v * abz + w * acz
    return True


@njit(cache=True)
def bin_triangles(box_lo, box_hi, grid_lo, cell, nbins, margin):
    """Cells (CSR) listing the triangles whose bounding box, widened by ``margin``, meets them."""
    ntri = box_lo.shape[0]
    ncells = nbins[0] * nbins[1] * nbins[2]
    counts = np.zeros(ncells + 1, dtype=np.int64)
    lo_cell = np.empty((ntri, 3), dtype=np.int64)
    hi_cell = np.empty((ntri, 3), dtype=np.int64)
    for t in range(ntri):
        for d in range(3):
            lo_cell[t, d] = min(max(int((box_lo[t, d] - margin - grid_lo[d]) / cell[d]), 0), nbins[d] - 1)
            hi_cell[t, d] = min(max(int((box_hi[t, d] + margin - grid_lo[d]) / cell[d]), 0), nbins[d] - 1)
        for ix in range(lo_cell[t, 0], hi_cell[t, 0] + 1):
            for iy in range(lo_cell[t, 1], hi_cell[t, 1] + 1):
                for iz in range(lo_cell[t, 2], hi_cell[t, 2] + 1):
                    counts[(ix * nbins[1] + iy) * nbins[2] + iz + 1] += 1
    for k in range(ncells):
        counts[k + 1] += counts[k]
    fill = counts[:-1].copy()
    members = np.empty(counts[ncells], dtype=np.int64)
    for t in range(ntri):
        for ix in range(lo_cell[t, 0], hi_cell[t, 0] + 1):
            for iy in range(lo_cell[t, 1], hi_cell[t, 1] + 1):
                for iz in range(lo_cell[t, 2], hi_cell[t, 2] + 1):
                    k = (ix * nbins[1] + iy) * nbins[2] + iz
                    members[fill[k]] = t
                    fill[k] += 1
    return counts, members


@njit(cache=True)
def cell_of(x, i, grid_lo, cell, nbins):
    """Flat index of the grid cell holding particle i, or -1 outside the grid."""
    flat = 0
    for d in range(3):
        c = int(math.floor((x[i, d] - grid_lo[d]) / cell[d]))
        if c < 0 or c >= nbins[d]:
            return -1
        flat = flat * nbins[d] + c
    return flat


@njit(cache=True)
def box_gap_sq(x, i, lo, hi):
    """Squared distance from particle i to the box [lo, hi]."""
    gap = 0.0
    for d in range(3):
        if x[i, d] < lo[d]:
            gap += (lo[d] - x[i, d]) ** 2
        elif x[i, d] > hi[d]:
            gap += (x[i, d] - hi[d]) ** 2
    return gap


@njit(cache=True)
def candidate_triangles(x, chosen, reach, box_lo, box_hi, grid_lo, cell, nbins, cell_start,
                        cell_members):
    """For each chosen particle, the triangles whose bounding box is closer than its reach (CSR)."""
    n = len(chosen)
    offsets = np.zeros(n + 1, dtype=np.int64)
    for k in range(n):
        i = chosen[k]
        flat = cell_of(x, i, grid_lo, cell, nbins)
        found = 0
        if flat >= 0:
            for m in range(cell_start[flat], cell_start[flat + 1]):
                t = cell_members[m]
                if box_gap_sq(x, i, box_lo[t], box_hi[t]) < reach[i] * reach[i]:
                    found += 1
        offsets[k + 1] = offsets[k] + found
    candidates = np.empty(offsets[n], dtype=np.int64)
    for k in range(n):
        i = chosen[k]
        flat = cell_of(x, i, grid_lo, cell, nbins)
        slot = offsets[k]
        if flat >= 0:
            for m in range(cell_start[flat], cell_start[flat + 1]):
                t = cell_members[m]
                if box_gap_sq(x, i, box_lo[t], box_hi[t]) < reach[i] * reach[i]:
                    candidates[slot] = t
                    slot += 1
    return offsets, candidates


@njit(cache=True)
def largest_move_sq(x, rows, built):
    """Largest squared distance of the points ``x[rows]`` from where they were (``built``)."""
    largest = 0.0
    for k in range(len(rows)):
        i = rows[k]
        moved = 0.0
        for d in range(3):
            moved += (x[i, d] - built[k, d]) ** 2
        largest = max(largest, moved)
    return largest


@njit(cache=True)
def separation(p, a, q, b):
    """Distance between row a of p and row b of q (3-vectors)."""
    return math.sqrt((p[a, 0] - q[b, 0]) ** 2 + (p[a, 1] - q[b, 1]) ** 2 + (p[a, 2] - q[b, 2]) ** 2)


@njit(cache=True)
def belt_on_face(belt, face_normal, out):
    """A conveyor's surface velocity on a face: the belt velocity projected onto the face's plane,
    at the belt's speed (LIGGGHTS's surface_vel)."""
    along = belt[0] * face_normal[0] + belt[1] * face_normal[1] + belt[2] * face_normal[2]
    in_plane = 0.0
    for d in range(3):
        out[d] = belt[d] - along * face_normal[d]
        in_plane += out[d] * out[d]
    speed = math.sqrt(belt[0] * belt[0] + belt[1] * belt[1] + belt[2] * belt[2])
    scale = speed / math.sqrt(in_plane) if in_plane > 0.0 else 0.0
    for d in range(3):
        out[d] *= scale


@njit(cache=True)
def rigid_velocity(point, velocity, spin, pivot, out):
    """Velocity of a point of a mesh moving with ``velocity`` and turning with ``spin`` about the
    axis through ``pivot``: V + omega x (p - P)."""
    rx, ry, rz = point[0] - pivot[0], point[1] - pivot[1], point[2] - pivot[2]
    out[0] = velocity[0] + spin[1] * rz - spin[2] * ry
    out[1] = velocity[1] + spin[2] * rx - spin[0] * rz
    out[2] = velocity[2] + spin[0] * ry - spin[1] * rx


@njit(cache=True)
def tally_wall_forces(count, key, touch, contact_force, i, x, v, wall_velocity, face_normal, ptype,
                      dt, reference, face_force, mesh_torque, wear_k, face_wear, face_area):
    """Add the forces on the wall (minus each contact's force on particle i) to their triangles,
    and their torque about ``reference``; with ``wear_k`` (Finnie's k per particle type, empty: no
    wear) each contact's wear 2 k |v_rel| |F| f(gamma) dt / A to its triangle
    (fix mesh/surface/stress)."""
    for c in range(count):
        t = key[c]
        fx, fy, fz = -contact_force[c, 0], -contact_force[c, 1], -contact_force[c, 2]
        face_force[t, 0] += fx
        face_force[t, 1] += fy
        face_force[t, 2] += fz
        rx = touch[c, 0] - reference[0]
        ry = touch[c, 1] - reference[1]
        rz = touch[c, 2] - reference[2]
        mesh_torque[0] += ry * fz - rz * fy
        mesh_torque[1] += rz * fx - rx * fz
        mesh_torque[2] += rx * fy - ry * fx
        if len(wear_k) == 0:
            continue
        # Finnie: only a particle moving towards its contact point wears the wall
        u0 = v[i, 0] - wall_velocity[c, 0]
        u1 = v[i, 1] - wall_velocity[c, 1]
        u2 = v[i, 2] - wall_velocity[c, 2]
        towards = ((touch[c, 0] - x[i, 0]) * u0 + (touch[c, 1] - x[i, 1]) * u1
                   + (touch[c, 2] - x[i, 2]) * u2)
        speed = math.sqrt(u0 * u0 + u1 * u1 + u2 * u2)
        if towards < 0.0 or speed == 0.0:
            continue
        sin_g = min(abs(u0 * face_normal[t, 0] + u1 * face_normal[t, 1] + u2 * face_normal[t, 2]) / speed, 1.0)
        cos_g = math.sqrt(1.0 - sin_g * sin_g)
        if 3.0 * sin_g <= cos_g:
            shape = 2.0 * sin_g * cos_g - 3.0 * sin_g * sin_g
        else:
            shape = cos_g * cos_g / 3.0
        force = math.sqrt(fx * fx + fy * fy + fz * fz)
        face_wear[t] += 2.0 * wear_k[ptype[i]] * speed * force * shape * dt / face_area[t]



def mesh_scratch(most):
    """The rows mesh_contact_table works in, for particles with up to ``most`` candidate triangles:
    made outside the kernel, which then allocates nothing (triangle, closest point, gap, on its face,
    kept; a probe point)."""
    return (np.empty(most, dtype=np.int64), np.empty((most, 3)), np.empty(most), np.empty(most, dtype=np.bool_),
            np.empty(most, dtype=np.bool_), np.empty((1, 3)))


@njit(cache=True)
def mesh_contact_rows(k, i, offsets, candidates, x, vertices, triangles, face_normal, radius, velocity, spin, pivot,
                      belt, conveyor, precision, tri, point, gap, on_face, keep, probe, base, distance, normal, key, touch,
                      wall_velocity):
    """Particle i's contacts (the k-th visited) with its candidate triangles (module docstring) into
    rows ``base``.. of ``distance``, ``normal`` (surface to centre), ``key`` (triangle), ``touch``
    (contact point) and ``wall_velocity`` (the wall's there); returns how many. Points closer than
    ``precision`` (the mesh's, as its nodes are compared) are one point."""
    r = radius[i]
    xi, yi, zi = x[i, 0], x[i, 1], x[i, 2]
    tolerance = max(MERGE_TOLERANCE * (r + max(abs(xi), abs(yi), abs(zi))), precision)
    nc = 0
    for m in range(offsets[k], offsets[k + 1]):
        t = candidates[m]
        inside = closest_on_triangle(xi, yi, zi, vertices[triangles[t, 0]],
                                     vertices[triangles[t, 1]], vertices[triangles[t, 2]],
                                     point[nc])
        g = math.sqrt((xi - point[nc, 0]) ** 2 + (yi - point[nc, 1]) ** 2
                      + (zi - point[nc, 2]) ** 2)
        if g < r:
            tri[nc] = t
            gap[nc] = g
            on_face[nc] = inside
            keep[nc] = True
            nc += 1
    # an edge or corner point lying on another touched triangle whose closest point is
    # elsewhere is not a local closest point; equal points are one contact
    for a in range(nc):
        if on_face[a]:
            continue
        for b in range(nc):
            if b == a:
                continue
            if separation(point, a, point, b) <= tolerance:
                continue
            t = tri[b]
            closest_on_triangle(point[a, 0], point[a, 1], point[a, 2],
                                vertices[triangles[t, 0]], vertices[triangles[t, 1]],
                                vertices[triangles[t, 2]], probe[0])
            if separation(probe, 0, point, a) <= tolerance:
                keep[a] = False
                break
    for a in range(nc):
        if not keep[a]:
            continue
        for b in range(a):
            if keep[b] and separation(point, a, point, b) <= tolerance:
                keep[a] = False
                break
    count = 0
    for a in range(nc):
        if not keep[a]:
            continue
        t = tri[a]
        row = base + count
        distance[row] = gap[a]
        key[row] = t
        for d in range(3):
            touch[row, d] = point[a, d]
        if gap[a] > tolerance:
            normal[row, 0] = (xi - point[a, 0]) / gap[a]
            normal[row, 1] = (yi - point[a, 1]) / gap[a]
            normal[row, 2] = (zi - point[a, 2]) / gap[a]
        else:
            for d in range(3):
                normal[row, d] = face_normal[t, d]
        if conveyor:
            belt_on_face(belt, face_normal[t], wall_velocity[row])
        else:
            rigid_velocity(point[a], velocity, spin, pivot, wall_velocity[row])
        count += 1
    return count


@njit(cache=True, _nrt=False)
def mesh_contact_table(chosen, offsets, candidates, x, vertices, triangles, face_normal, radius, velocity, spin,
                       pivot, belt, conveyor, precision, scratch, starts, table):
    """Every chosen particle's contacts with its candidate triangles, one after the other: particle
    k's are rows starts[k] .. starts[k + 1] of ``table`` (distance, normal, key, touch,
    wall_velocity: WallContactTable's arrays), for a composed contact loop."""
    tri, point, gap, on_face, keep, probe = scratch
    distance, normal, key, touch, wall_velocity = table
    base = 0
    for k in range(len(chosen)):
        starts[k] = base
        base += mesh_contact_rows(k, chosen[k], offsets, candidates, x, vertices, triangles, face_normal, radius,
                                  velocity, spin, pivot, belt, conveyor, precision, tri, point, gap, on_face, keep, probe,
                                  base, distance, normal, key, touch, wall_velocity)
    starts[len(chosen)] = base


@njit(cache=True, _nrt=False)
def tally_table(chosen, starts, key, touch, contact_force, x, v, wall_velocity, face_normal, ptype, dt, reference,
                face_force, mesh_torque, wear_k, face_wear, face_area):
    """tally_wall_forces for every chosen particle's rows of a contact table."""
    for k in range(len(chosen)):
        a, b = starts[k], starts[k + 1]
        tally_wall_forces(b - a, key[a:b], touch[a:b], contact_force[a:b], chosen[k], x, v, wall_velocity[a:b],
                          face_normal, ptype, dt, reference, face_force, mesh_torque, wear_k, face_wear, face_area)


class MeshContacts:
    """The contacts of a group's particles with one triangulated surface: candidate lists (rebuilt
    only when a particle or a vertex has moved half the skin, or particles were re-sorted), the
    contact history, and the force computation.

    ``surface`` is any object with the attributes ``vertices`` (n x 3, now), ``triangles``
    (m x 3), ``face_normal`` (m x 3), ``moving``, ``velocity``, ``spin``, ``pivot`` (its rigid
    motion now: the wall velocity at p is velocity + spin x (p - pivot)), ``belt`` and ``conveyor``
    (a conveyor's surface velocity), ``transfer_cos`` (history hand-over between triangles),
    ``precision`` (contact points this close are one): fix
    wall/mesh itself, or a fix mesh/surface."""

    def __init__(self, sim, surface, history_name, group, width=HISTORY_WIDTH):
        self.surface = surface
        self.group = group
        self.history = ContactHistory(sim, history_name, width=width)
        self.stale = True
        self.builds = 0
        self.chosen = np.zeros(0, dtype=np.int64)
        self.near = np.zeros(0, dtype=np.int64)
        self.nlocal_built = -1
        self.tags_built = np.zeros(0, dtype=np.int64)
        self.x_built = np.zeros((0, 3))
        self.radius_built = np.zeros(0)
        self.skin_built = None
        self.most = 0                   # the most candidate triangles of a visited particle
        self._scratch, self._scratch_for = None, 0            # mesh_scratch and its most candidates
        self.table = WallContactTable()                        # this step's contacts, for the law

    def setup(self):
        self.builds = 0
        self.stale = True

    def pre_neighbor(self, sim):
        # the candidate lists name particles by index: re-sorting or migration makes them stale
        p = sim.particles
        if (p.nlocal != self.nlocal_built
                or not np.array_equal(p.tag[self.chosen], self.tags_built)):
            self.stale = True

    def _rebuild_if_needed(self, sim, chosen, radius):
        p = sim.particles
        mesh = self.surface
        half_skin = 0.5 * sim.neighbor.skin
        # the skin widens in direct mode: lists made with a narrower one are made again
        if not self.stale and len(chosen) == len(self.x_built) and sim.neighbor.skin == self.skin_built:
            moved = largest_move_sq(p.arrays["x"], chosen, self.x_built)
            if sim.neighbor.radii_vary:
                # a radius grown since the build brings its sphere closer as a move would
                grown = float(np.max(radius[chosen] - self.radius_built, initial=0.0))
                moved = (math.sqrt(moved) + grown) ** 2
            shifted = (largest_move_sq(mesh.vertices, self.all_vertices, self.vertices_built)
                       if mesh.moving else 0.0)
            if moved <= half_skin ** 2 and shifted <= half_skin ** 2:
                return
        x = p.x[chosen]
        skin = sim.neighbor.skin
        reach = radius + skin
        farthest = float(reach[chosen].max()) if len(chosen) else skin
        corners = mesh.vertices[mesh.triangles]
        box_lo, box_hi = corners.min(axis=1), corners.max(axis=1)
        grid_lo = box_lo.min(axis=0) - farthest
        extent = box_hi.max(axis=0) + farthest - grid_lo
        if not np.isfinite(extent).all():
            raise ScriptError(f"the mesh plus the particles' reach {farthest:g} (radius and skin) spans "
                              "more than a float can hold")
        # a flat mesh with skin 0 and no particles has no width at all: one cell of any size
        size = max(farthest, float(extent.max()) / MAX_CELLS_PER_AXIS) or 1.0
        nbins = np.maximum(1, np.floor(extent / size)).astype(np.int64)
        cell = np.maximum(extent / nbins, size)
        start, members = bin_triangles(box_lo, box_hi, grid_lo, cell, nbins, farthest)
        offsets, self.candidates = candidate_triangles(
            p.x, chosen, reach, box_lo, box_hi, grid_lo, cell, nbins, start, members)
        # only particles with candidate triangles are visited until the next rebuild
        counts = np.diff(offsets)
        near = counts > 0
        forget_far(self.history.partner, chosen, near)
        self.near = chosen[near]
        self.offsets = np.zeros(len(self.near) + 1, dtype=np.int64)
        np.cumsum(counts[near], out=self.offsets[1:])
        self.most = int(counts.max()) if len(counts) else 0
        self.all_vertices = np.arange(len(mesh.vertices), dtype=np.int64)
        self.x_built = x
        self.radius_built = radius[chosen].copy()
        self.skin_built = skin
        self.vertices_built = mesh.vertices.copy()
        self.stale = False
        self.builds += 1

    def candidates_now(self, sim):
        """(particles visited, CSR offsets, candidate triangles), re-listed when needed."""
        p = sim.particles
        if self.stale:
            self.chosen = np.flatnonzero(sim.groups.select(sim, self.group)).astype(np.int64)
            self.nlocal_built = p.nlocal
            self.tags_built = p.tag[self.chosen].copy()
        self._rebuild_if_needed(sim, self.chosen, p.radius)
        return self.near, self.offsets, self.candidates

    def scratch(self):
        """mesh_scratch for the particles visited now (numba checks no bounds: rows for fewer
        candidates than a particle has would be overrun)."""
        if self._scratch is None or self._scratch_for < self.most:
            most = self.most + self.most // 4 + 4
            self._scratch, self._scratch_for = mesh_scratch(most), most
        return self._scratch

    def forces(self, sim, law, update, tally=None, wall_type=0, log=False, store=False, f=None, torque=None):
        """Wall forces on the group's particles with ``law`` (a bound WallLaw: the wall's composed
        contact law; ``wall_type`` the wall's material type); ``tally``: None, or what the forces on
        the wall are added to (fix mesh/surface/stress's tally(): reference point, face_force (m x 3),
        mesh_torque (3,), wear_k, face_wear, face_area). Returns the contacts' log (LOG_COLUMNS and
        history) with ``log`` (computed again, nothing kept: histories unchanged, forces into the
        ``f`` and ``torque`` given) or ``store`` (this step's)."""
        p = sim.particles
        mesh = self.surface
        near, offsets, candidates = self.candidates_now(sim)
        rotation = p.has("omega") and p.has("torque")
        omega, torque = (p.omega, p.torque if torque is None else torque) if rotation else law.still(sim)
        f = p.f if f is None else f
        history = self.history
        if log:
            history = SimpleNamespace(partner=history.partner, values=history.values.copy(),
                                      overflowed=history.overflowed)
        table = self.table.room(len(near), int(offsets[-1]))
        mesh_contact_table(near, offsets, candidates, p.x, mesh.vertices, mesh.triangles, mesh.face_normal,
                           p.radius, mesh.velocity, mesh.spin, mesh.pivot, mesh.belt, mesh.conveyor, mesh.precision,
                           self.scratch(),
                           table.starts, table.arrays())
        bad, logged = law.forces(sim, near, len(near), table.starts, table.arrays(), table.contact_force, history,
                                 wall_type, f, torque, update, radius=p.radius, mass=observables.masses(sim),
                                 omega=omega, log_rows=int(table.starts[len(near)]) if (log or store) else 0,
                                 transfer_cos=mesh.transfer_cos)
        if bad >= 0:
            history.overflowed(p.tag[bad])
        if tally is not None:
            tally_table(near, table.starts, table.key, table.touch, table.contact_force, p.x, p.v,
                        table.wall_velocity, mesh.face_normal, p.type, sim.dt,
                        *(no_wear(tally) if not update else tally))
        return logged


NO_TALLY = (np.zeros(3), np.zeros((0, 3)), np.zeros(3), np.zeros(0), np.zeros(0), np.zeros(0))


def no_wear(tally):
    """The tally without wear: a run's setup force computation wears nothing."""
    return tally[:3] + (NO_TALLY[3],) + tally[4:]


# ---- the style ----------------------------------------------------------------------------------
class FixWallMesh(Fix):
    name = "wall/mesh"
    minimize_idle = True         # granular walls act on moving particles: LAMMPS's fix wall/gran has no min_post_force
    transfer_cos = TRANSFER_COS         # as a surface: the history hand-over angle (wall_contact)
    usage = ("fix ID GROUP wall/mesh file FILE|mesh MESH_ID [scale S] [move DX DY DZ] "
             "[rotate axis AX AY AZ angle DEG] [velocity VX VY VZ] [omega WX WY WZ about PX PY PZ] "
             "[surface_vel VX VY VZ] model lsd e kn Cn kt Ct mu | model lsd e kn mu | "
             "model hertz Y nu e mu")

    class Args(PlacedMeshArgs):
        file: str | None = keyword(None)
        mesh: str | None = keyword(None, names="fix mesh/surface ID")
        velocity: Vector | None = keyword(None, unit="velocity")
        omega: tuple[float, float, float, Literal["about"], float, float, float] | None = keyword(
            None, unit=("angle/time", "angle/time", "angle/time", "1", "distance", "distance", "distance"))
        surface_vel: Vector | None = keyword(None, unit="velocity")
        model: LawWords = keyword(..., unit=LAW_UNITS)

    @classmethod
    def check_args(cls, args):
        motion = [word for word in ("velocity", "omega", "surface_vel") if getattr(args, word) is not None]
        if args.mesh is not None:
            others = (["file"] if args.file is not None else []) + [entry[0] for entry in args.placement] + motion
            if others:
                raise ScriptError(f"mesh MESH_ID takes its geometry and motion from the fix mesh/surface; "
                                  f"{others[0]} cannot be given with it")
        elif args.file is None:
            raise ScriptError(f"missing keyword file or mesh; usage: {cls.usage}")
        check_placement(args.placement)
        if args.surface_vel is not None and len(motion) > 1:
            raise ScriptError("surface_vel (a conveyor) cannot be combined with velocity or omega")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self._read_args(sim, args)
        self.contacts = MeshContacts(sim, self.surface, f"wall_{id}", group)
        self.wall_law = self.law.wall_law()
        self.elapsed = 0.0
        if self.surface is self:
            self.vertices = self.placed
            self._place()

    @property
    def history(self):
        return self.contacts.history

    @property
    def builds(self):
        return self.contacts.builds

    @property
    def near(self):
        return self.contacts.near

    # ---- script words ----
    def _read_args(self, sim, args):
        self.law = contact_law(args.model)
        if args.mesh is not None:
            self.surface = mesh_fix(sim, args.mesh)
            self.moving = False
            return
        self.surface = self
        self.file = args.file
        points, self.triangles = placed_mesh(sim, args.file, args.placement)
        self.placed = np.ascontiguousarray(points)
        self.velocity = np.array(args.velocity or (0.0, 0.0, 0.0))
        self.spin = np.array(args.omega[:3] if args.omega else (0.0, 0.0, 0.0))
        self.pivot0 = np.array(args.omega[4:] if args.omega else (0.0, 0.0, 0.0))
        self.belt = np.array(args.surface_vel or (0.0, 0.0, 0.0))
        self.conveyor = args.surface_vel is not None
        self.moving = bool(np.any(self.velocity) or np.any(self.spin))
        self.precision = 0.0        # PDPS's wall/mesh: points merge by MERGE_TOLERANCE alone

    # ---- mesh motion and candidate lists ----
    def _place(self):
        """Vertices, pivot and face normals at the mesh's current time."""
        self.pivot = self.pivot0 + self.velocity * self.elapsed
        if self.moving:
            angle = float(np.linalg.norm(self.spin)) * self.elapsed
            points = self.placed
            if angle != 0.0:
                turn = rotation_matrix(self.spin / np.linalg.norm(self.spin), angle)
                points = (points - self.pivot0) @ turn.T + self.pivot0
            self.vertices = np.ascontiguousarray(points + self.velocity * self.elapsed)
        self.face_normal = face_normals(self.vertices, self.triangles)

    # ---- restart files: the mesh's clock is all the instance keeps beyond its arguments ----
    def state(self):
        return {"elapsed": self.elapsed}

    def restore(self, state):
        self.elapsed = float(state["elapsed"])
        if self.surface is self:
            self._place()

    # ---- hooks ----
    def setup(self, sim):
        p = sim.particles
        if not p.has("radius"):
            raise ScriptError(f"fix {self.id} (wall/mesh) needs particle radii (particle_style sphere)")
        chosen = sim.groups.select(sim, self.group)
        self.law.check_timestep(sim, self, observables.masses(sim)[chosen])
        self.wall_law.bind(self.law.tables(sim.ntypes))
        self.contacts.setup()
        self.contacts.forces(sim, self.wall_law, update=False, tally=self.surface_tally())

    def pre_neighbor(self, sim):
        self.contacts.pre_neighbor(sim)

    def post_force(self, sim):
        self.elapsed += sim.dt
        if self.moving:
            self._place()
        self.contacts.forces(sim, self.wall_law, update=True, tally=self.surface_tally())

    def surface_tally(self):
        return None if self.surface is self else self.surface.tally()
