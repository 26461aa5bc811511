r"""Region ``plane``: the half-space :math:`(\mathbf{x} - \mathbf{p}) \cdot \mathbf{n} \ge 0`, the side the
normal points to (LAMMPS's region plane).

Syntax::

    region ID plane PX PY PZ NX NY NZ [side in|out] [units box|lattice]

P a point on the plane (lattice spacings with ``units lattice``, the LAMMPS dialect's default), N
its normal (any length, not zero). Points on the plane are inside. A half-space has no extent: it
cannot make a box, and a lattice filled through it takes the box's sites. Example::

    region upper plane 0 0 5 0 0 1 units box
"""

import numpy as np
from numba import njit

from pdps_core.api import Region, RegionArgs, ScriptError, SurfaceContacts, param


class RegionPlane(Region):
    name = "plane"
    usage = "region ID plane PX PY PZ NX NY NZ [side in|out] [units box|lattice]"

    class Args(RegionArgs):
        px: float = param(unit="distance")
        py: float = param(unit="distance")
        pz: float = param(unit="distance")
        nx: float = param(unit="dimensionless")
        ny: float = param(unit="dimensionless")
        nz: float = param(unit="dimensionless")

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        self.point = np.array([args.px, args.py, args.pz]) * self.scale
        normal = np.array([args.nx, args.ny, args.nz])
        length = float(np.linalg.norm(normal))
        if length == 0.0:
            raise ScriptError("the plane's normal must not be zero")
        self.normal = normal / length

    def inside(self, x):
        # summed term by term as LAMMPS does, so points on the plane fall on LAMMPS's side
        x = np.asarray(x, dtype=np.float64)
        p, n = self.point, self.normal
        return (x[:, 0] - p[0]) * n[0] + (x[:, 1] - p[1]) * n[1] + (x[:, 2] - p[2]) * n[2] >= 0.0

    def surface_contacts(self, x, reach, out=None):
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1, 3)
        out = out if out is not None else SurfaceContacts()
        return out.rows(plane_contacts(x, self.point, self.normal, float(reach), *out.room(len(x))))


@njit(cache=True)
def plane_contacts(x, point, unit, reach, index, distance, normal, element):
    """Points within reach of the plane (from either side, the normal towards the point), written
    into the buffers (room for one row a point); returns how many."""
    m = 0
    for p in range(x.shape[0]):
        height = (x[p, 0] - point[0]) * unit[0] + (x[p, 1] - point[1]) * unit[1] + (x[p, 2] - point[2]) * unit[2]
        if abs(height) < reach:
            side = 1.0 if height >= 0.0 else -1.0
            index[m] = p
            distance[m] = abs(height)
            for d in range(3):
                normal[m, d] = side * unit[d]
            element[m] = 0
            m += 1
    return m
