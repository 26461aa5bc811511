r"""Fix ``rigid``: sets of particles moving as rigid bodies (LAMMPS's fix rigid), integrated in NVE.

Each step the force and torque on every body are summed from its particles,

.. math::

    \mathbf{F} = \sum_{i \in B} \mathbf{f}_i, \qquad
    \boldsymbol{\tau} = \sum_{i \in B} (\mathbf{r}_i - \mathbf{X}) \times \mathbf{f}_i
                        \;(+\, \boldsymbol{\tau}_i \text{ of finite-size spheres}),

and the body's centre of mass X, velocity V, angular momentum L and orientation q (a unit quaternion)
advance by velocity Verlet: V and L half a step with F and tau, X a full step with V, q a full step with
the angular velocity omega = I^-1 L by Richardson iteration (q advanced once by dt and twice by dt/2
with omega re-evaluated at the midpoint; q = 2 q_half - q_full), then V and L the second half step
with the new F and tau. Particle positions and velocities are then set from the body,
r_i = X + R(q) d_i, v_i = V + omega x (r_i - X), d_i the particle's place in the body frame.
``fix rigid/nve`` integrates the same bodies symplectically instead (its module says how).

Bodies are set up at the start of every run from the particles as they are (``reinit yes``, LAMMPS's
default; ``reinit no``: at the first run only, later runs going on from the bodies as they were):
total mass M, centre of mass from positions unwrapped by their image flags (a body straddling a
periodic boundary is whole), the inertia tensor about it (spheres add 2/5 m R^2) diagonalised into
principal moments I_1..3 and axes (a right-handed frame, quaternion q), V = sum m v / M and
L = sum (r - X) x m v; particle velocities are then made rigid (v_i from V and omega).

Temperatures count a body's degrees of freedom as LAMMPS does: 3N - 6 are removed for a body of N
point particles wholly in the temperature group (3N - 5 for particles on a line, whose moment about
the line is 0; 2N - 3 in 2d; a finite-size sphere counts 6 to start with). The constraint forces
enter the pressure (LAMMPS's virial of fix rigid, on by default; ``fix_modify ID virial no`` drops
it): f_c = m (v_new - v_old) / (dt/2) - f on each particle of a body, half of r (x) f_c from each
half of the step. Forces between particles of one body do not move it: exclude them with
``neigh_modify exclude molecule/intra GROUP`` (or ``exclude group``) to save their cost. With
finite-size spheres (clumps), each particle's ``body_mass`` is its body's mass: granular contacts
(pair gran/*, dem/lsd, dem/hertz, fix wall/gran) take it for their effective mass, as LAMMPS's pair
gran and fix wall/gran take fix rigid's masstotal.

Body temperature (``f_ID``, intensive): sum (M V^2 + sum_k I_k omega_k^2) / (N_free k_B), N_free the
force and torque components left on, less 1 per linear body in 3d (LAMMPS subtracts it from its
second run on: its first run counts the linear body's 6). ``f_ID[i][j]`` (body i, counted from
the dialect's first index): columns x y z of the centre of mass, vx vy vz, fx fy fz, tx ty tz and
the three image flags of the centre of mass, as LAMMPS's global array.

Syntax::

    fix ID GROUP rigid BODYSTYLE [ARGS] [force M XFLAG YFLAG ZFLAG] [torque M XFLAG YFLAG ZFLAG]
        [reinit yes|no] [infile FILE] [langevin TSTART TSTOP TPERIOD SEED] [gravity FIX_ID]

- BODYSTYLE ``single``: the whole group is one body; ``molecule``: one body per molecule id in the
  group (the id 0 too); ``group N G1 ... GN``: one body per group, its particles those of the fix
  group in Gk; ``custom i_NAME`` or ``custom v_NAME``: one body per value of a per-particle integer
  property NAME (a fix property/atom's) or of an atom-style variable NAME (truncated to an integer),
  numbered as LAMMPS's, value - (smallest value in the group) + 1 (the IDs of an infile). A particle
  in two bodies is an error naming both.
- ``force M xflag yflag zflag`` (``on``/``off``): which components of the force move body M (all on
  by default; in 2d z is off); ``torque M ...`` likewise for the torque (x and y off in 2d). M is a
  body number from 1 or a range as LAMMPS writes it: ``*``, ``*n``, ``n*``, ``m*n``. Repeated
  keywords apply in order, the last setting of a body winning.
- ``reinit yes|no``: set the bodies up again from the particles at every run (yes, the default) or at
  the first only.
- ``infile FILE``: mass, centre of mass, inertia tensor (about the centre of mass, box axes), velocity,
  angular momentum and image flags of some bodies, instead of the values from their particles (for
  overlapping spheres, say): a count, then lines ``ID masstotal xcm ycm zcm ixx iyy izz ixy ixz iyz
  vxcm vycm vzcm lx ly lz ixcm iycm izcm`` (ID: 1 for single, the group's number, or the molecule id);
  # comments. As LAMMPS (recorded): bodies the file leaves out take everything from their particles,
  their motion included, and bodies are set up once.
- ``langevin TSTART TSTOP TPERIOD SEED`` (rigid and rigid/nve; LAMMPS refuses it with rigid/nvt): a
  Langevin thermostat on the bodies, LAMMPS's, at a target T ramped from TSTART to TSTOP over the run
  (temperature, >= 0; 0 gives the drag alone), damping time TPERIOD (time, > 0). Each step adds to
  the force on body b and, about each principal axis k, to its torque

  .. math::

      -\frac{M_b}{T_p} \mathbf{V}_b + \sqrt{\frac{24 k_B T M_b}{T_p \Delta t}}\,(\mathbf{u} - \tfrac12),
      \qquad -\frac{I_k}{T_p} \omega_k + \sqrt{\frac{24 k_B T I_k}{T_p \Delta t}}\,(u'_k - \tfrac12),

  u uniform in (0, 1) from the counter-based generator keyed by (SEED, step, body number): the same
  on any number of ranks, not LAMMPS's Marsaglia numbers (its drag alone, T = 0, is LAMMPS's to
  round-off). The rotational u' - 1/2 are a box-frame uniform vector projected on the principal
  axes: the covariance of LAMMPS's draws, and a torque sqrt(I) (u - 1/2) that no choice of axes
  (their signs, or any axes of equal moments, which round-off decides) changes. Forces are divided by ftm2v as LAMMPS's; in 2d only the in-plane force and the torque
  about z.
- ``gravity FIX_ID``: each body's centre of mass feels M g, g the acceleration of fix gravity FIX_ID
  (LAMMPS's): for bodies whose mass comes from an infile, with that fix's group holding none of their
  particles (else both act). Without it a gravity fix acts on the particles (a warning with infile).
- ``temp`` and ``tparam`` belong to ``rigid/nvt`` and ``rigid/npt``, the barostat keywords (iso,
  aniso, x, y, z, couple, pchain, dilate) to ``rigid/nph`` and ``rigid/npt``: refused here, as LAMMPS
  does, and ``mol`` (rigid/small's).

Units: masses (mass), positions (distance), torques (energy), as the particles'.

Examples::

    fix 1 clump rigid single
    fix 1 clump rigid single force 1 off off on langevin 1.0 1.0 1.0 428984
    fix 1 polychains rigid molecule force 1*5 off off off force 6*10 off off on
    fix 2 fluid rigid group 3 clump1 clump2 clump3 torque * off off off
    fix 3 clumps rigid/nve custom v_clump

Reference: LAMMPS's fix rigid documentation (docs/lammps.md, "fix rigid"); Richardson iteration as
in Evans, Mol. Phys. 34, 317 (1977) and Kamberaj, Low and Neal, J. Chem. Phys. 122, 224114 (2005).
"""

