r"""What the insertion fixes share (LIGGGHTS's fix insert): the general keywords, the schedule, the
draw of particles from a distribution, their placement, velocities, and their entry into the run.

General keywords (LIGGGHTS's names, after ``seed S distributiontemplate DIST``)::

    verbose yes|no                    a line per insertion (default no)
    maxattempt N                      candidate positions each particle may try (default 50)
    insert_every once|N               insert once, or every N steps (default: once for insert/pack)
    start STEP                        the first insertion step (default: the next step)
    overlapcheck yes|no               keep new particles clear of present and new ones (default yes)
    all_in yes|no                     whole particle inside the insertion volume, or its centre (default no)
    random_distribute exact|uncorrelated   read; pdps always inserts the exact count
    vel constant VX VY VZ | uniform VX VY VZ DVX DVY DVZ | gaussian VX VY VZ SX SY SZ
    omega constant WX WY WZ
    orientation random|template       read; a sphere has no orientation
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

import numpy as np

from pdps_core.api import Fix, ScriptError, StyleArgs, number, yes_no

from .placement import grid, place

GENERAL = {"seed": 1, "distributiontemplate": 1, "verbose": 1, "maxattempt": 1, "insert_every": 1,
           "start": 1, "overlapcheck": 1, "all_in": 1, "random_distribute": 1, "orientation": 1,
           "set_property": 2,
           "vel": lambda rest: _velocity_words(rest),
           "omega": lambda rest: 4}
VELOCITY_STYLES = {"constant": 3, "uniform": 6, "gaussian": 6}


def _velocity_words(rest):
    style = rest[0] if rest else ""
    if style not in VELOCITY_STYLES:
        raise ScriptError(f"vel must be constant, uniform or gaussian (got {style or 'nothing'})")
    return 1 + VELOCITY_STYLES[style]
POOL_LIMIT = 4_000_000       # candidate positions drawn per insertion at most
MAX_AT_ONCE = 10_000_000     # particles one insertion may add


# ---- words ---------------------------------------------------------------------------------------
def whole_number(word, what, low=None):
    """An integer; also written as a float with no fraction ("1.", as LIGGGHTS's tutorials write seeds,
    which its atoi reads)."""
    try:
        value = int(word)
    except ValueError:
        try:
            number_value = float(word)
        except ValueError:
            number_value = math.nan
        if not (math.isfinite(number_value) and number_value == int(number_value)):
            raise ScriptError(f"{what} must be a whole number (got {word})") from None
        value = int(number_value)
    if low is not None and value < low:
        raise ScriptError(f"{what} must be >= {low} (got {word})")
    return value


def read_keywords(words, arity):
    """{keyword: its words} from LIGGGHTS's keyword/value lists; ``arity[keyword]`` is how many words
    follow it, or a function of those words saying so (``vel constant ...`` / ``vel uniform ...``).
    A keyword given twice: the later holds."""
    given, i = {}, 0
    while i < len(words):
        word = words[i]
        if word not in arity:
            raise ScriptError(f"unknown keyword {word} (known: {', '.join(arity)})")
        count = arity[word]
        if callable(count):
            count = count(words[i + 1:])
        values = words[i + 1:i + 1 + count]
        if len(values) < count:
            raise ScriptError(f"keyword {word} needs {count} value(s) (got {len(values)})")
        given[word] = values
        i += 1 + count
    return given


class FixInsert(Fix):
    """The machinery; a style sets ``STYLE_ARITY`` (its own keywords), ``read_style(sim, given)``,
    ``wanted(sim)`` (how many particles this step), ``draw_points(rng, n)`` (candidate centres,
    uniform over its volume) and ``clearance(points, reach)`` (distance to its surface, for all_in)."""
    STYLE_ARITY = {}
    once_by_default = True

    class Args(StyleArgs):
        words: list[str] = []

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if sim.dimension != 3:
            raise ScriptError(f"fix {self.name} inserts spheres in 3-d only (as LIGGGHTS)")
        given = read_keywords(list(args.words), {**GENERAL, **self.STYLE_ARITY})
        for needed in ("seed", "distributiontemplate"):
            if needed not in given:
                raise ScriptError(f"missing keyword {needed}; usage: {self.usage}")
        self.seed = whole_number(given["seed"][0], "seed", low=1)
        name = given["distributiontemplate"][0]
        self.distribution = sim.fixes.get(name)
        if getattr(self.distribution, "name", None) != "particledistribution/discrete":
            known = [k for k, f in sim.fixes.items() if f.name == "particledistribution/discrete"]
            raise ScriptError(f"distributiontemplate {name} is not a fix particledistribution/discrete "
                              f"(defined: {', '.join(known) or 'none'})")
        self.verbose = yes_no(given["verbose"][0], "verbose") if "verbose" in given else False
        self.max_attempt = whole_number(given["maxattempt"][0], "maxattempt", low=1) if "maxattempt" in given else 50
        every = given.get("insert_every", ["once" if self.once_by_default else "1"])[0]
        self.every = None if every == "once" else whole_number(every, "insert_every", low=1)
        self.start = whole_number(given["start"][0], "start", low=0) if "start" in given else None
        self.overlap_check = yes_no(given["overlapcheck"][0], "overlapcheck") if "overlapcheck" in given else True
        self.all_in = yes_no(given["all_in"][0], "all_in") if "all_in" in given else False
        if "random_distribute" in given and given["random_distribute"][0] not in ("exact", "uncorrelated"):
            raise ScriptError(f"random_distribute must be exact or uncorrelated (got {given['random_distribute'][0]})")
        if "orientation" in given and given["orientation"][0] not in ("random", "template"):
            raise ScriptError(f"orientation must be random or template (got {given['orientation'][0]})")
        self.velocity_style, self.velocity_mean, self.velocity_spread = "constant", np.zeros(3), np.zeros(3)
        if "vel" in given:
            words = given["vel"]
            if words[0] not in ("constant", "uniform", "gaussian"):
                raise ScriptError(f"vel must be constant, uniform or gaussian (got {words[0]})")
            values = [number(w, f"vel {words[0]}") for w in words[1:]]
            self.velocity_style = words[0]
            self.velocity_mean = np.array(values[:3])
            if len(values) > 3:
                self.velocity_spread = np.array(values[3:])
                if (self.velocity_spread < 0).any():
                    raise ScriptError(f"vel {words[0]}: the spread must be >= 0 (got {' '.join(words[4:])})")
        self.omega = np.zeros(3)
        if "omega" in given:
            words = given["omega"]
            if words[0] != "constant":
                raise ScriptError(f"omega takes constant WX WY WZ (got {words[0]})")
            self.omega = np.array([number(w, "omega") for w in words[1:]])
        self.set_property = None
        if "set_property" in given:
            prop, value = given["set_property"]
            self.set_property = (prop, number(value, f"set_property {prop}"))
        self.read_style(sim, given)
        self.inserted = 0
        self.inserted_mass = 0.0
        self.events = 0
        self.next_reneighbor = None
        self.finished = False

    # ---- what a style defines ----
    def read_style(self, sim, given):
        raise NotImplementedError

    def wanted(self, sim):
        raise NotImplementedError

    def draw_points(self, rng, n):
        raise NotImplementedError

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
        if self.set_property is not None and not sim.particles.has(self.set_property[0]):
            raise ScriptError(f"set_property: no per-atom property {self.set_property[0]}")
        if self.finished:
            self.next_reneighbor = None
            return
        first = self.start if self.start is not None else sim.step + 1
        if getattr(self, "first_step", None) is None:
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
            pool = self._pool(rng, count, big)
            lo_grid, width, nbins, periodic, length = grid(sim.box, lo, hi, cell)
            clearance = self.clearance(pool, big) if self.all_in else np.full(len(pool), np.inf)
            self.taken = np.zeros(count, dtype=np.int64)
            place(pool, clearance, radius, old_x, old_r, lo_grid, width, nbins, periodic, length,
                  count * self.max_attempt, self.overlap_check, placed, done, self.taken)
        n = int(done.sum())
        self.placed_rows = self.taken[done] if count else np.zeros(0, dtype=np.int64)
        radius, density, types, which, placed = radius[done], density[done], types[done], which[done], placed[done]
        velocity = self._velocities(rng, n)
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
                     f"others found no room in {count * self.max_attempt} tries (maxattempt {self.max_attempt} each)")
        if self.verbose:
            sim.info(f"fix {self.id} ({self.name}): inserted {n} particles (mass {mass.sum():.6g}) at step "
                     f"{sim.step}; {self.inserted} (mass {self.inserted_mass:.6g}) so far")

    def _present(self, sim):
        """Centres and radii of every present particle, on every rank."""
        p = sim.particles
        n = p.nlocal
        rows = sim.comm.allgather_rows(np.column_stack([p.x[:n], p.radius[:n]]))
        return np.ascontiguousarray(rows[:, :3]), np.ascontiguousarray(rows[:, 3])

    def _pool(self, rng, count, big):
        """Candidate centres: count x maxattempt of them where the volume allows."""
        size = min(count * self.max_attempt, POOL_LIMIT)
        return np.ascontiguousarray(self.draw_points(rng, size))

    def _velocities(self, rng, n):
        mean, spread = self.velocity_mean, self.velocity_spread
        if self.velocity_style == "uniform":
            return mean + spread * (2.0 * rng.random((n, 3)) - 1.0)
        if self.velocity_style == "gaussian":
            return mean + spread * rng.standard_normal((n, 3))
        return np.tile(mean, (n, 1))
