r"""Pair style ``dpd/tstat``: the DPD thermostat alone, LAMMPS's pair dpd/tstat: pair dpd's dissipative
and random forces without the conservative one (``pdps doc pair dpd`` has the law),

.. math::

    \mathbf{F}_{ij} = \left[-\gamma\, w^2 (\hat{\mathbf{r}}_{ij}\cdot\mathbf{v}_{ij})
                      + \sigma\, w\, \xi_{ij}\, \Delta t^{-1/2}\right] \hat{\mathbf{r}}_{ij},
    \qquad \sigma^2 = 2 k_B T(t) \gamma, \quad w = 1 - r_{ij}/r_c,

with the target temperature ramped linearly over the run, :math:`T(t) = T_{start} + (T_{stop} -
T_{start})\,(n - n_0)/(n_1 - n_0)` at step n of a run from step :math:`n_0` to :math:`n_1` (of ``run N
start/stop`` when given), as LAMMPS. A thermostat for another pair style, under ``pair_style
hybrid/overlay``; it adds no energy. The noise is pair dpd's (counter-based, the same on any number
of ranks): LAMMPS's draws differ, so runs agree with LAMMPS's statistically; with T = 0 (friction
alone) they agree step for step (tests/test_dpd_tstat.py).

Parameters: ``pair_style dpd/tstat Tstart Tstop rc seed [noise gaussian|uniform]`` (temperatures >= 0,
rc > 0 distance, seed >= 1); ``pair_coeff I J gamma [rc]`` (gamma >= 0, force/velocity). Mixing as
pair dpd's (gamma and rc).

Example (LAMMPS)::

    pair_style hybrid/overlay lj/cut 2.5 dpd/tstat 1.0 1.0 2.5 34387
    pair_coeff * * lj/cut 1.0 1.0
    pair_coeff * * dpd/tstat 4.5
"""

import math
from typing import Literal

from pdps_core.api import StyleArgs, keyword, param

from .dpd import PairDPD


class PairDPDTstat(PairDPD):
    name = "dpd/tstat"
    usage = "pair_style dpd/tstat Tstart Tstop rc seed [noise gaussian|uniform]"
    coeff_usage = "gamma [rc]"

    class Args(StyleArgs):
        t_start: float = param(ge=0, unit="temperature")
        t_stop: float = param(ge=0, unit="temperature")
        cutoff: float = param(gt=0, unit="distance")
        seed: int = param(ge=1, lt=2**63, unit="dimensionless")
        noise: Literal["gaussian", "uniform"] = keyword("gaussian")

    class Coeff(StyleArgs):
        gamma: float = param(ge=0, unit="force/velocity")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def mix_coeff(self, ci, cj, rule):
        combine = (lambda p, q: math.sqrt(p * q)) if rule == "geometric" else (lambda p, q: 0.5 * (p + q))
        rc_i = ci.cutoff if ci.cutoff is not None else self.args.cutoff
        rc_j = cj.cutoff if cj.cutoff is not None else self.args.cutoff
        return self.Coeff(gamma=combine(ci.gamma, cj.gamma), cutoff=combine(rc_i, rc_j))

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        cut = c.cutoff if c.cutoff is not None else self.args.cutoff
        # sigma for k_B T = 1: law_state scales the noise by sqrt(k_B T(t)) at each step
        sigma = math.sqrt(2.0 * c.gamma)
        for table, value in ((self.a, 0.0), (self.gamma, c.gamma), (self.cut, cut), (self.sigma, sigma)):
            table[i, j] = table[j, i] = value
        return cut, (0.0, c.gamma, sigma, cut)

    def law_state(self, sim):
        temperature = sim.ramp(self.args.t_start, self.args.t_stop)
        kT = sim.units.boltz * temperature
        return (sim.random_key(self.args.seed), sim.step, math.sqrt(kT / sim.dt))
