"""Initialization commands: units, dimension, boundary, timestep, lattice, neighbor, neigh_modify,
particle_style, processors, integrate, comm_modify, newton."""

import numpy as np

from ..errors import ScriptError
from ..run.shrink_wrap import BOUNDARY_STYLES
from ..state import limits
from ..state.particles import PARTICLE_STYLES, style_properties, substyles
from ..state.units import UNITS
from . import command
from .words import choice, count, integer, number, type_range, yes_no

# LAMMPS's default skins: 0.3 sigma in lj units, 1 mm in SI.


def _before_box(sim, name):
    if sim.box is not None:
        raise ScriptError(f"{name} must come before the simulation box is created")


@command("units")
def units(sim, args):
    count(args, 1, f"units {'|'.join(UNITS)}")
    _before_box(sim, "units")
    style = choice(args[0], "units style", tuple(UNITS))
    sim.system.units = UNITS[style]
    sim.run_state.dt = sim.units.dt
    sim.neighbor.skin = sim.units.skin


@command("dimension")
def dimension(sim, args):
    count(args, 1, "dimension 2|3")
    _before_box(sim, "dimension")
    sim.system.dimension = int(choice(args[0], "dimension", ("2", "3")))


@command("boundary")
def boundary(sim, args):
    """``boundary x y z``, each p (periodic) or f, s, m for both faces, or two of f, s, m (lower,
    upper face), as LAMMPS's and LIGGGHTS's: s shrink-wraps the face around the particles at every
    neighbor list rebuild, m too but never inside the face's first position (pdps_core.run.shrink_wrap)."""
    count(args, 3, "boundary x y z  (each p, f, s, m, or two of f, s, m)")
    _before_box(sim, "boundary")
    for axis, word in zip("xyz", args):
        choice(word, f"boundary {axis}", BOUNDARY_STYLES)
    sim.system.periodicity = tuple(args)


@command("timestep")
def timestep(sim, args):
    count(args, 1, "timestep dt")
    number(args[0], "timestep", low=0.0, strict_low=True)
    sim.run_state.dt = number(args[0], "timestep", low=limits.MIN_SIZE, high=limits.MAX_SIZE)


@command("lattice")
def lattice(sim, args):
    """``lattice spacing x DX y DY z DZ`` (PDPS) or LAMMPS's lattices (pdps_core/state/lattice.py)."""
    from ..state.lattice import parse_lattice
    sim.system.lattice = parse_lattice(args, sim.units.name, sim.dimension)


@command("neighbor")
def neighbor(sim, args):
    """``neighbor SKIN|auto [single|multi|bin]``; ``auto`` (pdps's own): the first steps of the next
    run try several skins and keep the fastest (pdps_core/neighbor/skin_trial.py)."""
    count(args, 1, "neighbor SKIN|auto [single|multi|bin]", at_most=2)
    if args[0] == "auto":
        sim.neighbor.start_skin_trial()
    else:
        sim.neighbor.skin = number(args[0], "skin", low=0.0, high=limits.MAX_COORDINATE)
        sim.neighbor.skin_trial = None
    if len(args) == 2:
        style = choice(args[1], "neighbor style", ("single", "multi", "bin"))
        sim.neighbor.style = "single" if style == "bin" else style


@command("neigh_modify", "neighbor_modify")
def neigh_modify(sim, args):
    usage = "neigh_modify [every N] [delay N] [check yes|no] [once yes|no] [one N] [exclude type I J | group G1 G2 | molecule/intra G | molecule/inter G | none]"
    if not args:
        raise ScriptError(f"expected keyword/value pairs; usage: {usage}")
    args = _exclusions(sim, list(args), usage)
    if not args:
        return
    if len(args) % 2:
        raise ScriptError(f"expected keyword/value pairs; usage: {usage}")
    values = {}
    for key, value in zip(args[::2], args[1::2]):
        choice(key, "neigh_modify keyword", ("every", "delay", "check", "once", "one", "exclude"))
        if key in ("check", "once"):
            values[key] = yes_no(value, key)
        elif key == "one":
            values[key] = integer(value, key, low=1, high=limits.MAX_NEIGHBORS_ONE)
        else:
            values[key] = integer(value, key, low=1 if key == "every" else 0)
    sim.neighbor.modify(**values)


