r"""Pair style ``dpd``: dissipative particle dynamics (Hoogerbrugge & Koelman 1992; Groot & Warren,
J. Chem. Phys. 107, 4423 (1997)).

Between particles i and j closer than the cutoff :math:`r_c`, with :math:`\mathbf{r}_{ij} = \mathbf{r}_i
- \mathbf{r}_j`, :math:`\hat{\mathbf{r}}_{ij} = \mathbf{r}_{ij}/r_{ij}`, :math:`\mathbf{v}_{ij} =
\mathbf{v}_i - \mathbf{v}_j` and the weight :math:`w = 1 - r_{ij}/r_c`:

.. math::

    \mathbf{F}_{ij} = \left[ a\,w \;-\; \gamma\, w^2 (\hat{\mathbf{r}}_{ij}\cdot\mathbf{v}_{ij})
                      \;+\; \sigma\, w\, \xi_{ij}\, \Delta t^{-1/2} \right] \hat{\mathbf{r}}_{ij},
    \qquad \sigma^2 = 2 k_B T \gamma

:math:`\xi_{ij}` is a standard normal number, the same for (i, j) and (j, i), drawn from a counter-based
generator keyed by (seed, step, tag_i, tag_j): the noise does not depend on particle order or on how the
box is split over ranks. The potential energy counts the conservative part only,
:math:`E = \tfrac12 a r_c w^2`. Pairs closer than 1e-10 are skipped (coincident particles have no
defined direction), as in LAMMPS.

Parameters (LAMMPS/PDPS units of the run):

- ``pair_style dpd T rc seed``: ``T`` temperature (> = 0, temperature units), ``rc`` global cutoff
  (> 0, distance), ``seed`` integer >= 1.
- ``pair_coeff I J a gamma [rc]``: ``a`` repulsion (force), ``gamma`` friction (>= 0, force/velocity),
  ``rc`` cutoff of this pair (distance; default the global one).

Every type pair must be given, or derived from the i i and j j coefficients with ``pair_modify mix
geometric`` (:math:`a_{ij} = \sqrt{a_i a_j}`, likewise gamma and rc) or ``arithmetic``
(:math:`a_{ij} = (a_i + a_j)/2`, likewise gamma and rc). Ghosts carry velocities (the dissipative force
needs v_j).

Example (the PDPS manual's water)::

    pair_style dpd 1.0 1.0 3442527
    pair_coeff * * 25.0 4.5 1.0
"""

import math

import numpy as np
from numba import njit
from pydantic import Field

from pdps_core.api import Pair, ScriptError, StyleArgs, pair_gaussian

EPSILON = 1.0e-10


@njit(cache=True)
def dpd_compute(x, v, f, type_, tag, offsets, neighbors, nlocal, a, gamma, sigma, cut,
                dt_inv_sqrt, seed, step, eflag):
    energy = 0.0
    for i in range(nlocal):
        ti = type_[i]
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            tj = type_[j]
            delx = x[i, 0] - x[j, 0]
            dely = x[i, 1] - x[j, 1]
            delz = x[i, 2] - x[j, 2]
            rsq = delx * delx + dely * dely + delz * delz
            rc = cut[ti, tj]
            if rsq >= rc * rc:
                continue
            r = math.sqrt(rsq)
            if r < EPSILON:
                continue
            rinv = 1.0 / r
            dot = (delx * (v[i, 0] - v[j, 0]) + dely * (v[i, 1] - v[j, 1])
                   + delz * (v[i, 2] - v[j, 2]))
            w = 1.0 - r / rc
            xi = pair_gaussian(seed, step, tag[i], tag[j])
            fpair = (a[ti, tj] * w - gamma[ti, tj] * w * w * dot * rinv
                     + sigma[ti, tj] * w * xi * dt_inv_sqrt) * rinv
            f[i, 0] += delx * fpair
            f[i, 1] += dely * fpair
            f[i, 2] += delz * fpair
            f[j, 0] -= delx * fpair
            f[j, 1] -= dely * fpair
            f[j, 2] -= delz * fpair
            if eflag:
                energy += 0.5 * a[ti, tj] * rc * w * w
    return energy


class PairDPD(Pair):
    name = "dpd"
    usage = "pair_style dpd T rc seed"
    coeff_usage = "a gamma [rc]"
    ghost_velocity = True

    class Args(StyleArgs):
        temperature: float = Field(ge=0)
        cutoff: float = Field(gt=0)
        seed: int = Field(ge=1, lt=2**63)

    class Coeff(StyleArgs):
        a: float
        gamma: float = Field(ge=0)
        cutoff: float | None = Field(default=None, gt=0)

    def mix_coeff(self, ci, cj, rule):
        combine = (lambda p, q: math.sqrt(p * q)) if rule == "geometric" else (lambda p, q: 0.5 * (p + q))
        rc_i = ci.cutoff if ci.cutoff is not None else self.args.cutoff
        rc_j = cj.cutoff if cj.cutoff is not None else self.args.cutoff
        if rule == "geometric" and ci.a * cj.a < 0:
            raise ScriptError("geometric mixing needs a of one sign for both types")
        return self.Coeff(a=combine(ci.a, cj.a), gamma=combine(ci.gamma, cj.gamma),
                          cutoff=combine(rc_i, rc_j))

    def init(self, ntypes):
        shape = (ntypes + 1, ntypes + 1)
        self.a, self.gamma, self.sigma, self.cut = (np.zeros(shape) for _ in range(4))
        return super().init(ntypes)

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        cut = c.cutoff if c.cutoff is not None else self.args.cutoff
        kT = self.sim.units.boltz * self.args.temperature
        for table, value in ((self.a, c.a), (self.gamma, c.gamma), (self.cut, cut),
                             (self.sigma, math.sqrt(2.0 * kT * c.gamma))):
            table[i, j] = table[j, i] = value
        return cut

    def compute(self, sim, nlist, eflag, vflag):
        p = sim.particles
        self.energy = dpd_compute(p.x, p.v, p.f, p.type, p.tag, nlist.offsets, nlist.neighbors,
                                  p.nlocal, self.a, self.gamma, self.sigma, self.cut,
                                  1.0 / math.sqrt(sim.dt), self.args.seed, sim.step, eflag)
