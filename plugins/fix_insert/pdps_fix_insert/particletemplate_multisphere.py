r"""Fix ``particletemplate/multisphere``: what one inserted rigid clump of spheres is (LIGGGHTS's fix
particletemplate/multisphere): its spheres, its mass, centre of mass and inertia, for the insertion
fixes to insert whole and a ``fix multisphere`` to move.

The template's properties come from a Monte Carlo integration over the union of its spheres, done
as LIGGGHTS-PUBLIC 3.8.0's source does it, with its Park-Miller generator seeded with SEED, so that
a template's numbers are LIGGGHTS's to round-off:

1. the bounding sphere: Ritter's pass over the spheres in a random order, 200 times, the smallest
   kept (radius r_bound, centre x_bound);
2. NTRY points uniform in the spheres' bounding box: the share inside any sphere gives the volume
   V, their mean the centre of mass (the spheres are then shifted to put it at the origin),
   mass M = rho V;
3. NTRY more points: the inertia tensor about the centre of mass,
   :math:`I_{ab} = \rho\,V_\mathrm{box}/N_\mathrm{try} \sum_\mathrm{inside} (r^2 \delta_{ab} - r_a r_b)`,
   and its principal moments and axes, by LIGGGHTS's Jacobi rotations, in their order and with
   their signs (the third axis flipped to a right-handed frame; a moment below 1e-7 of the largest
   is zero).

With ``mass M`` and ``inertia_tensor ...`` those are given instead: ``use_volume`` keeps step 2 for the
volume and centre (density M / V), ``use_density`` skips it (volume M / rho, the centre of mass the
template's origin), as LIGGGHTS does.

Syntax::

    fix ID GROUP particletemplate/multisphere SEED atom_type T density constant RHO
        nspheres N ntry NTRY spheres file FILE [scale S] | spheres X1 Y1 Z1 R1 ... XN YN ZN RN
        type MT [mass M inertia_tensor IXX IXY IXZ IYY IYZ IZZ use_volume|use_density]
        [fflag on|off on|off on|off] [tflag on|off on|off on|off] [volume_limit V]

- ``SEED``: the Monte Carlo generator's seed (a positive whole number; LIGGGHTS asks for a prime
  above 10,000).
- ``atom_type T``: the spheres' particle type (default 1).
- ``density constant RHO``: the clump's density (mass/distance^3; constant only, as LIGGGHTS).
- ``nspheres N``: the number of spheres (>= 2); ``ntry NTRY``: Monte Carlo points (>= 1000; LIGGGHTS
  warns below 1e5).
- ``spheres file FILE scale S``: the spheres from a file, one ``x y z r`` per line (``#`` comments and
  blank lines skipped), exactly N lines, positions and radii times S (LIGGGHTS's source needs
  ``scale``; pdps takes 1 without it); or the 4 N numbers inline (distance).
- ``type MT``: the clump type, unique among the templates and consecutive from 1 (LIGGGHTS's check).
- ``mass M`` (mass) and ``inertia_tensor`` (mass distance^2, about the centre of mass), only both
  together and with ``use_volume`` or ``use_density``.
- ``fflag``, ``tflag``: the bodies' translational and rotational freedom per axis (default on on on).
- ``volume_limit V``: the smallest volume allowed (default 1e-12, distance^3).

Example::

    fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 nspheres 50 &
        ntry 1000000 spheres file data/stone1.multisphere scale 0.001 type 1
"""

import math
from pathlib import Path
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import ScriptError, StyleArgs, keyword, param, park_state, park_uniform

from .particletemplate_sphere import FixParticleTemplateSphere, units
from .size_distribution import Distribution
from .whole_number import WholeNumber

SHUFFLES = 200          # LIGGGHTS's N_SHUFFLE_BOUND
EPSILON = 1.0e-7        # a principal moment below EPSILON x the largest is zero
OnOff = Literal["on", "off"]


