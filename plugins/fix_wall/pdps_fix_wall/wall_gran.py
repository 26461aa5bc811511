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

from pdps_core.api import ContactHistory, Fix, ScriptError, StyleArgs, keyword, param
from pdps_granular_contact import contact_models, lammps_classic
from pdps_granular_contact.lammps_classic import NullableFloat

from .wall_contact import WallContactTable, WallLaw

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
def near_wall(x, radius, mask, groupbit, nlocal, wallstyle, lo, hi, cylinder, margin, near, partner):
    """The group's particles within their radius plus ``margin`` of the wall, into ``near``;
    returns how many. The group's others forget their wall contact (none of them touches the wall)."""
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
            else:
                for s in range(partner.shape[1]):
                    partner[i, s] = -1
    return count


@njit(cache=True)
def wall_table(x, near, count, wallstyle, lo, hi, cylinder, wall_velocity, spin, starts, distance, normal, key,
               velocity, curvature):
    """The wall's contact with each particle ``near[:count]`` (the nearer plane of the two, or the
    cylinder: key 0) as a contact table, particle k's rows starts[k] .. starts[k + 1]: distance from
    the surface, normal towards the centre, the wall's velocity (a turning cylinder's surface speed
    ``spin`` added) and its curvature (the cylinder's radius, negative inside; 0 for planes)."""
    base = 0
    for k in range(count):
        i = near[k]
        starts[k] = base
        d0, d1, d2 = 0.0, 0.0, 0.0
        rw = 0.0
        v0, v1, v2 = wall_velocity[0], wall_velocity[1], wall_velocity[2]
        if wallstyle == ZCYLINDER:
            across = math.sqrt(x[i, 0] * x[i, 0] + x[i, 1] * x[i, 1])
            if across == 0.0:
                continue
            gap = cylinder - across
            d0 = -gap / across * x[i, 0]
            d1 = -gap / across * x[i, 1]
            rw = -2.0 * cylinder if across < cylinder else 2.0 * cylinder
            v0 += spin * x[i, 1] / across
            v1 -= spin * x[i, 0] / across
        else:
            below = x[i, wallstyle] - lo
            above = hi - x[i, wallstyle]
            gap = below if below < above else -above
            if wallstyle == 0:
                d0 = gap
            elif wallstyle == 1:
                d1 = gap
            else:
                d2 = gap
        r = math.sqrt(d0 * d0 + d1 * d1 + d2 * d2)
        if r == 0.0:
            continue
        distance[base] = r
        normal[base, 0] = d0 / r
        normal[base, 1] = d1 / r
        normal[base, 2] = d2 / r
        key[base] = 0
        velocity[base, 0] = v0
        velocity[base, 1] = v1
        velocity[base, 2] = v2
        curvature[base] = rw
        base += 1
    starts[count] = base


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
        from .wall_gran_granular import FixWallGranGranular
        from .wall_gran_model import FixWallGranModel
        return (FixWallGranModel, FixWallGranGranular)

    @classmethod
    def respell(cls, dialect, words):
        # LIGGGHTS's spelling (``wall/gran model ...``, its keywords in any order) is a style of its own
        if "model" in words:
            from .wall_gran_model import FixWallGranModel
            return FixWallGranModel, list(words)
        # so is LAMMPS's with pair granular's models
        if words[:1] == ["granular"]:
            from .wall_gran_granular import FixWallGranGranular
            return FixWallGranGranular, list(words[1:])
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
        self.place_wall(sim, args)
        # LAMMPS's classic law, composed of pdps_granular_contact.classic's sub-models
        self.keep_contacts(sim, id, WallLaw(lammps_classic.contact_model(self.model)))

    def place_wall(self, sim, args):
        """The wall of ``args.wallstyle``, its motion (``wiggle``, ``shear``) and the particles near it."""
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
        self._near, self._count = np.empty(0, dtype=np.int64), 0
        self._still = np.zeros(3)

    def keep_contacts(self, sim, id, law):
        """The contact law (a WallLaw) and each particle's one contact with the wall (the nearer plane,
        or the cylinder): its history, then its normal."""
        self.law = law
        self.history = ContactHistory(sim, f"wall_gran_{id}", width=self.law.model.history_width + 3, capacity=2)
        self.table, self._curvature = WallContactTable(), np.zeros(0)

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
        self.law.bind(lammps_classic.constants(self.model, self.kn, self.kt, self.gamma_n, self.gamma_t, self.xmu,
                                               self.limit_damping, sim.ntypes))
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
        self._count = near_wall(a["x"], a["radius"], a["mask"], sim.groups.bit(self.group), p.nlocal,
                                self.wallstyle, lo, hi, self.cylinder, margin, self._near, self.history.partner)

    def post_force(self, sim):
        self.forces(sim, update=True)

    def forces(self, sim, update):
        p = sim.particles
        a = p.arrays
        if self.wiggle or self.shear:
            lo, hi, velocity, spin = self.wall_state(sim)
        else:
            lo, hi, velocity, spin = self.lo, self.hi, self._still, 0.0
        table = self.table.room(self._count, self._count)
        if len(self._curvature) < table.rows:
            self._curvature = np.zeros(table.rows)
        distance, normal, key, _, wall_velocity = table.arrays()
        wall_table(a["x"], self._near, self._count, self.wallstyle, lo, hi, self.cylinder, velocity, spin,
                   table.starts, distance, normal, key, wall_velocity, self._curvature)
        bad, _ = self.law.forces(sim, self._near, self._count, table.starts, table.arrays(), table.contact_force,
                                 self.history, 0, a["f"], a["torque"], update, radius=a["radius"], mass=a["rmass"],
                                 omega=a["omega"], body_mass=a.get("body_mass", contact_models.NO_BODY_MASS),
                                 curvature=self._curvature)
        if bad >= 0:
            self.history.overflowed(p.tag[bad])
