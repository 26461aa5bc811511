r"""Fix ``move``: a group moved on a prescribed path instead of by its forces (LAMMPS's and
LIGGGHTS's fix move).

Each particle keeps its unwrapped position :math:`\mathbf{X}_0` from the fix's definition (a
particle added later, from its first step in the group), and the time :math:`\tau = (n - n_0)\Delta t`
counts from the step :math:`n_0` the fix was defined on. At every step's ``initial_integrate``:

- ``linear VX VY VZ``: :math:`X_d = X_{0,d} + V_d\,\tau`, :math:`v_d = V_d` (velocity units);
- ``wiggle AX AY AZ PERIOD``: :math:`X_d = X_{0,d} + A_d \sin\omega\tau`, :math:`v_d = A_d\,\omega
  \cos\omega\tau`, :math:`\omega = 2\pi/` PERIOD (distance, time);
- ``rotate PX PY PZ RX RY RZ PERIOD``: about the axis :math:`\hat{\mathbf{R}}` through P by the right
  hand, :math:`\mathbf{X} = \mathbf{P} + \mathbf{C} + \mathbf{A}\cos\omega\tau + (\hat{\mathbf{R}}
  \times\mathbf{A})\sin\omega\tau` with :math:`\mathbf{C}` the part of :math:`\mathbf{X}_0 - \mathbf{P}`
  along the axis and :math:`\mathbf{A}` the rest, :math:`\mathbf{v} = \omega\hat{\mathbf{R}}\times
  (\mathbf{X} - \mathbf{P} - \mathbf{C})`; spheres (radius > 0) turn with it, :math:`\boldsymbol
  \omega = \omega\hat{\mathbf{R}}`;
- ``variable V_DX V_DY V_DZ V_VX V_VY V_VZ``: equal- or atom-style variables, each ``v_name`` or
  NULL: with a displacement :math:`X_d = X_{0,d} + \Delta_d`, with a velocity :math:`v_d` is set, with
  only a velocity the particle drifts at it (:math:`x_d \mathrel{+}= \Delta t\,v_d`), with only a
  displacement its velocity is left as it is.

A component given as NULL (and every component a variable leaves NULL) is integrated as fix nve
does it, forces and all. The new position is put at the periodic image nearest the old one (LAMMPS's
remap_near), so image flags stay right. The time origin is a step, as LAMMPS keeps it: after
``reset_timestep`` the path is where that step puts it (measured: LAMMPS's particles jump there
too). ``units lattice`` (LAMMPS's default; LIGGGHTS 3.8.0's default is box, measured; its manual says lattice) scales
VX..VZ, AX..AZ and P by the lattice spacings (1 without a lattice command: LAMMPS's lattice none
1.0); ``units box`` takes them as distances. The PDPS dialect's
default is box, as for its regions.

Syntax::

    fix ID GROUP move linear VX VY VZ [units box|lattice]
    fix ID GROUP move wiggle AX AY AZ PERIOD [units box|lattice]
    fix ID GROUP move rotate PX PY PZ RX RY RZ PERIOD [units box|lattice]
    fix ID GROUP move variable V_DX V_DY V_DZ V_VX V_VY V_VZ [units box|lattice]

Example::

    fix 2 lid move wiggle 0.0 0.0 1.0 1.0 units box
    fix 3 drum move rotate 0 0 0 0 0 1 5.0 units box
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param

NO_RMASS = np.zeros(0)
NO_OMEGA = np.zeros((0, 3))
# how a component moves: by its forces (fix nve), or with its position and/or velocity prescribed
FREE, POSITION, VELOCITY, BOTH = 0, 1, 2, 3


@njit(cache=True)
def _nearest_image(x, old, length, periodic):
    for d in range(3):
        if periodic[d]:
            x[d] -= length[d] * round((x[d] - old[d]) / length[d])


@njit(cache=True)
def move_initial(x, v, f, type_, mass, rmass, mask, groupbit, nlocal, dt, ftm2v, origin, shift, speed, how,
                 length, periodic):
    """One step's positions and velocities: per component, ``how`` says what is prescribed
    (``origin + shift``, ``speed``) and what integrates as fix nve."""
    half = 0.5 * dt * ftm2v
    with_rmass = len(rmass) > 0
    old = np.empty(3)
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        dtfm = half / (rmass[i] if with_rmass else mass[type_[i]])
        for d in range(3):
            old[d] = x[i, d]
            kind = how[d]
            if kind == FREE:
                v[i, d] += dtfm * f[i, d]
                x[i, d] += dt * v[i, d]
            elif kind == VELOCITY:
                v[i, d] = speed[i, d]
                x[i, d] += dt * v[i, d]
            else:
                x[i, d] = origin[i, d] + shift[i, d]
                if kind == BOTH:
                    v[i, d] = speed[i, d]
        _nearest_image(x[i], old, length, periodic)


@njit(cache=True)
def rotate_initial(x, v, omega, radius, mask, groupbit, nlocal, origin, point, axis, rate, angle, length,
                   periodic):
    cosine, sine = math.cos(angle), math.sin(angle)
    spin = len(omega) > 0
    old = np.empty(3)
    disp = np.empty(3)
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        along = 0.0
        for d in range(3):
            along += (origin[i, d] - point[d]) * axis[d]
        a0 = origin[i, 0] - point[0] - along * axis[0]
        a1 = origin[i, 1] - point[1] - along * axis[1]
        a2 = origin[i, 2] - point[2] - along * axis[2]
        b0 = axis[1] * a2 - axis[2] * a1
        b1 = axis[2] * a0 - axis[0] * a2
        b2 = axis[0] * a1 - axis[1] * a0
        disp[0], disp[1], disp[2] = a0 * cosine + b0 * sine, a1 * cosine + b1 * sine, a2 * cosine + b2 * sine
        for d in range(3):
            old[d] = x[i, d]
            x[i, d] = point[d] + along * axis[d] + disp[d]
        v[i, 0] = rate * (axis[1] * disp[2] - axis[2] * disp[1])
        v[i, 1] = rate * (axis[2] * disp[0] - axis[0] * disp[2])
        v[i, 2] = rate * (axis[0] * disp[1] - axis[1] * disp[0])
        if spin and radius[i] > 0.0:
            for d in range(3):
                omega[i, d] = rate * axis[d]
        _nearest_image(x[i], old, length, periodic)


@njit(cache=True)
def move_final(v, f, type_, mass, rmass, mask, groupbit, nlocal, dt, ftm2v, how):
    half = 0.5 * dt * ftm2v
    with_rmass = len(rmass) > 0
    for i in range(nlocal):
        if mask[i] & groupbit:
            dtfm = half / (rmass[i] if with_rmass else mass[type_[i]])
            for d in range(3):
                if how[d] == FREE:
                    v[i, d] += dtfm * f[i, d]


@njit(cache=True)
def keep_origins(origin, x, image, length, mask, groupbit, nlocal):
    """The unwrapped position of every group member that has none yet (column 3 flags it)."""
    for i in range(nlocal):
        if mask[i] & groupbit and origin[i, 3] == 0.0:
            for d in range(3):
                origin[i, d] = x[i, d] + image[i, d] * length[d]
            origin[i, 3] = 1.0


Component = float | Literal["NULL"]
Name = str | Literal["NULL"]


class FixMove(Fix):
    name = "move"
    time_integrate = True
    usage = ("fix ID GROUP move linear VX VY VZ | wiggle AX AY AZ PERIOD | rotate PX PY PZ RX RY RZ PERIOD | "
             "variable V_DX V_DY V_DZ V_VX V_VY V_VZ [units box|lattice]")

    class Args(StyleArgs):
        motion: (tuple[Literal["linear"], Component, Component, Component]
                 | tuple[Literal["wiggle"], Component, Component, Component, float]
                 | tuple[Literal["rotate"], float, float, float, float, float, float, float]
                 | tuple[Literal["variable"], Name, Name, Name, Name, Name, Name]) = param(
            unit={"linear": "velocity", "wiggle": ("distance", "distance", "distance", "time"),
                  "rotate": ("distance", "distance", "distance", "1", "1", "1", "time"), "variable": "1"})
        units: Literal["box", "lattice"] | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box("fix move")
        self.style, *values = args.motion
        units = args.units or sim.dialect.region_units
        scale = np.ones(3)
        if units == "lattice" and self.style != "variable" and sim.lattice is not None:
            # without a lattice command LAMMPS's lattice is "none 1.0": a scale of 1 (measured)
            scale = np.asarray(sim.lattice.spacing, dtype=np.float64)
        self.how = np.zeros(3, dtype=np.int64)
        self.rate = 0.0
        if self.style in ("linear", "wiggle"):
            given = [value != "NULL" for value in values[:3]]
            self.amount = np.array([float(value) if ok else 0.0 for value, ok in zip(values[:3], given)]) * scale
            self.how[:] = [BOTH if ok else FREE for ok in given]
            if self.style == "wiggle":
                self.rate = 2.0 * math.pi / self._period(values[3])
        elif self.style == "rotate":
            self.point = np.array(values[:3], dtype=np.float64) * scale
            axis = np.array(values[3:6], dtype=np.float64)
            if not np.linalg.norm(axis) > 0.0:
                raise ScriptError("the rotation axis RX RY RZ has zero length")
            self.axis = axis / np.linalg.norm(axis)
            self.rate = 2.0 * math.pi / self._period(values[6])
            self.how[:] = BOTH
        else:
            self.names = [None if value == "NULL" else self._variable(sim, value) for value in values]
            for d in range(3):
                shift, speed = self.names[d] is not None, self.names[3 + d] is not None
                self.how[d] = BOTH if shift and speed else POSITION if shift else VELOCITY if speed else FREE
        if sim.dimension == 2 and self._moves_z():
            raise ScriptError(f"fix move {self.style} cannot move along z in a 2-d run")
        self.time_origin = sim.step
        self.origin_name = f"move_origin_{id}"
        sim.particles.request(self.origin_name, width=4, ghost=False)
        self.shift = self.speed = np.zeros((0, 3))
        self.periodic = np.zeros(3, dtype=np.bool_)
        self._keep_origins(sim)

    def reset_dt(self, sim):
        # the path's time is (n - n0) dt: a step changing mid-run would move it (LAMMPS refuses too)
        raise ScriptError(f"fix {self.id} move: the time step cannot change during a run with fix move "
                          "(LAMMPS's and LIGGGHTS's fix move refuse it too: their source)")

    def setup(self, sim):
        self.periodic = np.array(sim.box.periodic, dtype=np.bool_)     # fixed within a run

    @staticmethod
    def _period(value):
        if not value > 0:
            raise ScriptError(f"PERIOD must be > 0 (got {value:g})")
        return value

    @staticmethod
    def _variable(sim, word):
        if not word.startswith("v_"):
            raise ScriptError(f"fix move variable takes v_NAME or NULL (got {word})")
        name = word[2:]
        if name not in sim.variables:
            raise ScriptError(f"variable {name} is not defined ({word})")
        if sim.variables.style(name) not in ("equal", "atom"):
            raise ScriptError(f"variable {name} is {sim.variables.style(name)}-style: fix move takes equal- "
                              "or atom-style variables")
        return name

    def _moves_z(self):
        if self.style == "rotate":
            return bool(self.axis[0] or self.axis[1])
        if self.style == "variable":
            return self.how[2] != FREE
        return bool(self.how[2] and self.amount[2])

    def _keep_origins(self, sim):
        p = sim.particles
        keep_origins(p.arrays[self.origin_name], p.x, p.image, sim.box.length, p.mask, sim.groups.bit(self.group),
                     p.nlocal)

    def _buffers(self, n):
        if len(self.shift) < n:
            self.shift, self.speed = np.zeros((2 * n + 16, 3)), np.zeros((2 * n + 16, 3))
        return self.shift[:n], self.speed[:n]

    def _fill(self, sim, tau, n):
        """This step's displacements and velocities of the prescribed components."""
        shift, speed = self._buffers(n)
        if self.style == "linear":
            shift[:] = self.amount * tau
            speed[:] = self.amount
        elif self.style == "wiggle":
            shift[:] = self.amount * math.sin(self.rate * tau)
            speed[:] = self.amount * self.rate * math.cos(self.rate * tau)
        else:
            for k, name in enumerate(self.names):
                if name is None:
                    continue
                target, d = (shift, k) if k < 3 else (speed, k - 3)
                if sim.variables.style(name) == "atom":
                    target[:, d] = sim.variables.atom_values(name)[:n]
                else:
                    target[:, d] = sim.variables.value(name)
        return shift, speed

    def initial_integrate(self, sim):
        p = sim.particles
        self._keep_origins(sim)
        a, n = p.arrays, p.nlocal
        tau = (sim.step - self.time_origin) * sim.dt
        length, periodic = sim.box.length, self.periodic
        origin = a[self.origin_name]
        if self.style == "rotate":
            omega = a["omega"] if p.has("omega") else NO_OMEGA
            radius = a["radius"] if p.has("radius") else NO_RMASS
            rotate_initial(a["x"], a["v"], omega, radius, a["mask"], sim.groups.bit(self.group), n, origin,
                           self.point, self.axis, self.rate, self.rate * tau, length, periodic)
            return
        shift, speed = self._fill(sim, tau, n)
        move_initial(a["x"], a["v"], a["f"], a["type"], sim.mass, a.get("rmass", NO_RMASS), a["mask"],
                     sim.groups.bit(self.group), n, sim.dt, sim.units.ftm2v, origin, shift, speed, self.how,
                     length, periodic)

    def final_integrate(self, sim):
        if self.style == "rotate":
            return
        a = sim.particles.arrays
        move_final(a["v"], a["f"], a["type"], sim.mass, a.get("rmass", NO_RMASS), a["mask"],
                   sim.groups.bit(self.group), sim.particles.nlocal, sim.dt, sim.units.ftm2v, self.how)

    def state(self):
        """A restart keeps the time origin (LAMMPS's); the origins are a per-atom array."""
        return {"time_origin": self.time_origin}

    def restore(self, state):
        self.time_origin = int(state["time_origin"])
