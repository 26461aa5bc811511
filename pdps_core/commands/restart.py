"""Restart commands: write_restart, read_restart, restart (LAMMPS semantics; the file format and what
it holds are in pdps_core/state/restart.py)."""

from ..errors import ScriptError
from ..state import restart as files
from . import command
from .words import count, integer


@command("write_restart")
def write_restart(sim, args):
    count(args, 1, "write_restart FILE")
    sim.require_box("write_restart")
    files.write_restart(sim, args[0].replace("*", str(sim.step)))


@command("read_restart")
def read_restart(sim, args):
    count(args, 1, "read_restart FILE")
    if sim.box is not None:
        raise ScriptError("read_restart needs no box to exist yet (it creates it)")
    path, shown = sim.resolve(args[0]), args[0]
    if "*" in path:
        path = shown = files.latest(path)
    files.read_restart(sim, path, shown)
    total = int(sim.comm.sum(sim.particles.nlocal))
    sim.output.message(f"Read restart file {shown}: {total} particles at step {sim.step}")


@command("restart")
def restart(sim, args):
    usage = "restart 0 | restart N FILE [FILE2]"
    if not args:
        raise ScriptError(f"expected N; usage: {usage}")
    every = integer(args[0], "N", low=0)
    if every == 0:
        count(args, 1, usage)
        sim.run_state.restart_output = None
        return
    count(args, 2, usage, at_most=3)
    sim.run_state.restart_output = files.RestartOutput(every, args[1:])
