r"""Pair style ``dem/hertz``: Hertz-Mindlin contacts between spheres from material constants, with
Coulomb friction and a tangential spring per contact (LIGGGHTS's ``pair_style gran model hertz
tangential history``; Hertz 1882; Mindlin, J. Appl. Mech. 16, 259 (1949); damping of Tsuji et al.,
Powder Technol. 71, 239 (1992), in LIGGGHTS's form).

Spheres i and j (Young's moduli :math:`Y_i, Y_j`, Poisson ratios :math:`\nu_i, \nu_j`, radii, masses
per particle) touch when :math:`r < R_i + R_j`. Per contact:

.. math::

    \frac{1}{E^*} = \frac{1-\nu_i^2}{Y_i} + \frac{1-\nu_j^2}{Y_j}, \quad
    \frac{1}{G^*} = \frac{2(2-\nu_i)(1+\nu_i)}{Y_i} + \frac{2(2-\nu_j)(1+\nu_j)}{Y_j}, \quad
    \frac{1}{R^*} = \frac{1}{R_i} + \frac{1}{R_j}, \quad \frac{1}{m^*} = \frac{1}{m_i} + \frac{1}{m_j}

.. math::

    S_n = 2E^*\sqrt{R^*\delta},\ S_t = 8G^*\sqrt{R^*\delta}, \quad
    F_n = \tfrac43 E^*\sqrt{R^*\delta}\,\delta - C_n v_n, \quad
    \mathbf{F}_t = -S_t\,\boldsymbol{\xi} - C_t\mathbf{v}_t, \quad |\mathbf{F}_t| \le \mu|F_n|

.. math::

    C_n = -2\sqrt{5/6}\,\beta\sqrt{S_n m^*}, \quad C_t = -2\sqrt{5/6}\,\beta\sqrt{S_t m^*}, \quad
    \beta = \frac{\ln e}{\sqrt{\ln^2 e + \pi^2}}

(``pdps_granular_contact.dem.normal_hertz`` and ``tangential_spring``; overlap, normal, contact-point velocity, the spring
:math:`\boldsymbol{\xi}` kept per contact and the torques are those of pdps_pair_dem.granular). The
damping grows as :math:`\delta^{1/4}`, which makes the restitution coefficient independent of the
impact speed and equal to e. No potential energy is reported (the contact dissipates; pe stays 0); the
virial is the core's :math:`\sum \mathbf{r}\cdot\mathbf{f}`.

Parameters (units of the run):

- ``pair_style dem/hertz [limit_damping yes|no] [max_contacts N]``: ``limit_damping yes`` keeps
  :math:`F_n \ge 0` (LAMMPS's keyword; default no, which gives the restitution exactly);
  ``max_contacts`` the contacts a particle can hold at once (default 16, >= 2).
- ``pair_coeff I J Y nu e mu``: Young's modulus Y (> 0, pressure), Poisson ratio nu (-1 < nu <= 0.5),
  restitution coefficient e (0 < e <= 1), friction coefficient mu (>= 0). ``pair_coeff I I`` gives
  type I's material. On an I J line with I != J, numbers make both bodies of that material (LAMMPS's
  pair granular), while ``pair_coeff I J NULL NULL e mu`` combines the two types' own materials
  from their I I lines in :math:`E^*` and :math:`G^*` (LIGGGHTS: Y and nu per type, e and mu per type
  pair).

The neighbor cutoff of types i, j is the largest :math:`R_i + R_j` of the particles present at the
start of each run. An unset I J pair is an error (no mixing rule).

``timestep_limits(sim)`` returns ``{"rayleigh": t_R, "hertz": t_H, "contact": min(t_R, t_H)}``
(LIGGGHTS's check/timestep/gran): the smallest Rayleigh time over the particles,

.. math::  t_R = \frac{\pi R\sqrt{\rho/G}}{0.1631\,\nu + 0.8766}, \quad G = \frac{Y}{2(1+\nu)}

with :math:`\rho` from each particle's mass and radius, and the smallest elastic Hertz time of a
particle hitting its own copy at the largest possible relative speed :math:`v = 2\max|\mathbf{v}|`,

.. math::  t_H = 2.868\,\big(m^{*2} / (R^* E^{*2} v)\big)^{1/5}, \quad m^* = m/2,\ R^* = R/2

(None when nothing moves). Damping lengthens a contact: by 1.1 % at e = 0.9 and 9.3 % at e = 0.5, so
:math:`t_H` is the shorter, safe bound.

Example (glass beads in SI units)::

    units si
    particle_style sphere
    pair_style dem/hertz
    pair_coeff * * 6.0e10 0.25 0.9 0.3
"""

import math

import numpy as np
from pdps_core.api import ScriptError, StyleArgs, keyword, param, parse_args
from pdps_granular_contact import contact_models

from .granular import DEFAULT_CONTACTS, GranularPair


def youngs_effective(youngs_i, poisson_i, youngs_j, poisson_j):
    return 1.0 / ((1.0 - poisson_i ** 2) / youngs_i + (1.0 - poisson_j ** 2) / youngs_j)


def shear_effective(youngs_i, poisson_i, youngs_j, poisson_j):
    return 1.0 / (2.0 * (2.0 - poisson_i) * (1.0 + poisson_i) / youngs_i
                  + 2.0 * (2.0 - poisson_j) * (1.0 + poisson_j) / youngs_j)


