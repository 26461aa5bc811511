r"""``velocity``: set, draw, scale, ramp or zero the velocities of a group (LAMMPS's command, which the
PDPS manual's ``velocity ... create|set`` is a part of).

    velocity GROUP create T SEED [keyword value]...      random velocities, scaled to temperature T
    velocity GROUP set VX VY VZ [keyword value]...       each a number, NULL (kept) or v_NAME
                                                         (equal- or atom-style variable)
    velocity GROUP scale T [keyword value]...            scaled to temperature T
    velocity GROUP ramp vx|vy|vz VLO VHI x|y|z CLO CHI   a velocity component linear in a coordinate
    velocity GROUP zero linear|angular                   the group's momentum or angular momentum removed

keywords (LAMMPS's, with its defaults): ``dist uniform|gaussian`` (uniform; PDPS also takes the bare
word ``uniform`` or ``gaussian``), ``sum no|yes`` (add to the velocities instead of replacing them),
``mom yes|no`` and ``rot no|yes`` (create: zero the linear / angular momentum before scaling),
``temp COMPUTE-ID`` (the temperature to scale by; default the group's own), ``loop all|local|geom``,
``units lattice|box`` (set's and ramp's numbers in lattice spacings or distance units; LAMMPS's
default lattice, PDPS's and LIGGGHTS 3.8.0's box, see ``Dialect.velocity_units``; without a lattice command the spacing is
1, LAMMPS's ``lattice none 1.0``). ``bias yes`` and ``rigid`` are not supported.

create, step by step (LAMMPS's order, velocity.cpp):

1. three numbers r per particle, U(-1/2, 1/2) or N(0, 1); v = r / sqrt(m) (so every mass gets the
   same temperature); v_z = 0 in 2-d;
2. ``mom yes``: v -= sum m v / sum m;  ``rot yes``: v -= omega x (x - x_cm), omega = I^-1 L about the
   centre of mass, with unwrapped positions (a singular I, for a line of particles: its
   eigenvectors, principal moments below 1e-6 of the largest taken as 0);
3. v *= sqrt(T / T_now), T_now = sum m v^2 mvv2e / (N_dof k_B), N_dof = d N - d - (removed by fixes),
   or the ``temp`` compute's value;
4. ``sum yes``: the velocities before the command are added back.

The numbers of step 1 depend on the dialect (``Dialect.velocity_numbers``):

- LAMMPS (``park``): LAMMPS's own Park-Miller generator (pdps_core/random_park.py) as LAMMPS drives
  it, so a deterministic LAMMPS script follows LAMMPS's trajectory. ``loop all`` (default) draws a
  triple for every id 1..N in turn from one stream seeded with SEED and keeps the owned ones (the
  ids must be exactly 1..N, LAMMPS's rule; the same numbers on any number of ranks); ``loop local``
  draws for the owned group members in order from a stream seeded SEED + rank after 100 warm-up
  draws (different on other rank counts); ``loop geom`` seeds a stream per particle from SEED and
  its position (the same on any rank count).
- PDPS (``counter``): counter-based numbers keyed by SEED and the particle id (pdps_core/random.py,
  stream 2), the same on any number of ranks and for any ids, with memory for the owned particles
  only; ``loop`` changes nothing.

Sums (mass, momentum, temperature) run over the owned particles in order, then over ranks, as
LAMMPS's, so one-rank runs agree with LAMMPS to the last bits.
"""

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from ..errors import ScriptError
from ..random import particle_gaussians, particle_uniforms
from ..random_park import MAX_SEED, park_reset_coord, park_triple, park_uniform
from ..state import limits
from ..state import observables as obs
from . import command
from .words import choice, integer, number, yes_no

USAGE = ("velocity GROUP create T SEED | set VX VY VZ | scale T | ramp vx|vy|vz VLO VHI x|y|z CLO CHI | "
         "zero linear|angular, then [dist uniform|gaussian] [sum yes|no] [mom yes|no] [rot yes|no] "
         "[temp COMPUTE-ID] [loop all|local|geom] [units box|lattice]")
STYLES = {"create": (2, "a temperature and a seed"), "set": (3, "VX VY VZ"), "scale": (1, "a temperature"),
          "ramp": (6, "vx|vy|vz VLO VHI x|y|z CLO CHI"), "zero": (1, "linear or angular")}
