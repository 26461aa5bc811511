r"""Fix ``pour``: spheres poured in batches into a falling stream from a block or a z-axis cylinder
(LAMMPS's fix pour, GRANULAR package, as LAMMPS 22 Jul 2025 computes it).

Syntax::

    fix ID GROUP pour N TYPE SEED keyword values ...

        region ID                          block, or z-axis cylinder (3-d only): the insertion volume (required)
        diam one D | range DLO DHI | poly NPOLY D1 P1 ... DN PN
                                           diameters: D (default 1), uniform in [DLO, DHI], or D_i with
                                           probability P_i (the P_i sum to 1)
        dens DLO DHI                       density uniform in [DLO, DHI] (default 1 1)
        vol FRAC MAXATTEMPT                volume fraction of a batch (default 0.25), tries per particle (50)
        rate V                             the insertion volume moves along z (y in 2-d) at V (default 0)
        vel VXLO VXHI VYLO VYHI VZ         3-d: vx, vy uniform in their ranges, vz at the top (default 0)
        vel VXLO VXHI VY                   2-d: vx uniform, vy at the top
        id max|next                        ids after the largest present one (pdps always numbers so)
        ignore                             LAMMPS skips line and triangle particles (pdps has none)

        mol TEMPLATE                       copies of a molecule template (the molecule command) instead
                                           of spheres; TYPE is added to the template's types
        rigid FIX_ID                       each copy a rigid body of that fix rigid/small ... mol TEMPLATE

``shake`` and ``molfrac`` are refused (pdps has no fix shake; its templates are one molecule each).
Units: diameters distance,
densities mass/distance^3 (in 2-d too: the mass is :math:`\tfrac{4}{3}\pi r^3 \rho`, as LAMMPS), velocities.

The schedule. A batch falls for the time a particle needs from the top of the volume to its bottom
under the gravity g of the fix gravity (which must point along -z, -y in 2-d) at the first run:
with :math:`v_r = v_z - \mathrm{rate}` and :math:`\Delta = z_{hi} - z_{lo}`,

.. math::  t = \bigl(-v_r - \sqrt{v_r^2 + 2 g \Delta}\bigr) / (-g), \qquad
           n_\mathrm{freq} = \lfloor t/\Delta t + 1/2 \rfloor

steps, and holds :math:`n_\mathrm{per} = \lfloor f V / V_1 \rfloor` particles, V the volume (a block's
y extent at least 1 in 3-d; its area in 2-d), :math:`V_1` the sphere (disc in 2-d) of the largest
diameter, or the mean of the ``poly`` ones. The first batch comes on the step after the fix is
defined, and on the first step of every later run; then every :math:`n_\mathrm{freq}` steps until N.
The gravity and the time step are those of the first run (LAMMPS 22 Jul 2025 takes them there: a
fix gravity or timestep given after the fix pour counts); a later run with another is refused.

One batch, as LAMMPS draws it from its Park-Miller generator (seeded with SEED, 30 numbers discarded),
the same on every rank: for each particle a height :math:`h = z_{hi} - u^2 (z_{hi} - z_{lo})` (u
uniform; the square spreads the stream evenly in time), its diameter, then up to MAXATTEMPT x batch
tries (shared by the batch) at x, y uniform over the block (a cylinder's disc by rejection) at that
height, each refused where the sphere touches or overlaps (:math:`d \le r_i + r_j`, minimum image)
a present particle near the volume or one placed before it; the first particle that finds no room
ends the batch, with LAMMPS's warning. A placed particle gets vx, vy uniform in their ranges and
:math:`v_z = -\sqrt{v_z^2 + 2 g (z_{hi} - z)}`, the speed of a fall from the top, then its density.

Molecules (``mol``), as LAMMPS draws them: the volume of one is the disc or sphere of the template's
reach (``molradius``: the largest distance of an atom's surface from its geometric centre), which
also widens the near list; per molecule a height; per try a centre (x, y at that height), a number
LAMMPS uses to choose among a set of templates (pdps has one: drawn and unused), a random axis (three
numbers less 1/2, normalised; z in 2-d) and an angle :math:`2\pi u`; the template turned by that
quaternion about its centre and put there, each atom wrapped into the periodic box (its image
flags counted); a try fails where any atom touches a present or placed particle. A placed copy
takes the velocity (drawn as a sphere's) on every atom, a new molecule id (where the particles have
molecule ids), the template's radii (0.5 without Diameters) and masses (4/3 pi r^3 without Masses);
with ``rigid`` the fix makes each copy a body, given the centre, velocity and turn.

Output: none (LAMMPS's fix pour has no f_ID).
"""

import math
from typing import Literal

