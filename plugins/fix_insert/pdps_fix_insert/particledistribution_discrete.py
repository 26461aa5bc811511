r"""Fix ``particledistribution/discrete``: a mixture of particle templates by mass (LIGGGHTS's fix
particledistribution/discrete, also spelled ``/massbased``), or by number
(``particledistribution/discrete/numberbased``), which the insertion fixes draw particles from.

Syntax::

    fix ID GROUP particledistribution/discrete[/massbased|/numberbased] SEED N TEMPLATE1 FRACTION1 ...

``TEMPLATEk`` the ID of a ``fix particletemplate/sphere``, ``FRACTIONk`` the fraction of the
*mass* its particles carry (LIGGGHTS's mass-%), or with ``/numberbased`` the fraction of the
particles that come from it (number-%: :math:`p_k = w_k`; LIGGGHTS 3.8.0 prints 30 % and 70 % for
weights 0.3 and 0.7 there, and 63.708005 % and 36.291995 % by number for them by mass with radii
5 and 8 mm, as :math:`p_k` below gives). Fractions that do not add up to 1 are scaled to do so,
with a warning. By mass, a particle comes from template k with the number probability

.. math::

    p_k = \frac{w_k / \langle m_k\rangle}{\sum_l w_l / \langle m_l\rangle}

(:math:`\langle m_k\rangle` the template's expected mass), so that in the long run template k's
particles carry the fraction :math:`w_k` of the inserted mass. An insertion of n particles takes
:math:`\lfloor n p_k\rfloor` from each template and the few left over at random by the remainders,
as LIGGGHTS does (its randomize_list with exact numbers, the default): the mixture of each insertion
is its shares to within a particle a template. The expected particle mass and
volume of the mixture are :math:`\sum_k p_k \langle m_k\rangle` and :math:`\sum_k p_k \langle
V_k\rangle`. As in LIGGGHTS, the particles of one insertion are placed largest first (a higher
packing fraction is reached); their types are the templates', their groups this fix's and the
template's besides the insertion fix's and ``all``.

``SEED``: a positive whole number, read for its range (the insertion fix's seed draws the
particles, on every rank alike).

Example::

    fix pdd all particledistribution/discrete 32452843 2 pts1 0.3 pts2 0.7
"""

from typing import NamedTuple

import numpy as np

from pdps_core.api import Fix, ScriptError, StyleArgs, param

from .whole_number import WholeNumber
from .particletemplate_sphere import FixParticleTemplateSphere


class Share(NamedTuple):
    template: str
    fraction: float


class FixParticleDistributionDiscrete(Fix):
    name = "particledistribution/discrete"
    usage = "fix ID GROUP particledistribution/discrete SEED N TEMPLATE1 FRACTION1 ... TEMPLATEN FRACTIONN"
    weights_by = "mass"             # what a template's fraction is a fraction of: "mass" or "number"

    class Args(StyleArgs):
        seed: WholeNumber = param(ge=1, unit="1")
        count: WholeNumber = param(ge=1, unit="1", alias="N")
        templates: list[Share] = param(default_factory=list, unit=("1", "dimensionless"))

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        if len(args.templates) != args.count:
            raise ScriptError(f"expected {min(args.count, 10 ** 6)} template/fraction pairs (got "
                              f"{2 * len(args.templates)} words after N)")
        for name, fraction in args.templates:
            if not 0 < fraction <= 1:
                raise ScriptError(f"{cls.weights_by} fraction of {name} must be > 0 and <= 1 (got {fraction:g})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.seed = args.seed
        self.templates, fractions = [], []
        for name, fraction in args.templates:
            template = sim.fixes.get(name)
            if not isinstance(template, FixParticleTemplateSphere):
                known = [k for k, f in sim.fixes.items() if isinstance(f, FixParticleTemplateSphere)]
                raise ScriptError(f"{name} is not a fix particletemplate/sphere (defined: {', '.join(known) or 'none'})")
            self.templates.append(template)
            fractions.append(fraction)
        total = sum(fractions)
        if abs(total - 1.0) > 1e-10:
            sim.warn(f"fix {id}: the {self.weights_by} fractions add up to {total:g}, not 1: they are scaled "
                     "to do so")
        mass = np.array([t.mass_expected for t in self.templates])
        if self.weights_by == "number":
            self.number_fraction = np.array(fractions) / total
            carried = self.number_fraction * mass
            self.mass_fraction = carried / carried.sum()
        else:
            self.mass_fraction = np.array(fractions) / total
            weight = self.mass_fraction / mass
            self.number_fraction = weight / weight.sum()
        self.mass_expected = float(self.number_fraction @ mass)
        self.volume_expected = float(self.number_fraction @ [t.volume_expected for t in self.templates])
        self.max_radius = max(t.max_radius for t in self.templates)

    def counts(self, rng, n):
        """How many of n particles each template gives, as LIGGGHTS's randomize_list with its
        default exact number: floor(n p_k) each, and the n - sum left over drawn one at a time among
        the templates with odds their remainders n p_k - floor(n p_k). So an insertion's mixture
        strays by at most the remainders from its shares, not by a multinomial's sqrt(n p (1 - p))."""
        share = n * self.number_fraction
        counts = np.floor(share).astype(np.int64)
        gap = n - int(counts.sum())
        if gap > 0:
            remainder = share - counts
            counts += np.bincount(rng.choice(len(counts), size=gap, p=remainder / remainder.sum()),
                                  minlength=len(counts))
        return counts

    def draw(self, rng, n):
        """n particles, largest first: (radius, density, type, template index) arrays."""
        which = np.repeat(np.arange(len(self.templates)), self.counts(rng, n))
        radius, density = np.empty(n), np.empty(n)
        for k, template in enumerate(self.templates):
            rows = np.flatnonzero(which == k)
            radius[rows], density[rows] = template.draw(rng, len(rows))
        order = np.argsort(-radius, kind="stable")
        types = np.array([t.atom_type for t in self.templates], dtype=np.int32)[which]
        return radius[order], density[order], types[order], which[order]


class FixParticleDistributionDiscreteMassBased(FixParticleDistributionDiscrete):
    name = "particledistribution/discrete/massbased"
    usage = FixParticleDistributionDiscrete.usage.replace("discrete", "discrete/massbased", 1)


class FixParticleDistributionDiscreteNumberBased(FixParticleDistributionDiscrete):
    name = "particledistribution/discrete/numberbased"
    usage = FixParticleDistributionDiscrete.usage.replace("discrete", "discrete/numberbased", 1)
    weights_by = "number"

