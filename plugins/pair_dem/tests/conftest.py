"""Test styles and helpers for the DEM pair styles, reached through the ``dem`` fixture: the kit's
``test/nve_sphere`` (velocity Verlet for spheres, so the tests need no other plugin) and
``test/force`` (a constant load), and a recorder of forces and state in tag order."""

import types

import numpy as np
import pytest

from pdps_core.api import Fix
from pdps_core.testing import ConstantForce, SphereVerlet, make_box, register_styles, unwrapped


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


def spheres(pair, coeffs, particles, box="0 10 0 10 0 10", boundary="p p p", ntypes=1, extra=""):
    """A simulation of spheres given as (type, x, y, z, diameter, density) with the pair style."""
    lines = [f"create_particle {t} single {x} {y} {z} diameter {d} density {rho}"
             for t, x, y, z, d, rho in particles]
    lines += [f"pair_style {pair}"] + [f"pair_coeff {c}" for c in coeffs]
    return make_box("\n".join(lines) + "\n" + extra, box=box, boundary=boundary, ntypes=ntypes,
                    particle_style="sphere")


def set_motion(sim, tag, v=(0.0, 0.0, 0.0), omega=(0.0, 0.0, 0.0)):
    i = sim.particles.index_of_tag(tag)
    sim.v[i] = v
    sim.particles.omega[i] = omega


def angular_momentum(x, v, omega, mass, radius):
    """Total angular momentum about the origin: sum x cross m v + 2/5 m r^2 omega."""
    return (np.cross(x, mass[:, None] * v).sum(axis=0)
            + ((0.4 * mass * radius ** 2)[:, None] * omega).sum(axis=0))


@pytest.fixture
def dem():
    register_styles(SphereVerlet, ConstantForce, Record)
    return types.SimpleNamespace(spheres=spheres, set_motion=set_motion,
                                 angular_momentum=angular_momentum)
