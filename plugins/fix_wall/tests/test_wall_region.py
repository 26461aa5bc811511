"""Fix wall/region: each law's force is minus its energy's derivative along the surface normal and
its energy is 0 at the cutoff (harmonic: its own formula); a particle near a block's corner feels
each face within the cutoff; the force on the wall is minus the particles'; bad input gets one line.
(LIGGGHTS 3.8.0's and LAMMPS's thermo for the same fix: the recorded cases wall_region_*.)"""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import total_energy

LAWS = {"lj93": "lj93 1.7 0.9 2.2", "lj126": "lj126 1.7 0.9 2.2", "harmonic": "harmonic 3.0 1.0 2.2",
        "colloid": "colloid 1.7 0.9 2.2"}


def one_particle(law, region="region ball sphere 0 0 0 5.0 units box", at=(0.0, 0.0, 3.5)):
    sim = Simulation(screen=False, log=None)
    style = "sphere" if law.startswith("colloid") else "atomic"
    sim.command(f"units lj\nparticle_style {style}\nboundary f f f\nregion box block -6 6 -6 6 -6 6\n"
                f"create_box 1 box\n{'' if style == 'sphere' else 'mass 1 1'}\n{region}\n"
                f"create_particle 1 single {at[0]} {at[1]} {at[2]}"
                + (" diameter 0.8 density 1.0" if style == "sphere" else "") + "\n"
                f"fix w all wall/region ball {law}\nfix_modify w energy yes\nrun 0")
    return sim


def at_distance(sim, r, radius=5.0):
    """Energy and radial force (outward positive) with the particle at distance r from a sphere
    wall of ``radius`` (on the +z axis)."""
    sim.x[0] = (0.0, 0.0, radius - r)
    sim.command("run 0")
    return total_energy(sim), -sim.f[0, 2]


@pytest.mark.parametrize("law", ["lj93", "lj126", "harmonic"])
def test_force_is_minus_the_energy_gradient_along_the_normal(law):
    sim = one_particle(LAWS[law])
    h = 1e-6
    for r in (0.7, 1.0, 1.6, 2.1):
        (e_plus, _), (e_minus, _), (_, force) = at_distance(sim, r + h), at_distance(sim, r - h), at_distance(sim, r)
        # the force pushes away from the surface: -dE/dr, r the distance to the surface
        assert force == pytest.approx(-(e_plus - e_minus) / (2 * h), rel=1e-5, abs=1e-8), r
    if law == "harmonic":
        assert at_distance(sim, 1.2)[0] == pytest.approx(3.0 * (2.2 - 1.2) ** 2)
        assert at_distance(sim, 1.2)[1] == pytest.approx(2.0 * 3.0 * (2.2 - 1.2))
    else:
        assert at_distance(sim, 2.2 - 1e-9)[0] == pytest.approx(0.0, abs=1e-7)


def test_colloid_force_and_energy_are_lammps_s_formulas():
    """LAMMPS's colloid law in wall/region (and LIGGGHTS 3.8.0's: the recorded case wall_region_colloid
    agrees with both), written out again here: its force is not minus its energy's gradient (nor
    the force of LAMMPS's fix wall/colloid, whose coefficients have the other sign)."""
    sim = one_particle(LAWS["colloid"])
    eps, sigma, radius, cutoff = 1.7, 0.9, 0.4, 2.2
    c1, c2 = -4.0 / 315.0 * eps * sigma ** 6, -2.0 / 3.0 * eps
    c3, c4 = eps * sigma ** 6 / 7560.0, eps / 6.0
    offset = c3 / cutoff ** 9 - c4 / cutoff ** 3        # the lj93 form's, as LAMMPS's source
    for r in (0.75, 1.3, 2.0):
        d = radius ** 2 - r ** 2
        force = (c1 * (radius ** 9 + 27 * radius ** 7 * r ** 2 + 63 * radius ** 5 * r ** 4 + 21 * radius ** 3 * r ** 6)
                 / d ** 8 - c2 * radius ** 3 / d ** 2)
        near, far = radius - r, r + radius
        energy = (c3 * ((-7 * radius + r) / near ** 7 + (7 * radius + r) / far ** 7)
                  - c4 * ((-2 * radius * r + near * far * (math.log(-near) - math.log(far))) * (-1 / near) / far)
                  - offset)
        got_energy, got_force = at_distance(sim, r)
        assert got_energy == pytest.approx(energy, rel=1e-12)
        assert got_force == pytest.approx(force, rel=1e-12)
    h = 1e-6
    gradient = -(at_distance(sim, 0.75 + h)[0] - at_distance(sim, 0.75 - h)[0]) / (2 * h)
    assert at_distance(sim, 0.75)[1] < 0 < gradient


