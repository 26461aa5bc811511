r"""Fix ``insert/pack``: fill a region up to a target, once or every N steps (LIGGGHTS's fix
insert/pack).

Syntax::

    fix ID GROUP insert/pack seed S distributiontemplate DIST [general keywords] region REGION
        volumefraction_region VF | particles_in_region N | mass_in_region M  [ntry_mc N]
        [check_dist_from_subdomain_border yes|no]

At each insertion step the fix counts what the region holds (particles whose centre it matches)
and inserts the difference to the target:

- ``particles_in_region N``: :math:`N - N_\mathrm{in}` particles;
- ``mass_in_region M``: :math:`(M - M_\mathrm{in})/\langle m\rangle` particles, with
  :math:`\langle m\rangle` the distribution's expected particle mass;
- ``volumefraction_region VF`` (0 < VF < 1): :math:`(VF\,V - V_\mathrm{in})/\langle V\rangle`
  particles, V the region's volume inside the box, measured once by ``ntry_mc`` uniform points of its
  extent (default 100000; the relative error is about :math:`\sqrt{(1-f)/(f\,n)}` for a region
  filling a share f of its extent);

whichever the target, the region's volume so measured must reach its ``volume_limit`` (default
1e-10), else the run stops at the first insertion, as LIGGGHTS's region.cpp stops it;

a fractional count rounded up or down at random with the odds that keep it unbiased (as LIGGGHTS
says of its mass-based counts). The particles go where the region matches (``all_in yes``: wholly
inside it, for regions whose surface distance pdps knows: those that can be walls), clear of every
present particle and of each other, with maxattempt x count / (1 - H/T) random positions among them
for a region holding H of its target T (LIGGGHTS's budget, which grows as the region fills). With
``check_dist_from_subdomain_border yes`` (the default) a position whose centre lies less than the
sphere's radius from a face of the box, periodic or not, is a failed try, as in LIGGGHTS, whose test
is against its subdomain's faces (pdps places the same particles on any rank count, so against the
box's); ``no`` allows it. insertion.py
gives the general keywords, the velocities and why the same particles appear on any number of
ranks. ``insert_every`` defaults to once; the default start is the next step.

Example (LIGGGHTS's)::

    region bc cylinder z 0.0 0.0 0.045 0.00 0.15 units box
    fix ins all insert/pack seed 32452843 distributiontemplate pdd vel constant 0. 0. -0.5 &
        insert_every once overlapcheck yes all_in yes particles_in_region 1800 region bc
"""

import math

import numpy as np

from pdps_core.api import ScriptError, keyword

from .insertion import FixInsert, InsertArgs, YesNo
from .whole_number import WholeNumber
from .region_volume import InRegion, insertion_region, region_volume

TARGETS = ("volumefraction_region", "particles_in_region", "mass_in_region")
NTRY_MC_MAX = 100_000_000


class FixInsertPack(InRegion, FixInsert):
    name = "insert/pack"
    usage = ("fix ID GROUP insert/pack seed S distributiontemplate DIST [keywords] region REGION "
             "volumefraction_region VF | particles_in_region N | mass_in_region M [ntry_mc N]")

    class Args(InsertArgs):
        region: str = keyword(..., names="region ID")
        volumefraction_region: float | None = keyword(None, unit="dimensionless")
        particles_in_region: WholeNumber | None = keyword(None, ge=0, unit="particles")
        mass_in_region: float | None = keyword(None, gt=0, unit="mass")
        ntry_mc: WholeNumber = keyword(100_000, ge=1000, unit="1")
        check_dist_from_subdomain_border: YesNo = keyword("yes")

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        targets = [t for t in TARGETS if getattr(args, t) is not None]
        if len(targets) != 1:
            raise ScriptError("give exactly one of volumefraction_region, particles_in_region, mass_in_region "
                              f"(got {', '.join(targets) or 'none'})")
        fraction = args.volumefraction_region
        if fraction is not None and not 0 < fraction < 1:
            raise ScriptError(f"volumefraction_region must be > 0 and < 1 (got {fraction:g})")
        if args.ntry_mc > NTRY_MC_MAX:
            raise ScriptError(f"ntry_mc must be at most {NTRY_MC_MAX} (got {args.ntry_mc:g})")

    def read_style(self, sim, args):
        self.region = insertion_region(sim, args.region)
        self.read_border(args)
        self.target = next(t for t in TARGETS if getattr(args, t) is not None)
        self.amount = getattr(args, self.target)
        self.ntry_mc = args.ntry_mc
        self.volume = None

    def wanted(self, sim):
        if self.volume is None:
            self.volume = region_volume(self.region, sim.box, np.random.default_rng([self.seed, 0]), self.ntry_mc)
            if self.volume < self.region.volume_limit:
                raise ScriptError(f"the volume of region {self.region.id} in the box, {self.volume:.6g} by "
                                  f"{self.ntry_mc} Monte Carlo points, is below its volume_limit "
                                  f"{self.region.volume_limit:g} (LIGGGHTS's check; lower volume_limit on the region)")
        p = sim.particles
        n = p.nlocal
        inside = self.region.match(p.x[:n])
        if self.target == "particles_in_region":
            held = int(sim.comm.sum(int(inside.sum())))
            self.filled = share(held, self.amount)
            return self.amount - held
        if self.target == "mass_in_region":
            held = float(sim.comm.sum(float(p.rmass[:n][inside].sum())))
            self.filled = share(held, self.amount)
            expected = (self.amount - held) / self.distribution.mass_expected
        else:
            held = float(sim.comm.sum(float((4.0 / 3.0 * math.pi * p.radius[:n][inside] ** 3).sum())))
            self.filled = share(held, self.amount * self.volume)
            expected = (self.amount * self.volume - held) / self.distribution.volume_expected
        if expected <= 0:
            return 0
        whole = math.floor(expected)
        odds = np.random.default_rng([self.seed, sim.step, 1]).random()
        return whole + (1 if odds < expected - whole else 0)


def share(held, target):
    """What the region holds as a share of the target, within [0, 1]."""
    return min(max(held / target, 0.0), 1.0) if target > 0 else 1.0
