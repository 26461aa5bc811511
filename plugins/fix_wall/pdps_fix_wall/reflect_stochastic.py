r"""Fix ``wall/reflect/stochastic``: flat walls that send crossing particles back with a velocity
drawn from the wall's gas-surface scattering kernel (LAMMPS's fix wall/reflect/stochastic, by
Q.-D. To: To, Vu, Lauriat and Leonard, J. Math. Phys. 56, 103101 (2015); the kernels: Maxwell, Phil.
Trans. R. Soc. 170, 231 (1879); Cercignani and Lampis, Transp. Theory Stat. Phys. 1, 101 (1971)).

After the positions have moved (``post_integrate``), a particle of the group found beyond a wall at
:math:`x_n = c` (below a ``lo`` wall, above a ``hi`` wall) is taken back along its path to the
point where it crossed, :math:`t_c = (x_n - c)/v_n` before the end of the step, given a new
velocity, and moved on from there with it for :math:`t_c`. With :math:`\theta = k_B T_w / m` (T_w
the wall's temperature, m the particle's mass), :math:`\mathbf{u}_w` the wall's (tangential)
velocity and n the wall's normal into the box:

- ``diffusive``: the particle forgets its velocity; it leaves with the wall's Maxwell flux
  distribution: tangential components :math:`u_{w,t} + \sqrt{\theta}\,\xi` (ξ standard normal),
  normal component Rayleigh-distributed, :math:`v_n = \sqrt{-2\theta\ln u}` into the box, so the
  density of leaving velocities is :math:`\propto v_n \exp(-|\mathbf{v}-\mathbf{u}_w|^2/2\theta)`.
- ``maxwell``: with probability α (the accommodation coefficient) the reflection is diffusive,
  otherwise specular (the normal component reversed, the tangential ones kept).
- ``ccl`` (Cercignani-Lampis): each component keeps part of its memory, by its own coefficient
  :math:`\alpha_k` (tangential: momentum accommodation, normal: energy accommodation).
  Tangential: :math:`u_{w,t} + (1-\alpha_t)(v_t - u_{w,t}) + \sqrt{(2-\alpha_t)\alpha_t\theta}\,\xi`;
  normal: LAMMPS's Bessel-exponential draw, :math:`|v_n'| = \sqrt{(1-\alpha_n) v_n^2 + r^2 -
  2\sqrt{1-\alpha_n}|v_n|\,r\cos\varphi}` with :math:`r = \sqrt{-2\alpha_n\theta\ln u_1}`,
  :math:`\varphi = 2\pi u_2`. α = 1 is diffusive, α = 0 specular.

Random numbers: pdps's counter-based generator keyed by (seed, step, particle id, wall), so a run
does not depend on particle order or the number of ranks; LAMMPS draws from one Marsaglia stream per
rank (seed + rank) in the order particles are stored, so trajectories differ from LAMMPS's from the
first collision on while the distributions are the same.

Where pdps differs: a particle found beyond a wall without moving out through it (placed there, or
at rest) is put on the wall (t_c = 0) with its new velocity; LAMMPS divides by its normal velocity
(0: NaN) or sends it further out. In 2-d, z components are left alone (LAMMPS draws a z velocity,
which fix enforce2d then removes).

A wall's position is a number (distance units; scaled by the lattice spacing with ``units lattice``,
LAMMPS's default, 1 without a lattice command) or ``EDGE`` (the box face where the fix is defined);
the walls stand on non-periodic axes, each face once, and act in the order given. The wall velocity
must be tangential.

Syntax (LAMMPS's)::

    fix ID GROUP wall/reflect/stochastic diffusive|maxwell|ccl SEED face args [face args ...] [units box|lattice]

    face = xlo | xhi | ylo | yhi | zlo | zhi
    args = coord T vx vy vz              (diffusive)
           coord T vx vy vz alpha        (maxwell)
           coord T vx vy vz ax ay az     (ccl: one coefficient per direction)
    coord = number | EDGE

Example::

    fix ywalls all wall/reflect/stochastic maxwell 29839 ylo EDGE 300 0 0 0 0.2 yhi EDGE 300 0 0 0.1 0.2
    fix walls all wall/reflect/stochastic ccl 9 zlo 0 1.0 0 0 0 0.5 0.5 0.8 zhi 10 1.0 0.1 0 0 0.5 0.5 0.8 units box
"""

