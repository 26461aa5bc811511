r"""Fix ``wall/gran model ...``: LIGGGHTS's granular walls, primitive (planes, cylinders) or meshes
(``fix mesh/surface``), with LIGGGHTS's contact models and the material of ``fix property/global``
(LIGGGHTS's fix wall/gran; the LAMMPS spelling ``fix wall/gran hooke|hooke/history|hertz/history ...``
is pdps_fix_wall.wall_gran).

Contact law: composed of LIGGGHTS's sub-models as pair gran's (``pdps doc pair gran``; the
generated ``wall_forces`` of ``pdps_granular_contact.composition``), with the wall as body j:
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
Each contact keeps what its sub-models keep (tangential spring, rolling torque) and its last normal,
per particle and wall element (as fix wall/mesh keeps them, handed on from one triangle to the
next).

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

Keywords, in any order (LIGGGHTS writes the model's first): ``model`` and ``tangential``
(required), ``rolling_friction``, ``cohesion``, ``surface`` and the model settings, as pair gran
takes them (``pdps doc pair gran``; any sub-model installed, ``pdps doc gran.PART NAME``). ``store_force yes`` keeps each particle's wall force of the step (force
units, 3 values; all the wall's contacts summed) in the per-atom property ``force_ID``: dump custom
reads it as ``f_ID[k]``, or as LIGGGHTS's ``f_force_ID[k]`` (k from 1) in the LIGGGHTS dialect.
``store_force_contact yes`` (or ``store_force_contact_every N``) and ``store_force_contact_stress
yes`` are read and keep nothing: LIGGGHTS-PUBLIC keeps them in per-contact stores no output reads
(its manual: not available in the PUBLIC version; the stress one is for the CFD coupling).

Cost: the particles within their radius plus the skin of a primitive wall are listed at each
neighbor list rebuild and only they are visited; mesh walls keep fix wall/mesh's binned candidate
triangles, re-listed only after a particle or vertex has moved half the skin.

Syntax::

    fix ID GROUP wall/gran model NORMAL tangential history|no_history
        [rolling_friction ...] [cohesion ...] [SETTING on|off ...]
        primitive type N xplane|yplane|zplane C | xcylinder|ycylinder|zcylinder R C1 C2  [shear DIM V]
      | mesh n_meshes N meshes ID1 ... IDN
        [store_force yes|no] [store_force_contact yes|no] [store_force_contact_every N]
        [store_force_contact_stress yes|no]

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
from types import SimpleNamespace
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import ContactHistory, Fix, HeatTransport, ScriptError, keyword
from pdps_granular_contact import contact_models
from pdps_granular_contact.gran.heat_conduction import CONSTANT, OVERLAP
from pdps_granular_contact.material import Material
from pdps_granular_contact.gran.words import GranModelArgs

from .mesh import MeshContacts, mesh_fix
from .wall_contact import TRANSFER_COS, WallContactTable, WallLaw, forget_far

XPLANE, YPLANE, ZPLANE, XCYLINDER, YCYLINDER, ZCYLINDER = range(6)
PRIMITIVES = {"xplane": XPLANE, "yplane": YPLANE, "zplane": ZPLANE, "xcylinder": XCYLINDER,
              "ycylinder": YCYLINDER, "zcylinder": ZCYLINDER}
PrimitiveWords = (tuple[Literal["xplane", "yplane", "zplane"], float]
                  | tuple[Literal["xcylinder", "ycylinder", "zcylinder"], float, float, float])
AXES = {"x": 0, "y": 1, "z": 2}
# a primitive wall touches a sphere at one point, so one slot holds its history (ContactHistory's
# least is two); the default of 16 cost 1.3 kB a particle per wall (26 MB per wall at 20,000)
PRIMITIVE_CONTACTS = 2


@njit(cache=True)
def primitive_contact(x, i, wallstyle, position, cylinder, shear, spin, row, distance, normal, wall_velocity):
    """Particle i's contact with the primitive wall into ``row`` of ``distance``, ``normal`` and
    ``wall_velocity``; returns False when its centre lies on the wall (no normal)."""
    for d in range(3):
        wall_velocity[row, d] = shear[d]
        normal[row, d] = 0.0
    if wallstyle <= ZPLANE:
        gap = x[i, wallstyle] - position
        if gap == 0.0:
            return False
        distance[row] = abs(gap)
        normal[row, wallstyle] = 1.0 if gap > 0.0 else -1.0
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
    distance[row] = abs(across - radius)
    normal[row, a] = outward * da / across
    normal[row, b] = outward * db / across
    if spin != 0.0:
        # turning about the axis: spin e_axis x rho, rho from the axis to the contact point
        ra, rb = radius * da / across, radius * db / across
        wall_velocity[row, a] = -spin * rb
        wall_velocity[row, b] = spin * ra
        wall_velocity[row, axis] = 0.0
    return True


@njit(cache=True)
def primitive_table(near, count_near, x, wallstyle, position, cylinder, shear, spin, starts, distance, normal, key,
                    touch, wall_velocity):
    """The primitive wall's contacts of the particles ``near[:count_near]`` (one each at most, key 0)
    as a contact table: particle k's rows are starts[k] .. starts[k + 1]."""
    base = 0
    for k in range(count_near):
        i = near[k]
        starts[k] = base
        if primitive_contact(x, i, wallstyle, position, cylinder, shear, spin, base, distance, normal,
                             wall_velocity):
            key[base] = 0
            for d in range(3):
                touch[base, d] = x[i, d] - distance[base] * normal[base, d]
            base += 1
    starts[count_near] = base


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


