r"""Pair style ``gran``: LIGGGHTS's granular contacts between spheres, built from a normal, a
tangential, a rolling-friction and a cohesion model, with the material read from ``fix
property/global`` (LIGGGHTS's ``pair_style gran model ...``; Di Renzo & Di Maio, Chem. Eng. Sci. 59,
525 (2004); Ai et al., Powder Technol. 206, 269 (2011)).

Spheres i and j (radii :math:`R_i, R_j`, masses :math:`m_i, m_j` per particle) at distance
:math:`r < R_i + R_j` overlap by :math:`\delta = R_i + R_j - r`, with normal :math:`\mathbf{n} =
(\mathbf{x}_i - \mathbf{x}_j)/r`, :math:`R^* = R_iR_j/(R_i+R_j)` and :math:`m^* = m_im_j/(m_i+m_j)`
(or the other sphere's mass when one is in the group of a ``fix freeze``). The contact points sit
at :math:`R_{i,j} - \delta/2` from the centres (LIGGGHTS's lever arms) and slide at

.. math::

    \mathbf{v}_{tr} = \mathbf{v}_t - \big((R_i - \tfrac\delta2)\boldsymbol\omega_i +
    (R_j - \tfrac\delta2)\boldsymbol\omega_j\big)\times\mathbf{n}

The force on i is :math:`F_n\mathbf{n} + \mathbf{F}_t` (:math:`-` that on j), the torques
:math:`-(R_{i,j} - \delta/2)\,\mathbf{n}\times\mathbf{F}_t`, and the rolling torque
:math:`\mp\mathbf{M}_r`. The law is composed of sub-models (``pdps_granular_contact.composition``),
one per model word, which walls share: LIGGGHTS's (hertz, hooke, hertz/stiffness, hooke/stiffness,
hooke/hysteresis; history, no_history; cdt, epsd, epsd2, epsd3; sjkr, sjkr2, easo/capillary/viscous,
washino/capillary/viscous; surface default) are
``pdps_granular_contact.gran``, each module with its formulas (``pdps doc gran.normal hertz``), and
a distribution may add others (entry-point groups ``pdps.gran.normal``, ``pdps.gran.tangential``,
``pdps.gran.rolling``, ``pdps.gran.cohesion``, ``pdps.gran.surface``; plugins/contact_vdw). Each
model of LIGGGHTS 3.8.0 gives LIGGGHTS's trajectory of two colliding spheres and of a sphere on a
wall to round-off (tests/test_gran_submodels.py).

Syntax (the words in any order after ``gran``, LIGGGHTS's)::

    pair_style gran model hertz|hooke|hertz/stiffness|hooke/stiffness|hooke/hysteresis
               tangential history|no_history [rolling_friction off|cdt|epsd|epsd2|epsd3]
               [cohesion off|sjkr|sjkr2|easo/capillary/viscous|washino/capillary/viscous]
               [surface default] [SETTING on|off ...] [max_contacts N]
    pair_coeff * *

- ``model``: normal model; hertz needs youngsModulus, poissonsRatio, coefficientRestitution;
  hooke also characteristicVelocity (its stiffness is the Hertz one at that impact speed);
  hooke/hysteresis also coefficientMaxElasticStiffness, coefficientAdhesionStiffness,
  coefficientPlasticityDepth; hooke/stiffness and hertz/stiffness kn, kt, gamman, gammat
  (gamman_abs, gammat_abs with absolute_damping on).
- ``tangential``: history (a spring per contact with Coulomb's limit) or no_history (viscous
  friction capped at Coulomb's limit); both read coefficientFriction.
- ``rolling_friction`` (default off): reads coefficientRollingFriction; epsd and epsd3 also
  coefficientRollingViscousDamping, epsd3 rollingStiffness.
- ``cohesion`` (default off): sjkr and sjkr2 read cohesionEnergyDensity (energy/volume); the
  liquid bridges easo/capillary/viscous and washino/capillary/viscous (``pdps doc gran.cohesion
  NAME``) their liquid's properties, act on spheres apart too (to the rupture distance; the
  neighbor cutoff grows to 1.1 maxSeparationDistanceRatio (R_i + R_j)) and move the per-atom
  ``surfaceLiquidContent``, which pair gran advances after each step's contacts (LIGGGHTS's
  transport equation).
- settings, each read by the models that declare it (LIGGGHTS refuses one no model of the line
  reads, and so does pdps): ``tangential_damping`` (default on), ``limitForce`` (default off: a
  contact may pull at its end, which gives the restitution coefficient exactly; on: :math:`F_n \ge
  0` before cohesion), ``absolute_damping`` (hooke/stiffness, default off), ``tangential_reduce``
  (sjkr, sjkr2, default off: on, the cohesion lowers the Coulomb limit and the rolling cap),
  ``torsionTorque`` (rolling models, default off: on, the spin about the normal is resisted too),
  ``limitLiquidContent`` and ``modifyLbVolume`` (washino/capillary/viscous, default off).
- ``max_contacts N`` (pdps keyword, default 16): contacts a particle can hold at once.

``pair_style bubble`` and ``pair_style gran_bubble`` are the same style under other names (LIGGGHTS's
aliases of gran, meant for pair hybrid with a law per phase, which pdps's pair hybrid does not take
granular styles for; recorded cases bubble and gran_bubble).

Material, from ``fix property/global`` (LIGGGHTS's names; ``fix_property``): youngsModulus
(pressure) and poissonsRatio per type (``peratomtype``), coefficientRestitution, coefficientFriction,
coefficientRollingFriction, coefficientRollingViscousDamping and cohesionEnergyDensity per type pair
(``peratomtypepair N``), characteristicVelocity (velocity, ``scalar``). They are read at the start
of each run: a missing one, a wrong count of values or a value out of range stops the run with one
line naming the property and the fix.

The contact history holds what the sub-models keep (the tangential spring, then the epsd/epsd2
rolling spring torque) on both spheres (pdps_pair_gran.gran: slots keyed by the partner's tag, the
partner's copy negated, ghost rows sent back to their owners in parallel runs). As in LIGGGHTS 3.8,
a contact whose spheres came apart is forgotten at the next build of the neighbor list, not at
once: spheres that touch again before then take up their old springs (its slots count towards
``max_contacts`` until then). Needs ``atom_style granular`` (= sphere). No potential energy is
reported; the neighbor cutoff is the largest :math:`R_i + R_j` present.

Time step: the run warns when it is more than a tenth of the shortest contact: the Hertz time
:math:`2.868\,(m^{*2}/(R^*Y^{*2}v))^{1/5}` at twice the largest speed (hertz), or
:math:`\pi/\sqrt{k_n/m^* - \gamma_n^2/4m^{*2}}` (hooke), for the lightest particle of each type
against its copy. ``fix check/timestep/gran`` also gets the Rayleigh time of the particles present,
:math:`\pi R\sqrt{\rho/G}/(0.1631\nu + 0.8766)`, :math:`G = Y/2(1+\nu)` (LIGGGHTS's).

Example (LIGGGHTS)::

    atom_style granular
    fix m1 all property/global youngsModulus peratomtype 5.e6
    fix m2 all property/global poissonsRatio peratomtype 0.45
    fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
    fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
    fix m5 all property/global coefficientRollingFriction peratomtypepair 1 0.1
    pair_style gran model hertz tangential history rolling_friction cdt
    pair_coeff * *
"""

