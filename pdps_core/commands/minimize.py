"""LAMMPS's minimisation commands: ``minimize ETOL FTOL MAXITER MAXEVAL``, ``min_style cg|sd|fire``,
``min_modify dmax D | line quadratic|backtrack`` (pdps_core/run/minimize.py)."""

from ..errors import ScriptError
from ..state import limits
from . import command
from .words import choice, count, integer, number


@command("min_style")
def min_style(sim, args):
    count(args, 1, "min_style cg|sd|fire")
    sim.run_state.min_settings.style = choice(args[0], "min_style", ("cg", "sd", "fire"))


@command("min_modify")
def min_modify(sim, args):
    usage = "min_modify [dmax D] [line quadratic|backtrack]"
    if not args or len(args) % 2:
        raise ScriptError(f"expected keyword/value pairs; usage: {usage}")
    for key, value in zip(args[::2], args[1::2]):
        choice(key, "min_modify keyword", ("dmax", "line"))
        if key == "dmax":
            sim.run_state.min_settings.dmax = number(value, "dmax", low=0.0, strict_low=True, high=limits.MAX_COORDINATE)
        else:
            sim.run_state.min_settings.line = choice(value, "line", ("quadratic", "backtrack"))


@command("minimize")
def minimize(sim, args):
    count(args, 4, "minimize ETOL FTOL MAXITER MAXEVAL")
    etol = number(args[0], "etol", low=0.0)
    ftol = number(args[1], "ftol", low=0.0)
    maxiter = integer(args[2], "maxiter", low=1, high=limits.MAX_RUN)
    maxeval = integer(args[3], "maxeval", low=1, high=limits.MAX_RUN)
    if sim.step + maxiter > limits.MAX_STEP:
        raise ScriptError(f"minimize {maxiter} iterations from step {sim.step} go past the last step a 64-bit "
                          "counter holds")
    sim.minimize(etol, ftol, maxiter, maxeval)
