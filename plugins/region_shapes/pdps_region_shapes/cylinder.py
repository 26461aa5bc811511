r"""Region ``cylinder``: a right circular cylinder along x, y or z (LAMMPS's region cylinder).

Syntax::

    region ID cylinder DIM C1 C2 RADIUS LO HI [side in|out] [units box|lattice]

DIM the axis (x, y or z); C1 C2 the axis's position in the other two coordinates in order (y z for
x, x z for y, x y for z); RADIUS; LO HI the extent along the axis (a number, ``INF``/``-INF`` for
unbounded, or ``EDGE`` for the box's face). With ``units lattice`` (the LAMMPS dialect's default) C1
C2 LO HI are in lattice spacings along their axes and the radius in the spacing of C1's axis, as
LAMMPS scales them. Points on the surface are inside. Example::

    region pipe cylinder z 5 5 2.0 INF INF units box
"""

import math

import numpy as np
from numba import njit
from pydantic import model_validator

from pdps_core.api import Region, RegionArgs, ScriptError, SurfaceContacts, param

HUGE = 1e300
OTHER = {"x": (1, 2), "y": (0, 2), "z": (0, 1)}


def bound(value, name):
    if value in ("INF", "-INF", "EDGE"):
        return value
    try:
        number = float(value)
    except ValueError:
        raise ValueError(f"{name} must be a number, INF, -INF or EDGE (got {value})") from None
    if not math.isfinite(number):
        raise ValueError(f"{name} must be a number, INF, -INF or EDGE (got {value})")
    return value


@njit(cache=True)
def cylinder_contacts(x, axis, a, b, c1, c2, radius, lo, hi, lo_cap, hi_cap, reach, index, distance, normal,
                      element):
    """RegionCylinder.surface_contacts into the buffers (room for 3 rows a point); returns how many."""
    m = 0
    for p in range(x.shape[0]):
        along = x[p, axis]
        if along < lo or along > hi:
            continue
        d1 = x[p, a] - c1
        d2 = x[p, b] - c2
        rho = math.sqrt(d1 * d1 + d2 * d2)
        if abs(rho - radius) < reach and rho > 0.0:
            side = -1.0 if rho < radius else 1.0       # towards the axis from inside
            index[m] = p
            distance[m] = abs(rho - radius)
            normal[m, axis] = 0.0
            normal[m, a] = side * d1 / rho
            normal[m, b] = side * d2 / rho
            element[m] = 0
            m += 1
        if rho > radius:
            continue
        for cap in range(2):
            if not (lo_cap if cap == 0 else hi_cap):
                continue
            gap = along - lo if cap == 0 else hi - along
            if gap < reach:
                index[m] = p
                distance[m] = gap
                normal[m, a] = 0.0
                normal[m, b] = 0.0
                normal[m, axis] = 1.0 if cap == 0 else -1.0
                element[m] = 1 + cap
                m += 1
    return m


@njit(cache=True)
def cylinder_wall_contacts(x, axis, a, b, c1, c2, radius, lo, hi, reach, exterior, index, distance, normal, element,
                           curvature):
    """LAMMPS's RegCylinder::surface_interior (a point inside: the curved wall, element 2, radius of
    curvature -2R, unless on the axis; the lo and hi caps, elements 0 and 1) or surface_exterior (a
    point outside within reach: its closest point, element 0, curvature 2R off the curved wall's
    side, else 0), normals LAMMPS's (the vector from the surface times 1 / distance); a point at
    distance 0 has no contact. Returns how many rows (room for 3 a point)."""
    m = 0
    for p in range(x.shape[0]):
        del1 = x[p, a] - c1
        del2 = x[p, b] - c2
        r = math.sqrt(del1 * del1 + del2 * del2)
        along = x[p, axis]
        if not exterior:
            if r > radius or along < lo or along > hi:
                continue
            gap = radius - r
            if gap < reach and r > 0.0 and gap > 0.0:
                rinv = 1.0 / gap
                index[m] = p
                distance[m] = gap
                normal[m, axis] = 0.0
                normal[m, a] = del1 * (1.0 - radius / r) * rinv
                normal[m, b] = del2 * (1.0 - radius / r) * rinv
                element[m] = 2
                curvature[m] = -2.0 * radius
                m += 1
            for cap in range(2):
                gap = along - lo if cap == 0 else hi - along
                if gap < reach and gap > 0.0:
                    index[m] = p
                    distance[m] = gap
                    rinv = 1.0 / gap
                    normal[m, a] = 0.0
                    normal[m, b] = 0.0
                    normal[m, axis] = gap * rinv if cap == 0 else -gap * rinv
                    element[m] = cap
                    curvature[m] = 0.0
                    m += 1
            continue
        if r >= radius + reach or along <= lo - reach or along >= hi + reach:
            continue
        if r < radius and along > lo and along < hi:
            continue
        crad = 0.0
        if r > radius:
            pa = c1 + del1 * radius / r
            pb = c2 + del2 * radius / r
            crad = 2.0 * radius
        else:
            pa = x[p, a]
            pb = x[p, b]
        paxis = lo if along < lo else (hi if along > hi else along)
        # the surface point's coordinates in x, y, z order (LAMMPS's add_contact)
        s0 = paxis if axis == 0 else (pa if a == 0 else pb)
        s1 = paxis if axis == 1 else (pa if a == 1 else pb)
        s2 = paxis if axis == 2 else (pa if a == 2 else pb)
        d0 = x[p, 0] - s0
        d1 = x[p, 1] - s1
        d2 = x[p, 2] - s2
        gap = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        if gap < reach and gap > 0.0:
            rinv = 1.0 / gap
            index[m] = p
            distance[m] = gap
            normal[m, 0] = d0 * rinv
            normal[m, 1] = d1 * rinv
            normal[m, 2] = d2 * rinv
            element[m] = 0
            curvature[m] = crad
            m += 1
    return m