def _exclusions(sim, args, usage):
    """Take ``exclude ...`` clauses out of neigh_modify's words (LAMMPS's pair exclusions)."""
    rest, k = [], 0
    neighbors = sim.neighbor
    while k < len(args):
        if args[k] != "exclude":
            rest.append(args[k])
            k += 1
            continue
        kind = args[k + 1] if k + 1 < len(args) else None
        if kind == "none":
            neighbors.excluded_type_pairs, neighbors.excluded_group_pairs = [], []
            neighbors.excluded_molecules = []
            k += 2
        elif kind == "type":
            if len(args) < k + 4:
                raise ScriptError(f"exclude type needs I J; usage: {usage}")
            sim.require_box("neigh_modify exclude type")
            neighbors.excluded_type_pairs.append((type_range(args[k + 2], sim.ntypes),
                                                  type_range(args[k + 3], sim.ntypes)))
            k += 4
        elif kind == "group":
            if len(args) < k + 4:
                raise ScriptError(f"exclude group needs G1 G2; usage: {usage}")
            neighbors.excluded_group_pairs.append((sim.require_group(args[k + 2]), sim.require_group(args[k + 3])))
            k += 4
        elif kind in ("molecule/intra", "molecule/inter"):
            if len(args) < k + 3:
                raise ScriptError(f"exclude {kind} needs a group; usage: {usage}")
            if not sim.particles.has("molecule"):
                raise ScriptError(f"exclude {kind} needs molecule ids (particle_style molecular, bond, "
                                  f"angle or full; this is {sim.particle_style})")
            neighbors.excluded_molecules.append((sim.require_group(args[k + 2]), kind.split("/")[1]))
            k += 3
        else:
            raise ScriptError(f"exclude takes type I J, group G1 G2, molecule/intra G, molecule/inter G or "
                              f"none (got {kind}); usage: {usage}")
    return rest


@command("particle_style", "atom_style")
def particle_style(sim, args):
    """``particle_style STYLE`` or ``particle_style hybrid STYLE1 STYLE2 ...`` (LAMMPS's atom_style
    hybrid: the per-atom values of every sub-style, e.g. ``hybrid sphere molecular`` for spheres with
    molecule ids); LIGGGHTS's ``atom_style granular`` is its sphere style. LAMMPS's ``atom_style
    sphere 0|1`` (whether radii may change in a run) is read as sphere: pdps's radii always may."""
    usage = "particle_style " + "|".join(PARTICLE_STYLES) + " or particle_style hybrid STYLE1 STYLE2 ..."
    if len(args) == 2 and args[0] == "sphere" and args[1] in ("0", "1"):
        # LAMMPS's radius flag (1: radii may change in a run, for fix adapt): pdps's radii always may
        args = args[:1]
    if args[:1] != ["hybrid"]:
        count(args, 1, usage)
    _before_box(sim, "particle_style")
    if args[0] != "hybrid":
        choice("sphere" if args[0] == "granular" else args[0], "particle style", tuple(PARTICLE_STYLES) + ("hybrid",))
    try:
        styles = substyles(" ".join(args))
    except ValueError as exc:
        raise ScriptError(f"{exc}; usage: {usage}") from None
    sim.system.particle_style = " ".join(("hybrid",) + styles) if args[0] == "hybrid" else styles[0]
    sim.particles.request_all(style_properties(sim.particle_style))


@command("processors")
def processors(sim, args):
    count(args, 3, "processors nx ny nz")
    grid = []
    for axis, word in zip("xyz", args):
        grid.append(None if word == "*" else integer(word, f"processors n{axis}", low=1))
    fixed = int(np.prod([g for g in grid if g is not None]))
    nprocs = sim.comm.nprocs
    if None not in grid and fixed != nprocs:
        raise ScriptError(f"processor grid {' x '.join(args)} = {fixed} does not match the "
                          f"{nprocs} rank(s) of this run")
    if nprocs % fixed:
        raise ScriptError(f"processor grid {' '.join(args)} cannot divide {nprocs} rank(s)")
    sim.system.processors = tuple(grid)
    sim.comm.set_grid(sim.system.processors)


@command("integrate", "run_style")
def integrate(sim, args):
    count(args, 1, "integrate v_verlet")
    style = "v_verlet" if args[0] == "verlet" else args[0]
    choice(style, "integrate style", ("v_verlet",))


@command("comm_modify")
def comm_modify(sim, args):
    """LAMMPS's ``comm_modify [mode single] [cutoff D] [vel yes|no]``: ghosts carry velocities even if
    no style asks for them (vel yes); ghosts reach at least D beyond the box (cutoff D)."""
    usage = "comm_modify [mode single] [cutoff D] [vel yes|no]"
    if not args or len(args) % 2:
        raise ScriptError(f"expected keyword/value pairs; usage: {usage}")
    for key, value in zip(args[::2], args[1::2]):
        choice(key, "comm_modify keyword", ("mode", "cutoff", "vel", "cutoff/multi", "group"))
        if key == "mode":
            # multi sends each type pair's ghosts only as far as its own cutoff: fewer ghosts than
            # single's, never another force, so pdps's single ghosts give the same numbers
            if choice(value, "mode", ("single", "multi")) == "multi" and sim.neighbor.style != "multi":
                raise ScriptError("mode multi needs multi neighbor lists (neighbor SKIN multi first), as LAMMPS's")
        elif key == "group":
            if value != "all":
                raise ScriptError(f"comm_modify group {value}: pdps sends the ghosts of every particle (group all)")
        elif key == "cutoff":
            sim.neighbor.comm_cutoff = number(value, "cutoff", low=0.0, high=limits.MAX_COORDINATE)
        elif key == "vel":
            sim.system.ghost_velocity = yes_no(value, "vel")
        else:
            raise ScriptError(f"comm_modify {key} is not supported (supported: mode single, cutoff, vel)")