import math
from pathlib import Path
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param, particle_uniforms

from . import bodies
from .quaternion import axes_from_quaternion, omega_from_angmom, quaternion_from_axes, richardson

NO_ARRAY = np.zeros(0)
NO_ARRAY2 = np.zeros((0, 3))
OnOff = Literal["on", "off"]
BodyStyle = (Literal["single", "molecule"] | tuple[Literal["group"], int, tuple[str, ...]]
             | tuple[Literal["custom"], str])
# LAMMPS's thresholds: a principal moment below EPSILON of the largest is 0 (a linear body); the
# moments recomputed in the body frame must match to TOLERANCE
EPSILON = 1e-7
TOLERANCE = 1e-6
# keywords LAMMPS refuses for a style (Illegal fix command), and why
NOSE_HOOVER_ONLY = "only fix rigid/nvt and rigid/npt take it (LAMMPS's page: not rigid or rigid/nve)"
BAROSTAT_ONLY = "only fix rigid/nph and rigid/npt take it (as LAMMPS)"
BAROSTAT_REFUSED = {word: BAROSTAT_ONLY for word in ("iso", "aniso", "x", "y", "z", "couple", "pchain", "dilate")}
MOL_REFUSED = {"mol": "only fix rigid/small and its variants take it (as LAMMPS)"}
# the langevin noise's streams of the counter-based generator, keyed by (seed, step, body number)
TRANSLATION_STREAM = 4
ROTATION_STREAM = 5
IMAGE_LIMIT = 2 ** 30        # the particles' image flags are int32
BODY_ID_LIMIT = 2 ** 31 - 1  # bodystyle custom's values, LAMMPS's int
INFILE_COLUMNS = "ID masstotal xcm ycm zcm ixx iyy izz ixy ixz iyz vxcm vycm vzcm lx ly lz ixcm iycm izcm"


def body_range(word, nbody, what):
    """LAMMPS's ``*``, ``*n``, ``n*``, ``m*n`` or ``n`` as (first, last), 1-based, within 1..nbody."""
    try:
        if "*" not in word:
            lo = hi = int(word)
        else:
            left, _, right = word.partition("*")
            lo = int(left) if left else 1
            hi = int(right) if right else nbody
    except ValueError:
        raise ScriptError(f"{what}: body {word!r} is not a number or a range (*, *n, n*, m*n)") from None
    if not 1 <= lo <= hi <= nbody:
        raise ScriptError(f"{what}: body range {word} is not within 1..{nbody} (the bodies of this fix)")
    return lo, hi


@njit(cache=True)
def richardson_initial(xcm, vcm, fcm, angmom, torque, omega, quat, ex, ey, ez, inertia, masstotal,
                       fflag, tflag, dtv, dtf, dtq):
    for b in range(xcm.shape[0]):
        dtfm = dtf / masstotal[b]
        for d in range(3):
            vcm[b, d] += dtfm * fcm[b, d] * fflag[b, d]
            xcm[b, d] += dtv * vcm[b, d]
            angmom[b, d] += dtf * torque[b, d] * tflag[b, d]
        omega_from_angmom(angmom, ex, ey, ez, inertia, omega, b)
        richardson(quat, angmom, omega, inertia, b, dtq)
        axes_from_quaternion(quat, b, ex, ey, ez)


@njit(cache=True)
def richardson_final(vcm, fcm, angmom, torque, omega, ex, ey, ez, inertia, masstotal, fflag, tflag, dtf):
    for b in range(vcm.shape[0]):
        dtfm = dtf / masstotal[b]
        for d in range(3):
            vcm[b, d] += dtfm * fcm[b, d] * fflag[b, d]
            angmom[b, d] += dtf * torque[b, d] * tflag[b, d]
        omega_from_angmom(angmom, ex, ey, ez, inertia, omega, b)


