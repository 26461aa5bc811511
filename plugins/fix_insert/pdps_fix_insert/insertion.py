r"""What the insertion fixes share (LIGGGHTS's fix insert): the general keywords, the schedule, the
draw of particles from a distribution, their placement, velocities, and their entry into the run.

General keywords (LIGGGHTS's names, after ``seed S distributiontemplate DIST``)::

    verbose yes|no                    a line per insertion (default no)
    maxattempt N                      candidate positions each particle may try (default 50); an
                                      insertion's tries are shared, and insert/pack divides them by
                                      the share of its target still missing (LIGGGHTS's calc_maxtry)
    insert_every once|N               insert once, or every N steps (default: once for insert/pack)
    start STEP                        the first insertion step (default: the next step)
    overlapcheck yes|no               keep new particles clear of present and new ones (default yes)
    all_in yes|no                     whole particle inside the insertion volume, or its centre (default no)
    random_distribute exact|uncorrelated   read; pdps always inserts the exact count
    compress_tags no                  LIGGGHTS's default; yes (ids numbered again) is refused
    vel constant VX VY VZ | uniform VX VY VZ DVX DVY DVZ | gaussian VX VY VZ SX SY SZ
    omega constant WX WY WZ
    orientation random|template|constant Q0 Q1 Q2 Q3
                                      a clump's (particletemplate/multisphere): its template's
                                      (default, as LIGGGHTS), uniform random, or rotated by the unit
                                      quaternion Q; a sphere has none
    set_property NAME VALUE           a per-atom value of the new particles (an existing per-atom array)

``vel uniform``: each component :math:`v = \bar v + \Delta v\,(2u - 1)`, u uniform on [0, 1)
(LIGGGHTS's amplitude); ``vel gaussian``: :math:`v = \bar v + s\,\xi`, :math:`\xi` standard normal.

The same particles on any number of ranks: every rank draws the step's particles, candidate
positions and velocities from one random stream keyed by (seed, step), places them against all
present particles (gathered) and each other, and rank 0 adds them; ids follow the order of the
draw, and the step's rebuild carries each particle to the rank that owns its position. (LIGGGHTS
seeds each rank differently, so its particles depend on the rank count.) Output: ``f_ID[1]``
(``f_ID[0]`` in the PDPS dialect) the particles inserted so far, ``f_ID[2]`` their mass.
"""

import math
from typing import Literal, NamedTuple

import numpy as np
from pdps_core.api import Fix, ScriptError, StyleArgs, keyword

from .particledistribution_discrete import FixParticleDistributionDiscrete
from .placement import grid, place
from .whole_number import WholeNumber

POOL_LIMIT = 4_000_000       # candidate positions drawn per insertion at most
MAX_AT_ONCE = 10_000_000     # particles one insertion may add
ALL_IN_DRAWS = 20            # pools drawn to find the candidates with room (all_in yes), at most


YesNo = Literal["yes", "no"]
Velocity = (tuple[Literal["constant"], float, float, float]
            | tuple[Literal["uniform", "gaussian"], float, float, float, float, float, float])


class Property(NamedTuple):
    name: str
    value: float


class InsertArgs(StyleArgs):
    """LIGGGHTS's general keywords of the insertion fixes, in any order; a keyword given twice: the
    later holds."""
    seed: WholeNumber = keyword(..., ge=1, unit="1")
    distributiontemplate: str = keyword(..., names="fix particledistribution/discrete ID")
    verbose: YesNo = keyword("no")
    maxattempt: WholeNumber = keyword(50, ge=1, unit="1")
    insert_every: Literal["once"] | WholeNumber | None = keyword(None, unit="timesteps")
    start: WholeNumber | None = keyword(None, ge=0, unit="timesteps")
    overlapcheck: YesNo = keyword("yes")
    all_in: YesNo = keyword("no")
    random_distribute: Literal["exact", "uncorrelated"] | None = keyword(None)
    orientation: (Literal["random", "template"] | tuple[Literal["constant"], float, float, float, float]
                  | None) = keyword(None, unit="1")
    set_property: Property | None = keyword(None, unit=("1", "as the property"))
    vel: Velocity | None = keyword(None, unit="velocity")
    omega: tuple[Literal["constant"], float, float, float] | None = keyword(None, unit="1/time")
    compress_tags: YesNo = keyword("no")


