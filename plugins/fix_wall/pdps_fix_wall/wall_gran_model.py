r"""Fix ``wall/gran model ...``: LIGGGHTS's granular walls, primitive (planes, cylinders) or meshes
(``fix mesh/surface``), with LIGGGHTS's contact models and the material of ``fix property/global``
(LIGGGHTS's fix wall/gran; the LAMMPS spelling ``fix wall/gran hooke|hooke/history|hertz/history ...``
is pdps_fix_wall.wall_gran).

Contact law: ``pdps_granular_contact.liggghts`` with the wall as body j (``pdps doc pair gran``):
:math:`R^* = R_i`, :math:`m^* = m_i`, no spin of the wall; the material of the type pair (particle's
type, the wall's ``type``) from ``fix property/global`` (youngsModulus, poissonsRatio,
coefficientRestitution, coefficientFriction; coefficientRollingFriction,
coefficientRollingViscousDamping, cohesionEnergyDensity, characteristicVelocity as the models
need them). A particle i at distance :math:`d < R_i` from the wall (overlap :math:`\delta = R_i -
d`, normal :math:`\mathbf{n}` from the wall to its centre, contact point p) with the wall's velocity
:math:`\mathbf{v}_w(\mathbf{p})` has :math:`v_n = (\mathbf{v}_i - \mathbf{v}_w)\cdot\mathbf{n}`, the
sliding velocity :math:`\mathbf{v}_{tr} = \mathbf{v}_t - (R_i - \delta/2)\,\boldsymbol\omega_i\times
\mathbf{n}` and gets the force :math:`\mathbf{F}` of the law, the torque :math:`-(R_i -
\delta/2)\,\mathbf{n}\times\mathbf{F}_t - \mathbf{M}_r` (rolling friction :math:`\mathbf{M}_r`).
Each contact keeps its tangential spring and rolling torque per particle and wall element (as
fix wall/mesh keeps them, handed on from one triangle to the next).

Walls:

- ``primitive type N xplane|yplane|zplane C``: the plane x (y, z) = C, touched from either side.
- ``primitive type N xcylinder R C1 C2``: the cylinder of radius R about the axis along x through
  (y, z) = (C1, C2), touched from inside or outside; ``ycylinder R C1 C2`` has its axis through
  (z, x) = (C1, C2) and ``zcylinder R C1 C2`` through (x, y) = (C1, C2) (LIGGGHTS's order: the two
  coordinates that follow the axis cyclically). Distances.
- ``mesh n_meshes N meshes ID1 .. IDN``: the surfaces of N ``fix mesh/surface`` (or
  ``mesh/surface/stress``, which then sum the forces on them), each with its own ``type``; moved
  by ``fix move/mesh``, the wall velocity at each contact from their motion.

``type N`` (primitive) is the wall's material type (1..number of types).

Moving primitive walls: ``shear DIM V``: a plane slides along DIM (x, y or z, not its own normal)
with velocity V; a cylinder slides along its axis when DIM is the axis, else turns about its axis
with angular velocity V (rad/time: LIGGGHTS multiplies the axis by V; the wall velocity is taken at
the contact point, :math:`V\hat{\mathbf{a}}\times\boldsymbol\rho` with :math:`\boldsymbol\rho` from
the axis to p, where LIGGGHTS takes it at the particle's centre). Only the friction feels it.

Keywords, in any order (LIGGGHTS writes the model's first): ``model hertz|hooke`` and
``tangential history|no_history`` (required), ``rolling_friction
off|cdt|epsd|epsd2``, ``cohesion off|sjkr|sjkr2``, ``tangential_damping on|off``, ``limitForce
on|off`` (as pair gran). ``store_force yes`` keeps each particle's wall force of the step (force
units, 3 values; all the wall's contacts summed) in the per-atom property ``force_ID``: dump custom
reads it as ``f_ID[k]``, or as LIGGGHTS's ``f_force_ID[k]`` (from 0) in the LIGGGHTS dialect.

Cost: the particles within their radius plus the skin of a primitive wall are listed at each
neighbor list rebuild and only they are visited; mesh walls keep fix wall/mesh's binned candidate
triangles, re-listed only after a particle or vertex has moved half the skin.

Syntax::

    fix ID GROUP wall/gran model hertz|hooke tangential history|no_history
        [rolling_friction ...] [cohesion ...] [tangential_damping on|off] [limitForce on|off]
        primitive type N xplane|yplane|zplane C | xcylinder|ycylinder|zcylinder R C1 C2  [shear DIM V]
      | mesh n_meshes N meshes ID1 ... IDN
        [store_force yes|no]

Examples::

    fix m1 all property/global youngsModulus peratomtype 5.e6
    fix m2 all property/global poissonsRatio peratomtype 0.45
    fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
    fix m4 all property/global coefficientFriction peratomtypepair 1 0.05
    fix floor all wall/gran model hertz tangential history primitive type 1 zplane 0.0
    fix drum all wall/gran model hertz tangential history primitive type 1 zcylinder 0.05 0 0
    fix cad all mesh/surface/stress file hopper.stl type 1
    fix walls all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import ContactHistory, Fix, ScriptError, StyleArgs, keyword
from pdps_granular_contact import liggghts

from .mesh import (LIGGGHTS_LAWS, NO_PDPS_LAW, NO_TALLY, MeshContacts, mesh_fix, mesh_wall_forces,
                   no_wear)
from .wall_contact import LIGGGHTS_WIDTH, LOG_COLUMNS, TRANSFER_COS, forget_far, liggghts_wall_contacts

XPLANE, YPLANE, ZPLANE, XCYLINDER, YCYLINDER, ZCYLINDER = range(6)
PRIMITIVES = {"xplane": XPLANE, "yplane": YPLANE, "zplane": ZPLANE, "xcylinder": XCYLINDER,
              "ycylinder": YCYLINDER, "zcylinder": ZCYLINDER}
PrimitiveWords = (tuple[Literal["xplane", "yplane", "zplane"], float]
                  | tuple[Literal["xcylinder", "ycylinder", "zcylinder"], float, float, float])
AXES = {"x": 0, "y": 1, "z": 2}
WIDTH = LIGGGHTS_WIDTH
# a primitive wall touches a sphere at one point, so one slot holds its history (ContactHistory's
# least is two); the default of 16 cost 1.3 kB a particle per wall (26 MB per wall at 20,000)
PRIMITIVE_CONTACTS = 2


@njit(cache=True)
def primitive_contact(x, i, wallstyle, position, cylinder, shear, spin, distance, normal,
                      wall_velocity):
    """Particle i's contact with the primitive wall into row 0 of ``distance``, ``normal`` and
    ``wall_velocity``; returns False when its centre lies on the wall (no normal)."""
    for d in range(3):
        wall_velocity[0, d] = shear[d]
        normal[0, d] = 0.0
    if wallstyle <= ZPLANE:
        gap = x[i, wallstyle] - position
        if gap == 0.0:
            return False
        distance[0] = abs(gap)
        normal[0, wallstyle] = 1.0 if gap > 0.0 else -1.0
        return True
    axis = wallstyle - XCYLINDER
    a, b = (axis + 1) % 3, (axis + 2) % 3
    da = x[i, a] - cylinder[1]
    db = x[i, b] - cylinder[2]
    across = math.sqrt(da * da + db * db)
    if across == 0.0:
        return False
    radius = cylinder[0]
    outward = 1.0 if across > radius else -1.0
    distance[0] = abs(across - radius)
    normal[0, a] = outward * da / across
    normal[0, b] = outward * db / across
    if spin != 0.0:
        # turning about the axis: spin e_axis x rho, rho from the axis to the contact point
        ra, rb = radius * da / across, radius * db / across
        wall_velocity[0, a] = -spin * rb
        wall_velocity[0, b] = spin * ra
        wall_velocity[0, axis] = 0.0
    return True


def primitive_scratch(slots):
    """The rows liggghts_primitive_forces works in, for ``slots`` history slots a particle: made
    outside the kernel, which then allocates nothing."""
    return (np.empty(1), np.empty((1, 3)), np.empty((1, 3)), np.zeros(1, dtype=np.int64), np.empty((1, 3)),
            np.empty((1, 3)), np.empty(slots, dtype=np.bool_), np.empty(1, dtype=np.int64),
            np.empty(liggghts.HISTORY_WIDTH), np.empty(3), np.empty(3), np.empty(3), np.empty(3), np.empty(3),
            np.empty(3))


# _nrt=False: no reference counting of the arrays liggghts_wall_contacts takes (it stores under
# branches, where numba keeps an atomic incref and decref of each around every call: numba issue
# #2350): examples/liggghts, steps 8,000-10,000 (its zcylinder shell), 151 -> 45 us a step.
# Nothing here allocates.
@njit(cache=True, _nrt=False)
def liggghts_primitive_forces(near, count_near, x, v, omega, f, torque, radius, rmass, ptype,
                              wallstyle, position, cylinder, shear, spin, wall_type, models, table,
                              charvel, nktv2p, dt, update, partner, values, log, logged, scratch):
    """The primitive wall's forces on the particles ``near[:count_near]``, logged as
    liggghts_wall_contacts does (``scratch``: primitive_scratch). Returns -1, or the index of a
    particle whose contact history overflowed."""
    (distance, touch, normal, key, wall_velocity, contact_force, used, slots, hist, force, tangential, roll, n, vtr,
     wr) = scratch
    for k in range(count_near):
        i = near[k]
        count = 1 if primitive_contact(x, i, wallstyle, position, cylinder, shear, spin, distance,
                                       normal, wall_velocity) else 0
        for d in range(3):
            touch[0, d] = x[i, d] - distance[0] * normal[0, d]
        if not liggghts_wall_contacts(i, count, distance, normal, key, touch, wall_velocity, v, omega,
                                      f, torque, radius, rmass, ptype, wall_type, models, table,
                                      charvel, nktv2p, dt, update, partner, values, used, slots,
                                      hist, force, tangential, roll, n, vtr, wr, contact_force, log,
                                      logged, TRANSFER_COS):
            return i
    return -1


@njit(cache=True)
def near_primitive(x, radius, chosen, wallstyle, position, cylinder, margin, flags):
    """Flags the chosen particles within their radius plus ``margin`` of the primitive wall."""
    for k in range(len(chosen)):
        i = chosen[k]
        if wallstyle <= ZPLANE:
            gap = abs(x[i, wallstyle] - position)
        else:
            axis = wallstyle - XCYLINDER
            a, b = (axis + 1) % 3, (axis + 2) % 3
            across = math.sqrt((x[i, a] - cylinder[1]) ** 2 + (x[i, b] - cylinder[2]) ** 2)
            gap = abs(across - cylinder[0])
        flags[k] = gap < radius[i] + margin


class FixWallGranModel(Fix):
    name = "wall/gran"
    minimize_idle = True         # LAMMPS's fix wall/gran has no min_post_force (recorded: a minimization ignores it)
    usage = ("fix ID GROUP wall/gran model hertz|hooke tangential history|no_history [rolling_friction "
             "off|cdt|epsd|epsd2] [cohesion off|sjkr|sjkr2] [tangential_damping on|off] [limitForce on|off] "
             "primitive type N xplane|yplane|zplane C | xcylinder|ycylinder|zcylinder R C1 C2 [shear DIM V] | "
             "mesh n_meshes N meshes ID1 ... IDN [store_force yes|no]")

    class Args(StyleArgs):
        model: Literal[tuple(liggghts.NORMAL_MODELS)] = keyword(...)
        tangential: Literal[tuple(liggghts.TANGENTIAL_MODELS)] = keyword(...)
        rolling_friction: Literal[tuple(liggghts.ROLLING_MODELS)] = keyword("off")
        cohesion: Literal[tuple(liggghts.COHESION_MODELS)] = keyword("off")
        tangential_damping: Literal["on", "off"] = keyword("on")
        limitForce: Literal["on", "off"] = keyword("off")
        primitive: tuple[Literal["type"], int, PrimitiveWords] | None = keyword(None, unit={
            "type N xplane|yplane|zplane C": ("1", "1", "1", "distance"),
            "type N xcylinder|ycylinder|zcylinder R C1 C2": ("1", "1", "1", "distance", "distance", "distance")})
        mesh: tuple[Literal["n_meshes"], int, Literal["meshes"], tuple[str, ...]] | None = keyword(
            None, unit="1", names="fix mesh/surface ID")
        shear: tuple[Literal["x", "y", "z"], float] | None = keyword(None, unit=("1", "velocity"))
        store_force: bool = keyword(False)

    @classmethod
    def check_args(cls, args):
        if (args.primitive is None) == (args.mesh is None):
            given = "both" if args.mesh is not None else "neither"
            raise ScriptError(f"expected primitive or mesh (got {given}); usage: {cls.usage}")
        if args.primitive is not None:
            style, *values = args.primitive[2]
            if len(values) == 3 and not values[0] > 0.0:
                raise ScriptError(f"{style} radius must be > 0 (got {values[0]:g})")
            if args.shear is not None and style.endswith("plane") and args.shear[0] == style[0]:
                raise ScriptError(f"shear {args.shear[0]} would move a {style} wall along its own normal; "
                                  "shear along a direction in the plane")
            return
        if args.shear is not None:
            raise ScriptError("shear moves primitive walls; move meshes with fix move/mesh")
        _, count, _, ids = args.mesh
        if count < 1:
            raise ScriptError(f"n_meshes must be > 0 (got {count})")
        if len(ids) != count:
            raise ScriptError(f"meshes needs {count} mesh ID(s) (got {' '.join(ids) or 'none'})")
        if len(set(ids)) != len(ids):
            raise ScriptError(f"a mesh is named twice in meshes {' '.join(ids)}")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if "sphere" not in sim.particle_styles:
            raise ScriptError("fix wall/gran needs atom_style granular or sphere (per-particle radius, mass "
                              "and rotation)")
        self.models = np.array([liggghts.NORMAL_MODELS[args.model], liggghts.TANGENTIAL_MODELS[args.tangential],
                                liggghts.ROLLING_MODELS[args.rolling_friction],
                                liggghts.COHESION_MODELS[args.cohesion], int(args.tangential_damping == "on"),
                                int(args.limitForce == "on"), sim.dimension], dtype=np.int64)
        self.meshes, self.primitive = [], None
        self.shear, self.spin = np.zeros(3), 0.0
        if args.primitive is not None:
            self._primitive(sim, args.primitive, args.shear)
        else:
            self.meshes = [mesh_fix(sim, ident) for ident in args.mesh[3]]
        self.store = None
        if args.store_force:
            self.store = f"force_{self.id}"
            sim.particles.request(self.store, width=3)
        self.table, self.charvel = None, 0.0
        self.history = (ContactHistory(sim, f"wall_{id}", width=WIDTH, capacity=PRIMITIVE_CONTACTS)
                        if self.primitive is not None else None)
        self.mesh_contacts = [MeshContacts(sim, mesh, f"wall_{id}_{mesh.id}", group, width=WIDTH)
                              for mesh in self.meshes]
        self._near = np.zeros(0, dtype=np.int64)
        self._count = 0
        self._primitive_rows, self._primitive_slots = None, 0      # primitive_scratch, for that many slots
        self._not_logged = np.zeros(1, dtype=np.int64)

    def _primitive(self, sim, words, shear):
        _, kind, (style, *values) = words
        if not 1 <= kind <= sim.ntypes:
            raise ScriptError(f"type must be from 1 to {sim.ntypes}, the number of types (got {kind})")
        self.wall_type = kind
        self.wallstyle = PRIMITIVES[style]
        self.position = values[0] if len(values) == 1 else 0.0
        self.cylinder = np.array(values if len(values) == 3 else [0.0, 0.0, 0.0])
        self.primitive = style
        if shear is not None:
            dim, value = shear
            axis = AXES[dim]
            if self.wallstyle <= ZPLANE or axis == self.wallstyle - XCYLINDER:
                self.shear[axis] = value
            else:
                self.spin = value

    # ---- hooks ----
    def setup(self, sim):
        ntypes = sim.ntypes
        self.models[6] = sim.dimension
        self.table, self.charvel = liggghts.material_table(sim, self.models, ntypes, f"fix {self.id} (wall/gran)")
        for contacts in self.mesh_contacts:
            contacts.setup()
        if self.primitive is not None:
            self.pre_neighbor(sim)
        self._forces(sim, update=False)

    def pre_neighbor(self, sim):
        if self.primitive is None:
            for contacts in self.mesh_contacts:
                contacts.pre_neighbor(sim)
            return
        p = sim.particles
        chosen = np.flatnonzero(sim.groups.select(sim, self.group)).astype(np.int64)
        flags = np.zeros(len(chosen), dtype=np.bool_)
        near_primitive(p.x, p.radius, chosen, self.wallstyle, self.position, self.cylinder, sim.neighbor.skin,
                       flags)
        forget_far(self.history.partner, chosen, flags)
        self._near = chosen[flags]
        self._count = len(self._near)

    def post_force(self, sim):
        self._forces(sim, update=True)

    def contact_log(self, sim):
        """Every contact of the current step, recomputed without touching forces or histories:
        [(wall number, rows)] with one row per contact, LOG_COLUMNS (particle row, element, ...)."""
        if self.table is None:
            raise ScriptError(f"fix {self.id} (wall/gran) has not computed contacts yet (run 0 first)")
        p = sim.particles
        scratch = {"f": np.zeros_like(p.f), "torque": np.zeros_like(p.torque)}
        return self._forces(sim, update=False, log=True, scratch=scratch)

    def _scratch(self, history):
        """primitive_scratch for the history's slots, made again if their number changed."""
        slots = history.partner.shape[1]
        if self._primitive_rows is None or self._primitive_slots != slots:
            self._primitive_rows, self._primitive_slots = primitive_scratch(slots), slots
        return self._primitive_rows

    def _forces(self, sim, update, log=False, scratch=None):
        p = sim.particles
        f, torque = (scratch["f"], scratch["torque"]) if scratch else (p.f, p.torque)
        common = (p.x, p.v, p.omega, f, torque, p.radius, p.rmass, p.type)
        law = (self.models, self.table, self.charvel, sim.units.nktv2p, sim.dt, update)
        logs = []
        if self.primitive is not None:
            history = self.history
            values = history.values.copy() if log else history.values
            rows, logged = self._log_buffer(self._count if (log or self.store) else 0)
            bad = liggghts_primitive_forces(self._near, self._count, *common, self.wallstyle, self.position,
                                            self.cylinder, self.shear, self.spin, self.wall_type, *law,
                                            history.partner, values, rows, logged, self._scratch(history))
            if bad >= 0:
                history.overflowed(p.tag[bad])
            logs = [(0, rows[:logged[0]])]
            if self.store and not log:
                self._store_forces(sim, logs)
            return logs
        for number, (mesh, contacts) in enumerate(zip(self.meshes, self.mesh_contacts)):
            near, offsets, triangles = contacts.candidates_now(sim)
            tally = None if log else mesh.tally()
            if tally is not None and not update:
                tally = no_wear(tally)
            history = contacts.history
            values = history.values.copy() if log else history.values
            rows, logged = self._log_buffer(offsets[-1] if (log or self.store) else 0)
            bad = mesh_wall_forces(near, offsets, triangles, p.x, p.type, mesh.vertices, mesh.triangles,
                                   mesh.face_normal, p.radius, p.rmass, p.v, p.omega, f, torque, True,
                                   history.partner, values, LIGGGHTS_LAWS, *NO_PDPS_LAW, self.models, self.table,
                                   self.charvel, sim.units.nktv2p, mesh.material_type, sim.dt, update,
                                   mesh.velocity, mesh.spin, mesh.pivot, mesh.belt, mesh.conveyor,
                                   tally is not None, *(NO_TALLY if tally is None else tally), mesh.transfer_cos,
                                   rows, logged, contacts.scratch())
            if bad >= 0:
                history.overflowed(p.tag[bad])
            logs.append((number, rows[:logged[0]]))
        if self.store and not log:
            self._store_forces(sim, logs)
        return logs

    def _store_forces(self, sim, logs):
        """store_force yes: each particle's wall force this step, from the contacts' log."""
        p = sim.particles
        stored = p.arrays[self.store]
        stored[: p.nlocal] = 0.0
        for _, rows in logs:
            np.add.at(stored, rows[:, 0].astype(np.int64), rows[:, 8:11])

    def peratom(self, sim):
        """store_force yes: the wall force on each owned particle (nlocal, 3), for dump custom
        (``f_ID[k]``; LIGGGHTS's ``f_force_ID[k]`` in the LIGGGHTS dialect)."""
        if not self.store:
            raise ScriptError(f"fix {self.id} (wall/gran) has per-atom values only with store_force yes")
        p = sim.particles
        return p.arrays[self.store][: p.nlocal]

    def _log_buffer(self, most):
        if most == 0:
            return NO_LOG, self._not_logged
        return np.zeros((most, len(LOG_COLUMNS))), np.zeros(1, dtype=np.int64)


NO_LOG = np.zeros((0, len(LOG_COLUMNS)))
