r"""Region ``block``: an axis-aligned box, :math:`x_{lo} \le x \le x_{hi}` (and so for y, z).

Syntax::

    region ID block xlo xhi ylo yhi zlo zhi [side in|out] [units box|lattice]

Each bound is a number (distance units, or lattice spacings with ``units lattice``: the LAMMPS
dialect's default), ``INF`` or ``-INF`` (unbounded on that side, whichever
sign is written, as in LAMMPS) or ``EDGE`` (the simulation box's
face, which must exist then), as in LAMMPS. Points on the faces are inside.

As a wall (``fix wall/dem``), the block is seen from the side the point is on. These are the two
cases of LAMMPS's region walls (``surface_interior`` for ``side in``, ``surface_exterior`` for ``side
out``); a pdps block has no ``side`` keyword, the point's position chooses:

- a point inside the block (a container) touches every face closer than the reach, one contact per
  face, at distance :math:`x - x_{lo}` with normal :math:`+\hat{x}`, :math:`x_{hi} - x` with normal
  :math:`-\hat{x}`, and so on; a sphere in a corner touches two or three faces. Element ids: 0 xlo,
  1 xhi, 2 ylo, 3 yhi, 4 zlo, 5 zhi.
- a point outside the block (an obstacle) touches it once, at the block's closest point
  :math:`\mathbf{c} = \mathrm{clamp}(\mathbf{x}, \mathbf{lo}, \mathbf{hi})`, with normal
  :math:`(\mathbf{x}-\mathbf{c})/\lvert\mathbf{x}-\mathbf{c}\rvert`: on a face, an edge or a
  corner. Element id 6 in every case, so a sphere rolling over an edge keeps its contact history.

A sphere whose centre crosses a face changes side (a thin block is a wall from both sides). ``INF``
faces are never touched.

Example::

    region box block 0 10 0 10 0 10
    create_box 1 box
"""

import math

import numpy as np
from numba import njit
from pydantic import model_validator

from pdps_core.api import Region, RegionArgs, ScriptError, SurfaceContacts, param

HUGE = 1e300


UNBOUNDED = ("INF", "-INF")
Bound = float | str
EXTERIOR = 6        # element id of a contact from outside (face, edge or corner alike)


@njit(cache=True)
def block_contacts(x, lo, hi, reach, index, distance, normal, element):
    """Contacts of points x with the block's surface closer than reach (see the module docstring),
    written into the buffers (room for 6 rows a point); returns how many."""
    m = 0
    for p in range(x.shape[0]):
        inside = True
        for d in range(3):
            if x[p, d] < lo[d] or x[p, d] > hi[d]:
                inside = False
        if inside:
            for d in range(3):
                for side in range(2):
                    gap = x[p, d] - lo[d] if side == 0 else hi[d] - x[p, d]
                    if gap < reach:
                        index[m] = p
                        distance[m] = gap
                        for e in range(3):
                            normal[m, e] = 0.0
                        normal[m, d] = 1.0 if side == 0 else -1.0
                        element[m] = 2 * d + side
                        m += 1
        else:
            dx = x[p, 0] - min(max(x[p, 0], lo[0]), hi[0])
            dy = x[p, 1] - min(max(x[p, 1], lo[1]), hi[1])
            dz = x[p, 2] - min(max(x[p, 2], lo[2]), hi[2])
            gap = math.sqrt(dx * dx + dy * dy + dz * dz)
            if gap < reach:
                index[m] = p
                distance[m] = gap
                normal[m, 0] = dx / gap
                normal[m, 1] = dy / gap
                normal[m, 2] = dz / gap
                element[m] = EXTERIOR
                m += 1
    return m