KEYWORDS = ("dist", "sum", "mom", "rot", "temp", "loop", "units")
VELOCITY_STREAM = 2      # fix langevin draws in stream 1
WARMUP_LOCAL = 100       # LAMMPS's warm-up draws for loop local
SINGULAR = 1e-6          # LAMMPS's group.cpp: a determinant of I below this is singular
AXES = "xyz"


@dataclass
class Options:
    dist: str = "uniform"
    sum: bool = False
    mom: bool = True
    rot: bool = False
    temp: str = None
    loop: str = "all"
    units: str = "lattice"


@command("velocity")
def velocity(sim, args):
    if len(args) < 2:
        raise ScriptError(f"expected a group and a style; usage: {USAGE}")
    sim.require_box("velocity")
    group = sim.require_group(args[0])
    style = choice(args[1], "velocity style", tuple(STYLES))
    needed, what = STYLES[style]
    given = args[2:2 + needed]
    if len(given) < needed:
        raise ScriptError(f"expected {what}; usage: {USAGE}")
    options = _options(sim, args[2 + needed:])
    p = sim.particles
    before = p.v[: p.nlocal].copy()
    try:
        {"create": _create, "set": _set, "scale": _scale, "ramp": _ramp, "zero": _zero}[style](
            sim, group, given, options)
        changed = p.v[: p.nlocal][sim.groups.select(sim, group)]
        largest = float(sim.comm.max(float(np.abs(changed).max(initial=0.0))))
        if not largest <= limits.MAX_COORDINATE:
            raise ScriptError(f"velocity {style} gives a velocity of {largest:g}, beyond "
                              f"+-{limits.MAX_COORDINATE:g} where squares overflow")
    except ScriptError:
        p.v[: p.nlocal] = before         # a refused command changes nothing
        raise


def _options(sim, words):
    options = Options(units=sim.dialect.velocity_units)
    i = 0
    while i < len(words):
        key = words[i]
        if key in ("uniform", "gaussian"):          # the PDPS manual's spelling of dist
            options.dist, i = key, i + 1
            continue
        if key == "rigid" or (key == "bias" and words[i + 1: i + 2] != ["no"]):
            raise ScriptError(f"velocity keyword {key} is not supported (supported: {', '.join(KEYWORDS)})")
        if key not in KEYWORDS + ("bias",):
            raise ScriptError(f"unknown velocity keyword {key}; usage: {USAGE}")
        if i + 1 >= len(words):
            raise ScriptError(f"keyword {key} needs a value; usage: {USAGE}")
        value = words[i + 1]
        if key == "dist":
            options.dist = choice(value, "dist", ("uniform", "gaussian"))
        elif key in ("sum", "mom", "rot"):
            setattr(options, key, yes_no(value, key))
        elif key == "loop":
            options.loop = choice(value, "loop", ("all", "local", "geom"))
        elif key == "units":
            options.units = choice(value, "units", ("box", "lattice"))
        elif key == "temp":
            compute = sim.computes.get(value)
            if compute is None:
                raise ScriptError(f"temp {value}: compute {value} is not defined")
            if not compute.name.startswith("temp"):
                raise ScriptError(f"temp {value}: compute {value} ({compute.name}) does not compute a temperature")
            options.temp = value
        i += 2
    return options


