r"""Region ``mesh/tet``: the volume of a tetrahedral mesh read from a VTK file (LIGGGHTS's region
mesh/tet), e.g. to fill an odd shape with ``create_atoms 1 region ID``.

Syntax::

    region ID mesh/tet file FILE scale S move DX DY DZ rotate AX AY AZ [side in|out] units box

FILE is an unstructured grid (legacy VTK, or anything meshio reads) whose tetrahedra (VTK cell type
10) make the region; other cells are left out with a warning, as LIGGGHTS does. Each vertex
:math:`\mathbf{p}` of the file is placed at

.. math::

    \mathbf{p}' = R_z(\gamma)\,R_y(\beta)\,R_x(\alpha)\,\bigl(S\,(\mathbf{p} + \mathbf{d})\bigr)

(``move`` :math:`\mathbf{d}` before ``scale`` S, then ``rotate`` by the angles AX, AY, AZ in degrees
about x, then y, then z: LIGGGHTS's order), and must lie in the simulation box. A point is inside
when it lies strictly inside one tetrahedron: the four tetrahedra it makes with the faces all have
positive volume, so a point on the mesh's surface, or on a face two tetrahedra share, is outside
(LIGGGHTS's test; a lattice plane through the mesh's top face stays empty in both programs). The
keywords stand in this order and ``units box`` is required (LIGGGHTS refuses lattice units here).

Example (LIGGGHTS's mesh_tet tutorial)::

    region mesh mesh/tet file data/test.vtk scale 1. move 0. 0. 0. rotate 0. 0. 0. units box
    lattice sc 0.05
    create_atoms 1 region mesh
"""

import contextlib
import io
import math
import os
from typing import Literal

import meshio
import numpy as np
from numba import njit
from pdps_core.api import Region, ScriptError, StyleArgs, keyword, param


@njit(cache=True)
def _volume(a, b, c, d):
    """Signed volume of the tetrahedron (a, b, c, d), as LIGGGHTS orders the products."""
    ax, ay, az = d[0] - b[0], d[1] - b[1], d[2] - b[2]
    bx, by, bz = c[0] - b[0], c[1] - b[1], c[2] - b[2]
    cx, cy, cz = a[0] - b[0], a[1] - b[1], a[2] - b[2]
    return ((ay * bz - az * by) * cx + (-ax * bz + az * bx) * cy + (ax * by - ay * bx) * cz) / 6.0


@njit(cache=True)
def inside_tets(x, nodes, lo, hi, out):
    """out[p]: whether point p lies strictly inside one of the tetrahedra ``nodes`` (m x 4 x 3, each
    of positive volume) whose box lo..hi holds it."""
    for p in range(x.shape[0]):
        point = x[p]
        out[p] = False
        for t in range(nodes.shape[0]):
            if (point[0] < lo[t, 0] or point[0] > hi[t, 0] or point[1] < lo[t, 1] or point[1] > hi[t, 1]
                    or point[2] < lo[t, 2] or point[2] > hi[t, 2]):
                continue
            n = nodes[t]
            if (_volume(n[0], n[1], n[2], point) > 0.0 and _volume(n[0], n[1], point, n[3]) > 0.0
                    and _volume(n[0], point, n[2], n[3]) > 0.0 and _volume(point, n[1], n[2], n[3]) > 0.0):
                out[p] = True
                break


def rotation(angles):
    """LIGGGHTS's R = Rz Ry Rx for angles (x, y, z) in degrees."""
    ax, ay, az = (math.radians(a) for a in angles)
    rx = np.array([[1, 0, 0], [0, math.cos(ax), -math.sin(ax)], [0, math.sin(ax), math.cos(ax)]])
    ry = np.array([[math.cos(ay), 0, math.sin(ay)], [0, 1, 0], [-math.sin(ay), 0, math.cos(ay)]])
    rz = np.array([[math.cos(az), -math.sin(az), 0], [math.sin(az), math.cos(az), 0], [0, 0, 1]])
    return rz @ ry @ rx


class RegionMeshTet(Region):
    name = "mesh/tet"
    usage = "region ID mesh/tet file FILE scale S move DX DY DZ rotate AX AY AZ [side in|out] units box"

    class Args(StyleArgs):
        """Its own words, then RegionArgs's keywords but move and rotate (here they place the mesh once)."""
        file_word: Literal["file"]
        file: str
        scale_word: Literal["scale"]
        scale: float = param(gt=0, unit="1")
        move_word: Literal["move"]
        move: tuple[float, float, float] = param(unit=("distance", "distance", "distance"))
        rotate_word: Literal["rotate"]
        rotate: tuple[float, float, float] = param(unit=("degrees", "degrees", "degrees"))
        side: Literal["in", "out"] = keyword("in")
        units: Literal["box", "lattice"] | None = keyword(None)
        volume_limit: float | None = keyword(None, unit="volume")

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        if (args.units or sim.dialect.region_units) != "box":
            raise ScriptError(f"region {id} mesh/tet: give units box (lattice units are not defined for a "
                              "tetrahedral mesh, as in LIGGGHTS)")
        points, tets = read_tets(sim.resolve(args.file), args.file, sim)
        placed = (args.scale * (points + np.asarray(args.move))) @ rotation(args.rotate).T
        box = sim.box
        if box is not None and ((placed < box.lo - 1e-12 * box.length).any()
                                or (placed > box.hi + 1e-12 * box.length).any()):
            raise ScriptError(f"region {id} mesh/tet: the mesh of {args.file} reaches outside the simulation box")
        nodes = placed[tets]
        # a tetrahedron of negative volume has its first and last corner swapped (LIGGGHTS)
        negative = np.array([_volume(*tet) < 0.0 for tet in nodes], dtype=bool)
        nodes[negative] = nodes[negative][:, [3, 1, 2, 0]]
        self.nodes = np.ascontiguousarray(nodes)
        self.lo = np.ascontiguousarray(nodes.min(axis=1))
        self.hi = np.ascontiguousarray(nodes.max(axis=1))
        self.volume = float(sum(_volume(*tet) for tet in self.nodes))

    def inside(self, x):
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1, 3)
        out = np.empty(len(x), dtype=np.bool_)
        inside_tets(x, self.nodes, self.lo, self.hi, out)
        return out

    def bounds(self):
        return self.lo.min(axis=0), self.hi.max(axis=0)


def read_tets(path, shown, sim):
    """(points n x 3, tetrahedra m x 4) of a volume mesh file; a warning when other cells are left out."""
    if not os.path.isfile(path):
        raise ScriptError(f"mesh file {shown} does not exist")
    try:
        with contextlib.redirect_stderr(io.StringIO()), np.errstate(all="ignore"):
            mesh = meshio.read(path)
    except Exception as exc:
        reason = " ".join(str(exc).split()) or type(exc).__name__
        raise ScriptError(f"mesh file {shown} cannot be read as a volume mesh: {reason}") from None
    points = np.asarray(mesh.points, dtype=np.float64)
    tets = [np.asarray(cells.data, dtype=np.int64) for cells in mesh.cells if cells.type == "tetra"]
    if not tets:
        raise ScriptError(f"mesh file {shown} has no tetrahedra (VTK cell type 10)")
    if any(cells.type != "tetra" for cells in mesh.cells):
        sim.warn(f"mesh file {shown}: cells other than tetrahedra are left out, as LIGGGHTS does")
    return points, np.concatenate(tets)
