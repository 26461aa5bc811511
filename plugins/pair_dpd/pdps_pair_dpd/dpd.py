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
box is split over ranks (normal numbers by Marsaglia and Tsang's ziggurat). With ``noise uniform``,
:math:`\xi_{ij}` is instead uniform on :math:`[-\sqrt3, \sqrt3]` (zero mean, unit variance), Groot and
Warren's choice: the fluctuation-dissipation theorem needs only the variance, and the uniform number
is cheaper; docs/performance.md gives what it saves and what it changes. The potential energy counts
the conservative part only,
:math:`E = \tfrac12 a r_c w^2`. Pairs closer than 1e-10 are skipped (coincident particles have no
defined direction), as in LAMMPS.

Parameters (LAMMPS/PDPS units of the run):

- ``pair_style dpd T rc seed [noise gaussian|uniform]``: ``T`` temperature (> = 0, temperature
  units), ``rc`` global cutoff (> 0, distance), ``seed`` integer >= 1; ``noise`` the distribution of
  the random numbers (default gaussian, as LAMMPS; ``noise`` is pdps's own keyword).
- ``pair_coeff I J a gamma [rc]``: ``a`` repulsion (force), ``gamma`` friction (>= 0, force/velocity),
  ``rc`` cutoff of this pair (distance; default the global one).

Every type pair must be given, or derived from the i i and j j coefficients with ``pair_modify mix
geometric`` (:math:`a_{ij} = \sqrt{a_i a_j}`, likewise gamma and rc) or ``arithmetic``
(:math:`a_{ij} = (a_i + a_j)/2`, likewise gamma and rc). Ghosts carry velocities (the dissipative force
needs v_j).

Stability check. At the start of each run the style estimates, for every type pair, how stiff the
fluid is for the time step, using the mean number of neighbors within the cutoff
:math:`n_c = \rho\, \tfrac{4}{3}\pi r_c^3` (:math:`\rho\pi r_c^2` in 2-d):

.. math::

    S_C = \Delta t \sqrt{\frac{n_c\, a}{r_c\, m}}, \qquad
    S_D = \Delta t\, \frac{\gamma\, n_c \langle w^2 \rangle}{m}, \quad
    \langle w^2\rangle = \tfrac{1}{10}\ (\tfrac16 \text{ in 2-d})

and warns, naming the setting, when :math:`S_C > 1.2` or :math:`S_D > 1`. Calibration with fix nve
(docs/accuracy-dpd.md): the PDPS water example (rho = 4, gamma = 4.5, dt = 0.04) gives T = 1.03 at
a = 25 (S_C = 0.82), 1.04 at a = 50 (1.16), 1.05 at a = 100 (1.64), 1.11 at a = 150 (2.0), 1.30 at
a = 200 (2.3) and blows up at a = 300 (2.8); the Groot-Warren fluid (rho = 3, a = 25) gives
T = 1.03 at dt = 0.04 (S_C = 0.71), 1.06 at 0.06 (1.06), 1.13 at 0.08 (1.42), 1.34 at 0.1 (1.77).

Example (the PDPS manual's water)::

    pair_style dpd 1.0 1.0 3442527
    pair_coeff * * 25.0 4.5 1.0
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import PairLaw, ScriptError, StyleArgs, keyword, observables, param, pair_gaussian, pair_uniform

EPSILON = 1.0e-10        # the core's pair loop skips pairs closer than this (coincident particles)
STIFFNESS_LIMIT = 1.2     # dt*sqrt(n_c a/(rc m)) above which T runs hot by more than ~5 % (docstring)
SQRT3 = math.sqrt(3.0)


@njit(cache=True, inline="always")
def dpd_pair(rsq, dot, coeff, xi, dt_inv_sqrt):
    """F/r and the conservative energy of one pair from r^2, r_ij . v_ij and the noise xi (the
    docstring formula); coeff = (a, gamma, sigma, rc)."""
    a, gamma, sigma, rc = coeff[0], coeff[1], coeff[2], coeff[3]
    r = math.sqrt(rsq)
    rinv = 1.0 / r
    w = 1.0 - r / rc
    fpair = a * w - gamma * w * w * dot * rinv + sigma * w * xi * dt_inv_sqrt
    return fpair * rinv, 0.5 * a * rc * w * w


@njit(cache=True, inline="always")
def dpd_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """The force law with Gaussian noise; atom = (v, tag), state = (seed, step, 1/sqrt(dt))."""
    v, tag = atom
    seed, step, dt_inv_sqrt = state
    dot = dx * (v[i, 0] - v[j, 0]) + dy * (v[i, 1] - v[j, 1]) + dz * (v[i, 2] - v[j, 2])
    return dpd_pair(rsq, dot, coeff, pair_gaussian(seed, step, tag[i], tag[j]), dt_inv_sqrt)


@njit(cache=True, inline="always")
def dpd_uniform_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """The force law with uniform noise of unit variance, sqrt(3) (2u - 1) (``noise uniform``)."""
    v, tag = atom
    seed, step, dt_inv_sqrt = state
    dot = dx * (v[i, 0] - v[j, 0]) + dy * (v[i, 1] - v[j, 1]) + dz * (v[i, 2] - v[j, 2])
    xi = SQRT3 * (2.0 * pair_uniform(seed, step, tag[i], tag[j]) - 1.0)
    return dpd_pair(rsq, dot, coeff, xi, dt_inv_sqrt)


@njit(cache=True, inline="always")
def dpd_conservative_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """The conservative part alone, for a splitting integrator (fix shardlow) that takes friction
    and noise."""
    a, rc = coeff[0], coeff[3]
    r = math.sqrt(rsq)
    w = 1.0 - r / rc
    return a * w / r, 0.5 * a * rc * w * w


class PairDPD(PairLaw):
    name = "dpd"
    usage = "pair_style dpd T rc seed [noise gaussian|uniform]"
    coeff_usage = "a gamma [rc]"
    ghost_velocity = True
    params = ("a", "gamma", "sigma", "rc")
    law_atom = ("v", "tag")
    law = staticmethod(dpd_law)
    uniform_law = staticmethod(dpd_uniform_law)
    conservative_law = staticmethod(dpd_conservative_law)
    single_law = conservative_law       # Pair.single: a0 w / r and 1/2 a rc w^2, as LAMMPS's dpd
    split = False       # True when a splitting integrator (fix shardlow) takes the friction and noise

    class Args(StyleArgs):
        temperature: float = param(ge=0, unit="temperature")
        cutoff: float = param(gt=0, unit="distance")
        seed: int = param(ge=1, lt=2**63, unit="dimensionless")
        noise: Literal["gaussian", "uniform"] = keyword("gaussian")

    class Coeff(StyleArgs):
        a: float = param(unit="force")
        gamma: float = param(ge=0, unit="force/velocity")
        cutoff: float | None = param(None, gt=0, unit="distance")

    def mix_coeff(self, ci, cj, rule):
        combine = (lambda p, q: math.sqrt(p * q)) if rule == "geometric" else (lambda p, q: 0.5 * (p + q))
        rc_i = ci.cutoff if ci.cutoff is not None else self.args.cutoff
        rc_j = cj.cutoff if cj.cutoff is not None else self.args.cutoff
        if rule == "geometric" and ci.a * cj.a < 0:
            raise ScriptError("geometric mixing needs a of one sign for both types")
        return self.Coeff(a=combine(ci.a, cj.a), gamma=combine(ci.gamma, cj.gamma),
                          cutoff=combine(rc_i, rc_j))

    def init(self, ntypes, pairs=None):
        shape = (ntypes + 1, ntypes + 1)
        self.a, self.gamma, self.sigma, self.cut = (np.zeros(shape) for _ in range(4))
        cutoffs = super().init(ntypes, pairs)
        self.check_stability(ntypes)
        return cutoffs

    def check_stability(self, ntypes):
        """Warn when dt is too large for the conservative or dissipative stiffness (docstring)."""
        sim = self.sim
        count = observables.count(sim)
        if count == 0:
            return
        density = count / sim.box.volume
        mass = sim.comm.min(float(observables.masses(sim).min()) if sim.nlocal else math.inf)
        dt = sim.dt
        two_d = sim.dimension == 2
        for i in range(1, ntypes + 1):
            for j in range(i, ntypes + 1):
                rc = self.cut[i, j]
                if rc == 0.0:           # a type pair another sub-style of pair hybrid takes
                    continue
                neighbors = density * (math.pi * rc ** 2 if two_d else 4.0 / 3.0 * math.pi * rc ** 3)
                mean_w2 = 1.0 / 6.0 if two_d else 0.1
                stiffness = dt * math.sqrt(max(self.a[i, j], 0.0) * neighbors / (rc * mass))
                friction = dt * self.gamma[i, j] * neighbors * mean_w2 / mass
                if stiffness > STIFFNESS_LIMIT:
                    safe = STIFFNESS_LIMIT * dt / stiffness
                    sim.warn(f"pair dpd: timestep {dt:g} is too large for a = {self.a[i, j]:g} "
                             f"(types {i} {j}) at number density {density:.3g}: dt*sqrt(n_c a/(rc m)) = "
                             f"{stiffness:.2f} > {STIFFNESS_LIMIT}, where velocity Verlet loses temperature control; "
                             f"use timestep <= {safe:.3g} or a smaller a")
                if friction > 1.0 and not self.split:
                    safe = dt / friction
                    sim.warn(f"pair dpd: timestep {dt:g} is too large for gamma = {self.gamma[i, j]:g} "
                             f"(types {i} {j}) at number density {density:.3g}: "
                             f"dt*gamma*n_c*<w^2>/m = {friction:.2f} > 1, the friction overshoots; "
                             f"use timestep <= {safe:.3g} or a smaller gamma")

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        cut = c.cutoff if c.cutoff is not None else self.args.cutoff
        kT = self.sim.units.boltz * self.args.temperature
        gamma = self.friction(i, j, c, kT)
        sigma = math.sqrt(2.0 * kT * gamma)
        for table, value in ((self.a, c.a), (self.gamma, gamma), (self.cut, cut), (self.sigma, sigma)):
            table[i, j] = table[j, i] = value
        return cut, (c.a, gamma, sigma, cut)

    def friction(self, i, j, coeff, kT):
        """gamma of the type pair from its pair_coeff (the second coefficient here)."""
        return coeff.gamma

    def force_law(self):
        if self.split:
            return self.conservative_law
        return self.uniform_law if self.args.noise == "uniform" else self.law

    def law_state(self, sim):
        return (sim.random_key(self.args.seed), sim.step, 1.0 / math.sqrt(sim.dt))