# ---- create -------------------------------------------------------------------------------------
def _create(sim, group, words, options):
    park = sim.dialect.velocity_numbers == "park"
    temp = number(words[0], "temperature", low=0.0, high=limits.MAX_SIZE)
    seed = integer(words[1], "seed", low=1, high=MAX_SEED if park else 2 ** 63 - 1)
    p = sim.particles
    rows = np.flatnonzero(sim.groups.select(sim, group))
    _require_masses(sim)
    if park and sim.comm.sum(len(rows)) == 0:
        raise ScriptError(f"group {group} has no particles")
    v = p.v[: p.nlocal]
    held = v[rows].copy() if options.sum else None
    gaussian = options.dist == "gaussian"
    if not park:
        draws = counter_draws(p.tag[: p.nlocal][rows], seed, gaussian)
    elif options.loop == "all":
        draws = _park_all(sim, rows, seed, gaussian)
    elif options.loop == "local":
        if seed + sim.comm.nprocs - 1 > MAX_SEED:
            raise ScriptError(f"seed {seed} plus the rank (loop local seeds SEED + rank) must be at most "
                              f"{MAX_SEED}")
        draws = np.empty((len(rows), 3))
        _park_local(seed + sim.comm.rank, gaussian, draws)
    else:
        draws = np.empty((len(rows), 3))
        _park_geom(seed, np.ascontiguousarray(p.x[: p.nlocal][rows]), gaussian, draws)
    m = obs.masses(sim, rows)
    factor = 1.0 / np.sqrt(m)
    v[rows] = draws * factor[:, None]
    if sim.dimension == 2:
        v[rows, 2] = 0.0
    if options.mom:
        zero_momentum(sim, rows)
    if options.rot:
        zero_rotation(sim, rows)
    current = _temperature(sim, group, rows, options)
    if current == 0.0 and not park:
        pass            # PDPS: a group with no thermal degrees of freedom keeps its zero velocities
    else:
        _rescale(sim, rows, current, temp)
    if held is not None:
        v[rows] += held


def _park_all(sim, rows, seed, gaussian):
    p = sim.particles
    tags = p.tag[: p.nlocal]
    natoms = int(sim.comm.sum(p.nlocal))
    if natoms > 2 ** 31 - 1:
        raise ScriptError(f"loop all draws for every id up to 2^31 - 1 (LAMMPS's limit); there are {natoms} "
                          "particles: use loop local or loop geom")
    low = int(sim.comm.min(int(tags.min()) if len(tags) else limits.MAX_TAG))
    high = int(sim.comm.max(int(tags.max()) if len(tags) else 0))
    if natoms and (low != 1 or high != natoms):
        raise ScriptError(f"loop all needs the particle ids to be 1..N (LAMMPS's rule); the {natoms} "
                          f"particles have ids {low}..{high}: use loop local or loop geom")
    chosen = tags[rows]
    order = np.argsort(chosen, kind="stable")
    draws = np.empty((len(rows), 3))
    _park_loop_all(seed, natoms, gaussian, np.ascontiguousarray(chosen[order]), order, draws)
    return draws


@njit(cache=True)
def _park_loop_all(seed, natoms, gaussian, sorted_tags, order, out):
    """A triple for each id 1..natoms from one stream; those of sorted_tags go to out[order[k]]."""
    state = np.empty(3)
    state[0], state[1], state[2] = seed, 0.0, 0.0
    k = 0
    n = len(sorted_tags)
    for i in range(1, natoms + 1):
        a, b, c = park_triple(state, gaussian)
        while k < n and sorted_tags[k] == i:
            out[order[k], 0], out[order[k], 1], out[order[k], 2] = a, b, c
            k += 1


@njit(cache=True)
def _park_local(seed, gaussian, out):
    state = np.empty(3)
    state[0], state[1], state[2] = seed, 0.0, 0.0
    for _ in range(WARMUP_LOCAL):
        park_uniform(state)
    for k in range(out.shape[0]):
        out[k, 0], out[k, 1], out[k, 2] = park_triple(state, gaussian)


@njit(cache=True)
def _park_geom(seed, x, gaussian, out):
    state = np.empty(3)
    for k in range(out.shape[0]):
        park_reset_coord(state, seed, x[k])
        out[k, 0], out[k, 1], out[k, 2] = park_triple(state, gaussian)


@njit(cache=True)
def _counter_draws(tags, seed, gaussian, out):
    for k in range(len(tags)):
        if gaussian:
            g0, g1, g2, _ = particle_gaussians(seed, 0, tags[k], VELOCITY_STREAM)
            out[k, 0], out[k, 1], out[k, 2] = g0, g1, g2
        else:
            u0, u1, u2, _ = particle_uniforms(seed, 0, tags[k], VELOCITY_STREAM)
            out[k, 0], out[k, 1], out[k, 2] = u0 - 0.5, u1 - 0.5, u2 - 0.5


