r"""Fix ``wall/harmonic``: flat walls that push particles back with a harmonic spring (LAMMPS's fix
wall/harmonic).

For a particle at distance :math:`d` from a wall (measured into the box) closer than the cutoff
:math:`r_c`:

.. math::

    E = \varepsilon\,(r_c - d)^2, \qquad F = 2\varepsilon\,(r_c - d) \quad\text{(away from the wall)}

``sigma`` is read and unused, as in LAMMPS. A particle on or behind a wall stops the run with an
error (the force is undefined there), as LAMMPS's "Particle on or inside fix wall surface".

Thermo: the scalar ``f_ID`` is the walls' total energy, ``f_ID[k]`` the force on wall k along its
axis (from the dialect's first index, in the order given). ``fix_modify ID energy yes`` adds it to
``pe``; ``fix_modify ID virial yes`` adds the walls' virial to ``press`` (off by default, as in
LAMMPS). The virial of a wall is tallied relative to the wall, :math:`d\,F` per particle, so a gas
held by walls on the box faces reads the pressure it exerts on them: for an ideal gas,
:math:`N k_B T / V_\mathrm{acc}`, with the accessible volume :math:`V_\mathrm{acc}` smaller than the
box by the walls' soft range (plugins/fix_wall/tests/test_harmonic.py).

Parameters, for each wall: ``face`` (xlo, xhi, ylo, yhi, zlo, zhi), ``coord`` (distance, or EDGE:
the box face), ``epsilon`` (energy/distance^2), ``sigma`` (distance, unused), ``cutoff`` (> 0,
distance). ``units lattice`` (LAMMPS's default) scales numeric coords by the lattice spacing (1 when
no lattice is defined); ``units box`` takes them as they are.

Syntax::

    fix ID GROUP wall/harmonic face coord epsilon sigma cutoff [face ...] [units box|lattice]

Example::

    fix walls all wall/harmonic zlo EDGE 50.0 1.0 1.0 zhi EDGE 50.0 1.0 1.0
    fix_modify walls virial yes
"""

from typing import Literal, NamedTuple

import numpy as np
from numba import njit
from pydantic import model_validator

from pdps_core.api import Fix, StyleArgs, keyword, param

from .faces import Face, check_walls, wall_planes


class Wall(NamedTuple):
    face: Face
    coord: float | Literal["EDGE"]
    epsilon: float
    sigma: float
    cutoff: float


@njit(cache=True)
def harmonic_walls(x, f, mask, groupbit, nlocal, axes, lower, coords, epsilon, cutoff, on_wall):
    """Adds the wall forces and each wall's force from the particles into ``on_wall``; returns
    (energy, xx, yy, zz virial, index of a particle on or behind a wall or -1)."""
    energy = 0.0
    vxx = 0.0
    vyy = 0.0
    vzz = 0.0
    for w in range(len(axes)):
        a = axes[w]
        c = coords[w]
        rc = cutoff[w]
        for i in range(nlocal):
            if not mask[i] & groupbit:
                continue
            d = x[i, a] - c if lower[w] else c - x[i, a]
            if d >= rc:
                continue
            if d <= 0.0:
                return energy, vxx, vyy, vzz, i
            push = 2.0 * epsilon[w] * (rc - d)
            f[i, a] += push if lower[w] else -push
            on_wall[w] += -push if lower[w] else push
            energy += epsilon[w] * (rc - d) * (rc - d)
            if a == 0:
                vxx += d * push
            elif a == 1:
                vyy += d * push
            else:
                vzz += d * push
    return energy, vxx, vyy, vzz, -1


class FixWallHarmonic(Fix):
    name = "wall/harmonic"
    usage = "fix ID GROUP wall/harmonic face coord epsilon sigma cutoff [face ...] [units box|lattice]"
    can_energy = True
    can_virial = True
    extensive = True        # f_ID and f_ID[k] are totals: per particle where thermo normalises (lj)

    class Args(StyleArgs):
        wall: list[Wall] = param(min_length=1, unit=("1", "distance", "energy/area", "distance", "distance"))
        units: Literal["box", "lattice"] = keyword("lattice")

        @model_validator(mode="after")
        def _walls(self):
            check_walls(self.wall)
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        walls = {face: values for face, *values in args.wall}
        units = args.units
        self.axes, self.lower, self.coords = wall_planes(
            sim, {face: values[0] for face, values in walls.items()}, units)
        self.epsilon = np.array([values[1] for values in walls.values()])
        self.cutoff = np.array([values[3] for values in walls.values()])
        self.wall_energy = 0.0
        self.wall_virial = np.zeros(6)
        self.wall_force = np.zeros(len(self.axes))

    def setup(self, sim):
        self.post_force(sim)

    def min_post_force(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        self.wall_force[:] = 0.0
        energy, vxx, vyy, vzz, inside = harmonic_walls(
            p.x, p.f, p.mask, sim.groups.bit(self.group), p.nlocal, self.axes, self.lower,
            self.coords, self.epsilon, self.cutoff, self.wall_force)
        message = None
        if inside >= 0:
            message = (f"fix {self.id} (wall/harmonic): particle {int(p.tag[inside])} is on or behind a "
                       f"wall at step {sim.step} (position {', '.join(f'{c:.6g}' for c in p.x[inside])})")
        sim.comm.agree(message)
        self.wall_energy = energy
        self.wall_virial[:3] = (vxx, vyy, vzz)

    def energy(self, sim):
        return self.wall_energy

    def virial(self, sim):
        return self.wall_virial

    def scalar(self, sim):
        """The walls' total energy (f_ID), summed over ranks."""
        return float(sim.comm.sum(self.wall_energy))

    def vector(self, sim):
        """The force on each wall along its axis (f_ID[k]), summed over ranks."""
        return np.asarray(sim.comm.sum(self.wall_force), dtype=float)