import math

import numpy as np

from pdps_core.api import HeatTransport, Pair, ScriptError, SimulationError, keyword
from pdps_granular_contact import contact_models
from pdps_granular_contact.material import Material, find_property
from pdps_granular_contact.gran.words import GranModelArgs
from pdps_granular_contact.contact_models import NO_BODY_MASS, NO_LIQUID
from pdps_granular_contact.contact_slots import HeldRows, Mirrors, pack_slots

from .gran import DEFAULT_CONTACTS, PairGran

NO_HEAT = (np.zeros(0), np.zeros(0), np.zeros((0, 3)))
# a wet model's per-atom liquid (LIGGGHTS's names): content (content units, LIGGGHTS's "% of the
# solid volume"), its rate of change from the bridges, and a source the script may set
LIQUID, LIQUID_FLUX, LIQUID_SOURCE = "surfaceLiquidContent", "liquidFlux", "liquidSource"
NO_LOG = (np.zeros((0, 2), dtype=np.int64), np.zeros((0, 3)), np.zeros(1, dtype=np.int64))


class PairGranModel(PairGran):
    name = "gran"
    usage = ("pair_style gran model hertz|hooke|hertz/stiffness|hooke/stiffness|hooke/hysteresis tangential "
             "history|no_history [rolling_friction off|cdt|epsd|epsd2|epsd3] [cohesion off|sjkr|sjkr2|"
             "easo/capillary/viscous|washino/capillary/viscous] [surface default] [tangential_damping|limitForce|"
             "absolute_damping|tangential_reduce|torsionTorque|limitLiquidContent|modifyLbVolume on|off] "
             "[max_contacts N]")
    coeff_usage = "(no coefficients: pair_coeff * *; the material comes from fix property/global)"
    history_name = "gran_model_history"

    class Args(GranModelArgs):
        max_contacts: int = keyword(DEFAULT_CONTACTS, ge=2, le=1000, unit="dimensionless")

    def __init__(self, sim, args):
        Pair.__init__(self, sim, args)
        self.history = None
        self._touched = None
        self._rows = self._touching = self._rows_of = None
        self.held, self.mirrors = HeldRows(), Mirrors()
        self._ntouching = np.zeros(1, dtype=np.int64)
        self._entry_slots = np.full((0, 2), -1, dtype=np.int32)
        self.contact_model = args.contact_model()
        self.history_width = self.contact_model.history_width
        self._block = self.contact_model.block()
        self._no_history = (np.full((1, 2), -1, dtype=np.int64), np.zeros((1, 2)), 2)
        self.contact_coeff = self.kernels = None
        if self.contact_model.wet:
            # a liquid bridge reads the liquid of ghost partners too
            self.ghost_fields = (*PairGran.ghost_fields, LIQUID)

    def init(self, ntypes):
        sim = self.sim
        if "sphere" not in sim.particle_styles:
            raise ScriptError(f"pair {self.name} needs atom_style granular or sphere (per-particle radius, mass "
                              "and rotation)")
        self.material = Material(sim, ntypes, f"pair {self.name}")
        # a fix carrying heat through the contacts composes its conduction into them
        heat = self.heat_fix(sim)
        self.contact_model = self.args.contact_model(None if heat is None else heat.contact_heat_model(sim))
        self.contact_coeff = self.contact_model.bind(self.material)
        if self.contact_model.wet:
            self.open_liquid()
        self.kernels = self.contact_model.pair_kernels()
        if self.history_width > 0:
            self.open_history()
        self.freeze_bit = np.uint32(self.frozen_group_bit(sim))
        self.radius_moving, self.radius_frozen = self.largest_radii(ntypes)
        self.check_box()
        cutoffs = Pair.init(self, ntypes)
        self.warn_coarse_timestep(sim)
        return cutoffs

    def init_one(self, i, j):
        """The largest sum of radii the types meet with (gran's rule), times the reach of a model acting
        on spheres apart (LIGGGHTS's contact distance factor: a liquid bridge's rupture distance)."""
        return self.contact_model.reach * PairGran.init_one(self, i, j)

    def open_liquid(self):
        """The per-atom surface liquid of a wet model (LIGGGHTS's fix property/atom made by its
        transportequation/scalar liquidtransfer): ``surfaceLiquidContent`` (new particles start at
        surfaceLiquidContentInitial as LIGGGHTS prints it, %e: seven significant digits), ``liquidFlux`` and
        ``liquidSource`` (content/time); made once, kept by later runs."""
        p = self.sim.particles
        initial = float(f"{self.material.property('surfaceLiquidContentInitial'):e}")
        p.request(LIQUID, default=initial)
        p.request(LIQUID_FLUX)
        p.request(LIQUID_SOURCE, ghost=False)

    def _liquid_arrays(self, p):
        if not self.contact_model.wet:
            return NO_LIQUID
        return p.arrays[LIQUID], p.arrays[LIQUID_FLUX]

    def transfer_liquid(self, sim, update):
        """After the contacts: the fluxes of ghosts summed onto their owners, and on a step (not in a
        run's setup) each owned particle's content advanced, c += (flux + source) dt (LIGGGHTS's
        transportequation/scalar, explicit: its final_integrate gives the same c to every output
        and to the next step's contacts)."""
        p = sim.particles
        sim.comm.reverse_comm(p, (LIQUID_FLUX,))
        if update:
            n = p.nlocal
            a = p.arrays
            a[LIQUID][:n] += (a[LIQUID_FLUX][:n] + a[LIQUID_SOURCE][:n]) * sim.dt

    def timestep_limits(self, sim, at_least=0.0):
        """{"rayleigh": t_R, "hertz": t_H, "contact": t}: the smallest Rayleigh time of the particles
        present (LIGGGHTS's check/timestep/gran: pi R sqrt(rho/G) / (0.1631 nu + 0.8766), G = Y / 2(1 +
        nu)); LIGGGHTS's Hertz estimate, for every normal model (its check/timestep/gran: each particle
        against its copy with m* its full mass, R* = R/2, Y* of its type, at twice the largest speed,
        2.87 (m*^2 / (R* Y*^2 v))^(1/5)); both only where the material gives Young's moduli (the
        stiffness models need none); and the shortest contact of the lightest particle of each type
        hitting its copy at twice the largest speed, with m* = m/2, R* = R/2, as the normal model
        times it (``contact_time``; the run's own warning). None where there is nothing to time (no
        particles; for Hertz, nothing moving)."""
        p = sim.particles
        nl = p.nlocal
        normal = self.contact_model.part("normal")
        with_youngs = self.reads_youngs(sim)
        rayleigh, shortest, hertz = math.inf, math.inf, math.inf
        speed = max(at_least, sim.comm.max(float(np.sqrt((p.v[:nl] ** 2).sum(axis=1)).max()) if nl else 0.0))
        for t in range(1, sim.ntypes + 1):
            of_type = p.type[:nl] == t
            if with_youngs and of_type.any():
                youngs = self.material.property("youngsModulus")[t]
                poisson = self.material.property("poissonsRatio")[t]
                radius, mass = p.radius[:nl][of_type], p.rmass[:nl][of_type]
                density = mass / (4.0 / 3.0 * math.pi * radius ** 3)
                if p.has("density"):
                    # a clump's spheres carry its mass, and their own density (LIGGGHTS's atom density)
                    given = p.arrays["density"][:nl][of_type]
                    density = np.where(given > 0.0, given, density)
                    mass = density * (4.0 / 3.0 * math.pi * radius ** 3)
                k = int(np.argmin(radius * np.sqrt(density)))
                shear = youngs / (2.0 * (1.0 + poisson))
                rayleigh = min(rayleigh, contact_models.rayleigh_time(radius[k], density[k], shear, poisson))
                if speed > 0.0:
                    y_star = self.material.youngs_effective()[t, t]
                    k = int(np.argmin(mass * mass / radius))
                    hertz = min(hertz, 2.87 * (mass[k] ** 2 / (0.5 * radius[k] * y_star ** 2 * 2.0 * speed)) ** 0.2)
            lightest = sim.comm.min(float(p.rmass[:nl][of_type].min()) if of_type.any() else math.inf)
            if not math.isfinite(lightest):
                continue
            rows = np.flatnonzero(of_type & (p.rmass[:nl] == lightest))
            radius = sim.comm.min(float(p.radius[:nl][rows].min()) if len(rows) else math.inf)
            duration = normal.contact_time(self.material, t, 0.5 * lightest, 0.5 * radius, 2.0 * speed)
            if duration is not None:
                shortest = min(shortest, duration)
        rayleigh, hertz = sim.comm.min(rayleigh), sim.comm.min(hertz)
        return {"rayleigh": rayleigh if math.isfinite(rayleigh) else None,
                "hertz": hertz if math.isfinite(hertz) else None, "contact": shortest}

    def reads_youngs(self, sim):
        """Whether the material gives Young's moduli (LIGGGHTS's fix property/global youngsModulus), for
        the Rayleigh and Hertz estimates of timestep_limits."""
        return find_property(sim, "youngsModulus") is not None

    @staticmethod
    def heat_fix(sim):
        return sim.fix_with(HeatTransport)

    def conducts_heat(self, sim):
        """Whether the contacts carry heat now (the ContactConduction capability): a fix heat/gran
        is defined, and this pair style composes its conduction at each run's start."""
        return self.heat_fix(sim) is not None

    def _heat_arrays(self, p):
        """(temperatures, heat flux, directional heat flux) the loop fills, or empty ones."""
        if self.contact_model.part("heat") is None:
            return NO_HEAT
        a = p.arrays
        return a["Temp"], a["heatFlux"], a["directionalHeatFlux"]

    def entry_slots(self, nlist, npairs, fresh):
        """Each list entry's contact slots (on i, on j's owner), kept between steps: a contact's are
        searched for among its particles' once and read here after (pair_forces), valid while the
        slots stay put, between two sweeps of stale contacts (at list builds); ``fresh``: forget
        them (a build, a run's setup, which packs the slots)."""
        if len(self._entry_slots) < npairs:
            self._entry_slots = np.full((npairs + npairs // 4 + 16, 2), -1, dtype=np.int32)
        elif fresh:
            self._entry_slots[:npairs] = -1
        return self._entry_slots

    def history_partners(self):
        """The tags each particle keeps a contact history with ((rows, slots), -1 empty), or None
        without a history (compute contact/atom/gran reads it as LIGGGHTS's touch flags)."""
        if self.history is None or not self.history_width:
            return None
        return self.history.partner

    def _history_arrays(self):
        if self.history is None:
            return self._no_history[0], self._no_history[1]
        return self.history.partner, self.history.values

    def contacts(self, sim, group="all"):
        """The contacts of owned particles with both particles in ``group``, as the forces of this
        moment give them (velocities, spins and springs now; nothing advanced): a dict of arrays
        over the contacts, "i" and "j" (particle rows, j possibly a ghost), "force" (on i),
        "tangential" (its tangential part) and "history" (the contact's history values as i sees
        them: the tangential spring, then the rolling spring torque where the models keep them)
        (compute pair/gran/local reads it)."""
        p = sim.particles
        nlist = sim.pair_list
        size = max(len(nlist.neighbors), 1)
        rows = np.zeros((size, 2), dtype=np.int64)
        force, tangential = np.zeros((size, 3)), np.zeros((size, 3))
        width = self.history_width
        hist = np.zeros((size, width))
        a = p.arrays
        partner, values = self._history_arrays()
        count = self.kernels.pair_contacts(
            a["x"], a["v"], a["omega"], a["radius"], a["rmass"], a.get("body_mass", NO_BODY_MASS), a["type"], a["mask"], a["tag"],
            nlist.offsets, nlist.neighbors, p.nlocal, self.contact_coeff, self.freeze_bit, sim.dt, sim.dimension,
            partner if width else partner[:0], values, np.uint32(sim.groups.bit(group)), self._liquid_arrays(p)[0],
            rows, force, tangential, hist)
        return {"i": rows[:count, 0], "j": rows[:count, 1], "force": force[:count],
                "tangential": tangential[:count], "history": hist[:count]}

    def forget_apart(self, sim, nlist, owner, touched, rows, touching, npairs):
        """After a step's contacts: forget those whose spheres came apart. LIGGGHTS forgets them only
        when the list is next built (its pair loop zeroes no spring of a listed pair that does not
        touch): spheres that touch again before then take up their old springs."""
        if self.held.ready(nlist):
            touched[:] = False
        else:
            partner, values = self._history_arrays()
            self.held.sweep_all(sim, nlist, partner, values, touched)
            # the sweep packed the slots: each entry's are searched for again
            self._entry_slots[:npairs] = -1

    def compute(self, sim, nlist, eflag, vflag):
        p = sim.particles
        update = not sim.in_setup
        owner = sim.comm.owners(p)
        with_history = self.history is not None
        partner, values = self._history_arrays()
        capacity = partner.shape[1]
        if with_history and not update:
            pack_slots(partner, values, p.nall)
        touched = self.touched_flags(p.nall if with_history else 1, capacity)
        rows, touching, npairs = self.list_rows(nlist, p.nlocal)
        entry_slots = self.entry_slots(nlist, npairs, fresh=not update or not self.held.ready(nlist))
        a = p.arrays
        liquid = self._liquid_arrays(p)
        liquid[1][:] = 0.0
        bad = self.kernels.pair_forces(
            a["x"], a["v"], a["omega"], a["radius"], a["rmass"], a.get("body_mass", NO_BODY_MASS), a["type"], a["mask"], a["f"],
            a["torque"], a["tag"], owner, nlist.offsets, nlist.neighbors, p.nlocal, self.contact_coeff, self.freeze_bit,
            sim.dt, update, sim.dimension, partner, values, touched, touching, self._ntouching, entry_slots,
            *self._block, *self._heat_arrays(p), *liquid, *NO_LOG)
        if self.contact_model.wet and bad < 0:
            self.transfer_liquid(sim, update)
        if with_history and bad < 0 and update:
            bad = self.collect_mirrors(sim, owner, touched)
            if bad < 0:
                self.forget_apart(sim, nlist, owner, touched, rows, touching, npairs)
        if not update or bad >= 0:
            self.held.invalidate()
        if bad >= 0:
            touched[:] = False
            raise SimulationError(f"particle {bad} has more than {capacity} contacts at step {sim.step}; "
                                  f"raise max_contacts of pair_style {self.name}")
        self.energy = 0.0


class PairBubble(PairGranModel):
    """LIGGGHTS's ``pair_style bubble``: the same as gran (its manual: "aliases for gran, which can
    e.g. be used for the modelling of systems with different phases using pair hybrid")."""
    name = "bubble"
    usage = PairGranModel.usage.replace("pair_style gran", "pair_style bubble", 1)
    history_name = "bubble_history"


class PairGranBubble(PairGranModel):
    """LIGGGHTS's ``pair_style gran_bubble``: the same as gran, under a third name for pair hybrid."""
    name = "gran_bubble"
    usage = PairGranModel.usage.replace("pair_style gran", "pair_style gran_bubble", 1)
    history_name = "gran_bubble_history"

