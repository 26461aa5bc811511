r"""Pair styles ``dpd/ext`` and ``dpd/ext/tstat``: dissipative particle dynamics with friction and noise
along and across the line of centres, each with its own weight exponent (Junghans, Praprotnik and
Kremer, Soft Matter 4, 156 (2008); LAMMPS's pair dpd/ext and dpd/ext/tstat).

With :math:`\hat{\mathbf{r}} = \mathbf{r}_{ij}/r`, :math:`\mathbf{v}_{ij} = \mathbf{v}_i - \mathbf{v}_j`,
:math:`w = 1 - r/r_c`, :math:`w_\parallel = w^{s_\parallel}`, :math:`w_\perp = w^{s_\perp}` and
:math:`\mathsf{P} = \mathsf{I} - \hat{\mathbf{r}}\hat{\mathbf{r}}` (the projection across the line):

.. math::

    \mathbf{F}_{ij} = \left[a\,w - \gamma_\parallel w_\parallel^2\,(\hat{\mathbf{r}}\cdot\mathbf{v}_{ij})
        + \sigma_\parallel w_\parallel\,\xi\,\Delta t^{-1/2}\right]\hat{\mathbf{r}}
        - \gamma_\perp w_\perp^2\,\mathsf{P}\mathbf{v}_{ij}
        + \sigma_\perp w_\perp\,\mathsf{P}\boldsymbol{\xi}\,\Delta t^{-1/2},
    \qquad \sigma^2 = 2 k_B T \gamma

for both the parallel and the perpendicular part, :math:`\xi` and the three components of
:math:`\boldsymbol{\xi}` standard normal numbers drawn per pair and step. The force across the line
makes the pair force non-central, so the style has its own loop over the half neighbor list (the
core's loop takes central laws). The noise is pdps's counter-based one, keyed by (seed, step, the
two ids) and oriented from the smaller id to the larger, so a run is the same on any number of
ranks; LAMMPS's draws differ, so runs agree with LAMMPS's statistically. The energy is the
conservative part's, :math:`\tfrac12 a r_c w^2`. ``dpd/ext/tstat`` is the thermostat alone (a = 0,
no energy), with the target temperature ramped over the run from Tstart to Tstop, as dpd/tstat,
for use under ``pair_style hybrid/overlay``.

Parameters:

- ``pair_style dpd/ext T RC SEED``; ``pair_style dpd/ext/tstat TSTART TSTOP RC SEED``: temperatures
  (>= 0), the global cutoff (> 0, distance), the seed (>= 1).
- ``pair_coeff I J A GAMMA_PAR GAMMA_PERP S_PAR S_PERP [RC]`` (dpd/ext) and ``pair_coeff I J
  GAMMA_PAR GAMMA_PERP S_PAR S_PERP [RC]`` (dpd/ext/tstat): ``A`` the repulsion (force), the
  frictions (force/velocity, >= 0), the weight exponents (dimensionless), this pair's cutoff.

Every type pair is given (LAMMPS's dpd/ext does not mix). Ghosts carry velocities.

Example (LAMMPS's dpdext example)::

    pair_style dpd/ext 1.0 1.0 3854262
    pair_coeff 1 1 25.0 4.5 4.53 0.5 0.53 1.2
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import Pair, ScriptError, StyleArgs, pair_gaussian, param

EPSILON = 1.0e-10       # coincident particles have no direction (skipped, as LAMMPS's)
# coeff columns
A, GAMMA, GAMMA_PERP, SIGMA, SIGMA_PERP, S_PAR, S_PERP, CUT = range(8)


@njit(cache=True)
def dpd_ext_forces(x, v, f, types, tags, nlocal, offsets, neighbors, cutsq, coeff, noise_scale, seed, step,
                   dt_inv_sqrt, eflag):
    """The docstring's forces over a half list; the conservative energy when eflag. noise_scale
    multiplies both sigmas (sqrt(k_B T(t)) for the ramped thermostat, 1 otherwise)."""
    energy = 0.0
    counter = 4 * step
    for i in range(nlocal):
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            dx = x[i, 0] - x[j, 0]
            dy = x[i, 1] - x[j, 1]
            dz = x[i, 2] - x[j, 2]
            rsq = dx * dx + dy * dy + dz * dz
            ti = types[i]
            tj = types[j]
            if rsq >= cutsq[ti, tj]:
                continue
            r = math.sqrt(rsq)
            if r < EPSILON:
                continue
            c = coeff[ti, tj]
            rinv = 1.0 / r
            ux = dx * rinv
            uy = dy * rinv
            uz = dz * rinv
            dvx = v[i, 0] - v[j, 0]
            dvy = v[i, 1] - v[j, 1]
            dvz = v[i, 2] - v[j, 2]
            along = ux * dvx + uy * dvy + uz * dvz
            w = 1.0 - r / c[CUT]
            w_par = w ** c[S_PAR]
            w_perp = w ** c[S_PERP]
            # one number along the line and a vector across it, the vector pointing from the smaller id
            sign = 1.0 if tags[i] < tags[j] else -1.0
            xi = pair_gaussian(seed, counter, tags[i], tags[j])
            xix = sign * pair_gaussian(seed, counter + 1, tags[i], tags[j])
            xiy = sign * pair_gaussian(seed, counter + 2, tags[i], tags[j])
            xiz = sign * pair_gaussian(seed, counter + 3, tags[i], tags[j])
            f_along = (c[A] * w - c[GAMMA] * w_par * w_par * along
                       + noise_scale * c[SIGMA] * w_par * xi * dt_inv_sqrt)
            drag = c[GAMMA_PERP] * w_perp * w_perp
            kick = noise_scale * c[SIGMA_PERP] * w_perp * dt_inv_sqrt
            xi_along = ux * xix + uy * xiy + uz * xiz
            fx = f_along * ux - drag * (dvx - along * ux) + kick * (xix - xi_along * ux)
            fy = f_along * uy - drag * (dvy - along * uy) + kick * (xiy - xi_along * uy)
            fz = f_along * uz - drag * (dvz - along * uz) + kick * (xiz - xi_along * uz)
            f[i, 0] += fx
            f[i, 1] += fy
            f[i, 2] += fz
            f[j, 0] -= fx
            f[j, 1] -= fy
            f[j, 2] -= fz
            if eflag:
                energy += 0.5 * c[A] * c[CUT] * w * w
    return energy


class PairDPDExt(Pair):
    name = "dpd/ext"
    usage = "pair_style dpd/ext T RC SEED"
    coeff_usage = "A GAMMA_PAR GAMMA_PERP S_PAR S_PERP [RC]"
    neighbor_list = "half"
    ghost_velocity = True
    hybrid_sub_style = True     # its loop skips the type pairs of cutoff 0

    class Args(StyleArgs):
        temperature: float = param(ge=0, unit="temperature")
        cutoff: float = param(gt=0, unit="distance")
        seed: int = param(ge=1, lt=2**63, unit="dimensionless")

    class Coeff(StyleArgs):
        a: float = param(unit="force")
        gamma: float = param(ge=0, unit="force/velocity")
        gamma_perp: float = param(ge=0, unit="force/velocity")
        s_par: float = param(unit="dimensionless")
        s_perp: float = param(unit="dimensionless")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def mix(self, i, j):
        raise ScriptError(f"pair coefficients are not set for types {i} {j} (pair style {self.name} does not mix: "
                          "give pair_coeff for every type pair, as LAMMPS's)")

    def init(self, ntypes, pairs=None):
        self.coeff_table = np.zeros((ntypes + 1, ntypes + 1, 8))
        cut = super().init(ntypes, pairs)
        self.cutsq = cut * cut
        return cut

    def conservative(self, c):
        return c.a

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        cut = c.cutoff if c.cutoff is not None else self.args.cutoff
        kT = self.sigma_temperature()
        row = (self.conservative(c), c.gamma, c.gamma_perp, math.sqrt(2.0 * kT * c.gamma),
               math.sqrt(2.0 * kT * c.gamma_perp), c.s_par, c.s_perp, cut)
        self.coeff_table[i, j] = self.coeff_table[j, i] = row
        return cut

    def sigma_temperature(self):
        """k_B T of the sigmas (the pair_style line's temperature)."""
        return self.sim.units.boltz * self.args.temperature

    def noise_scale(self, sim):
        return 1.0

    def compute(self, sim, nlist, eflag, vflag):
        p = sim.particles
        a = p.arrays
        self.energy = dpd_ext_forces(a["x"], a["v"], a["f"], a["type"], a["tag"], p.nlocal, nlist.offsets,
                                     nlist.neighbors, self.cutsq, self.coeff_table, self.noise_scale(sim),
                                     sim.random_key(self.args.seed), sim.step, 1.0 / math.sqrt(sim.dt), bool(eflag))


class PairDPDExtTstat(PairDPDExt):
    name = "dpd/ext/tstat"
    usage = "pair_style dpd/ext/tstat TSTART TSTOP RC SEED"
    coeff_usage = "GAMMA_PAR GAMMA_PERP S_PAR S_PERP [RC]"

    class Args(StyleArgs):
        t_start: float = param(ge=0, unit="temperature")
        t_stop: float = param(ge=0, unit="temperature")
        cutoff: float = param(gt=0, unit="distance")
        seed: int = param(ge=1, lt=2**63, unit="dimensionless")

    class Coeff(StyleArgs):
        gamma: float = param(ge=0, unit="force/velocity")
        gamma_perp: float = param(ge=0, unit="force/velocity")
        s_par: float = param(unit="dimensionless")
        s_perp: float = param(unit="dimensionless")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def conservative(self, c):
        return 0.0

    def sigma_temperature(self):
        # sigmas for k_B T = 1: noise_scale gives sqrt(k_B T(t)) at each step
        return 1.0

    def noise_scale(self, sim):
        return math.sqrt(sim.units.boltz * sim.ramp(self.args.t_start, self.args.t_stop))
