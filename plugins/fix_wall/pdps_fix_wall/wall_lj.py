r"""Fixes ``wall/lj93`` and ``wall/lj126``: flat Lennard-Jones walls on box faces (LAMMPS's fix
wall/lj93 and wall/lj126), the two members of one family that differ only in the law.

For a particle at distance :math:`r` from a wall (measured into the box), :math:`r < r_c`:

.. math::

    E_{93} = \varepsilon\left[\tfrac{2}{15}\left(\tfrac{\sigma}{r}\right)^{9}
             - \left(\tfrac{\sigma}{r}\right)^{3}\right] - E_{93}(r_c), \qquad
    F_{93} = \varepsilon\left[\tfrac{6}{5}\tfrac{\sigma^9}{r^{10}} - 3\tfrac{\sigma^3}{r^4}\right]

    E_{126} = 4\varepsilon\left[\left(\tfrac{\sigma}{r}\right)^{12}
              - \left(\tfrac{\sigma}{r}\right)^{6}\right] - E_{126}(r_c), \qquad
    F_{126} = \varepsilon\left[48\tfrac{\sigma^{12}}{r^{13}} - 24\tfrac{\sigma^6}{r^7}\right]

(F away from the wall; lj93 is the 12-6 potential integrated over a half space of particles, Magda,
Tirrell and Davis, J. Chem. Phys. 83, 1888 (1985); energies shifted to 0 at the cutoff, as LAMMPS).
A particle on or behind a wall stops the run, as LAMMPS's "Particle on or inside fix wall surface".

Thermo: ``f_ID`` is the walls' total energy, ``f_ID[k]`` the force on wall k (from the dialect's first
index, in the order given). ``fix_modify ID energy yes`` adds the energy to ``pe``, ``fix_modify ID
virial yes`` the walls' virial (r . f relative to the wall) to ``press``; both off by default, as in
LAMMPS.

Parameters, for each wall: ``face`` (xlo, xhi, ylo, yhi, zlo, zhi), ``coord`` (EDGE: the box face
now; a number; or v_NAME: an equal-style variable evaluated every step, so a wall can move),
``epsilon`` (energy), ``sigma`` (distance), ``cutoff`` (> 0, distance). ``units lattice`` (LAMMPS's
default) multiplies numeric and variable coords by the lattice spacing (1 when no lattice is
defined); ``units box`` takes them as they are. A wall stands on a non-periodic axis unless ``pbc
yes`` says it is meant to be inside a periodic one.

Syntax (LAMMPS's)::

    fix ID GROUP wall/lj93 face coord epsilon sigma cutoff [face ...] [units box|lattice] [pbc yes|no]
    fix ID GROUP wall/lj126 face coord epsilon sigma cutoff [face ...] [units box|lattice] [pbc yes|no]

Example::

    fix walls all wall/lj93 zlo EDGE 1.0 1.0 2.5 zhi EDGE 1.0 1.0 2.5 units box
    fix_modify walls energy yes virial yes
"""

import math
from typing import Literal, NamedTuple

import numpy as np
from numba import njit
from pydantic import model_validator

from pdps_core.api import Fix, FloatOrVariable, ScriptError, StyleArgs, VariableRef, keyword, param

from .faces import FACES, Face, check_walls


class Wall(NamedTuple):
    face: Face
    coord: FloatOrVariable | Literal["EDGE"]
    epsilon: float
    sigma: float
    cutoff: float

LJ93, LJ126 = 0, 1


@njit(cache=True)
def lj_wall(x, f, mask, groupbit, nlocal, axis, lower, coord, law, c1, c2, c3, c4, offset, cutoff, virial):
    """One wall's forces added to f; returns (energy, force on the wall, a particle on or behind it
    or -1); the virial (LAMMPS's v_tally of -F d) accumulates into ``virial[axis]``."""
    energy = 0.0
    fsum = 0.0
    side = -1.0 if lower else 1.0
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        delta = x[i, axis] - coord if lower else coord - x[i, axis]
        if delta >= cutoff:
            continue
        if delta <= 0.0:
            return energy, fsum, i
        rinv = 1.0 / delta
        r2inv = rinv * rinv
        if law == LJ93:
            r4inv = r2inv * r2inv
            r10inv = r4inv * r4inv * r2inv
            fwall = side * (c1 * r10inv - c2 * r4inv)
            energy += c3 * r4inv * r4inv * rinv - c4 * r2inv * rinv - offset
        else:
            r6inv = r2inv * r2inv * r2inv
            fwall = side * r6inv * (c1 * r6inv - c2) * rinv
            energy += r6inv * (c3 * r6inv - c4) - offset
        f[i, axis] -= fwall
        fsum += fwall
        virial[axis] += -fwall * delta if lower else fwall * delta
    return energy, fsum, -1