def jacobi(tensor, sweeps=50):
    """Principal moments and axes (columns) of a symmetric 3x3 tensor by the cyclic Jacobi rotations
    of LIGGGHTS's (and LAMMPS's) MathExtra::jacobi, whose order and signs of the axes are the body
    frame LIGGGHTS's bodies have (their quat, inertia, ex_space... as compute multisphere reads
    them); numpy's eigh sorts them instead."""
    a = np.array(tensor, dtype=np.float64)
    vectors = np.eye(3)
    b = np.diag(a).copy()
    values = b.copy()
    z = np.zeros(3)

    def rotate(m, i, j, k, l, s, tau):
        g, h = m[i, j], m[k, l]
        m[i, j] = g - s * (h + g * tau)
        m[k, l] = h + s * (g - h * tau)

    for sweep in range(1, sweeps + 1):
        if abs(a[0, 1]) + abs(a[0, 2]) + abs(a[1, 2]) == 0.0:
            return values, vectors
        tresh = 0.2 * (abs(a[0, 1]) + abs(a[0, 2]) + abs(a[1, 2])) / 9.0 if sweep < 4 else 0.0
        for i in range(2):
            for j in range(i + 1, 3):
                g = 100.0 * abs(a[i, j])
                if sweep > 4 and abs(values[i]) + g == abs(values[i]) and abs(values[j]) + g == abs(values[j]):
                    a[i, j] = 0.0
                elif abs(a[i, j]) > tresh:
                    h = values[j] - values[i]
                    if abs(h) + g == abs(h):
                        t = a[i, j] / h
                    else:
                        theta = 0.5 * h / a[i, j]
                        t = 1.0 / (abs(theta) + math.sqrt(1.0 + theta * theta))
                        if theta < 0.0:
                            t = -t
                    c = 1.0 / math.sqrt(1.0 + t * t)
                    s = t * c
                    tau = s / (1.0 + c)
                    h = t * a[i, j]
                    z[i] -= h
                    z[j] += h
                    values[i] -= h
                    values[j] += h
                    a[i, j] = 0.0
                    for k in range(i):
                        rotate(a, k, i, k, j, s, tau)
                    for k in range(i + 1, j):
                        rotate(a, i, k, k, j, s, tau)
                    for k in range(j + 1, 3):
                        rotate(a, i, k, j, k, s, tau)
                    for k in range(3):
                        rotate(vectors, k, i, k, j, s, tau)
        b += z
        values = b.copy()
        z[:] = 0.0
    raise ScriptError("the inertia tensor's principal axes were not found in 50 Jacobi sweeps")


@njit(cache=True)
def bounding_sphere(state, x, r):
    """LIGGGHTS's calc_bounding_sphere: Ritter's pass in a random order, SHUFFLES times; the
    smallest (radius, centre) found."""
    n = len(r)
    best, centre = 1e8, np.zeros(3)
    visited = np.zeros(n, dtype=np.bool_)
    for _ in range(SHUFFLES):
        visited[:] = False
        k = -1
        while k < 0 or k >= n or visited[k]:
            k = int(park_uniform(state) * n)
        visited[k] = True
        seen = 1
        c = x[k].copy()
        radius = r[k]
        while seen < n:
            while k < 0 or k >= n or visited[k]:
                k = int(park_uniform(state) * n)
            seen += 1
            visited[k] = True
            d = x[k] - c
            dist = math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
            if dist + r[k] > radius:
                fact = (dist + r[k] - radius) / (2.0 * dist)
                d *= fact
                c += d
                radius += math.sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2])
        if radius < best:
            best = radius
            centre[:] = c
    return best, centre


@njit(cache=True)
def _inside(x, r, p):
    for j in range(len(r)):
        dx, dy, dz = p[0] - x[j, 0], p[1] - x[j, 1], p[2] - x[j, 2]
        if dx * dx + dy * dy + dz * dz < r[j] * r[j]:
            return True
    return False


@njit(cache=True)
def centre_of_mass(state, x, r, lo, hi, ntry):
    """LIGGGHTS's calc_center_of_mass: (the points inside, their running mean)."""
    xcm = np.zeros(3)
    p = np.zeros(3)
    hits = 0
    for _ in range(ntry):
        for d in range(3):
            p[d] = lo[d] + (hi[d] - lo[d]) * park_uniform(state)
        if _inside(x, r, p):
            for d in range(3):
                xcm[d] = (xcm[d] * hits + p[d]) / (hits + 1)
            hits += 1
    return hits, xcm


@njit(cache=True)
def inertia_sums(state, x, r, lo, hi, ntry):
    """LIGGGHTS's calc_inertia before its scaling: sum over the points inside of r^2 delta - r r."""
    moi = np.zeros((3, 3))
    p = np.zeros(3)
    for _ in range(ntry):
        for d in range(3):
            p[d] = lo[d] + (hi[d] - lo[d]) * park_uniform(state)
        if _inside(x, r, p):
            moi[0, 0] += p[1] * p[1] + p[2] * p[2]
            moi[0, 1] -= p[0] * p[1]
            moi[0, 2] -= p[0] * p[2]
            moi[1, 0] -= p[1] * p[0]
            moi[1, 1] += p[0] * p[0] + p[2] * p[2]
            moi[1, 2] -= p[1] * p[2]
            moi[2, 0] -= p[2] * p[0]
            moi[2, 1] -= p[2] * p[1]
            moi[2, 2] += p[0] * p[0] + p[1] * p[1]
    return moi