import numpy as np
from numba import njit
from pdps_core.api import Fix, MoleculeBodies, ScriptError, StyleArgs, keyword, park_state, park_uniform, param

from .whole_number import WholeNumber

GRAVITY_DIRECTION_TOLERANCE = 0.001     # LAMMPS's EPSILON on the gravity unit vector
POLY_SUM_TOLERANCE = 1.0e-10            # LAMMPS's SMALL on the sum of the poly fractions
WARMUP = 30                             # numbers LAMMPS discards after seeding
ONE, RANGE, POLY = 0, 1, 2
BLOCK, CYLINDER = 0, 1
# LAMMPS takes these two region styles by name and reads their geometry (RegBlock's and
# RegCylinder's bounds); pdps's regions declare no capability that gives it
SHAPES = {"block": BLOCK, "cylinder": CYLINDER}
ONE_TEMPLATE = "pdps's molecule templates are one molecule each (LAMMPS's molfrac chooses among a set's)"


@njit(cache=True)
def _outside(value, lo, hi, boxlo, prd, periodic):
    """LAMMPS's FixPour::outside: value outside [lo, hi], a range wrapping a periodic axis."""
    outside_range = value < lo or value > hi
    if not outside_range or not periodic:
        return outside_range
    boxhi = boxlo + prd
    if (lo < boxlo and hi > boxhi) or hi - lo > prd:
        return False
    if lo < boxlo:
        return value > hi and value < lo + prd
    if hi > boxhi:
        return value < lo and value > hi - prd
    return True


@njit(cache=True)
def _minimum_image(delta, prd, periodic):
    if periodic:
        half = 0.5 * prd
        while delta > half:
            delta -= prd
        while delta < -half:
            delta += prd
    return delta


@njit(cache=True)
def near_volume(x, radius, n, shape, dimension, bounds, lo_current, hi_current, radius_max, boxlo, prd,
                periodic):
    """Rows of the particles that could touch a sphere inserted into the volume (LAMMPS's
    FixPour::overlap): within r_i + radius_max of the block, or of the cylinder's disc and z range."""
    keep = np.zeros(n, dtype=np.bool_)
    for i in range(n):
        delta = radius[i] + radius_max
        if dimension == 2:
            keep[i] = not (_outside(x[i, 0], bounds[0] - delta, bounds[1] + delta, boxlo[0], prd[0], periodic[0])
                           or _outside(x[i, 1], lo_current - delta, hi_current + delta, boxlo[1], prd[1],
                                       periodic[1]))
            continue
        vertical = _outside(x[i, 2], lo_current - delta, hi_current + delta, boxlo[2], prd[2], periodic[2])
        if shape == BLOCK:
            keep[i] = not (_outside(x[i, 0], bounds[0] - delta, bounds[1] + delta, boxlo[0], prd[0], periodic[0])
                           or _outside(x[i, 1], bounds[2] - delta, bounds[3] + delta, boxlo[1], prd[1],
                                       periodic[1]) or vertical)
        else:
            dx = _minimum_image(x[i, 0] - bounds[4], prd[0], periodic[0])
            dy = _minimum_image(x[i, 1] - bounds[5], prd[1], periodic[1])
            reach = bounds[6] + delta
            keep[i] = dx * dx + dy * dy <= reach * reach and not vertical
    return np.flatnonzero(keep)


@njit(cache=True)
def _draw_centre(state, coord, h, dimension, shape, bounds):
    """A try's centre at height h, in LAMMPS's order of draws: x (2-d: the height is y), or x and
    y in the block, or a point of the cylinder's disc by rejection."""
    if dimension == 2:
        coord[0] = bounds[0] + park_uniform(state) * (bounds[1] - bounds[0])
        coord[1] = h
        coord[2] = 0.0
    elif shape == BLOCK:
        coord[0] = bounds[0] + park_uniform(state) * (bounds[1] - bounds[0])
        coord[1] = bounds[2] + park_uniform(state) * (bounds[3] - bounds[2])
        coord[2] = h
    else:
        while True:
            r1 = park_uniform(state) - 0.5
            r2 = park_uniform(state) - 0.5
            if r1 * r1 + r2 * r2 < 0.25:
                break
        coord[0] = bounds[4] + 2.0 * r1 * bounds[6]
        coord[1] = bounds[5] + 2.0 * r2 * bounds[6]
        coord[2] = h


@njit(cache=True)
def _radius(state, dstyle, radius_one, radius_lo, radius_hi, poly_radius, poly_fraction):
    if dstyle == ONE:
        return radius_one
    if dstyle == RANGE:
        return radius_lo + park_uniform(state) * (radius_hi - radius_lo)
    value = park_uniform(state)
    i = 0
    total = 0.0
    while total < value and i < len(poly_fraction):
        total += poly_fraction[i]
        i += 1
    return poly_radius[max(i - 1, 0)]


