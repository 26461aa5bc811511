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

from pdps_core.api import Region, RegionArgs, ScriptError, param


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

    def surface_contacts(self, x, reach):
        x = np.asarray(x, dtype=np.float64).reshape(-1, 3)
        h = (x - self.point) @ self.normal
        index = np.flatnonzero(np.abs(h) < reach)
        normal = np.where((h[index] >= 0)[:, None], self.normal, -self.normal)
        return index, np.abs(h[index]), normal, np.zeros(len(index), dtype=np.int64)
