r"""Fix ``indent``: a spherical, cylindrical or planar indenter that pushes the group's particles
away with a cubic potential (LAMMPS's fix indent, by R. Agrawal).

A particle at distance :math:`r` from the centre of a sphere (from the axis of an infinite cylinder)
of radius :math:`R`, and inside it (``side out``, the default: particles outside are pushed away
from its outer surface) or outside it (``side in``: the indenter is a container), feels

.. math::

    F(r) = -K\,(r - R)^2 \quad\text{(away from the surface)}, \qquad E = \tfrac{K}{3}\,|r - R|^3,

and nothing where it does not overlap. A ``plane`` is the same law on one axis: ``lo`` pushes the
particles below the plane up (those above feel nothing), ``hi`` the particles above it down;
``side`` does not apply to it. K is in force/distance² (not scaled by ``units``).

Geometry: the centre of a sphere (x y z), the axis of a cylinder (the two coordinates c1 c2 of the
other axes, in the order x, y, z), the radius R and a plane's position may each be ``v_NAME``, an
equal-style variable evaluated at every force evaluation, so the indenter can move or grow. Numbers
are in lattice spacings with ``units lattice`` (LAMMPS's default; 1 without a lattice command): x, y,
z and a plane by their axis's spacing, the radius by x's; variables are taken as they are, as
LAMMPS. On periodic axes the centre (axis) is wrapped into the box and distances are minimum-image.

Output: ``f_ID`` is the indenter's energy, the sum of E (``fix_modify ID energy yes`` adds it to
``pe`` and to what ``minimize`` minimizes), ``f_ID[1..3]`` in LAMMPS's dialect (``f_ID[0..2]`` in
PDPS's) the force on the indenter, minus the sum of the forces on the particles; both extensive.
The forces act at set-up, in every step's ``post_force`` and at every evaluation of a minimization,
as LAMMPS's.

Where pdps differs: a particle exactly at a sphere's centre (on a cylinder's axis) feels no force,
its energy counted (LAMMPS divides by r = 0). LAMMPS's ``cone`` indenter is not built and is refused.

Syntax (LAMMPS's)::

    fix ID GROUP indent K GEOMETRY [side in|out] [units box|lattice]

    GEOMETRY = sphere x y z R | cylinder x|y|z c1 c2 R | plane x|y|z pos lo|hi

Example::

    variable z equal "10 - 0.01*step*dt"
    fix 1 all indent 10.0 sphere 5 5 v_z 3.0 units box
    fix_modify 1 energy yes
    thermo_style custom step pe f_1 f_1[3]
"""

import math
from typing import Literal

import numpy as np
from numba import njit
from pydantic import model_validator

from pdps_core.api import Fix, FloatOrVariable, ScriptError, StyleArgs, VariableRef, keyword, param

Axis = Literal["x", "y", "z"]
SPHERE = -1


F = FloatOrVariable
Sphere = tuple[Literal["sphere"], F, F, F, F]                         # x y z R
Cylinder = tuple[Literal["cylinder"], Axis, F, F, F]                  # axis c1 c2 R
Plane = tuple[Literal["plane"], Axis, F, Literal["lo", "hi"]]         # axis pos side
Cone = tuple[Literal["cone"], Axis, F, F, F, F, F, F]                 # LAMMPS's, refused


@njit(cache=True)
def _minimum_image(delta, j, box_length, periodic):
    if periodic[j]:
        return delta - box_length[j] * round(delta / box_length[j])
    return delta


@njit(cache=True)
def round_indenter(x, f, mask, groupbit, nlocal, centre, axis, radius, k, outside, box_length, periodic,
                   on_indenter):
    """A sphere (axis -1) or a cylinder along ``axis``: forces added to f; the energy and the force
    on the indenter accumulate into on_indenter (4,)."""
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        dx = 0.0 if axis == 0 else _minimum_image(x[i, 0] - centre[0], 0, box_length, periodic)
        dy = 0.0 if axis == 1 else _minimum_image(x[i, 1] - centre[1], 1, box_length, periodic)
        dz = 0.0 if axis == 2 else _minimum_image(x[i, 2] - centre[2], 2, box_length, periodic)
        r = math.sqrt(dx * dx + dy * dy + dz * dz)
        dr = r - radius if outside else radius - r
        if dr >= 0.0:
            continue
        fmag = k * dr * dr if outside else -k * dr * dr
        on_indenter[0] -= k / 3.0 * dr * dr * dr
        if r == 0.0:
            continue
        fx, fy, fz = dx * fmag / r, dy * fmag / r, dz * fmag / r
        f[i, 0] += fx
        f[i, 1] += fy
        f[i, 2] += fz
        on_indenter[1] -= fx
        on_indenter[2] -= fy
        on_indenter[3] -= fz


@njit(cache=True)
def plane_indenter(x, f, mask, groupbit, nlocal, axis, position, planeside, k, on_indenter):
    """A plane on ``axis`` pushing up the particles below it (planeside -1, lo) or down those above
    it (planeside 1, hi)."""
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        dr = planeside * (position - x[i, axis])
        if dr >= 0.0:
            continue
        push = -planeside * k * dr * dr
        f[i, axis] += push
        on_indenter[0] -= k / 3.0 * dr * dr * dr
        on_indenter[1 + axis] -= push


