r"""Fix ``check/timestep/gran``: checks every NEVERY steps that the time step resolves granular
contacts and that the neighbor skin covers a step's motion (LIGGGHTS's fix check/timestep/gran).

Three ratios are computed:

.. math::

    \frac{\Delta t}{t_R}, \qquad \frac{\Delta t}{t_H}, \qquad \frac{v_{max}\,\Delta t}{r_{skin}}

where :math:`t_R = \pi R \sqrt{\rho/G} / (0.1631\nu + 0.8766)` is the Rayleigh time (the smallest
over the particles), :math:`t_H` LIGGGHTS's estimate of the Hertz collision time (each particle
against its copy: :math:`2.87 (m^2/(R^* Y^{*2} v))^{1/5}` with :math:`m` the particle's full mass,
:math:`R^* = R/2` and :math:`v = 2 v_{max}`, the smallest over the particles; recorded equal to
LIGGGHTS 3.8.0 on every row of a three-sphere scene), :math:`v_{max}` the largest particle speed of the
group and :math:`r_{skin}` the neighbor skin. A warning names the limit passed and gives the three
ratios when :math:`\Delta t > f_R t_R`, :math:`\Delta t > f_H t_H` or :math:`v_{max}\Delta t > r_{skin}`
(particles could cross the skin in one step, so contacts could be found late); it is given again only
when a limit is passed that was not at the previous check. The ratios of the last check are kept in
``ratios`` and read as LIGGGHTS's vector of this fix: ``f_ID[1]`` :math:`\Delta t/t_R`, ``f_ID[2]``
:math:`\Delta t/t_H`, ``f_ID[3]`` the skin ratio at LIGGGHTS's relative speed :math:`2 v_{max}` (0 for a
ratio with nothing to measure). The check also runs at the start of each run, for its warning; the
ratios it reads then are published only by the checks every NEVERY steps, so a run's first thermo
row shows the previous run's ratios (zeros before any), as LIGGGHTS's.

The times come from the pair style: its ``timestep_limits(sim)`` returns
``{"rayleigh": t_R or None, "hertz": t_H or None, "contact": t_c}``. When it gives neither a
Rayleigh nor a Hertz time (a linear spring-dashpot has no material moduli) its contact time
:math:`t_c` takes the Hertz time's place, labelled ``contact``; a Hertz time of None with a
Rayleigh time (nothing moves yet) leaves that ratio out, as LIGGGHTS. A pair style without ``timestep_limits``, or no pair style, is reported once and only
the skin ratio is checked.

pdps compares a particle's own displacement per step with the skin, as the skin is a distance each
particle may move before lists are rebuilt; LIGGGHTS uses the relative speed of two particles,
:math:`2 v_{max}`, so its skin ratio is twice this one.

Parameters:

- ``NEVERY``: check every this many steps (>= 1).
- ``FRACTION_R``: warn when dt exceeds this fraction of the Rayleigh time (> 0; LIGGGHTS
  suggests 0.1-0.2).
- ``FRACTION_H``: warn when dt exceeds this fraction of the Hertz (or contact) time (> 0).
- ``error yes|no`` (optional, LIGGGHTS; default no): stop the run instead of warning.
- ``warn yes|no`` (optional, LIGGGHTS; default yes): ``no`` gives no warning (the ratios are still
  kept for ``f_ID``).
- ``vmax V`` (optional, LIGGGHTS): the largest speed is at least V (velocity units): the Hertz time
  and the skin ratio are those of V when the particles are slower, as for a scene about to be
  filled.

Syntax::

    fix ID GROUP check/timestep/gran NEVERY FRACTION_R FRACTION_H [error yes|no] [warn yes|no] [vmax V]

Example::

    fix ts all check/timestep/gran 1000 0.1 0.1
"""

import math

import numpy as np
from pdps_core.api import ContactTimes, Fix, SimulationError, StyleArgs, keyword, param

from ._common import chosen