class RegionCylinder(Region):
    name = "cylinder"
    usage = "region ID cylinder x|y|z C1 C2 RADIUS LO HI [side in|out] [units box|lattice]"

    class Args(RegionArgs):
        dim: str = param()
        c1: float = param(unit="distance")
        c2: float = param(unit="distance")
        radius: float = param(ge=0, unit="distance")
        lo: str = param(unit="distance")
        hi: str = param(unit="distance")

        @model_validator(mode="after")
        def _words(self):
            if self.dim not in OTHER:
                raise ValueError(f"dim must be x, y or z (got {self.dim})")
            bound(self.lo, "lo")
            bound(self.hi, "hi")
            return self

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        self.axis = "xyz".index(args.dim)
        self.across = OTHER[args.dim]
        self.c = np.array([args.c1 * self.scale[self.across[0]], args.c2 * self.scale[self.across[1]]])
        self.radius = args.radius * self.scale[self.across[0]]
        self.lo = self._end(sim, args.lo, True)
        self.hi = self._end(sim, args.hi, False)
        if not self.lo <= self.hi:
            raise ScriptError(f"lo must be <= hi (got {self.lo:g} {self.hi:g})")

    def _end(self, sim, value, is_lo):
        if value in ("INF", "-INF"):
            return -HUGE if is_lo else HUGE
        if value == "EDGE":
            if sim.box is None:
                raise ScriptError(f"{'lo' if is_lo else 'hi'} EDGE needs the simulation box to exist")
            return float((sim.box.lo if is_lo else sim.box.hi)[self.axis])
        return float(value) * self.scale[self.axis]

    def inside(self, x):
        x = np.asarray(x, dtype=np.float64)
        a, b = self.across
        d1, d2 = x[:, a] - self.c[0], x[:, b] - self.c[1]
        along = x[:, self.axis]
        return (np.sqrt(d1 * d1 + d2 * d2) <= self.radius) & (along >= self.lo) & (along <= self.hi)

    def surface_contacts(self, x, reach, out=None):
        """Points within reach of the curved wall (from inside or outside, along the cylinder's length)
        or of a finite end cap (from inside): element 0 the curved wall, 1 the lo cap, 2 the hi cap."""
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1, 3)
        out = out if out is not None else SurfaceContacts()
        a, b = self.across
        return out.rows(cylinder_contacts(x, self.axis, a, b, self.c[0], self.c[1], self.radius, self.lo, self.hi,
                                          abs(self.lo) < HUGE, abs(self.hi) < HUGE, float(reach),
                                          *out.room(3 * len(x))))

    def own_wall_contacts(self, x, reach, out):
        a, b = self.across
        out.room(3 * len(x))
        return out.wall_rows(cylinder_wall_contacts(x, self.axis, a, b, self.c[0], self.c[1], self.radius, self.lo,
                                                    self.hi, float(reach), self.side_out, out.index, out.distance,
                                                    out.normal, out.element, out.curvature))

    def bounds(self):
        if abs(self.lo) >= HUGE or abs(self.hi) >= HUGE:
            raise ScriptError(f"region {self.id} is unbounded (INF) and cannot define a box")
        return self.extent()

    def extent(self):
        lo, hi = np.empty(3), np.empty(3)
        for k, d in enumerate(self.across):
            lo[d], hi[d] = self.c[k] - self.radius, self.c[k] + self.radius
        lo[self.axis], hi[self.axis] = self.lo, self.hi
        return lo, hi
