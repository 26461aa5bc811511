"""Granular hard cases (issue 4): spheres created fully overlapping separate under nve/limit without
blowing up; a sphere hitting a wall at 100x the usual speed either bounces or is named in a warning
from the timestep check, never passes through silently."""

import io

import numpy as np
import pytest

from pdps_core.api import Simulation, SimulationError

MATERIAL = """
pair_style dem/lsd 0.5 1.0
pair_coeff * * 200000.0 25.0 57142.857 12.5 0.5
neighbor 0.2 bin
timestep 0.0001
"""


def test_fully_overlapping_spheres_separate_under_nve_limit():
    sim = Simulation(screen=False, log=None)
    sim.command("""
        particle_style sphere
        boundary p p p
        region box block 0 8 0 8 0 8
        create_box 1 box
        create_particle 1 single 4.0 4.0 4.0 diameter 1.0 density 1.9098593
        create_particle 1 single 4.0 4.0 4.0 diameter 1.0 density 1.9098593
        create_particle 1 single 4.05 4.0 4.0 diameter 1.0 density 1.9098593
        create_particle 1 single 4.0 4.1 4.02 diameter 1.0 density 1.9098593
    """ + MATERIAL + "fix 1 all nve/limit 0.001\nrun 4000")
    x = sim.x
    assert np.isfinite(x).all() and np.isfinite(sim.v).all()
    distances = [np.linalg.norm(x[i] - x[j]) for i in range(4) for j in range(i + 1, 4)]
    # two particles created at the same point have no normal and stay together (r = 0 is skipped);
    # every pair with a direction has been pushed out to contact distance or beyond
    separated = [d for d in distances if d > 1e-9]
    assert len(separated) >= 5 and min(separated) > 0.95
    assert np.abs(sim.v).max() < 0.001 / 0.0001 + 1e-9          # the cap held every step


def impact(speed):
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None)
    sim.command(f"""
        particle_style sphere
        boundary p p f
        region box block 0 8 0 8 0 20
        create_box 1 box
        create_particle 1 single 4.0 4.0 3.0 diameter 1.0 density 1.9098593
        velocity all set 0 0 -{speed}
        region floor block INF INF INF INF 0 20
        fix w all wall/dem lsd region floor 0.5 200000.0 50.0 57142.857 25.0 0.5 0.5
        fix 1 all nve/sphere
        fix check all check/timestep/gran 1 0.2 0.2
    """ + MATERIAL)
    return sim, int(4.0 / speed / 0.0001)                         # time to reach the floor twice over


@pytest.mark.parametrize("speed", [1.0, 100.0])
def test_an_impact_at_up_to_100x_the_usual_speed_bounces_off_the_wall(speed):
    sim, steps = impact(speed)
    sim.command(f"run {steps}")
    assert sim.v[0, 2] > 0.0 and sim.x[0, 2] > 0.5               # on its way back up, never through
    assert not [w for w in sim.warnings if "check/timestep/gran" in w]


def test_an_impact_too_fast_for_the_contact_stiffness_stops_with_a_clear_error():
    # at 1000x the linear spring cannot stop the sphere within its radius (v sqrt(m/kn) = 2.2 > 0.5):
    # it passes the wall's plane and the run stops naming it, rather than running on silently
    sim, steps = impact(1000.0)
    with pytest.raises(SimulationError) as info:
        sim.command(f"run {steps}")
    assert str(info.value).startswith("<command>:1: run: particle 1 lost through the fixed z boundary at step ")
    assert np.isfinite(sim.x).all()
