r"""A region's motion: LAMMPS's ``move v_dx v_dy v_dz`` and ``rotate v_theta Px Py Pz Rx Ry Rz``
keywords of the region command (its Region::pretransform, forward_transform, inverse_transform,
rotate, set_velocity and velocity_contact).

The region's shape stands in its own frame; at each use the equal-style variables are evaluated
(displacement :math:`\mathbf{d}`, angle :math:`\theta` in radians) and a point :math:`\mathbf{x}` of
the simulation is taken into that frame by :math:`\mathbf{x}' = R(-\theta)(\mathbf{x} - \mathbf{d})`,
the rotation :math:`R` about the line through :math:`\mathbf{P}` along the unit vector
:math:`\hat{\mathbf{r}} = \mathbf{R}/|\mathbf{R}|` (right-hand rule; a point :math:`\mathbf{y}` goes to
:math:`\mathbf{P} + \mathbf{c} + \mathbf{a}\cos\theta + (\hat{\mathbf{r}}\times\mathbf{a})\sin\theta`
with :math:`\mathbf{c} = ((\mathbf{y}-\mathbf{P})\cdot\hat{\mathbf{r}})\hat{\mathbf{r}}`,
:math:`\mathbf{a} = \mathbf{y} - \mathbf{P} - \mathbf{c}`). A surface point found there comes back by
:math:`R(\theta)\mathbf{y} + \mathbf{d}`: rotated about the original P, then displaced.

The wall velocity (for fix wall/gran/region) is LAMMPS's finite difference over the last step:
:math:`\mathbf{v} = (\mathbf{d}_n - \mathbf{d}_{n-1})/\Delta t`, :math:`\boldsymbol\omega =
\mathbf{R}\,(\theta_n - \theta_{n-1})/\Delta t` (LAMMPS multiplies by the axis as written, not by
its unit vector, so an axis longer than 1 spins the wall's velocity faster than the region turns;
pdps does the same, to LAMMPS's numbers), and at a contact point :math:`\mathbf{x}_c`:
:math:`\mathbf{v}_w = \mathbf{v} + \boldsymbol\omega\times(\mathbf{x}_c - \mathbf{P} - \mathbf{d})`.
The previous values start at 0 when a fix takes the region up (LAMMPS's reset_vel), and are
taken once per step.
"""

import math

import numpy as np
from numba import njit

from .errors import ScriptError


@njit(cache=True)
def rotate_points(x, out, point, runit, angle):
    """LAMMPS's Region::rotate of each row of x by ``angle`` about the line (point, runit), into out."""
    sine = math.sin(angle)
    cosine = math.cos(angle)
    for k in range(x.shape[0]):
        d0 = x[k, 0] - point[0]
        d1 = x[k, 1] - point[1]
        d2 = x[k, 2] - point[2]
        along = d0 * runit[0] + d1 * runit[1] + d2 * runit[2]
        c0 = along * runit[0]
        c1 = along * runit[1]
        c2 = along * runit[2]
        a0 = d0 - c0
        a1 = d1 - c1
        a2 = d2 - c2
        b0 = runit[1] * a2 - runit[2] * a1
        b1 = runit[2] * a0 - runit[0] * a2
        b2 = runit[0] * a1 - runit[1] * a0
        out[k, 0] = point[0] + c0 + (a0 * cosine + b0 * sine)
        out[k, 1] = point[1] + c1 + (a1 * cosine + b1 * sine)
        out[k, 2] = point[2] + c2 + (a2 * cosine + b2 * sine)


@njit(cache=True)
def turn_contacts(x, x_frame, index, distance, normal, point, runit, angle, shift):
    """The contacts found in the region's frame (points x_frame) brought back to the simulation's:
    each contact point rotated by ``angle`` and displaced by ``shift``, the normal made
    (x - point) (1 / distance) with the distance kept (LAMMPS's Region::surface and its nx = dx rinv)."""
    sine = math.sin(angle)
    cosine = math.cos(angle)
    for k in range(len(index)):
        p = index[k]
        r = distance[k]
        y0 = x_frame[p, 0] - normal[k, 0] * r - point[0]
        y1 = x_frame[p, 1] - normal[k, 1] * r - point[1]
        y2 = x_frame[p, 2] - normal[k, 2] * r - point[2]
        along = y0 * runit[0] + y1 * runit[1] + y2 * runit[2]
        c0 = along * runit[0]
        c1 = along * runit[1]
        c2 = along * runit[2]
        a0 = y0 - c0
        a1 = y1 - c1
        a2 = y2 - c2
        b0 = runit[1] * a2 - runit[2] * a1
        b1 = runit[2] * a0 - runit[0] * a2
        b2 = runit[0] * a1 - runit[1] * a0
        s0 = point[0] + c0 + (a0 * cosine + b0 * sine) + shift[0]
        s1 = point[1] + c1 + (a1 * cosine + b1 * sine) + shift[1]
        s2 = point[2] + c2 + (a2 * cosine + b2 * sine) + shift[2]
        if r > 0.0:
            rinv = 1.0 / r
            normal[k, 0] = (x[p, 0] - s0) * rinv
            normal[k, 1] = (x[p, 1] - s1) * rinv
            normal[k, 2] = (x[p, 2] - s2) * rinv


