r"""Region ``prism``: a parallelepiped (LAMMPS's region prism).

Syntax::

    region ID prism XLO XHI YLO YHI ZLO ZHI XY XZ YZ [side in|out] [units box|lattice]

The box [XLO, XHI] x [YLO, YHI] x [ZLO, ZHI] sheared by the tilts XY (x shifted by XY over the height
in y), XZ and YZ, as LAMMPS's triclinic boxes are: a point is inside when its coordinates in the
prism's edge vectors a = (XHI-XLO, 0, 0), b = (XY, YHI-YLO, 0), c = (XZ, YZ, ZHI-ZLO) from the corner
(XLO, YLO, ZLO) lie in [0, 1]. pdps's boxes are orthogonal: a prism selects particles and fills
lattices; ``create_box`` with a tilted prism is refused. Example::

    region slab prism 0 10 0 10 0 5 2 0 0 units box
"""

import numpy as np

from pdps_core.api import Region, RegionArgs, ScriptError, param


class RegionPrism(Region):
    name = "prism"
    usage = "region ID prism XLO XHI YLO YHI ZLO ZHI XY XZ YZ [side in|out] [units box|lattice]"

    class Args(RegionArgs):
        xlo: float = param(unit="distance")
        xhi: float = param(unit="distance")
        ylo: float = param(unit="distance")
        yhi: float = param(unit="distance")
        zlo: float = param(unit="distance")
        zhi: float = param(unit="distance")
        xy: float = param(unit="distance")
        xz: float = param(unit="distance")
        yz: float = param(unit="distance")

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        sx, sy, sz = self.scale
        self.lo = np.array([args.xlo * sx, args.ylo * sy, args.zlo * sz])
        self.hi = np.array([args.xhi * sx, args.yhi * sy, args.zhi * sz])
        for axis, a, b in zip("xyz", self.lo, self.hi):
            if not a < b:
                raise ScriptError(f"{axis}lo must be < {axis}hi (got {a:g} {b:g})")
        self.tilt = np.array([args.xy * sx, args.xz * sx, args.yz * sy])
        xy, xz, yz = self.tilt
        lx, ly, lz = self.hi - self.lo
        # LAMMPS's closed-form inverse of the edge matrix, so that points on a slanted face
        # fall on the same side as in LAMMPS
        self.hinv = np.array([[1.0 / lx, -xy / (lx * ly), (yz * xy - ly * xz) / (lx * ly * lz)],
                              [0.0, 1.0 / ly, -yz / (ly * lz)],
                              [0.0, 0.0, 1.0 / lz]])

    def inside(self, x):
        d = np.asarray(x, dtype=np.float64) - self.lo
        h = self.hinv
        a = h[0, 0] * d[:, 0] + h[0, 1] * d[:, 1] + h[0, 2] * d[:, 2]
        b = h[1, 1] * d[:, 1] + h[1, 2] * d[:, 2]
        c = h[2, 2] * d[:, 2]
        return (a >= 0.0) & (a <= 1.0) & (b >= 0.0) & (b <= 1.0) & (c >= 0.0) & (c <= 1.0)

    def bounds(self):
        if np.any(self.tilt != 0.0):
            raise ScriptError(f"region {self.id} is a tilted prism: pdps's boxes are orthogonal")
        return self.lo.copy(), self.hi.copy()
