r"""Fix ``particletemplate/sphere``: what one inserted sphere is (LIGGGHTS's fix
particletemplate/sphere): its particle type, and the random distributions its radius and density
are drawn from (size_distribution.py). It does nothing during a run; a ``fix
particledistribution/discrete`` names it, and an insertion fix draws particles from that.

Syntax::

    fix ID GROUP particletemplate/sphere SEED atom_type T density STYLE ... radius STYLE ...
        [volume_limit V]

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

Each particle: radius r and density rho drawn independently, mass :math:`m = \rho\,\tfrac43\pi r^3`.
The template's expected volume is :math:`\tfrac43\pi\langle r^3\rangle` and its expected mass
:math:`\langle\rho\rangle\tfrac43\pi\langle r^3\rangle`, the numbers insertion rates and
distributions are converted with.

Example::

    fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.0015
    fix pts2 all particletemplate/sphere 15485867 atom_type 1 density constant 2500 radius uniform mass 0.001 0.002
"""

import math

from pdps_core.api import ScriptError, StyleArgs, Fix

from .insertion import read_keywords, whole_number
from .size_distribution import Distribution


class FixParticleTemplateSphere(Fix):
    name = "particletemplate/sphere"
    usage = ("fix ID GROUP particletemplate/sphere SEED atom_type T density STYLE ... radius STYLE ... "
             "[volume_limit V]")

    class Args(StyleArgs):
        words: list[str] = []

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        words = list(args.words)
        if not words:
            raise ScriptError(f"missing argument seed; usage: {self.usage}")
        self.seed = whole_number(words[0], "seed", low=1)
        given = read_keywords(words[1:], {
            "atom_type": 1, "volume_limit": 1,
            "density": lambda rest: Distribution.word_count(rest, radius=False),
            "radius": lambda rest: Distribution.word_count(rest, radius=True),
        })
        self.atom_type = whole_number(given["atom_type"][0], "atom_type", low=1) if "atom_type" in given else 1
        if sim.ntypes and self.atom_type > sim.ntypes:
            raise ScriptError(f"atom_type must be from 1 to {sim.ntypes}, the number of types (got {self.atom_type})")
        for needed in ("density", "radius"):
            if needed not in given:
                raise ScriptError(f"missing keyword {needed}; usage: {self.usage}")
        self.density = Distribution.read(given["density"], "density", radius=False)
        self.radius = Distribution.read(given["radius"], "radius", radius=True)
        limit = 1e-12
        if "volume_limit" in given:
            limit = float(given["volume_limit"][0]) if _finite(given["volume_limit"][0]) else -1.0
            if not limit > 0:
                raise ScriptError(f"volume_limit must be a number > 0 (got {given['volume_limit'][0]})")
        self.volume_expected = 4.0 / 3.0 * math.pi * self.radius.mean_of(3)
        if self.volume_expected < limit:
            raise ScriptError(f"the expected particle volume {self.volume_expected:.3g} is below volume_limit "
                              f"{limit:g}: check the radius units, or lower volume_limit")
        self.mass_expected = self.density.mean_of(1) * self.volume_expected
        self.max_radius = self.radius.support()[1]

    def draw(self, rng, n):
        """(radii, densities) of n particles."""
        return self.radius.draw(rng, n), self.density.draw(rng, n)


def _finite(word):
    try:
        return math.isfinite(float(word))
    except ValueError:
        return False
