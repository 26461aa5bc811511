r"""Region ``sphere``: the ball :math:`|\mathbf{x} - \mathbf{c}| \le R` (LAMMPS's region sphere).

Syntax::

    region ID sphere X Y Z RADIUS [side in|out] [units box|lattice]

X Y Z the centre and RADIUS (distance units; with ``units lattice``, the LAMMPS dialect's default,
the centre in lattice spacings along each axis and the radius in the x spacing, as LAMMPS scales
them). Points on the surface are inside. Example::

    region ball sphere 5 5 5 2.5 units box
    group inner region ball
"""

import numpy as np

from pdps_core.api import Region, RegionArgs, ScriptError, param


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

    def surface_contacts(self, x, reach):
        """Points within reach of the sphere's surface, from inside or outside (one contact each)."""
        x = np.asarray(x, dtype=np.float64).reshape(-1, 3)
        d = x - self.centre
        r = np.sqrt(np.einsum("ij,ij->i", d, d))
        gap = np.abs(r - self.radius)
        index = np.flatnonzero((gap < reach) & (r > 0))
        if self.radius <= 0:
            raise ScriptError(f"region {self.id}: a sphere of radius 0 cannot act as a wall")
        outward = d[index] / r[index, None]
        inside = r[index] < self.radius
        normal = np.where(inside[:, None], -outward, outward)
        return index, gap[index], normal, np.zeros(len(index), dtype=np.int64)