def counter_draws(tags, seed, gaussian):
    """PDPS's numbers: three per particle id (N(0,1), or U(-1/2, 1/2)), the same on any rank count."""
    out = np.empty((len(tags), 3))
    _counter_draws(np.ascontiguousarray(tags, dtype=np.int64), seed, gaussian, out)
    return out


def _require_masses(sim):
    p = sim.particles
    if p.has("rmass"):
        return
    used = p.type[: p.nlocal]
    unset = used[~(sim.mass[used] > 0)]
    first = int(sim.comm.min(int(unset.min()) if len(unset) else sim.ntypes + 1))
    if first <= sim.ntypes:
        raise ScriptError(f"mass is not set for type {first} (use the mass command)")


# ---- group sums, in LAMMPS's order ----------------------------------------------------------------
@njit(cache=True)
def _mass_momentum(v, m, rows):
    total, px, py, pz = 0.0, 0.0, 0.0, 0.0
    for k in range(len(rows)):
        i = rows[k]
        total += m[k]
        px += v[i, 0] * m[k]
        py += v[i, 1] * m[k]
        pz += v[i, 2] * m[k]
    return total, px, py, pz


@njit(cache=True)
def _sum_m_v2(v, m, rows):
    total = 0.0
    for k in range(len(rows)):
        i = rows[k]
        total += (v[i, 0] * v[i, 0] + v[i, 1] * v[i, 1] + v[i, 2] * v[i, 2]) * m[k]
    return total


@njit(cache=True)
def _mass_centre_sums(unwrapped, m):
    total, cx, cy, cz = 0.0, 0.0, 0.0, 0.0
    for k in range(len(m)):
        total += m[k]
        cx += unwrapped[k, 0] * m[k]
        cy += unwrapped[k, 1] * m[k]
        cz += unwrapped[k, 2] * m[k]
    return total, cx, cy, cz


@njit(cache=True)
def _angular_sums(d, v, m, rows, out):
    """out[0:3]: angular momentum about the centre (d = x - x_cm); out[3:9]: the inertia tensor's
    xx, yy, zz, xy, yz, xz."""
    for k in range(len(rows)):
        i = rows[k]
        dx, dy, dz = d[k, 0], d[k, 1], d[k, 2]
        out[0] += m[k] * (dy * v[i, 2] - dz * v[i, 1])
        out[1] += m[k] * (dz * v[i, 0] - dx * v[i, 2])
        out[2] += m[k] * (dx * v[i, 1] - dy * v[i, 0])
        out[3] += m[k] * (dy * dy + dz * dz)
        out[4] += m[k] * (dx * dx + dz * dz)
        out[5] += m[k] * (dx * dx + dy * dy)
        out[6] -= m[k] * dx * dy
        out[7] -= m[k] * dy * dz
        out[8] -= m[k] * dx * dz


def zero_momentum(sim, rows):
    """v -= sum m v / sum m over the group's owned rows (all ranks)."""
    p = sim.particles
    v = p.v[: p.nlocal]
    if sim.comm.sum(len(rows)) == 0:
        return
    sums = sim.comm.sum(np.array(_mass_momentum(v, obs.masses(sim, rows), rows)))
    total = sums[0]
    vcm = sums[1:] / total if total > 0.0 else sums[1:]
    v[rows] -= vcm


def zero_rotation(sim, rows):
    """v -= omega x (x - x_cm), omega = I^-1 L, with unwrapped positions about the centre of mass."""
    p = sim.particles
    n = p.nlocal
    v = p.v[:n]
    if sim.comm.sum(len(rows)) == 0:
        return
    m = obs.masses(sim, rows)
    unwrapped = p.x[:n][rows] + p.image[:n][rows] * sim.box.length
    sums = sim.comm.sum(np.array(_mass_centre_sums(unwrapped, m)))
    total = sums[0]
    centre = sums[1:] / total if total > 0.0 else sums[1:]
    d = unwrapped - centre
    local = np.zeros(9)
    _angular_sums(d, v, m, rows, local)
    sums = sim.comm.sum(local)
    angmom = sums[:3]
    xx, yy, zz, xy, yz, xz = sums[3:]
    inertia = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    omega = _omega(angmom, inertia)
    v[rows, 0] -= omega[1] * d[:, 2] - omega[2] * d[:, 1]
    v[rows, 1] -= omega[2] * d[:, 0] - omega[0] * d[:, 2]
    v[rows, 2] -= omega[0] * d[:, 1] - omega[1] * d[:, 0]


