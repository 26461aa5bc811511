r"""Fix ``move/mesh``: a prescribed rigid motion of a ``fix mesh/surface`` (LIGGGHTS's fix move/mesh).

Each style is a rigid motion :math:`\mathbf{X}(t) = R(t)\,\mathbf{X}_0 + \mathbf{d}(t)` of the mesh's
vertices :math:`\mathbf{X}_0` as they were when the fix was defined, with t the time since then
(time units; :math:`\omega = 2\pi/T` for a period T):

- ``linear VX VY VZ``: :math:`\mathbf{X} = \mathbf{X}_0 + \mathbf{V}t` (velocity units).
- ``linear/variable v_VX v_VY v_VZ``: the same with equal-style variables, evaluated each step:
  :math:`\mathbf{d} \mathrel{+}= \mathbf{V}(t)\,\Delta t`.
- ``wiggle amplitude AX AY AZ period T``: :math:`\mathbf{X} = \mathbf{X}_0 + \mathbf{A}\sin\omega t`.
- ``rotate origin PX PY PZ axis AX AY AZ period T``: turns about the axis through P by
  :math:`\omega t` (right-hand rule about the axis).
- ``rotate/variable origin PX PY PZ axis AX AY AZ omega v_W``: turns at the angular velocity of an
  equal-style variable (rad/time): :math:`\varphi \mathrel{+}= W(t)\,\Delta t`.
- ``riggle origin PX PY PZ axis AX AY AZ period T amplitude DEG``: turns to the angle
  :math:`\varphi = A\sin\omega t` (A in degrees).
- ``viblin axis AX AY AZ order n amplitude C1..Cn phase p1..pn period T``:
  :math:`\mathbf{X} = \mathbf{X}_0 + \hat{\mathbf{D}}\sum_{k=1}^n C_k\cos(k\omega t + p_k)` (phases in
  rad), as the manual writes it: the mesh jumps by :math:`\hat{\mathbf{D}}\sum C_k\cos p_k` when the
  run starts unless the phases make that zero (use :math:`p_k = -\pi/2` for a start at rest).
- ``vibrot origin PX PY PZ axis AX AY AZ order n amplitude C1..Cn phase p1..pn period T``: turns
  about the axis through P to the angle :math:`\varphi = \sum_k C_k\cos(k\omega t + p_k)` (rad).

The wall velocity each contact law sees is the time derivative of this motion at the contact point.
Several ``move/mesh`` on one mesh are superposed: each moves in the frame carried along by the ones
defined before it (LIGGGHTS's manual; fix mesh/surface gives the formula). The fix group is not
used. The motions move the vertices in ``initial_integrate``, as LIGGGHTS does; a wall's candidate
triangles are re-listed only once a vertex has moved half the skin since they were listed.

The motion's clock, and what the variable styles have integrated, are saved in restart files.

Syntax::

    fix ID GROUP move/mesh mesh MESH_ID STYLE ARGS

Examples::

    fix shake all move/mesh mesh floor wiggle amplitude 0 0 0.01 period 0.05
    fix stir all move/mesh mesh blade rotate origin 0 0 0 axis 0 0 1 period 2.0
"""

import math

import numpy as np

from pdps_core.api import Fix, MeshSurface, ScriptError, StyleArgs, VariableRef, number

from .mesh import rotation_matrix, unit

