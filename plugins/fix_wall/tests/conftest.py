"""Test styles and scenes for the wall tests, so they need no integrator or gravity plugin: the kit's
``test/nve_sphere`` (velocity Verlet for x, v and omega) and ``test/record`` (x, v, omega, f and
torque of every particle, by tag, after each step), and ``test/wall_gravity GX GY GZ``: the force
m g on every particle of the group (also at setup, so the first half-kick sees it).
"""

import os
import textwrap

import numpy as np
import pytest

from pdps_core.api import Fix, Simulation, StyleArgs, observables
from pdps_core.testing import Record, SphereVerlet, make_box, register_styles

DATA = os.path.join(os.path.dirname(__file__), "data")


class Gravity(Fix):
    name = "test/wall_gravity"

    class Args(StyleArgs):
        gx: float
        gy: float
        gz: float

    def setup(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        m = observables.masses(sim)
        p.f[: p.nlocal] += m[:, None] * np.array([self.args.gx, self.args.gy, self.args.gz])


register_styles(SphereVerlet, Gravity, Record)


def sphere_scene(box="-4 4 -4 4 -4 4", boundary="f f f", skin=0.1):
    """A box of spheres (particle_style sphere), no particles yet."""
    return make_box(f"neighbor {skin}", box=box, boundary=boundary, particle_style="sphere")


@pytest.fixture
def data():
    """The folder of the test meshes."""
    return DATA


@pytest.fixture
def scene():
    """``scene(box=..., boundary=..., skin=...)``: a new simulation of spheres (see sphere_scene)."""
    return sphere_scene


@pytest.fixture
def liggghts_granular():
    """``liggghts_granular(lines)``: a silent simulation reading LIGGGHTS's dialect, granular
    particles in lj units in a closed box, then ``lines``."""
    def make(lines):
        sim = Simulation(screen=False, log=None)
        sim.command("dialect liggghts")
        sim.command("units lj\natom_style granular\nboundary f f f\n" + textwrap.dedent(lines))
        return sim
    return make