@njit(cache=True)
def block_wall_contacts(x, lo, hi, reach, exterior, index, distance, normal, element, curvature):
    """LAMMPS's RegBlock::surface_interior (each face closer than reach of a point inside, faces 0-5
    xlo, xhi, ylo, yhi, zlo, zhi) or surface_exterior (a point outside within reach: its closest
    point, element 0), normals LAMMPS's (the vector from the surface times 1 / distance); a point at
    distance 0 has no normal and no contact. Returns how many rows (room for 6 a point)."""
    m = 0
    for p in range(x.shape[0]):
        if not exterior:
            if (x[p, 0] < lo[0] or x[p, 0] > hi[0] or x[p, 1] < lo[1] or x[p, 1] > hi[1]
                    or x[p, 2] < lo[2] or x[p, 2] > hi[2]):
                continue
            for d in range(3):
                for side in range(2):
                    gap = x[p, d] - lo[d] if side == 0 else hi[d] - x[p, d]
                    if gap < reach and gap > 0.0:
                        index[m] = p
                        distance[m] = gap
                        rinv = 1.0 / gap
                        for e in range(3):
                            normal[m, e] = 0.0
                        normal[m, d] = gap * rinv if side == 0 else -gap * rinv
                        element[m] = 2 * d + side
                        curvature[m] = 0.0
                        m += 1
            continue
        outside_reach = False
        inside = True
        for d in range(3):
            if x[p, d] <= lo[d] - reach or x[p, d] >= hi[d] + reach:
                outside_reach = True
            if not (x[p, d] > lo[d] and x[p, d] < hi[d]):
                inside = False
        if outside_reach or inside:
            continue
        dx = x[p, 0] - min(max(x[p, 0], lo[0]), hi[0])
        dy = x[p, 1] - min(max(x[p, 1], lo[1]), hi[1])
        dz = x[p, 2] - min(max(x[p, 2], lo[2]), hi[2])
        gap = math.sqrt(dx * dx + dy * dy + dz * dz)
        if gap < reach and gap > 0.0:
            rinv = 1.0 / gap
            index[m] = p
            distance[m] = gap
            normal[m, 0] = dx * rinv
            normal[m, 1] = dy * rinv
            normal[m, 2] = dz * rinv
            element[m] = 0
            curvature[m] = 0.0
            m += 1
    return m


class RegionBlock(Region):
    name = "block"
    usage = "region ID block xlo xhi ylo yhi zlo zhi [side in|out] [units box|lattice]"

    class Args(RegionArgs):
        xlo: Bound = param(unit="distance")
        xhi: Bound = param(unit="distance")
        ylo: Bound = param(unit="distance")
        yhi: Bound = param(unit="distance")
        zlo: Bound = param(unit="distance")
        zhi: Bound = param(unit="distance")

        @model_validator(mode="after")
        def _words(self):
            for name in ("xlo", "xhi", "ylo", "yhi", "zlo", "zhi"):
                value = getattr(self, name)
                if isinstance(value, str) and value not in ("EDGE", *UNBOUNDED):
                    try:
                        finite = math.isfinite(float(value))
                    except ValueError:
                        finite = False
                    # float() also reads "nan", "inf" and "1e999": only INF/-INF may be unbounded
                    if not finite:
                        raise ValueError(f"{name} must be a number, INF, -INF or EDGE (got {value})")
            return self

    def __init__(self, sim, id, args):
        super().__init__(sim, id, args)
        bounds = []
        for k, name in enumerate(("xlo", "xhi", "ylo", "yhi", "zlo", "zhi")):
            value = getattr(args, name)
            is_lo = k % 2 == 0
            if value in UNBOUNDED:
                value = -HUGE if is_lo else HUGE       # LAMMPS: INF opens the block on that side
            elif value == "EDGE":
                if sim.box is None:
                    raise ScriptError(f"{name} EDGE needs the simulation box to exist")
                value = (sim.box.lo if is_lo else sim.box.hi)[k // 2]
            else:
                value = float(value) * self.scale[k // 2]
            bounds.append(float(value))
        self.lo = np.array(bounds[0::2])
        self.hi = np.array(bounds[1::2])
        for axis, lo, hi in zip("xyz", self.lo, self.hi):
            if not lo <= hi:
                raise ScriptError(f"{axis}lo must be <= {axis}hi (got {lo:g} {hi:g})")

    def inside(self, x):
        return np.all((x >= self.lo) & (x <= self.hi), axis=1)

    def bounds(self):
        if np.any(np.abs(self.lo) >= HUGE) or np.any(np.abs(self.hi) >= HUGE):
            raise ScriptError(f"region {self.id} is unbounded (INF) and cannot define a box")
        return self.extent()

    def extent(self):
        return self.lo.copy(), self.hi.copy()

    def surface_contacts(self, x, reach, out=None):
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1, 3)
        out = out if out is not None else SurfaceContacts()
        return out.rows(block_contacts(x, self.lo, self.hi, float(reach), *out.room(6 * len(x))))

    def own_wall_contacts(self, x, reach, out):
        out.room(6 * len(x))
        return out.wall_rows(block_wall_contacts(x, self.lo, self.hi, float(reach), self.side_out, out.index,
                                                 out.distance, out.normal, out.element, out.curvature))