@njit(cache=True)
def pour_batch(state, nnew, maxattempt, lo_current, hi_current, shape, dimension, bounds, dstyle, radius_one,
               radius_lo, radius_hi, poly_radius, poly_fraction, density_lo, density_hi, velocity, grav,
               near_x, near_r, prd, periodic, new_x, new_r, new_v, new_density):
    """One batch in LAMMPS's order of draws (FixPour::pre_exchange, atoms); writes the placed
    particles' centres, radii, velocities and densities and returns how many were placed."""
    nnear = len(near_r)
    xs = np.empty((nnear + nnew, 3))
    rs = np.empty(nnear + nnew)
    xs[:nnear] = near_x
    rs[:nnear] = near_r
    coord = np.zeros(3)
    attempt = 0
    maxiter = nnew * maxattempt
    placed = 0
    while placed < nnew:
        rn = park_uniform(state)
        h = hi_current - rn * rn * (hi_current - lo_current)
        radius = _radius(state, dstyle, radius_one, radius_lo, radius_hi, poly_radius, poly_fraction)
        success = False
        while attempt < maxiter:
            attempt += 1
            _draw_centre(state, coord, h, dimension, shape, bounds)
            clear = True
            for i in range(nnear):
                delx = _minimum_image(coord[0] - xs[i, 0], prd[0], periodic[0])
                dely = _minimum_image(coord[1] - xs[i, 1], prd[1], periodic[1])
                delz = _minimum_image(coord[2] - xs[i, 2], prd[2], periodic[2])
                radsum = radius + rs[i]
                if delx * delx + dely * dely + delz * delz <= radsum * radsum:
                    clear = False
                    break
            if clear:
                success = True
                break
        if not success:
            break
        xs[nnear] = coord
        rs[nnear] = radius
        nnear += 1
        new_x[placed] = coord
        new_r[placed] = radius
        new_v[placed, 0] = velocity[0] + park_uniform(state) * (velocity[1] - velocity[0])
        if dimension == 3:
            new_v[placed, 1] = velocity[2] + park_uniform(state) * (velocity[3] - velocity[2])
            new_v[placed, 2] = -math.sqrt(velocity[5] * velocity[5] + 2.0 * grav * (coord[2] - hi_current))
        else:
            new_v[placed, 1] = -math.sqrt(velocity[4] * velocity[4] + 2.0 * grav * (coord[1] - hi_current))
            new_v[placed, 2] = 0.0
        new_density[placed] = density_lo + park_uniform(state) * (density_hi - density_lo)
        placed += 1
    return placed


@njit(cache=True)
def _remap(coord, image, boxlo, prd, periodic):
    """LAMMPS's Domain::remap of one point into the periodic box, its image flags counted."""
    for d in range(3):
        if not periodic[d]:
            continue
        hi = boxlo[d] + prd[d]
        while coord[d] < boxlo[d]:
            coord[d] += prd[d]
            image[d] -= 1
        while coord[d] >= hi:
            coord[d] -= prd[d]
            image[d] += 1
        coord[d] = max(coord[d], boxlo[d])


