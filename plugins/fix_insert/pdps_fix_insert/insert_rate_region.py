r"""Fix ``insert/rate/region``: particles inserted into a region at a rate (LIGGGHTS's fix
insert/rate/region).

Syntax::

    fix ID GROUP insert/rate/region seed S distributiontemplate DIST nparticles N|INF | mass M|INF
        particlerate R | massrate R  insert_every N  region REGION [general keywords] [ntry_mc N]
        [check_dist_from_subdomain_border yes|no]

Every ``insert_every`` steps (required; the first insertion at ``start``, default the next step)
the fix inserts :math:`\lfloor n + u\rfloor` particles, :math:`n = \dot N\,\Delta t_\mathrm{ins}`
with :math:`\dot N` the particle rate (``particlerate``, particles/time) or :math:`\dot M/\langle
m\rangle` (``massrate``, mass/time, :math:`\langle m\rangle` the distribution's expected particle
mass), :math:`\Delta t_\mathrm{ins}` = insert_every x dt and u uniform on [0, 1): each insertion
rounds at random, to the rate on average, as LIGGGHTS's fix insert does (its
``calc_ninsert_this``); the delivered number wanders from the rate's line as a sum of such
roundings, by about :math:`\sqrt{k\,p(1-p)}` after k insertions, p the fraction of n. It stops after
``nparticles N`` particles, or :math:`M/\langle m\rangle` of them for ``mass M`` (rounded to the
nearest; with sizes drawn at random the mass is reached on average); ``INF``: never. Particles that
found no room are not owed later (as in LIGGGHTS). Placement, velocities and the general keywords:
insertion.py; ``all_in``, ``ntry_mc`` and ``check_dist_from_subdomain_border`` as for insert/pack.

Example::

    fix ins all insert/rate/region seed 100001 distributiontemplate pdd nparticles 6000 &
        particlerate 60000 insert_every 1000 overlapcheck yes vel constant 0. 0. -1. region top
"""

import math
from typing import Literal

import numpy as np

from pdps_core.api import ScriptError, keyword

from .insertion import FixInsert, InsertArgs, YesNo, positive
from .whole_number import WholeNumber
from .region_volume import InRegion, insertion_region


class RateArgs(InsertArgs):
    """The total and the rate of the rate-based insertion fixes."""
    nparticles: WholeNumber | Literal["INF"] | None = keyword(None, unit="particles")
    mass: float | Literal["INF"] | None = keyword(None, unit="mass")
    particlerate: float | None = keyword(None, gt=0, unit="particles/time")
    massrate: float | None = keyword(None, gt=0, unit="mass/time")


def check_rate(fix, args):
    """One total (nparticles|mass) and one rate (particlerate|massrate), each > 0, and insert_every
    a number of steps where given."""
    totals = [k for k in ("nparticles", "mass") if getattr(args, k) is not None]
    rates = [k for k in ("particlerate", "massrate") if getattr(args, k) is not None]
    if len(totals) != 1:
        raise ScriptError(f"give one of nparticles, mass (got {', '.join(totals) or 'none'})")
    if len(rates) != 1:
        raise ScriptError(f"give one of particlerate, massrate (got {', '.join(rates) or 'none'})")
    positive(args, "nparticles")
    positive(args, "mass")
    if args.insert_every == "once":
        raise ScriptError(f"insert_every must be a number of steps for fix {fix.name} (got once)")


def read_rate(fix, args):
    """The total and the rate, as particle counts."""
    mass = fix.distribution.mass_expected
    if args.nparticles == "INF" or args.mass == "INF":
        fix.total = math.inf
    elif args.nparticles is not None:
        fix.total = args.nparticles
    else:
        fix.total = max(1, round(args.mass / mass))
    fix.rate = args.particlerate if args.particlerate is not None else args.massrate / mass


def rate_count(fix, sim):
    """Particles for the current insertion, as LIGGGHTS counts them: int(n + u) for the n = rate x
    insert_every x dt the rate asks, u uniform on [0, 1) (drawn from the seed and the step, so a
    restart draws the same), capped at what the total leaves."""
    odds = np.random.default_rng([fix.seed, sim.step, 1]).random()
    count = min(int(fix.rate * fix.every * sim.dt + odds), fix.total - fix.wanted_so_far)
    fix.wanted_so_far += max(count, 0)
    if fix.wanted_so_far >= fix.total:
        fix.finished = True
    return count


class FixInsertRateRegion(InRegion, FixInsert):
    name = "insert/rate/region"
    usage = ("fix ID GROUP insert/rate/region seed S distributiontemplate DIST nparticles N|INF | mass M|INF "
             "particlerate R | massrate R insert_every N region REGION [keywords]")
    once_by_default = False

    class Args(RateArgs):
        region: str = keyword(..., names="region ID")
        insert_every: Literal["once"] | WholeNumber = keyword(..., unit="timesteps")
        ntry_mc: WholeNumber | None = keyword(None, ge=1, unit="1")    # LIGGGHTS's; read and not needed
        check_dist_from_subdomain_border: YesNo = keyword("yes")

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        check_rate(cls, args)

    def read_style(self, sim, args):
        self.region = insertion_region(sim, args.region)
        self.read_border(args)
        read_rate(self, args)
        self.wanted_so_far = 0

    def wanted(self, sim):
        return rate_count(self, sim)
