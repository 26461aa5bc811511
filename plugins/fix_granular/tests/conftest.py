"""In-process test styles (a torque, an overlap repulsion, a pair style with time-step limits; the
kit's test/force, test/record and test/no_force, which has none) and fixtures that build a small scene."""

import io

import numpy as np
import pytest

from pdps_core.api import Fix, StyleArgs
from pdps_core.testing import ConstantForce, NoForcePair, Record, make_box, register_styles


class ConstantTorque(Fix):
    """Adds a constant torque to its group, at setup and every step."""
    name = "test/granular/torque"

    class Args(StyleArgs):
        tx: float
        ty: float
        tz: float

    def setup(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        p.torque[: p.nlocal][sim.groups.select(sim, self.group)] += [self.args.tx, self.args.ty,
                                                                     self.args.tz]


class OverlapRepulsion(Fix):
    """A stiff harmonic repulsion between overlapping spheres, F = K (R_i + R_j - r) along the line
    of centres (all pairs of owned particles; the scenes are tiny and not periodic)."""
    name = "test/granular/overlap"

    class Args(StyleArgs):
        stiffness: float

    def setup(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        x, radius = p.x[:n], p.radius[:n]
        for i in range(n):
            for j in range(i + 1, n):
                delta = x[i] - x[j]
                r = float(np.linalg.norm(delta))
                overlap = radius[i] + radius[j] - r
                if overlap > 0:
                    force = self.args.stiffness * overlap * delta / r
                    p.f[i] += force
                    p.f[j] -= force


class LimitsPair(NoForcePair):
    """No forces; reports the time-step limits it was given (``pair_style test/granular/limits
    RAYLEIGH HERTZ CONTACT``, 0 meaning none). ``shrink`` makes the Rayleigh time
    RAYLEIGH / (1 + shrink * step), to see a limit passed in the middle of a run."""
    name = "test/granular/limits"

    class Args(StyleArgs):
        rayleigh: float
        hertz: float
        contact: float
        shrink: float = 0.0

    def timestep_limits(self, sim, at_least=0.0):
        a = self.args
        rayleigh = a.rayleigh / (1.0 + a.shrink * sim.step)
        return {"rayleigh": rayleigh or None, "hertz": a.hertz or None, "contact": a.contact}


register_styles(ConstantForce, ConstantTorque, OverlapRepulsion, Record, LimitsPair, NoForcePair)


@pytest.fixture
def spheres(tmp_path, monkeypatch):
    """``spheres(particles, dimension=3, box=..., boundary=...)``: a Simulation with particle_style
    sphere and one particle type; ``particles`` is script text (create_particle ...).
    ``sim.output.screen.getvalue()`` is what it printed."""
    monkeypatch.chdir(tmp_path)

    def make(particles, dimension=3, box="-20 20 -20 20 -20 20", boundary="f f f", ntypes=1):
        if dimension == 2:
            box = " ".join(box.split()[:4]) + " -0.5 0.5"
            boundary = " ".join(boundary.split()[:2]) + " p"
        return make_box(particles, box=box, boundary=boundary, ntypes=ntypes, particle_style="sphere",
                        dimension=dimension, screen=io.StringIO())
    return make


@pytest.fixture
def make_plain(tmp_path, monkeypatch):
    """A silent Simulation of two point particles (particle_style atomic) in a fixed 10^3 box."""
    monkeypatch.chdir(tmp_path)

    def make():
        return make_box("""
            mass 1 2.0
            create_particle 1 single 2 2 2
            create_particle 1 single 7 7 7
        """, boundary="f f f")
    return make