def _geometry_units(shape):
    kinds = {"sphere": ("1", "distance", "distance", "distance", "distance"),
             "cylinder": ("1", "1", "distance", "distance", "distance"),
             "plane": ("1", "1", "distance", "1"),
             "cone": ("1", "1") + ("distance",) * 6}
    return kinds[shape]


class FixIndent(Fix):
    name = "indent"
    usage = ("fix ID GROUP indent K sphere x y z R | cylinder x|y|z c1 c2 R | plane x|y|z pos lo|hi "
             "[side in|out] [units box|lattice]")
    can_energy = True
    extensive = True

    class Args(StyleArgs):
        k: float = param(ge=0, unit="force/area")
        geometry: Sphere | Cylinder | Plane | Cone = param(
            unit={shape: _geometry_units(shape) for shape in ("sphere", "cylinder", "plane", "cone")})
        side: Literal["in", "out"] = keyword("out")
        units: Literal["box", "lattice"] = keyword("lattice")

        @model_validator(mode="after")
        def _shape(self):
            shape = self.geometry[0]
            if shape == "cone":
                raise ValueError("the cone indenter is not supported (sphere, cylinder and plane are)")
            radius = self.geometry[-1] if shape != "plane" else None
            if isinstance(radius, float) and radius < 0:
                raise ValueError(f"{shape} radius must be >= 0 (got {radius:g})")
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box(f"fix {self.name}")
        shape, *values = args.geometry
        spacing = (np.asarray(sim.lattice.spacing, dtype=float) if args.units == "lattice" and sim.lattice is not None
                   else np.ones(3))

        def scaled(value, axis):
            # numbers are in lattice spacings; variables are taken as they are (LAMMPS's)
            return value if isinstance(value, VariableRef) else value * float(spacing[axis])

        self.shape = shape
        if shape == "sphere":
            self.axis = SPHERE
            self.centre = [scaled(c, axis) for axis, c in enumerate(values[:3])]
        elif shape == "cylinder":
            self.axis = "xyz".index(values[0])
            others = [a for a in range(3) if a != self.axis]
            self.centre = [0.0, 0.0, 0.0]
            self.centre[others[0]] = scaled(values[1], others[0])
            self.centre[others[1]] = scaled(values[2], others[1])
        else:
            self.axis = "xyz".index(values[0])
            self.position = scaled(values[1], self.axis)
            self.planeside = -1.0 if values[2] == "lo" else 1.0
        if shape != "plane":
            self.radius = scaled(values[-1], 0)
        self.outside = args.side == "out"
        self.on_indenter = np.zeros(4)
        self.centre_now = np.zeros(3)
        self.periodic = np.array(sim.box.periodic, dtype=np.bool_)

    def setup(self, sim):
        for value in (getattr(self, "centre", []) + [getattr(self, "radius", None), getattr(self, "position", None)]):
            if isinstance(value, VariableRef):
                if value.name not in sim.variables:
                    raise ScriptError(f"fix {self.id} indent: variable {value.name} is not defined")
                if sim.variables.style(value.name) != "equal":
                    raise ScriptError(f"fix {self.id} indent: variable {value.name} is not equal-style "
                                      f"(got {sim.variables.style(value.name)})")
        self.post_force(sim)

    def min_post_force(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        self.on_indenter[:] = 0.0
        groupbit = sim.groups.bit(self.group)
        if self.shape == "plane":
            plane_indenter(p.x, p.f, p.mask, groupbit, p.nlocal, self.axis, float(sim.evaluate(self.position)),
                           self.planeside, self.args.k, self.on_indenter)
            return
        radius = float(sim.evaluate(self.radius))
        if not radius >= 0.0:
            raise ScriptError(f"fix {self.id} indent: the {self.shape} radius must be >= 0 (got {radius:g} "
                              f"at step {sim.step})")
        box = sim.box
        for j in range(3):
            c = float(sim.evaluate(self.centre[j])) if j != self.axis else float(box.lo[j])
            if self.periodic[j]:
                c = float(box.lo[j]) + (c - float(box.lo[j])) % float(box.length[j])
            self.centre_now[j] = c
        round_indenter(p.x, p.f, p.mask, groupbit, p.nlocal, self.centre_now, self.axis, radius, self.args.k,
                       self.outside, np.asarray(box.length, dtype=float), self.periodic, self.on_indenter)

    def compute_energy(self, sim):
        return float(self.on_indenter[0])

    def scalar(self, sim):
        """The indenter's energy (f_ID), summed over ranks."""
        return float(sim.comm.sum(self.on_indenter[0]))

    def vector(self, sim):
        """The force on the indenter (f_ID[1..3] in LAMMPS's dialect), summed over ranks."""
        return np.array(sim.comm.sum(self.on_indenter[1:].copy()), dtype=float)
