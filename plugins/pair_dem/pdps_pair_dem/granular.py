r"""What the DEM pair styles share: the base class that declares what granular contacts need, the
per-contact history on both particles, and the contact loop: pdps_granular_contact's composed one
(``composition``), of PDPS's sub-models (``pdps_granular_contact.dem``: surface default, normal lsd
or hertz, tangential spring), which logs each contact for ContactTable.

Geometry of a contact between spheres i and j (radii :math:`R_i, R_j`) at distance :math:`r <
R_i + R_j`: overlap :math:`\delta = R_i + R_j - r`, unit normal :math:`\mathbf{n} = (\mathbf{x}_i -
\mathbf{x}_j)/r` (from j to i), and lever arms from each centre to the contact point
:math:`a_i = R_i - \delta/2`, :math:`a_j = R_j - \delta/2` (LAMMPS's pair granular), so that
:math:`a_i + a_j = r`. The contact points move with

.. math::

    \mathbf{v} = \mathbf{v}_i - \mathbf{v}_j - (a_i\boldsymbol{\omega}_i + a_j\boldsymbol{\omega}_j)
                 \times \mathbf{n}

and the contact force :math:`\mathbf{F}` on i (:math:`-\mathbf{F}` on j) gives the torques

.. math::

    \boldsymbol{\tau}_i = -a_i\, \mathbf{n}\times\mathbf{F}, \qquad
    \boldsymbol{\tau}_j = -a_j\, \mathbf{n}\times\mathbf{F}.

Because the arms add up to the centre distance, the torques and the couple of the tangential force
cancel: a contact conserves the total angular momentum :math:`\sum \mathbf{x}\times m\mathbf{v} +
I\boldsymbol{\omega}` exactly (LAMMPS's gran/hooke/history uses the radii as arms, which loses
:math:`\delta\,\mathbf{n}\times\mathbf{F}_t` per contact).

History. The tangential spring :math:`\boldsymbol{\xi}` of a contact is kept on both particles in
``pdps_core.api.ContactHistory`` arrays, keyed by the partner's tag: i holds :math:`\boldsymbol{\xi}`
(the spring acting on i), j holds :math:`-\boldsymbol{\xi}`, so either particle can compute the pair
after a rebuild or a re-sort swaps their roles. A ghost partner's copy is written to its owner;
in a parallel run a partner owned by another rank gets it through its ghost row, which is sent back to
the owner after the pair loop and merged slot by slot (LAMMPS's reverse communication of history). A
contact not seen in a step's force computation (the spheres separated) has its slots freed at the end
of that step. In the setup force computation of a run the springs are read but not advanced (LAMMPS's
``shearupdate = 0`` during setup), so splitting a run in two does not change the trajectory.
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import ContactHistory, Pair, ScriptError, SimulationError
from pdps_granular_contact import contact_models
from pdps_granular_contact.composition import ContactModel
from pdps_granular_contact.contact_slots import PAIR_SHEAR, HeldRows, Mirrors, contact_rows, pack_slots
from pdps_granular_contact.dem.base import Tables
DEFAULT_CONTACTS = 16
NO_HEAT = (np.zeros(0), np.zeros(0), np.zeros((0, 3)))
NO_SLOTS = np.zeros((0, 2), dtype=np.int32)     # its slots move at every step's sweep: not kept per entry


@njit(cache=True)
def first_coincident(x, radius, offsets, neighbors, nlocal):
    """(i, j) of the first listed pair whose centres are closer than 1e-10 of their radii, or (-1, -1)."""
    for i in range(nlocal):
        for k in range(offsets[i], offsets[i + 1]):
            j = neighbors[k]
            tiny = 1e-10 * (radius[i] + radius[j])
            dx = x[i, 0] - x[j, 0]
            dy = x[i, 1] - x[j, 1]
            dz = x[i, 2] - x[j, 2]
            if dx * dx + dy * dy + dz * dz <= tiny * tiny:
                return i, j
    return -1, -1


class GranularPair(Pair):
    """Base of the DEM pair styles: spheres with radius, per-particle mass and rotation, ghosts that
    carry v and omega, and a tangential spring per contact."""
    per_atom = ("radius", "rmass", "omega", "torque")
    ghost_velocity = True
    ghost_fields = ("omega",)
    cutoff_from_radii = True

    def __init__(self, sim, args):
        super().__init__(sim, args)
        self.history = None
        self._touched = None
        self._law = None
        self.contact_model = ContactModel("dem", {"normal": self.normal_model, "tangential": "spring"},
                                          {"limit_damping": args.limit_damping}, log=True)
        self._block = self.contact_model.block()
        self._touching, self._ntouching = np.zeros(1, dtype=np.int32), np.zeros(1, dtype=np.int64)
        self._log_pairs = None
        self._logged = np.zeros(1, dtype=np.int64)
        self.held, self.mirrors = HeldRows(), Mirrors()

    # ---- start of a run ---------------------------------------------------------------------------
    def init(self, ntypes):
        sim = self.sim
        if "sphere" not in sim.particle_styles:
            raise ScriptError(f"pair {self.name} needs particle_style sphere "
                              "(per-particle radius, mass and rotation)")
        self.open_history()
        self._law = None        # the law's tables as this run's coefficients make them
        self.max_radius, _ = self.extremes(ntypes)
        self.check_box()
        cutoffs = super().init(ntypes)
        self.warn_coarse_timestep(sim)
        return cutoffs

    def warn_coarse_timestep(self, sim):
        """A collision resolved by few steps loses restitution silently (docs/accuracy-dem.md:
        ~9 % at t_c/10, ~21 % at t_c/5 for single collisions): say so before the run."""
        limits = self.timestep_limits(sim)
        contact = limits.get("contact") or limits.get("hertz")
        if contact:
            limit, what = contact / 10.0, f"the shortest contact ({contact:.3g})"
        elif limits.get("rayleigh"):
            limit, what = 0.2 * limits["rayleigh"], f"0.2 of the Rayleigh time ({limits['rayleigh']:.3g})"
        else:
            return
        if sim.dt > limit:
            sim.warn(f"pair {self.name}: timestep {sim.dt:g} is more than {what}"
                     f"{' / 10' if contact else ''}: collisions lose restitution (up to ~9 % at t_c/10, "
                     f"~21 % at t_c/5); use timestep <= {limit:.3g}")

    def open_history(self):
        if self.history is not None:
            return
        capacity = self.args.max_contacts
        particles = self.sim.particles
        name = f"{PAIR_SHEAR}_partner"
        if particles.has(name) and particles.arrays[name].shape[1] != capacity:
            raise ScriptError(f"max_contacts cannot change once contacts are stored "
                              f"(stored: {particles.arrays[name].shape[1]}, asked: {capacity})")
        self.history = ContactHistory(self.sim, PAIR_SHEAR, width=3, capacity=capacity)

    def extremes(self, ntypes):
        """Largest radius of each type among the particles now present or to be inserted by a fix,
        and smallest mass among those present (0 and inf for a type with none)."""
        sim, p = self.sim, self.sim.particles
        n = p.nlocal
        types, radius, mass = p.type[:n], p.radius[:n], p.rmass[:n]
        max_radius = np.zeros(ntypes + 1)
        min_mass = np.full(ntypes + 1, math.inf)
        for t in range(1, ntypes + 1):
            chosen = types == t
            max_radius[t] = sim.comm.max(float(radius[chosen].max()) if chosen.any() else 0.0)
            max_radius[t] = max([max_radius[t]] + [fix.inserted_radius(t) for fix in sim.fixes.values()])
            min_mass[t] = sim.comm.min(float(mass[chosen].min()) if chosen.any() else math.inf)
        return max_radius, min_mass

    def check_box(self):
        sim = self.sim
        largest = 2.0 * float(self.max_radius.max())
        for d, axis in enumerate("xyz"[: sim.dimension]):
            length = float(sim.box.length[d])
            if sim.box.periodic[d] and length <= largest:
                raise ScriptError(f"pair {self.name}: the periodic box is thinner along {axis} ({length:g}) "
                                  f"than the largest particle (diameter {largest:g}): a particle would "
                                  "touch its own image")

    def contact_reach(self, i, j):
        """Neighbor cutoff that sees every contact of types i and j present at the start of the run."""
        return float(self.max_radius[i] + self.max_radius[j])

    # ---- forces -----------------------------------------------------------------------------------
    def compute(self, sim, nlist, eflag, vflag):
        p = sim.particles
        if sim.in_setup:
            self.warn_coincident(sim, nlist)
        update = not sim.in_setup      # the setup forces read the springs without advancing them
        history = self.history
        partner, values = history.partner, history.values
        if not update:
            pack_slots(partner, values, p.nall)
        # cleared by free_stale after each step: allocated only when the particles outgrow it
        if self._touched is None or self._touched.shape[0] < p.nall:
            self._touched = np.zeros((p.nall, history.capacity), dtype=np.bool_)
        touched = self._touched
        owner = sim.comm.owners(p)
        bad = self.kernel(sim, nlist, update, owner, partner, values, touched)
        if bad < 0 and update:
            bad = self.collect_mirrors(sim, owner, touched)
            if bad < 0:
                self.forget_stale(sim, nlist, owner, touched)
        if not update or bad >= 0:
            self.held.invalidate()
        if bad >= 0:
            touched[:] = False
            raise SimulationError(f"particle {bad} has more than {history.capacity} contacts at step "
                                  f"{sim.step}; raise max_contacts of pair_style {self.name}")
        # contact forces are dissipative: no potential energy is reported (the elastic part is not
        # a potential once friction slides), as LAMMPS's granular pair styles
        self.energy = 0.0

    def forget_stale(self, sim, nlist, owner, touched):
        """Forget the contacts this step did not see: between two list builds a sweep of
        the rows that kept contacts and those of this step's contacts (the contact log), instead of
        every particle's row (HeldRows)."""
        partner, values = self.history.partner, self.history.values
        if not self.held.ready(nlist):
            self.held.sweep_all(sim, nlist, partner, values, touched)
            return
        ncontacts = int(self._logged[0])
        contact_rows(self._log_pairs, ncontacts, owner, self._fresh)
        self.held.sweep_of(partner, values, touched, self._fresh, 2 * ncontacts, self.mirrors.merged)

    def warn_coincident(self, sim, nlist):
        """Spheres whose centres coincide have no contact normal, so they exert no force on each
        other (as in PDPS and LAMMPS): say so at a run's start rather than let them pass silently."""
        p = sim.particles
        i, j = first_coincident(p.x, p.radius, nlist.offsets, nlist.neighbors, p.nlocal)
        found = sim.comm.max(int(p.tag[i]) if i >= 0 else -1)
        if found >= 0:
            partner = int(p.tag[j]) if i >= 0 else -1
            where = f"particles {found} and {partner}" if partner >= 0 else f"particle {found} and another"
            sim.warn(f"pair {self.name}: {where} sit at the same point at step {sim.step}: their contact "
                     "has no normal, so they exert no force on each other (separate them, or start "
                     "with fix nve/limit)")

    def collect_mirrors(self, sim, owner, touched):
        """Send springs written into rows of ghosts owned elsewhere back to their owners."""
        return self.mirrors.collect(sim, self.history, owner, touched)

    def contact_log(self, nlist):
        """Buffers the kernel fills with the contacts of this force computation (one per list pair
        at most), reused between steps."""
        size = max(len(nlist.neighbors), 1)
        if self._log_pairs is None or len(self._log_pairs) < size:
            self._log_pairs = np.empty((size, 2), dtype=np.int64)
            self._log_force = np.empty((size, 3))
            self._fresh = np.empty(2 * size, dtype=np.int32)      # the rows of each logged contact
        self._logged[0] = 0
        return self._log_pairs, self._log_force, self._logged

    def contacts(self, sim, group="all"):
        """The contacts of the last force computation with both particles in ``group`` (the
        ContactTable capability): rows "i", "j" and "force", the force on i from j."""
        m = int(self._logged[0]) if self._log_pairs is not None else 0
        pairs = self._log_pairs[:m] if m else np.zeros((0, 2), dtype=np.int64)
        force = self._log_force[:m].copy() if m else np.zeros((0, 3))
        member = (sim.particles.mask & sim.groups.bit(group)) != 0
        chosen = member[pairs[:, 0]] & member[pairs[:, 1]]
        return {"i": pairs[chosen, 0], "j": pairs[chosen, 1], "force": force[chosen]}

    def kernel(self, sim, nlist, update, owner, partner, values, touched):
        """The composed contact loop (pdps_granular_contact.dem's sub-models: surface default, the
        style's normal model, tangential spring), logging its contacts."""
        p = sim.particles
        a = p.arrays
        if self._law is None:
            self._law = self.contact_model.bind(Tables(sim.ntypes, self.law_tables()))
            self.kernels = self.contact_model.pair_kernels()
        if len(self._touching) < len(nlist.neighbors):
            self._touching = np.empty(len(nlist.neighbors) + len(nlist.neighbors) // 4 + 16, dtype=np.int32)
        return self.kernels.pair_forces(
            a["x"], a["v"], a["omega"], a["radius"], a["rmass"], a.get("body_mass", contact_models.NO_BODY_MASS),
            a["type"], a["mask"], a["f"], a["torque"], a["tag"], owner, nlist.offsets, nlist.neighbors, p.nlocal,
            self._law, np.uint32(0), sim.dt, update, sim.dimension, partner, values, touched, self._touching,
            self._ntouching, NO_SLOTS, *self._block, *NO_HEAT, *contact_models.NO_LIQUID, *self.contact_log(nlist))

    def law_tables(self):
        """The contact law's per-type-pair tables by the names its sub-models read."""
        raise NotImplementedError
