"""What the run and minimize commands do around their integrator: the run's bounds, the setup,
the loop, and the summary LAMMPS prints after a run (loop time, performance, the stage table)."""

import time


def run_steps(sim, nsteps, ramp_bounds=None):
    """Run ``nsteps`` timesteps (ramp() reads ``ramp_bounds``, default this run's first and last)."""
    from .verlet import Verlet
    run = sim.run_state
    sim.require_box("run")
    sim.system.check_masses()
    run.ramp_bounds = (run.step, run.step + nsteps) if ramp_bounds is None else tuple(ramp_bounds)
    run.run_first_step = run.step
    last = run.step + nsteps
    run.run_last_step = last
    run.run_wall_start = None       # thermo's cpu counts from the loop's start, 0 before
    sim.output.thermo.last_clock = None
    integrator = Verlet(sim)
    run.integrator = integrator
    if sim.styles.restored_states:
        from ..state.restart import drop_unclaimed_states
        drop_unclaimed_states(sim)
    try:
        integrator.setup()
        sim.output.setup(run.step, last)
        sim.timers.reset()
        t_loop = time.perf_counter()
        run.run_wall_start = t_loop
        integrator.run(nsteps)
        loop = time.perf_counter() - t_loop
    finally:
        sim.output.flush()
    # between runs ramp() reads its start value, as LAMMPS's (its run's first and last steps collapse)
    run.ramp_bounds = (run.step, run.step)
    _report(sim, nsteps, loop)
    sim.output.flush()


def minimize(sim, etol, ftol, maxiter, maxeval):
    """LAMMPS's minimize (pdps_core/run/minimize.py); the result is kept in ``minimize_result``."""
    from .minimize import Minimizer
    run = sim.run_state
    sim.require_box("minimize")
    sim.system.check_masses()
    run.run_first_step, run.run_last_step = run.step, run.step + maxiter
    run.ramp_bounds = (run.step, run.step + maxiter)
    run.run_wall_start = None
    sim.output.thermo.last_clock = None
    minimizer = Minimizer(sim, run.min_settings)
    run.integrator = minimizer
    try:
        run.minimize_result = minimizer.minimize(etol, ftol, maxiter, maxeval)
    finally:
        sim.output.flush()
    run.run_last_step = run.step
    return run.minimize_result


def _report(sim, nsteps, loop):
    n = int(sim.comm.sum(sim.particles.nlocal))
    loop = float(sim.comm.max(loop))
    message = sim.output.message
    message(f"Loop time of {loop:.6g} on {sim.comm.nprocs} procs for {nsteps} steps with {n} particles")
    if loop > 0 and nsteps:
        message(f"Performance: {nsteps / loop:.4g} timesteps/s, {n * nsteps / loop / 1e6:.4g} M particle-steps/s")
    for line in sim.timers.report(loop):
        message(line)
    neighbor = sim.neighbor
    if neighbor.requests:
        message(f"Neighbor list builds = {neighbor.builds}, dangerous builds = {neighbor.dangerous}")
    message("")