@njit(cache=True)
def contact_velocities(x, index, distance, normal, velocity, omega, centre, out):
    """The wall's velocity at each contact point x - distance normal: velocity + omega x (x_c - centre)."""
    for k in range(len(index)):
        p = index[k]
        c0 = x[p, 0] - normal[k, 0] * distance[k] - centre[0]
        c1 = x[p, 1] - normal[k, 1] * distance[k] - centre[1]
        c2 = x[p, 2] - normal[k, 2] * distance[k] - centre[2]
        out[k, 0] = velocity[0] + omega[1] * c2 - omega[2] * c1
        out[k, 1] = velocity[1] + omega[2] * c0 - omega[0] * c2
        out[k, 2] = velocity[2] + omega[0] * c1 - omega[1] * c0


def variable_name(word, keyword):
    """NAME of a ``v_NAME`` word of move or rotate; None for NULL (move only)."""
    if word == "NULL" and keyword == "move":
        return None
    if not word.startswith("v_") or len(word) == 2:
        allowed = "v_NAME or NULL" if keyword == "move" else "v_NAME"
        raise ScriptError(f"{keyword} takes an equal-style variable, {allowed} (got {word})")
    return word[2:]


class RegionMotion:
    """A region's ``move`` and ``rotate``: its displacement and angle now (``update``), points taken
    into its frame and its contacts back (``to_frame``, ``contacts_back``), its wall velocity."""

    def __init__(self, region_id, move, rotate, scale):
        self.region_id = region_id
        self.scale = np.asarray(scale, dtype=np.float64)
        self.move = None if move is None else [variable_name(word, "move") for word in move]
        self.rotating = rotate is not None
        self.shift, self.theta = np.zeros(3), 0.0
        self.point, self.axis, self.runit = np.zeros(3), np.zeros(3), np.zeros(3)
        if rotate is not None:
            self.angle_variable = variable_name(rotate[0], "rotate")
            self.point = np.array(rotate[1:4], dtype=np.float64) * self.scale
            self.axis = np.array(rotate[4:7], dtype=np.float64)
            length = math.sqrt(float(self.axis @ self.axis))
            if length == 0.0:
                raise ScriptError("rotate needs an axis of length > 0 (got 0 0 0)")
            self.runit = self.axis / length
        self._frame = np.empty((0, 3))
        self.reset_velocity()

    def _value(self, sim, name):
        if name not in sim.variables:
            raise ScriptError(f"region {self.region_id}: variable {name} is not defined")
        if sim.variables.style(name) != "equal":
            raise ScriptError(f"region {self.region_id}: variable {name} is {sim.variables.style(name)}-style, "
                              "not equal-style")
        return float(sim.variables.value(name))

    def update(self, sim):
        """The displacement and angle of the current step (LAMMPS's pretransform)."""
        if self.move is not None:
            for d, name in enumerate(self.move):
                if name is not None:
                    self.shift[d] = self.scale[d] * self._value(sim, name)
        if self.rotating:
            self.theta = self._value(sim, self.angle_variable)

    def to_frame(self, x):
        """The points x (n, 3) in the region's own frame (a buffer kept by the motion)."""
        n = len(x)
        if len(self._frame) < n:
            self._frame = np.empty((n + n // 4 + 16, 3))
        frame = self._frame[:n]
        np.subtract(x, self.shift, out=frame)
        if self.rotating:
            rotate_points(frame, frame, self.point, self.runit, -self.theta)
        return frame

    def contacts_back(self, x, frame, index, distance, normal):
        """Contacts found at the points ``frame`` (to_frame(x)) made the simulation's: a translation
        leaves the normals as they are; a rotation turns them (in place)."""
        if self.rotating and len(index):
            turn_contacts(np.ascontiguousarray(x, dtype=np.float64), frame, index, distance, normal, self.point,
                          self.runit, self.theta, self.shift)

    def reset_velocity(self):
        """LAMMPS's reset_vel: the previous displacement and angle taken as 0."""
        self.previous = np.zeros(4)
        self.velocity, self.omega, self.centre = np.zeros(3), np.zeros(3), np.zeros(3)
        self.velocity_step = None

    def start_run(self):
        """A run begins: the next set_velocity takes its step even if the last run ended on it."""
        self.velocity_step = None

    def set_velocity(self, step, dt):
        """The velocity and spin over the last step (0 at step 0), once per step (LAMMPS's set_velocity)."""
        if self.velocity_step == step:
            return
        self.velocity_step = step
        if self.move is not None:
            self.velocity[:] = (self.shift - self.previous[:3]) / dt if step > 0 else 0.0
            self.previous[:3] = self.shift
        if self.rotating:
            self.centre[:] = self.point + self.shift
            self.omega[:] = (self.theta - self.previous[3]) / dt * self.axis if step > 0 else 0.0
            self.previous[3] = self.theta

    def wall_velocity(self, x, index, distance, normal, out):
        """The wall's velocity at each contact (rows of index, distance, normal) into out."""
        contact_velocities(np.ascontiguousarray(x, dtype=np.float64), index, distance, normal, self.velocity,
                           self.omega, self.centre, out)
