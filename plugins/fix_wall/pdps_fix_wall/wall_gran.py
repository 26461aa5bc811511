r"""Fix ``wall/gran``: LAMMPS's frictional granular walls (flat planes and a cylinder about the z
axis) with the classic laws of pair gran/hooke, gran/hooke/history and gran/hertz/history (LAMMPS's
fix wall/gran, older positional syntax).

A wall is body j of infinite mass and no spin. Particle i (radius :math:`R_i`, mass :math:`m_i`) at
distance :math:`d < R_i` from it overlaps it by :math:`\delta = R_i - d`, with normal
:math:`\mathbf{n}` from the wall to the centre of i, :math:`m^* = m_i` and
:math:`R^* = R_i` (planes) or :math:`R^* = R_iR_w/(R_i + R_w)` with :math:`R_w = -2R_c` inside and
:math:`+2R_c` outside a cylinder of radius :math:`R_c` (as LAMMPS). With the wall's velocity
:math:`\mathbf{v}_w`, :math:`v_n = (\mathbf{v}_i - \mathbf{v}_w)\cdot\mathbf{n}`, the tangential part
:math:`\mathbf{v}_t` and :math:`\mathbf{v}_{tr} = \mathbf{v}_t - R_i\boldsymbol\omega_i\times
\mathbf{n}`, the force on i is that of ``pdps_granular_contact.lammps_classic``:

.. math::

    F_n = s\,(k_n\delta - m_i\gamma_n v_n), \qquad
    \mathbf{F}_t = -(k_t\sqrt{\delta R^*}\,\boldsymbol\xi + s\,m_i\gamma_t\mathbf{v}_{tr}) \ \
    (|\mathbf{F}_t| \le \mu|F_n|), \qquad \boldsymbol\tau_i = -R_i\,\mathbf{n}\times\mathbf{F}_t

(:math:`s = 1`, or :math:`\sqrt{\delta R^*}` for hertz/history; hooke has no spring,
:math:`\mathbf{F}_t = -\min(\mu|F_n|, m_i\gamma_t|\mathbf{v}_{tr}|)\,\hat{\mathbf{v}}_{tr}`). Each
particle keeps one spring :math:`\boldsymbol\xi` for its wall contact (history styles), grown by
:math:`\mathbf{v}_{tr}\Delta t`, projected onto the wall's tangent plane, cut back at the Coulomb
limit to :math:`-(\mathbf{F}_t + s\,m_i\gamma_t\mathbf{v}_{tr})/k_t`, and zeroed when the particle
leaves the wall; the setup force computation of a run does not advance it. The spring's stiffness
:math:`k_t\sqrt{\delta R^*}` also for hooke/history, and the cut back by :math:`k_t` alone, are how
LAMMPS's fix wall/gran (22 Jul 2025, through its granular sub-models) differs from pair
gran/hooke/history and gran/hertz/history; pdps follows it (measured: trajectories equal to 1e-15).

Wall styles:

- ``xplane LO HI``, ``yplane LO HI``, ``zplane LO HI``: planes at coordinate LO and HI (NULL: no
  such plane). A particle is pushed by the nearer of the two only: by LO along + when
  :math:`x - LO < HI - x`, else by HI along -, whenever its distance to that plane is below its
  radius (also from the far side, as LAMMPS).
- ``zcylinder RADIUS``: the cylinder :math:`x^2 + y^2 = R_c^2` about the z axis, touched from
  inside or outside.

Keywords:

- ``wiggle dim amplitude period``: the wall oscillates along dim (x, y or z; z only for zcylinder):
  a plane along dim moves to :math:`LO + A(1 - \cos\omega t)` (and so HI), :math:`\omega = 2\pi/T`,
  and every wall has the velocity :math:`A\omega\sin\omega t` along dim, t counted from the step the
  fix was defined (LAMMPS).
- ``shear dim vshear``: the wall slides with velocity vshear along dim (not its own normal), which
  only the friction feels. For zcylinder, ``shear z`` slides it along its axis and ``shear x`` or
  ``shear y`` turns it about the axis with surface speed vshear: :math:`\mathbf{v}_w = v_s\,(y, -x,
  0)/\sqrt{x^2+y^2}` at the particle.

Parameters (units as the pair styles): ``Kn``, ``Kt`` (force/distance; pressure for hertz/history,
divided by nktv2p; Kt NULL: 2/7 Kn), ``gamma_n``, ``gamma_t`` (1/time; gamma_t NULL: gamma_n / 2),
``xmu`` (0 to 10000), ``dampflag`` (0: gamma_t = 0), ``limit_damping`` (optional word: the normal
force is never attractive).

Syntax::

    fix ID GROUP wall/gran STYLE Kn Kt gamma_n gamma_t xmu dampflag [limit_damping] WALLSTYLE args
        [wiggle dim amplitude period] [shear dim vshear]

    STYLE = hooke | hooke/history | hertz/history
    WALLSTYLE args = xplane|yplane|zplane LO HI  |  zcylinder RADIUS

Cost: at each neighbor list rebuild the fix lists the particles within their radius plus the skin
of the wall (plus its stroke when it wiggles), and at each step visits only those: no particle can
reach the wall before the next rebuild without moving more than the skin, when the run warns.

Differences from LAMMPS: a rotating cylinder (``zcylinder ... shear x|y``) has the wall velocity of
each particle's own contact point (LAMMPS adds every contacting particle's into one running sum);
with gamma_n = 0 the tangential damping is m_i gamma_t (LAMMPS's fix computes gamma_t/gamma_n and
gives NaN); a particle whose centre lies exactly on the wall feels no force (no normal). The
``region`` wall style and ``contacts``/``temperature`` keywords of LAMMPS are not supported.

LIGGGHTS's spelling (a line with the keyword ``model``) is a style of its own, pdps_fix_wall.wall_gran_model,
whose docstring gives the physics: LIGGGHTS's contact models of pair gran (hertz, hooke, rolling
friction, cohesion) with the wall as a body of infinite mass and radius, the material of the type
pair (particle, wall) from fix property/global::

    fix ID GROUP wall/gran model hertz|hooke tangential history|no_history
        [rolling_friction off|cdt|epsd|epsd2] [cohesion off|sjkr|sjkr2]
        [tangential_damping on|off] [limitForce on|off]
        primitive type N xplane|yplane|zplane C | xcylinder|ycylinder|zcylinder R C1 C2 [shear DIM V]
      | mesh n_meshes N meshes MESH_ID ...   (fix mesh/surface IDs; moved by fix move/mesh)

Planes are touched from either side, cylinders from inside and outside (axis through (y, z) for
xcylinder, (z, x) for ycylinder, (x, y) for zcylinder: LIGGGHTS's order); ``shear DIM V`` slides a
plane along DIM, or a cylinder along its axis, or turns it about its axis at V rad/time.

Example (the benchmark kit's in.gran_box)::

    fix w all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 40.0
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param
from pdps_granular_contact import contact_models, lammps_classic
from pdps_granular_contact.lammps_classic import NullableFloat

FAR = 1.0e20                    # a NULL plane, as LAMMPS's BIG
XPLANE, YPLANE, ZPLANE, ZCYLINDER = 0, 1, 2, 3
WALL_STYLES = {"xplane": XPLANE, "yplane": YPLANE, "zplane": ZPLANE, "zcylinder": ZCYLINDER}
AXES = {"x": 0, "y": 1, "z": 2}
Axis = Literal["x", "y", "z"]


class LawStyle(StyleArgs):
    style: Literal["hooke", "hooke/history", "hertz/history"] = param()


WallWords = (tuple[Literal["xplane", "yplane", "zplane"], NullableFloat, NullableFloat]
             | tuple[Literal["zcylinder"], float])


@njit(cache=True)
def near_wall(x, radius, mask, groupbit, nlocal, wallstyle, lo, hi, cylinder, margin, near, history,
              with_history):
    """The group's particles within their radius plus ``margin`` of the wall, into ``near``;
    returns how many. The springs of the group's others are zeroed (none of them touches the wall)."""
    count = 0
    for i in range(nlocal):
        if mask[i] & groupbit:
            if wallstyle == ZCYLINDER:
                gap = abs(cylinder - math.sqrt(x[i, 0] * x[i, 0] + x[i, 1] * x[i, 1]))
            else:
                gap = min(abs(x[i, wallstyle] - lo), abs(hi - x[i, wallstyle]))
            if gap < radius[i] + margin:
                near[count] = i
                count += 1
            elif with_history:
                for k in range(3):
                    history[i, k] = 0.0
    return count