def _ratio(value):
    return "n/a" if value is None else f"{value:.4g}"


class FixCheckTimestepGran(Fix):
    name = "check/timestep/gran"
    usage = "fix ID GROUP check/timestep/gran NEVERY FRACTION_R FRACTION_H [error yes|no] [warn yes|no] [vmax V]"

    class Args(StyleArgs):
        nevery: int = param(ge=1, unit="timesteps")
        fraction_r: float = param(gt=0, unit="dimensionless")
        fraction_h: float = param(gt=0, unit="dimensionless")
        error: bool = keyword(False)
        warn: bool = keyword(True)
        vmax: float = keyword(0.0, ge=0, unit="velocity")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.ratios = (None, None, None)
        self._passed = frozenset()
        self._told_no_limits = set()

    def setup(self, sim):
        self._passed = frozenset()
        self.check(sim, publish=False)

    def vector(self, sim):
        rayleigh, collision, skin = (0.0 if r is None else r for r in self.ratios)
        return np.array([rayleigh, collision, 2.0 * skin])

    def end_of_step(self, sim):
        if sim.step % self.args.nevery == 0:
            self.check(sim)

    def _limits(self, sim):
        pair = sim.pair
        if isinstance(pair, ContactTimes):
            return pair.timestep_limits(sim, self.args.vmax) or {}
        reason = ("no pair style is defined" if pair is None else
                  f"pair style {pair.name} gives no time-step limits (it has no timestep_limits method)")
        if reason not in self._told_no_limits:
            self._told_no_limits.add(reason)
            sim.warn(f"fix {self.id} (check/timestep/gran): {reason}, so only the skin ratio is checked")
        return {}

    def check(self, sim, publish=True):
        """Compute the three ratios (kept for f_ID when ``publish``); warn (or stop) when a limit is
        newly passed."""
        dt, skin = sim.dt, sim.neighbor.skin
        limits = self._limits(sim)
        rayleigh = limits.get("rayleigh")
        collision, label = limits.get("hertz"), "Hertz"
        if not collision and not rayleigh and limits.get("contact"):
            # no material times at all (a linear spring-dashpot): its contact time is the limit
            collision, label = limits["contact"], "contact"
        p = sim.particles
        v = p.v[: p.nlocal][chosen(sim, self.group)]
        speed = max(self.args.vmax, math.sqrt(sim.comm.max(float(np.einsum("ij,ij->i", v, v).max(initial=0.0)))))
        ratio_r = dt / rayleigh if rayleigh else None
        ratio_h = dt / collision if collision else None
        ratio_s = speed * dt / skin if skin > 0 else None
        if publish:
            self.ratios = (ratio_r, ratio_h, ratio_s)

        passed, clauses = set(), []
        if ratio_r is not None and ratio_r > self.args.fraction_r:
            passed.add("rayleigh")
            clauses.append(f"time step {dt:g} exceeds {self.args.fraction_r:g} of the Rayleigh time "
                           f"{rayleigh:.4g}")
        if ratio_h is not None and ratio_h > self.args.fraction_h:
            passed.add(label)
            clauses.append(f"time step {dt:g} exceeds {self.args.fraction_h:g} of the {label} time "
                           f"{collision:.4g}")
        if ratio_s is not None and ratio_s > 1.0:
            passed.add("skin")
            clauses.append(f"particles move up to {speed * dt:.4g} per step, more than the skin {skin:g}")
        new = passed - self._passed
        self._passed = frozenset(passed)
        if not new:
            return
        message = (f"fix {self.id} (check/timestep/gran) at step {sim.step}: {'; '.join(clauses)} "
                   f"(dt/t_rayleigh = {_ratio(ratio_r)}, dt/t_{label.lower()} = {_ratio(ratio_h)}, "
                   f"v_max*dt/skin = {_ratio(ratio_s)})")
        if self.args.error:
            raise SimulationError(message)
        if self.args.warn:
            sim.warn(message)
