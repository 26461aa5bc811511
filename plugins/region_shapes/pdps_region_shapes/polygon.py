r"""Region ``polygon``: a flat polygon in space, given point by point (a surface, e.g. for walls).

The first three points fix the normal,

.. math::

    \mathbf{n} = \frac{(\mathbf{p}_2-\mathbf{p}_1)\times(\mathbf{p}_3-\mathbf{p}_1)}
                      {\lvert(\mathbf{p}_2-\mathbf{p}_1)\times(\mathbf{p}_3-\mathbf{p}_1)\rvert}

(PDPS manual). All points must lie in that plane, in order around the polygon (which need not be
convex). A polygon has no inside: it cannot hold particles or make a box; wall styles use its
``points`` and ``normal``.

As a wall (``fix wall/dem``) the polygon is a two-sided surface. A point touches it at its closest
point of the polygon: the foot of the perpendicular, :math:`\mathbf{x} - h\mathbf{n}` with
:math:`h = (\mathbf{x}-\mathbf{p}_1)\cdot\mathbf{n}`, when the foot is inside the polygon (distance
:math:`|h|`, normal :math:`\mathrm{sign}(h)\,\mathbf{n}`), else the closest point of its edges and
corners (normal from that point to the point x). One contact per point, element id 0, so a sphere
sliding off the face over an edge keeps its contact history.

Syntax::

    region ID polygon p1 x y z p2 x y z p3 x y z [p4 x y z ...]

Example::

    region wall1 polygon p1 15 0 0 p2 15 10 0 p3 10 10 0 p4 10 0 0
"""

import math
from typing import NamedTuple

import numpy as np
from numba import njit
from pdps_core.api import Region, ScriptError, StyleArgs, SurfaceContacts, param


class Point(NamedTuple):
    label: str
    x: float
    y: float
    z: float


@njit(cache=True)
def inside_polygon(a, b, corners):
    """Crossing-number test of the in-plane point (a, b) against the polygon's in-plane corners."""
    inside = False
    k = corners.shape[0]
    for e in range(k):
        a1, b1 = corners[e, 0], corners[e, 1]
        a2, b2 = corners[(e + 1) % k, 0], corners[(e + 1) % k, 1]
        if (b1 > b) != (b2 > b):
            crossing = a1 + (b - b1) * (a2 - a1) / (b2 - b1)
            if a < crossing:
                inside = not inside
    return inside


@njit(cache=True)
def polygon_contacts(x, points, normal, u_axis, v_axis, corners, reach, index, distance, direction, element):
    """Contacts of points x with the polygon closer than reach (see the module docstring), written
    into the buffers (room for one row a point); returns how many."""
    k = points.shape[0]
    m = 0
    for p in range(x.shape[0]):
        r0 = x[p, 0] - points[0, 0]
        r1 = x[p, 1] - points[0, 1]
        r2 = x[p, 2] - points[0, 2]
        height = r0 * normal[0] + r1 * normal[1] + r2 * normal[2]
        a = r0 * u_axis[0] + r1 * u_axis[1] + r2 * u_axis[2]
        b = r0 * v_axis[0] + r1 * v_axis[1] + r2 * v_axis[2]
        if inside_polygon(a, b, corners):
            gap = abs(height)
            side = 1.0 if height >= 0.0 else -1.0
            for d in range(3):
                direction[m, d] = side * normal[d]
        else:
            gap_sq = math.inf
            for e in range(k):
                q = (e + 1) % k
                along = 0.0
                length_sq = 0.0
                for d in range(3):
                    edge = points[q, d] - points[e, d]
                    along += (x[p, d] - points[e, d]) * edge
                    length_sq += edge * edge
                t = min(max(along / length_sq, 0.0), 1.0) if length_sq > 0.0 else 0.0
                trial = 0.0
                for d in range(3):
                    delta = x[p, d] - (points[e, d] + t * (points[q, d] - points[e, d]))
                    trial += delta * delta
                if trial < gap_sq:
                    gap_sq = trial
                    for d in range(3):
                        direction[m, d] = x[p, d] - (points[e, d] + t * (points[q, d] - points[e, d]))
            gap = math.sqrt(gap_sq)
            for d in range(3):
                direction[m, d] /= gap
        if gap < reach:
            index[m] = p
            distance[m] = gap
            element[m] = 0
            m += 1
    return m


class RegionPolygon(Region):
    name = "polygon"
    usage = "region ID polygon p1 x y z p2 x y z p3 x y z ..."

    class Args(StyleArgs):
        point: list[Point] = param(min_length=3, unit=("1", "distance", "distance", "distance"))

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        self.labels = [point.label for point in args.point]
        self.points = np.array([[point.x, point.y, point.z] for point in args.point])
        normal = np.cross(self.points[1] - self.points[0], self.points[2] - self.points[0])
        length = np.linalg.norm(normal)
        if length == 0:
            raise ScriptError(f"region {id}: the first three points are on one line")
        self.normal = normal / length
        off_plane = np.abs((self.points - self.points[0]) @ self.normal)
        if off_plane.max() > 1e-9 * max(1.0, np.abs(self.points).max()):
            k = int(off_plane.argmax())
            raise ScriptError(f"region {id}: point {self.labels[k]} is not in the plane of the first three")
        # an in-plane basis, for the inside test of a point's foot on the plane
        self.u_axis = (self.points[1] - self.points[0]) / np.linalg.norm(self.points[1] - self.points[0])
        self.v_axis = np.cross(self.normal, self.u_axis)
        rel = self.points - self.points[0]
        self.corners = np.column_stack([rel @ self.u_axis, rel @ self.v_axis])

    def surface_contacts(self, x, reach, out=None):
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1, 3)
        out = out if out is not None else SurfaceContacts()
        return out.rows(polygon_contacts(x, self.points, self.normal, self.u_axis, self.v_axis, self.corners,
                                         float(reach), *out.room(len(x))))
