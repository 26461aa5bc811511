"""fix property/atom/regiontracer/time: a particle's time in the simulation is its steps times dt;
its time in a region counts from the first look that finds it inside to the first that finds it
out (looks at multiples of check_region_every); the global means divide by every particle; what it
needs, one line each. (LIGGGHTS 3.8.0's numbers for the same fix: the recorded case
regiontracer_time, plugins/fix_property/tests/data/liggghts.cases.json.)"""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

DT = 1e-3
SETUP = f"""atom_style sphere
units si
boundary f f f
region box block 0 1 0 1 0 1 units box
create_box 1 box
region slab block 0.405 0.6 INF INF INF INF units box
create_atoms 1 single 0.1 0.5 0.5 units box
create_atoms 1 single 0.9 0.5 0.5 units box
set group all diameter 0.01 density 1000
group first id 1
velocity first set 1.0 0.0 0.0 units box
timestep {DT}
fix integr all nve/sphere
"""


def run(fix, steps):
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(SETUP + fix + f"\nrun {steps}")
    return sim


def test_a_crossing_counts_from_look_to_look():
    sim = run("fix rt all property/atom/regiontracer/time add_region slab check_region_every 30", 800)
    times = sim.fixes["rt"].peratom(sim)
    order = np.argsort(sim.particles.tag[:2])
    first, second = times[order]
    # particle 1 moves 1 mm a step from x = 0.1 (nothing acts on it): inside the slab from step 305
    # to 500; the looks at steps 330 to 480 find it in, the look at 510 out: 180 steps of dt
    assert first[0] == pytest.approx(800 * DT)
    assert first[1] == pytest.approx(180 * DT)
    assert first[2] == 0.0                              # the bitmap: out at the last look
    assert second[0] == pytest.approx(800 * DT) and second[1] == 0.0
    # the global means: sums over the group divided by all particles
    np.testing.assert_allclose(sim.fixes["rt"].vector(sim), [800 * DT, 180 * DT / 2])


def test_only_the_group_is_timed_and_without_regions_one_value_each():
    sim = run("fix rt first property/atom/regiontracer/time", 100)
    times = sim.fixes["rt"].peratom(sim)
    order = np.argsort(sim.particles.tag[:2])
    np.testing.assert_allclose(times[order], [100 * DT, 0.0])
    np.testing.assert_allclose(sim.fixes["rt"].vector(sim), [100 * DT / 2])


@pytest.mark.parametrize("fix, message", [
    ("fix rt all property/atom/regiontracer/time add_region nowhere",
     "region nowhere is not defined (defined: box, slab)"),
    ("fix rt all property/atom/regiontracer/time check_region_every 0", "check_region_every must be >= 1 (got 0)"),
    ("fix rt all property/atom/regiontracer/time add_region " + " add_region ".join(["slab"] * 54),
     "at most 53 regions (a bitmap in a double, as LIGGGHTS; got 54)"),
])
def test_what_it_needs_is_one_line(fix, message):
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(SETUP)
    with pytest.raises(ScriptError) as error:
        sim.command(fix)
    assert str(error.value) == f"<command>:1: fix: {message}"