@njit(cache=True)
def langevin_body_forces(vcm, omega, ex, ey, ez, inertia, masstotal, key, step, t_target, t_period, dt, boltz,
                         mvv2e, ftm2v, planar, langextra):
    """LAMMPS's Langevin force and torque on each body (rows: fx fy fz tx ty tz): -M V / Tperiod plus
    sqrt(24 k_B T M / (Tperiod dt)) (u - 1/2) on the centre of mass, and about each principal axis k
    -I_k w_k / Tperiod plus sqrt(24 k_B T I_k / (Tperiod dt)) (u - 1/2)_k, w_k the angular velocity
    in the body frame, (u - 1/2)_k the projection on axis k of a box-frame vector; u uniform in (0, 1),
    keyed by (seed, step, body number). In 2d only fx, fy and tz."""
    for b in range(vcm.shape[0]):
        langevin_one_body(b, b + 1, vcm, omega, ex, ey, ez, inertia, masstotal, key, step, t_target, t_period, dt,
                          boltz, mvv2e, ftm2v, planar, langextra)


@njit(cache=True)
def langevin_keyed_forces(body_keys, vcm, omega, ex, ey, ez, inertia, masstotal, key, step, t_target, t_period, dt,
                          boltz, mvv2e, ftm2v, planar, langextra):
    """langevin_body_forces for bodies 0..len(body_keys)-1, body b's noise keyed by body_keys[b] (fix
    rigid/small: its owner particle's id, which no number of ranks changes)."""
    for b in range(body_keys.shape[0]):
        langevin_one_body(b, body_keys[b], vcm, omega, ex, ey, ez, inertia, masstotal, key, step, t_target,
                          t_period, dt, boltz, mvv2e, ftm2v, planar, langextra)


@njit(cache=True)
def langevin_one_body(b, body_key, vcm, omega, ex, ey, ez, inertia, masstotal, key, step, t_target, t_period, dt,
                      boltz, mvv2e, ftm2v, planar, langextra):
    """Row b of langextra (langevin_body_forces), the noise drawn for (key, step, body_key)."""
    noise = math.sqrt(t_target) * math.sqrt(24.0 * boltz / t_period / dt / mvv2e) / ftm2v
    drag = -1.0 / t_period / ftm2v
    u0, u1, u2, _ = particle_uniforms(key, step, body_key, TRANSLATION_STREAM)
    root = math.sqrt(masstotal[b])
    langextra[b, 0] = drag * masstotal[b] * vcm[b, 0] + root * noise * (u0 - 0.5)
    langextra[b, 1] = drag * masstotal[b] * vcm[b, 1] + root * noise * (u1 - 0.5)
    langextra[b, 2] = drag * masstotal[b] * vcm[b, 2] + root * noise * (u2 - 0.5)
    # the rotational noise is drawn in the box frame and projected on the principal axes: the same
    # covariance (k_B T I / Tperiod dt) as LAMMPS's draws about each axis, but the torque it gives,
    # sqrt(I) u, is one whatever sign or (for equal moments) choice of axes round-off makes
    u0, u1, u2, _ = particle_uniforms(key, step, body_key, ROTATION_STREAM)
    n0, n1, n2 = u0 - 0.5, u1 - 0.5, u2 - 0.5
    r0 = ex[b, 0] * n0 + ex[b, 1] * n1 + ex[b, 2] * n2
    r1 = ey[b, 0] * n0 + ey[b, 1] * n1 + ey[b, 2] * n2
    r2 = ez[b, 0] * n0 + ez[b, 1] * n1 + ez[b, 2] * n2
    w0 = ex[b, 0] * omega[b, 0] + ex[b, 1] * omega[b, 1] + ex[b, 2] * omega[b, 2]
    w1 = ey[b, 0] * omega[b, 0] + ey[b, 1] * omega[b, 1] + ey[b, 2] * omega[b, 2]
    w2 = ez[b, 0] * omega[b, 0] + ez[b, 1] * omega[b, 1] + ez[b, 2] * omega[b, 2]
    t0 = inertia[b, 0] * drag * w0 + math.sqrt(inertia[b, 0]) * noise * r0
    t1 = inertia[b, 1] * drag * w1 + math.sqrt(inertia[b, 1]) * noise * r1
    t2 = inertia[b, 2] * drag * w2 + math.sqrt(inertia[b, 2]) * noise * r2
    for d in range(3):
        langextra[b, 3 + d] = ex[b, d] * t0 + ey[b, d] * t1 + ez[b, d] * t2
    if planar:
        langextra[b, 2] = 0.0
        langextra[b, 3] = 0.0
        langextra[b, 4] = 0.0


def check_langevin(langevin):
    """The langevin keyword's values (Tstart Tstop Tperiod seed), one line for a bad one."""
    if langevin is None:
        return
    start, stop, period, seed = langevin
    if not (start >= 0 and stop >= 0 and math.isfinite(start) and math.isfinite(stop)):
        raise ScriptError(f"langevin: Tstart and Tstop must be >= 0 (got {start:g} {stop:g})")
    if not (period > 0 and math.isfinite(period)):
        raise ScriptError(f"langevin: Tperiod must be > 0 (got {period:g})")
    if not 0 < seed < 2 ** 63:
        raise ScriptError(f"langevin: the seed must be a positive integer (got {seed})")


@njit(cache=True)
def omegas(angmom, ex, ey, ez, inertia, omega):
    for b in range(angmom.shape[0]):
        omega_from_angmom(angmom, ex, ey, ez, inertia, omega, b)


class BodyForcesTiming:
    """``fix_modify ID bodyforces early|late`` of the rigid fixes: early, the bodies' forces and
    torques are summed at the fix's turn in post_force, so forces that fixes defined after it add
    there do not reach the bodies (LAMMPS's earlyflag); late, the default, in final_integrate, every
    fix's forces included. ``_sum_force_torque`` is the fix's own sum."""
    idle_hooks = frozenset({"post_force"})

    def modify_param(self, sim, keyword, value):
        if keyword != "bodyforces":
            return super().modify_param(sim, keyword, value)
        if value not in ("early", "late"):
            raise ScriptError(f"bodyforces must be early or late (got {value})")
        self.idle_hooks = frozenset() if value == "early" else frozenset({"post_force"})
        return True

    def post_force(self, sim):
        self._sum_force_torque(sim)

    def _late_sum(self, sim):
        if "post_force" in self.idle_hooks:
            self._sum_force_torque(sim)


