r"""Fix ``rigid/small``: many small rigid bodies, one per molecule, each owned by one rank (LAMMPS's
fix rigid/small).

The bodies move as fix ``rigid``'s do (``pdps doc fix rigid``): each step the force and torque on a
body are summed from its particles,

.. math::

    \mathbf{F} = \sum_{i \in B} \mathbf{f}_i, \qquad
    \boldsymbol{\tau} = \sum_{i \in B} (\mathbf{r}_i - \mathbf{X}) \times \mathbf{f}_i
                        \;(+\, \boldsymbol{\tau}_i \text{ of finite-size spheres}),

centre of mass X and velocity V advance by velocity Verlet, the orientation (a unit quaternion) by
Richardson iteration from the angular momentum L (``rigid/nve/small`` and ``rigid/nvt/small``: the
symplectic scheme of fix rigid/nve and rigid/nvt), and the particles follow, r_i = X + R(q) d_i,
v_i = V + omega x (r_i - X). Degrees of freedom and the constraint virial are fix rigid's: 3N - 6 removed
per body wholly in a temperature's group (3N - 5 for a linear body, 2N - 3 in 2d); the virial of the
constraint forces m (v_new - v_old) / (dt/2) - f enters the pressure (``fix_modify ID virial no``
drops it).

What differs is where a body lives. The rigid variant keeps every body on every rank and sums forces
over all ranks each step; here a body belongs to the particle nearest the centre of its bounding box
(unwrapped; the lower id on a tie), the body's *owner*, and to the rank owning that particle. The
body's record (mass, centre of mass and its image flags, velocity, angular momentum, quaternion,
principal moments) travels with the owner when it migrates between ranks (on one rank the bodies
stay in their arrays and only their owners' rows are found again after particles are sorted).
Particles of the body on the owner's rank and on its neighbours find the body through the owner's
ghost copy: each step the owner's rank sends the body's position, orientation and velocities to the
ghost copies, and the particles' force and torque sums come back onto the owner (LAMMPS's forward
and reverse communication of bodies). Nothing is summed over all ranks but totals for thermo, so the cost grows with the bodies
a rank holds. Bodies are set up at a run's start (``reinit yes``, the default; ``no``: at the first
run only) from the particles, their properties computed on the rank the molecule id hashes to and
sent back (LAMMPS's rendezvous).

The ghost cutoff (pair cutoff plus skin, or ``comm_modify cutoff``) must reach from a body's owner to
its farthest particle; the set-up prints that distance, and a particle that cannot see its owner
stops the run with a line naming it.

``f_ID``: the bodies' temperature, sum (M V^2 + sum_k I_k omega_k^2) / (N_f k_B), N_f = 6 per body less
one per linear body in 3d (intensive), as LAMMPS's rigid/small counts them (6 in 2d as well, where a
body has 3: its temperature there reads half its particles'). There is no per-body global
array (LAMMPS's rigid/small has none): ``compute rigid/local`` gives the bodies' values.

Syntax::

    fix ID GROUP rigid/small molecule [reinit yes|no] [infile FILE] [langevin TSTART TSTOP TPERIOD SEED]
        [mol TEMPLATE] [gravity FIX_ID]

- ``molecule``: one body per molecule id among the group's particles (LAMMPS's only bodystyle for
  rigid/small); the particles need molecule ids (atom_style molecular, bond, angle or full).
- ``reinit yes|no``: set the bodies up again from the particles at every run (yes) or at the first
  only.
- ``infile FILE``: mass, centre of mass, inertia tensor (about the centre of mass, box axes),
  velocity, angular momentum and the centre of mass's image flags of some bodies instead of the
  values from their particles, in fix rigid's format (``pdps doc fix rigid``; ID the molecule id).
  As LAMMPS's rigid/small: bodies the file leaves out take everything from their particles, their
  motion included (as fix rigid's), and bodies are set up at the first run only.
- ``langevin TSTART TSTOP TPERIOD SEED`` (rigid/small and rigid/nve/small; LAMMPS refuses it with
  rigid/nvt/small): fix rigid's Langevin thermostat on each body (``pdps doc fix rigid``): drag
  -M V / TPERIOD and -I_k w_k / TPERIOD about each principal axis plus uniform noise, target T ramped
  from TSTART to TSTOP (temperature, >= 0; 0 gives the drag alone), TPERIOD (time, > 0). A body's
  noise is keyed by (SEED, step, the id of its owner particle), so it is the same on any number of
  ranks (not LAMMPS's numbers, which depend on the rank; its drag alone is LAMMPS's to round-off).
- ``temp`` and ``tparam`` belong to rigid/nvt/small and rigid/npt/small, the barostat keywords (iso,
  aniso, x, y, z, couple, pchain, dilate) to rigid/nph/small and rigid/npt/small: refused here, as
  LAMMPS does.
- ``mol TEMPLATE`` (rigid/small and rigid/nve/small; the other variants refuse it): bodies made
  during a run of the copies of a molecule template (the ``molecule`` command) that fix pour ``mol
  TEMPLATE rigid ID`` inserts, as LAMMPS's set_molecule makes them: the template's body is worked out
  once, at the first run, as LAMMPS's Molecule does it (mass, centre of mass and inertia tensor
  from the file's header or its atoms, principal axes by Jacobi rotations in LAMMPS's arithmetic,
  moments decreasing, each atom's displacement in the body frame, the owner the atom nearest the
  centre of mass); a copy's centre of mass is the centre the pour chose plus the turned offset from
  the template's geometric centre, its orientation the pour's turn times the template's axes, its
  velocity the pour's and its angular momentum 0.
- ``gravity FIX_ID`` (rigid/small and rigid/nve/small): each body's centre of mass feels
  :math:`M\mathbf{g}`, g the acceleration of that fix gravity (LAMMPS's), so gravity puts no torque
  on a body whose masses come from a template's header; ``fix ... gravity ... disable`` then leaves
  the particles alone (else both act).

Units: masses (mass), positions (distance), torques (energy), as the particles'.

Examples::

    fix 1 water rigid/small molecule
    neigh_modify exclude molecule/intra water

    molecule ell ell.mol
    fix grav all gravity 9.8 vector 0 0 -1 disable
    fix rig all rigid/small molecule mol ell gravity grav
    fix ins all pour 9 0 7310 region slab mol ell rigid rig

Reference: LAMMPS's fix rigid documentation (docs/lammps.md, "fix rigid"); the integrators'
references are fix rigid's and rigid/nve's.
"""

from pathlib import Path
from types import SimpleNamespace
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Fix, MoleculeBodies, ScriptError, StyleArgs, keyword, param