def positive(args, name):
    """A number keyword that may be INF (nparticles, mass): refused at or below 0."""
    value = getattr(args, name)
    if value is not None and value != "INF" and not value > 0:
        raise ScriptError(f"{name} must be > 0 (got {value:g})")


class FixInsert(Fix):
    """The machinery; a style adds its own keywords to ``InsertArgs``, and sets ``read_style(sim, args)``,
    ``wanted(sim)`` (how many particles this step), ``draw_points(rng, n)`` (candidate centres,
    uniform over its volume) and ``clearance(points, reach)`` (distance to its surface, for all_in)."""
    once_by_default = True
    Args = InsertArgs

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        if args.compress_tags == "yes":
            raise ScriptError("compress_tags yes (LIGGGHTS numbers every particle 1..N again after each "
                              "insertion) is not supported: pdps keeps each particle's id, which contact "
                              "histories and dumps follow")
        if isinstance(args.insert_every, int) and args.insert_every < 1:
            raise ScriptError(f"insert_every must be >= 1 (got {args.insert_every})")
        if args.vel is not None and any(v < 0 for v in args.vel[4:]):
            spread = " ".join(f"{v:g}" for v in args.vel[4:])
            raise ScriptError(f"vel {args.vel[0]}: the spread must be >= 0 (got {spread})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if sim.dimension != 3:
            raise ScriptError(f"fix {self.name} inserts spheres in 3-d only (as LIGGGHTS)")
        self.seed = args.seed
        name = args.distributiontemplate
        self.distribution = sim.fixes.get(name)
        if not isinstance(self.distribution, FixParticleDistributionDiscrete):
            known = [k for k, f in sim.fixes.items() if isinstance(f, FixParticleDistributionDiscrete)]
            raise ScriptError(f"distributiontemplate {name} is not a fix particledistribution/discrete "
                              f"(defined: {', '.join(known) or 'none'})")
        self.verbose = args.verbose == "yes"
        self.max_attempt = args.maxattempt
        every = args.insert_every or ("once" if self.once_by_default else 1)
        self.every = None if every == "once" else every
        self.start = args.start
        self.overlap_check = args.overlapcheck == "yes"
        self.all_in = args.all_in == "yes"
        # a try fails where the centre lies less than border x its radius inside the box (LIGGGHTS's
        # check_dist_from_subdomain_border; -inf: no check)
        self.border = -np.inf
        self.velocity_style, self.velocity_mean, self.velocity_spread = "constant", np.zeros(3), np.zeros(3)
        if args.vel is not None:
            self.velocity_style = args.vel[0]
            self.velocity_mean = np.array(args.vel[1:4])
            if len(args.vel) > 4:
                self.velocity_spread = np.array(args.vel[4:])
        self.omega = np.zeros(3) if args.omega is None else np.array(args.omega[1:])
        self.set_property = None if args.set_property is None else tuple(args.set_property)
        self.orientation = "template" if args.orientation is None else args.orientation
        self.orientation_quat = np.array([1.0, 0.0, 0.0, 0.0])
        if isinstance(self.orientation, tuple):
            self.orientation_quat = np.array(self.orientation[1:])
            if abs(np.dot(self.orientation_quat, self.orientation_quat) - 1.0) > 1e-10:
                raise ScriptError(f"orientation constant: the quaternion must have unit length (got "
                                  f"{' '.join(f'{c:g}' for c in self.orientation_quat)})")
        # clumps of a particletemplate/multisphere: inserted whole, bodies of the fix multisphere
        kinds = {hasattr(t, "displace") for t in self.distribution.templates}
        if len(kinds) > 1:
            raise ScriptError(f"distributiontemplate {name} mixes particletemplate/sphere and /multisphere "
                              "templates: insert each kind with a fix of its own")
        self.clumps = kinds == {True}
        self.multisphere = None
        self.read_style(sim, args)
        self.inserted = 0
        self.inserted_mass = 0.0
        self.events = 0
        self.next_reneighbor = None
        self.finished = False
        self.first_step = None          # the schedule's first insertion step, set at the first setup
        self.wanted_so_far = 0          # particles a rate's line has asked for so far (rate styles)
        self.filled = 0.0               # the share of its target the region holds (insert/pack)

    # ---- what a style defines ----
    def read_style(self, sim, args):
        raise NotImplementedError

    def wanted(self, sim):
        raise NotImplementedError

    def tries(self, count):
        """Candidate positions an insertion of ``count`` may use: maxattempt each, divided by the
        share of the target still missing (LIGGGHTS's calc_maxtry: a nearly full region, where
        few candidates are free, does not give up early)."""
        budget = count * self.max_attempt
        return int(budget / (1.0 - self.filled)) if self.filled < 1.0 else budget

    def draw_points(self, rng, n):
        raise NotImplementedError

    def draw_candidates(self, rng, n):
        """Candidate centres and, per candidate, the shift a sphere's radius moves it by (the centre
        is ``point + r shift``): ``draw_points`` unshifted, unless a style places by radius."""
        points = self.draw_points(rng, n)
        return points, np.zeros_like(points)

    def clearance(self, points, reach):
        raise NotImplementedError

    def extent(self, sim):
        """(lo, hi) of the insertion volume."""
        raise NotImplementedError

    # ---- schedule ----
    def setup(self, sim):
        if sim.fixes.get(self.distribution.id) is not self.distribution:
            raise ScriptError(f"fix {self.id}: its distributiontemplate {self.distribution.id} has been unfixed")
        if "sphere" not in sim.particle_styles:
            raise ScriptError(f"fix {self.name} needs spheres (atom_style granular or sphere; got "
                              f"{sim.particle_style})")
        if self.clumps:
            bodies = [f for f in sim.fixes.values() if hasattr(f, "add_bodies")]
            if len(bodies) != 1:
                raise ScriptError(f"fix {self.id} inserts multisphere clumps: they need exactly one fix "
                                  f"multisphere (found {len(bodies)}), as LIGGGHTS")
            self.multisphere = bodies[0]
        if self.set_property is not None and not sim.particles.has(self.set_property[0]):
            raise ScriptError(f"set_property: no per-atom property {self.set_property[0]}")
        if self.finished:
            self.next_reneighbor = None
            return
        first = self.start if self.start is not None else sim.step + 1
        if self.first_step is None:
            self.first_step = max(first, sim.step + 1)
        step = self.first_step
        if self.every is not None and step <= sim.step:
            step += -((step - sim.step - 1) // self.every) * self.every
        self.next_reneighbor = step if step > sim.step else None

    def pre_exchange(self, sim):
        if self.next_reneighbor != sim.step:
            return
        count = max(int(self.wanted(sim)), 0)
        if count > MAX_AT_ONCE:
            raise ScriptError(f"fix {self.id} ({self.name}) would insert {count:.3g} particles at step {sim.step}, "
                              f"more than {MAX_AT_ONCE:,} at once: check its target or rate")
        self.events += 1
        self._insert(sim, count)
        if self.every is None or self.finished:
            self.finished = True
            self.next_reneighbor = None
        else:
            self.next_reneighbor = sim.step + self.every

    # ---- restart files and the clock ----
    def state(self):
        """What a restart file keeps (LIGGGHTS's fix insert keeps the count, mass and schedule):
        given again with its ID after read_restart, the fix goes on inserting where it stopped."""
        return {"inserted": self.inserted, "inserted_mass": self.inserted_mass, "events": self.events,
                "first_step": self.first_step, "finished": self.finished, "wanted_so_far": self.wanted_so_far}

    def restore(self, state):
        self.inserted = int(state["inserted"])
        self.inserted_mass = float(state["inserted_mass"])
        self.events = int(state["events"])
        self.first_step = None if state["first_step"] is None else int(state["first_step"])
        self.finished = bool(state["finished"])
        self.wanted_so_far = int(state["wanted_so_far"])

    def reset_timestep(self, sim, new, old):
        """The schedule moves with the clock, as LIGGGHTS's next insertion step does."""
        if self.first_step is not None:
            self.first_step += new - old

    def vector(self, sim):
        return np.array([float(self.inserted), self.inserted_mass])

    def inserted_radius(self, type_):
        if self.finished:
            return 0.0
        return max([t.max_radius for t in self.distribution.templates if t.atom_type == type_], default=0.0)

    # ---- one insertion ----
    def _insert(self, sim, count):
        rng = np.random.default_rng([self.seed, sim.step])
        radius, density, types, which = self.distribution.draw(rng, count)
        placed = np.zeros((count, 3))
        done = np.zeros(count, dtype=np.bool_)
        if count:
            old_x, old_r = self._present(sim)
            big = float(radius.max())
            cell = big + max(big, float(old_r.max()) if len(old_r) else 0.0)
            lo, hi = self.extent(sim)
            pool, shift, clearance = self._pool(rng, count, float(radius.min()), big)
            lo_grid, width, nbins, periodic, length = grid(sim.box, lo, hi, cell)
            self.taken = np.zeros(count, dtype=np.int64)
            box_lo, box_hi = np.array(sim.box.lo, dtype=np.float64), np.array(sim.box.hi, dtype=np.float64)
            place(pool, shift, clearance, radius, old_x, old_r, lo_grid, width, nbins, periodic, length,
                  self.tries(count), self.overlap_check, box_lo, box_hi, self.border, placed, done, self.taken)
        n = int(done.sum())
        self.placed_rows = self.taken[done] if count else np.zeros(0, dtype=np.int64)
        radius, density, types, which, placed = radius[done], density[done], types[done], which[done], placed[done]
        velocity = self._velocities(rng, n)
        if self.clumps:
            self._insert_clumps(sim, rng, placed, velocity, which)
            return
        mass = density * (4.0 / 3.0 * math.pi) * radius ** 3
        # groups: all, this fix's, the distribution's and each particle's template's (LIGGGHTS)
        bits = np.uint32(1) | sim.groups.bit(self.group) | sim.groups.bit(self.distribution.group)
        template_bits = np.array([sim.groups.bit(t.group) for t in self.distribution.templates], dtype=np.uint32)
        per_atom = {"radius": radius, "rmass": mass, "omega": np.tile(self.omega, (n, 1)),
                    "mask": bits | template_bits[which]}
        if self.set_property is not None:
            per_atom[self.set_property[0]] = self.set_property[1]
        if sim.comm.rank == 0:
            sim.add_particles(placed, types, v=velocity, **per_atom)
        else:
            sim.add_particles(np.zeros((0, 3)), 1)
        self.inserted += n
        self.inserted_mass += float(mass.sum())
        if n < count:
            sim.warn(f"fix {self.id} ({self.name}): inserted {n} of {count} particles at step {sim.step}: the "
                     f"others found no room in {self.tries(count)} tries (maxattempt {self.max_attempt})")
        if self.verbose:
            sim.info(f"fix {self.id} ({self.name}): inserted {n} particles (mass {mass.sum():.6g}) at step "
                     f"{sim.step}; {self.inserted} (mass {self.inserted_mass:.6g}) so far")

    def _insert_clumps(self, sim, rng, placed, velocity, which):
        """Insert the placed clumps of a particletemplate/multisphere (their centres of mass at the
        points placed, as LIGGGHTS's particleToInsert_multisphere puts them): each clump's spheres,
        and its body given to the fix multisphere."""
        n = len(placed)
        templates = [self.distribution.templates[k] for k in which]
        rotation = self._orientations(rng, n)
        axes = np.einsum("bij,bkj->bki", rotation, np.array([t.axes for t in templates]).reshape(n, 3, 3))
        xcm = placed
        omega = np.tile(self.omega, (n, 1))
        nrigid = np.array([t.nspheres for t in templates], dtype=np.int64)
        displace = np.concatenate([t.displace for t in templates]) if n else np.zeros((0, 3))
        body = np.repeat(np.arange(n), nrigid)
        arm = np.einsum("sk,skd->sd", displace, axes[body]) if n else np.zeros((0, 3))
        x = xcm[body] + arm
        v = velocity[body] + np.cross(omega[body], arm)
        mass = np.array([t.mass_expected for t in templates])
        per_atom = self.multisphere.add_bodies(
            sim, xcm, velocity, omega, axes[:, 0], axes[:, 1], axes[:, 2], np.array([t.inertia for t in templates]).reshape(n, 3),
            mass, np.array([t.body_density for t in templates]), nrigid,
            np.array([t.fflag for t in templates]).reshape(n, 3), np.array([t.tflag for t in templates]).reshape(n, 3),
            np.array([t.clumptype for t in templates], dtype=np.int64), displace,
            atomtype=np.array([t.atom_type for t in templates], dtype=np.int64))
        bits = np.uint32(1) | sim.groups.bit(self.group) | sim.groups.bit(self.distribution.group)
        per_atom.update(radius=np.concatenate([t.radii for t in templates]) if n else np.zeros(0),
                        rmass=mass[body], omega=omega[body],
                        mask=bits | np.array([sim.groups.bit(t.group) for t in templates], dtype=np.uint32)[body])
        types = np.array([t.atom_type for t in templates], dtype=np.int32)[body]
        if self.set_property is not None:
            per_atom[self.set_property[0]] = self.set_property[1]
        if sim.comm.rank == 0:
            sim.add_particles(x, types, v=v, **per_atom)
        else:
            sim.add_particles(np.zeros((0, 3)), 1)
        self.inserted += n
        self.inserted_mass += float(mass.sum())

    def _orientations(self, rng, n):
        """Rotation matrices (n, 3, 3) of n clumps: the template's own (``orientation template``, the
        default, as LIGGGHTS's), one quaternion's (``constant``), or uniform random ones."""
        if self.orientation == "random":
            u1, u2, u3 = rng.random((3, n))
            q = np.stack([np.sqrt(1 - u1) * np.sin(2 * np.pi * u2), np.sqrt(1 - u1) * np.cos(2 * np.pi * u2),
                          np.sqrt(u1) * np.sin(2 * np.pi * u3), np.sqrt(u1) * np.cos(2 * np.pi * u3)], 1)
        else:
            q = np.tile(self.orientation_quat, (n, 1))
        w, a, b, c = q.T
        return np.stack([np.stack([w * w + a * a - b * b - c * c, 2 * (a * b - w * c), 2 * (a * c + w * b)], -1),
                         np.stack([2 * (a * b + w * c), w * w - a * a + b * b - c * c, 2 * (b * c - w * a)], -1),
                         np.stack([2 * (a * c - w * b), 2 * (b * c + w * a), w * w - a * a - b * b + c * c], -1)], 1)

    def _present(self, sim):
        """Centres and radii of every present particle, on every rank."""
        p = sim.particles
        n = p.nlocal
        rows = sim.comm.allgather_rows(np.column_stack([p.x[:n], p.radius[:n]]))
        return np.ascontiguousarray(rows[:, :3]), np.ascontiguousarray(rows[:, 3])

    def _pool(self, rng, count, smallest, big):
        """Candidate centres and their room to the insertion volume's surface (all_in), as many as
        the insertion may try, at most POOL_LIMIT. A point with no room for the smallest sphere is
        no try, as in LIGGGHTS, whose draw repeats until the point lies the sphere's radius inside:
        the pool is drawn until it holds enough points with room, or ALL_IN_DRAWS times its size."""
        size = min(self.tries(count), POOL_LIMIT)
        if not self.all_in:
            points, shift = self.draw_candidates(rng, size)
            return np.ascontiguousarray(points), np.ascontiguousarray(shift), np.full(size, np.inf)
        points, rooms, kept = [], [], 0
        for _ in range(ALL_IN_DRAWS):
            batch = self.draw_points(rng, size)
            room = self.clearance(batch, big)
            fits = room >= smallest
            points.append(batch[fits])
            rooms.append(room[fits])
            kept += int(fits.sum())
            if kept >= size:
                break
        points = np.ascontiguousarray(np.concatenate(points)[:size])
        return points, np.zeros_like(points), np.concatenate(rooms)[:size]

    def _velocities(self, rng, n):
        mean, spread = self.velocity_mean, self.velocity_spread
        if self.velocity_style == "uniform":
            return mean + spread * (2.0 * rng.random((n, 3)) - 1.0)
        if self.velocity_style == "gaussian":
            return mean + spread * rng.standard_normal((n, 3))
        return np.tile(mean, (n, 1))