import math
from typing import Literal, NamedTuple

import numpy as np
from numba import njit
from pydantic import model_validator

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param, particle_gaussians, particle_uniforms

from .faces import FACES, Face, check_order, once_each, wall_planes

RULES = ("diffusive", "maxwell", "ccl")
DIFFUSIVE, MAXWELL, CCL = range(3)
# how many accommodation coefficients each rule takes after the wall velocity
COEFFICIENTS = {"diffusive": 0, "maxwell": 1, "ccl": 3}
# the Philox streams of wall k: STREAM + 2k (uniforms) and STREAM + 2k + 1 (normal numbers)
STREAM = 0x5717


class Wall(NamedTuple):
    face: Face
    coord: float | Literal["EDGE"]
    temp: float
    vx: float
    vy: float
    vz: float
    accommodation: tuple[float, ...]


@njit(cache=True)
def bessel_exponential(theta, alpha, vn, u1, u2):
    """LAMMPS's RanMars::besselexp: the Cercignani-Lampis normal velocity after a collision with
    normal velocity ``vn`` (its sign reversed), from two uniform numbers."""
    radius_sq = -2.0 * alpha * theta * math.log(u1)
    cross = 2.0 * math.sqrt(-2.0 * theta * (1.0 - alpha) * alpha * math.log(u1)) * math.cos(2.0 * math.pi * u2) * vn
    if vn < 0.0:
        return math.sqrt(max((1.0 - alpha) * vn * vn + radius_sq + cross, 0.0))
    return -math.sqrt(max((1.0 - alpha) * vn * vn + radius_sq - cross, 0.0))


@njit(cache=True)
def scatter(x, v, tag, type_, mass, rmass, mask, groupbit, nlocal, axes, lower, coords, kt, wall_velocity,
            accommodation, rule, key, step, dimension):
    """Every particle of the group beyond a wall: back to its crossing point, a new velocity from the
    wall's kernel, on from there for the time it had spent beyond the wall."""
    for w in range(len(axes)):
        d = axes[w]
        c = coords[w]
        inward = 1.0 if lower[w] else -1.0
        for i in range(nlocal):
            if not mask[i] & groupbit:
                continue
            if (lower[w] and x[i, d] >= c) or (not lower[w] and x[i, d] <= c):
                continue
            theta = kt[w] / (rmass[i] if len(rmass) else mass[type_[i]])
            # the time since the crossing; a particle that did not move out through the wall is put on it
            t_beyond = (x[i, d] - c) / v[i, d] if v[i, d] * inward < 0.0 else 0.0
            u0, u1, u2, _ = particle_uniforms(key, step, tag[i], STREAM + 2 * w)
            g0, g1, _, _ = particle_gaussians(key, step, tag[i], STREAM + 2 * w + 1)
            diffuse = rule == DIFFUSIVE or (rule == MAXWELL and u0 < accommodation[w, 0])
            tangential = 0
            for j in range(dimension):
                x[i, j] -= v[i, j] * t_beyond
                if j == d:
                    if rule == CCL:
                        v[i, j] = bessel_exponential(theta, accommodation[w, j], v[i, j], u1, u2)
                    elif diffuse:
                        v[i, j] = inward * math.sqrt(theta) * math.sqrt(-2.0 * math.log(u1))
                    else:
                        v[i, j] = -v[i, j]
                    x[i, j] = c + v[i, j] * t_beyond
                    continue
                xi = g0 if tangential == 0 else g1
                tangential += 1
                if rule == CCL:
                    a = accommodation[w, j]
                    v[i, j] = (wall_velocity[w, j] + (1.0 - a) * (v[i, j] - wall_velocity[w, j])
                               + math.sqrt((2.0 - a) * a * theta) * xi)
                elif diffuse:
                    v[i, j] = wall_velocity[w, j] + math.sqrt(theta) * xi
                x[i, j] += v[i, j] * t_beyond


