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
:math:`\mp\mathbf{M}_r`; the laws (hertz, hooke; history, no_history; cdt, epsd, epsd2; sjkr,
sjkr2) and their formulas are ``pdps_granular_contact.liggghts``, which walls share.

Syntax (the words in any order after ``gran``, LIGGGHTS's)::

    pair_style gran model hertz|hooke tangential history|no_history
               [rolling_friction off|cdt|epsd|epsd2] [cohesion off|sjkr|sjkr2]
               [tangential_damping on|off] [limitForce on|off] [max_contacts N]
    pair_coeff * *

- ``model``: normal model; hertz needs youngsModulus, poissonsRatio, coefficientRestitution;
  hooke also characteristicVelocity (its stiffness is the Hertz one at that impact speed).
- ``tangential``: history (a spring per contact with Coulomb's limit) or no_history (viscous
  friction capped at Coulomb's limit); both read coefficientFriction.
- ``rolling_friction`` (default off): reads coefficientRollingFriction; epsd also
  coefficientRollingViscousDamping.
- ``cohesion`` (default off): reads cohesionEnergyDensity (energy/volume).
- ``tangential_damping`` (default on), ``limitForce`` (default off: a contact may pull at its end,
  which gives the restitution coefficient exactly; on: :math:`F_n \ge 0` before cohesion).
- ``max_contacts N`` (pdps keyword, default 16): contacts a particle can hold at once.

Material, from ``fix property/global`` (LIGGGHTS's names; ``fix_property``): youngsModulus
(pressure) and poissonsRatio per type (``peratomtype``), coefficientRestitution, coefficientFriction,
coefficientRollingFriction, coefficientRollingViscousDamping and cohesionEnergyDensity per type pair
(``peratomtypepair N``), characteristicVelocity (velocity, ``scalar``). They are read at the start
of each run: a missing one, a wrong count of values or a value out of range stops the run with one
line naming the property and the fix.

The contact history holds the tangential spring and the epsd/epsd2 rolling spring torque on both
spheres (pdps_pair_gran.gran: slots keyed by the partner's tag, the partner's copy negated, ghost
rows sent back to their owners in parallel runs). As in LIGGGHTS 3.8, a contact whose spheres came
apart is forgotten at the next build of the neighbor list, not at once: spheres that touch again
before then take up their old springs (its slots count towards ``max_contacts`` until then).
Needs ``atom_style granular`` (= sphere). No potential energy is reported; the neighbor cutoff is
the largest :math:`R_i + R_j` present.

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
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Pair, ScriptError, SimulationError, StyleArgs, find_slot, keyword
from pdps_granular_contact import contact_models, liggghts
from pdps_granular_contact.contact_slots import HeldRows, Mirrors, load_history, pack_slots, store_history

from .gran import DEFAULT_CONTACTS, PairGran

OnOff = Literal["on", "off"]


# _nrt=False: no reference counting of the arrays its contact helpers take (they store under
# branches, where numba's counting stays in the loop as atomic calls: numba issue #2350); nothing
# here allocates
@njit(cache=True, _nrt=False)
def gran_model_compute(x, v, omega, radius, rmass, type_, mask, f, torque, tag, owner, offsets, neighbors,
                       nlocal, models, table, charvel, nktv2p, freeze_bit, dt, update, partner, history,
                       touched, touching, ntouching, n, vtr, wr, hist, force, tangential, roll):
    """Contact forces and torques of a half list; returns -1, or the tag of a particle whose
    contact slots are full. The list entries of the contacts, in list order, go into ``touching``
    and their number into ``ntouching[0]`` (for the end-of-step sweep). The last seven arrays are
    one contact's scratch (3 each; ``hist`` HISTORY_WIDTH)."""
    m = 0
    for i in range(nlocal):
        xi0 = x[i, 0]
        xi1 = x[i, 1]
        xi2 = x[i, 2]
        radi = radius[i]
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            # most listed pairs (within the skin) do not touch: only their distance is measured
            delx = xi0 - x[j, 0]
            dely = xi1 - x[j, 1]
            delz = xi2 - x[j, 2]
            rsq = delx * delx + dely * dely + delz * delz
            radsum = radi + radius[j]
            if rsq >= radsum * radsum or rsq == 0.0:
                continue
            r = math.sqrt(rsq)
            n[0] = delx / r
            n[1] = dely / r
            n[2] = delz / r
            overlap = radsum - r
            arm_i = radi - 0.5 * overlap
            arm_j = radius[j] - 0.5 * overlap
            vr0 = v[i, 0] - v[j, 0]
            vr1 = v[i, 1] - v[j, 1]
            vr2 = v[i, 2] - v[j, 2]
            v_n = vr0 * n[0] + vr1 * n[1] + vr2 * n[2]
            w0 = arm_i * omega[i, 0] + arm_j * omega[j, 0]
            w1 = arm_i * omega[i, 1] + arm_j * omega[j, 1]
            w2 = arm_i * omega[i, 2] + arm_j * omega[j, 2]
            vtr[0] = vr0 - v_n * n[0] - (w1 * n[2] - w2 * n[1])
            vtr[1] = vr1 - v_n * n[1] - (w2 * n[0] - w0 * n[2])
            vtr[2] = vr2 - v_n * n[2] - (w0 * n[1] - w1 * n[0])
            for d in range(3):
                wr[d] = omega[i, d] - omega[j, d]
            m_eff = rmass[i] * rmass[j] / (rmass[i] + rmass[j])
            if mask[i] & freeze_bit:
                m_eff = rmass[j]
            if mask[j] & freeze_bit:
                m_eff = rmass[i]
            slot_i, slot_j = load_history(partner, history, touched, owner, tag, i, j, update, hist)
            if update and (slot_i < 0 or slot_j < 0):
                return tag[i] if slot_i < 0 else tag[j]
            touching[m] = k
            m += 1
            liggghts.liggghts_contact(models, False, table, type_[i], type_[j], r, radi, radius[j], rmass[i],
                                      rmass[j], m_eff, n, v_n, vtr, wr, charvel, nktv2p, dt, update, hist,
                                      force, tangential, roll)
            if update or slot_i >= 0:
                store_history(history, owner, i, j, slot_i, slot_j, hist)
            cx = n[1] * tangential[2] - n[2] * tangential[1]
            cy = n[2] * tangential[0] - n[0] * tangential[2]
            cz = n[0] * tangential[1] - n[1] * tangential[0]
            for d in range(3):
                f[i, d] += force[d]
                f[j, d] -= force[d]
            torque[i, 0] -= arm_i * cx + roll[0]
            torque[i, 1] -= arm_i * cy + roll[1]
            torque[i, 2] -= arm_i * cz + roll[2]
            torque[j, 0] += roll[0] - arm_j * cx
            torque[j, 1] += roll[1] - arm_j * cy
            torque[j, 2] += roll[2] - arm_j * cz
    ntouching[0] = m
    return -1


@njit(cache=True)
def gran_model_contacts(x, v, omega, radius, rmass, type_, mask, tag, offsets, neighbors, nlocal, models, table,
                        charvel, nktv2p, freeze_bit, dt, partner, history, groupbit, rows, force_out, tangential_out,
                        hist_out, n, vtr, wr, hist, force, tangential, roll):
    """Every contact of the half list whose two particles are in ``groupbit``, evaluated as the
    setup force computation does (nothing stored): returns how many; their rows (i, j), forces on
    i, tangential parts and history values (as i sees them) into the ``*_out`` arrays."""
    count = 0
    width = len(hist)
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            if not mask[j] & groupbit:
                continue
            delx = x[i, 0] - x[j, 0]
            dely = x[i, 1] - x[j, 1]
            delz = x[i, 2] - x[j, 2]
            rsq = delx * delx + dely * dely + delz * delz
            radsum = radius[i] + radius[j]
            if rsq >= radsum * radsum or rsq == 0.0:
                continue
            r = math.sqrt(rsq)
            n[0] = delx / r
            n[1] = dely / r
            n[2] = delz / r
            arm_i = radius[i] - 0.5 * (radsum - r)
            arm_j = radius[j] - 0.5 * (radsum - r)
            v_n = (v[i, 0] - v[j, 0]) * n[0] + (v[i, 1] - v[j, 1]) * n[1] + (v[i, 2] - v[j, 2]) * n[2]
            w0 = arm_i * omega[i, 0] + arm_j * omega[j, 0]
            w1 = arm_i * omega[i, 1] + arm_j * omega[j, 1]
            w2 = arm_i * omega[i, 2] + arm_j * omega[j, 2]
            vtr[0] = v[i, 0] - v[j, 0] - v_n * n[0] - (w1 * n[2] - w2 * n[1])
            vtr[1] = v[i, 1] - v[j, 1] - v_n * n[1] - (w2 * n[0] - w0 * n[2])
            vtr[2] = v[i, 2] - v[j, 2] - v_n * n[2] - (w0 * n[1] - w1 * n[0])
            for d in range(3):
                wr[d] = omega[i, d] - omega[j, d]
            m_eff = rmass[i] * rmass[j] / (rmass[i] + rmass[j])
            if mask[i] & freeze_bit:
                m_eff = rmass[j]
            if mask[j] & freeze_bit:
                m_eff = rmass[i]
            slot = find_slot(partner, i, tag[j])
            for d in range(width):
                hist[d] = history[i, width * slot + d] if slot >= 0 else 0.0
            for d in range(width):
                hist_out[count, d] = hist[d]
            liggghts.liggghts_contact(models, False, table, type_[i], type_[j], r, radius[i], radius[j], rmass[i],
                                      rmass[j], m_eff, n, v_n, vtr, wr, charvel, nktv2p, dt, False, hist, force,
                                      tangential, roll)
            rows[count, 0] = i
            rows[count, 1] = j
            for d in range(3):
                force_out[count, d] = force[d]
                tangential_out[count, d] = tangential[d]
            count += 1
    return count


class PairGranModel(PairGran):
    name = "gran"
    usage = ("pair_style gran model hertz|hooke tangential history|no_history [rolling_friction off|cdt|epsd|epsd2] "
             "[cohesion off|sjkr|sjkr2] [tangential_damping on|off] [limitForce on|off] [max_contacts N]")
    coeff_usage = "(no coefficients: pair_coeff * *; the material comes from fix property/global)"
    history_width = liggghts.HISTORY_WIDTH
    history_name = "gran_model_history"

    class Args(StyleArgs):
        model: Literal["hertz", "hooke"] = keyword(...)
        tangential: Literal["history", "no_history"] = keyword(...)
        rolling_friction: Literal["off", "cdt", "epsd", "epsd2"] = keyword("off")
        cohesion: Literal["off", "sjkr", "sjkr2"] = keyword("off")
        tangential_damping: OnOff = keyword("on")
        limitForce: OnOff = keyword("off")
        max_contacts: int = keyword(DEFAULT_CONTACTS, ge=2, le=1000, unit="dimensionless")

    def __init__(self, sim, args):
        Pair.__init__(self, sim, args)
        self.history = None
        self._touched = None
        self._rows = self._touching = self._rows_of = None
        self.held, self.mirrors = HeldRows(), Mirrors()
        self._ntouching = np.zeros(1, dtype=np.int64)
        self._scratch = tuple(np.zeros(3) for _ in range(3))
        self._contact = (np.zeros(liggghts.HISTORY_WIDTH),) + tuple(np.zeros(3) for _ in range(3))
        self.models = np.array([liggghts.NORMAL_MODELS[args.model], liggghts.TANGENTIAL_MODELS[args.tangential],
                                liggghts.ROLLING_MODELS[args.rolling_friction],
                                liggghts.COHESION_MODELS[args.cohesion], args.tangential_damping == "on",
                                args.limitForce == "on", sim.dimension], dtype=np.int64)
        self.table, self.charvel = None, 0.0

    def init(self, ntypes):
        sim = self.sim
        if "sphere" not in sim.particle_styles:
            raise ScriptError(f"pair {self.name} needs atom_style granular or sphere (per-particle radius, mass "
                              "and rotation)")
        self.models[6] = sim.dimension
        self.table, self.charvel = liggghts.material_table(sim, self.models, ntypes, f"pair {self.name}")
        self.youngs = liggghts.read_property(sim, "youngsModulus", ntypes, f"pair {self.name}")
        self.poisson = liggghts.read_property(sim, "poissonsRatio", ntypes, f"pair {self.name}")
        self.open_history()
        self.freeze_bit = np.uint32(self.frozen_group_bit(sim))
        self.radius_moving, self.radius_frozen = self.largest_radii(ntypes)
        self.check_box()
        cutoffs = Pair.init(self, ntypes)
        self.warn_coarse_timestep(sim)
        return cutoffs

    def timestep_limits(self, sim):
        """{"rayleigh": t_R, "hertz": t_H, "contact": t}: the smallest Rayleigh time of the particles
        present (LIGGGHTS's check/timestep/gran: pi R sqrt(rho/G) / (0.1631 nu + 0.8766), G = Y / 2(1 +
        nu)); LIGGGHTS's Hertz estimate, for hooke models too (its check/timestep/gran: each particle
        against its copy with m* its full mass, R* = R/2, Y* of its type, at twice the largest speed,
        2.87 (m*^2 / (R* Y*^2 v))^(1/5)); and the shortest contact of the lightest particle of each
        type hitting its copy, with m* = m/2 (module docstring; the run's own warning). None where there
        is nothing to time (no particles; for hertz, nothing moving)."""
        p = sim.particles
        nl = p.nlocal
        rayleigh = math.inf
        for t in range(1, sim.ntypes + 1):
            of_type = p.type[:nl] == t
            if not of_type.any():
                continue
            radius, mass = p.radius[:nl][of_type], p.rmass[:nl][of_type]
            density = mass / (4.0 / 3.0 * math.pi * radius ** 3)
            k = int(np.argmin(radius * np.sqrt(density)))
            shear = self.youngs[t] / (2.0 * (1.0 + self.poisson[t]))
            rayleigh = min(rayleigh, contact_models.rayleigh_time(radius[k], density[k], shear, self.poisson[t]))
        rayleigh = sim.comm.min(rayleigh)
        shortest, hertz = math.inf, math.inf
        speed = sim.comm.max(float(np.sqrt((p.v[:nl] ** 2).sum(axis=1)).max()) if nl else 0.0)
        for t in range(1, sim.ntypes + 1):
            of_type = p.type[:nl] == t
            y_star = self.table[liggghts.Y_STAR, t, t]
            if speed > 0.0 and of_type.any():
                mass, radius = p.rmass[:nl][of_type], p.radius[:nl][of_type]
                k = int(np.argmin(mass * mass / radius))
                hertz = min(hertz, 2.87 * (mass[k] ** 2 / (0.5 * radius[k] * y_star ** 2 * 2.0 * speed)) ** 0.2)
            lightest = sim.comm.min(float(p.rmass[:nl][of_type].min()) if of_type.any() else math.inf)
            if not math.isfinite(lightest):
                continue
            rows = np.flatnonzero(of_type & (p.rmass[:nl] == lightest))
            radius = sim.comm.min(float(p.radius[:nl][rows].min()) if len(rows) else math.inf)
            m_eff, r_eff = 0.5 * lightest, 0.5 * radius
            if self.models[0] == liggghts.HERTZ:
                if speed > 0.0:
                    shortest = min(shortest, contact_models.hertz_contact_time(y_star, r_eff, m_eff, 2.0 * speed))
                continue
            kn, _, gamma_n, _ = liggghts.normal_constants(liggghts.HOOKE, self.table, t, t, r_eff, m_eff, 0.0,
                                                          self.charvel, sim.units.nktv2p, True)
            rate = kn / m_eff - (gamma_n / (2.0 * m_eff)) ** 2
            shortest = min(shortest, math.pi / math.sqrt(rate) if rate > 0 else math.pi * math.sqrt(m_eff / kn))
        hertz = sim.comm.min(hertz)
        return {"rayleigh": rayleigh if math.isfinite(rayleigh) else None,
                "hertz": hertz if math.isfinite(hertz) else None, "contact": shortest}

    def contacts(self, sim, group="all"):
        """The contacts of owned particles with both particles in ``group``, as the forces of this
        moment give them (velocities, spins and springs now; nothing advanced): a dict of arrays
        over the contacts, "i" and "j" (particle rows, j possibly a ghost), "force" (on i),
        "tangential" (its tangential part) and "history" (the HISTORY_WIDTH values as i sees them)
        (compute pair/gran/local reads it)."""
        p = sim.particles
        nlist = sim.pair_list
        size = max(len(nlist.neighbors), 1)
        rows = np.zeros((size, 2), dtype=np.int64)
        force, tangential = np.zeros((size, 3)), np.zeros((size, 3))
        hist = np.zeros((size, liggghts.HISTORY_WIDTH))
        a = p.arrays
        count = gran_model_contacts(a["x"], a["v"], a["omega"], a["radius"], a["rmass"], a["type"], a["mask"], a["tag"],
                                    nlist.offsets, nlist.neighbors, p.nlocal, self.models, self.table, self.charvel,
                                    sim.units.nktv2p, self.freeze_bit, sim.dt, self.history.partner,
                                    self.history.values, np.uint32(sim.groups.bit(group)), rows, force, tangential,
                                    hist, self._scratch[0], self._scratch[1], self._scratch[2], *self._contact)
        return {"i": rows[:count, 0], "j": rows[:count, 1], "force": force[:count],
                "tangential": tangential[:count], "history": hist[:count]}

    def compute(self, sim, nlist, eflag, vflag):
        p = sim.particles
        update = not sim.in_setup
        owner = sim.comm.owners(p)
        partner, values, capacity = self.history.partner, self.history.values, self.history.capacity
        if not update:
            pack_slots(partner, values, p.nall)
        touched = self.touched_flags(p.nall, capacity)
        rows, touching, _ = self.list_rows(nlist, p.nlocal)
        a = p.arrays
        bad = gran_model_compute(a["x"], a["v"], a["omega"], a["radius"], a["rmass"], a["type"], a["mask"], a["f"],
                                 a["torque"], a["tag"], owner, nlist.offsets, nlist.neighbors, p.nlocal, self.models,
                                 self.table, self.charvel, sim.units.nktv2p, self.freeze_bit, sim.dt, update,
                                 partner, values, touched, touching, self._ntouching, self._scratch[0],
                                 self._scratch[1], self._scratch[2], *self._contact)
        if bad < 0 and update:
            bad = self.collect_mirrors(sim, owner, touched)
            if bad < 0:
                if self.held.ready(nlist):
                    # LIGGGHTS forgets a contact that came apart only when the list is next built
                    # (its pair loop zeroes no spring of a listed pair that does not touch): spheres
                    # that touch again before then take up their old springs
                    touched[:] = False
                else:
                    self.held.sweep_all(sim, nlist, partner, values, touched)
        if not update or bad >= 0:
            self.held.invalidate()
        if bad >= 0:
            touched[:] = False
            raise SimulationError(f"particle {bad} has more than {capacity} contacts at step {sim.step}; "
                                  f"raise max_contacts of pair_style {self.name}")
        self.energy = 0.0
