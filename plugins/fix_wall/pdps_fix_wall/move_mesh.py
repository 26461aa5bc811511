r"""Fix ``move/mesh``: a prescribed rigid motion of a ``fix mesh/surface`` (LIGGGHTS's fix move/mesh).

Each style is a rigid motion :math:`\mathbf{X}(t) = R(t)\,\mathbf{X}_0 + \mathbf{d}(t)` of the mesh's
vertices :math:`\mathbf{X}_0` as they were when the fix was defined, with t the time since then
(time units; :math:`\omega = 2\pi/T` for a period T):

- ``linear VX VY VZ``: :math:`\mathbf{X} = \mathbf{X}_0 + \mathbf{V}t` (velocity units).
- ``linear/variable v_VX v_VY v_VZ``: the same with equal-style variables, evaluated each step:
  :math:`\mathbf{d} \mathrel{+}= \mathbf{V}(t)\,\Delta t`.
- ``wiggle amplitude AX AY AZ period T``: the velocity :math:`\mathbf{A}\omega\cos\omega t`.
- ``rotate origin PX PY PZ axis AX AY AZ period T``: turns about the axis through P by
  :math:`\omega t` (right-hand rule about the axis).
- ``rotate/variable origin PX PY PZ axis AX AY AZ omega v_W``: turns at the angular velocity of an
  equal-style variable (rad/time): :math:`\varphi \mathrel{+}= W(t)\,\Delta t`.
- ``riggle origin PX PY PZ axis AX AY AZ period T amplitude DEG``: turns at the angular velocity
  :math:`A\omega\cos\omega t` (A in degrees).
- ``viblin axis AX AY AZ order n amplitude C1..Cn phase p1..pn period T``: the velocity
  :math:`-\hat{\mathbf{D}}\sum_{k=1}^n C_k k\omega\sin(k\omega t + p_k)` (phases in rad).
- ``vibrot origin PX PY PZ axis AX AY AZ order n amplitude C1..Cn phase p1..pn period T``: turns
  about the axis through P at the angular velocity :math:`-\sum_k C_k k\omega\sin(k\omega t + p_k)`.

The oscillating motions (wiggle, riggle, viblin, vibrot) are integrated as LIGGGHTS 3.8.0 integrates
them (its source, and its numbers recorded in plugins/fix_wall/tests/data/liggghts.cases.json, case
move_mesh_wiggle): each step moves the mesh by the velocity at the step's end times the timestep,
:math:`\mathbf{d} \mathrel{+}= \dot{\mathbf{d}}(t + \Delta t)\,\Delta t`, so the mesh starts from where
it is, without the jump :math:`\hat{\mathbf{D}}\sum C_k\cos p_k` the manual's viblin formula has, and
drifts from :math:`\mathbf{A}\sin\omega t` by :math:`O(\Delta t)` as LIGGGHTS's does.

The wall velocity each contact law sees is the time derivative of this motion at the contact point.
Several ``move/mesh`` on one mesh are superposed: each moves in the frame carried along by the ones
defined before it (LIGGGHTS's manual; fix mesh/surface gives the formula). The fix group is not
used. The motions move the vertices in ``initial_integrate``, as LIGGGHTS does; a wall's candidate
triangles are re-listed only once a vertex has moved half the skin since they were listed. An unfixed
motion leaves the mesh where it took it, at rest, and a motion defined after starts from there (as
LIGGGHTS's tutorial movingMeshGran moves its bucket, then turns it); unfixing one of several
motions of one mesh at once is refused.

The motion's clock, and what the variable styles have integrated, are saved in restart files.

Syntax::

    fix ID GROUP move/mesh mesh MESH_ID STYLE ARGS

The keywords of ARGS (``amplitude``, ``origin``, ``axis``, ``period``, ``omega``, ``order``,
``phase``) stand in any order; each motion takes those its line above names, no others.

Examples::

    fix shake all move/mesh mesh floor wiggle amplitude 0 0 0.01 period 0.05
    fix stir all move/mesh mesh blade rotate origin 0 0 0 axis 0 0 1 period 2.0
"""

import math
from typing import Literal

import numpy as np

from pdps_core.api import FloatOrVariable, Fix, MeshSurface, ScriptError, StyleArgs, VariableRef, keyword, param

from .mesh import rotation_matrix, unit

MAX_ORDER = 10
STILL, NO_TURN = np.eye(3), np.zeros((3, 3))    # read only: the pose of a translation
STILL.flags.writeable = False
# the motions integrated step by step from their velocity (LIGGGHTS's), and those that turn the mesh
OSCILLATIONS = ("wiggle", "riggle", "viblin", "vibrot")
TURNS = ("rotate/variable", "riggle", "vibrot")
# the keywords each motion takes (all of them, in any order)
MOTION_WORDS = {"linear": (), "linear/variable": (), "wiggle": ("amplitude", "period"),
                "rotate": ("origin", "axis", "period"), "rotate/variable": ("origin", "axis", "omega"),
                "riggle": ("origin", "axis", "period", "amplitude"),
                "viblin": ("axis", "order", "amplitude", "phase", "period"),
                "vibrot": ("origin", "axis", "order", "amplitude", "phase", "period")}