# _nrt=False: no reference counting of the arrays its contact helpers take (they store under
# branches, where numba's counting stays in the loop as atomic calls: numba issue #2350); nothing
# here allocates
@njit(cache=True, _nrt=False)
def wall_gran_forces(x, v, omega, radius, rmass, body_mass, f, torque, near, count, wallstyle, lo,
                     hi, cylinder, wall_velocity, spin, model, kn, kt, gamma_n, gamma_t, xmu,
                     limit_damping, dt, update, history, d, n, vw, vtr, tangential):
    """Wall forces and torques on the particles ``near[:count]``. ``spin``: surface speed of a
    cylinder turning about z (0 otherwise); ``history`` (nlocal, 3) springs, or one scratch row
    for hooke; ``d``, ``n``, ``vw``, ``vtr``, ``tangential``: scratch vectors."""
    with_history = model != lammps_classic.HOOKE
    for c in range(count):
        i = near[c]
        d[:] = 0.0
        r_wall = 0.0
        for k in range(3):
            vw[k] = wall_velocity[k]
        touching = True
        if wallstyle == ZCYLINDER:
            across = math.sqrt(x[i, 0] * x[i, 0] + x[i, 1] * x[i, 1])
            gap = cylinder - across
            if gap > radius[i] or across == 0.0:
                touching = False
            else:
                d[0] = -gap / across * x[i, 0]
                d[1] = -gap / across * x[i, 1]
                r_wall = -2.0 * cylinder if across < cylinder else 2.0 * cylinder
                vw[0] += spin * x[i, 1] / across
                vw[1] -= spin * x[i, 0] / across
        else:
            below = x[i, wallstyle] - lo
            above = hi - x[i, wallstyle]
            d[wallstyle] = below if below < above else -above
        rsq = d[0] * d[0] + d[1] * d[1] + d[2] * d[2]
        if not touching or rsq >= radius[i] * radius[i] or rsq == 0.0:
            if with_history:
                history[i, :] = 0.0
            continue
        r = math.sqrt(rsq)
        for k in range(3):
            n[k] = d[k] / r
        r_eff = radius[i] if r_wall == 0.0 else radius[i] * r_wall / (radius[i] + r_wall)
        vr0 = v[i, 0] - vw[0]
        vr1 = v[i, 1] - vw[1]
        vr2 = v[i, 2] - vw[2]
        v_n = vr0 * n[0] + vr1 * n[1] + vr2 * n[2]
        w0 = radius[i] * omega[i, 0]
        w1 = radius[i] * omega[i, 1]
        w2 = radius[i] * omega[i, 2]
        vtr[0] = vr0 - v_n * n[0] - (w1 * n[2] - w2 * n[1])
        vtr[1] = vr1 - v_n * n[1] - (w2 * n[0] - w0 * n[2])
        vtr[2] = vr2 - v_n * n[2] - (w0 * n[1] - w1 * n[0])
        shear = history[i] if with_history else history[0]
        m_eff = contact_models.contact_mass(rmass, body_mass, i)
        fn = lammps_classic.classic_contact(model, True, radius[i] - r, r_eff, n, v_n, vtr, m_eff, kn, kt,
                                            gamma_n, gamma_t, xmu, limit_damping, update, dt, shear,
                                            tangential)
        for k in range(3):
            f[i, k] += fn * n[k] + tangential[k]
        torque[i, 0] -= radius[i] * (n[1] * tangential[2] - n[2] * tangential[1])
        torque[i, 1] -= radius[i] * (n[2] * tangential[0] - n[0] * tangential[2])
        torque[i, 2] -= radius[i] * (n[0] * tangential[1] - n[1] * tangential[0])


