r"""Fix ``wall/dem``: granular (DEM) walls made of regions, with a linear spring-dashpot contact law
and Coulomb friction (PDPS manual 2.2.8.5).

A particle i of radius :math:`R_i` at distance :math:`d` from a wall surface, with unit normal
:math:`\mathbf{n}` from the surface to its centre, overlaps the wall by :math:`\delta = R_i - d > 0`.
The wall is body j of infinite mass and radius (so :math:`m^* = m_i`, the mass of i's rigid body where a
fix rigid makes i part of one, as pair dem/lsd's); with the relative velocity of
the contact points :math:`\mathbf{v} = \mathbf{v}_i + \boldsymbol\omega_i\times(-R_i\mathbf{n})`,
:math:`v_n = \mathbf{v}\cdot\mathbf{n}`, :math:`\mathbf{v}_t = \mathbf{v} - v_n\mathbf{n}` and the
tangential spring :math:`\boldsymbol\xi` (grown by :math:`\mathbf{v}_t\Delta t` over the contact, kept
per particle-wall contact):

.. math::

    \mathbf{F}_i = (k_n\delta - C_n v_n)\,\mathbf{n} + \mathbf{F}_t, \qquad
    \mathbf{F}_t = -k_t\boldsymbol\xi - C_t\mathbf{v}_t, \quad
    |\mathbf{F}_t| \le \mu\,|k_n\delta - C_n v_n|, \qquad
    \boldsymbol\tau_i = (-R_i\mathbf{n})\times\mathbf{F}_i

(``pdps_granular_contact.dem``: normal lsd, tangential spring; when the Coulomb limit is reached the spring is
cut back to it). The normal force is not clipped at zero near the end of a contact, as LAMMPS by default, so
a head-on impact rebounds with exactly

.. math::

    e = \exp\!\left(-\frac{\pi\zeta}{\sqrt{1-\zeta^2}}\right), \quad \zeta = \frac{C_n}{2\sqrt{k_n m_i}},
    \qquad t_c = \frac{\pi}{\sqrt{k_n/m_i - (C_n/2m_i)^2}}.

Walls are regions with a surface: ``block`` (its six faces, touched from inside as a container or
from outside as an obstacle) and ``polygon`` (a flat polygon, touched from both sides, at its face,
edges or corners); see ``pdps doc region block`` and ``pdps doc region polygon``. A particle touching
several faces (a corner of a box) gets one contact per face. Walls do not move.

Parameters:

- ``e``: restitution coefficient (0 < e <= 1). The PDPS form reads it and, as PDPS does, does not
  use it: the damping is ``Cn``. The restitution form derives ``Cn`` from it for each particle's mass.
- ``kn`` normal stiffness (force/distance), ``Cn`` normal damping (force/velocity), ``kt``
  tangential stiffness (force/distance), ``Ct`` tangential damping (force/velocity), ``mu`` friction
  coefficient (>= 0, no unit).
- ``cutoff`` (distance): the contact distance of particles without a radius (``particle_style
  atomic``), as in PDPS; spheres touch at their radius.

Syntax::

    fix ID GROUP wall/dem lsd region R1 [region R2 ...] e kn Cn kt Ct mu cutoff    (PDPS)
    fix ID GROUP wall/dem lsd region R1 [region R2 ...] e kn mu [cutoff]           (restitution form)

The restitution form sets :math:`C_n = 2\zeta\sqrt{k_n m_i}` with :math:`\zeta` from ``e`` for each
particle, :math:`k_t = \tfrac27 k_n` and :math:`C_t = C_n/2` (LAMMPS's gran/hooke defaults).

Particles with ``omega`` and ``torque`` (``particle_style sphere``) feel the torque and their spin
enters the contact velocity; others slide without rotating. Forces are added in ``post_force`` (and
at setup, without advancing the contact history). The run warns when the time step resolves the
lightest particle's contact time with fewer than 10 steps.

Cost: at each neighbor list rebuild the fix asks the regions which of its particles lie within the
largest contact distance plus the skin of a surface, and at each step visits only those (no particle
reaches a wall before the next rebuild without moving more than the skin, when the run warns).

Example (PDPS manual)::

    region wall1 polygon p1 15 0 0 p2 15 10 0 p3 10 10 0 p4 10 0 0
    region wall2 block 0 20 0 20 0 20
    fix 2 all wall/dem lsd region wall1 region wall2 0.85 3000 28.6527 571.43 15.82634 0.4 0.5
"""

import inspect
from typing import Literal, NamedTuple

import numpy as np
from numba import njit

from pdps_core.api import ContactHistory, Fix, Region, ScriptError, StyleArgs, SurfaceContacts, observables, param
from pdps_granular_contact import contact_models

