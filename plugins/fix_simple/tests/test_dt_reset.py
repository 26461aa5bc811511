"""fix dt/reset: the step that moves the fastest particle Xmax, bounded; fixes that keep constants of
the step follow it (reset_dt), fix move refuses it; bad input gets one line. LIGGGHTS 3.8.0's
numbers for a granular bed under gravity are in data/liggghts.cases.json (dt_reset,
dt_reset_unbounded), checked by tests/test_recorded_thermo.py."""

import io
import math

import pytest

from pdps_core.api import ScriptError, Simulation

ATOMS = """units lj
atom_style atomic
boundary p p p
region box block 0 10 0 10 0 10
create_box 1 box
mass 1 2.0
create_atoms 1 single 2 2 2
create_atoms 1 single 6 6 6
pair_style zero 1.0
pair_coeff * *
timestep 0.005
"""


def simulation(extra):
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None, dialect="lammps")
    sim.command(ATOMS + extra)
    return sim, screen


def test_the_step_moves_the_fastest_particle_xmax():
    """v = 4 (the faster one), no force: dt = Xmax / |v| = 0.1 / 4, in lattice units of spacing 1."""
    sim, _ = simulation("velocity all set 0 0 0\nfix 1 all nve\nfix d all dt/reset 1 NULL NULL 0.1")
    sim.particles.v[0] = (0.0, 4.0, 0.0)
    sim.particles.v[1] = (1.0, 0.0, 0.0)
    sim.command("run 3")
    assert sim.dt == pytest.approx(0.025, rel=1e-14)
    assert sim.fixes["d"].scalar(sim) == 0.0          # it changed at the setup of step 0 only
    assert sim.time == pytest.approx(3 * 0.025, rel=1e-14)


def test_a_force_bounds_the_step_by_the_distance_it_drives():
    """At rest under F = 8 on mass 2: dt = sqrt(2 Xmax m / F), which moves it Xmax exactly."""
    sim, _ = simulation("velocity all set 0 0 0\nfix 1 all nve\nfix push all addforce 8.0 0.0 0.0\n"
                        "fix d all dt/reset 1 NULL NULL 0.1 units box")
    sim.command("run 0")
    assert sim.dt == pytest.approx(math.sqrt(2 * 0.1 * 2.0 / 8.0), rel=1e-14)


def test_tmin_and_tmax_bound_it_and_nothing_moving_keeps_it():
    sim, _ = simulation("velocity all set 0 0 0\nfix 1 all nve\nfix d all dt/reset 1 0.5 0.75 0.1")
    sim.particles.v[0] = (0.0, 4.0, 0.0)
    sim.command("run 1")
    assert sim.dt == 0.5
    sim, screen = simulation("velocity all set 0 0 0\nfix 1 all nve\nfix d all dt/reset 1 NULL NULL 0.1\nrun 2")
    assert sim.dt == 0.005
    assert ("WARNING: fix d dt/reset: nothing in group all moves or feels a force and no Tmax is given: the "
            "time step stays 0.005 (step 0)") in screen.getvalue()


def test_a_thermostat_follows_the_new_step_and_fix_move_refuses_it():
    sim, _ = simulation("velocity all set 1 0 0\nfix 1 all nvt temp 1.0 1.0 0.5\nfix d all dt/reset 1 NULL NULL 0.1")
    sim.command("run 2")
    assert sim.dt != 0.005 and sim.fixes["1"].dtv == sim.dt and sim.fixes["1"].dthalf == 0.5 * sim.dt
    sim, _ = simulation("velocity all set 1 0 0\nfix 1 all move linear 1 0 0\nfix d all dt/reset 1 NULL NULL 0.1")
    with pytest.raises(ScriptError) as caught:
        sim.command("run 2")
    assert caught.value.message == ("fix 1 move: the time step cannot change during a run with fix move "
                                    "(LAMMPS's and LIGGGHTS's fix move refuse it too: their source)")


@pytest.mark.parametrize("words, message", [
    ("1 0.5 0.25 0.1", "Tmin must be below Tmax (got 0.5 0.25)"),
    ("1 -1 NULL 0.1", "Tmin must be >= 0 or NULL (got -1)"),
    ("1 NULL NULL 0", "xmax must be > 0 (got 0)"),
    ("0 NULL NULL 0.1", "every must be >= 1 (got 0)"),
    ("1 NULL NULL 0.1 units cells", "units must be one of 'box' or 'lattice' (got cells)"),
])
def test_bad_arguments(words, message):
    sim, _ = simulation("")
    with pytest.raises(ScriptError) as caught:
        sim.command(f"fix d all dt/reset {words}")
    assert message in caught.value.message
