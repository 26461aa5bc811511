r"""Fix ``particletemplate/sphere``: what one inserted sphere is (LIGGGHTS's fix
particletemplate/sphere): its particle type, and the random distributions its radius and density
are drawn from (size_distribution.py). It does nothing during a run; a ``fix
particledistribution/discrete`` names it, and an insertion fix draws particles from that.

Syntax::

    fix ID GROUP particletemplate/sphere SEED atom_type T density STYLE ... radius STYLE ...
        [volume_limit V] [relative yes|no]

- ``SEED``: a positive whole number (LIGGGHTS's random seed of the template; pdps draws every
  inserted particle from the insertion fix's seed, so that the same particles appear on any number
  of ranks, and reads this one only for its range).
- ``atom_type T``: the inserted particles' type (default 1).
- ``density constant RHO | uniform LO HI | gaussian MU SIGMA | lognormal MU SIGMA`` (mass/distance^3;
  required).
- ``radius constant R | uniform number|mass LO HI | gaussian number MU SIGMA | lognormal
  number|mass MU SIGMA`` (distance; required). ``number``: the distribution of the radii of the
  particles; ``mass``: the distribution of the mass over radii (LIGGGHTS's mass-% basis).
- ``volume_limit V``: the smallest expected particle volume allowed (default 1e-12, distance^3).
- ``relative yes|no``: LIGGGHTS's flag saying the radii are relative to a reference radius, for
  commands that would read it: none of LIGGGHTS-PUBLIC's does (its source), none of pdps's; the
  radii are lengths either way. LIGGGHTS 3.8.0 leaves a ``relative yes`` template's radii out of
  the neighbor cutoff (and aborts when nothing else sizes it, measured); pdps sizes the cutoff from
  them as with ``relative no``, and says so.

Each particle: radius r and density rho drawn independently, mass :math:`m = \rho\,\tfrac43\pi r^3`.
The template's expected volume is :math:`\tfrac43\pi\langle r^3\rangle` and its expected mass
:math:`\langle\rho\rangle\tfrac43\pi\langle r^3\rangle`, the numbers insertion rates and
distributions are converted with.

Example::

    fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0015
    fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius uniform mass 0.001 0.002
"""

import math
from typing import Literal

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param

from .whole_number import WholeNumber
from .size_distribution import Distribution

# a density's style word, then its values; a radius's style word, then number|mass (but constant), then its values
Density = tuple[Literal["constant"], float] | tuple[Literal["uniform", "gaussian", "lognormal"], float, float]
Radius = (tuple[Literal["constant"], float]
          | tuple[Literal["uniform", "gaussian", "lognormal"], Literal["number", "mass"], float, float])


def units(kind):
    """The units of a distribution's values by its style word (lognormal's MU and SIGMA are those of
    ln of the value)."""
    return {"constant": kind, "uniform": kind, "gaussian": kind, "lognormal": "dimensionless"}


class FixParticleTemplateSphere(Fix):
    name = "particletemplate/sphere"
    usage = ("fix ID GROUP particletemplate/sphere SEED atom_type T density STYLE ... radius STYLE ... "
             "[volume_limit V] [relative yes|no]")

    class Args(StyleArgs):
        seed: WholeNumber = param(ge=1, unit="1")
        atom_type: WholeNumber = keyword(1, ge=1, unit="1")
        density: Density = keyword(..., unit=units("density"))
        radius: Radius = keyword(..., unit=units("distance"))
        volume_limit: float = keyword(1e-12, gt=0, unit="volume")
        relative: bool = keyword(False)

    @classmethod
    def check_args(cls, args):
        super().check_args(args)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.seed = args.seed
        self.atom_type = args.atom_type
        if sim.ntypes and self.atom_type > sim.ntypes:
            raise ScriptError(f"atom_type must be from 1 to {sim.ntypes}, the number of types (got {self.atom_type})")
        self.density = Distribution.read(args.density, "density", radius=False)
        self.radius = Distribution.read(args.radius, "radius", radius=True)
        limit = args.volume_limit
        self.volume_expected = 4.0 / 3.0 * math.pi * self.radius.mean_of(3)
        if self.volume_expected < limit:
            raise ScriptError(f"the expected particle volume {self.volume_expected:.3g} is below volume_limit "
                              f"{limit:g}: check the radius units, or lower volume_limit")
        self.mass_expected = self.density.mean_of(1) * self.volume_expected
        self.max_radius = self.radius.support()[1]
        if args.relative:
            sim.info(f"fix {id} particletemplate/sphere: relative yes is read by no command; the radii are "
                     "lengths, and the neighbor cutoff is sized from them (LIGGGHTS leaves them out of it)")

    def draw(self, rng, n):
        """(radii, densities) of n particles."""
        return self.radius.draw(rng, n), self.density.draw(rng, n)
