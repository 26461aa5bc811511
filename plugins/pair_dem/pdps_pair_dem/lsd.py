r"""Pair style ``dem/lsd``: linear spring-dashpot contacts between spheres with Coulomb friction and a
tangential spring per contact (PDPS manual 2.2.15.1; Cundall & Strack, Geotechnique 29, 47 (1979);
the LAMMPS form gran/hooke/history of Silbert et al., Phys. Rev. E 64, 051302 (2001)).

Spheres i and j touch when :math:`r < R_i + R_j` (radii per particle, ``particle_style sphere``). With
overlap :math:`\delta = R_i + R_j - r`, normal :math:`\mathbf{n}` from j to i and the relative velocity
of the contact points split into :math:`v_n` and :math:`\mathbf{v}_t` (pdps_pair_dem.granular), the
force on i is

.. math::

    F_n = k_n\,\delta - C_n\,v_n, \qquad
    \mathbf{F}_t = -k_t\,\boldsymbol{\xi} - C_t\,\mathbf{v}_t, \quad
    |\mathbf{F}_t| \le \mu\,|F_n|, \qquad \mathbf{F} = F_n\mathbf{n} + \mathbf{F}_t

and :math:`-\mathbf{F}` on j. :math:`\boldsymbol{\xi}` is the tangential spring of the contact: it
grows by :math:`\mathbf{v}_t\Delta t` each step, is turned into the current tangent plane, and is cut
back when the contact slides so that :math:`|\mathbf{F}_t| = \mu|F_n|` (the law is
``pdps_granular_contact.dem.normal_lsd`` and ``tangential_spring``). It lives as long as the contact, survives neighbor list
rebuilds and re-sorting, and is freed when the spheres separate. Both spheres get the torque of
:math:`\mathbf{F}` about their centres. No potential energy is reported (the contact dissipates; pe
stays 0); the virial is the core's :math:`\sum \mathbf{r}\cdot\mathbf{f}`.

Parameters (units of the run):

- ``pair_style dem/lsd e cutoff [limit_damping yes|no] [max_contacts N]``

  - ``e``: restitution coefficient, 0 < e <= 1. PDPS reads it and does not use it; here it is the
    restitution of ``pair_coeff`` lines in the restitution form that give no ``e`` of their own.
  - ``cutoff``: neighbor cutoff of pairs that give none (distance). Contacts are decided by the radii;
    the cutoff is raised, where smaller, to the largest :math:`R_i + R_j` of the particles present
    at the start of each run, so it can never hide a contact.
  - ``limit_damping yes``: a contact never pulls (:math:`F_n < 0` set to 0), LAMMPS's keyword. Default
    no, which gives the requested restitution exactly.
  - ``max_contacts N``: contacts a particle can hold at once (default 16, >= 2).

- ``pair_coeff I J kn cn kt ct mu [cutoff]`` (the PDPS form): :math:`k_n` normal stiffness (> 0,
  force/distance), :math:`C_n` normal damping (>= 0, force/velocity = mass/time), :math:`k_t`
  tangential stiffness (>= 0, force/distance), :math:`C_t` tangential damping (>= 0, mass/time),
  :math:`\mu` friction coefficient (>= 0), cutoff (> 0, distance; default the pair_style one).

- ``pair_coeff I J kn KN [kt KT] [e E] mu MU [ct CT] [cutoff RC]`` (the restitution form): the
  damping is derived per contact from the restitution coefficient and the two masses,

  .. math::

      C_n = 2\zeta\sqrt{k_n m^*}, \quad \zeta = \frac{-\ln e}{\sqrt{\pi^2 + \ln^2 e}}, \quad
      m^* = \frac{m_i m_j}{m_i + m_j}

  (``contact_models.lsd_damping``), with :math:`m_i, m_j` the per-particle masses (``rmass``), as
  LAMMPS computes its damping per contact from the two masses: every pair of particles, whatever
  their sizes, bounces with restitution e. ``kt`` defaults to :math:`\tfrac27 k_n` and ``ct`` to
  :math:`C_n/2`, per contact (LAMMPS's gran/hooke/history defaults); ``e`` to the pair_style's.

An unset I J pair is an error (no mixing rule). Contacts need ghost velocities and ghost omega, which
the style asks for. The contact lasts (while it does not slide)

.. math::  t_c = \pi \Big/ \sqrt{k_n/m^* - (C_n/2m^*)^2}

``timestep_limits(sim)`` returns ``{"rayleigh": None, "hertz": None, "contact": t}`` with t the
smallest :math:`t_c` over the type pairs present, each at its smallest :math:`m^*` (an overdamped
contact, :math:`C_n \ge 2\sqrt{k_n m^*}`, counts with its undamped :math:`\pi\sqrt{m^*/k_n}`; inf
without particles). Masses are those present when it is called; it needs a run (run 0) first.

The PDPS example, ``pair_style dem/lsd 0.3 1.0`` and ``pair_coeff * * 1000 16.6016 314.29 6.3008 0.5
1``, reads: restitution 0.3 (unused by the force), global cutoff 1; :math:`k_n = 1000`,
:math:`C_n = 16.6016`, :math:`k_t = 314.29` (0.314 :math:`k_n`), :math:`C_t = 6.3008`,
:math:`\mu = 0.5` (the manual's list calls this fifth number e, PDPS's source reads it as the
friction coefficient), cutoff 1. The damping is fixed, so the restitution depends on the masses:
e = 0.3 needs :math:`m^* = 0.538` (two spheres of mass 1.076), and two spheres of diameter 1 and
density 1 (:math:`m^* = \pi/12`) bounce with e = 0.153 after :math:`t_c = 0.0592`. Restitution 0.3
whatever the masses, with the example's stiffnesses and friction::

    pair_style dem/lsd 0.3 1.0
    pair_coeff * * kn 1000 kt 314.29 e 0.3 mu 0.5

Example (PDPS manual)::

    particle_style sphere
    pair_style dem/lsd 0.3 1.0
    pair_coeff * * 1000 16.6016 314.29 6.3008 0.5 1
"""

