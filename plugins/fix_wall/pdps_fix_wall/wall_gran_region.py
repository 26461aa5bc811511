r"""Fix ``wall/gran/region``: LAMMPS's frictional granular walls made of a region's surface, with the
classic laws of fix wall/gran (hooke, hooke/history, hertz/history: ``pdps doc fix wall/gran``) or
the contact models of its pair granular (``granular``: ``pdps doc pair granular``, ``pdps doc
granular.PART NAME``), as LAMMPS's fix wall/gran/region.

The region's surface is LAMMPS's (Region.wall_contacts: its surface_interior with ``side in``, its
surface_exterior with ``side out``): a ``block`` with ``side in`` is a container, only particles
inside it touching it, each face closer than the particle's radius once (a sphere in a corner touches
two or three faces); with ``side out`` an obstacle touched once, at its closest point (face, edge or
corner), by the particles outside. A ``cylinder`` inside: its curved wall (unless the centre is on the
axis) and its two caps; outside: its closest point. ``intersect`` and ``union`` of them: each
region's contacts, kept where the contact point is inside all the others (intersect) or none
(union). Each contact is a wall of infinite mass: overlap :math:`\delta = R_i - d`, :math:`m^* = m_i`,
:math:`R^* = R_i` on flat faces and :math:`R^* = R_iR_w/(R_i + R_w)` on a cylinder's curved wall
(:math:`R_w = -2R` inside, :math:`2R` outside, as LAMMPS), the tangential force turning i with arm
:math:`R_i`; the wall's velocity at the contact point :math:`\mathbf{x}_c` enters the relative
velocity.

A region that moves (``region ... move v_dx v_dy v_dz``, ``rotate v_theta P R``) is followed at each
step: its variables evaluated, the contacts found in its frame and brought back, the wall velocity
:math:`\mathbf{v} + \boldsymbol\omega\times(\mathbf{x}_c - \mathbf{P} - \mathbf{d})` of LAMMPS's
finite differences over the last step (pdps_core.region_motion; 0 at the setup of the run that
takes the region up).

History, as LAMMPS's (ncontact, walls, c2r): each particle keeps the history of its contacts in
slots, each slot the face it belongs to. A particle the region does not select keeps them untouched;
one selected without contacts forgets them all. Otherwise the slots of faces no longer touched are
removed (the last slot copied over each), new faces open zeroed slots at the end, and contact number
ic (the region's order: xlo, xhi, ylo, yhi, zlo, zhi) takes the slot c2r[ic], where LAMMPS sets
c2r[slot] = ic: the right slot for one or two contacts, a permuted one when a sphere in a corner has
gained its three faces in a cyclic order (pdps follows LAMMPS; measured: a sphere pushed into a box
corner, floor first, then xlo, then ylo, keeps LAMMPS's energies to 1e-15, and differs from them by
1e-3 with each face's own spring). The setup force computation of a run does not advance the history.

The region is looked up by its ID when each run starts (LAMMPS's init): ``region ID delete`` and a
new region of that ID between runs make the wall the new region, with LAMMPS's warning "Region
properties for region ID changed between runs, resetting its motion" and its motion's velocity
started from rest.

Syntax::

    fix ID GROUP wall/gran/region hooke|hooke/history|hertz/history Kn Kt gamma_n gamma_t xmu dampflag
        [limit_damping] region REGION-ID
    fix ID GROUP wall/gran/region granular NORMAL coefficients [damping DAMPING] tangential TANGENTIAL
        coefficients [rolling sds ...] [twisting marshall|sds ...] [limit_damping] region REGION-ID

Regions: ``block`` and ``cylinder``, still or moving, and their ``intersect`` and ``union`` (side in;
their contacts have no wall velocity, as LAMMPS 22 Jul 2025's: see pdps_region_shapes.union). Not
built: sphere, cone, plane, prism and the other regions, ``open`` faces, union and intersect with
``side out``, the ``contacts`` and ``temperature`` keywords, jkr.

Cost: a still region: at each neighbor list rebuild the particles within their radius plus the skin
of the surface, the others visited no more until the next; a moving one: every particle of the group
at every step (the surface moves without the particles' lists knowing).

Example (LAMMPS's granregion box)::

    region container block -6 6 -6 6 -6 6 units box rotate v_theta 0 0 0 0 0 1
    fix container all wall/gran/region hooke/history 4000.0 NULL 100.0 NULL 0.5 1 region container
"""

from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import ContactHistory, Fix, ScriptError, StyleArgs, SurfaceContacts, keyword, param, parse_args
from pdps_granular_contact import contact_models, lammps_classic
from pdps_granular_contact.composition import ContactModel
from pdps_granular_contact.granular.base import WALL, Laws

