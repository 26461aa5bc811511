"""Hook dispatch overhead on the PDPS water example (DESIGN: under 2 % of a step), and what
pluggy's call would cost in its place (why pdps_core/run/hookspec.py dispatches by tuples).

Runs the water example (no dump) and measures, per step, (a) the whole step, (b) the cost of
calling the timestep hooks the run uses as the loop does, each dispatched to an implementation that
returns at once, and (c) the same hooks called through a pluggy PluginManager (pluggy is in the
bench extra, not a dependency of the core). Prints the three and the ratios.

    .venv/bin/python benchmarks/dispatch_overhead.py
"""

import pathlib
import time

import pluggy

from pdps_core.api import Simulation
from pdps_core.run.hookspec import HOOKS

WATER = (pathlib.Path(__file__).parents[1] / "examples" / "water.in").read_text()
STEPS = 200
CALLS = 2000


def pluggy_hooks(hooks, nstyles):
    """A pluggy manager with ``nstyles`` plugins implementing each of ``hooks`` by returning."""
    marker, implementation = pluggy.HookspecMarker("bench"), pluggy.HookimplMarker("bench")
    spec = type("Spec", (), {h: marker(lambda self, sim: None) for h in hooks})
    manager = pluggy.PluginManager("bench")
    manager.add_hookspecs(spec)
    for k in range(nstyles):
        manager.register(type(f"Style{k}", (), {h: implementation(lambda self, sim: None) for h in hooks})())
    return [getattr(manager.hook, h) for h in hooks]


def main():
    sim = Simulation(screen=False, log=None)
    sim.command(WATER.replace("dump              1 all atom 1 dump.atom", "").replace("run               200", "run 10"))
    t0 = time.perf_counter()
    sim.command(f"run {STEPS}")
    per_step = (time.perf_counter() - t0) / STEPS

    integrator = sim.run_state.integrator
    hooks = [h for h in HOOKS if h in integrator.hooks]
    nstyles = max(len(functions) for functions in integrator.hooks.values())
    integrator.hooks = {h: tuple((lambda sim: None) for _ in integrator.hooks[h]) for h in hooks}
    t0 = time.perf_counter()
    for _ in range(CALLS):
        for hook in hooks:
            integrator._call(hook)
    dispatch = (time.perf_counter() - t0) / CALLS

    callers = pluggy_hooks(hooks, nstyles)
    t0 = time.perf_counter()
    for _ in range(CALLS):
        for caller in callers:
            caller(sim=sim)
    through_pluggy = (time.perf_counter() - t0) / CALLS
    print(f"step {per_step * 1e3:.3f} ms; {len(hooks)} hooks ({', '.join(hooks)}): dispatch by tuple "
          f"{dispatch * 1e6:.2f} us ({100 * dispatch / per_step:.2f} % of a step), through pluggy "
          f"{through_pluggy * 1e6:.2f} us ({100 * through_pluggy / per_step:.2f} %)")


if __name__ == "__main__":
    main()