import math

import numpy as np
from pdps_core.api import ScriptError, StyleArgs, keyword, param, parse_args
from pdps_granular_contact import contact_models

from .granular import DEFAULT_CONTACTS, GranularPair

KT_OVER_KN = 2.0 / 7.0        # LAMMPS's default tangential stiffness
CT_OVER_CN = 0.5              # LAMMPS's default tangential damping


class PairDEMLsd(GranularPair):
    name = "dem/lsd"
    usage = "pair_style dem/lsd e cutoff [limit_damping yes|no] [max_contacts N]"
    coeff_usage = "kn cn kt ct mu [cutoff]  or  kn KN [kt KT] [e E] mu MU [ct CT] [cutoff RC]"

    class Args(StyleArgs):
        e: float = param(gt=0, le=1, unit="dimensionless")
        cutoff: float = param(gt=0, unit="distance")
        limit_damping: bool = keyword(False)
        max_contacts: int = keyword(DEFAULT_CONTACTS, ge=2, unit="dimensionless")

    class Coeff(StyleArgs):
        """The PDPS form: damping given directly."""
        kn: float = param(gt=0, unit="force/distance")
        cn: float = param(ge=0, unit="force/velocity")
        kt: float = param(ge=0, unit="force/distance")
        ct: float = param(ge=0, unit="force/velocity")
        mu: float = param(ge=0, unit="dimensionless")
        cutoff: float | None = param(None, gt=0, unit="distance")

    class RestitutionCoeff(StyleArgs):
        """The restitution form: damping derived per contact from e and the two masses."""
        kn: float = keyword(..., gt=0, unit="force/distance")
        kt: float | None = keyword(None, ge=0, unit="force/distance")
        e: float | None = keyword(None, gt=0, le=1, unit="dimensionless")
        mu: float = keyword(..., ge=0, unit="dimensionless")
        ct: float | None = keyword(None, ge=0, unit="force/velocity")
        cutoff: float | None = keyword(None, gt=0, unit="distance")

    def parse_coeff(self, words):
        if words and words[0] in self.RestitutionCoeff.model_fields:
            return parse_args(self.RestitutionCoeff, words, self.coeff_usage)
        return parse_args(self.Coeff, words, self.coeff_usage)

    def init(self, ntypes):
        shape = (ntypes + 1, ntypes + 1)
        (self.kn, self.cn, self.kt, self.ct, self.cn_per_root_mass, self.ct_over_cn,
         self.mu) = (np.zeros(shape) for _ in range(7))
        return super().init(ntypes)

    def init_one(self, i, j):
        c = self.resolved[(i, j)]
        if isinstance(c, self.RestitutionCoeff):
            e = c.e if c.e is not None else self.args.e
            kt = c.kt if c.kt is not None else KT_OVER_KN * c.kn
            # C_n = lsd_damping(kn, m*, e) grows as sqrt(m*): keep the factor, apply m* per contact
            values = {"kn": c.kn, "cn": 0.0, "kt": kt, "ct": c.ct if c.ct is not None else 0.0,
                      "cn_per_root_mass": contact_models.lsd_damping(c.kn, 1.0, e),
                      "ct_over_cn": CT_OVER_CN if c.ct is None else 0.0, "mu": c.mu}
        else:
            values = {"kn": c.kn, "cn": c.cn, "kt": c.kt, "ct": c.ct, "cn_per_root_mass": 0.0,
                      "ct_over_cn": 0.0, "mu": c.mu}
        for name, value in values.items():
            table = getattr(self, name)
            table[i, j] = table[j, i] = value
        cutoff = c.cutoff if c.cutoff is not None else self.args.cutoff
        return max(cutoff, self.contact_reach(i, j))

    normal_model = "lsd"

    def law_tables(self):
        """The tables the dem sub-models read (pdps_granular_contact.dem.normal_lsd, tangential_spring)."""
        return {name: getattr(self, name) for name in ("kn", "cn", "kt", "ct", "cn_per_root_mass", "ct_over_cn",
                                                         "mu")}

    def damping(self, i, j, m_star):
        return self.cn[i, j] + self.cn_per_root_mass[i, j] * math.sqrt(m_star)

    def timestep_limits(self, sim, at_least=0.0):
        """Smallest contact time of the type pairs present, each at its smallest m* (docstring)."""
        if getattr(self, "resolved", None) is None:
            raise ScriptError(f"pair {self.name}: timestep limits are known once a run has started")
        ntypes = sim.ntypes
        _, min_mass = self.extremes(ntypes)
        contact = math.inf
        for i in range(1, ntypes + 1):
            for j in range(i, ntypes + 1):
                mi, mj = min_mass[i], min_mass[j]
                if not (math.isfinite(mi) and math.isfinite(mj)):
                    continue            # no particle of one of the types
                m_star = mi * mj / (mi + mj)
                kn, cn = self.kn[i, j], self.damping(i, j, m_star)
                if cn * cn < 4.0 * kn * m_star:
                    t = contact_models.lsd_contact_time(kn, cn, m_star)
                else:
                    t = math.pi * math.sqrt(m_star / kn)
                contact = min(contact, t)
        return {"rayleigh": None, "hertz": None, "contact": contact}
