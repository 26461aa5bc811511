r"""Fix ``insert/rate/region``: particles inserted into a region at a rate (LIGGGHTS's fix
insert/rate/region).

Syntax::

    fix ID GROUP insert/rate/region seed S distributiontemplate DIST nparticles N|INF | mass M|INF
        particlerate R | massrate R  insert_every N  region REGION [general keywords] [ntry_mc N]

Every ``insert_every`` steps (required; the first insertion at ``start``, default the next step)
the fix inserts the particles that keep the inserted number on the rate's line: after the k-th
insertion, :math:`\lfloor k\,\dot N\,\Delta t_\mathrm{ins}\rfloor` in all, with :math:`\dot N` the
particle rate (``particlerate``, particles/time) or :math:`\dot M/\langle m\rangle` (``massrate``,
mass/time, :math:`\langle m\rangle` the distribution's expected particle mass) and
:math:`\Delta t_\mathrm{ins}` = insert_every x dt. So the delivered number never strays a whole
particle from the rate (LIGGGHTS rounds each insertion at random instead). It stops after
``nparticles N`` particles, or :math:`M/\langle m\rangle` of them for ``mass M`` (rounded to the
nearest; with sizes drawn at random the mass is reached on average); ``INF``: never. Particles that
found no room are not owed later (as in LIGGGHTS). Placement, velocities and the general keywords:
insertion.py; ``all_in`` and ``ntry_mc`` as for insert/pack.

Example::

    fix ins all insert/rate/region seed 100001 distributiontemplate pdd nparticles 6000 &
        particlerate 60000 insert_every 1000 overlapcheck yes vel constant 0. 0. -1. region top
"""

import math

from pdps_core.api import ScriptError, number

from .insertion import FixInsert, whole_number
from .region_volume import InRegion, insertion_region

RATE_ARITY = {"nparticles": 1, "mass": 1, "particlerate": 1, "massrate": 1}


def read_rate(fix, given, every_needed=True):
    """The total and the rate (nparticles|mass, particlerate|massrate), as particle counts."""
    totals = [k for k in ("nparticles", "mass") if k in given]
    rates = [k for k in ("particlerate", "massrate") if k in given]
    if len(totals) != 1:
        raise ScriptError(f"give one of nparticles, mass (got {', '.join(totals) or 'none'})")
    if len(rates) != 1:
        raise ScriptError(f"give one of particlerate, massrate (got {', '.join(rates) or 'none'})")
    if every_needed and "insert_every" not in given:
        raise ScriptError(f"missing keyword insert_every; usage: {fix.usage}")
    if fix.every is None:
        raise ScriptError(f"insert_every must be a number of steps for fix {fix.name} (got once)")
    mass = fix.distribution.mass_expected
    word = given[totals[0]][0]
    if word == "INF":
        fix.total = math.inf
    elif totals[0] == "nparticles":
        fix.total = whole_number(word, "nparticles", low=1)
    else:
        value = number(word, "mass")
        if not value > 0:
            raise ScriptError(f"mass must be > 0 (got {word})")
        fix.total = max(1, round(value / mass))
    rate = number(given[rates[0]][0], rates[0])
    if not rate > 0:
        raise ScriptError(f"{rates[0]} must be > 0 (got {given[rates[0]][0]})")
    fix.rate = rate if rates[0] == "particlerate" else rate / mass


def rate_count(fix, sim):
    """Particles for the current insertion: the rate's line, less what is already owed, capped."""
    line = math.floor(fix.events_done_after() * fix.rate * fix.every * sim.dt + 1e-9)
    count = min(line, fix.total) - fix.wanted_so_far
    fix.wanted_so_far += max(count, 0)
    if fix.wanted_so_far >= fix.total:
        fix.finished = True
    return count


class FixInsertRateRegion(InRegion, FixInsert):
    name = "insert/rate/region"
    usage = ("fix ID GROUP insert/rate/region seed S distributiontemplate DIST nparticles N|INF | mass M|INF "
             "particlerate R | massrate R insert_every N region REGION [keywords]")
    STYLE_ARITY = {**RATE_ARITY, "region": 1, "ntry_mc": 1}
    once_by_default = False

    def read_style(self, sim, given):
        if "region" not in given:
            raise ScriptError(f"missing keyword region; usage: {self.usage}")
        self.region = insertion_region(sim, given["region"][0])
        read_rate(self, given)
        self.wanted_so_far = 0

    def events_done_after(self):
        return self.events + 1          # wanted() is asked before the insertion counts

    def wanted(self, sim):
        return rate_count(self, sim)
