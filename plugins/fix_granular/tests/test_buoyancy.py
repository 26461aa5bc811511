"""fix buoyancy (LIGGGHTS's numbers: plugins/fix_granular/tests/data/liggghts.cases.json, cases
buoyancy and buoyancy_region): a sphere fully below the level carries the weight of its volume of
fluid, one cut by the surface that of its immersed cap, one above none; what it needs is refused by
line."""

import math

import pytest

from pdps_core.api import ScriptError


def _force_on(spheres, z, level=1.0, rho=2.0, g=3.0):
    sim = spheres(f"""
        create_particle 1 single 0 0 {z} diameter 1.0 density 1.0
        fix grav all gravity {g} vector 0 0 -1
        fix float all buoyancy density {rho} level {level} dim z
        run 0
    """)
    return sim.fixes["float"].vector(sim)[2]


@pytest.mark.parametrize("z, immersed", [
    (-5.0, 4.0 / 3.0 * math.pi * 0.125),               # fully immersed
    (3.0, 0.0),                                        # above the surface
    (1.0, 2.0 / 3.0 * math.pi * 0.125),                # cut through its centre: half
    (1.3, math.pi * 0.2 ** 2 * (3 * 0.5 - 0.2) / 3),   # a cap of height 0.2 in the fluid
])
def test_the_force_is_the_weight_of_the_fluid_displaced(spheres, z, immersed):
    assert _force_on(spheres, z) == pytest.approx(3.0 * 2.0 * immersed, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize("setup, line, message", [
    ("fix grav all gravity 9.81 vector 0 0 -1", "fix f all buoyancy density 1000", "fix buoyancy needs dim x|y|z"),
    ("fix grav all gravity 9.81 vector 0 0 -1", "fix f all buoyancy dim z", "fix buoyancy needs density RHO"),
    ("", "fix f all buoyancy density 1000 dim z\nrun 0", "fix f (buoyancy) needs exactly one fix gravity (found 0)"),
    ("fix grav all gravity 9.81 vector 1 0 -1", "fix f all buoyancy density 1000 dim z\nrun 0",
     "fix f (buoyancy): fix grav (gravity) does not point along dim z"),
    ("fix grav all gravity 9.81 vector 0 0 -1", "fix f all buoyancy density 1000 dim z level -1",
     "level must be > 0 (got -1)"),
])
def test_what_it_needs_is_a_one_line_error(spheres, setup, line, message):
    sim = spheres("create_particle 1 single 0 0 0 diameter 1.0\n" + setup)
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert message in error.value.message