from .wall_contact import HISTORY_WIDTH, ContactLaw, check_law_numbers, forget_far

ELEMENT_BITS = 32           # history key = wall number << 32 | element id on that wall


class RegionWall(NamedTuple):
    region: Literal["region"]
    ID: str


@njit(cache=True)
def merge_contacts(index_a, distance_a, normal_a, key_a, index_b, distance_b, normal_b, element_b, wall_b,
                   index, distance, normal, key):
    """The contacts a (with their history keys) and those of wall number ``wall_b`` (element ids),
    both in point order, merged in point order, a's first at a point (as a stable sort of a then
    b); b's keys become wall_b << ELEMENT_BITS | element. Returns how many rows."""
    na, nb = len(index_a), len(index_b)
    ka = kb = 0
    for m in range(na + nb):
        if kb >= nb or (ka < na and index_a[ka] <= index_b[kb]):
            index[m] = index_a[ka]
            distance[m] = distance_a[ka]
            key[m] = key_a[ka]
            for d in range(3):
                normal[m, d] = normal_a[ka, d]
            ka += 1
        else:
            index[m] = index_b[kb]
            distance[m] = distance_b[kb]
            key[m] = (wall_b << ELEMENT_BITS) + element_b[kb]
            for d in range(3):
                normal[m, d] = normal_b[kb, d]
            kb += 1
    return na + nb


@njit(cache=True)
def contact_offsets(index, count, offsets):
    """offsets[k]..offsets[k+1]: the rows of ``index`` (sorted) that belong to point k < count."""
    row = 0
    for k in range(count + 1):
        while row < len(index) and index[row] < k:
            row += 1
        offsets[k] = row