from . import bodies
from .jacobi import eigen3
from .quaternion import axes_from_quaternion, quaternion_from_axes, rotation_matrix, quaternion_product
from .rigid import (EPSILON, TOLERANCE, BodyForcesTiming, BodyStyle, FixRigid, check_langevin, langevin_keyed_forces, omegas,
                    richardson_final, richardson_initial)

NO_ARRAY = np.zeros(0)
NO_ARRAY2 = np.zeros((0, 3))
# keywords LAMMPS refuses for a style of the family (Illegal fix command)
THERMOSTAT_ONLY = "only fix rigid/nvt/small and rigid/npt/small take it (as LAMMPS)"
BAROSTAT_ONLY = "only fix rigid/nph/small and rigid/npt/small take it (as LAMMPS)"
# the thermostatted and barostatted variants take no bodies added during a run, nor the gravity keyword
NOT_YET = {word: "fix rigid/small and rigid/nve/small take it; this variant does not yet" for word in ("mol", "gravity")}
BAROSTAT_REFUSED = {word: BAROSTAT_ONLY for word in ("iso", "aniso", "x", "y", "z", "couple", "pchain", "dilate")}
# a body's record, kept on its owner particle: where each value sits in the row
MASS, XCM, VCM, ANGMOM, QUAT, INERTIA, IMAGE, CONJQM, NRIGID = 0, 1, 4, 7, 10, 14, 17, 20, 24
RECORD = 25
# per-body arrays (local bodies first, then ghost copies of bodies owned elsewhere): width, type
BODY_ARRAYS = {"masstotal": (0, np.float64), "xcm": (3, np.float64), "vcm": (3, np.float64), "fcm": (3, np.float64),
               "torque": (3, np.float64), "angmom": (3, np.float64), "omega": (3, np.float64),
               "inertia": (3, np.float64), "ex": (3, np.float64), "ey": (3, np.float64), "ez": (3, np.float64),
               "image_body": (3, np.int64), "quat": (4, np.float64), "conjqm": (4, np.float64),
               "fflag": (3, np.float64), "tflag": (3, np.float64), "nrigid": (0, np.int64), "sums": (6, np.float64),
               "body_rows": (0, np.int64), "owner_tag": (0, np.int64), "langextra": (6, np.float64)}
# what ghost copies of a body need after the first half step (xcm vcm omega quat image) and after the
# second (vcm omega)
STATE, MOTION = 16, 6


@njit(cache=True)
def find_owners(tag, bodytag, nlocal, nall, rowmap, atom2row):
    """The row of each owned particle's body owner (owned rows preferred; -1 outside a body, -2
    when no copy of the owner is here); ``rowmap`` (largest tag + 1,) is scratch, -1 on entry."""
    for r in range(nall - 1, -1, -1):
        rowmap[tag[r]] = r
    missing = 0
    for i in range(nlocal):
        owner = bodytag[i]
        if owner <= 0:
            atom2row[i] = -1
        elif owner < len(rowmap) and rowmap[owner] >= 0:
            atom2row[i] = rowmap[owner]
        else:
            atom2row[i] = -2
            missing += 1
    for r in range(nall):
        rowmap[tag[r]] = -1
    return missing


@njit(cache=True)
def number_bodies(tag, bodytag, atom2row, nlocal, nall, body_of_row, atom2body, body_rows):
    """Local bodies (owner here) first, then ghost bodies (owner a ghost row some particle here
    needs); each owned particle's body index. Returns (local, ghost) counts."""
    for r in range(nall):
        body_of_row[r] = -1
    count = 0
    for r in range(nlocal):
        if bodytag[r] > 0 and bodytag[r] == tag[r]:
            body_of_row[r] = count
            body_rows[count] = r
            count += 1
    local = count
    for i in range(nlocal):
        r = atom2row[i]
        if r >= nlocal and body_of_row[r] < 0:
            body_of_row[r] = count
            body_rows[count] = r
            count += 1
    for i in range(nlocal):
        r = atom2row[i]
        atom2body[i] = body_of_row[r] if r >= 0 else -1
    return local, count - local


@njit(cache=True)
def place_bodies(tag, nlocal, owner_tag, nbody, atom2row, rowmap, body_rows, body_of_row, atom2body):
    """One rank: the bodies keep their places in the arrays; their owners' rows (-1 for an owner no
    longer here) and each owned particle's body, after particles were reordered."""
    for r in range(nlocal):
        rowmap[tag[r]] = r
        body_of_row[r] = -1
    for b in range(nbody):
        owner = owner_tag[b]
        r = rowmap[owner] if owner < len(rowmap) else -1
        body_rows[b] = r
        if r >= 0:
            body_of_row[r] = b
    for i in range(nlocal):
        r = atom2row[i]
        atom2body[i] = body_of_row[r] if r >= 0 else -1
    for r in range(nlocal):
        rowmap[tag[r]] = -1


@njit(cache=True)
def pack_state(first, last, body_rows, xcm, vcm, omega, quat, image_body, state):
    """Bodies first..last-1 into their owners' rows of ``state``: xcm vcm omega quat image (16), or,
    with ``state`` 6 wide, vcm omega."""
    motion_only = state.shape[1] == 6
    for b in range(first, last):
        r = body_rows[b]
        if motion_only:
            for d in range(3):
                state[r, d] = vcm[b, d]
                state[r, 3 + d] = omega[b, d]
            continue
        for d in range(3):
            state[r, d] = xcm[b, d]
            state[r, 3 + d] = vcm[b, d]
            state[r, 6 + d] = omega[b, d]
            state[r, 13 + d] = image_body[b, d]
        for c in range(4):
            state[r, 9 + c] = quat[b, c]


@njit(cache=True)
def unpack_state(first, last, body_rows, xcm, vcm, omega, quat, ex, ey, ez, image_body, state):
    """pack_state's inverse; the axes follow from the quaternion, as on the owner's rank."""
    motion_only = state.shape[1] == 6
    for b in range(first, last):
        r = body_rows[b]
        if motion_only:
            for d in range(3):
                vcm[b, d] = state[r, d]
                omega[b, d] = state[r, 3 + d]
            continue
        for d in range(3):
            xcm[b, d] = state[r, d]
            vcm[b, d] = state[r, 3 + d]
            omega[b, d] = state[r, 6 + d]
            image_body[b, d] = int(state[r, 13 + d])
        for c in range(4):
            quat[b, c] = state[r, 9 + c]
        axes_from_quaternion(quat, b, ex, ey, ez)


