r"""Pair style ``granular``: LAMMPS's GRANULAR package's composed contacts between spheres (its
``pair_style granular``), of a normal, a damping, a tangential and optionally a rolling and a
twisting model chosen per ``pair_coeff`` line, with coefficients per type and mixing between types
(LAMMPS 22 Jul 2025's GranularModel and GranSubMod's; their formulas, coefficients and papers:
``pdps doc granular.PART NAME``, modules ``pdps_granular_contact.granular``).

Spheres i and j (radii :math:`R_i, R_j`, masses :math:`m_i, m_j`) at distance :math:`r < R_i +
R_j` overlap by :math:`\delta = R_i + R_j - r`, with normal :math:`\mathbf{n} = (\mathbf{x}_i -
\mathbf{x}_j)/r`, :math:`R^* = R_iR_j/(R_i + R_j)`, :math:`m^* = m_im_j/(m_i + m_j)` (the other
sphere's mass when one is in the group of the first ``fix freeze``). The contact points slide at
:math:`\mathbf{v}_{tr} = \mathbf{v}_t - (R_i\boldsymbol\omega_i + R_j\boldsymbol\omega_j)\times
\mathbf{n}`; the force on i is :math:`F_n\mathbf{n} + \mathbf{F}_t` (its negative on j), the torques
:math:`-(R_{i,j} - \delta/2)\,\mathbf{n}\times\mathbf{F}_t`, plus the rolling torque :math:`\pm R^*
\mathbf{n}\times\mathbf{F}_r` and the twisting torque :math:`\pm M_t\mathbf{n}`. A JKR contact, once
made, lasts until the spheres are its pull-off distance apart (``granular.normal jkr``).

Syntax::

    pair_style granular [cutoff] [max_contacts N]
    pair_coeff I J NORMAL coefficients [damping DAMPING] tangential TANGENTIAL coefficients
               [rolling sds k_roll gamma_roll mu_roll] [twisting marshall | twisting sds k gamma mu]
               [limit_damping] [cutoff DISTANCE]

- NORMAL: ``hooke k_n eta_n0``, ``hertz k_n eta_n0``, ``hertz/material E eta_n0 nu``, ``dmt E
  eta_n0 nu gamma``, ``jkr E eta_n0 nu gamma``.
- DAMPING (default viscoelastic): velocity, mass_velocity, viscoelastic, tsuji, coeff_restitution
  (the last two read eta_n0 as the restitution coefficient).
- TANGENTIAL (required): ``linear_nohistory x_gamma_t mu_s``, ``linear_history k_t x_gamma_t
  mu_s``, ``mindlin``, ``mindlin/force``, ``mindlin_rescale``, ``mindlin_rescale/force`` (``k_t|NULL
  x_gamma_t mu_s``; NULL: 8 G* of the normal model's material).
- ``limit_damping``: the normal force never pulls (not with dmt or jkr, as LAMMPS);
  ``cutoff``: the neighbor cutoff of the type pair (default: the largest radii's sum, plus JKR's
  pull-off distance); the ``pair_style`` cutoff is the same for every pair.
- ``max_contacts N`` (pdps keyword, default 16): contacts a particle holds at once.

``pair_coeff I I`` alone for each type gives every ``I J`` by LAMMPS's mixing: the geometric mean of
each coefficient, Young's moduli as the effective modulus :math:`1/E^* = (1-\nu_i^2)/E_i +
(1-\nu_j^2)/E_j` (``pdps_granular_contact.granular.base``); types with different models cannot be
mixed. pdps composes one contact law for every type pair: the models (not their coefficients) of
every pair_coeff line must be the same, and a line naming others is refused.

History: what the models keep (the tangential spring, then the rolling displacement and the twist
angle; one value for JKR, which marks a contact made) lives on both spheres, the partner's copy of the
spring negated and of the rolling displacement, twist angle and mindlin_rescale's contact radius
unchanged (they are the same seen from either sphere; LAMMPS 22 Jul 2025 negates the rolling and
twist values too), and a contact not seen in a step is forgotten at its end (LAMMPS zeroes a pair's
history once its spheres part). The run warns when the time step is more than a tenth of the shortest
contact (pi sqrt(m*/k_n) for hooke, Hertz's 2.868 (m*^2/(R* E*^2 v))^(1/5) for the others, the
lightest spheres of each type meeting at twice the largest speed). Needs ``atom_style sphere``; ghosts
carry v and omega without ``comm_modify vel yes``. No potential energy (pe stays 0, as LAMMPS). Not
built: the ``classic`` normal model (use pair gran/*), the heat models (they need LAMMPS's fix
heat/flow), mdr.

Example (the LAMMPS bench scene in.granular_settle)::

    pair_style granular
    pair_coeff * * hertz/material 5.e6 0.5 0.45 tangential mindlin NULL 1.0 0.5 &
               rolling sds 100.0 0.05 0.05 damping coeff_restitution
"""

import numpy as np

from pdps_core.api import Pair, ScriptError, StyleArgs, keyword, param
from pdps_granular_contact.composition import ContactModel
from pdps_granular_contact.granular.base import Laws
from pdps_granular_contact.granular.words import USAGE, read_law

