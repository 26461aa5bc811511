"""A timestep between two neighbor list builds allocates nothing (issue 12: no allocation inside the
step, no numpy temporaries over the particles): every array a step uses is kept and grown in place.

Measured with tracemalloc, which sees numpy's arrays and numba's (its runtime allocates through
Python's raw allocator): a fix defined before every other resets the peak of traced memory at
initial_integrate, one defined after every other reads it at end_of_step. What a step leaves on top
of where it started is Python's own small objects (floats, tuples, frames: 1-3 KB measured); a
temporary over the 2,000-4,000 particles of these scenes would be 16 KB or more (one float each).
Steps that rebuild the lists may allocate (ghosts, lists and wall candidates grow, particles are
re-sorted); they are told apart and left out. The same scenes run on two ranks as well, where ghosts
and contact springs travel in messages between the ranks.
"""

import subprocess
import sys
import tracemalloc
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Fix, Simulation
from pdps_core.testing import mpiexec, register_styles

# Python's own objects in one step (measured: 1.3-2.7 KB on the scenes below); a float per
# particle is 16 KB at 2,000 particles
STEP_LIMIT = 6 * 1024


class OpenStep(Fix):
    """Defined first: resets tracemalloc's peak as the step starts."""
    name = "test/alloc_open"

    def initial_integrate(self, sim):
        tracemalloc.reset_peak()
        self.start = tracemalloc.get_traced_memory()[0]


class CloseStep(Fix):
    """Defined last: the step's peak of traced memory above its start, and whether it rebuilt."""
    name = "test/alloc_close"

    def init_run(self, sim):
        self.steps = []

    def end_of_step(self, sim):
        peak = tracemalloc.get_traced_memory()[1]
        self.steps.append((sim.neighbor.ago == 0, peak - sim.fixes["open"].start))


class EveryStepAllocates(Fix):
    """A fix that makes a temporary over the owned particles at every step (the negative control)."""
    name = "test/alloc_temporary"

    def post_force(self, sim):
        sim.f[:] += np.zeros(sim.nlocal)[:, None]


SPHERES = """
particle_style  sphere
units           lj
boundary        p p f
region          box block 0 16 0 16 0 12
create_box      1 box
lattice         spacing x 1.05 y 1.05 z 1.05
region          fill block 0 16 0 16 0.45 8.5
create_particle 1 region fill diameter 1.0 density 1.9098593
neighbor        0.2 bin
neigh_modify    delay 0 every 1 check yes
timestep        0.0002
"""

SCENES = {
    # LAMMPS's granular pair and wall with LIGGGHTS-style gravity: gran_box's styles
    "gran/hooke/history, wall/gran": SPHERES + """
fix             open all test/alloc_open
pair_style      gran/hooke/history 200000.0 NULL 50.0 NULL 0.5 1
pair_coeff      * *
fix             grav all gravity 1.0 vector 0 0 -1
fix             w all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 12.0
fix             1 all nve/sphere
""",
    # PDPS's DEM pair and walls: a block floor and a polygon shelf (two regions: their contacts merged)
    "dem/lsd, wall/dem": SPHERES + """
fix             open all test/alloc_open
pair_style      dem/lsd 0.5 1.0
pair_coeff      * * 200000.0 25.0 57142.857 12.5 0.5
fix             grav all gravity 1.0 vector 0 0 -1
region          floor block -1 17 -1 17 0 12
region          shelf polygon p1 2 2 4 p2 8 2 4 p3 8 8 4 p4 2 8 4
fix             walls all wall/dem lsd region floor region shelf 0.5 200000.0 50.0 57142.857 25.0 0.5 0.5
fix             1 all nve/sphere
""",
    # LAMMPS's pair granular (JKR necks beyond touching, rolling and twisting history) and its walls,
    # the spheres of a lattice pressed together so that their contacts are made before the steps measured
    "granular, wall/gran granular, wall/gran/region": SPHERES.replace("spacing x 1.05 y 1.05 z 1.05",
                                                                      "spacing x 0.99 y 0.99 z 0.99") + """
fix             open all test/alloc_open
pair_style      granular
pair_coeff      * * jkr 1.0e5 500.0 0.3 2.0 tangential mindlin NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 twisting marshall
fix             grav all gravity 1.0 vector 0 0 -1
fix             w all wall/gran granular hertz/material 1.0e5 0.5 0.3 damping coeff_restitution tangential mindlin NULL 1.0 0.5 zplane 0.0 12.0
region          cup block 0.0 16.0 0.0 16.0 -1.0 13.0 units box
fix             c all wall/gran/region granular hooke 2.0e5 50.0 damping mass_velocity tangential linear_history 5.7e4 0.5 0.4 region cup
fix             1 all nve/sphere
""",
    # a DPD fluid whose lists live one step: forces from the cell bins (direct mode)
    "dpd, direct mode": """
units           lj
region          box block 0 10 0 10 0 10
create_box      1 box
create_particle 1 random 3000 4567 box
mass            1 1.0
pair_style      dpd 1.0 1.0 34387
pair_coeff      * * 25.0 4.5 1.0
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
velocity        all create 1.0 4928459
comm_modify     vel yes
timestep        0.04
fix             open all test/alloc_open
fix             1 all nve
""",
    # LAMMPS's in.lj: lj/cut on a half list rebuilt every 20 steps
    "lj/cut": """
units           lj
lattice         fcc 0.8442
region          box block 0 10 0 10 0 10
create_box      1 box
create_particle 1 box
mass            1 1.0
velocity        all create 3.0 87287
pair_style      lj/cut 2.5
pair_coeff      1 1 1.0 1.0 2.5
neighbor        0.3 bin
neigh_modify    every 20 delay 0 check no
fix             open all test/alloc_open
fix             1 all nve
""",
}