@njit(cache=True)
def wall_conductance(kp, kw, mode, area_constant, radius, distance):
    """4 k_p k_w / (k_p + k_w) sqrt(A) of one wall contact (0 when either conductivity is), A by
    fix heat/gran's contact_area: overlap pi (R^2 - d^2) at centre distance d, constant, or pi R^2."""
    if kp <= 0.0 or kw <= 0.0:
        return 0.0
    if mode == OVERLAP:
        area = math.pi * (radius * radius - distance * distance)
    elif mode == CONSTANT:
        area = area_constant
    else:
        area = math.pi * radius * radius
    return 4.0 * kp * kw / (kp + kw) * math.sqrt(max(area, 0.0))


@njit(cache=True)
def wall_heat_flux(near, count, starts, distance, radius, ptype, wall_type, conductivity, mode, area_constant,
                   wall_temperature, temp, heat_flux, coefficient, store):
    """Heat into each particle from a wall at ``wall_temperature`` through its contacts (rows
    starts[k] .. starts[k + 1] of particle near[k], centre distance ``distance``):
    wall_conductance (T_w - T_p); the last contact's conductance into ``coefficient`` when ``store``
    (LIGGGHTS's wallHeattransferCoeff)."""
    kw = conductivity[wall_type]
    for k in range(count):
        i = near[k]
        for row in range(starts[k], starts[k + 1]):
            h = wall_conductance(conductivity[ptype[i]], kw, mode, area_constant, radius[i], distance[row])
            heat_flux[i] += h * (wall_temperature - temp[i])
            if store:
                coefficient[i] = h


@njit(cache=True)
def contact_heat(rows, distance, radius, ptype, wall_type, conductivity, mode, area_constant, wall_temperature,
                 temp, out):
    """The heat of each logged contact (particle rows[k], centre distance distance[k]) into ``out``."""
    kw = conductivity[wall_type]
    for k in range(len(rows)):
        i = rows[k]
        out[k] = wall_conductance(conductivity[ptype[i]], kw, mode, area_constant, radius[i], distance[k]) \
            * (wall_temperature - temp[i])