from .wall_contact import WallContactTable, WallLaw
from .wall_gran_granular import FixWallGranGranular

CONTACTS_AT_MOST = 8        # LAMMPS's tmax: 3 for a block (a sphere in a corner), its parts' sum for intersect


class WallGranRegionArgs(StyleArgs):
    """The law's style and words (a classic law's numbers, or pair granular's model words read by
    pdps_granular_contact.granular.words) and the region."""
    style: Literal["granular", "hooke", "hooke/history", "hertz/history"] = param()
    law_words: list[str] = param(names="the law's coefficients: Kn Kt gamma_n gamma_t xmu dampflag "
                                       "[limit_damping], or pair granular's model words")
    region: str = keyword(..., names="region ID")


class ClassicWords(lammps_classic.ClassicLaw):
    limit_damping: Literal["limit_damping"] | None = param(None)


@njit(cache=True)
def lammps_contacts(rows, index, distance, normal, element, curvature, radius, partner, values, starts, out_distance,
                    out_normal, out_key, out_curvature, out_at, scratch):
    """Each particle rows[k]'s contacts closer than its radius (the region's rows of point k, in
    ``index`` order) into the table (starts, out_*; out_at: the region's row), its history slots
    kept as LAMMPS's fix wall/gran/region keeps them (see the module docstring); each contact's key
    is the wall of the slot it takes, so the force loop finds that slot (``scratch``: two rows of
    the capacity's length). Returns the table's rows, or -1 - i when particle i has too many."""
    capacity = partner.shape[1]
    stride = values.shape[1] // capacity
    row = 0
    m = 0
    for k in range(len(rows)):
        i = rows[k]
        starts[k] = m
        first = m
        while row < len(index) and index[row] < k:
            row += 1
        while row < len(index) and index[row] == k:
            if distance[row] < radius[i]:
                out_distance[m] = distance[row]
                out_key[m] = element[row]
                out_at[m] = row
                out_curvature[m] = curvature[row]
                for d in range(3):
                    out_normal[m, d] = normal[row, d]
                m += 1
            row += 1
        nc = m - first
        count = 0
        while count < capacity and partner[i, count] >= 0:
            count += 1
        if nc == 0:
            for s in range(capacity):
                partner[i, s] = -1
            continue
        if nc > capacity:
            return -1 - i
        c2r, walls = scratch[0], scratch[1]
        if nc == 1 and count == 0:
            partner[i, 0] = out_key[first]
            for h in range(stride):
                values[i, h] = 0.0
            c2r[0] = 0
        elif nc == 1 and count == 1 and partner[i, 0] == out_key[first]:
            c2r[0] = 0
        else:
            # old slots whose wall is no longer touched: the last slot copied over each
            old = 0
            while old < count:
                found = False
                for c in range(first, m):
                    if out_key[c] == partner[i, old]:
                        found = True
                if found:
                    old += 1
                else:
                    last = count - 1
                    for h in range(stride):
                        values[i, old * stride + h] = values[i, last * stride + h]
                    partner[i, old] = partner[i, last]
                    partner[i, last] = -1
                    count -= 1
            kept = count
            for c in range(first, m):
                s = -1
                for q in range(kept):
                    if partner[i, q] == out_key[c]:
                        s = q
                        break
                if s >= 0:
                    c2r[s] = c - first
                else:
                    c2r[count] = c - first
                    for h in range(stride):
                        values[i, count * stride + h] = 0.0
                    partner[i, count] = out_key[c]
                    count += 1
        # contact ic takes slot c2r[ic] (LAMMPS's indexing): its key names that slot's wall
        for ic in range(nc):
            walls[ic] = partner[i, c2r[ic]]
        for ic in range(nc):
            out_key[first + ic] = walls[ic]
    starts[len(rows)] = m
    return m