def _omega(angmom, inertia):
    """omega with I omega = L: by the cofactor inverse, as LAMMPS's Group::omega, when det I > 1e-6;
    otherwise in I's principal axes, principal moments below 1e-6 of the largest counted as 0."""
    i = inertia
    det = (i[0, 0] * i[1, 1] * i[2, 2] + i[0, 1] * i[1, 2] * i[2, 0] + i[0, 2] * i[1, 0] * i[2, 1]
           - i[0, 0] * i[1, 2] * i[2, 1] - i[0, 1] * i[1, 0] * i[2, 2] - i[2, 0] * i[1, 1] * i[0, 2])
    if det > SINGULAR:
        inverse = np.empty((3, 3))
        inverse[0, 0] = i[1, 1] * i[2, 2] - i[1, 2] * i[2, 1]
        inverse[0, 1] = -(i[0, 1] * i[2, 2] - i[0, 2] * i[2, 1])
        inverse[0, 2] = i[0, 1] * i[1, 2] - i[0, 2] * i[1, 1]
        inverse[1, 0] = -(i[1, 0] * i[2, 2] - i[1, 2] * i[2, 0])
        inverse[1, 1] = i[0, 0] * i[2, 2] - i[0, 2] * i[2, 0]
        inverse[1, 2] = -(i[0, 0] * i[1, 2] - i[0, 2] * i[1, 0])
        inverse[2, 0] = i[1, 0] * i[2, 1] - i[1, 1] * i[2, 0]
        inverse[2, 1] = -(i[0, 0] * i[2, 1] - i[0, 1] * i[2, 0])
        inverse[2, 2] = i[0, 0] * i[1, 1] - i[0, 1] * i[1, 0]
        inverse /= det
        return np.array([inverse[k, 0] * angmom[0] + inverse[k, 1] * angmom[1] + inverse[k, 2] * angmom[2]
                         for k in range(3)])
    moments, axes = np.linalg.eigh(inertia)
    largest = moments.max()
    projected = axes.T @ angmom
    body = np.where(moments < SINGULAR * largest, 0.0,
                    np.divide(projected, moments, out=np.zeros(3), where=moments != 0.0))
    body[moments <= 0.0] = 0.0
    return axes @ body


def _temperature(sim, group, rows, options):
    """The temperature create and scale scale by: the ``temp`` compute's, else the group's as
    LAMMPS's compute temp sums it (sum m v^2, times mvv2e / (N_dof k_B))."""
    if options.temp is not None:
        compute = sim.computes[options.temp]
        if compute.group != group:
            sim.warn(f"velocity: group {group} is scaled by the temperature of compute {options.temp}, "
                     f"of group {compute.group}")
        return float(compute.scalar(sim))
    p = sim.particles
    total = sim.comm.sum(_sum_m_v2(p.v[: p.nlocal], obs.masses(sim, rows), rows))
    dof = obs.degrees_of_freedom(sim, group)
    factor = sim.units.mvv2e / (dof * sim.units.boltz) if dof > 0 else 0.0
    return total * factor


def _rescale(sim, rows, current, wanted):
    if not math.isfinite(current):
        raise ScriptError(f"the group's temperature is {current:g}: velocities too large to scale")
    if current == 0.0:
        raise ScriptError("the group's temperature is 0, which no factor scales (particles at rest, or "
                          "no degrees of freedom)")
    p = sim.particles
    p.v[: p.nlocal][rows] *= math.sqrt(wanted / current)


# ---- scale, set, ramp, zero -----------------------------------------------------------------------
def _scale(sim, group, words, options):
    wanted = number(words[0], "temperature", low=0.0, high=limits.MAX_SIZE)
    _require_masses(sim)
    rows = np.flatnonzero(sim.groups.select(sim, group))
    _rescale(sim, rows, _temperature(sim, group, rows, options), wanted)


def _spacing(sim, options):
    if options.units == "box" or sim.lattice is None:
        return np.ones(3)
    return np.asarray(sim.lattice.spacing, dtype=np.float64)