class PairDEMHertz(GranularPair):
    name = "dem/hertz"
    usage = "pair_style dem/hertz [limit_damping yes|no] [max_contacts N]"
    coeff_usage = "Y nu e mu  or  NULL NULL e mu (I != J: the two types' own materials)"

    class Args(StyleArgs):
        limit_damping: bool = keyword(False)
        max_contacts: int = keyword(DEFAULT_CONTACTS, ge=2, unit="dimensionless")

    class Coeff(StyleArgs):
        youngs: float = param(gt=0, unit="pressure")
        poisson: float = param(gt=-1, le=0.5, unit="dimensionless")
        e: float = param(gt=0, le=1, unit="dimensionless")
        mu: float = param(ge=0, unit="dimensionless")

    class CrossCoeff(StyleArgs):
        """``NULL NULL e mu``: Y and nu of each type from its I I line."""
        e: float = param(gt=0, le=1, unit="dimensionless")
        mu: float = param(ge=0, unit="dimensionless")

    def parse_coeff(self, words):
        nulls = [w.upper() == "NULL" for w in words[:2]]
        if any(nulls):
            if not all(nulls):
                raise ScriptError("youngs and poisson are both numbers, or both NULL (each type's own "
                                  f"material); usage: pair_coeff I J {self.coeff_usage}")
            return parse_args(self.CrossCoeff, words[2:], self.coeff_usage)
        return parse_args(self.Coeff, words, self.coeff_usage)

    def coeff(self, i, j, coeff):
        if i == j and isinstance(coeff, self.CrossCoeff):
            raise ScriptError(f"youngs and poisson of type {i} cannot be NULL: pair_coeff {i} {i} "
                              "gives the type's own material")
        super().coeff(i, j, coeff)

    def material(self, t, of_pair):
        """(Y, nu) of type t, from its pair_coeff t t line."""
        own = self.coeffs.get((t, t))
        if own is None:
            raise ScriptError(f"pair_coeff {of_pair[0]} {of_pair[1]} NULL NULL needs the material of "
                              f"type {t} from a pair_coeff {t} {t} line")
        return own.youngs, own.poisson

    def init(self, ntypes):
        shape = (ntypes + 1, ntypes + 1)
        self.e_star, self.g_star, self.beta, self.mu = (np.zeros(shape) for _ in range(4))
        return super().init(ntypes)

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        if isinstance(c, self.CrossCoeff):
            (yi, nui), (yj, nuj) = self.material(i, (i, j)), self.material(j, (i, j))
        else:
            yi, nui, yj, nuj = c.youngs, c.poisson, c.youngs, c.poisson
        for table, value in ((self.e_star, youngs_effective(yi, nui, yj, nuj)),
                             (self.g_star, shear_effective(yi, nui, yj, nuj)),
                             (self.beta, contact_models.restitution_beta(c.e)), (self.mu, c.mu)):
            table[i, j] = table[j, i] = value
        return self.contact_reach(i, j)

    normal_model = "hertz"

    def law_tables(self):
        """The tables the dem sub-models read (pdps_granular_contact.dem.normal_hertz, tangential_spring)."""
        return {"e_star": self.e_star, "g_star": self.g_star, "beta": self.beta, "mu": self.mu}

    def timestep_limits(self, sim, at_least=0.0):
        """Rayleigh and Hertz times of the particles now present (docstring)."""
        if getattr(self, "resolved", None) is None:
            raise ScriptError(f"pair {self.name}: timestep limits are known once a run has started")
        p = sim.particles
        n = p.nlocal
        types, radius, mass = p.type[:n], p.radius[:n], p.rmass[:n]
        volume = math.pi * radius ** 2 if sim.dimension == 2 else 4.0 / 3.0 * math.pi * radius ** 3
        density = mass / volume
        speed = float(np.sqrt(np.einsum("ij,ij->i", p.v[:n], p.v[:n])).max(initial=0.0))
        v_max = 2.0 * max(at_least, sim.comm.max(speed))
        rayleigh, hertz = math.inf, math.inf
        for t in np.unique(types):
            youngs, poisson = self.material(int(t), (t, t))
            of_type = np.flatnonzero(types == t)
            # within a type t_R grows with R sqrt(rho) and t_H with m^2/R: one particle decides each
            k = of_type[np.argmin(radius[of_type] * np.sqrt(density[of_type]))]
            rayleigh = min(rayleigh, contact_models.rayleigh_time(
                radius[k], density[k], youngs / (2.0 * (1.0 + poisson)), poisson))
            if v_max > 0.0:
                k = of_type[np.argmin(mass[of_type] ** 2 / radius[of_type])]
                e_star = youngs_effective(youngs, poisson, youngs, poisson)
                hertz = min(hertz, contact_models.hertz_contact_time(
                    e_star, 0.5 * radius[k], 0.5 * mass[k], v_max))
        rayleigh, hertz = float(sim.comm.min(rayleigh)), float(sim.comm.min(hertz))
        rayleigh = rayleigh if math.isfinite(rayleigh) else None
        hertz = hertz if math.isfinite(hertz) else None
        limits = [t for t in (rayleigh, hertz) if t is not None]
        return {"rayleigh": rayleigh, "hertz": hertz, "contact": min(limits, default=math.inf)}