class WallLJ(Fix):
    """What wall/lj93 and wall/lj126 share: the walls, their coords, the tallies."""
    law = LJ93
    can_energy = True
    can_virial = True
    extensive = True

    class Args(StyleArgs):
        wall: list[Wall] = param(min_length=1, unit=("1", "distance", "energy", "distance", "distance"))
        units: Literal["box", "lattice"] = keyword("lattice")
        pbc: Literal["yes", "no"] = keyword("no")

        @model_validator(mode="after")
        def _walls(self):
            check_walls(self.wall)
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box(f"fix {self.name}")
        self.units, pbc = args.units, args.pbc == "yes"
        walls = {face: tuple(values) for face, *values in args.wall}
        for face in walls:
            axis = FACES.index(face) // 2
            if axis == 2 and sim.dimension == 2:
                raise ScriptError(f"wall {face} in a 2-d simulation")
            if sim.box.periodic[axis] and not pbc:
                raise ScriptError(f"wall {face} stands on the periodic {'xyz'[axis]} axis: make it fixed "
                                  "(boundary f) or say pbc yes")
        self.walls = list(walls.items())
        # EDGE is the face where the fix is defined (LAMMPS reads boxlo/boxhi once)
        self.edges = [float((sim.box.lo if face.endswith("lo") else sim.box.hi)[FACES.index(face) // 2])
                      for face, _ in self.walls]
        self.coefficients = [self.coefficients_of(eps, sigma, cutoff) for _, (_, eps, sigma, cutoff) in self.walls]
        self.wall_energy = 0.0
        self.wall_forces = np.zeros(len(self.walls))
        self.wall_virial = np.zeros(6)

    def _coord(self, sim, k):
        face, (coord, *_) = self.walls[k]
        axis = FACES.index(face) // 2
        if coord == "EDGE":
            return self.edges[k]
        spacing = sim.lattice.spacing[axis] if (self.units == "lattice" and sim.lattice is not None) else 1.0
        if isinstance(coord, VariableRef):
            if coord.name not in sim.variables:
                raise ScriptError(f"fix {self.id} {self.name}: variable {coord.name} is not defined (coord {coord})")
            coord = float(sim.variables.value(coord.name))
        return coord * float(spacing)

    def setup(self, sim):
        self.post_force(sim)

    def min_post_force(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        groupbit = sim.groups.bit(self.group)
        self.wall_energy = 0.0
        self.wall_virial[:] = 0.0
        message = None
        for k, (face, (_, _, _, cutoff)) in enumerate(self.walls):
            c1, c2, c3, c4, offset = self.coefficients[k]
            energy, force, inside = lj_wall(p.x, p.f, p.mask, groupbit, p.nlocal, FACES.index(face) // 2,
                                            face.endswith("lo"), self._coord(sim, k), self.law, c1, c2, c3, c4,
                                            offset, cutoff, self.wall_virial)
            self.wall_energy += energy
            self.wall_forces[k] = force
            if inside >= 0 and message is None:
                message = (f"fix {self.id} ({self.name}): particle {int(p.tag[inside])} is on or behind wall "
                           f"{face} at step {sim.step} (position {', '.join(f'{c:.6g}' for c in p.x[inside])})")
        sim.comm.agree(message)

    def energy(self, sim):
        return self.wall_energy

    def virial(self, sim):
        return self.wall_virial

    def scalar(self, sim):
        """The walls' total energy (f_ID), summed over ranks."""
        return float(sim.comm.sum(self.wall_energy))

    def vector(self, sim):
        """The force on each wall (f_ID[k]), summed over ranks."""
        return np.asarray(sim.comm.sum(self.wall_forces.copy()))


class FixWallLJ93(WallLJ):
    name = "wall/lj93"
    usage = "fix ID GROUP wall/lj93 face coord epsilon sigma cutoff [face ...] [units box|lattice] [pbc yes|no]"
    law = LJ93

    @staticmethod
    def coefficients_of(epsilon, sigma, cutoff):
        c1 = 6.0 / 5.0 * epsilon * math.pow(sigma, 9.0)
        c2 = 3.0 * epsilon * math.pow(sigma, 3.0)
        c3 = 2.0 / 15.0 * epsilon * math.pow(sigma, 9.0)
        c4 = epsilon * math.pow(sigma, 3.0)
        rinv = 1.0 / cutoff
        r2inv = rinv * rinv
        r4inv = r2inv * r2inv
        return c1, c2, c3, c4, c3 * r4inv * r4inv * rinv - c4 * r2inv * rinv


class FixWallLJ126(WallLJ):
    name = "wall/lj126"
    usage = "fix ID GROUP wall/lj126 face coord epsilon sigma cutoff [face ...] [units box|lattice] [pbc yes|no]"
    law = LJ126

    @staticmethod
    def coefficients_of(epsilon, sigma, cutoff):
        c1 = 48.0 * epsilon * math.pow(sigma, 12.0)
        c2 = 24.0 * epsilon * math.pow(sigma, 6.0)
        c3 = 4.0 * epsilon * math.pow(sigma, 12.0)
        c4 = 4.0 * epsilon * math.pow(sigma, 6.0)
        r2inv = 1.0 / (cutoff * cutoff)
        r6inv = r2inv * r2inv * r2inv
        return c1, c2, c3, c4, r6inv * (c3 * r6inv - c4)

