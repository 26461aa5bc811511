"""Particles inserted and deleted by a fix on steps it chooses: counts, globally unique ids, and
the same particles on 1 and 2 ranks."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

from pdps_core.testing import mpiexec

DRIVER = '''
import sys
import numpy as np
from pdps_core.api import Fix, Simulation, StyleArgs, registry


class FixRain(Fix):
    """Every 10 steps: 5 particles appear (drawn on rank 0, added there), and on step 50 every
    particle whose id is a multiple of 7 is removed."""
    name = "rain"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.rng = np.random.default_rng(4)

    def setup(self, sim):
        self.next_reneighbor = sim.step + 10

    def pre_exchange(self, sim):
        if sim.step != self.next_reneighbor:
            return
        x = self.rng.uniform(0.0, 10.0, size=(5, 3))
        v = self.rng.normal(size=(5, 3))
        if sim.comm.rank == 0:
            sim.add_particles(x, 1, v=v)
        else:
            sim.add_particles(np.zeros((0, 3)), 1)
        if sim.step == 50:
            p = sim.particles
            sim.delete_particles(p.tag[: p.nlocal] % 7 == 0)
        self.next_reneighbor = sim.step + 10


registry.register("fix", "rain", FixRain)
sim = Simulation(screen=False, log=None)
sim.command("""
    region box block 0 10 0 10 0 10
    create_box 1 box
    create_particle 1 random 40 77 box
    mass 1 1.0
    velocity all create 1.0 3
    pair_style lj/cut 1.0
    pair_coeff * * 0.01 0.5
    fix 1 all nve
    fix r all rain
    run 95
""")
p = sim.particles
n = p.nlocal
rows = sim.comm.gather_rows(np.column_stack([p.tag[:n], p.x[:n], p.v[:n]]))
if sim.comm.rank == 0:
    np.save(sys.argv[1], rows)
'''


@pytest.fixture(scope="module")
def finals(tmp_path_factory):
    folder = tmp_path_factory.mktemp("rain")
    (folder / "driver.py").write_text(DRIVER)
    out = {}
    for ranks in (1, 2):
        path = folder / f"rows{ranks}.npy"
        command = [sys.executable, "driver.py", str(path)]
        if ranks > 1:
            command = [mpiexec(), "-n", str(ranks)] + command
        done = subprocess.run(command, cwd=folder, capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr
        rows = np.load(path)
        out[ranks] = rows[np.argsort(rows[:, 0])]
    return out


def test_counts_and_ids_after_insertions_and_a_deletion(finals):
    rows = finals[1]
    inserted = 5 * 9                                  # steps 10, 20, ..., 90
    ids = np.arange(1, 40 + inserted + 1)
    survivors = ids[(ids % 7 != 0) | (ids > 40 + 25)]   # step 50 removed multiples of 7 up to id 65
    assert rows[:, 0].astype(int).tolist() == survivors.tolist()


def test_one_and_two_ranks_hold_the_same_particles(finals):
    one, two = finals[1], finals[2]
    assert two[:, 0].tolist() == one[:, 0].tolist()
    assert two[:, 1:] == pytest.approx(one[:, 1:], rel=1e-9, abs=1e-9)
