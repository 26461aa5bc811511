"""Test fixes and helpers for the DEM pair styles: a velocity-Verlet integrator for spheres (so the
tests need no other plugin), a constant load, and a recorder of forces and state in tag order. Tests
reach the helpers through the ``dem`` fixture."""

import math
import types

import numpy as np
import pytest

from pdps_core.api import Fix, Simulation, StyleArgs, keyword, registry


class SphereVerlet(Fix):
    """Velocity Verlet for x, v and omega of solid spheres (I = 2/5 m r^2); ``rotate no`` keeps
    omega fixed, ``translate no`` keeps x and v fixed."""
    name = "test/dem/nve_sphere"

    class Args(StyleArgs):
        rotate: bool = keyword(True)
        translate: bool = keyword(True)

    def initial_integrate(self, sim):
        self.kick(sim)
        p = sim.particles
        chosen = sim.groups.select(sim, self.group)
        if self.args.translate:
            p.x[: p.nlocal][chosen] += sim.dt * p.v[: p.nlocal][chosen]

    def final_integrate(self, sim):
        self.kick(sim)

    def kick(self, sim):
        p, n = sim.particles, sim.particles.nlocal
        chosen = sim.groups.select(sim, self.group)
        mass = p.rmass[:n][chosen]
        if self.args.translate:
            p.v[:n][chosen] += 0.5 * sim.dt * p.f[:n][chosen] / mass[:, None]
        if self.args.rotate:
            inertia = 0.4 * mass * p.radius[:n][chosen] ** 2
            p.omega[:n][chosen] += 0.5 * sim.dt * p.torque[:n][chosen] / inertia[:, None]


class Load(Fix):
    """A constant force on every particle of the group (also at setup, so the first kick has it)."""
    name = "test/dem/load"

    class Args(StyleArgs):
        fx: float
        fy: float
        fz: float

    def setup(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        chosen = sim.groups.select(sim, self.group)
        sim.f[chosen] += [self.args.fx, self.args.fy, self.args.fz]


class Record(Fix):
    """Per step, in tag order: pair forces and torques with the positions they were computed at
    (post_force; define this fix before any load), and x (unwrapped), v, omega after the step; also
    which particle's list held each ghost pair."""
    name = "test/dem/record"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.forces, self.torques, self.at = [], [], []
        self.x, self.v, self.omega = [], [], []
        self.ghost_listers = []

    def post_force(self, sim):
        order = np.argsort(sim.tag)
        self.forces.append(sim.f[order].copy())
        self.torques.append(sim.particles.torque[: sim.nlocal][order].copy())
        self.at.append(unwrapped(sim))
        nlist, nlocal = sim.pair_list, sim.nlocal
        listers = set()
        for i in range(nlocal):
            if (nlist.neighbors[nlist.offsets[i]:nlist.offsets[i + 1]] >= nlocal).any():
                listers.add(int(sim.tag[i]))
        self.ghost_listers.append(listers)

    def end_of_step(self, sim):
        order = np.argsort(sim.tag)
        self.x.append(unwrapped(sim))
        self.v.append(sim.v[order].copy())
        self.omega.append(sim.particles.omega[: sim.nlocal][order].copy())


def unwrapped(sim):
    """Positions x + image * L in tag order."""
    p = sim.particles
    x = sim.x + p.image[: p.nlocal] * sim.box.length
    return x[np.argsort(sim.tag)]


def spheres(pair, coeffs, particles, box="0 10 0 10 0 10", boundary="p p p", ntypes=1, extra=""):
    """A simulation of spheres given as (type, x, y, z, diameter, density) with the pair style."""
    sim = Simulation(screen=False, log=None)
    lines = [f"units lj", f"boundary {boundary}", "particle_style sphere",
             f"region box block {box}", f"create_box {ntypes} box"]
    lines += [f"create_particle {t} single {x} {y} {z} diameter {d} density {rho}"
              for t, x, y, z, d, rho in particles]
    lines += [f"pair_style {pair}"] + [f"pair_coeff {c}" for c in coeffs]
    sim.command("\n".join(lines) + "\n" + extra)
    return sim


def set_motion(sim, tag, v=(0.0, 0.0, 0.0), omega=(0.0, 0.0, 0.0)):
    i = sim.particles.index_of_tag(tag)
    sim.v[i] = v
    sim.particles.omega[i] = omega


def sphere_mass(diameter, density):
    return density * math.pi / 6.0 * diameter ** 3


def angular_momentum(x, v, omega, mass, radius):
    """Total angular momentum about the origin: sum x cross m v + 2/5 m r^2 omega."""
    return (np.cross(x, mass[:, None] * v).sum(axis=0)
            + ((0.4 * mass * radius ** 2)[:, None] * omega).sum(axis=0))


@pytest.fixture
def dem():
    for style in (SphereVerlet, Load, Record):
        registry.register("fix", style.name, style)
    return types.SimpleNamespace(spheres=spheres, set_motion=set_motion, sphere_mass=sphere_mass,
                                 angular_momentum=angular_momentum, unwrapped=unwrapped)