class FixWallGranRegion(Fix):
    name = "wall/gran/region"
    minimize_idle = True         # granular walls act on moving particles: LAMMPS's fix wall/gran has no min_post_force
    usage = ("fix ID GROUP wall/gran/region hooke|hooke/history|hertz/history Kn Kt gamma_n gamma_t xmu dampflag "
             "[limit_damping] region REGION-ID | granular NORMAL coefficients ... region REGION-ID")
    Args = WallGranRegionArgs

    @classmethod
    def check_args(cls, args):
        if args.style == "granular":
            FixWallGranGranular.wall_law(args.law_words)
        else:
            parse_args(ClassicWords, list(args.law_words), cls.usage)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if "sphere" not in sim.particle_styles:
            raise ScriptError("fix wall/gran/region needs atom_style sphere (per-particle radius, mass and rotation)")
        self.region_id = args.region
        self.region = self.checked_region(sim.region(args.region))
        if args.style == "granular":
            self.granular_law = FixWallGranGranular.wall_law(args.law_words)
            model = ContactModel("granular", {part: cls.name for part, (cls, _) in self.granular_law.parts.items()})
        else:
            words = parse_args(ClassicWords, list(args.law_words), self.usage)
            self.model = lammps_classic.MODELS[args.style]
            self.constants = (*words.constants(self.model, sim.units.nktv2p), words.xmu,
                              words.limit_damping is not None)
            model = lammps_classic.contact_model(self.model)
        self.law = WallLaw(model)
        # each contact's history, then its normal (the force loop stores it)
        self.history = ContactHistory(sim, f"wall_region_{id}", width=model.history_width + 3,
                                      capacity=CONTACTS_AT_MOST)
        self.table = WallContactTable()
        self._near = np.empty(0, dtype=np.int64)
        self._region_row, self._curvature = np.empty(0, dtype=np.int64), np.empty(0)
        self._contacts = SurfaceContacts()
        self._scratch = np.empty((2, CONTACTS_AT_MOST), dtype=np.int64)

    @staticmethod
    def checked_region(region):
        # a region without LAMMPS's granular surface refuses here, with its own reason
        region.own_wall_contacts(np.zeros((0, 3)), 0.0, SurfaceContacts())
        return region

    def init_run(self, sim):
        # LAMMPS's init: the region of this ID now, its motion restarted when it is another one
        try:
            region = sim.region(self.region_id)
        except ScriptError:
            raise ScriptError(f"region {self.region_id} for fix wall/gran/region does not exist") from None
        moved_in = region is not self.region
        if moved_in:
            self.region = self.checked_region(region)
            sim.warn(f"Region properties for region {self.region_id} changed between runs, resetting its motion")
        self.region.start_run(moved_in)

    def setup(self, sim):
        if self.args.style == "granular":
            self.law.bind(Laws(sim.ntypes, {(0, t): self.granular_law for t in range(1, sim.ntypes + 1)}, WALL))
        else:
            self.law.bind(lammps_classic.constants(self.model, *self.constants, sim.ntypes))
        self.pre_neighbor(sim)
        self._forces(sim, update=False)

    def pre_neighbor(self, sim):
        """A still region: the group's particles within their radius plus the skin of the surface (a
        rebuild comes before any particle moves half the skin; the others have no contact until the
        next rebuild and forget theirs). A moving region: all of the group, every step."""
        p = sim.particles
        chosen = np.flatnonzero(sim.groups.select(sim, self.group)).astype(np.int64)
        if self.region.dynamic or not len(chosen):
            self._near = chosen
            return
        radius = p.arrays["radius"]
        index = self.region.wall_contacts(p.x[chosen], float(radius[chosen].max()) + sim.neighbor.skin)[0]
        near = np.zeros(len(chosen), dtype=np.bool_)
        near[index] = True
        far = chosen[~near]
        self.history.partner[far[self.region.match(p.x[far])]] = -1
        self._near = chosen[near]

    def post_force(self, sim):
        self._forces(sim, update=True)

    def _forces(self, sim, update):
        p = sim.particles
        a = p.arrays
        region = self.region
        dynamic = region.dynamic
        if dynamic:
            region.match(a["x"][:0])            # the motion of this step (LAMMPS's prematch)
            region.set_velocity(sim.step, sim.dt)
        rows = self._near
        x = a["x"][rows]
        # LAMMPS's loop visits only the particles the region selects (their history otherwise untouched)
        rows = rows[region.match(x)]
        x = a["x"][rows]
        radius = a["radius"]
        farthest = float(radius[rows].max()) if len(rows) else 0.0
        index, distance, normal, element, curvature = region.wall_contacts(x, farthest, self._contacts)
        table = self.table.room(len(rows), len(index))
        if len(self._region_row) < table.rows:
            self._region_row = np.empty(table.rows, dtype=np.int64)
            self._curvature = np.empty(table.rows)
        count = lammps_contacts(rows, index, distance, normal, element, curvature, radius, self.history.partner,
                                self.history.values, table.starts, table.distance, table.normal, table.key,
                                self._curvature, self._region_row, self._scratch)
        if count < 0:
            self.history.overflowed(p.tag[-1 - count])
        velocity = table.wall_velocity[:count]
        if dynamic:
            region.wall_velocity(self._region_row[:count], velocity)
        else:
            velocity[:] = 0.0
        bad, _ = self.law.forces(sim, rows, len(rows), table.starts, table.arrays(), table.contact_force,
                                 self.history, 0, a["f"], a["torque"], update, radius=radius, mass=a["rmass"],
                                 omega=a["omega"], body_mass=a.get("body_mass", contact_models.NO_BODY_MASS),
                                 transfer_cos=2.0, curvature=self._curvature)
        if bad >= 0:
            self.history.overflowed(p.tag[bad])
