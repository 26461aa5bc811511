r"""Fix ``insert/pack``: fill a region up to a target, once or every N steps (LIGGGHTS's fix
insert/pack).

Syntax::

    fix ID GROUP insert/pack seed S distributiontemplate DIST [general keywords] region REGION
        volumefraction_region VF | particles_in_region N | mass_in_region M  [ntry_mc N]

At each insertion step the fix counts what the region holds (particles whose centre it matches)
and inserts the difference to the target:

- ``particles_in_region N``: :math:`N - N_\mathrm{in}` particles;
- ``mass_in_region M``: :math:`(M - M_\mathrm{in})/\langle m\rangle` particles, with
  :math:`\langle m\rangle` the distribution's expected particle mass;
- ``volumefraction_region VF`` (0 < VF < 1): :math:`(VF\,V - V_\mathrm{in})/\langle V\rangle`
  particles, V the region's volume inside the box, measured once by ``ntry_mc`` uniform points of its
  extent (default 100000; the relative error is about :math:`\sqrt{(1-f)/(f\,n)}` for a region
  filling a share f of its extent);

a fractional count rounded up or down at random with the odds that keep it unbiased (as LIGGGHTS
says of its mass-based counts). The particles go where the region matches (``all_in yes``: wholly
inside it, for regions whose surface distance pdps knows: those that can be walls), clear of every
present particle and of each other, each trying ``maxattempt`` random positions; insertion.py
gives the general keywords, the velocities and why the same particles appear on any number of
ranks. ``insert_every`` defaults to once; the default start is the next step.

Example (LIGGGHTS's)::

    region bc cylinder z 0.0 0.0 0.045 0.00 0.15 units box
    fix ins all insert/pack seed 32452843 distributiontemplate pdd vel constant 0. 0. -0.5 &
        insert_every once overlapcheck yes all_in yes particles_in_region 1800 region bc
"""

import math

import numpy as np

from pdps_core.api import ScriptError, number

from .insertion import FixInsert, whole_number
from .region_volume import InRegion, insertion_region, region_volume

TARGETS = ("volumefraction_region", "particles_in_region", "mass_in_region")


class FixInsertPack(InRegion, FixInsert):
    name = "insert/pack"
    usage = ("fix ID GROUP insert/pack seed S distributiontemplate DIST [keywords] region REGION "
             "volumefraction_region VF | particles_in_region N | mass_in_region M [ntry_mc N]")
    STYLE_ARITY = {"region": 1, "volumefraction_region": 1, "particles_in_region": 1, "mass_in_region": 1,
                   "ntry_mc": 1}

    def read_style(self, sim, given):
        if "region" not in given:
            raise ScriptError(f"missing keyword region; usage: {self.usage}")
        self.region = insertion_region(sim, given["region"][0])
        targets = [t for t in TARGETS if t in given]
        if len(targets) != 1:
            raise ScriptError("give exactly one of volumefraction_region, particles_in_region, mass_in_region "
                              f"(got {', '.join(targets) or 'none'})")
        self.target = targets[0]
        word = given[self.target][0]
        if self.target == "particles_in_region":
            self.amount = whole_number(word, "particles_in_region", low=0)
        else:
            self.amount = number(word, self.target)
            if self.target == "volumefraction_region" and not 0 < self.amount < 1:
                raise ScriptError(f"volumefraction_region must be > 0 and < 1 (got {word})")
            if self.target == "mass_in_region" and not self.amount > 0:
                raise ScriptError(f"mass_in_region must be > 0 (got {word})")
        self.ntry_mc = whole_number(given["ntry_mc"][0], "ntry_mc", low=1000) if "ntry_mc" in given else 100_000
        if self.ntry_mc > 100_000_000:
            raise ScriptError(f"ntry_mc must be at most 100000000 (got {given['ntry_mc'][0]})")
        self.volume = None

    def wanted(self, sim):
        p = sim.particles
        n = p.nlocal
        inside = self.region.match(p.x[:n])
        if self.target == "particles_in_region":
            return self.amount - int(sim.comm.sum(int(inside.sum())))
        if self.target == "mass_in_region":
            held = float(sim.comm.sum(float(p.rmass[:n][inside].sum())))
            expected = (self.amount - held) / self.distribution.mass_expected
        else:
            if self.volume is None:
                self.volume = region_volume(self.region, sim.box, np.random.default_rng([self.seed, 0]),
                                            self.ntry_mc)
            held = float(sim.comm.sum(float((4.0 / 3.0 * math.pi * p.radius[:n][inside] ** 3).sum())))
            expected = (self.amount * self.volume - held) / self.distribution.volume_expected
        if expected <= 0:
            return 0
        whole = math.floor(expected)
        odds = np.random.default_rng([self.seed, sim.step, 1]).random()
        return whole + (1 if odds < expected - whole else 0)