@njit(cache=True)
def pour_molecule_batch(state, nnew, maxattempt, lo_current, hi_current, shape, dimension, bounds, velocity, grav,
                        dx, atom_r, near_x, near_r, boxlo, prd, periodic, new_x, new_image, centres, quats, new_v):
    """One batch of molecules in LAMMPS's order of draws (FixPour::pre_exchange, mode MOLECULE): per
    molecule a height; per try a centre, the template's draw (one template: unused), a random axis
    (3-d; z in 2-d) and angle, the copy turned about its geometric centre and wrapped into the
    box, refused where any atom touches a present or placed one; then the velocity. Writes the
    atoms (molecule by molecule), their image flags, each copy's centre, quaternion and velocity;
    returns how many molecules were placed."""
    natom = len(atom_r)
    nnear = len(near_r)
    xs = np.empty((nnear + nnew * natom, 3))
    rs = np.empty(nnear + nnew * natom)
    xs[:nnear] = near_x
    rs[:nnear] = near_r
    coord = np.zeros(3)
    axis = np.zeros(3)
    quat = np.zeros(4)
    rot = np.zeros((3, 3))
    trial = np.zeros((natom, 3))
    image = np.zeros((natom, 3), dtype=np.int32)
    attempt = 0
    maxiter = nnew * maxattempt
    placed = 0
    while placed < nnew:
        rn = park_uniform(state)
        h = hi_current - rn * rn * (hi_current - lo_current)
        success = False
        while attempt < maxiter:
            attempt += 1
            _draw_centre(state, coord, h, dimension, shape, bounds)
            park_uniform(state)     # LAMMPS's choice among the templates of a set (pdps: one)
            if dimension == 3:
                axis[0] = park_uniform(state) - 0.5
                axis[1] = park_uniform(state) - 0.5
                axis[2] = park_uniform(state) - 0.5
            else:
                axis[0] = 0.0
                axis[1] = 0.0
                axis[2] = 1.0
            theta = park_uniform(state) * 2.0 * math.pi
            scale = 1.0 / math.sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2])
            half = 0.5 * theta
            sine = math.sin(half)
            quat[0] = math.cos(half)
            for d in range(3):
                quat[d + 1] = axis[d] * scale * sine
            _rotation(quat, rot)
            for m in range(natom):
                for d in range(3):
                    trial[m, d] = rot[d, 0] * dx[m, 0] + rot[d, 1] * dx[m, 1] + rot[d, 2] * dx[m, 2] + coord[d]
                    image[m, d] = 0
                _remap(trial[m], image[m], boxlo, prd, periodic)
            clear = True
            for m in range(natom):
                for i in range(nnear):
                    delx = _minimum_image(trial[m, 0] - xs[i, 0], prd[0], periodic[0])
                    dely = _minimum_image(trial[m, 1] - xs[i, 1], prd[1], periodic[1])
                    delz = _minimum_image(trial[m, 2] - xs[i, 2], prd[2], periodic[2])
                    radsum = atom_r[m] + rs[i]
                    if delx * delx + dely * dely + delz * delz <= radsum * radsum:
                        clear = False
                        break
                if not clear:
                    break
            if clear:
                success = True
                break
        if not success:
            break
        for m in range(natom):
            xs[nnear] = trial[m]
            rs[nnear] = atom_r[m]
            nnear += 1
            new_x[placed * natom + m] = trial[m]
            new_image[placed * natom + m] = image[m]
        centres[placed] = coord
        quats[placed] = quat
        new_v[placed, 0] = velocity[0] + park_uniform(state) * (velocity[1] - velocity[0])
        if dimension == 3:
            new_v[placed, 1] = velocity[2] + park_uniform(state) * (velocity[3] - velocity[2])
            new_v[placed, 2] = -math.sqrt(velocity[5] * velocity[5] + 2.0 * grav * (coord[2] - hi_current))
        else:
            new_v[placed, 1] = -math.sqrt(velocity[4] * velocity[4] + 2.0 * grav * (coord[1] - hi_current))
            new_v[placed, 2] = 0.0
        placed += 1
    return placed


@njit(cache=True)
def _rotation(q, rot):
    """LAMMPS's MathExtra::quat_to_mat: the rotation matrix of a unit quaternion (w, x, y, z)."""
    w2, i2, j2, k2 = q[0] * q[0], q[1] * q[1], q[2] * q[2], q[3] * q[3]
    twoij, twoik, twojk = 2.0 * q[1] * q[2], 2.0 * q[1] * q[3], 2.0 * q[2] * q[3]
    twoiw, twojw, twokw = 2.0 * q[1] * q[0], 2.0 * q[2] * q[0], 2.0 * q[3] * q[0]
    rot[0, 0] = w2 + i2 - j2 - k2
    rot[0, 1] = twoij - twokw
    rot[0, 2] = twojw + twoik
    rot[1, 0] = twoij + twokw
    rot[1, 1] = w2 - i2 + j2 - k2
    rot[1, 2] = twojk - twoiw
    rot[2, 0] = twoik - twojw
    rot[2, 1] = twojk + twoiw
    rot[2, 2] = w2 - i2 - j2 + k2


def gravity_of(sim):
    """The acceleration (3,) of the first gravity fix (its ``gvec``), or None."""
    return next((np.asarray(g, dtype=np.float64) for fix in sim.fixes.values()
                 if (g := fix.extract("gvec")) is not None), None)


