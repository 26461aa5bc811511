r"""What LAMMPS's classic granular pair styles share (gran/hooke, gran/hooke/history,
gran/hertz/history): the script arguments, the contact history and the cutoffs. The law is composed
of pdps_granular_contact.classic's sub-models (surface default: the radii as lever arms; normal
hooke or hertz; tangential history or no_history; formulas in ``lammps_classic``'s docstring), and
the loop is the composed one over the list entries whose spheres touch (``pair_forces_touching``).

Geometry, as LAMMPS's pair_gran_*.cpp: spheres i and j (radii :math:`R_i, R_j`, masses
:math:`m_i, m_j` per particle) at distance :math:`r < R_i + R_j` overlap by :math:`\delta = R_i + R_j
- r`, with normal :math:`\mathbf{n} = (\mathbf{x}_i - \mathbf{x}_j)/r`, effective radius
:math:`R^* = R_iR_j/(R_i + R_j)` and effective mass :math:`m^* = m_im_j/(m_i + m_j)`, or the other
particle's mass when one of them is in the group of a ``fix freeze`` (the first one defined, as
LAMMPS). The contact points slide at

.. math::

    \mathbf{v}_{tr} = \mathbf{v}_t - (R_i\boldsymbol\omega_i + R_j\boldsymbol\omega_j)\times\mathbf{n}

(lever arms are the radii, not the distances to the contact point), and the tangential force
:math:`\mathbf{F}_t` of the law gives both spheres the torque
:math:`\boldsymbol\tau_{i,j} = -R_{i,j}\,\mathbf{n}\times\mathbf{F}_t`. So a contact conserves the
total angular momentum only up to :math:`\delta\,\mathbf{n}\times\mathbf{F}_t` per step, as in
LAMMPS (pair dem/lsd and dem/hertz use the contact point and conserve it exactly).

History (gran/hooke/history, gran/hertz/history): the spring :math:`\boldsymbol\xi` of a contact is
kept on both spheres in a ``pdps_core.api.ContactHistory`` keyed by the partner's tag, i holding
:math:`\boldsymbol\xi` and j :math:`-\boldsymbol\xi` (LAMMPS's history transfer between partners);
a ghost partner's copy goes to its owner, on another rank through its ghost row sent back after the
pair loop. A contact no force computation saw in a step (the spheres apart) is forgotten at the end
of that step, as LAMMPS zeroes the spring of a pair that stopped touching. The setup force
computation of a run reads the springs without growing them (LAMMPS's ``shearupdate = 0``).

The neighbor cutoff of types I, J is, as LAMMPS's, the largest sum of the radii of a moving
particle of one type and any particle of the other present at the start of the run or to be
inserted by a fix during it (two frozen particles never need to meet). No potential energy is reported (pe stays 0, as LAMMPS); the virial
is the core's :math:`\sum \mathbf{r}\cdot\mathbf{f}`.
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import ContactHistory, Pair, ScriptError, SimulationError, keyword
from pdps_granular_contact import contact_models, lammps_classic, liggghts2
from pdps_granular_contact.contact_loop import touching_pairs
from pdps_granular_contact.contact_slots import PAIR_SHEAR, HeldRows, Mirrors, pack_slots

DEFAULT_CONTACTS = 16
# the composed loop's arrays for heat, liquid and a contact log, which the classic styles have not
NO_HEAT_OR_LOG = (np.zeros(0), np.zeros(0), np.zeros((0, 3)), *contact_models.NO_LIQUID, np.zeros((0, 2), dtype=np.int64),
                  np.zeros((0, 3)), np.zeros(1, dtype=np.int64))


class GranArgs(lammps_classic.ClassicLaw):
    """``Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]``, as LAMMPS's pair_gran page, and pdps's
    ``max_contacts N``."""
    limit_damping: Literal["limit_damping"] | None = None
    max_contacts: int = keyword(DEFAULT_CONTACTS, ge=2, le=1000, unit="dimensionless")


@njit(cache=True)
def entry_rows(offsets, nlocal, rows):
    """The owned particle i of every entry of a CSR list (``rows[k]`` for ``neighbors[k]``)."""
    for i in range(nlocal):
        for k in range(offsets[i], offsets[i + 1]):
            rows[k] = i


@njit(cache=True)
def touched_rows(rows, neighbors, touching, ntouching, owner, fresh):
    """The rows whose contact slots the touching entries used: i, and j's owner (j where it has
    none), two per entry into ``fresh``."""
    for h in range(ntouching):
        k = touching[h]
        j = neighbors[k]
        fresh[2 * h] = rows[k]
        fresh[2 * h + 1] = owner[j] if owner[j] >= 0 else j


class PairGran(Pair):
    """Base of the classic granular styles: spheres with radius, per-particle mass and rotation,
    ghosts carrying v and omega; ``model`` is the law (lammps_classic.HOOKE, ...)."""
    Args = GranArgs
    per_atom = ("radius", "rmass", "omega", "torque")
    ghost_velocity = True
    ghost_fields = ("omega",)
    cutoff_from_radii = True
    model = lammps_classic.HOOKE
    history_width = 3         # values per contact: the tangential spring
    history_name = PAIR_SHEAR

    @classmethod
    def spellings(cls):
        if cls.name not in liggghts2.MODELS:
            return ()
        from .gran_model import PairGranModel
        return (PairGranModel,)

    @classmethod
    def respell(cls, dialect, words):
        """In a LIGGGHTS script, this style without coefficients is its 2.x spelling of pair gran."""
        if dialect != "liggghts" or cls.name not in liggghts2.MODELS:
            return None
        today = liggghts2.pair_words(cls.name, words)
        if today is None:
            return None
        from .gran_model import PairGranModel
        return PairGranModel, today

    def __init__(self, sim, args):
        super().__init__(sim, args)
        self.history = None
        self._touched = None
        self._rows = self._touching = self._rows_of = None
        self.held, self.mirrors = HeldRows(), Mirrors()
        self.xmu, self.limit_damping = args.xmu, args.limit_damping is not None
        self._no_history = (np.full((1, 2), -1, dtype=np.int64), np.zeros((1, 6)), 2)
        self.kn, self.kt, self.gamma_n, self.gamma_t = args.constants(self.model, sim.units.nktv2p)
        # LAMMPS's classic law, composed of pdps_granular_contact.classic's sub-models
        self.contact_model = lammps_classic.contact_model(self.model)
        self._block = self.contact_model.block()

    def init(self, ntypes):
        sim = self.sim
        if "sphere" not in sim.particle_styles:
            raise ScriptError(f"pair {self.name} needs atom_style sphere (per-particle radius, mass "
                              "and rotation)")
        if self.model != lammps_classic.HOOKE:
            self.open_history()
        self.contact_coeff = self.contact_model.bind(lammps_classic.constants(
            self.model, self.kn, self.kt, self.gamma_n, self.gamma_t, self.xmu, self.limit_damping, ntypes))
        self.kernels = self.contact_model.pair_kernels()
        self.freeze_bit = np.uint32(self.frozen_group_bit(sim))
        self.radius_moving, self.radius_frozen = self.largest_radii(ntypes)
        self.check_box()
        cutoffs = super().init(ntypes)
        self.warn_coarse_timestep(sim)
        return cutoffs

    def frozen_group_bit(self, sim):
        """The group bit of the first fix holding particles at rest (fix freeze: its particles give a
        contact the partner's mass)."""
        for fix in sim.fixes.values():
            if fix.holds_at_rest:
                return int(sim.groups.bit(fix.group))
        return 0

    def open_history(self):
        if self.history is not None:
            return
        capacity = self.args.max_contacts
        particles = self.sim.particles
        name = f"{self.history_name}_partner"
        if particles.has(name) and particles.arrays[name].shape[1] != capacity:
            raise ScriptError(f"max_contacts cannot change once contacts are stored "
                              f"(stored: {particles.arrays[name].shape[1]}, asked: {capacity})")
        values = f"{self.history_name}_history"
        if particles.has(values) and particles.arrays[values].shape[1] != capacity * self.history_width:
            stored = particles.arrays[values].shape[1] // capacity
            raise ScriptError(f"the contacts stored keep {stored} value(s) each, pair {self.name}'s "
                              f"{self.history_width}: they were written under other models (a restart file of "
                              "other model words, or of a pdps before 11-28) and cannot carry over")
        self.history = ContactHistory(self.sim, self.history_name, width=self.history_width, capacity=capacity)

    def largest_radii(self, ntypes):
        """Largest radius of each type among the moving and among the frozen particles present."""
        sim, p = self.sim, self.sim.particles
        n = p.nlocal
        frozen = (p.mask[:n] & np.uint32(self.freeze_bit)) != 0
        moving_max, frozen_max = np.zeros(ntypes + 1), np.zeros(ntypes + 1)
        for t in range(1, ntypes + 1):
            of_type = p.type[:n] == t
            for table, chosen in ((moving_max, of_type & ~frozen), (frozen_max, of_type & frozen)):
                table[t] = sim.comm.max(float(p.radius[:n][chosen].max()) if chosen.any() else 0.0)
            # particles an insertion fix will add during the run move
            moving_max[t] = max([moving_max[t]] + [fix.inserted_radius(t) for fix in sim.fixes.values()])
        return moving_max, frozen_max

    def check_box(self):
        largest = 2.0 * float(max(self.radius_moving.max(), self.radius_frozen.max()))
        for d, axis in enumerate("xyz"[: self.sim.dimension]):
            length = float(self.sim.box.length[d])
            if self.sim.box.periodic[d] and length <= largest:
                raise ScriptError(f"pair {self.name}: the periodic box is thinner along {axis} ({length:g}) "
                                  f"than the largest particle (diameter {largest:g}): a particle would "
                                  "touch its own image")

    def init_one(self, i, j):
        moving, frozen = self.radius_moving, self.radius_frozen
        return float(max(moving[i] + moving[j], frozen[i] + moving[j], moving[i] + frozen[j]))

    # ---- time-step advice -------------------------------------------------------------------------
    def timestep_limits(self, sim, at_least=0.0):
        """{"rayleigh": None, "hertz": None, "contact": t_c}: the Hooke contact time of the two
        lightest particles (lammps_classic.contact_time); for gran/hertz/history the elastic Hertz
        time of the lightest, smallest particle hitting its copy at twice the largest speed (inf
        when nothing moves)."""
        p = sim.particles
        n = p.nlocal
        lightest = sim.comm.min(float(p.rmass[:n].min()) if n else math.inf)
        if not math.isfinite(lightest):
            return {"rayleigh": None, "hertz": None, "contact": math.inf}
        m_eff = 0.5 * lightest
        if self.model != lammps_classic.HERTZ_HISTORY:
            return {"rayleigh": None, "hertz": None,
                    "contact": lammps_classic.contact_time(self.kn, self.gamma_n, m_eff)}
        speed = max(at_least, sim.comm.max(float(np.sqrt((p.v[:n] ** 2).sum(axis=1)).max()) if n else 0.0))
        smallest = sim.comm.min(float(p.radius[:n].min()))
        if speed == 0.0 or self.kn == 0.0:
            return {"rayleigh": None, "hertz": None, "contact": math.inf}
        # LAMMPS's Kn sqrt(R* delta) delta is Hertz's 4/3 E* sqrt(R*) delta^3/2 with E* = 3 Kn / 4
        hertz = contact_models.hertz_contact_time(0.75 * self.kn, 0.5 * smallest, m_eff, 2.0 * speed)
        return {"rayleigh": None, "hertz": None, "contact": hertz}

    def warn_coarse_timestep(self, sim):
        contact = self.timestep_limits(sim)["contact"]
        if math.isfinite(contact) and sim.dt > contact / 10.0:
            sim.warn(f"pair {self.name}: timestep {sim.dt:g} is more than the shortest contact "
                     f"({contact:.3g}) / 10: collisions lose restitution; use timestep <= {contact / 10.0:.3g}")

    # ---- forces -----------------------------------------------------------------------------------
    def compute(self, sim, nlist, eflag, vflag):
        p = sim.particles
        update = not sim.in_setup
        owner = sim.comm.owners(p)
        if self.history is not None:
            partner, values = self.history.partner, self.history.values
            capacity = self.history.capacity
            if not update:
                pack_slots(partner, values, p.nall)
        else:
            partner, values, capacity = self._no_history
        touched = self.touched_flags(p.nall if self.history is not None else 1, capacity)
        a = p.arrays
        rows, touching, npairs = self.list_rows(nlist, p.nlocal)
        ntouching = touching_pairs(a["x"], a["radius"], rows, nlist.neighbors, npairs, touching)
        bad = self.kernels.pair_forces_touching(
            a["x"], a["v"], a["omega"], a["radius"], a["rmass"], a.get("body_mass", contact_models.NO_BODY_MASS),
            a["type"], a["mask"], a["f"], a["torque"], a["tag"], owner, rows, nlist.neighbors, touching, ntouching,
            self.contact_coeff, self.freeze_bit, sim.dt, update, sim.dimension, partner, values, touched, *self._block,
            *NO_HEAT_OR_LOG)
        if self.history is not None and bad < 0 and update:
            bad = self.collect_mirrors(sim, owner, touched)
            if bad < 0:
                self.forget_stale(sim, nlist, owner, touched, rows, touching, ntouching)
        if not update or bad >= 0:
            self.held.invalidate()
        if bad >= 0:
            touched[:] = False
            raise SimulationError(f"particle {bad} has more than {capacity} contacts at step {sim.step}; "
                                  f"raise max_contacts of pair_style {self.name}")
        self.energy = 0.0

    def list_rows(self, nlist, nlocal):
        """The particle of every list entry (made again when the list was rebuilt), room for the
        touching entries (both grow only with the list) and the number of entries."""
        npairs = int(nlist.offsets[nlocal])
        if self._rows is None or len(self._rows) < npairs:
            size = max(npairs + npairs // 4, 64)
            self._rows, self._touching = np.empty(size, dtype=np.int32), np.empty(size, dtype=np.int32)
            # the two rows of every touching entry, for the end-of-step sweep (forget_stale)
            self._fresh = np.empty(2 * size, dtype=np.int32)
            self._rows_of = None
        if self._rows_of != (nlist, nlist.version):
            entry_rows(nlist.offsets, nlocal, self._rows)
            self._rows_of = (nlist, nlist.version)
        return self._rows, self._touching, npairs

    def forget_stale(self, sim, nlist, owner, touched, rows, touching, ntouching):
        """Forget the contacts this step did not see: between two list builds a sweep of
        the rows that kept contacts and those the touching entries used (HeldRows), instead of every
        particle's row (gran_box: 15 -> 2 us a step)."""
        partner, values = self.history.partner, self.history.values
        if not self.held.ready(nlist):
            self.held.sweep_all(sim, nlist, partner, values, touched)
            return
        touched_rows(rows, nlist.neighbors, touching, ntouching, owner, self._fresh)
        self.held.sweep_of(partner, values, touched, self._fresh, 2 * ntouching, self.mirrors.merged)

    def touched_flags(self, rows, capacity):
        """Which slots a contact touched this step; free_stale clears what it set, so the flags are
        all False between steps and are allocated only when the particles outgrow them."""
        if self._touched is None or self._touched.shape[0] < rows or self._touched.shape[1] != capacity:
            self._touched = np.zeros((max(rows, 1), capacity), dtype=np.bool_)
        return self._touched

    def collect_mirrors(self, sim, owner, touched):
        """Send springs written into rows of ghosts owned elsewhere back to their owners."""
        return self.mirrors.collect(sim, self.history, owner, touched)