# Shardlow's splitting: the sweep's pairs from the list read in direct mode at every step; on several
# ranks pairs and velocities travel in messages (send_rows with kept buffers)
SCENES["dpd/fdt, fix shardlow"] = SCENES["dpd, direct mode"].replace(
    "pair_style      dpd 1.0 1.0 34387", "pair_style      dpd/fdt 1.0 1.0 34387").replace(
    "fix             1 all nve", "fix             1 all shardlow\nfix             2 all nve")


def step_allocations(script, warm=100, steps=200):
    """(peaks of the steps that built no list, peaks of those that did), in bytes, over ``steps``
    steps after ``warm`` (arrays sized by the first steps, kernels loaded)."""
    register_styles(OpenStep, CloseStep, EveryStepAllocates)
    sim = Simulation(screen=False, log=None)
    sim.command(script + "fix close all test/alloc_close\nthermo 0\n")
    sim.command(f"run {warm}")
    tracemalloc.start()
    try:
        sim.command(f"run {steps}")
    finally:
        tracemalloc.stop()
    steps = sim.fixes["close"].steps
    return [peak for built, peak in steps if not built], [peak for built, peak in steps if built]


@pytest.mark.parametrize("scene", SCENES)
def test_a_step_between_list_builds_allocates_nothing(scene):
    plain, built = step_allocations(SCENES[scene])
    print(f"{scene}: {len(plain)} steps without a build, largest {max(plain) / 1024:.1f} KB; "
          f"{len(built)} builds, largest {max(built, default=0) / 1024:.1f} KB")
    assert len(plain) >= 50
    assert max(plain) < STEP_LIMIT


def test_a_temporary_over_the_particles_is_seen():
    """The negative control: a fix adding np.zeros(nlocal) at every step is measured above the limit."""
    script = SCENES["lj/cut"].replace("fix             1 all nve", "fix 1 all nve\nfix t all test/alloc_temporary")
    plain, _ = step_allocations(script, warm=10, steps=40)
    assert min(plain) > 4 * STEP_LIMIT


# The scenes of this file on two ranks, each rank measuring its own steps: ghosts refreshed and
# forces summed back through messages, springs of contacts across the cut sent back to their owners.
RANKS_DRIVER = """
import sys
from mpi4py import MPI
sys.path.insert(0, sys.argv[1])
from test_step_allocations import SCENES, step_allocations
world = MPI.COMM_WORLD
for name, script in SCENES.items():
    plain, _ = step_allocations(script)
    for rank, steps, peak in world.gather((world.rank, len(plain), max(plain)), root=0) or []:
        print(f"{rank}|{name}|{steps}|{peak}", flush=True)
"""


def test_a_step_between_list_builds_allocates_nothing_on_2_ranks(tmp_path):
    (tmp_path / "driver.py").write_text(RANKS_DRIVER)
    done = subprocess.run([mpiexec(), "-n", "2", sys.executable, "driver.py", str(Path(__file__).parent)],
                          cwd=tmp_path, capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stderr
    measured = [line.split("|") for line in done.stdout.splitlines() if line.count("|") == 3]
    print("\n".join(f"rank {rank}, {name}: {steps} steps without a build, largest {int(peak) / 1024:.1f} KB"
                    for rank, name, steps, peak in measured))
    assert sorted((rank, name) for rank, name, _, _ in measured) == sorted(
        (str(rank), name) for rank in (0, 1) for name in SCENES)
    for rank, name, steps, peak in measured:
        assert int(steps) >= 50
        assert int(peak) < STEP_LIMIT, (rank, name)
