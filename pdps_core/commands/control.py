"""Script control and output commands: variable, next, print, include, run, reset_timestep, thermo,
thermo_style, log."""

from ..errors import ScriptError
from ..state import limits
from ..script.lexer import substitute
from . import command
from .words import count, integer


@command("variable")
def variable(sim, args):
    sim.variables.define(args)


@command("next")
def next_(sim, args):
    if not args:
        raise ScriptError("expected: next NAME...")
    for name in args:
        sim.variables.next(name)


@command("print")
def print_(sim, args):
    """Quoted text is substituted here too, as LAMMPS's print does."""
    sim.output.message(substitute(" ".join(args), sim.variables.text))


@command("include")
def include(sim, args):
    count(args, 1, "include FILE")
    sim.file(sim.resolve(args[0]))


@command("run")
def run(sim, args):
    count(args, 1, "run N")
    nsteps = integer(args[0], "N", low=0, high=limits.MAX_RUN)
    if sim.step + nsteps > limits.MAX_STEP:
        raise ScriptError(f"run {nsteps} from step {sim.step} goes past the last step a 64-bit "
                          f"counter holds ({limits.MAX_STEP})")
    sim.run_steps(nsteps)


@command("reset_timestep")
def reset_timestep(sim, args):
    count(args, 1, "reset_timestep N")
    sim.reset_step(integer(args[0], "timestep", low=0, high=limits.MAX_STEP))
    sim.energy_step = sim.virial_step = None


@command("thermo")
def thermo(sim, args):
    count(args, 1, "thermo N")
    sim.output.thermo.every = integer(args[0], "N", low=0)


@command("thermo_style")
def thermo_style(sim, args):
    sim.output.thermo.set_style(args)


@command("log")
def log(sim, args):
    count(args, 1, "log FILE|none")
    if args[0] == "none":
        sim.output.close_log()
    else:
        sim.output.open_log(args[0])
