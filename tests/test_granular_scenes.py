"""Granular scenes end to end (issue 4): a bed of 4,000 spheres settles to rest in a box, and the
same bed drains from an STL hopper. Minutes of run time each: behind the `slow` marker, run by
benchmarks, not by `make test`."""

import pathlib

import numpy as np
import pytest

from pdps_core.api import Simulation

HOPPER = pathlib.Path(__file__).parents[1] / "examples" / "hopper" / "hopper.stl"

MATERIAL = """
pair_style dem/lsd 0.5 1.0
pair_coeff * * 200000.0 25.0 57142.857 12.5 0.5
neighbor 0.2 bin
neigh_modify delay 0 every 1 check yes
timestep 0.0001
fix grav all gravity 1.0 vector 0 0 -1
fix 1 all nve/sphere
"""


def kinetic_energy(sim):
    p = sim.particles
    n = p.nlocal
    inertia = 0.4 * p.rmass[:n] * p.radius[:n] ** 2
    return 0.5 * float((p.rmass[:n] * (p.v[:n] ** 2).sum(axis=1)).sum()
                       + (inertia * (p.omega[:n] ** 2).sum(axis=1)).sum())


def largest_overlap(sim):
    p, nlist = sim.particles, sim.pair_list
    worst = 0.0
    for i in range(p.nlocal):
        js = nlist.neighbors[nlist.offsets[i]:nlist.offsets[i + 1]]
        if len(js):
            r = np.linalg.norm(p.x[js] - p.x[i], axis=1)
            worst = max(worst, float((p.radius[i] + p.radius[js] - r).max()))
    return worst


@pytest.mark.slow
def test_a_poured_bed_of_4000_spheres_settles_to_rest_inside_its_box():
    sim = Simulation(screen=False, log=None)
    sim.command("""
        particle_style sphere
        boundary f f f
        region box block 0 22.2 0 22.2 0 40
        create_box 1 box
        lattice spacing x 1.1 y 1.1 z 1.1
        region pour block 0.6 21.6 0.6 21.6 2 13
        create_particle 1 region pour diameter 1.0 density 1.9098593
        velocity all create 0.5 99 gaussian
        region walls block 0 22.2 0 22.2 0 40
        fix w all wall/dem lsd region walls 0.5 200000.0 50.0 57142.857 25.0 0.5 0.5
    """ + MATERIAL)
    assert sim.nlocal == 4000
    peak, history = kinetic_energy(sim), []
    for _ in range(60):
        sim.command("run 5000")
        energy = kinetic_energy(sim)
        peak = max(peak, energy)
        history.append(energy)
        if energy < 1e-6 * peak:
            break
    assert history[-1] < 1e-6 * peak, f"kinetic energy {history[-1]:.3g} vs peak {peak:.3g}"
    assert sim.nlocal == 4000                                   # nobody left (f walls would error)
    inside = sim.box.inside(sim.x) & (sim.x[:, 2] > 0.0)
    assert inside.all()
    assert largest_overlap(sim) < 0.01 * 1.0                     # below 1 % of a diameter


@pytest.mark.slow
def test_the_bed_drains_from_the_stl_hopper_through_its_outlet():
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        particle_style sphere
        boundary f f f
        region box block -12 12 -12 12 -30 32
        create_box 1 box
        lattice spacing x 1.1 y 1.1 z 1.1
        region fill block -9 9 -9 9 12 29
        create_particle 1 region fill diameter 1.0 density 1.9098593
        region floor block -12 12 -12 12 -30 32
        fix hopper all wall/mesh file {HOPPER} model lsd 0.5 200000.0 50.0 57142.857 25.0 0.5
        fix w all wall/dem lsd region floor 0.5 200000.0 50.0 57142.857 25.0 0.5 0.5
    """ + MATERIAL.replace("timestep 0.0001", "timestep 0.0002"))
    total = sim.nlocal
    below = []
    for _ in range(20):                         # 20 time units
        sim.command("run 5000")
        below.append(int((sim.x[:, 2] < 0.0).sum()))
    # an 8-diameter outlet discharges steadily (Beverloo: ~70 spheres per time unit once flowing)
    assert below[-1] > 500, below
    assert all(b2 >= b1 for b1, b2 in zip(below, below[1:]))
    assert total - below[-1] > 0                # still draining, not a wall that let all through