class FixPour(Fix):
    name = "pour"
    usage = ("fix ID GROUP pour N TYPE SEED region ID [diam one D | range DLO DHI | poly N D1 P1 ...] "
             "[dens DLO DHI] [vol FRAC MAXATTEMPT] [rate V] [vel VXLO VXHI VYLO VYHI VZ | VXLO VXHI VY] "
             "[id max|next] [ignore] [mol TEMPLATE [rigid FIX_ID]]")
    refused = {"molfrac": ONE_TEMPLATE, "shake": "pdps has no fix shake"}

    class Args(StyleArgs):
        ninsert: WholeNumber = param(ge=1, unit="particles")
        type: WholeNumber = param(ge=0, unit="1")
        seed: WholeNumber = param(ge=1, unit="1")
        region: str = keyword(..., names="region ID")
        diam: (tuple[Literal["one"], float] | tuple[Literal["range"], float, float]
               | tuple[Literal["poly"], float, tuple[float, ...]] | None) = keyword(None, unit="distance")
        dens: tuple[float, float] = keyword((1.0, 1.0), unit="density")
        vol: tuple[float, WholeNumber] = keyword((0.25, 50), unit=("1", "1"))
        rate: float = keyword(0.0, unit="velocity")
        vel: tuple[float, ...] | None = keyword(None, unit="velocity")
        id: Literal["max", "next"] = keyword("max")
        ignore: tuple[()] | None = keyword(None)
        mol: str | None = keyword(None)
        rigid: str | None = keyword(None)

    @classmethod
    def check_args(cls, args):
        if args.rigid is not None and args.mol is None:
            raise ScriptError("rigid needs mol: fix pour makes rigid bodies of molecules only (LAMMPS: Cannot use fix "
                              "pour rigid and not molecule)")
        if args.dens[0] > args.dens[1]:
            raise ScriptError(f"dens: DLO must be <= DHI (got {args.dens[0]:g} {args.dens[1]:g})")
        if not args.vol[0] > 0:
            raise ScriptError(f"vol: the volume fraction must be > 0 (got {args.vol[0]:g})")
        if args.vol[1] < 1:
            raise ScriptError(f"vol: MAXATTEMPT must be >= 1 (got {args.vol[1]})")
        diam = args.diam
        if diam is None:
            return
        if diam[0] == "one" and not diam[1] > 0:
            raise ScriptError(f"diam one: the diameter must be > 0 (got {diam[1]:g})")
        if diam[0] == "range" and not 0 < diam[1] <= diam[2]:
            raise ScriptError(f"diam range: need 0 < DLO <= DHI (got {diam[1]:g} {diam[2]:g})")
        if diam[0] == "poly":
            count, values = diam[1], diam[2]
            if count != int(count) or count < 1:
                raise ScriptError(f"diam poly: NPOLY must be a whole number >= 1 (got {count:g})")
            if len(values) != 2 * int(count):
                raise ScriptError(f"diam poly {int(count)} needs {2 * int(count)} values, a diameter and a "
                                  f"fraction each (got {len(values)})")
            if any(d <= 0 for d in values[0::2]) or any(p < 0 for p in values[1::2]):
                raise ScriptError("diam poly: each diameter must be > 0 and each fraction >= 0 (got "
                                  f"{' '.join(f'{v:g}' for v in values)})")
            if abs(sum(values[1::2]) - 1.0) > POLY_SUM_TOLERANCE:
                raise ScriptError(f"diam poly: the fractions must sum to 1 (got {sum(values[1::2]):.12g})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        dimension = sim.dimension
        if "sphere" not in sim.particle_styles:
            raise ScriptError(f"fix pour needs radius and rmass (atom_style sphere or granular; got "
                              f"{sim.particle_style})")
        self.template = sim.molecule_template(args.mol) if args.mol is not None else None
        if self.template is None and not 1 <= args.type <= sim.ntypes:
            raise ScriptError(f"TYPE must be from 1 to {sim.ntypes} (got {args.type})")
        if self.template is not None and args.type + self.template.ntypes > sim.ntypes:
            raise ScriptError(f"TYPE {args.type} plus molecule {args.mol}'s types (up to {self.template.ntypes}) must be "
                              f"at most {sim.ntypes} (LAMMPS: Invalid atom type in fix pour mol command)")
        self.rigid_id = args.rigid
        self.ninsert, self.ntype = args.ninsert, args.type
        self.volfrac, self.maxattempt = args.vol
        self.rate = args.rate
        self.density_lo, self.density_hi = args.dens
        self._read_diameters(args.diam)
        self._read_velocity(args.vel, dimension)
        self._read_region(sim, args.region, dimension)
        self.state = park_state(args.seed)
        for _ in range(WARMUP):
            park_uniform(self.state)
        self.next_reneighbor = sim.step + 1
        self.nfirst = self.next_reneighbor
        self.ninserted = 0
        if self.template is not None:
            # the copies' radius, for the volume of one and for the present particles they may touch
            self.radius_max = self.template.molradius
        self.nper = int(self.volfrac * self._volume(dimension) / self._volume_one(dimension))
        if self.nper == 0:
            raise ScriptError("fix pour inserts 0 particles each time (vol FRAC times the region's volume is "
                              "less than one particle's)")
        self.region_id = args.region
        # LAMMPS 22 Jul 2025 finds the gravity and the schedule at the first run (recorded: a fix
        # gravity or a timestep given after the fix pour counts), and stops a later run whose
        # gravity or time step has changed
        self.grav = self.dt = self.nfreq = None

    def _schedule(self, sim):
        """nfreq from the fall through the region under the gravity now, and LAMMPS's line."""
        if sim.dimension == 3:
            v_relative, delta = self.velocity[5] - self.rate, self.zhi - self.zlo
        else:
            v_relative, delta = self.velocity[4] - self.rate, self.bounds[3] - self.bounds[2]
        t = (-v_relative - math.sqrt(v_relative * v_relative - 2.0 * self.grav * delta)) / self.grav
        self.nfreq = int(t / sim.dt + 0.5)
        if self.nfreq < 1:
            raise ScriptError(f"fix {self.id} (pour): a batch falls through region {self.region_id} in {t:g} time "
                              f"units, less than half a time step ({sim.dt:g}): nothing would clear the volume")
        self.dt = sim.dt
        nfinal = sim.step + 1 + (self.ninsert - 1) // self.nper * self.nfreq
        sim.info(f"Particle insertion: {self.nper} every {self.nfreq} steps, {self.ninsert} by step {nfinal}")

    def _read_diameters(self, diam):
        self.dstyle, self.radius_one, self.radius_lo, self.radius_hi = ONE, 0.5, 0.5, 0.5
        self.poly_radius, self.poly_fraction = np.zeros(1), np.ones(1)
        if diam is None or diam[0] == "one":
            self.radius_one = 0.5 if diam is None else 0.5 * diam[1]
            self.radius_max = self.radius_one
        elif diam[0] == "range":
            self.dstyle, self.radius_lo, self.radius_hi = RANGE, 0.5 * diam[1], 0.5 * diam[2]
            self.radius_max = self.radius_hi
        else:
            self.dstyle = POLY
            self.poly_radius = 0.5 * np.array(diam[2][0::2], dtype=np.float64)
            self.poly_fraction = np.array(diam[2][1::2], dtype=np.float64)
            self.radius_max = float(self.poly_radius.max())

    def _read_velocity(self, vel, dimension):
        # vxlo vxhi vylo vyhi vy vz
        self.velocity = np.zeros(6)
        if vel is None:
            return
        if dimension == 3:
            if len(vel) != 5:
                raise ScriptError(f"vel takes VXLO VXHI VYLO VYHI VZ in 3-d (got {len(vel)} values)")
            self.velocity[[0, 1, 2, 3, 5]] = vel
            if vel[0] > vel[1] or vel[2] > vel[3]:
                raise ScriptError(f"vel: need VXLO <= VXHI and VYLO <= VYHI (got {' '.join(f'{v:g}' for v in vel)})")
        else:
            if len(vel) != 3:
                raise ScriptError(f"vel takes VXLO VXHI VY in 2-d (got {len(vel)} values)")
            self.velocity[[0, 1, 4]] = vel
            if vel[0] > vel[1]:
                raise ScriptError(f"vel: need VXLO <= VXHI (got {vel[0]:g} {vel[1]:g})")

    def _read_region(self, sim, name, dimension):
        region = sim.region(name)
        if region.dynamic:
            raise ScriptError(f"region {name} moves (move or rotate): fix pour region cannot be dynamic (as LAMMPS)")
        box = sim.box
        # bounds: xlo xhi ylo yhi xc yc rc
        self.bounds = np.zeros(7)
        self.shape = SHAPES.get(region.name)
        if self.shape == BLOCK:
            lo, hi = region.lo, region.hi
            self.bounds[:4] = lo[0], hi[0], lo[1], hi[1]
            self.zlo, self.zhi = float(lo[2]), float(hi[2])
            outside = (lo < box.lo).any() or (hi > box.hi).any()
        elif self.shape == CYLINDER:
            if dimension == 2:
                raise ScriptError(f"region {name}: fix pour in 2-d needs a block region (as LAMMPS)")
            if region.axis != 2:
                raise ScriptError(f"region {name}: fix pour needs a z-axis cylinder (got {'xyz'[region.axis]})")
            (xc, yc), rc = region.c, region.radius
            self.bounds[4:] = xc, yc, rc
            self.zlo, self.zhi = float(region.lo), float(region.hi)
            outside = (xc - rc < box.lo[0] or xc + rc > box.hi[0] or yc - rc < box.lo[1] or yc + rc > box.hi[1]
                       or self.zlo < box.lo[2] or self.zhi > box.hi[2])
        else:
            raise ScriptError(f"region {name} is a {region.name}: fix pour needs a block or cylinder region")
        if outside:
            raise ScriptError(f"region {name} extends outside the simulation box (fix pour inserts inside it)")
        if region.side_out:
            raise ScriptError(f"region {name} has side out: fix pour inserts into a region's inside")

    def _volume(self, dimension):
        xlo, xhi, ylo, yhi, _, _, rc = self.bounds
        if dimension == 2:
            return (xhi - xlo) * (yhi - ylo)
        if self.shape == BLOCK:
            return (xhi - xlo) * max(yhi - ylo, 1.0) * (self.zhi - self.zlo)
        return math.pi * rc * rc * (self.zhi - self.zlo)

    def _volume_one(self, dimension):
        power, factor = (3, 4.0 / 3.0 * math.pi) if dimension == 3 else (2, math.pi)
        if self.dstyle == POLY and self.template is None:
            return float(sum(factor * r ** power * p for r, p in zip(self.poly_radius, self.poly_fraction)))
        return factor * self.radius_max ** power

    # ---- schedule ----
    def setup(self, sim):
        g = gravity_of(sim)
        if g is None:
            raise ScriptError(f"fix {self.id} (pour) needs a fix gravity (LAMMPS: No fix gravity defined for fix pour)")
        magnitude = float(np.linalg.norm(g))
        down = np.zeros(3)
        down[sim.dimension - 1] = -1.0
        if magnitude == 0.0 or (np.abs(g / magnitude - down) > GRAVITY_DIRECTION_TOLERANCE).any():
            axis = "-z in 3-d" if sim.dimension == 3 else "-y in 2-d"
            raise ScriptError(f"fix {self.id} (pour): gravity must point along {axis} (got "
                              f"{' '.join(f'{c:g}' for c in g)})")
        if self.grav is None:
            self.grav = -magnitude * sim.units.ftm2v
            self._schedule(sim)
        if -magnitude * sim.units.ftm2v != self.grav:
            raise ScriptError(f"fix {self.id} (pour): gravity changed since its first run")
        if sim.dt != self.dt:
            raise ScriptError(f"fix {self.id} (pour): the time step changed since its first run ({self.dt:g}, now "
                              f"{sim.dt:g}; LAMMPS: Cannot change timestep with fix pour)")
        self.bodies = self._rigid_fix(sim) if self.rigid_id is not None else None
        # LAMMPS's setup_pre_exchange: every run starts with a batch on its first step
        self.next_reneighbor = sim.step + 1 if self.ninserted < self.ninsert else None

    def _rigid_fix(self, sim):
        fix = sim.fixes.get(self.rigid_id)
        if fix is None:
            raise ScriptError(f"fix {self.id} (pour): rigid fix {self.rigid_id} does not exist")
        if not isinstance(fix, MoleculeBodies):
            raise ScriptError(f"fix {self.id} (pour): fix {self.rigid_id} ({fix.name}) makes no rigid bodies of "
                              "molecule templates (fix rigid/small ... mol TEMPLATE does)")
        if fix.body_template is not self.template:
            theirs = getattr(fix.body_template, "id", None)
            raise ScriptError(f"fix {self.id} (pour) and fix {self.rigid_id} use different molecule templates "
                              f"({self.template.id} and {theirs or 'none'})")
        return fix

    def reset_dt(self, sim):
        raise ScriptError(f"fix {self.id} (pour) cannot follow a change of time step (as LAMMPS)")

    def inserted_radius(self, type_):
        if self.template is not None:
            atom_r = self.template.radius if self.template.radius is not None else np.full(self.template.natoms, 0.5)
            chosen = self.ntype + self.template.types == type_
            return float(atom_r[chosen].max()) if chosen.any() else 0.0
        return self.radius_max if type_ == self.ntype else 0.0

    # ---- one batch ----
    def pre_exchange(self, sim):
        if self.next_reneighbor != sim.step:
            return
        nnew = min(self.nper, self.ninsert - self.ninserted)
        shift = (sim.step - self.nfirst) * sim.dt * self.rate
        if sim.dimension == 3:
            lo_current, hi_current = self.zlo + shift, self.zhi + shift
        else:
            lo_current, hi_current = self.bounds[2] + shift, self.bounds[3] + shift
        box = sim.box
        boxlo = np.asarray(box.lo, dtype=np.float64)
        prd = np.asarray(box.length, dtype=np.float64)
        periodic = np.array(box.periodic, dtype=np.bool_)
        p = sim.particles
        n = p.nlocal
        if self.template is not None:
            self._pour_molecules(sim, nnew, lo_current, hi_current, boxlo, prd, periodic)
            return
        rows = near_volume(p.x, p.radius, n, self.shape, sim.dimension, self.bounds, lo_current, hi_current,
                           self.radius_max, boxlo, prd, periodic)
        near = sim.comm.allgather_rows(np.column_stack([p.x[rows], p.radius[rows]]))
        new_x, new_v = np.zeros((nnew, 3)), np.zeros((nnew, 3))
        new_r, new_density = np.zeros(nnew), np.zeros(nnew)
        placed = pour_batch(self.state, nnew, self.maxattempt, lo_current, hi_current, self.shape, sim.dimension,
                            self.bounds, self.dstyle, self.radius_one, self.radius_lo, self.radius_hi,
                            self.poly_radius, self.poly_fraction, self.density_lo, self.density_hi, self.velocity,
                            self.grav, np.ascontiguousarray(near[:, :3]), np.ascontiguousarray(near[:, 3]),
                            prd, periodic, new_x, new_r, new_v, new_density)
        self.ninserted += placed
        if placed < nnew:
            sim.warn(f"fix {self.id} (pour): inserted {placed} of {nnew} particles at step {sim.step} (LAMMPS: Fewer "
                     "insertions than requested)")
        r = new_r[:placed]
        mass = 4.0 * math.pi / 3.0 * r * r * r * new_density[:placed]
        bits = np.uint32(1) | sim.groups.bit(self.group)
        if sim.comm.rank == 0:
            sim.add_particles(new_x[:placed], self.ntype, v=new_v[:placed], radius=r, rmass=mass,
                              mask=np.full(placed, bits, dtype=np.uint32))
        else:
            sim.add_particles(np.zeros((0, 3)), self.ntype)
        self.next_reneighbor = sim.step + self.nfreq if self.ninserted < self.ninsert else None

    def _pour_molecules(self, sim, nnew, lo_current, hi_current, boxlo, prd, periodic):
        """A batch of copies of the template (LAMMPS's mode MOLECULE): each atom takes the type TYPE
        plus its template type, the template's radius (0.5 without Diameters) and mass (4/3 pi r^3
        without Masses), the copy's velocity; each copy a new molecule id; a rigid fix makes bodies."""
        p = sim.particles
        n = p.nlocal
        template = self.template
        natom = template.natoms
        atom_r = template.radius if template.radius is not None else np.full(natom, 0.5)
        rows = near_volume(p.x, p.radius, n, self.shape, sim.dimension, self.bounds, lo_current, hi_current,
                           self.radius_max, boxlo, prd, periodic)
        near = sim.comm.allgather_rows(np.column_stack([p.x[rows], p.radius[rows]]))
        new_x, new_image = np.zeros((nnew * natom, 3)), np.zeros((nnew * natom, 3), dtype=np.int32)
        centres, quats, new_v = np.zeros((nnew, 3)), np.zeros((nnew, 4)), np.zeros((nnew, 3))
        placed = pour_molecule_batch(self.state, nnew, self.maxattempt, lo_current, hi_current, self.shape,
                                     sim.dimension, self.bounds, self.velocity, self.grav,
                                     np.ascontiguousarray(template.dx), np.ascontiguousarray(atom_r, dtype=np.float64),
                                     np.ascontiguousarray(near[:, :3]), np.ascontiguousarray(near[:, 3]), boxlo, prd,
                                     periodic, new_x, new_image, centres, quats, new_v)
        self.ninserted += placed
        if placed < nnew:
            sim.warn(f"fix {self.id} (pour): inserted {placed} of {nnew} molecules at step {sim.step} (LAMMPS: Fewer "
                     "insertions than requested)")
        count = placed * natom
        molecule = None
        if p.has("molecule"):
            largest = int(sim.comm.max(int(p.molecule[:n].max()) if n else 0))
            molecule = np.repeat(np.arange(largest + 1, largest + 1 + placed, dtype=np.int64), natom)
        radius = np.tile(atom_r, placed)
        mass = (np.tile(template.rmass, placed) if template.rmass is not None
                else 4.0 * math.pi / 3.0 * radius * radius * radius)
        extra = {} if molecule is None else {"molecule": molecule}
        bits = np.uint32(1) | sim.groups.bit(self.group)
        if sim.comm.rank == 0:
            added = sim.add_particles(new_x[:count], self.ntype + np.tile(template.types, placed),
                                      v=np.repeat(new_v[:placed], natom, axis=0), radius=radius, rmass=mass,
                                      image=new_image[:count], mask=np.full(count, bits, dtype=np.uint32), **extra)
        else:
            added = sim.add_particles(np.zeros((0, 3)), self.ntype)
            placed = 0
        if self.bodies is not None:
            self.bodies.add_molecule_bodies(sim, np.asarray(added).reshape(placed, natom), centres[:placed],
                                            new_v[:placed], quats[:placed])
        self.next_reneighbor = sim.step + self.nfreq if self.ninserted < self.ninsert else None