def test_lj93_energy_is_the_formula():
    sim = one_particle(LAWS["lj93"])
    r = 1.1
    formula = 1.7 * (2 / 15 * (0.9 / r) ** 9 - (0.9 / r) ** 3) - 1.7 * (2 / 15 * (0.9 / 2.2) ** 9 - (0.9 / 2.2) ** 3)
    assert at_distance(sim, r)[0] == pytest.approx(formula, rel=1e-12)


def test_near_a_block_corner_each_face_within_the_cutoff_pushes():
    sim = one_particle("harmonic 2.0 1.0 1.5", region="region ball block -3 3 -3 3 -3 3 units box",
                       at=(2.0, 2.5, -2.2))
    # faces xhi at 1.0, yhi at 0.5, zlo at 0.8: each within 1.5, each pushes inward
    expected = np.array([-2 * 2.0 * (1.5 - 1.0), -2 * 2.0 * (1.5 - 0.5), 2 * 2.0 * (1.5 - 0.8)])
    np.testing.assert_allclose(sim.f[0], expected, rtol=1e-12)
    fix = sim.fixes["w"]
    np.testing.assert_allclose(fix.vector(sim), -expected, rtol=1e-12)
    assert fix.scalar(sim) == pytest.approx(2.0 * (0.5 ** 2 + 1.0 ** 2 + 0.7 ** 2))


def test_a_region_with_side_out_is_a_wall_from_outside():
    sim = one_particle("harmonic 2.0 1.0 1.5", region="region ball sphere 0 0 0 2.0 side out units box",
                       at=(0.0, 0.0, 3.0))
    np.testing.assert_allclose(sim.f[0], [0.0, 0.0, 2 * 2.0 * (1.5 - 1.0)], atol=1e-14)


def test_a_particle_outside_the_region_stops_the_run():
    sim = one_particle(LAWS["lj93"])
    sim.x[0] = (0.0, 0.0, 5.5)
    with pytest.raises(ScriptError) as error:
        sim.command("run 0")
    assert str(error.value) == ("<command>:1: run: fix w (wall/region): particle 1 is on or outside the surface of "
                                "region ball at step 0 (position 0, 0, 5.5)")


@pytest.mark.parametrize("line, message", [
    ("fix w all wall/region ball lj1043 1 1 2", "law must be one of 'lj93', 'lj126', 'colloid' or 'harmonic' (got lj1043)"),
    ("fix w all wall/region ball lj93 1 1 0", "cutoff must be > 0 (got 0)"),
    ("fix w all wall/region nowhere lj93 1 1 2", "region nowhere is not defined (defined: box, ball)"),
    ("fix w all wall/region ball colloid 1 1 2",
     "fix w wall/region colloid needs finite-size particles (atom_style sphere)"),
])
def test_bad_lines(line, message):
    sim = Simulation(screen=False, log=None)
    sim.command("units lj\nboundary f f f\nregion box block -6 6 -6 6 -6 6\ncreate_box 1 box\n"
                "region ball sphere 0 0 0 5.0 units box")
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert str(error.value) == f"<command>:1: fix: {message}"