@command("comm_style")
def comm_style(sim, args):
    """LAMMPS's ``comm_style brick|tiled``: pdps's ranks hold a regular grid of bricks (LAMMPS's brick);
    tiled, the sub-domains balance/fix balance rcb would cut, is read as it: the tiling changes
    which rank computes a particle, not a number."""
    count(args, 1, "comm_style brick|tiled")
    choice(args[0], "comm_style", ("brick", "tiled"))


@command("balance")
def balance(sim, args):
    """LAMMPS's ``balance THRESH STYLE args ... [keyword value ...]`` (styles x, y, z, shift, rcb):
    pdps keeps the regular processor grid it starts with, so on one rank this does nothing, as in
    LAMMPS, and on more it says once that it keeps the grid; ``out FILE`` is refused (no sub-domains
    to write)."""
    usage = "balance THRESH x|y|z|shift|rcb args ... [weight ...]"
    count(args, 2, usage, at_most=999)
    number(args[0], "thresh", low=0.0)
    choice(args[1], "balance style", ("x", "y", "z", "shift", "rcb"))
    if "out" in args[2:]:
        raise ScriptError("out: pdps keeps a regular processor grid, so it has no balanced sub-domains to write")
    sim.require_box("balance")
    if sim.comm.nprocs > 1:
        sim.warn("balance: pdps keeps its regular processor grid; balancing would move work between ranks, not "
                 "change a number")


@command("communicate")
def communicate(sim, args):
    """LIGGGHTS's (and old LAMMPS's) ``communicate single [cutoff D] [vel yes|no]``: comm_modify's
    settings with the style first."""
    count(args, 1, "communicate single [cutoff D] [vel yes|no]", at_most=5)
    choice(args[0], "communicate style", ("single",))
    if len(args) > 1:
        comm_modify(sim, args[1:])


@command("soft_particles")
def soft_particles(sim, args):
    """LIGGGHTS's ``soft_particles yes|no``: yes lifts its lower bound on youngsModulus (5e6 in si,
    5e7 in cgs units), which the granular material otherwise enforces."""
    count(args, 1, "soft_particles yes|no")
    sim.system.stiffness_checks["soft"] = not yes_no(args[0], "soft_particles")


@command("hard_particles")
def hard_particles(sim, args):
    """LIGGGHTS's ``hard_particles yes|no``: yes lifts its upper bound on youngsModulus (1e9 in si,
    1e10 in cgs units)."""
    count(args, 1, "hard_particles yes|no")
    sim.system.stiffness_checks["hard"] = not yes_no(args[0], "hard_particles")


@command("newton")
def newton(sim, args):
    """Accepted: pdps computes each pair with ghosts once and sums ghost forces back (LAMMPS's newton
    on); with off LAMMPS computes such pairs on both ranks instead, and the results are the same."""
    count(args, 1, "newton on|off [on|off]", at_most=2)
    for word in args:
        choice(word, "newton", ("on", "off"))


@command("atom_modify")
def atom_modify(sim, args):
    """LAMMPS's ``atom_modify [sort N BINSIZE] [map array|hash|yes] [id yes] [first GROUP]``: re-sort
    owned particles by cell every N steps (0: never; the bin size is accepted, pdps sorts on cells of
    half the neighbor cutoff). ``map`` and ``id yes`` are accepted (pdps always has ids and finds
    particles by id its own way); ``id no`` is refused. ``first GROUP`` (LAMMPS keeps the group's
    particles first in storage, for the speed of styles on that group, and refuses it with sorting
    on) changes no result: the group must exist and sorting be off (``sort 0 0``), as LAMMPS asks;
    pdps keeps its own order."""
    usage = "atom_modify [sort N BINSIZE] [map array|hash|yes] [id yes] [first GROUP]"
    if not args:
        raise ScriptError(f"expected keywords; usage: {usage}")
    k = 0
    first = None
    while k < len(args):
        key = args[k]
        if key == "sort":
            if k + 2 >= len(args):
                raise ScriptError(f"sort needs N and BINSIZE; usage: {usage}")
            sim.neighbor.sort_every = integer(args[k + 1], "sort interval", low=0)
            sim.neighbor.sort_set = True
            number(args[k + 2], "bin size", low=0.0)
            k += 3
        elif key in ("map", "id") and k + 1 < len(args):
            if key == "map":
                choice(args[k + 1], "map", ("array", "hash", "yes"))
            elif choice(args[k + 1], "id", ("yes", "no")) == "no":
                raise ScriptError("atom_modify id no is not supported: pdps particles always have ids")
            k += 2
        elif key == "first" and k + 1 < len(args):
            if args[k + 1] != "all":
                sim.require_group(args[k + 1])
                first = args[k + 1]
            k += 2
        elif key == "first":
            raise ScriptError(f"first needs a group; usage: {usage}")
        else:
            raise ScriptError(f"unknown atom_modify keyword {key}; usage: {usage}")
    if first is not None and sim.neighbor.sort_every > 0:
        raise ScriptError(f"first {first} needs sorting off (sort 0 0 first; LAMMPS: Atom_modify sort and first "
                          "options cannot be used together)")