class FixWallGran(Fix):
    name = "wall/gran"
    minimize_idle = True         # LAMMPS's fix wall/gran has no min_post_force (recorded: a minimization ignores it)
    usage = ("fix ID GROUP wall/gran hooke|hooke/history|hertz/history Kn Kt gamma_n gamma_t xmu dampflag "
             "[limit_damping] xplane|yplane|zplane LO HI | zcylinder RADIUS [wiggle dim A T] [shear dim V]")

    class Args(lammps_classic.ClassicLaw, LawStyle):
        limit_damping: Literal["limit_damping"] | None = param(None)
        wallstyle: WallWords = param(unit={"xplane|yplane|zplane LO HI": ("1", "distance", "distance"),
                                           "zcylinder RADIUS": ("1", "distance")})
        wiggle: tuple[Axis, float, float] | None = keyword(None, unit=("1", "distance", "time"))
        shear: tuple[Axis, float] | None = keyword(None, unit=("1", "velocity"))

    @classmethod
    def spellings(cls):
        from .wall_gran_model import FixWallGranModel
        return (FixWallGranModel,)

    @classmethod
    def respell(cls, dialect, words):
        # LIGGGHTS's spelling (``wall/gran model ...``, its keywords in any order) is a style of its own
        if "model" in words:
            from .wall_gran_model import FixWallGranModel
            return FixWallGranModel, list(words)
        return None

    @classmethod
    def check_args(cls, args):
        if args.wallstyle[0] == "zcylinder" and not args.wallstyle[1] > 0.0:
            raise ScriptError(f"radius must be > 0 (got {args.wallstyle[1]:g})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if "sphere" not in sim.particle_styles:
            raise ScriptError("fix wall/gran needs atom_style sphere (per-particle radius, mass and "
                              "rotation)")
        self.model = lammps_classic.MODELS[args.style]
        self.kn, self.kt, self.gamma_n, self.gamma_t = args.constants(self.model, sim.units.nktv2p)
        self.xmu = args.xmu
        self.limit_damping = args.limit_damping is not None
        wallstyle, *values = args.wallstyle
        self.wallstyle = WALL_STYLES[wallstyle]
        if self.wallstyle == ZCYLINDER:
            self.lo, self.hi, self.cylinder = 0.0, 0.0, values[0]
        else:
            lo, hi = values
            self.lo = -FAR if lo is None else lo
            self.hi = FAR if hi is None else hi
            self.cylinder = 0.0
        self.check_motion(sim, wallstyle, args)
        self.wiggle, self.shear = args.wiggle, args.shear
        self.time_origin = sim.step
        self.spring = None
        self._near, self._count = np.empty(0, dtype=np.int64), 0
        self._still, self._no_history = np.zeros(3), np.zeros((1, 3))
        self._scratch = tuple(np.zeros(3) for _ in range(5))
        if self.model != lammps_classic.HOOKE:
            name = f"wall_gran_{id}"
            sim.particles.request(name, width=3)
            self.spring = name

    def check_motion(self, sim, wallstyle, wall):
        periodic = sim.box.periodic
        if self.wallstyle == ZCYLINDER and (periodic[0] or periodic[1]):
            raise ScriptError("zcylinder needs a box not periodic in x and y (boundary f or s there)")
        if self.wallstyle != ZCYLINDER and periodic[self.wallstyle]:
            raise ScriptError(f"{wallstyle} needs a box not periodic in {'xyz'[self.wallstyle]} "
                              "(boundary f or s there)")
        if wall.wiggle and wall.shear:
            raise ScriptError("a wall can wiggle or shear, not both")
        if wall.wiggle:
            dim, _, period = wall.wiggle
            if not period > 0.0:
                raise ScriptError(f"wiggle period must be > 0 (got {period:g})")
            if self.wallstyle == ZCYLINDER and dim != "z":
                raise ScriptError(f"a zcylinder wiggles along z only (got wiggle {dim})")
        if wall.shear and self.wallstyle != ZCYLINDER and AXES[wall.shear[0]] == self.wallstyle:
            raise ScriptError(f"shear {wall.shear[0]} would move a {wallstyle} wall along its own normal; "
                              "shear along a direction in the plane")

    def wall_state(self, sim):
        """(lo, hi, wall velocity, cylinder surface speed) at the current step."""
        lo, hi, velocity, spin = self.lo, self.hi, np.zeros(3), 0.0
        if self.wiggle:
            dim, amplitude, period = self.wiggle
            axis = AXES[dim]
            frequency = 2.0 * math.pi / period
            phase = frequency * (sim.step - self.time_origin) * sim.dt
            if self.wallstyle == axis:
                lo = lo + amplitude - amplitude * math.cos(phase)
                hi = hi + amplitude - amplitude * math.cos(phase)
            velocity[axis] = amplitude * frequency * math.sin(phase)
        elif self.shear:
            dim, speed = self.shear
            if self.wallstyle == ZCYLINDER and dim != "z":
                spin = speed
            else:
                velocity[AXES[dim]] = speed
        return lo, hi, velocity, spin

    def setup(self, sim):
        self.pre_neighbor(sim)
        self.forces(sim, update=False)

    def pre_neighbor(self, sim):
        """The particles that may touch the wall before the next rebuild: within their radius plus
        the skin (a rebuild comes before any particle moves half of it; a wiggling plane adds its
        stroke). Only they are visited at each step."""
        p = sim.particles
        a = p.arrays
        if len(self._near) < p.nlocal:
            self._near = np.empty(p.nall, dtype=np.int64)
        margin = sim.neighbor.skin
        if self.wiggle and AXES[self.wiggle[0]] == self.wallstyle:
            margin += 2.0 * abs(self.wiggle[1])
        lo, hi = self.lo, self.hi
        if self.wiggle:
            lo, hi, _, _ = self.wall_state(sim)
        history = a[self.spring] if self.spring else self._no_history
        self._count = near_wall(a["x"], a["radius"], a["mask"], sim.groups.bit(self.group), p.nlocal,
                                self.wallstyle, lo, hi, self.cylinder, margin, self._near, history,
                                self.spring is not None)

    def post_force(self, sim):
        self.forces(sim, update=True)

    def forces(self, sim, update):
        a = sim.particles.arrays
        if self.wiggle or self.shear:
            lo, hi, velocity, spin = self.wall_state(sim)
        else:
            lo, hi, velocity, spin = self.lo, self.hi, self._still, 0.0
        history = a[self.spring] if self.spring else self._no_history
        wall_gran_forces(a["x"], a["v"], a["omega"], a["radius"], a["rmass"],
                         a.get("body_mass", contact_models.NO_BODY_MASS), a["f"], a["torque"], self._near,
                         self._count, self.wallstyle, lo, hi, self.cylinder, velocity, spin, self.model,
                         self.kn, self.kt, self.gamma_n, self.gamma_t, self.xmu, self.limit_damping, sim.dt,
                         update, history, *self._scratch)