@njit(cache=True)
def ghost_sums_out(local, total, body_rows, sums, rows):
    """Zero ``rows`` (per-atom, all rows), then put the ghost bodies' sums on their owners' ghost rows."""
    rows[:] = 0.0
    for b in range(local, total):
        r = body_rows[b]
        for c in range(sums.shape[1]):
            rows[r, c] = sums[b, c]


@njit(cache=True)
def ghost_sums_in(local, body_rows, sums, rows):
    """Add what the other copies of each local body's owner collected."""
    for b in range(local):
        r = body_rows[b]
        for c in range(sums.shape[1]):
            sums[b, c] += rows[r, c]


@njit(cache=True)
def split_sums(local, sums, fcm, torque):
    for b in range(local):
        for d in range(3):
            fcm[b, d] = sums[b, d]
            torque[b, d] = sums[b, 3 + d]


@njit(cache=True)
def count_members(atom2body, chosen, extended, nlocal, sums):
    """Per body: its particles in a group, point particles (column 0) and spheres (column 1)."""
    sums[:] = 0.0
    for i in range(nlocal):
        b = atom2body[i]
        if b < 0 or not chosen[i]:
            continue
        sums[b, 1 if extended[i] else 0] += 1.0


@njit(cache=True)
def axes_of(quat, ex, ey, ez, count):
    """Principal axes of bodies 0..count-1 from their quaternions."""
    for b in range(count):
        axes_from_quaternion(quat, b, ex, ey, ez)


def principal_axes(tensor):
    """Principal moments (ascending, below EPSILON of the largest set to 0) and right-handed axes of
    inertia tensors given as (xx, yy, zz, yz, xz, xy) rows; quaternions of the axes."""
    t = tensor
    matrices = np.stack([t[:, [0, 5, 4]], t[:, [5, 1, 3]], t[:, [4, 3, 2]]], axis=1)
    moments, vectors = np.linalg.eigh(matrices)
    moments[moments < EPSILON * moments.max(axis=1, keepdims=True)] = 0.0
    ex, ey, ez = vectors[:, :, 0].copy(), vectors[:, :, 1].copy(), vectors[:, :, 2].copy()
    ez[np.einsum("bi,bi->b", np.cross(ex, ey), ez) < 0.0] *= -1.0
    quat = np.zeros((len(t), 4))
    for b in range(len(t)):
        quaternion_from_axes(ex[b], ey[b], ez[b], quat[b])
    return moments, quat


class TemplateBody:
    """A molecule template as one rigid body (LAMMPS's Molecule::compute_mass, compute_com and
    compute_inertia, which fix rigid/small mol reads): mass, centre of mass less the geometric
    centre, principal moments and the quaternion of the principal axes, each atom's displacement in
    the body frame, the atom nearest the centre of mass (the body's owner) and the largest distance
    from it to another atom."""

    def __init__(self, template, type_mass, dimension):
        self.mass, com, t = template.mass_properties(type_mass)
        found = eigen3([[t[0], t[5], t[4]], [t[5], t[1], t[3]], [t[4], t[3], t[2]]])
        if found is None:
            raise ScriptError(f"molecule {template.id}: its inertia tensor does not diagonalise (LAMMPS: "
                              "Insufficient Jacobi rotations for rigid molecule)")
        moments, vectors = found
        ex, ey, ez = (np.array([vectors[0][k], vectors[1][k], vectors[2][k]]) for k in range(3))
        largest = max(moments)
        self.inertia = np.array([0.0 if c < EPSILON * largest else c for c in moments])
        if np.dot(np.cross(ex, ey), ez) < 0.0:
            ez = -ez
        self.quat = np.zeros(4)
        quaternion_from_axes(ex, ey, ez, self.quat)
        d = template.coords - com
        self.displace = np.array([[a[0] * r[0] + a[1] * r[1] + a[2] * r[2] for a in (ex, ey, ez)] for r in d])
        self.centre_to_com = com - template.center
        self.owner = int(np.argmin([r[0] * r[0] + r[1] * r[1] + r[2] * r[2] for r in d]))
        self.extent = float(np.sqrt(((template.coords - template.coords[self.owner]) ** 2).sum(axis=1).max()))
        self.natoms = template.natoms


def template_body(template, type_mass, dimension):
    if template.natoms < 2:
        raise ScriptError(f"molecule {template.id} has {template.natoms} atom: a rigid body needs at least 2")
    return TemplateBody(template, type_mass, dimension)