from .gran import DEFAULT_CONTACTS
from .gran_model import PairGranModel


class GranularArgs(StyleArgs):
    cutoff: float | None = param(None, gt=0, unit="distance")
    max_contacts: int = keyword(DEFAULT_CONTACTS, ge=2, le=1000, unit="dimensionless")

    def contact_model(self, heat=None):
        """The surface alone: the pair_coeff lines name the models, composed at each run's start."""
        return ContactModel("granular", {})


class GranularCoeff(StyleArgs):
    """A pair_coeff line's words after the types, kept as written (a restart file holds them); their
    Law is read from them (pdps_granular_contact.granular.words)."""
    words: tuple[str, ...] = param(names="pair granular's model words and coefficients (pdps doc granular.PART NAME)")

    def law(self):
        return read_law(list(self.words))


def law_of(coeff):
    """The Law of a type pair's coefficients: a pair_coeff line's, or one mixed of two."""
    return coeff.law() if isinstance(coeff, GranularCoeff) else coeff


class PairGranular(PairGranModel):
    name = "granular"
    usage = "pair_style granular [cutoff] [max_contacts N]"
    coeff_usage = USAGE
    Args = GranularArgs
    Coeff = GranularCoeff
    history_name = "granular_history"

    def parse_coeff(self, words):
        law = read_law(words)
        named = {part: cls.name for part, (cls, _) in law.parts.items()}
        for other in self.coeffs.values():
            before = {part: cls.name for part, (cls, _) in other.law().parts.items()}
            if before != named:
                differ = next(part for part in sorted(set(before) | set(named)) if before.get(part) != named.get(part))
                raise ScriptError(f"pdps composes one law for every type pair: {differ} "
                                  f"{named.get(differ, 'none')} differs from the {before.get(differ, 'none')} of an "
                                  f"earlier pair_coeff line (got {named.get(differ, 'none')})")
        return GranularCoeff(words=tuple(words))

    def mix(self, i, j):
        for k in (i, j):
            if (k, k) not in self.coeffs:
                raise ScriptError(f"pair coefficients for types {k} {k} are needed to mix {i} {j}")
        try:
            return self.coeffs[(i, i)].law().mix(self.coeffs[(j, j)].law(), i, j)
        except (ValueError, ZeroDivisionError, OverflowError) as exc:
            raise ScriptError(f"pair coefficients for types {i} {j} cannot be mixed ({exc}): give pair_coeff {i} {j}") \
                from None

    def init(self, ntypes):
        sim = self.sim
        if "sphere" not in sim.particle_styles:
            raise ScriptError(f"pair {self.name} needs atom_style sphere (per-particle radius, mass and rotation)")
        self.freeze_bit = np.uint32(self.frozen_group_bit(sim))
        self.radius_moving, self.radius_frozen = self.largest_radii(ntypes)
        self.check_box()
        cutoffs = Pair.init(self, ntypes)
        laws = {pair: law_of(coeff) for pair, coeff in self.resolved.items()}
        law = next(iter(laws.values()))
        self.contact_model = ContactModel("granular", {part: cls.name for part, (cls, _) in law.parts.items()})
        self.history_width = self.contact_model.history_width
        self._block = self.contact_model.block()
        # the laws stand for the material of pair gran's time-step advice (timestep_limits)
        self.material = Laws(ntypes, laws)
        self.contact_coeff = self.contact_model.bind(self.material)
        self.kernels = self.contact_model.pair_kernels()
        if self.history_width > 0:
            self.open_history()
        self.warn_coarse_timestep(sim)
        return cutoffs

    def init_one(self, i, j):
        """LAMMPS's: the pair_coeff cutoff, else the pair_style one, else the largest sum of the radii
        of a moving particle of one type and any of the other (gran's rule) plus JKR's pull-off distance
        of the largest radii."""
        law = law_of(self.resolved[(i, j)])
        if law.cutoff is not None:
            return law.cutoff
        if self.args.cutoff is not None:
            return self.args.cutoff
        reach = super().init_one(i, j)
        normal_cls, _ = law.parts["normal"]
        pulloff = getattr(normal_cls, "pulloff", None)
        if pulloff is None or reach == 0.0:
            return reach
        values = np.array(normal_cls({}).values(law, "pair"))
        largest = max(self.radius_moving[i], self.radius_frozen[i]), max(self.radius_moving[j], self.radius_frozen[j])
        return reach + float(pulloff(values, largest[0], largest[1]))


    def reads_youngs(self, sim):
        """No: the moduli are the pair_coeff lines' (timestep_limits times contacts by the normal model
        alone: pi sqrt(m*/k_n) for hooke, Hertz's time for the others)."""
        return False

    def conducts_heat(self, sim):
        """Its contacts carry no heat (the heat models are not built)."""
        return False

    def forget_apart(self, sim, nlist, owner, touched, rows, touching, npairs):
        """LAMMPS's pair granular forgets a contact at the end of the step its spheres parted in."""
        self.forget_stale(sim, nlist, owner, touched, rows, touching, int(self._ntouching[0]))
