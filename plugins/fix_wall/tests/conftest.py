"""In-process test styles for the wall tests, so they need no integrator or gravity plugin:

- ``test/wall_nve_sphere [rotate yes|no]``: velocity Verlet for x, v and (unless ``rotate no``) the
  spin omega of solid spheres, I = 2/5 m r^2 (LAMMPS's fix nve/sphere);
- ``test/wall_gravity GX GY GZ``: the force m g on every particle of the group (also at setup, so the
  first half-kick sees it);
- ``test/wall_record``: x, v, omega, f and torque of every particle (by tag) after each step.
"""

import os
from typing import Literal

import numpy as np
import pytest

from pdps_core.api import Fix, Simulation, StyleArgs, observables, registry

DATA = os.path.join(os.path.dirname(__file__), "data")


class SphereVerlet(Fix):
    name = "test/wall_nve_sphere"

    class Args(StyleArgs):
        rotate: Literal["yes", "no"] = "yes"

    def _kick(self, sim):
        p = sim.particles
        n = p.nlocal
        half = 0.5 * sim.dt
        m = observables.masses(sim)
        p.v[:n] += half * p.f[:n] / m[:, None]
        if self.args.rotate == "yes":
            inertia = 0.4 * m * p.radius[:n] ** 2
            p.omega[:n] += half * p.torque[:n] / inertia[:, None]

    def initial_integrate(self, sim):
        self._kick(sim)
        p = sim.particles
        p.x[: p.nlocal] += sim.dt * p.v[: p.nlocal]

    def final_integrate(self, sim):
        self._kick(sim)


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


class Record(Fix):
    name = "test/wall_record"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.rows = {key: [] for key in ("t", "x", "v", "omega", "f", "torque")}

    def end_of_step(self, sim):
        p = sim.particles
        order = np.argsort(p.tag[: p.nlocal])
        self.rows["t"].append(sim.time)
        for key in ("x", "v", "f"):
            self.rows[key].append(p.arrays[key][order].copy())
        for key in ("omega", "torque"):
            if p.has(key):
                self.rows[key].append(p.arrays[key][order].copy())

    def series(self, key, particle=0):
        """Rows of one particle (0 = the lowest tag) over the recorded steps."""
        return np.array([row[particle] for row in self.rows[key]])


for style in (SphereVerlet, Gravity, Record):
    registry.register("fix", style.name, style)


def sphere_scene(box="-4 4 -4 4 -4 4", boundary="f f f", skin=0.1):
    """A box of spheres (particle_style sphere), no particles yet."""
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        units lj
        particle_style sphere
        boundary {boundary}
        region box block {box}
        create_box 1 box
        neighbor {skin}
    """)
    return sim


@pytest.fixture
def data():
    """The folder of the test meshes."""
    return DATA


@pytest.fixture
def scene():
    """``scene(box=..., boundary=..., skin=...)``: a new simulation of spheres (see sphere_scene)."""
    return sphere_scene