class FixRigidSmall(BodyForcesTiming, Fix):
    name = "rigid/small"
    time_integrate = True
    usage = ("fix ID GROUP rigid/small molecule [reinit yes|no] [infile FILE] [langevin TSTART TSTOP TPERIOD SEED] "
             "[mol TEMPLATE] [gravity FIX_ID]")
    can_virial = True
    virial_default = True
    virial_after = "final_integrate"
    refused = {"temp": THERMOSTAT_ONLY, "tparam": THERMOSTAT_ONLY} | BAROSTAT_REFUSED

    class Args(StyleArgs):
        # read as fix rigid's, to say that only molecule is taken
        bodystyle: BodyStyle = param(names="group ID", unit={"group": ("1", "1", "1")})
        reinit: Literal["yes", "no"] = keyword("yes")
        infile: str | None = keyword(None)
        langevin: tuple[float, float, float, int] | None = keyword(
            None, unit=("temperature", "temperature", "time", "dimensionless"))
        mol: str | None = keyword(None)
        gravity: str | None = keyword(None)

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        style = args.bodystyle if isinstance(args.bodystyle, str) else args.bodystyle[0]
        if style != "molecule":
            raise ScriptError(f"fix {cls.name} takes bodystyle molecule only (as LAMMPS's; got {style}): "
                              "fix rigid has the others")
        check_langevin(args.langevin)

    # ---- set-up ----------------------------------------------------------------------------------
    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box(f"fix {id} ({self.name})")
        p = sim.particles
        if not p.has("molecule"):
            raise ScriptError(f"fix {id}: bodystyle molecule needs molecule ids (atom_style molecular, bond, angle "
                              f"or full; particle style here: {sim.particle_style})")
        self.tag_name = f"rigid_small_owner_{id}"
        self.displace_name = f"rigid_small_displace_{id}"
        self.record_name = f"rigid_small_record_{id}"
        p.request(self.tag_name, dtype=np.int64, default=0, ghost=False)
        p.request(self.displace_name, width=3, ghost=False)
        if p.has("rmass"):
            # granular contacts take a clump's mass for their effective mass (LAMMPS's mass_rigid,
            # which pair gran/* and fix wall/gran read from rigid/small as from rigid)
            p.request("body_mass")
        # on one rank bodies never move between ranks: no per-particle record, no ghost bodies
        self.parallel = sim.comm.nprocs > 1
        if self.parallel:
            p.request(self.record_name, width=RECORD, ghost=False)
            self.state_name = f"rigid_small_state_{id}"
            self.motion_name = f"rigid_small_motion_{id}"
            self.sums_name = f"rigid_small_sums_{id}"
            p.request(self.state_name, width=STATE)
            p.request(self.motion_name, width=MOTION)
            p.request(self.sums_name, width=6)
        members = sim.groups.select(sim, group)
        self.nbody = 0              # counted when the bodies are set up
        self.body_template = sim.molecule_template(args.mol) if args.mol is not None else None
        self.template_body = None   # the template's body, worked out at the first run (masses may come later)
        self.gvec = None
        if self.body_template is None and sim.comm.sum(int(members.sum())) == 0:
            raise ScriptError(f"fix {id}: no particles in group {group} to make rigid bodies of")
        self._check_other_fixes(sim, members)
        self.from_file = self._read_infile(sim, members) if args.infile is not None else {}
        self.capacity = 0
        self._allocate(16)
        self.nlocal_body = self.nghost_body = 0
        self.atom2body = np.full(0, -1, dtype=np.int64)
        self.atom2row = np.full(0, -1, dtype=np.int64)
        self.body_of_row = np.full(0, -1, dtype=np.int64)
        self.rowmap = np.full(1, -1, dtype=np.int64)
        self.step_virial = np.zeros(6)
        self.final_virial = np.zeros(6)
        self.set_up = 0
        self.compact = False        # the bodies' arrays and each particle's body are current (after pre_neighbor)
        self.atom_arrays = None
        self.maxextent = 0.0
        self.dof_cache = {}

    def _check_other_fixes(self, sim, members):
        p = sim.particles
        n = p.nlocal
        for other in sim.fixes.values():
            if other is self or other.id == self.id:
                continue
            if isinstance(other, FixRigid) and p.has(other.body_name):
                theirs = p.arrays[other.body_name][:n] >= 0
            elif isinstance(other, FixRigidSmall):
                theirs = sim.groups.select(sim, other.group)
            else:
                continue
            both = members & theirs
            tag = sim.comm.min((int(p.tag[:n][both].min()) if both.any() else np.iinfo(np.int64).max,))[0]
            if tag == np.iinfo(np.int64).max:
                continue
            i = p.index_of_tag(tag)
            where = f"molecule {int(p.molecule[i])}" if i >= 0 else "a molecule"
            raise ScriptError(f"particle {tag} is in two bodies: {where} of fix {self.id} and a body of fix "
                              f"{other.id} ({other.name})")

    def _read_infile(self, sim, members):
        """``infile FILE``: {molecule id: LAMMPS's 19 values of the body}, read and checked as fix rigid
        reads it (its parser, told the molecule ids of the group's bodies)."""
        mol = sim.particles.molecule[: sim.particles.nlocal][members]
        ids = np.unique(sim.comm.allgather_rows(np.unique(mol)))
        reader = SimpleNamespace(id=self.id, body_ids=ids)
        found, problem = {}, None
        if sim.comm.is_root:
            try:
                found = FixRigid._parse_infile(reader, Path(sim.resolve(self.args.infile)))
            except ScriptError as error:
                problem = str(error)
            except OSError as error:
                problem = f"infile {self.args.infile}: cannot read it ({error.strerror or error})"
        found, problem = sim.comm.bcast((found, problem))
        if problem:
            raise ScriptError(problem)
        return {int(ids[index]): np.asarray(row, dtype=np.float64) for index, row in found.items()}

    def _allocate(self, count):
        """Room for ``count`` bodies (local and ghost), values kept."""
        if count <= self.capacity:
            return
        size = max(count, int(1.5 * self.capacity) + 16)
        old = self.capacity
        for name, (width, dtype) in BODY_ARRAYS.items():
            shape = (size, width) if width else (size,)
            fresh = np.zeros(shape, dtype=dtype)
            if old:
                fresh[:old] = getattr(self, name)
            setattr(self, name, fresh)
        self.capacity = size
        self._flags()

    def _flags(self):
        self.fflag[:] = 1.0
        self.tflag[:] = 1.0
        if self.sim.dimension == 2:
            self.fflag[:, 2] = 0.0
            self.tflag[:, :2] = 0.0

    def setup_bodies(self, sim):
        """Every body from its particles (LAMMPS's create_bodies and setup_bodies_static/dynamic):
        each group particle's row goes to the rank its molecule id hashes to, which computes the
        body and sends back to each particle its owner's id and body-frame displacement, and to
        the owner the body's record."""
        p = sim.particles
        n = p.nlocal
        a = p.arrays
        length = np.asarray(sim.box.length, dtype=np.float64)
        periodic = np.asarray(sim.box.periodic, dtype=np.bool_)
        members = np.flatnonzero(sim.groups.select(sim, self.group))
        image = a["image"][members]
        message = None
        stray = (image != 0) & ~periodic[None, :]
        if stray.any():
            i = members[int(np.flatnonzero(stray.any(axis=1))[0])]
            message = (f"fix {self.id}: particle {int(p.tag[i])} of a rigid body has a non-zero image flag in a "
                       "non-periodic dimension")
        masses = a["rmass"][members] if p.has("rmass") else sim.mass[a["type"][members]]
        if not np.all(np.isfinite(masses)) or np.any(masses <= 0):
            message = message or f"fix {self.id}: every particle of a rigid body needs a positive mass"
        sim.comm.agree(message)
        spheres = p.has("radius")
        spinning = p.has("omega")
        columns = [members.astype(np.float64)[:, None], p.tag[members].astype(np.float64)[:, None],
                   p.molecule[members].astype(np.float64)[:, None], a["x"][members] + image * length,
                   masses[:, None], a["v"][members]]
        if spheres:
            columns.append(a["radius"][members][:, None])
        if spinning:
            columns.append(a["omega"][members])
        rows = np.hstack(columns) if len(members) else np.zeros((0, 10 + spheres + 3 * spinning))
        ranks = (p.molecule[members] % sim.comm.nprocs).astype(np.int64)
        received, came_from = sim.comm.send_rows(rows, ranks)
        answers, problem, extent = self._bodies_of(sim, received, spheres, spinning, length, periodic)
        sim.comm.agree(problem)
        back, _ = sim.comm.send_rows(answers, came_from)
        bodytag = a[self.tag_name]
        bodytag[:n] = 0
        index = back[:, 0].astype(np.int64)
        bodytag[index] = back[:, 1].astype(np.int64)
        if p.has("body_mass"):
            a["body_mass"][:n] = 0.0
            a["body_mass"][index] = back[:, 6 + RECORD]
        a[self.displace_name][index] = back[:, 2:5]
        owners = back[:, 5] > 0.0
        if self.parallel:
            a[self.record_name][index[owners]] = back[owners, 6:6 + RECORD]
        else:
            count = int(owners.sum())
            self._allocate(count)
            self._load(back[owners, 6:6 + RECORD], count)
            self.owner_tag[:count] = back[owners, 1].astype(np.int64)
            self.nlocal_body = count
        extent = float(sim.comm.max(extent))
        count = int(sim.comm.sum(int(owners.sum())))
        atoms = int(sim.comm.sum(len(index)))
        self.nbody = count
        if not self.set_up:
            sim.info(f"fix {self.id}: {count} rigid bodies with {atoms} particles; {extent:.8g} = max distance from "
                     "body owner to body particle")
        self.maxextent = extent
        self.set_up += 1
        self.compact = False
        self.dof_cache = {}

    def _bodies_of(self, sim, rows, spheres, spinning, length, periodic):
        """The bodies of the particle rows this rank received: (answers, problem, max extent); an
        answer row per particle: its index on its rank, owner id, displacement (3), 1 for the owner,
        the body's record (owners' rows only) and the body's mass."""
        count = len(rows)
        answers = np.zeros((count, 7 + RECORD))
        if count == 0:
            return answers, None, 0.0
        tag, mol, xu, m, v = rows[:, 1], rows[:, 2], rows[:, 3:6], rows[:, 6], rows[:, 7:10]
        radius = rows[:, 10] if spheres else NO_ARRAY
        omega_atom = np.ascontiguousarray(rows[:, 10 + spheres:13 + spheres]) if spinning else NO_ARRAY2
        ids, body = np.unique(mol, return_inverse=True)
        body = body.astype(np.int64)
        nb = len(ids)
        nrigid = np.bincount(body, minlength=nb)
        if np.any(nrigid <= 1):
            k = int(np.flatnonzero(nrigid <= 1)[0])
            return answers, (f"fix {self.id}: body of molecule {int(ids[k])} has {nrigid[k]} particle(s); a rigid "
                             "body needs at least 2"), 0.0
        # the owner: the particle nearest the centre of the body's bounding box, the lower id on a tie
        low = np.full((nb, 3), np.inf)
        high = np.full((nb, 3), -np.inf)
        np.minimum.at(low, body, xu)
        np.maximum.at(high, body, xu)
        rsq = ((xu - 0.5 * (low + high)[body]) ** 2).sum(axis=1)
        order = np.lexsort((tag, rsq, body))
        first = order[np.searchsorted(body[order], np.arange(nb))]
        owner_tag = tag[first]
        extent = float(np.sqrt(((xu - xu[first][body]) ** 2).sum(axis=1).max()))
        # the body's properties, from unwrapped positions (image flags 0)
        xu = np.ascontiguousarray(xu)
        zero_image = np.zeros((count, 3), dtype=np.int32)
        zero_body_image = np.zeros((nb, 3), dtype=np.int64)
        no_types = np.zeros(count, dtype=np.int32)
        sums = bodies.mass_and_centre(xu, zero_image, body, no_types, NO_ARRAY, m, length, count, nb)
        masstotal = sums[:, 3].copy()
        xcm = sums[:, :3] / masstotal[:, None]
        # infile: LAMMPS's values (centre of mass with its image flags) instead of the particles'
        listed = [(b, self.from_file[int(ident)]) for b, ident in enumerate(ids) if int(ident) in self.from_file]
        for b, row in listed:
            masstotal[b] = row[0]
            xcm[b] = row[1:4] + row[16:19] * length
        tensor = bodies.inertia_sums(xu, zero_image, body, no_types, NO_ARRAY, m, radius, length, xcm,
                                     zero_body_image, count, nb)
        for b, row in listed:
            ixx, iyy, izz, ixy, ixz, iyz = row[4:10]
            tensor[b] = (ixx, iyy, izz, iyz, ixz, ixy)
        inertia, quat = principal_axes(tensor)
        ex, ey, ez = np.zeros((nb, 3)), np.zeros((nb, 3)), np.zeros((nb, 3))
        axes_of(quat, ex, ey, ez, nb)
        displace = np.zeros((count, 3))
        check = bodies.body_frame(xu, zero_image, body, no_types, NO_ARRAY, m, radius, length, xcm, zero_body_image,
                                  ex, ey, ez, displace, count, nb)
        zero = inertia == 0.0
        relative = np.abs(check[:, :3] - inertia) / np.where(zero, 1.0, inertia)
        bad = np.where(zero, np.abs(check[:, :3]) > TOLERANCE, relative > TOLERANCE)
        bad |= np.abs(check[:, 3:]) > TOLERANCE * inertia.sum(axis=1, keepdims=True) / 3.0
        bad[[b for b, _ in listed]] = False      # the file's values need not be the particles'
        if bad.any():
            b = int(np.flatnonzero(bad.any(axis=1))[0])
            return answers, (f"fix {self.id}: body of molecule {int(ids[b])} has bad principal moments of inertia "
                             f"({', '.join(f'{c:.6g}' for c in inertia[b])})"), 0.0
        momenta = bodies.momenta(xu, np.ascontiguousarray(v), omega_atom, zero_image, body, no_types, NO_ARRAY, m,
                                 radius, length, xcm, zero_body_image, count, nb)
        vcm = momenta[:, :3] / masstotal[:, None]
        angmom = momenta[:, 3:].copy()
        # as LAMMPS's rigid/small: bodies the file leaves out move as their particles do
        for b, row in listed:
            vcm[b] = row[10:13]
            angmom[b] = row[13:16]
        if sim.dimension == 2:
            vcm[:, 2] = 0.0
            angmom[:, :2] = 0.0
        image_body = np.zeros((nb, 3), dtype=np.int64)
        bodies.remap_centres(xcm, image_body, np.asarray(sim.box.lo, dtype=np.float64),
                             np.asarray(sim.box.hi, dtype=np.float64), length, periodic)
        record = np.zeros((nb, RECORD))
        record[:, MASS] = masstotal
        record[:, XCM:XCM + 3] = xcm
        record[:, VCM:VCM + 3] = vcm
        record[:, ANGMOM:ANGMOM + 3] = angmom
        record[:, QUAT:QUAT + 4] = quat
        record[:, INERTIA:INERTIA + 3] = inertia
        record[:, IMAGE:IMAGE + 3] = image_body
        record[:, NRIGID] = nrigid
        answers[:, 0] = rows[:, 0]
        answers[:, 1] = owner_tag[body]
        answers[:, 2:5] = displace
        answers[first, 5] = 1.0
        answers[first, 6:6 + RECORD] = record
        answers[:, 6 + RECORD] = masstotal[body]
        return answers, None, extent

    # ---- bodies of a template's copies, added during a run (fix pour mol ... rigid) ------------------
    def add_molecule_bodies(self, sim, rows, centres, velocities, quats):
        """LAMMPS's FixRigidSmall::set_molecule for each new copy: the template's body, its centre
        of mass at the copy's centre plus the turned offset from the geometric centre, its
        orientation the insertion's turn times the template's principal axes', the velocity given,
        no angular momentum; the owner the atom nearest the centre of mass."""
        body = self.template_body
        p = sim.particles
        a = p.arrays
        count = len(rows)
        total = int(sim.comm.sum(count))
        if total == 0:
            return
        self.nbody += total
        self.dof_cache = {}
        if count == 0:
            return
        record = np.zeros((count, RECORD))
        rotation = np.zeros((3, 3))
        combined = np.zeros((1, 4))
        for k in range(count):
            rotation_matrix(quats[k], rotation)
            offset = body.centre_to_com
            for d in range(3):
                record[k, XCM + d] = (rotation[d, 0] * offset[0] + rotation[d, 1] * offset[1]
                                      + rotation[d, 2] * offset[2]) + centres[k, d]
            quaternion_product(quats[k], body.quat, combined[0])
            record[k, QUAT:QUAT + 4] = combined[0]
        record[:, MASS] = body.mass
        record[:, VCM:VCM + 3] = velocities
        record[:, INERTIA:INERTIA + 3] = body.inertia
        record[:, NRIGID] = body.natoms
        if sim.dimension == 2:
            record[:, VCM + 2] = 0.0
        flat = rows.ravel()
        owners = rows[:, body.owner]
        a[self.tag_name][flat] = np.repeat(p.tag[owners], body.natoms)
        a[self.displace_name][flat] = np.tile(body.displace, (count, 1))
        if p.has("body_mass"):
            a["body_mass"][flat] = body.mass
        if self.parallel:
            self._to_records(sim)
            a[self.record_name][owners] = record
            return
        nl = self.nlocal_body
        self._allocate(nl + count)
        self._load_at(nl, record)
        self.owner_tag[nl:nl + count] = p.tag[owners]
        self.nlocal_body = nl + count
        self.compact = False
        self.atom_arrays = None

    def _load_at(self, first, records):
        """Bodies first.. from records (one rank: straight into the arrays)."""
        count = len(records)
        last = first + count
        self.masstotal[first:last] = records[:, MASS]
        self.xcm[first:last] = records[:, XCM:XCM + 3]
        self.vcm[first:last] = records[:, VCM:VCM + 3]
        self.angmom[first:last] = records[:, ANGMOM:ANGMOM + 3]
        self.quat[first:last] = records[:, QUAT:QUAT + 4]
        self.inertia[first:last] = records[:, INERTIA:INERTIA + 3]
        self.image_body[first:last] = records[:, IMAGE:IMAGE + 3].astype(np.int64)
        self.conjqm[first:last] = records[:, CONJQM:CONJQM + 4]
        self.nrigid[first:last] = records[:, NRIGID].astype(np.int64)

    # ---- bodies between the per-atom records and the compact arrays -------------------------------
    def _to_records(self, sim):
        """The local bodies back onto their owners' rows (before particles migrate or reorder; on one
        rank they stay in their arrays)."""
        if not self.compact or not self.parallel:
            return
        nl = self.nlocal_body
        rows = self.body_rows[:nl]
        record = sim.particles.arrays[self.record_name]
        record[rows, MASS] = self.masstotal[:nl]
        record[rows, XCM:XCM + 3] = self.xcm[:nl]
        record[rows, VCM:VCM + 3] = self.vcm[:nl]
        record[rows, ANGMOM:ANGMOM + 3] = self.angmom[:nl]
        record[rows, QUAT:QUAT + 4] = self.quat[:nl]
        record[rows, INERTIA:INERTIA + 3] = self.inertia[:nl]
        record[rows, IMAGE:IMAGE + 3] = self.image_body[:nl]
        record[rows, CONJQM:CONJQM + 4] = self.conjqm[:nl]
        record[rows, NRIGID] = self.nrigid[:nl]
        self.compact = False

    def _from_records(self, sim):
        """The bodies this rank holds, from the records on their owners' rows; each owned particle's
        body (local, or the ghost copy of a body owned elsewhere)."""
        p = sim.particles
        n, nall = p.nlocal, p.nall
        a = p.arrays
        tag, bodytag = a["tag"], a[self.tag_name]
        if len(self.atom2row) < nall:
            size = int(1.25 * nall) + 16
            self.atom2row = np.full(size, -1, dtype=np.int64)
            self.atom2body = np.full(size, -1, dtype=np.int64)
            self.body_of_row = np.full(size, -1, dtype=np.int64)
        largest = int(tag[:nall].max()) if nall else 0
        if len(self.rowmap) <= largest:
            self.rowmap = np.full(int(1.25 * largest) + 16, -1, dtype=np.int64)
        missing = find_owners(tag, bodytag, n, nall, self.rowmap, self.atom2row)
        message = None
        if missing:
            i = int(np.flatnonzero(self.atom2row[:n] == -2)[0])
            where = (f"among this rank's particles and ghosts at step {sim.step}: lost, or the ghost cutoff does not "
                     f"span the body (its extent was {self.maxextent:.6g} at set-up; use comm_modify cutoff)"
                     if self.parallel else f"at step {sim.step}: it was lost")
            message = (f"fix {self.id}: particle {int(tag[i])} cannot find its body's owner particle "
                       f"{int(bodytag[i])} {where}")
        sim.comm.agree(message)
        if self.parallel:
            # at most: the owners here, and one ghost body per owned particle whose owner is a ghost
            owners = int(np.count_nonzero(bodytag[:n] == tag[:n]))
            self._allocate(owners + int(np.count_nonzero(self.atom2row[:n] >= n)))
            nl, ng = number_bodies(tag, bodytag, self.atom2row, n, nall, self.body_of_row, self.atom2body,
                                   self.body_rows)
            self.nlocal_body, self.nghost_body = nl, ng
            self._load(a[self.record_name][self.body_rows[:nl]], nl)
            self.owner_tag[:nl] = tag[self.body_rows[:nl]]
        else:
            nl = self.nlocal_body
            place_bodies(tag, n, self.owner_tag, nl, self.atom2row, self.rowmap, self.body_rows, self.body_of_row,
                         self.atom2body)
            if np.any(self.body_rows[:nl] < 0):
                nl = self._drop_lost_bodies(sim)
        bodies.remap_centres(self.xcm[:nl], self.image_body[:nl], np.asarray(sim.box.lo, dtype=np.float64),
                             np.asarray(sim.box.hi, dtype=np.float64), np.asarray(sim.box.length, dtype=np.float64),
                             np.asarray(sim.box.periodic, dtype=np.bool_))
        axes_of(self.quat, self.ex, self.ey, self.ez, nl)
        omegas(self.angmom[:nl], self.ex[:nl], self.ey[:nl], self.ez[:nl], self.inertia[:nl], self.omega[:nl])
        self.compact = True
        self.atom_arrays = None
        self._share(sim)

    def _load(self, records, count):
        """Bodies 0..count-1 from their records (rows of RECORD values)."""
        self._load_at(0, records[:count])

    def _drop_lost_bodies(self, sim):
        """One rank: bodies whose every particle was lost (their owner among them) leave the arrays."""
        nl = self.nlocal_body
        keep = np.flatnonzero(self.body_rows[:nl] >= 0)
        for name in BODY_ARRAYS:
            values = getattr(self, name)
            values[: len(keep)] = values[keep]
        self.nlocal_body = self.nbody = len(keep)
        self.body_of_row[:] = -1
        self.body_of_row[self.body_rows[: len(keep)]] = np.arange(len(keep))
        rows = self.atom2row[: sim.particles.nlocal]
        self.atom2body[: len(rows)] = np.where(rows >= 0, self.body_of_row[np.maximum(rows, 0)], -1)
        return len(keep)

    # ---- communication of bodies (only with more than one rank) -----------------------------------
    def _share(self, sim, motion_only=False):
        """Ghost bodies take their owners' current position, orientation and motion (velocities
        only, after the second half step)."""
        if not self.parallel:
            return
        p = sim.particles
        name = self.motion_name if motion_only else self.state_name
        state = p.arrays[name]
        nl, total = self.nlocal_body, self.nlocal_body + self.nghost_body
        pack_state(0, nl, self.body_rows, self.xcm, self.vcm, self.omega, self.quat, self.image_body, state)
        sim.comm.forward_comm(p, (name,))
        unpack_state(nl, total, self.body_rows, self.xcm, self.vcm, self.omega, self.quat, self.ex, self.ey, self.ez,
                     self.image_body, state)

    def _collect(self, sim, sums):
        """Complete the local bodies' rows of ``sums`` with what other ranks summed onto their ghost
        bodies."""
        if not self.parallel:
            return
        p = sim.particles
        rows = p.arrays[self.sums_name]
        nl, total = self.nlocal_body, self.nlocal_body + self.nghost_body
        ghost_sums_out(nl, total, self.body_rows, sums, rows)
        sim.comm.reverse_comm(p, (self.sums_name,))
        ghost_sums_in(nl, self.body_rows, sums, rows)

    # ---- a run -----------------------------------------------------------------------------------
    def reset_dt(self, sim):
        """The step's constants (at each run's start, and for a new step mid-run: fix dt/reset)."""
        self.dtv = sim.dt
        self.dtf = 0.5 * sim.dt * sim.units.ftm2v
        self.dtq = 0.5 * sim.dt

    def init_run(self, sim):
        # a rigid fix defined after this one does not look for this one's bodies
        self._check_other_fixes(sim, sim.groups.select(sim, self.group))
        self.reset_dt(sim)
        self.gvec = FixRigid._gravity(self, sim)
        if self.body_template is not None and self.template_body is None:
            self.template_body = template_body(self.body_template, sim.mass, sim.dimension)
            sim.info(f"fix {self.id}: bodies of molecule {self.body_template.id}: mass "
                     f"{self.template_body.mass:.8g}, principal moments "
                     f"{' '.join(f'{c:.8g}' for c in self.template_body.inertia)}; {self.template_body.extent:.8g} "
                     "= max distance from body owner to body particle")
        # a file's values hold for the first run only (as fix rigid's infile)
        if (self.args.reinit == "yes" and self.args.infile is None) or not self.set_up:
            self.setup_bodies(sim)
        else:
            self._to_records(sim)

    def pre_exchange(self, sim):
        self._to_records(sim)

    def pre_neighbor(self, sim):
        self._to_records(sim)
        self._from_records(sim)

    def _atoms(self, sim):
        if self.atom_arrays is None:
            p = sim.particles
            a = p.arrays
            self.atom_arrays = (a["x"], a["v"], a["f"], a["image"], self.atom2body, a[self.displace_name], a["type"],
                                sim.mass, a.get("rmass", NO_ARRAY), a.get("radius", NO_ARRAY),
                                a.get("omega", NO_ARRAY2), a.get("torque", NO_ARRAY2),
                                np.asarray(sim.box.length, dtype=np.float64))
        return self.atom_arrays

    def _sum_force_torque(self, sim):
        x, v, f, image, body, displace, *_, torque_atom, length = self._atoms(sim)
        bodies.force_torque(x, f, torque_atom, image, body, length, self.xcm, self.image_body, sim.particles.nlocal,
                            self.sums)
        self._collect(sim, self.sums)
        split_sums(self.nlocal_body, self.sums, self.fcm, self.torque)
        if self.args.langevin is not None and not sim.in_setup:
            self._langevin(sim)
        if self.gvec is not None:
            nl = self.nlocal_body
            self.fcm[:nl] += self.masstotal[:nl, None] * self.gvec

    def _langevin(self, sim):
        """The local bodies' Langevin force and torque of this step, added to their sums (LAMMPS's
        apply_langevin_thermostat, from the motion after the first half step, as fix rigid's)."""
        nl = self.nlocal_body
        start, stop, period, seed = self.args.langevin
        langevin_keyed_forces(self.owner_tag[:nl], self.vcm, self.omega, self.ex, self.ey, self.ez, self.inertia,
                              self.masstotal, sim.random_key(seed), sim.step, sim.ramp(start, stop), period, sim.dt,
                              sim.units.boltz, sim.units.mvv2e, sim.units.ftm2v, sim.dimension == 2, self.langextra)
        self.fcm[:nl] += self.langextra[:nl, :3]
        self.torque[:nl] += self.langextra[:nl, 3:]

    def _set_v(self, sim, virial, tally):
        x, v, f, image, body, displace, type_, mass, rmass, radius, omega_atom, _, length = self._atoms(sim)
        bodies.set_v(x, v, f, omega_atom, image, body, displace, type_, mass, rmass, length, self.vcm, self.omega,
                     self.ex, self.ey, self.ez, self.image_body, sim.particles.nlocal, self.dtf, virial, tally)

    def _local(self):
        """The local bodies' arrays, as the integrators take them."""
        nl = self.nlocal_body
        return (self.xcm[:nl], self.vcm[:nl], self.fcm[:nl], self.angmom[:nl], self.torque[:nl], self.omega[:nl],
                self.quat[:nl], self.ex[:nl], self.ey[:nl], self.ez[:nl], self.inertia[:nl], self.masstotal[:nl],
                self.fflag[:nl], self.tflag[:nl])

    def setup(self, sim):
        self.atom_arrays = None
        self._sum_force_torque(sim)
        nl = self.nlocal_body
        omegas(self.angmom[:nl], self.ex[:nl], self.ey[:nl], self.ez[:nl], self.inertia[:nl], self.omega[:nl])
        self._share(sim, motion_only=True)
        self.step_virial[:] = 0.0
        self.final_virial[:] = 0.0
        self._set_v(sim, self.step_virial, True)
        # LAMMPS's estimate of the setup virial: twice the set_v half
        self.step_virial *= 2.0

    def advance_initial(self, sim):
        xcm, vcm, fcm, angmom, torque, omega, quat, ex, ey, ez, inertia, masstotal, fflag, tflag = self._local()
        richardson_initial(xcm, vcm, fcm, angmom, torque, omega, quat, ex, ey, ez, inertia, masstotal, fflag, tflag,
                           self.dtv, self.dtf, self.dtq)

    def advance_final(self, sim):
        xcm, vcm, fcm, angmom, torque, omega, quat, ex, ey, ez, inertia, masstotal, fflag, tflag = self._local()
        richardson_final(vcm, fcm, angmom, torque, omega, ex, ey, ez, inertia, masstotal, fflag, tflag, self.dtf)

    def initial_integrate(self, sim):
        self.advance_initial(sim)
        self._share(sim)
        self.place_particles(sim)

    def place_particles(self, sim):
        """Each body's particles on it (positions and velocities from its centre, orientation and
        motion), the first half of the step's constraint virial."""
        x, v, f, image, body, displace, type_, mass, rmass, radius, omega_atom, _, length = self._atoms(sim)
        self.step_virial[:] = 0.0
        bodies.set_xv(x, v, f, omega_atom, image, body, displace, type_, mass, rmass, length, self.xcm, self.vcm,
                      self.omega, self.ex, self.ey, self.ez, self.image_body, sim.particles.nlocal, self.dtf,
                      self.step_virial, self.thermo_virial)

    def final_integrate(self, sim):
        self._late_sum(sim)
        self.advance_final(sim)
        self._share(sim, motion_only=True)
        self.final_virial[:] = 0.0
        self._set_v(sim, self.final_virial, sim.vflag and self.thermo_virial)

    # ---- a box change (a barostat's) carries the bodies ----------------------------------------------
    def box_carried_centres(self):
        """The centres of mass of the bodies this rank owns, which a box change scales (None before the
        bodies exist)."""
        return self.xcm[: self.nlocal_body] if self.compact else None

    def box_carried(self, sim):
        """After a box change moved the centres: the ghost copies take them, the box lengths are read
        again."""
        self.atom_arrays = None
        self._share(sim)

    # ---- thermo ----------------------------------------------------------------------------------
    def compute_virial(self, sim):
        return tuple(float(c) for c in self.step_virial + self.final_virial)

    def dof_removed(self, sim, group):
        if not self.set_up or not self.compact:
            return 0
        key = (group, self.set_up)
        if key not in self.dof_cache:
            p = sim.particles
            n = p.nlocal
            chosen = sim.groups.select(sim, group)
            extended = p.radius[:n] > 0 if p.has("radius") else np.zeros(n, dtype=np.bool_)
            sums = np.zeros((self.nlocal_body + self.nghost_body, 6))
            count_members(self.atom2body, chosen, extended, n, sums)
            self._collect(sim, sums)
            nl = self.nlocal_body
            nall, mall = sums[:nl, 0].astype(np.int64), sums[:nl, 1].astype(np.int64)
            whole = nall + mall == self.nrigid[:nl]
            partial = int(sim.comm.sum(int(np.count_nonzero((nall + mall > 0) & ~whole))))
            if partial:
                sim.warn(f"fix {self.id}: group {group} holds part of {partial} rigid bodies; its temperature counts "
                         "none of their constraints")
            if sim.dimension == 3:
                linear = (self.inertia[:nl] == 0.0).any(axis=1)
                removed = np.where(whole, 3 * nall + 6 * mall - 6 + linear, 0)
            else:
                removed = np.where(whole, 2 * nall + 3 * mall - 3, 0)
            self.dof_cache[key] = int(sim.comm.sum(int(removed.sum())))
        return self.dof_cache[key]

    def _kinetic(self):
        """Twice the local bodies' translational and rotational kinetic energies (mass velocity^2)."""
        nl = self.nlocal_body
        translation = float((self.masstotal[:nl] * (self.vcm[:nl] ** 2).sum(axis=1)).sum())
        angmom = self.angmom[:nl]
        projected = np.stack([np.einsum("bd,bd->b", axis[:nl], angmom) for axis in (self.ex, self.ey, self.ez)], 1)
        inertia = self.inertia[:nl]
        wbody = np.divide(projected, inertia, out=np.zeros_like(projected), where=inertia != 0.0)
        return translation, float((inertia * wbody ** 2).sum())

    def scalar(self, sim):
        """The bodies' temperature: 6 degrees of freedom each, less one per linear body in 3d (LAMMPS's
        count, in 2d too: a 2d body's reads half its particles')."""
        if not self.set_up or not self.compact:
            return 0.0
        translation, rotation = self._kinetic()
        nl = self.nlocal_body
        free = 6 * self.nbody
        if sim.dimension == 3:
            free -= int(sim.comm.sum(int(np.count_nonzero((self.inertia[:nl] == 0.0).any(axis=1)))))
        total = float(sim.comm.sum(translation + rotation))
        return total * sim.units.mvv2e / (free * sim.units.boltz) if free > 0 else 0.0
