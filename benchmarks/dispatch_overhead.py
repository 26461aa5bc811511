"""Hook dispatch overhead on the PDPS water example (DESIGN: under 2 % of a step).

Runs the water example (no dump) and measures, per step, (a) the whole step and (b) the cost of
calling the timestep hooks through pluggy with the styles' work removed: every hook the run uses is
dispatched to implementations that return at once. Prints both and their ratio.

    .venv/bin/python benchmarks/dispatch_overhead.py
"""

import pathlib
import time

from pdps_core.api import Simulation

WATER = (pathlib.Path(__file__).parents[1] / "examples" / "water.in").read_text()
STEPS = 200


def main():
    sim = Simulation(screen=False, log=None)
    sim.command(WATER.replace("dump              1 all atom 1 dump.atom", "").replace("run               200", "run 10"))
    t0 = time.perf_counter()
    sim.command(f"run {STEPS}")
    per_step = (time.perf_counter() - t0) / STEPS

    integrator = sim.run_state.integrator
    for hook, caller in integrator.hooks.items():
        for impl in caller.get_hookimpls():
            setattr(impl.plugin.style, hook, lambda sim: None)
    integrator._register_hooks()
    hooks = list(integrator.hooks)
    calls = 2000
    t0 = time.perf_counter()
    for _ in range(calls):
        for hook in hooks:
            integrator._call(hook)
    dispatch = (time.perf_counter() - t0) / calls
    print(f"step {per_step * 1e3:.3f} ms, hook dispatch {dispatch * 1e6:.1f} us "
          f"({len(hooks)} hooks: {', '.join(hooks)}), overhead {100 * dispatch / per_step:.2f} %")


if __name__ == "__main__":
    main()