class FixParticleTemplateMultisphere(FixParticleTemplateSphere):
    name = "particletemplate/multisphere"
    usage = ("fix ID GROUP particletemplate/multisphere SEED atom_type T density constant RHO nspheres N ntry NTRY "
             "spheres file FILE [scale S] | spheres X1 Y1 Z1 R1 ... type MT [mass M inertia_tensor IXX IXY IXZ IYY "
             "IYZ IZZ use_volume|use_density] [fflag on|off on|off on|off] [tflag on|off on|off on|off] "
             "[volume_limit V]")

    class Args(StyleArgs):
        seed: WholeNumber = param(ge=1, unit="1")
        atom_type: WholeNumber = keyword(1, ge=1, unit="1")
        density: tuple[Literal["constant"], float] = keyword(..., unit=units("density"))
        nspheres: WholeNumber = keyword(..., ge=2, unit="1")
        ntry: WholeNumber = keyword(..., ge=1000, unit="1")
        spheres: (tuple[Literal["file"], str, Literal["scale"], float] | tuple[Literal["file"], str]
                  | list[float]) = keyword(..., unit="distance")
        type: WholeNumber = keyword(..., ge=1, unit="1")
        mass: float | None = keyword(None, gt=0, unit="mass")
        inertia_tensor: tuple[float, float, float, float, float, float] | None = keyword(None, unit="mass*area")
        use_volume: tuple[()] | None = keyword(None)
        use_density: tuple[()] | None = keyword(None)
        fflag: tuple[OnOff, OnOff, OnOff] = keyword(("on", "on", "on"))
        tflag: tuple[OnOff, OnOff, OnOff] = keyword(("on", "on", "on"))
        volume_limit: float = keyword(1e-12, gt=0, unit="volume")

    @classmethod
    def check_args(cls, args):
        if args.density[1] <= 0:
            raise ScriptError(f"density must be > 0 (got {args.density[1]:g})")
        if (args.mass is None) != (args.inertia_tensor is None):
            raise ScriptError("have to define either both 'mass' and 'inertia_tensor' or none of the two (as LIGGGHTS)")
        if args.mass is not None and (args.use_volume is None) == (args.use_density is None):
            raise ScriptError("with 'mass' and 'inertia_tensor', give one of 'use_volume' or 'use_density'")
        if isinstance(args.spheres, list) and len(args.spheres) != 4 * args.nspheres:
            raise ScriptError(f"spheres: {args.nspheres} spheres need {4 * args.nspheres} numbers x y z r (got "
                              f"{len(args.spheres)})")
        if isinstance(args.spheres, tuple) and len(args.spheres) == 4 and not args.spheres[3] > 0:
            raise ScriptError(f"scale must be > 0 (got {args.spheres[3]:g})")

    def __init__(self, sim, id, group, args):
        self.sim, self.id, self.group, self.args = sim, id, group, args
        self.thermo_energy = False
        self.thermo_virial = self.virial_default
        if sim.dimension != 3:
            raise ScriptError(f"fix {id} particletemplate/multisphere needs a 3-d simulation (as LIGGGHTS)")
        self.seed = args.seed
        self.atom_type = args.atom_type
        if sim.ntypes and self.atom_type > sim.ntypes:
            raise ScriptError(f"atom_type must be from 1 to {sim.ntypes}, the number of types (got {self.atom_type})")
        self.clumptype = args.type
        taken = [f.id for f in sim.fixes.values() if isinstance(f, FixParticleTemplateMultisphere)
                 and f.id != id and f.clumptype == self.clumptype]
        if taken:
            raise ScriptError(f"type {self.clumptype}: fix {taken[0]} has it; multisphere template types have to be "
                              "unique (as LIGGGHTS)")
        rho = float(args.density[1])
        self.density = Distribution.read(args.density, "density", radius=False)
        x, r = self._spheres(sim, args)
        self.fflag = np.array([flag == "on" for flag in args.fflag])
        self.tflag = np.array([flag == "on" for flag in args.tflag])
        self._properties(x, r, rho, args)
        if self.volume_expected < args.volume_limit:
            raise ScriptError(f"the template's volume {self.volume_expected:.3g} is below volume_limit "
                              f"{args.volume_limit:g}: check the sphere units (scale), or lower volume_limit")
        if args.ntry < 100000:
            sim.warn(f"fix {id} particletemplate/multisphere: ntry {args.ntry} is very low (as LIGGGHTS warns below 1e5)")
        sim.info(f"fix {id} particletemplate/multisphere: mass {self.mass_expected:.6e}, bounding sphere radius "
                 f"{self.bound_radius:.6e}, principal moments {', '.join(f'{m:.6e}' for m in self.inertia)}")

    def _spheres(self, sim, args):
        """Positions (n, 3) and radii (n,) as given (a file's times its scale)."""
        n = args.nspheres
        if isinstance(args.spheres, list):
            values = np.array(args.spheres).reshape(n, 4)
        else:
            scale = args.spheres[3] if len(args.spheres) == 4 else 1.0
            values = self._read_file(sim, args.spheres[1], n) * scale
        x, r = np.ascontiguousarray(values[:, :3]), np.ascontiguousarray(values[:, 3])
        if not np.all(r > 0):
            raise ScriptError(f"spheres: radius must be > 0 (sphere {int(np.argmin(r > 0)) + 1}: {r.min():g})")
        return x, r

    def _read_file(self, sim, name, n):
        path = Path(sim.resolve(name))
        try:
            text = path.read_text()
        except (OSError, UnicodeDecodeError) as error:
            raise ScriptError(f"spheres file {name}: cannot read it ({getattr(error, 'strerror', None) or error})") from None
        rows = []
        for k, line in enumerate(text.splitlines(), 1):
            words = line.split("#")[0].split()
            if not words:
                continue
            try:
                values = [float(w) for w in words[:4]]
            except ValueError:
                raise ScriptError(f"spheres file {name}:{k}: not numbers: {line.strip()} (a line is x y z r)") from None
            if len(values) < 4 or not all(map(math.isfinite, values)):
                raise ScriptError(f"spheres file {name}:{k}: a line is x y z r (got {line.strip()})")
            rows.append(values)
        if len(rows) != n:
            raise ScriptError(f"spheres file {name}: {len(rows)} spheres, nspheres says {n}")
        return np.array(rows)

    def _properties(self, x, r, rho, args):
        """Mass, volume, centre, inertia and the body frame, by LIGGGHTS's procedure (module doc)."""
        state = park_state(args.seed)
        lo, hi = (x - r[:, None]).min(axis=0), (x + r[:, None]).max(axis=0)
        self.bound_radius, bound_centre = bounding_sphere(state, x, r)
        if args.mass is None or args.use_volume is not None:
            hits, xcm = centre_of_mass(state, x, r, lo, hi, args.ntry)
            if hits == 0:
                raise ScriptError(f"fix {self.id}: no Monte Carlo point fell inside a sphere: raise ntry")
            volume = hits / args.ntry * (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])
            x, lo, hi, bound_centre = x - xcm, lo - xcm, hi - xcm, bound_centre - xcm
        if args.mass is None:
            mass = volume * rho
            scale = rho / args.ntry * (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2])
            tensor = inertia_sums(state, x, r, lo, hi, args.ntry) * scale
            tensor = 0.5 * (tensor + tensor.T)
        else:
            mass = args.mass
            ixx, ixy, ixz, iyy, iyz, izz = args.inertia_tensor
            tensor = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
            if args.use_volume is not None:
                rho = mass / volume
            else:
                volume = mass / rho
        moments, vectors = jacobi(tensor)
        if moments.min() < -1e-12 * abs(moments).max():
            raise ScriptError(f"fix {self.id}: the inertia tensor has a negative principal moment "
                              f"({moments.min():.6g})")
        moments[moments < EPSILON * moments.max()] = 0.0
        ex, ey, ez = vectors[:, 0].copy(), vectors[:, 1].copy(), vectors[:, 2].copy()
        if np.dot(np.cross(ex, ey), ez) < 0.0:
            ez = -ez
        self.axes = np.array([ex, ey, ez])                 # rows: the principal axes in the template frame
        self.inertia = moments
        self.positions = x                                 # about the centre of mass, template frame
        self.displace = x @ self.axes.T                    # the same in the body frame
        self.bound_offset = bound_centre                   # centre of mass to bounding-sphere centre
        self.radii = r
        self.nspheres = len(r)
        self.body_density = rho
        self.mass_expected = float(mass)
        self.volume_expected = float(volume)
        self.max_radius = float(r.max())

    def draw(self, rng, n):
        """(radii, densities) of n clumps for their placement, which puts their centres of mass at
        the points drawn (as LIGGGHTS does): the radius of the sphere about the centre of mass that
        holds the clump in any orientation (bounding radius plus the bounding centre's distance),
        and the clump's density."""
        reach = self.bound_radius + float(np.linalg.norm(self.bound_offset))
        return np.full(n, reach), np.full(n, self.body_density)