class FixWallReflectStochastic(Fix):
    name = "wall/reflect/stochastic"
    usage = ("fix ID GROUP wall/reflect/stochastic diffusive|maxwell|ccl SEED face coord T vx vy vz [alpha | ax ay az] "
             "[face ...] [units box|lattice]")

    class Args(StyleArgs):
        rule: Literal["diffusive", "maxwell", "ccl"] = param()
        seed: int = param(ge=1, unit="1")
        wall: list[Wall] = param(min_length=1, unit=("1", "distance", "temperature", "velocity", "velocity",
                                                      "velocity", "1"))
        units: Literal["box", "lattice"] = keyword("lattice")

        @model_validator(mode="after")
        def _walls(self):
            once_each((wall.face, wall.coord) for wall in self.wall)
            wanted = COEFFICIENTS[self.rule]
            for wall in self.wall:
                given = len(wall.accommodation)
                if given != wanted:
                    what = {0: "no accommodation coefficient", 1: "one accommodation coefficient",
                            3: "three accommodation coefficients (x y z)"}[wanted]
                    raise ValueError(f"wall {wall.face}: {self.rule} takes {what} after the wall velocity "
                                     f"(got {' '.join(f'{a:g}' for a in wall.accommodation) or 'none'})")
                for a in wall.accommodation:
                    if not 0.0 <= a <= 1.0:
                        raise ValueError(f"wall {wall.face}: accommodation coefficients must be from 0 to 1 "
                                         f"(got {a:g})")
                if wall.temp < 0.0:
                    raise ValueError(f"wall {wall.face}: temperature must be >= 0 (got {wall.temp:g})")
                draws_rayleigh = self.rule == "diffusive" or (self.rule == "maxwell" and wall.accommodation[0] > 0)
                if wall.temp == 0.0 and draws_rayleigh:
                    raise ValueError(f"wall {wall.face}: temperature must be > 0 for {self.rule} reflection (got 0)")
                axis = FACES.index(wall.face) // 2
                normal = (wall.vx, wall.vy, wall.vz)[axis]
                if normal != 0.0:
                    raise ValueError(f"wall {wall.face}: the wall velocity must be tangential "
                                     f"(got v{'xyz'[axis]} {normal:g})")
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box(f"fix {self.name}")
        for wall in args.wall:
            axis = FACES.index(wall.face) // 2
            if axis == 2 and sim.dimension == 2:
                raise ScriptError(f"wall {wall.face} in a 2-d simulation")
            if sim.box.periodic[axis]:
                raise ScriptError(f"wall {wall.face} stands on the periodic {'xyz'[axis]} axis: "
                                  "make it fixed (boundary f)")
        self.rule = RULES.index(args.rule)
        self.axes, self.lower, self.coords = wall_planes(sim, {w.face: w.coord for w in args.wall}, args.units)
        check_order([w.face for w in args.wall], self.coords)
        # k_B T / mvv2e: divided by each particle's mass, the variance of a velocity component
        self.kt = np.array([sim.units.boltz * w.temp / sim.units.mvv2e for w in args.wall])
        self.wall_velocity = np.array([(w.vx, w.vy, w.vz) for w in args.wall], dtype=np.float64)
        self.accommodation = np.zeros((len(args.wall), 3))
        for k, wall in enumerate(args.wall):
            if wall.accommodation:
                # maxwell's one coefficient serves every direction, as LAMMPS stores it
                self.accommodation[k] = wall.accommodation if len(wall.accommodation) == 3 else wall.accommodation[0]
        self.no_rmass = np.zeros(0)

    def post_integrate(self, sim):
        p = sim.particles
        rmass = p.rmass if p.has("rmass") else self.no_rmass
        scatter(p.x, p.v, p.tag, p.type, sim.mass, rmass, p.mask, sim.groups.bit(self.group), p.nlocal,
                self.axes, self.lower, self.coords, self.kt, self.wall_velocity, self.accommodation, self.rule,
                sim.random_key(self.args.seed), sim.step, sim.dimension)