class FixRigid(BodyForcesTiming, Fix):
    name = "rigid"
    time_integrate = True
    usage = ("fix ID GROUP rigid single|molecule|group N G1 .. GN|custom i_NAME|v_NAME [force M XFLAG YFLAG ZFLAG] "
             "[torque M XFLAG YFLAG ZFLAG] [reinit yes|no] [infile FILE] [langevin TSTART TSTOP TPERIOD SEED] "
             "[gravity FIX_ID]")
    can_virial = True
    virial_default = True
    virial_after = "final_integrate"
    refused = {"temp": NOSE_HOOVER_ONLY, "tparam": NOSE_HOOVER_ONLY} | BAROSTAT_REFUSED | MOL_REFUSED

    class Args(StyleArgs):
        bodystyle: BodyStyle = param(names="group ID", unit={"group": ("1", "1", "1")})
        force: list[tuple[str, OnOff, OnOff, OnOff]] = keyword(default_factory=list)
        torque: list[tuple[str, OnOff, OnOff, OnOff]] = keyword(default_factory=list)
        reinit: Literal["yes", "no"] = keyword("yes")
        infile: str | None = keyword(None)
        langevin: tuple[float, float, float, int] | None = keyword(
            None, unit=("temperature", "temperature", "time", "dimensionless"))
        gravity: str | None = keyword(None)

        @property
        def style(self):
            """single, molecule, group or custom."""
            return self.bodystyle if isinstance(self.bodystyle, str) else self.bodystyle[0]

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        if args.style == "group":
            count = args.bodystyle[1]
            if count < 1:
                raise ScriptError(f"bodystyle group needs N >= 1 and N group ids (got {count})")
        elif args.style == "custom":
            source = args.bodystyle[1]
            if not source.startswith(("i_", "v_")) or len(source) < 3:
                raise ScriptError(f"bodystyle custom needs one i_NAME (a per-particle integer property) or v_NAME "
                                  f"(an atom-style variable) (got {source})")
        check_langevin(args.langevin)

    # ---- bodies ---------------------------------------------------------------------------------
    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box(f"fix {id} ({self.name})")
        p = sim.particles
        self.body_name = f"rigid_body_{id}"
        self.displace_name = f"rigid_displace_{id}"
        body = p.request(self.body_name, dtype=np.int64, default=-1, ghost=False)
        p.request(self.displace_name, width=3, ghost=False)
        if p.has("rmass"):
            # granular contacts take a clump's mass for their effective mass (LAMMPS's mass_rigid)
            p.request("body_mass")
        n = p.nlocal
        body[:] = -1
        self.nbody = self._assign(sim, body[:n])
        counts = np.bincount(body[:n][body[:n] >= 0], minlength=self.nbody).astype(np.int64)
        self.nrigid = np.asarray(sim.comm.sum(counts), dtype=np.int64)
        if self.nbody == 0:
            raise ScriptError(f"fix {id}: no particles in group {group} to make rigid bodies of")
        lonely = np.flatnonzero(self.nrigid <= 1)
        if lonely.size:
            raise ScriptError(f"fix {id}: body {lonely[0] + 1} has {self.nrigid[lonely[0]]} particle(s); "
                              "a rigid body needs at least 2")
        self._check_other_fixes(sim, body[:n])
        self.fflag = np.ones((self.nbody, 3))
        self.tflag = np.ones((self.nbody, 3))
        if sim.dimension == 2:
            self.fflag[:, 2] = 0.0
            self.tflag[:, :2] = 0.0
        for word, flags in (("force", args.force), ("torque", args.torque)):
            target = self.fflag if word == "force" else self.tflag
            for m, *xyz in flags:
                lo, hi = body_range(m, self.nbody, word)
                values = [1.0 if flag == "on" else 0.0 for flag in xyz]
                if sim.dimension == 2 and (values[2] if word == "force" else (values[0] or values[1])):
                    axis = "z" if word == "force" else "x and y"
                    raise ScriptError(f"{word} {m}: the {axis} component(s) cannot be on in a 2d simulation")
                target[lo - 1:hi] = values
        nb = self.nbody
        self.masstotal = np.zeros(nb)
        self.xcm, self.vcm, self.fcm = np.zeros((nb, 3)), np.zeros((nb, 3)), np.zeros((nb, 3))
        self.angmom, self.omega, self.torque = np.zeros((nb, 3)), np.zeros((nb, 3)), np.zeros((nb, 3))
        self.inertia = np.zeros((nb, 3))
        self.ex, self.ey, self.ez = np.zeros((nb, 3)), np.zeros((nb, 3)), np.zeros((nb, 3))
        self.quat = np.zeros((nb, 4))
        self.image_body = np.zeros((nb, 3), dtype=np.int64)
        self.sums = np.zeros((nb, 6))
        self.step_virial = np.zeros(6)
        self.final_virial = np.zeros(6)
        self.langextra = np.zeros((nb, 6))
        self.gvec = None
        self.set_up = 0
        self.dof_cache = {}
        self.atom_arrays = None
        self.from_file = self._read_infile(sim) if args.infile is not None else {}
        sim.info(f"fix {id}: {nb} rigid bodies with {int(self.nrigid.sum())} particles")

    def _assign(self, sim, body):
        """Set each owned particle's body index; return the number of bodies."""
        p = sim.particles
        n = p.nlocal
        members = sim.groups.select(sim, self.group)
        style = self.args.style
        if style == "single":
            body[members] = 0
            self.body_ids = np.array([1])
            return 1
        if style in ("molecule", "custom"):
            mol = self._molecule_ids(sim, members) if style == "custom" else None
            if style == "molecule":
                if not p.has("molecule"):
                    raise ScriptError(f"fix {self.id}: bodystyle molecule needs molecule ids (atom_style molecular, "
                                      f"bond, angle or full; particle style here: {sim.particle_style})")
                mol = p.molecule[:n]
            ids = np.unique(sim.comm.allgather_rows(np.unique(mol[members])))
            body[members] = np.searchsorted(ids, mol[members])
            self.body_ids = ids
            return len(ids)
        names = self.args.bodystyle[2]
        owner = np.full(n, -1, dtype=np.int64)
        clash = (np.iinfo(np.int64).max, 0, 0)
        for k, name in enumerate(names):
            sim.require_group(name)
            chosen = members & sim.groups.select(sim, name)
            twice = chosen & (owner >= 0)
            if twice.any():
                i = int(np.flatnonzero(twice)[np.argmin(p.tag[:n][twice])])
                clash = min(clash, (int(p.tag[i]), int(owner[i]), k))
            owner[chosen & (owner < 0)] = k
        clash = sim.comm.min(clash)
        if clash[0] != np.iinfo(np.int64).max:
            raise ScriptError(f"fix {self.id}: particle {clash[0]} is in two bodies: group {names[clash[1]]} "
                              f"(body {clash[1] + 1}) and group {names[clash[2]]} (body {clash[2] + 1})")
        body[:] = owner
        self.body_ids = np.arange(1, len(names) + 1)
        return len(names)

    def _molecule_ids(self, sim, members):
        """bodystyle custom: LAMMPS's body ids from a per-particle integer property (i_NAME) or an
        atom-style variable (v_NAME, truncated to an integer): value - (smallest value in the group) + 1
        for the group's particles, 0 for the others."""
        p = sim.particles
        n = p.nlocal
        source = self.args.bodystyle[1]
        name = source[2:]
        if source.startswith("i_"):
            if not p.has(name) or p.arrays[name].ndim != 1:
                raise ScriptError(f"fix {self.id}: bodystyle custom {source}: no per-particle property {name} "
                                  "with one value per particle")
            values = np.asarray(p.arrays[name][:n], dtype=np.float64)
            if np.any(values[members] != np.round(values[members])):
                raise ScriptError(f"fix {self.id}: bodystyle custom {source}: property {name} holds values that "
                                  "are not integers")
        else:
            if name not in sim.variables:
                raise ScriptError(f"fix {self.id}: bodystyle custom {source}: variable {name} is not defined")
            values = np.trunc(np.asarray(sim.variables.atom_values(name), dtype=np.float64))
        chosen = values[members]
        if not np.all(np.isfinite(chosen)) or np.any(np.abs(chosen) > BODY_ID_LIMIT):
            raise ScriptError(f"fix {self.id}: bodystyle custom {source}: values must be integers within "
                              f"+-{BODY_ID_LIMIT}")
        smallest = sim.comm.min(float(chosen.min()) if len(chosen) else math.inf)
        ids = np.zeros(n, dtype=np.int64)
        ids[members] = (chosen - smallest + 1).astype(np.int64)
        return ids

    def _read_infile(self, sim):
        """The bodies' values of ``infile FILE`` (LAMMPS's format: a count, then one line per body:
        ID masstotal xcm ycm zcm ixx iyy izz ixy ixz iyz vxcm vycm vzcm lx ly lz ixcm iycm izcm; blank
        lines and # comments ignored): {body index: row}, read on rank 0, checked line by line."""
        path = Path(sim.resolve(self.args.infile))
        found, problem = {}, None
        if sim.comm.is_root:
            try:
                found = self._parse_infile(path)
            except ScriptError as error:
                problem = str(error)
            except OSError as error:
                problem = f"infile {self.args.infile}: cannot read it ({error.strerror or error})"
        found, problem = sim.comm.bcast((found, problem))
        if problem:
            raise ScriptError(problem)
        return found

    def _parse_infile(self, path):
        where = f"infile {path}"
        try:
            text = path.read_bytes().decode("utf-8")
        except UnicodeDecodeError as error:
            raise ScriptError(f"{where}: not a text file (byte {error.start}: {error.reason})") from None
        lines = [(k, line.split("#")[0].split()) for k, line in enumerate(text.splitlines(), 1)]
        lines = [(k, words) for k, words in lines if words]
        if not lines:
            raise ScriptError(f"{where}: no count of bodies")
        k, words = lines[0]
        if len(words) != 1 or not words[0].isdigit():
            raise ScriptError(f"{where}:{k}: the first line is the number of bodies that follow (got {' '.join(words)})")
        count = int(words[0])
        if len(lines) - 1 != count:
            raise ScriptError(f"{where}: {count} bodies announced, {len(lines) - 1} lines follow")
        index = {int(i): b for b, i in enumerate(self.body_ids)}
        found = {}
        for k, words in lines[1:]:
            if len(words) != 20:
                raise ScriptError(f"{where}:{k}: {len(words)} values; a line is {INFILE_COLUMNS}")
            try:
                ident = int(words[0])
                values = [float(w) for w in words[1:17]]
                images = [int(w) for w in words[17:]]
            except ValueError:
                raise ScriptError(f"{where}:{k}: not numbers: {' '.join(words)} ({INFILE_COLUMNS})") from None
            if ident not in index:
                raise ScriptError(f"{where}:{k}: no body {ident} in fix {self.id} (its bodies: "
                                  f"{self.body_ids[0]}..{self.body_ids[-1]})")
            if any(abs(i) > IMAGE_LIMIT for i in images):
                raise ScriptError(f"{where}:{k}: image flags {' '.join(words[17:])} beyond +-{IMAGE_LIMIT}")
            if not all(np.isfinite(values)) or values[0] <= 0:
                raise ScriptError(f"{where}:{k}: masstotal must be > 0 and every value finite "
                                  f"(got {' '.join(words[1:17])})")
            ixx, iyy, izz, ixy, ixz, iyz = values[4:10]
            moments = np.linalg.eigvalsh([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
            if moments[0] < -1e-12 * abs(moments[-1]):
                raise ScriptError(f"{where}:{k}: the inertia tensor of body {ident} has a negative principal "
                                  f"moment ({moments[0]:.6g}); it is not a body's")
            found[index[ident]] = values + images
        return found

    def _check_other_fixes(self, sim, body):
        p = sim.particles
        for other in sim.fixes.values():
            if other is self or not isinstance(other, FixRigid) or other.id == self.id:
                continue
            if not p.has(other.body_name):
                continue
            theirs = p.arrays[other.body_name][: p.nlocal]
            both = (body >= 0) & (theirs >= 0)
            found = (int(p.tag[: p.nlocal][both].min()), ) if both.any() else (np.iinfo(np.int64).max,)
            tag = sim.comm.min(found)[0]
            if tag != np.iinfo(np.int64).max:
                i = p.index_of_tag(tag)
                mine = f"body {body[i] + 1}" if i >= 0 else "a body"
                raise ScriptError(f"particle {tag} is in two bodies: {mine} of fix {self.id} and body "
                                  f"{theirs[i] + 1 if i >= 0 else '?'} of fix {other.id}")

    def _atoms(self, sim):
        """The per-atom arrays the kernels read, as plain arrays; kept from one neighbor list build to
        the next (particles move between arrays, and arrays grow, only then)."""
        if self.atom_arrays is None:
            self.atom_arrays = self._read_atoms(sim)
        return self.atom_arrays

    def _read_atoms(self, sim):
        p = sim.particles
        a = p.arrays
        return (a["x"], a["v"], a["f"], a["image"], a[self.body_name], a[self.displace_name], a["type"],
                sim.mass, a.get("rmass", NO_ARRAY), a.get("radius", NO_ARRAY), a.get("omega", NO_ARRAY2),
                a.get("torque", NO_ARRAY2), np.asarray(sim.box.length, dtype=np.float64))

    def setup_bodies(self, sim):
        """LAMMPS's setup_bodies_static and setup_bodies_dynamic, from the particles as they are."""
        p = sim.particles
        n = p.nlocal
        self.atom_arrays = None
        x, v, f, image, body, displace, type_, mass, rmass, radius, omega_atom, _, length = self._atoms(sim)
        nb = self.nbody
        periodic = np.asarray(sim.box.periodic, dtype=np.bool_)
        mine = body[:n] >= 0
        stray = mine[:, None] & (image[:n] != 0) & ~periodic[None, :]
        message = None
        if stray.any():
            i = int(np.flatnonzero(stray.any(axis=1))[0])
            message = (f"fix {self.id}: particle {int(p.tag[i])} of a rigid body has a non-zero image flag "
                       "in a non-periodic dimension")
        # particles deleted since the fix was defined (delete_atoms, lost ones) change the bodies
        counts = np.bincount(body[:n][mine], minlength=nb).astype(np.int64)
        self.nrigid = np.asarray(sim.comm.sum(counts), dtype=np.int64)
        lonely = np.flatnonzero(self.nrigid <= 1)
        if lonely.size:
            b = int(lonely[0])
            raise ScriptError(f"fix {self.id}: body {self.body_ids[b]} has {self.nrigid[b]} particle(s) left; a "
                              "rigid body needs at least 2 (particles deleted since the fix was defined? "
                              "define the fix again)")
        masses = mass[type_[:n][mine]] if len(rmass) == 0 else rmass[:n][mine]
        if not np.all(np.isfinite(masses)) or np.any(masses <= 0):
            message = message or f"fix {self.id}: every particle of a rigid body needs a positive mass"
        sim.comm.agree(message)
        sums = np.asarray(sim.comm.sum(bodies.mass_and_centre(x, image, body, type_, mass, rmass, length, n, nb)))
        self.masstotal[:] = sums[:, 3]
        self.xcm[:] = sums[:, :3] / self.masstotal[:, None]
        self.image_body[:] = 0
        for b, row in self.from_file.items():
            self.masstotal[b], self.xcm[b], self.image_body[b] = row[0], row[1:4], row[16:19]
        if p.has("body_mass"):
            p.arrays["body_mass"][:n][mine] = self.masstotal[body[:n][mine]]
        bodies.remap_centres(self.xcm, self.image_body, np.asarray(sim.box.lo, dtype=np.float64),
                             np.asarray(sim.box.hi, dtype=np.float64), length, periodic)
        if not self.set_up:
            self._warn_spanning(sim, x, image, body, length, periodic)
        tensor = np.asarray(sim.comm.sum(bodies.inertia_sums(x, image, body, type_, mass, rmass, radius, length,
                                                             self.xcm, self.image_body, n, nb)))
        for b, row in self.from_file.items():
            ixx, iyy, izz, ixy, ixz, iyz = row[4:10]
            tensor[b] = (ixx, iyy, izz, iyz, ixz, ixy)
        t = tensor
        matrices = np.stack([t[:, [0, 5, 4]], t[:, [5, 1, 3]], t[:, [4, 3, 2]]], axis=1)
        moments, vectors = np.linalg.eigh(matrices)          # ascending, as LAMMPS's jacobi
        moments[moments < EPSILON * moments.max(axis=1, keepdims=True)] = 0.0
        self.inertia[:] = moments
        self.ex[:], self.ey[:], self.ez[:] = vectors[:, :, 0], vectors[:, :, 1], vectors[:, :, 2]
        left_handed = np.einsum("bi,bi->b", np.cross(self.ex, self.ey), self.ez) < 0.0
        self.ez[left_handed] *= -1.0
        for b in range(nb):
            quaternion_from_axes(self.ex[b], self.ey[b], self.ez[b], self.quat[b])
        check = np.asarray(sim.comm.sum(bodies.body_frame(x, image, body, type_, mass, rmass, radius, length,
                                                           self.xcm, self.image_body, self.ex, self.ey, self.ez,
                                                           displace, n, nb)))
        moments = self.inertia
        zero = moments == 0.0
        relative = np.abs(check[:, :3] - moments) / np.where(zero, 1.0, moments)
        bad = np.where(zero, np.abs(check[:, :3]) > TOLERANCE, relative > TOLERANCE)
        bad |= np.abs(check[:, 3:]) > TOLERANCE * moments.sum(axis=1, keepdims=True) / 3.0
        bad[list(self.from_file)] = False       # the file's values need not be the particles'
        if bad.any():
            b = int(np.flatnonzero(bad.any(axis=1))[0])
            raise ScriptError(f"fix {self.id}: body {b + 1} has bad principal moments of inertia "
                              f"({', '.join(f'{m:.6g}' for m in moments[b])}; recomputed in the body frame: "
                              f"{', '.join(f'{c:.6g}' for c in check[b, :3])})")
        # every body's motion from its particles; a file's values replace those of the bodies it
        # lists (LAMMPS 22 Jul 2025, recorded: the others move as without the file)
        momenta = np.asarray(sim.comm.sum(bodies.momenta(x, v, omega_atom, image, body, type_, mass, rmass,
                                                         radius, length, self.xcm, self.image_body, n, nb)))
        self.vcm[:] = momenta[:, :3] / self.masstotal[:, None]
        self.angmom[:] = momenta[:, 3:]
        for b, row in self.from_file.items():
            self.vcm[b], self.angmom[b] = row[10:13], row[13:16]
        if sim.dimension == 2:
            # 2d bodies move in the plane and turn about z only (LAMMPS's fix enforce2d on bodies)
            self.vcm[:, 2] = 0.0
            self.angmom[:, :2] = 0.0
        self.set_up += 1
        self.dof_cache = {}

    def _warn_spanning(self, sim, x, image, body, length, periodic):
        """A body wider than half a periodic box was most likely given inconsistent image flags
        (LAMMPS takes it as it is, and so does pdps): say so once."""
        n = sim.particles.nlocal
        mine = np.flatnonzero(body[:n] >= 0)
        b = body[mine]
        unwrapped = x[mine] + (image[mine] - self.image_body[b]) * length
        highest = np.full((self.nbody, 3), -np.inf)
        lowest = np.full((self.nbody, 3), np.inf)
        np.maximum.at(highest, b, unwrapped)
        np.minimum.at(lowest, b, unwrapped)
        highest = sim.comm.allgather_rows(highest[None]).max(axis=0)
        lowest = sim.comm.allgather_rows(lowest[None]).min(axis=0)
        width = highest - lowest
        spanning = (width > 0.5 * length) & periodic
        if spanning.any():
            k, d = (int(i) for i in np.argwhere(spanning)[0])
            sim.warn(f"fix {self.id}: body {self.body_ids[k]} is {width[k, d]:.6g} wide along {'xyz'[d]}, more "
                     f"than half the periodic box ({length[d]:g}): are its particles' image flags those of one "
                     "whole body?")

    def _gravity(self, sim):
        """The acceleration of the fix the gravity keyword names (LAMMPS's extract("gvec")), or None;
        LAMMPS's warning where bodies whose masses come from a file fall under a gravity fix without it."""
        name = self.args.gravity
        if name is None:
            if self.args.infile is not None and any(fix.extract("gvec") is not None for fix in sim.fixes.values()):
                sim.warn(f"fix {self.id}: gravity may not be correctly applied to rigid bodies if they consist of "
                         "overlapped particles (the infile's masses; use the gravity keyword, as LAMMPS says)")
            return None
        fix = sim.fixes.get(name)
        if fix is None:
            raise ScriptError(f"fix {self.id}: cannot find fix gravity ID {name}")
        gvec = fix.extract("gvec")
        if gvec is None:
            raise ScriptError(f"fix {self.id}: gravity fix ID {name} is not a gravity fix style ({fix.name})")
        return np.asarray(gvec, dtype=np.float64)

    def reset_dt(self, sim):
        """The step's constants (at each run's start, and for a new step mid-run: fix dt/reset)."""
        self.dtv = sim.dt
        self.dtf = 0.5 * sim.dt * sim.units.ftm2v
        self.dtq = 0.5 * sim.dt

    def init_run(self, sim):
        self.gvec = self._gravity(sim)
        self.reset_dt(sim)
        # a file's values hold for the first run only (LAMMPS: infile sets reinit no)
        if (self.args.reinit == "yes" and self.args.infile is None) or not self.set_up:
            self.setup_bodies(sim)
        # a linear body does not turn about its line in 3d; in 2d it turns about z all the same
        nlinear = int(np.count_nonzero((self.inertia == 0.0).any(axis=1))) if sim.dimension == 3 else 0
        free = self.fflag.sum() + self.tflag.sum() - nlinear
        self.tfactor = sim.units.mvv2e / (free * sim.units.boltz) if free > 0 else 0.0

    # ---- the timestep ---------------------------------------------------------------------------
    def _sum_force_torque(self, sim):
        x, v, f, image, body, displace, *_, torque_atom, length = self._atoms(sim)
        bodies.force_torque(x, f, torque_atom, image, body, length, self.xcm, self.image_body,
                            sim.particles.nlocal, self.sums)
        total = sim.comm.sum(self.sums)
        self.fcm[:] = total[:, :3]
        self.torque[:] = total[:, 3:]
        if self.args.langevin is not None and not sim.in_setup:
            self._langevin(sim)
            self.fcm += self.langextra[:, :3]
            self.torque += self.langextra[:, 3:]
        if self.gvec is not None:
            self.fcm += self.masstotal[:, None] * self.gvec

    def _langevin(self, sim):
        """The Langevin force and torque of this step (LAMMPS applies them from post_force on the
        bodies' motion after the first half step; nothing changes that motion before final_integrate,
        so they are drawn here). The target T ramps from Tstart to Tstop over the run."""
        start, stop, period, seed = self.args.langevin
        langevin_body_forces(self.vcm, self.omega, self.ex, self.ey, self.ez, self.inertia, self.masstotal,
                             sim.random_key(seed), sim.step, sim.ramp(start, stop), period, sim.dt, sim.units.boltz,
                             sim.units.mvv2e, sim.units.ftm2v, sim.dimension == 2, self.langextra)

    def _set_v(self, sim, virial, tally):
        x, v, f, image, body, displace, type_, mass, rmass, radius, omega_atom, _, length = self._atoms(sim)
        bodies.set_v(x, v, f, omega_atom, image, body, displace, type_, mass, rmass, length, self.vcm, self.omega,
                     self.ex, self.ey, self.ez, self.image_body, sim.particles.nlocal, self.dtf, virial, tally)

    def setup(self, sim):
        self.atom_arrays = None
        self._sum_force_torque(sim)
        omegas(self.angmom, self.ex, self.ey, self.ez, self.inertia, self.omega)
        self.step_virial[:] = 0.0
        self.final_virial[:] = 0.0
        self._set_v(sim, self.step_virial, True)
        # LAMMPS's estimate of the setup virial: twice the set_v half
        self.step_virial *= 2.0

    def advance_initial(self, sim):
        richardson_initial(self.xcm, self.vcm, self.fcm, self.angmom, self.torque, self.omega, self.quat,
                           self.ex, self.ey, self.ez, self.inertia, self.masstotal, self.fflag, self.tflag,
                           self.dtv, self.dtf, self.dtq)

    def advance_final(self, sim):
        richardson_final(self.vcm, self.fcm, self.angmom, self.torque, self.omega, self.ex, self.ey, self.ez,
                         self.inertia, self.masstotal, self.fflag, self.tflag, self.dtf)

    def initial_integrate(self, sim):
        self.advance_initial(sim)
        self.place_particles(sim)

    def place_particles(self, sim):
        """Particle positions and velocities from the bodies (LAMMPS's set_xv), with the first half
        of the step's constraint virial."""
        x, v, f, image, body, displace, type_, mass, rmass, radius, omega_atom, _, length = self._atoms(sim)
        self.step_virial[:] = 0.0
        bodies.set_xv(x, v, f, omega_atom, image, body, displace, type_, mass, rmass, length, self.xcm, self.vcm,
                      self.omega, self.ex, self.ey, self.ez, self.image_body, sim.particles.nlocal, self.dtf,
                      self.step_virial, self.thermo_virial)

    def final_integrate(self, sim):
        self._late_sum(sim)
        self.advance_final(sim)
        self.final_virial[:] = 0.0
        self._set_v(sim, self.final_virial, sim.vflag and self.thermo_virial)

    def pre_neighbor(self, sim):
        self.atom_arrays = None
        bodies.remap_centres(self.xcm, self.image_body, np.asarray(sim.box.lo, dtype=np.float64),
                             np.asarray(sim.box.hi, dtype=np.float64), np.asarray(sim.box.length, dtype=np.float64),
                             np.asarray(sim.box.periodic, dtype=np.bool_))

    # ---- thermo ---------------------------------------------------------------------------------
    def box_carried_centres(self):
        """The bodies' centres of mass, which a box change scales (every rank has them all)."""
        return self.xcm

    def box_carried(self, sim):
        """After a box change moved the centres: the box lengths are read again."""
        self.atom_arrays = None

    def compute_virial(self, sim):
        """Both halves of the step's constraint virial (read after final_integrate)."""
        return tuple(float(c) for c in self.step_virial + self.final_virial)

    def dof_removed(self, sim, group):
        if not self.set_up:
            return 0
        key = (group, self.set_up)
        if key not in self.dof_cache:
            p = sim.particles
            n = p.nlocal
            body = p.arrays[self.body_name][:n]
            chosen = (body >= 0) & sim.groups.select(sim, group)
            extended = chosen & (p.radius[:n] > 0) if p.has("radius") else np.zeros(n, dtype=bool)
            points = np.bincount(body[chosen & ~extended], minlength=self.nbody)
            spheres = np.bincount(body[extended], minlength=self.nbody)
            counts = np.asarray(sim.comm.sum(np.stack([points, spheres]).astype(np.int64)))
            nall, mall = counts
            whole = nall + mall == self.nrigid
            if np.any((nall + mall > 0) & ~whole):
                sim.warn(f"fix {self.id}: group {group} holds part of a rigid body; its temperature counts "
                         "none of that body's constraints")
            if sim.dimension == 3:
                linear = (self.inertia == 0.0).any(axis=1)
                removed = np.where(whole, 3 * nall + 6 * mall - 6 + linear, 0)
            else:
                removed = np.where(whole, 2 * nall + 3 * mall - 3, 0)
            self.dof_cache[key] = int(removed.sum())
        return self.dof_cache[key]

    def scalar(self, sim):
        """Temperature of the bodies' translation and rotation (the components left on)."""
        if not self.set_up:
            return 0.0
        translation = self.masstotal * np.einsum("bd,bd->b", self.fflag, self.vcm ** 2)
        projected = np.stack([np.einsum("bd,bd->b", axis, self.angmom) for axis in (self.ex, self.ey, self.ez)], 1)
        wbody = np.divide(projected, self.inertia, out=np.zeros_like(projected), where=self.inertia != 0.0)
        rotation = np.einsum("bd,bd->b", self.tflag, self.inertia * wbody ** 2)
        return float(translation.sum() + rotation.sum()) * self.tfactor

    def array(self, sim):
        return np.hstack([self.xcm, self.vcm, self.fcm, self.torque, self.image_body.astype(np.float64)])
