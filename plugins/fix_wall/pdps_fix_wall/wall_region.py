r"""Fix ``wall/region``: the surface of a region as a wall with a potential, acting on the particles
of the group the region holds (LAMMPS's and LIGGGHTS 3.8.0's fix wall/region).

For each particle at distance :math:`r < r_c` from the region's surface (from each face of a block
within the cutoff of an interior point; from the nearest point of the surface for a region with
``side out``), a force of magnitude F along the surface's normal, away from the surface, and the
energy E (shifted to 0 at the cutoff for the Lennard-Jones and colloid laws):

- ``lj93``: :math:`E = \varepsilon[\tfrac{2}{15}(\sigma/r)^9 - (\sigma/r)^3]`,
  :math:`F = \varepsilon[\tfrac{6}{5}\sigma^9/r^{10} - 3\sigma^3/r^4]`;
- ``lj126``: :math:`E = 4\varepsilon[(\sigma/r)^{12} - (\sigma/r)^6]`,
  :math:`F = \varepsilon[48\sigma^{12}/r^{13} - 24\sigma^6/r^7]`;
- ``colloid``: the integrated Lennard-Jones interaction of a sphere of radius R (the particle's)
  with a half space (LAMMPS's fix wall/colloid law, r the centre's distance, r > R),
  :math:`F = -\tfrac{4}{315}\varepsilon\sigma^6\,(R^9 + 27R^7r^2 + 63R^5r^4 + 21R^3r^6)/(R^2-r^2)^8
  + \tfrac{2}{3}\varepsilon R^3/(R^2-r^2)^2`, and E as LAMMPS's source gives it (its shift at the
  cutoff is the lj93 form's). That is LAMMPS's law, measured: LAMMPS 22 Jul 2025 and LIGGGHTS 3.8.0
  print the same rows for it, and pdps does. Its force is not minus its energy's derivative (it
  pulls a sphere onto the surface where the energy pushes it off; fix wall/colloid's coefficients
  have the other sign), so a colloid wall/region does not conserve energy;
- ``harmonic``: :math:`E = \varepsilon (r_c - r)^2`, :math:`F = 2\varepsilon (r_c - r)` (epsilon in
  energy/distance^2; sigma is read and not used).

A particle of the group outside the region, or on its surface (for colloid: nearer than its radius),
stops the run with a line naming it, as LAMMPS's "Particle on or inside surface of region used in
fix wall/region".

Output: ``f_ID`` the wall's energy, ``f_ID[1..3]`` the force on the wall (minus the sum of the forces
on the particles); ``fix_modify ID energy yes`` adds the energy to ``pe`` (off by default);
``fix_modify ID virial yes`` adds the wall's virial (f . del per contact, as today's LAMMPS; LIGGGHTS
3.8.0 tallies none) to the pressure (off by default).

Syntax::

    fix ID GROUP wall/region REGION lj93|lj126|colloid|harmonic EPSILON SIGMA CUTOFF

- REGION: a region that can act as a wall (block, sphere, cylinder, cone, plane, prism, union and
  intersect of those: pdps's region styles with a surface);
- EPSILON (energy, or energy/distance^2 for harmonic), SIGMA (distance), CUTOFF (> 0, distance).

Example::

    region ball sphere 0 0 0 5.0 side in units box
    fix wall all wall/region ball lj93 1.0 1.0 2.5

Recorded with LIGGGHTS 3.8.0 (cases wall_region_*, plugins/fix_wall/tests/data/liggghts.cases.json).
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import ScriptError, StyleArgs, SurfaceContacts, param

from .faces import PotentialWalls

LAWS = ("lj93", "lj126", "colloid", "harmonic")


@njit(cache=True)
def wall_region_forces(index, distance, normal, rows, mask, groupbit, radius, f, law, c1, c2, c3, c4, offset, epsilon,
                       cutoff, tally, virial):
    """Forces of the ``rows`` contacts of the group's particles added to f; tally = (energy, force
    on the wall x, y, z); virial (6) accumulates f . del; returns a contact's row that is too close,
    or -1."""
    for m in range(rows):
        i = index[m]
        if not mask[i] & groupbit:
            continue
        r = distance[m]
        rad = radius[i] if law == 2 else 0.0
        if r <= rad:
            return m
        rinv = 1.0 / r
        if law == 0:
            r2inv = rinv * rinv
            r4inv = r2inv * r2inv
            fwall = c1 * r4inv * r4inv * r2inv - c2 * r4inv
            energy = c3 * r4inv * r4inv * rinv - c4 * r2inv * rinv - offset
        elif law == 1:
            r2inv = rinv * rinv
            r6inv = r2inv * r2inv * r2inv
            fwall = r6inv * (c1 * r6inv - c2) * rinv
            energy = r6inv * (c3 * r6inv - c4) - offset
        elif law == 2:
            rad2 = rad * rad
            rad4 = rad2 * rad2
            rad8 = rad4 * rad4
            dinv = 1.0 / (rad2 - r * r)
            d2inv = dinv * dinv
            d4inv = d2inv * d2inv
            d8inv = d4inv * d4inv
            fwall = (c1 * (rad8 * rad + 27.0 * rad4 * rad2 * rad * r * r + 63.0 * rad4 * rad * r ** 4
                           + 21.0 * rad2 * rad * r ** 6) * d8inv - c2 * rad * rad2 * d2inv)
            diam = 2.0 * rad
            near = 0.5 * diam - r
            far = r + 0.5 * diam
            near_inv = 1.0 / near
            near2 = near_inv * near_inv
            far_inv = 1.0 / far
            far2 = far_inv * far_inv
            energy = (c3 * ((-3.5 * diam + r) * near2 * near2 * near2 * near_inv
                            + (3.5 * diam + r) * far2 * far2 * far2 * far_inv)
                      - c4 * ((-diam * r + near * far * (math.log(-near) - math.log(far))) * (-near_inv) * far_inv)
                      - offset)
        else:
            dr = cutoff - r
            fwall = 2.0 * epsilon * dr
            energy = epsilon * dr * dr
        fx, fy, fz = fwall * normal[m, 0], fwall * normal[m, 1], fwall * normal[m, 2]
        f[i, 0] += fx
        f[i, 1] += fy
        f[i, 2] += fz
        tally[0] += energy
        tally[1] -= fx
        tally[2] -= fy
        tally[3] -= fz
        dx, dy, dz = r * normal[m, 0], r * normal[m, 1], r * normal[m, 2]
        virial[0] += fx * dx
        virial[1] += fy * dy
        virial[2] += fz * dz
        virial[3] += fx * dy
        virial[4] += fx * dz
        virial[5] += fy * dz
    return -1


def coefficients(law, epsilon, sigma, cutoff):
    """(c1, c2, c3, c4, offset) of a law, as LAMMPS's FixWallRegion::init."""
    rinv = 1.0 / cutoff
    if law == "lj93":
        c1, c2 = 6.0 / 5.0 * epsilon * sigma ** 9, 3.0 * epsilon * sigma ** 3
        c3, c4 = 2.0 / 15.0 * epsilon * sigma ** 9, epsilon * sigma ** 3
        return c1, c2, c3, c4, c3 * rinv ** 9 - c4 * rinv ** 3
    if law == "lj126":
        c1, c2 = 48.0 * epsilon * sigma ** 12, 24.0 * epsilon * sigma ** 6
        c3, c4 = 4.0 * epsilon * sigma ** 12, 4.0 * epsilon * sigma ** 6
        return c1, c2, c3, c4, rinv ** 6 * (c3 * rinv ** 6 - c4)
    if law == "colloid":
        c1, c2 = -4.0 / 315.0 * epsilon * sigma ** 6, -2.0 / 3.0 * epsilon
        c3, c4 = epsilon * sigma ** 6 / 7560.0, epsilon / 6.0
        return c1, c2, c3, c4, c3 * rinv ** 9 - c4 * rinv ** 3
    return 0.0, 0.0, 0.0, 0.0, 0.0