class FixWallGranModel(Fix):
    name = "wall/gran"
    minimize_idle = True         # LAMMPS's fix wall/gran has no min_post_force (recorded: a minimization ignores it)
    usage = ("fix ID GROUP wall/gran model hertz|hooke|hertz/stiffness|hooke/stiffness|hooke/hysteresis tangential "
             "history|no_history [rolling_friction off|cdt|epsd|epsd2|epsd3] [cohesion off|sjkr|sjkr2] "
             "[SETTING on|off] primitive type N xplane|yplane|zplane C | xcylinder|ycylinder|zcylinder R C1 C2 "
             "[shear DIM V] | mesh n_meshes N meshes ID1 ... IDN [store_force yes|no]")

    class Args(GranModelArgs):
        primitive: tuple[Literal["type"], int, PrimitiveWords] | None = keyword(None, unit={
            "type N xplane|yplane|zplane C": ("1", "1", "1", "distance"),
            "type N xcylinder|ycylinder|zcylinder R C1 C2": ("1", "1", "1", "distance", "distance", "distance")})
        mesh: tuple[Literal["n_meshes"], int, Literal["meshes"], tuple[str, ...]] | None = keyword(
            None, unit="1", names="fix mesh/surface ID")
        shear: tuple[Literal["x", "y", "z"], float] | None = keyword(None, unit=("1", "velocity"))
        store_force: bool = keyword(False)
        # per-contact stores that no output of LIGGGHTS-PUBLIC reads (its manual: "not available in the
        # PUBLIC version"; the stress one feeds the CFD coupling's fix continuum/weighted)
        store_force_contact: bool = keyword(False)
        store_force_contact_every: int | None = keyword(None, gt=0, unit="timesteps")
        store_force_contact_stress: bool = keyword(False)

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
        self.contact_model = args.contact_model()
        if self.contact_model.wet:
            raise ScriptError(f"cohesion {args.cohesion} is a liquid bridge between particles: pair gran only "
                              "(LIGGGHTS's manual: not part of fix wall/gran)")
        self.law = WallLaw(self.contact_model)
        # a wall contact keeps the law's history, then its last normal (wall_slots hands it on)
        width = self.contact_model.history_width + 3
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
        if args.store_force_contact or args.store_force_contact_every or args.store_force_contact_stress:
            sim.info(f"fix {id} wall/gran: store_force_contact and store_force_contact_stress keep nothing "
                     "any output reads (as in LIGGGHTS-PUBLIC); store_force yes keeps each particle's wall force")
        self.history = (ContactHistory(sim, f"wall_{id}", width=width, capacity=PRIMITIVE_CONTACTS)
                        if self.primitive is not None else None)
        self.mesh_contacts = [MeshContacts(sim, mesh, f"wall_{id}_{mesh.id}", group, width=width)
                              for mesh in self.meshes]
        self.table = WallContactTable()
        self._near = np.zeros(0, dtype=np.int64)
        self._count = 0
        self.heat = None        # fix heat/gran, when a mesh has a temperature (found at each run's setup)

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
        self.law.bind(Material(sim, sim.ntypes, f"fix {self.id} (wall/gran)"))
        self.heat = None
        hot = [mesh.id for mesh in self.meshes if getattr(mesh, "temperature", None) is not None]
        if hot:
            self.heat = sim.fix_with(HeatTransport)
            if self.heat is None:
                raise ScriptError(f"fix {self.id} (wall/gran): mesh {hot[0]} has a temperature, which needs a fix "
                                  "heat/gran for the particles' (LIGGGHTS: no Temp property)")
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
        if self.law.kernels is None:
            raise ScriptError(f"fix {self.id} (wall/gran) has not computed contacts yet (run 0 first)")
        p = sim.particles
        scratch = {"f": np.zeros_like(p.f), "torque": np.zeros_like(p.torque)}
        return self._forces(sim, update=False, log=True, scratch=scratch)

    def _forces(self, sim, update, log=False, scratch=None):
        p = sim.particles
        f, torque = (scratch["f"], scratch["torque"]) if scratch else (p.f, p.torque)
        table = self.table
        logs = []
        if self.primitive is not None:
            table.room(self._count, self._count)
            primitive_table(self._near, self._count, p.x, self.wallstyle, self.position, self.cylinder, self.shear,
                            self.spin, table.starts, *table.arrays())
            logs.append((0, self._wall_forces(sim, self._near, self._count, self.history, self.wall_type, f, torque,
                                              update, log, TRANSFER_COS)))
        for number, (mesh, contacts) in enumerate(zip(self.meshes, self.mesh_contacts)):
            logs.append((number, contacts.forces(sim, self.law, update, tally=None if log else mesh.tally(),
                                                 wall_type=mesh.material_type, log=log, store=bool(self.store),
                                                 f=f, torque=torque)))
            if not log and self.heat is not None and mesh.temperature is not None:
                self._conduct(sim, mesh, contacts)
        if self.store and not log:
            self._store_forces(sim, logs)
        return logs

    def _conduct(self, sim, mesh, contacts):
        """The heat of this step's contacts with a mesh that has a temperature into the particles'
        heat flux (fix heat/gran's law, its area model and conductivities)."""
        a = sim.particles.arrays
        mode, area_constant, conductivity = self.heat.wall_conduction(sim)
        store = "wallHeattransferCoeff" in a
        coefficient = a["wallHeattransferCoeff"] if store else a["heatFlux"]
        table = contacts.table
        wall_heat_flux(contacts.near, len(contacts.near), table.starts, table.distance, a["radius"], a["type"],
                       mesh.material_type, conductivity, mode, area_constant, float(mesh.temperature), a["Temp"],
                       a["heatFlux"], coefficient, store)

    def contact_heat(self, sim, number, rows, distance):
        """The heat into the particles of logged contacts with mesh ``number`` (rows, centre
        distances): 0 unless the mesh has a temperature under fix heat/gran (compute
        wall/gran/local's heatFlux)."""
        mesh = self.meshes[number] if self.meshes else None
        out = np.zeros(len(rows))
        if mesh is None or getattr(mesh, "temperature", None) is None or self.heat is None:
            return out
        a = sim.particles.arrays
        mode, area_constant, conductivity = self.heat.wall_conduction(sim)
        contact_heat(rows, np.ascontiguousarray(distance), a["radius"], a["type"], mesh.material_type, conductivity,
                     mode, area_constant, float(mesh.temperature), a["Temp"], out)
        return out

    def _wall_forces(self, sim, rows, nrows, history, wall_type, f, torque, update, log, transfer_cos):
        """The composed law on the contact table's rows; the contacts' log (rows of LOG_COLUMNS and
        the history) when asked for it or for store_force."""
        p = sim.particles
        if log:
            history = SimpleNamespace(partner=history.partner, values=history.values.copy(),
                                      overflowed=history.overflowed)
        logged = int(self.table.starts[nrows]) if (log or self.store) else 0
        table = self.table
        bad, rows_logged = self.law.forces(sim, rows, nrows, table.starts, table.arrays(), table.contact_force, history,
                                           wall_type, f, torque, update, radius=p.radius, mass=p.rmass, omega=p.omega,
                                           body_mass=p.arrays.get("body_mass", contact_models.NO_BODY_MASS),
                                           log_rows=logged, transfer_cos=transfer_cos)
        if bad >= 0:
            history.overflowed(p.tag[bad])
        return rows_logged

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
