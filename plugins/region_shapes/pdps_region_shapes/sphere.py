r"""Region ``sphere``: the ball :math:`|\mathbf{x} - \mathbf{c}| \le R` (LAMMPS's region sphere).

Syntax::

    region ID sphere X Y Z RADIUS [side in|out] [units box|lattice]

X Y Z the centre and RADIUS (distance units; with ``units lattice``, the LAMMPS dialect's default,
the centre in lattice spacings along each axis and the radius in the x spacing, as LAMMPS scales
them). Points on the surface are inside. Example::

    region ball sphere 5 5 5 2.5 units box
    group inner region ball
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import Region, RegionArgs, ScriptError, SurfaceContacts, param


class RegionSphere(Region):
    name = "sphere"
    usage = "region ID sphere X Y Z RADIUS [side in|out] [units box|lattice]"

    class Args(RegionArgs):
        x: float = param(unit="distance")
        y: float = param(unit="distance")
        z: float = param(unit="distance")
        radius: float = param(ge=0, unit="distance")

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        self.centre = np.array([args.x, args.y, args.z]) * self.scale
        self.radius = args.radius * self.scale[0]

    def inside(self, x):
        # r <= R with r = sqrt(dx dx + dy dy + dz dz), as LAMMPS compares (points on the surface alike)
        d = np.asarray(x, dtype=np.float64) - self.centre
        return np.sqrt(d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1] + d[:, 2] * d[:, 2]) <= self.radius

    def bounds(self):
        return self.centre - self.radius, self.centre + self.radius

    def surface_contacts(self, x, reach, out=None):
        """Points within reach of the sphere's surface, from inside or outside (one contact each)."""
        if self.radius <= 0:
            raise ScriptError(f"region {self.id}: a sphere of radius 0 cannot act as a wall")
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1, 3)
        out = out if out is not None else SurfaceContacts()
        return out.rows(sphere_contacts(x, self.centre, self.radius, float(reach), *out.room(len(x))))


@njit(cache=True)
def sphere_contacts(x, centre, radius, reach, index, distance, normal, element):
    """Points within reach of the sphere's surface (not at its centre), the normal towards the point,
    written into the buffers (room for one row a point); returns how many."""
    m = 0
    for p in range(x.shape[0]):
        d0 = x[p, 0] - centre[0]
        d1 = x[p, 1] - centre[1]
        d2 = x[p, 2] - centre[2]
        r = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        if abs(r - radius) < reach and r > 0.0:
            side = -1.0 if r < radius else 1.0
            index[m] = p
            distance[m] = abs(r - radius)
            normal[m, 0] = side * d0 / r
            normal[m, 1] = side * d1 / r
            normal[m, 2] = side * d2 / r
            element[m] = 0
            m += 1
    return m