class FixWallRegion(PotentialWalls):
    name = "wall/region"
    usage = "fix ID GROUP wall/region REGION lj93|lj126|colloid|harmonic EPSILON SIGMA CUTOFF"

    class Args(StyleArgs):
        region: str = param(names="region ID")
        law: Literal[LAWS] = param(names="style")
        epsilon: float = param(unit="energy")
        sigma: float = param(unit="distance")
        cutoff: float = param(gt=0, unit="distance")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.region_id = args.region
        self.region(sim)
        if args.law == "colloid" and "sphere" not in sim.particle_styles:
            raise ScriptError(f"fix {id} wall/region colloid needs finite-size particles (atom_style sphere)")
        self.law = LAWS.index(args.law)
        self.coefficients = coefficients(args.law, args.epsilon, args.sigma, args.cutoff)
        self.contacts = SurfaceContacts()
        self.tally = np.zeros(4)
        self.wall_energy = 0.0
        self.wall_force = np.zeros(3)
        self.wall_virial = np.zeros(6)
        self.no_radius = np.zeros(0)

    def region(self, sim):
        return sim.region(self.region_id)

    def init_run(self, sim):
        if self.law == 2:
            p = sim.particles
            chosen = (p.mask[:p.nlocal] & sim.groups.bit(self.group)) != 0
            if sim.comm.sum(int((p.radius[:p.nlocal][chosen] == 0.0).sum())):
                raise ScriptError(f"fix {self.id} wall/region colloid needs finite-size particles (a particle of "
                                  f"group {self.group} has radius 0)")

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        region = self.region(sim)
        groupbit = sim.groups.bit(self.group)
        message = None
        outside = np.flatnonzero(~region.match(p.x[:n]) & ((p.mask[:n] & groupbit) != 0))
        if outside.size:
            message = self._too_close(sim, int(outside[0]))
        index, distance, normal, _ = region.surface(p.x[:n], self.args.cutoff, self.contacts)
        radius = p.radius if self.law == 2 else self.no_radius
        self.tally[:] = 0.0
        self.wall_virial[:] = 0.0
        c1, c2, c3, c4, offset = self.coefficients
        bad = wall_region_forces(index, distance, normal, len(index), p.mask, groupbit, radius, p.f, self.law,
                                 c1, c2, c3, c4, offset, self.args.epsilon, self.args.cutoff, self.tally,
                                 self.wall_virial)
        if bad >= 0 and message is None:
            message = self._too_close(sim, int(index[bad]))
        self.wall_energy = float(self.tally[0])
        self.wall_force[:] = self.tally[1:]
        sim.comm.agree(message)

    def _too_close(self, sim, i):
        p = sim.particles
        return (f"fix {self.id} (wall/region): particle {int(p.tag[i])} is on or outside the surface of region "
                f"{self.region_id} at step {sim.step} (position {', '.join(f'{c:.6g}' for c in p.x[i])})")