MAX_ORDER = 10
STILL, NO_TURN = np.eye(3), np.zeros((3, 3))    # read only: the pose of a translation
STILL.flags.writeable = False
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
        words: list[str]

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        words = list(args.words)
        if len(words) < 3 or words[0] != "mesh":
            raise ScriptError(f"expected mesh MESH_ID and a motion; usage: {self.usage}")
        mesh = sim.fixes.get(words[1])
        if mesh is None:
            raise ScriptError(f"fix {words[1]} is not defined (move/mesh needs a fix mesh/surface ID)")
        if not isinstance(mesh, MeshSurface):
            raise ScriptError(f"fix {words[1]} ({mesh.name}) is not a mesh/surface: it cannot be moved")
        self.style = words[2]
        readers = {"linear": self._linear, "linear/variable": self._linear_variable,
                   "wiggle": self._wiggle, "rotate": self._rotate, "rotate/variable": self._rotate_variable,
                   "riggle": self._riggle, "viblin": self._viblin, "vibrot": self._vibrot}
        if self.style not in readers:
            raise ScriptError(f"motion must be one of {', '.join(readers)} (got {self.style})")
        self.elapsed = 0.0
        self.integrated = np.zeros(3)        # linear/variable: d; rotate/variable: [angle, 0, 0]
        self.rate = np.zeros(3)
        readers[self.style](sim, words[3:])
        self.mesh = mesh
        mesh.add_mover(self)

    # ---- reading the motions ----
    def _expect(self, words, layout):
        """Values of ``layout`` = [(keyword or None, count)], in that order, as lists of words."""
        values, k = [], 0
        keywords = {keyword for keyword, _ in layout if keyword is not None}
        for keyword, count in layout:
            if keyword is not None:
                if k >= len(words) or words[k] != keyword:
                    got = words[k] if k < len(words) else "nothing"
                    raise ScriptError(f"{self.style}: expected keyword {keyword} (got {got}); usage: "
                                      f"{self._style_usage()}")
                k += 1
            chunk = words[k:k + count]
            cut = [w for w in chunk if w in keywords]
            if cut:
                chunk = chunk[:chunk.index(cut[0])]
            if len(chunk) < count:
                raise ScriptError(f"{self.style}: {keyword or 'it'} needs {count} value(s) "
                                  f"(got {' '.join(chunk) or 'none'})")
            values.append(chunk)
            k += count
        if k < len(words):
            raise ScriptError(f"{self.style}: unexpected words {' '.join(words[k:])}; usage: "
                              f"{self._style_usage()}")
        return values

    def _style_usage(self):
        for part in self.usage.split(" | "):
            if part.split()[-1:] and (f" {self.style} " in f" {part} "):
                return part.replace("fix ID GROUP move/mesh mesh MESH_ID ", "")
        return self.usage

    def _period(self, word):
        (period,) = [number(text, f"{self.style} period", representable=True) for text in [word]]
        if not period > 0.0:
            raise ScriptError(f"{self.style}: period must be > 0 (got {word})")
        return period

    def _variables(self, sim, words):
        refs = []
        for word in words:
            if not word.startswith("v_"):
                raise ScriptError(f"{self.style}: expected a variable v_NAME (got {word})")
            refs.append(VariableRef(word[2:]))
        return refs

    def _linear(self, sim, words):
        (v,) = self._expect(words, [(None, 3)])
        self.velocity = np.array([number(text, "linear velocity", representable=True) for text in v])

    def _linear_variable(self, sim, words):
        (v,) = self._expect(words, [(None, 3)])
        self.velocity_variables = self._variables(sim, v)

    def _wiggle(self, sim, words):
        a, t = self._expect(words, [("amplitude", 3), ("period", 1)])
        self.amplitude = np.array([number(text, "wiggle amplitude", representable=True) for text in a])
        self.omega = 2.0 * math.pi / self._period(t[0])

    def _axis_origin(self, origin, axis):
        self.origin = np.array([number(text, f"{self.style} origin", representable=True) for text in origin])
        self.axis = unit([number(text, f"{self.style} axis", representable=True) for text in axis],
                         f"{self.style} axis")

    def _rotate(self, sim, words):
        p, a, t = self._expect(words, [("origin", 3), ("axis", 3), ("period", 1)])
        self._axis_origin(p, a)
        self.omega = 2.0 * math.pi / self._period(t[0])

    def _rotate_variable(self, sim, words):
        p, a, w = self._expect(words, [("origin", 3), ("axis", 3), ("omega", 1)])
        self._axis_origin(p, a)
        self.omega_variable = self._variables(sim, w)[0]

    def _riggle(self, sim, words):
        p, a, t, amplitude = self._expect(words, [("origin", 3), ("axis", 3), ("period", 1),
                                                  ("amplitude", 1)])
        self._axis_origin(p, a)
        self.omega = 2.0 * math.pi / self._period(t[0])
        (degrees,) = [number(text, "riggle amplitude", representable=True) for text in amplitude]
        self.angle_amplitude = math.radians(degrees)

    def _series(self, words, head):
        """The order, amplitudes and phases of viblin and vibrot after their ``head`` words."""
        k = sum(1 + count for _, count in head)
        if len(words) < k + 2 or words[k] != "order":
            got = words[k] if len(words) > k else "nothing"
            raise ScriptError(f"{self.style}: expected keyword order (got {got}); usage: {self._style_usage()}")
        try:
            order = int(words[k + 1])
        except ValueError:
            raise ScriptError(f"{self.style}: order must be a whole number (got {words[k + 1]})") from None
        if not 1 <= order <= MAX_ORDER:
            raise ScriptError(f"{self.style}: order must be from 1 to {MAX_ORDER} (got {order})")
        values = self._expect(words, head + [("order", 1), ("amplitude", order), ("phase", order),
                                             ("period", 1)])
        self.order = order
        self.coefficients = np.array([number(text, f"{self.style} amplitude", representable=True)
                                      for text in values[-3]])
        self.phases = np.array([number(text, f"{self.style} phase", representable=True) for text in values[-2]])
        self.omega = 2.0 * math.pi / self._period(values[-1][0])
        return values

    def _viblin(self, sim, words):
        values = self._series(words, [("axis", 3)])
        self.direction = unit([number(text, "viblin axis", representable=True) for text in values[0]], "viblin axis")

    def _vibrot(self, sim, words):
        values = self._series(words, [("origin", 3), ("axis", 3)])
        self._axis_origin(values[0], values[1])

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
        if style == "linear/variable":
            return still, self.integrated.copy(), zero, self.rate.copy()
        if style == "wiggle":
            return (still, self.amplitude * math.sin(self.omega * t), zero,
                    self.amplitude * self.omega * math.cos(self.omega * t))
        if style == "rotate":
            return turn_about(self.axis, self.origin, self.omega * t, self.omega)
        if style == "rotate/variable":
            return turn_about(self.axis, self.origin, self.integrated[0], self.rate[0])
        if style == "riggle":
            return turn_about(self.axis, self.origin, self.angle_amplitude * math.sin(self.omega * t),
                              self.angle_amplitude * self.omega * math.cos(self.omega * t))
        value, rate = self._series_value(t)
        if style == "viblin":
            return still, self.direction * value, zero, self.direction * rate
        return turn_about(self.axis, self.origin, value, rate)

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
        self.elapsed += dt

    # ---- hooks: the last motion of a mesh places it once all have advanced ----
    def setup(self, sim):
        if self.mesh.movers and self.mesh.movers[-1] is self:
            self.mesh.place()

    def initial_integrate(self, sim):
        self._advance(sim)
        if self.mesh.movers[-1] is self:
            self.mesh.place()

    # ---- restart files ----
    def state(self):
        return {"elapsed": self.elapsed, "integrated": self.integrated, "rate": self.rate}

    def restore(self, state):
        self.elapsed = float(state["elapsed"])
        self.integrated = np.asarray(state["integrated"], dtype=float)
        self.rate = np.asarray(state["rate"], dtype=float)
        if self.mesh.movers[-1] is self:
            self.mesh.place()