ALL_WORDS = ("origin", "axis", "order", "amplitude", "phase", "period", "omega")
NO_TURN.flags.writeable = False


def cross_matrix(axis):
    ax, ay, az = axis
    return np.array([[0.0, -az, ay], [az, 0.0, -ax], [-ay, ax, 0.0]])


def turn_about(axis, origin, angle, rate):
    """(R, d, dR/dt, dd/dt) of a turn by ``angle`` about the axis through ``origin``, turning at
    ``rate`` (rad/time): x -> R (x - P) + P."""
    rotation = rotation_matrix(axis, angle)
    turning = rate * cross_matrix(axis) @ rotation
    return rotation, origin - rotation @ origin, turning, -turning @ origin


class FixMoveMesh(Fix):
    name = "move/mesh"
    usage = ("fix ID GROUP move/mesh mesh MESH_ID linear VX VY VZ | linear/variable v_X v_Y v_Z | "
             "wiggle amplitude AX AY AZ period T | rotate origin PX PY PZ axis AX AY AZ period T | "
             "rotate/variable origin PX PY PZ axis AX AY AZ omega v_W | "
             "riggle origin PX PY PZ axis AX AY AZ period T amplitude DEG | "
             "viblin axis AX AY AZ order N amplitude C1..CN phase P1..PN period T | "
             "vibrot origin PX PY PZ axis AX AY AZ order N amplitude C1..CN phase P1..PN period T")

    class Args(StyleArgs):
        # needed: the default only lets a motion written first be named as the wrong word
        mesh: tuple[Literal["mesh"], str] | None = param(None, names="fix mesh/surface ID")
        motion: (tuple[Literal["linear"], float, float, float]
                 | tuple[Literal["linear/variable"], FloatOrVariable, FloatOrVariable, FloatOrVariable]
                 | tuple[Literal["wiggle", "rotate", "rotate/variable", "riggle", "viblin", "vibrot"]]) = param(
            unit={"linear": ("1", "velocity"), "linear/variable": ("1", "velocity")})
        origin: tuple[float, float, float] | None = keyword(None, unit="distance")
        axis: tuple[float, float, float] | None = keyword(None, unit="1")
        order: int | None = keyword(None, unit="1")
        amplitude: tuple[float, ...] | None = keyword(None, unit={
            "wiggle": "distance", "riggle": "degrees", "viblin": "distance", "vibrot": "angle"})
        phase: tuple[float, ...] | None = keyword(None, unit="angle")
        period: float | None = keyword(None, unit="time")
        omega: FloatOrVariable | None = keyword(None, unit="angle/time")

    @classmethod
    def check_args(cls, args):
        if args.mesh is None:
            raise ScriptError(f"expected mesh MESH_ID and a motion; usage: {cls.usage}")
        style = args.motion[0]
        needed = MOTION_WORDS[style]
        given = [word for word in ALL_WORDS if getattr(args, word) is not None]
        usage = cls.style_usage(style)
        missing = [word for word in needed if word not in given]
        if missing:
            raise ScriptError(f"{style}: expected keyword {missing[0]}; usage: {usage}")
        extra = [word for word in given if word not in needed]
        if extra:
            raise ScriptError(f"{style} takes no {extra[0]}; usage: {usage}")
        if args.order is not None and not 1 <= args.order <= MAX_ORDER:
            raise ScriptError(f"{style}: order must be from 1 to {MAX_ORDER} (got {args.order})")
        counts = {"wiggle": 3, "riggle": 1, "viblin": args.order, "vibrot": args.order}
        for word in ("amplitude", "phase"):
            values = getattr(args, word)
            if values is not None and len(values) != counts[style]:
                raise ScriptError(f"{style}: {word} needs {counts[style]} value(s) "
                                  f"(got {' '.join(f'{v:g}' for v in values) or 'none'})")
        if args.period is not None and not args.period > 0.0:
            raise ScriptError(f"{style}: period must be > 0 (got {args.period:g})")
        if args.axis is not None:
            unit(args.axis, f"{style} axis")
        variables = {"rotate/variable": [args.omega], "linear/variable": args.motion[1:]}.get(style, ())
        for value in variables:
            if not isinstance(value, VariableRef):
                raise ScriptError(f"{style}: expected a variable v_NAME (got {value:g})")

    @classmethod
    def style_usage(cls, style):
        for part in cls.usage.split(" | "):
            if f" {style} " in f" {part} ":
                return part.replace("fix ID GROUP move/mesh mesh MESH_ID ", "")
        return cls.usage

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        ident = args.mesh[1]
        mesh = sim.fixes.get(ident)
        if mesh is None:
            raise ScriptError(f"fix {ident} is not defined (move/mesh needs a fix mesh/surface ID)")
        if not isinstance(mesh, MeshSurface):
            raise ScriptError(f"fix {ident} ({mesh.name}) is not a mesh/surface: it cannot be moved")
        self.style, *velocity = args.motion
        self.elapsed = 0.0
        self.integrated = np.zeros(3)        # linear/variable: d; rotate/variable: [angle, 0, 0]
        self.rate = np.zeros(3)
        if self.style == "linear":
            self.velocity = np.array(velocity, dtype=float)
        elif self.style == "linear/variable":
            self.velocity_variables = velocity
        elif self.style == "rotate/variable":
            self.omega_variable = args.omega
        if args.period is not None:
            self.omega = 2.0 * math.pi / args.period
        if args.origin is not None:
            self.origin = np.array(args.origin)
        if args.axis is not None:
            self.axis = unit(args.axis, f"{self.style} axis")
        if self.style == "wiggle":
            self.amplitude = np.array(args.amplitude)
        elif self.style == "riggle":
            self.angle_amplitude = math.radians(args.amplitude[0])
        elif self.style in ("viblin", "vibrot"):
            self.order = args.order
            self.coefficients = np.array(args.amplitude)
            self.phases = np.array(args.phase)
            self.direction = self.axis
        self.mesh = mesh
        mesh.add_mover(self)

    # ---- the motion now ----
    def _series_value(self, t):
        k = np.arange(1, self.order + 1)
        phase = k * self.omega * t + self.phases
        return (float(np.sum(self.coefficients * np.cos(phase))),
                float(-np.sum(self.coefficients * k * self.omega * np.sin(phase))))

    def pose(self):
        """(R, d, dR/dt, dd/dt) of this motion at its clock."""
        t = self.elapsed
        still, zero = STILL, NO_TURN
        style = self.style
        if style == "linear":
            return still, self.velocity * t, zero, self.velocity.copy()
        if style == "rotate":
            return turn_about(self.axis, self.origin, self.omega * t, self.omega)
        if style in TURNS:
            return turn_about(self.axis, self.origin, self.integrated[0], self.rate[0])
        return still, self.integrated.copy(), zero, self.rate.copy()

    def _oscillation_rate(self, t):
        """The velocity (wiggle, viblin) or [angular velocity, 0, 0] (riggle, vibrot) at time t."""
        style = self.style
        if style == "wiggle":
            return self.amplitude * self.omega * math.cos(self.omega * t)
        if style == "riggle":
            return np.array([self.angle_amplitude * self.omega * math.cos(self.omega * t), 0.0, 0.0])
        rate = self._series_value(t)[1]
        return self.direction * rate if style == "viblin" else np.array([rate, 0.0, 0.0])

    def _advance(self, sim):
        dt = sim.dt
        if self.style == "linear/variable":
            self.rate = np.array([sim.evaluate(ref) for ref in self.velocity_variables], dtype=float)
            if not np.isfinite(self.rate).all():
                raise ScriptError(f"fix {self.id} (move/mesh): a velocity variable is not finite "
                                  f"({self.rate.tolist()})")
            self.integrated = self.integrated + self.rate * dt
        elif self.style == "rotate/variable":
            rate = float(sim.evaluate(self.omega_variable))
            if not math.isfinite(rate):
                raise ScriptError(f"fix {self.id} (move/mesh): omega variable is not finite ({rate})")
            self.rate = np.array([rate, 0.0, 0.0])
            self.integrated = self.integrated + self.rate * dt
        elif self.style in OSCILLATIONS:
            self.rate = self._oscillation_rate(self.elapsed + dt)
            self.integrated = self.integrated + self.rate * dt
        self.elapsed += dt

    # ---- hooks: the last motion of a mesh places it once all have advanced ----
    def setup(self, sim):
        if self.mesh.movers and self.mesh.movers[-1] is self:
            self.mesh.place()

    def initial_integrate(self, sim):
        self._advance(sim)
        if self.mesh.movers[-1] is self:
            self.mesh.place()

    # ---- unfix: the mesh stays where this motion took it ----
    def removed(self, sim):
        """LIGGGHTS leaves the mesh where it is; a motion defined later starts from there (a rotation
        turns the moved mesh, not the mesh as read)."""
        if self not in self.mesh.movers:
            return
        if len(self.mesh.movers) > 1:
            raise ScriptError(f"fix {self.id} (move/mesh): mesh {self.mesh.id} has other move/mesh fixes "
                              f"({', '.join(m.id for m in self.mesh.movers if m is not self)}) moving it at once: unfixing "
                              "one of several is not supported")
        self.mesh.settle()

    # ---- restart files ----
    def state(self):
        return {"elapsed": self.elapsed, "integrated": self.integrated, "rate": self.rate}

    def restore(self, state):
        self.elapsed = float(state["elapsed"])
        self.integrated = np.asarray(state["integrated"], dtype=float)
        self.rate = np.asarray(state["rate"], dtype=float)
        if self.mesh.movers[-1] is self:
            self.mesh.place()
