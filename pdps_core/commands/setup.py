"""Initialization commands: units, dimension, boundary, timestep, lattice, neighbor, neigh_modify,
particle_style, processors, integrate, comm_modify, newton."""

import numpy as np

from ..errors import ScriptError
from ..state import limits
from ..state.units import UNITS
from . import command
from .words import choice, count, integer, number, yes_no

# LAMMPS's default skins: 0.3 sigma in lj units, 1 mm in SI.


def _before_box(sim, name):
    if sim.box is not None:
        raise ScriptError(f"{name} must come before the simulation box is created")


@command("units")
def units(sim, args):
    count(args, 1, f"units {'|'.join(UNITS)}")
    _before_box(sim, "units")
    style = choice(args[0], "units style", tuple(UNITS))
    sim.unit_system = UNITS[style]
    sim.dt = sim.unit_system.dt
    sim.neighbors.skin = sim.unit_system.skin


@command("dimension")
def dimension(sim, args):
    count(args, 1, "dimension 2|3")
    _before_box(sim, "dimension")
    sim.dimension = int(choice(args[0], "dimension", ("2", "3")))


@command("boundary")
def boundary(sim, args):
    count(args, 3, "boundary x y z  (each p or f)")
    _before_box(sim, "boundary")
    for axis, word in zip("xyz", args):
        choice(word, f"boundary {axis}", ("p", "f"))
    sim.periodicity = tuple(args)


@command("timestep")
def timestep(sim, args):
    count(args, 1, "timestep dt")
    number(args[0], "timestep", low=0.0, strict_low=True)
    sim.dt = number(args[0], "timestep", low=limits.MIN_SIZE, high=limits.MAX_SIZE)


@command("lattice")
def lattice(sim, args):
    """``lattice spacing x DX y DY z DZ`` (PDPS) or LAMMPS's lattices (pdps_core/state/lattice.py)."""
    from ..state.lattice import parse_lattice
    sim.lattice = parse_lattice(args, sim.unit_system.name, sim.dimension)


@command("neighbor")
def neighbor(sim, args):
    count(args, 1, "neighbor SKIN [single|multi|bin]", at_most=2)
    sim.neighbors.skin = number(args[0], "skin", low=0.0)
    if len(args) == 2:
        style = choice(args[1], "neighbor style", ("single", "multi", "bin"))
        sim.neighbors.style = "single" if style == "bin" else style


@command("neigh_modify", "neighbor_modify")
def neigh_modify(sim, args):
    usage = "neigh_modify [every N] [delay N] [check yes|no] [one N]"
    if not args or len(args) % 2:
        raise ScriptError(f"expected keyword/value pairs; usage: {usage}")
    values = {}
    for key, value in zip(args[::2], args[1::2]):
        choice(key, "neigh_modify keyword", ("every", "delay", "check", "one"))
        if key == "check":
            values[key] = yes_no(value, "check")
        elif key == "one":
            values[key] = integer(value, key, low=1, high=limits.MAX_NEIGHBORS_ONE)
        else:
            values[key] = integer(value, key, low=1 if key == "every" else 0)
    sim.neighbors.modify(**values)


@command("particle_style", "atom_style")
def particle_style(sim, args):
    count(args, 1, "particle_style atomic|sphere")
    _before_box(sim, "particle_style")
    style = choice(args[0], "particle style", ("atomic", "sphere"))
    sim.particle_style = style
    if style == "sphere":
        for name in ("radius", "rmass", "omega", "torque"):
            sim.particles.request(name)


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
    sim.processors = tuple(grid)
    sim.comm.set_grid(sim.processors)


@command("integrate", "run_style")
def integrate(sim, args):
    count(args, 1, "integrate v_verlet")
    style = "v_verlet" if args[0] == "verlet" else args[0]
    choice(style, "integrate style", ("v_verlet",))


@command("comm_modify")
def comm_modify(sim, args):
    """LAMMPS's ``comm_modify vel yes``: ghosts carry velocities even if no style asks for them."""
    if len(args) != 2 or args[0] != "vel":
        raise ScriptError("only 'comm_modify vel yes|no' is supported")
    sim.ghost_velocity = yes_no(args[1], "vel")


@command("newton")
def newton(sim, args):
    count(args, 1, "newton on", at_most=2)
    if any(word != "on" for word in args):
        raise ScriptError("only newton on is supported (pairs with ghosts are summed back)")


@command("atom_modify")
def atom_modify(sim, args):
    """LAMMPS's ``atom_modify sort N BINSIZE``: re-sort owned particles by cell every N steps (0: never).
    The bin size is accepted; pdps sorts on cells of half the neighbor cutoff."""
    if len(args) != 3 or args[0] != "sort":
        raise ScriptError("only 'atom_modify sort N BINSIZE' is supported")
    sim.neighbors.sort_every = integer(args[1], "sort interval", low=0)
    number(args[2], "bin size", low=0.0)