class FixWallDEM(Fix):
    name = "wall/dem"
    minimize_idle = True         # granular walls act on moving particles: LAMMPS's fix wall/gran has no min_post_force
    usage = ("fix ID GROUP wall/dem lsd region R1 [region R2 ...] e kn Cn kt Ct mu cutoff"
             " | ... e kn mu [cutoff]")

    class Args(StyleArgs):
        model: Literal["lsd"] = param()
        regions: list[RegionWall] = param(default_factory=list, names="region ID")
        law: (tuple[float, float, float, float, float, float, float] | tuple[float, float, float, float]
              | tuple[float, float, float]) = param(unit={
                  "e kn Cn kt Ct mu cutoff": ("1", "force/distance", "force/velocity", "force/distance",
                                              "force/velocity", "1", "distance"),
                  "e kn mu [cutoff]": ("1", "force/distance", "1", "distance")})

    @classmethod
    def check_args(cls, args):
        if not args.regions:
            raise ScriptError(f"expected at least one region R after lsd; usage: {cls.usage}")
        if len(args.law) == 7:
            e, kn, cn, kt, ct, mu, cutoff = args.law
            check_law_numbers(e=e, kn=kn, cn=cn, kt=kt, ct=ct, mu=mu)
        else:
            e, kn, mu, *cutoff = args.law
            check_law_numbers(e=e, kn=kn, mu=mu)
            cutoff = cutoff[0] if cutoff else None
        if cutoff is not None and not cutoff > 0.0:
            raise ScriptError(f"cutoff must be > 0 (got {cutoff:g})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if len(args.law) == 7:
            e, kn, cn, kt, ct, mu, self.cutoff = args.law
            self.law = ContactLaw.lsd(kn, mu, e=e, cn=cn, kt=kt, ct=ct)
        else:
            e, kn, mu, *cutoff = args.law
            self.law = ContactLaw.lsd(kn, mu, e=e)
            self.cutoff = cutoff[0] if cutoff else None
        self.use_regions(sim, id, [ident for _, ident in args.regions], self.law.wall_law(), HISTORY_WIDTH)

    def use_regions(self, sim, id, idents, wall_law, width):
        """The regions ``idents`` as walls of the composed law ``wall_law`` (a WallLaw), each particle's
        contacts with them keeping ``width`` values, and the buffers of the contacts of a step."""
        self.regions = []
        for ident in idents:
            region = sim.region(ident)
            if type(region).surface_contacts is Region.surface_contacts:
                raise ScriptError(f"region {region.id} ({region.name}) has no surface to act as a wall")
            if region.dynamic:
                raise ScriptError(f"region {region.id} moves (move or rotate): fix {self.name}'s walls stand still "
                                  "(fix wall/gran/region follows a moving region)")
            self.regions.append(region)
        self.history = ContactHistory(sim, f"wall_{id}", width=width)
        self._near, self._farthest = np.empty(0, dtype=np.int64), 0.0
        # positions of the near particles and their contacts' offsets, in buffers kept between rebuilds
        self._x_near_rows, self._offset_rows = np.empty((0, 3)), np.empty(1, dtype=np.int64)
        self._cutoffs = np.empty(0)
        self._still = np.zeros((0, 3))
        self._contact_force = np.empty((0, 3))
        self.wall_law = wall_law
        self._rows = [SurfaceContacts() for _ in self.regions]    # each region's contacts of a step
        # a region style written before surface_contacts took buffers (out) is called without
        self._takes_out = ["out" in inspect.signature(type(r).surface_contacts).parameters for r in self.regions]
        self._merged = (SurfaceContacts(), SurfaceContacts())      # merge_contacts' results, in turn

    def setup(self, sim):
        self.wall_law.bind(self.law.tables(sim.ntypes))
        chosen = np.flatnonzero(sim.groups.select(sim, self.group))
        self.law.check_timestep(sim, self, observables.masses(sim)[chosen])
        self.pre_neighbor(sim)
        self._forces(sim, update=False)

    def post_force(self, sim):
        self._forces(sim, update=True)

    def reach(self, sim):
        """Each particle's contact distance: its radius, or the cutoff of particles without one."""
        p = sim.particles
        if p.has("radius"):
            return p.arrays["radius"]
        if self.cutoff is None:
            raise ScriptError(f"fix {self.id} (wall/dem) needs particle radii (particle_style sphere) "
                              "or a cutoff for particles without one")
        if len(self._cutoffs) < p.nall:
            self._cutoffs = np.full(p.nall, self.cutoff)
        return self._cutoffs

    def pre_neighbor(self, sim):
        """The particles that may touch a wall before the next rebuild: within the largest contact
        distance plus the skin of a surface (a rebuild comes before any particle moves half the
        skin). Only they are visited at each step; the others' wall contacts are closed."""
        p = sim.particles
        chosen = np.flatnonzero(sim.groups.select(sim, self.group)).astype(np.int64)
        reach = self.reach(sim)
        self._farthest = float(reach[chosen].max()) if len(chosen) else 0.0
        x = p.x[chosen]
        flags = np.zeros(len(chosen), dtype=np.bool_)
        for wall in range(len(self.regions)):
            flags[self._surface(wall, x, self._farthest + sim.neighbor.skin)[0]] = True
        forget_far(self.history.partner, chosen, flags)
        self._near = chosen[flags]
        n = len(self._near)
        if len(self._x_near_rows) < n:
            self._x_near_rows = np.empty((n + n // 4 + 16, 3))
            self._offset_rows = np.empty(len(self._x_near_rows) + 1, dtype=np.int64)
        self._x_near, self._offsets = self._x_near_rows[:n], self._offset_rows[:n + 1]

    def _surface(self, wall, x, reach):
        """Region number ``wall``'s contacts with the points x, in point order, in its buffers."""
        region = self.regions[wall]
        if self._takes_out[wall]:
            return region.surface_contacts(x, reach, self._rows[wall])
        index, distance, normal, element = region.surface_contacts(x, reach)
        order = np.argsort(index, kind="stable")
        return (np.asarray(index, dtype=np.int64)[order], np.asarray(distance, dtype=np.float64)[order],
                np.ascontiguousarray(normal, dtype=np.float64)[order], np.asarray(element, dtype=np.int64)[order])

    def _forces(self, sim, update):
        p = sim.particles
        a = p.arrays
        near, x = self._near, self._x_near
        # mode clip: numpy's default (raise) buffers the output to keep it whole on a bad index
        np.take(a["x"], near, axis=0, out=x, mode="clip")
        parts = [self._surface(wall, x, self._farthest) for wall in range(len(self.regions))]
        index, distance, normal, key = parts[0]
        for wall in range(1, len(parts)):
            merged = self._merged[wall % 2]
            count = merge_contacts(index, distance, normal, key, *parts[wall], wall,
                                   *merged.room(len(index) + len(parts[wall][0])))
            index, distance, normal, key = merged.rows(count)
        contact_offsets(index, len(near), self._offsets)
        if len(self._still) < len(index):
            self._still = np.zeros((2 * len(index), 3))
            self._contact_force = np.empty((2 * len(index), 3))
        rotation = "omega" in a and "torque" in a
        omega, torque = (a["omega"], a["torque"]) if rotation else self.wall_law.still(sim)
        mass = a["rmass"] if "rmass" in a else observables.masses(sim)
        # a region wall stands still: no contact point is logged, no wall velocity
        contacts = (distance, normal, key, self._still, self._still)
        bad, _ = self.wall_law.forces(sim, near, len(near), self._offsets, contacts, self._contact_force,
                                      self.history, 0, a["f"], torque, update, radius=self.reach(sim), mass=mass,
                                      omega=omega, body_mass=a.get("body_mass", contact_models.NO_BODY_MASS))
        if bad >= 0:
            self.history.overflowed(p.tag[bad])