def _component(sim, word, axis, scale):
    """One of set's values: None (NULL), a number (scaled), or a variable's per-particle values."""
    if word == "NULL":
        return None
    if word.startswith("v_"):
        name = word[2:]
        if name not in sim.variables:
            raise ScriptError(f"v{axis}: variable {name} is not defined")
        style = sim.variables.style(name)
        if style not in ("equal", "internal", "atom"):
            raise ScriptError(f"v{axis}: variable {name} is {style}-style; velocity set takes equal- or "
                              "atom-style variables")
        if sim.dimension == 2 and axis == "z":
            raise ScriptError(f"vz cannot be a variable in 2-d (got {word})")
        values = sim.variables.atom_values(name)
        bad = ~(np.abs(values) <= limits.MAX_COORDINATE)
        if bad.any():
            raise ScriptError(f"v{axis}: variable {name} is {values[bad][0]:g}, beyond "
                              f"+-{limits.MAX_COORDINATE:g}")
        return values
    value = number(word, "v" + axis, low=-limits.MAX_COORDINATE, high=limits.MAX_COORDINATE)
    if sim.dimension == 2 and axis == "z" and value != 0.0:
        raise ScriptError(f"vz must be 0 or NULL in 2-d (got {word})")
    value *= scale
    if abs(value) > limits.MAX_COORDINATE:
        raise ScriptError(f"v{axis} {word} times the lattice spacing {scale:g} is beyond "
                          f"+-{limits.MAX_COORDINATE:g}")
    return value


def _set(sim, group, words, options):
    spacing = _spacing(sim, options)
    # every value is read before any is set, so a bad one changes nothing
    values = [_component(sim, word, axis, spacing[d]) for d, (axis, word) in enumerate(zip(AXES, words))]
    p = sim.particles
    chosen = sim.groups.select(sim, group)
    v = p.v[: p.nlocal]
    for d, value in enumerate(values):
        if value is None:
            continue
        if isinstance(value, np.ndarray):
            value = value[chosen]
        if options.sum:
            v[chosen, d] += value
        else:
            v[chosen, d] = value


def _ramp(sim, group, words, options):
    spacing = _spacing(sim, options)
    vdim = "xyz".index(choice(words[0], "ramp component", ("vx", "vy", "vz"))[1])
    if vdim == 2 and sim.dimension == 2:
        raise ScriptError("ramp of vz in 2-d")
    low = spacing[vdim] * number(words[1], "vlo", low=-limits.MAX_COORDINATE, high=limits.MAX_COORDINATE)
    high = spacing[vdim] * number(words[2], "vhi", low=-limits.MAX_COORDINATE, high=limits.MAX_COORDINATE)
    dim = AXES.index(choice(words[3], "ramp coordinate", tuple(AXES)))
    clo = spacing[dim] * number(words[4], "clo", low=-limits.MAX_COORDINATE, high=limits.MAX_COORDINATE)
    chi = spacing[dim] * number(words[5], "chi", low=-limits.MAX_COORDINATE, high=limits.MAX_COORDINATE)
    if clo == chi:
        raise ScriptError(f"ramp needs clo != chi (got {words[4]} {words[5]})")
    for name, value in (("vlo", low), ("vhi", high), ("clo", clo), ("chi", chi)):
        if not abs(value) <= limits.MAX_COORDINATE:
            raise ScriptError(f"{name} in lattice units is {value:g}, beyond +-{limits.MAX_COORDINATE:g}")
    p = sim.particles
    chosen = sim.groups.select(sim, group)
    x = p.x[: p.nlocal][chosen, dim]
    fraction = np.minimum(np.maximum((x - clo) / (chi - clo), 0.0), 1.0)
    ramped = low + fraction * (high - low)
    v = p.v[: p.nlocal]
    if options.sum:
        v[chosen, vdim] += ramped
    else:
        v[chosen, vdim] = ramped


def _zero(sim, group, words, options):
    which = choice(words[0], "zero", ("linear", "angular"))
    _require_masses(sim)
    rows = np.flatnonzero(sim.groups.select(sim, group))
    if sim.comm.sum(len(rows)) == 0:
        raise ScriptError(f"group {group} has no particles to zero the momentum of")
    (zero_momentum if which == "linear" else zero_rotation)(sim, rows)
