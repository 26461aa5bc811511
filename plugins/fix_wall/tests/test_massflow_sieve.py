"""fix massflow/mesh/sieve: the passage probability, the share of many spheres let through against
it and against LIGGGHTS 3.8.0's share of the same scene (recorded by
benchmarks/liggghts_references/sieve_statistics.py; binomial error bars, as the two programs draw
different numbers), the spring-dashpot of one sphere held back, and the refusals. The deterministic
scenes (probability 0: the bed bounces off the sieve; above 1: all pass, counted as massflow/mesh
counts) are LIGGGHTS's recorded cases sieve_held and sieve_pass (tests/test_recorded_thermo.py)."""

import json
import math
import os
from pathlib import Path

import pytest

from pdps_core.api import ScriptError, Simulation

RECORDED = json.loads((Path(__file__).parent / "data" / "liggghts_sieve_statistics.json").read_text())
# holes of 3 mm at 1.5 mm spacing, spheres of 2 mm
PROBABILITY = 0.78539816339 * (0.003 - 0.002) ** 2 / 0.0015 ** 2


def run(folder, script):
    (folder / "sieve.stl").write_text(RECORDED["sieve.stl"])
    (folder / "in.sieve").write_text(script)
    here = os.getcwd()
    os.chdir(folder)
    try:
        sim = Simulation(screen=False, log=None, dialect="liggghts")
        sim.file("in.sieve")
    finally:
        os.chdir(here)
    return sim


def test_the_probability_formula():
    from pdps_fix_wall.massflow_mesh_sieve import pass_probability
    assert pass_probability(0.001, 0.003, 0.0015) == pytest.approx(PROBABILITY, rel=1e-15)
    assert pass_probability(0.0015, 0.003, 0.0015) == 0.0
    assert pass_probability(0.002, 0.003, 0.0015) == 0.0


def test_the_share_let_through_is_the_probability_and_liggghts_share(tmp_path):
    """1600 spheres, each touching the sieve once: the number passed is binomial (n, P); pdps's count
    lies within 3 standard deviations of n P, LIGGGHTS's too, and the two within 3 of their
    difference's."""
    sim = run(tmp_path, RECORDED["script"])
    n = RECORDED["spheres"]
    passed = sim.fixes["sieve"].number
    sigma = math.sqrt(n * PROBABILITY * (1.0 - PROBABILITY))
    assert abs(passed - n * PROBABILITY) < 3.0 * sigma, (passed, n * PROBABILITY, sigma)
    assert abs(RECORDED["passed"] - n * PROBABILITY) < 3.0 * sigma
    assert abs(passed - RECORDED["passed"]) < 3.0 * math.sqrt(2.0) * sigma
    # every sphere has drawn: those let through crossed, the others went back up
    below = (sim.particles.x[:sim.particles.nlocal, 2] < 0.0).sum()
    assert below == passed
    assert sim.particles.nlocal == n


def one_sphere(tmp_path, words, z=0.00105, vz=-0.05):
    script = RECORDED["script"].replace(
        "region bed block -0.0475 0.0475 -0.0475 0.0475 0.0025 0.0175 units box\n"
        "lattice sc 0.005 origin 0.5 0.5 0.5\ncreate_atoms 1 region bed\n",
        f"create_atoms 1 single 0.01 0.02 {z} units box\n")
    script = script.replace("velocity all set 0.0 0.0 -1.0", f"velocity all set 0.0 0.0 {vz}")
    script = script.replace("sieveSize 0.003 sieveSpacing 0.0015 sieveStiffness 100", words)
    script = script.replace("run 2000", "run 0")
    return run(tmp_path, script)


def test_a_sphere_held_back_bounces_as_its_spring_dashpot_says(tmp_path):
    """Probability 0: one sphere at 0.05 m/s onto the sieve, k = 100, no damping: it leaves at the
    speed it came (the force depends on the position only); with damping c it leaves slower, by the
    restitution of a spring-dashpot that never pulls (Schwager and Poeschel, Phys. Rev. E 75, 051304
    (2007)), to the 1.6 % overlap that shortens LIGGGHTS's normal."""
    sim = one_sphere(tmp_path, "sieveSize 0.001 sieveSpacing 0.0015 sieveStiffness 100")
    mass = 2500 * math.pi / 6 * 0.002 ** 3
    sim.command("run 400")
    assert sim.v[0, 2] == pytest.approx(0.05, rel=1e-3)
    assert sim.fixes["sieve"].number == 0
    damping = 0.01
    sim = one_sphere(tmp_path, f"sieveSize 0.001 sieveSpacing 0.0015 sieveStiffness 100 sieveDamping {damping}")
    sim.command("run 400")
    zeta = damping / (2 * math.sqrt(100 * mass))
    root = math.sqrt(1 - zeta ** 2)
    restitution = math.exp(-zeta / root * (math.pi - math.atan(2 * zeta * root / (1 - 2 * zeta ** 2))))
    assert 0.6 < restitution < 0.7
    assert sim.v[0, 2] == pytest.approx(0.05 * restitution, rel=2e-2)


def test_a_sphere_let_through_is_counted(tmp_path):
    sim = one_sphere(tmp_path, "sieveSize 0.05 sieveSpacing 0.0015 sieveStiffness 100")
    sim.command("run 2500")
    assert sim.x[0, 2] < 0.0
    assert sim.v[0, 2] == pytest.approx(-0.05, rel=1e-12)
    assert sim.fixes["sieve"].number == 1


@pytest.mark.parametrize("words, message", [
    ("sieveSpacing 0.0015 sieveStiffness 100", "'sieveSize' is not set, larger than 100000, or less than zero"),
    ("sieveSize -1 sieveSpacing 0.0015 sieveStiffness 100",
     "'sieveSize' is not set, larger than 100000, or less than zero (got -1)"),
    ("sieveSize 0.003 sieveStiffness 100", "'sieveSpacing' is not set, larger than 100000, or less than zero"),
    ("sieveSize 0.003 sieveSpacing 0.0015", "'sieveStiffness' is not set, larger than 1e+10, or less than zero"),
    ("sieveSize 0.003 sieveSpacing 0.0015 sieveStiffness 2e10",
     "'sieveStiffness' is not set, larger than 1e+10, or less than zero (got 2e+10)"),
    ("sieveSize 0.003 sieveSpacing 0 sieveStiffness 100", "'sieveSpacing' must be > 0"),
    ("sieveSize 0.003 sieveSpacing 0.0015 sieveStiffness 100 sieveHoles 3", "sieveHoles"),
])
def test_refused_at_the_fix_line(tmp_path, words, message):
    with pytest.raises(ScriptError) as info:
        one_sphere(tmp_path, words)
    assert message in str(info.value)


def test_sieve_multisphere_can_pass_is_a_flag(tmp_path):
    sim = one_sphere(tmp_path, "sieveSize 0.05 sieveSpacing 0.0015 sieveStiffness 100 sieveMultiSphereCanPass")
    assert sim.fixes["sieve"].args.sieveMultiSphereCanPass is True
