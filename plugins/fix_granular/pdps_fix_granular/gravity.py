r"""Fix ``gravity``: the same acceleration on every particle of a group, along any direction
(LAMMPS's and LIGGGHTS's fix gravity).

.. math::  \mathbf{F}_i \mathrel{+}= m_i\, g\, \hat{\mathbf{n}}, \qquad
           \hat{\mathbf{n}} = \mathbf{n} / |\mathbf{n}|

:math:`m_i` is the per-particle mass (``rmass``) when present, else the type's mass; :math:`g` the
magnitude. The direction :math:`\hat{\mathbf{n}}` is

- ``vector X Y Z``: the vector normalised (only its direction matters; in 2-d its z is ignored);
- ``chute ANGLE``: tilted by ANGLE degrees towards +x from -z (3-d) or -y (2-d):
  :math:`(\sin\theta, 0, -\cos\theta)`, in 2-d :math:`(\sin\theta, -\cos\theta, 0)`;
- ``spherical PHI THETA``: :math:`\phi` from +x, :math:`\theta` from +z (3-d), in degrees:
  :math:`(\sin\theta\cos\phi, \sin\theta\sin\phi, \cos\theta)`; in 2-d :math:`\theta` is measured
  from +y in the xy plane, :math:`(\sin\theta, \cos\theta, 0)`, and :math:`\phi` is ignored.

Unlike ``fix addforce``, the force is proportional to mass. Applied in ``post_force`` and at setup,
so the first step feels it. The spheres of a ``fix multisphere``'s bodies feel none: that fix
applies M g to each body (LIGGGHTS's fix gravity skips them too). Variables (``v_name``) are not supported for the values.

Parameters:

- ``MAGNITUDE``: acceleration g (force/mass units); negative reverses the direction.
- ``vector X Y Z`` | ``chute ANGLE`` | ``spherical PHI THETA``: the direction (angles in degrees).

Syntax::

    fix ID GROUP gravity MAGNITUDE vector X Y Z
    fix ID GROUP gravity MAGNITUDE chute ANGLE
    fix ID GROUP gravity MAGNITUDE spherical PHI THETA
    ... [disable]

- ``disable`` (LAMMPS's): the particles feel nothing; the fix only holds the acceleration for the
  styles that read it (fix rigid/small's and rigid's ``gravity FIX_ID``, fix pour's schedule).

Examples::

    fix grav all gravity 9.81 vector 0 0 -1
    fix 1 all gravity 1.0 chute 24.0
"""

import math
from typing import Literal

import numpy as np
from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, param

from ._common import NO_RMASS, add_weight, add_weight_unbound

def direction(style, values, dimension):
    """Unit vector of the acceleration for a style and its values (angles in degrees)."""
    if style == "chute":
        angle = math.radians(values[0])
        if dimension == 2:
            return np.array([math.sin(angle), -math.cos(angle), 0.0])
        return np.array([math.sin(angle), 0.0, -math.cos(angle)])
    if style == "spherical":
        phi, theta = math.radians(values[0]), math.radians(values[1])
        if dimension == 2:
            return np.array([math.sin(theta), math.cos(theta), 0.0])
        return np.array([math.sin(theta) * math.cos(phi), math.sin(theta) * math.sin(phi), math.cos(theta)])
    vector = np.array(values, dtype=float)
    if dimension == 2:
        vector[2] = 0.0
    length = float(np.linalg.norm(vector))
    if length == 0.0:
        plane = " in the xy plane (z is ignored in 2-d)" if dimension == 2 else ""
        raise ScriptError(f"gravity vector {' '.join(f'{c:g}' for c in values)} has no direction{plane}")
    return vector / length


class FixGravity(Fix):
    name = "gravity"
    minimize_idle = True         # LAMMPS's fix gravity has no min_post_force (recorded: a minimization ignores it)
    usage = "fix ID GROUP gravity MAGNITUDE vector X Y Z | chute ANGLE | spherical PHI THETA [disable]"

    class Args(StyleArgs):
        magnitude: float = param(unit="acceleration")
        direction: (tuple[Literal["vector"], float, float, float] | tuple[Literal["chute"], float]
                    | tuple[Literal["spherical"], float, float]) = param(
            unit={"vector": "dimensionless", "chute": "degrees", "spherical": "degrees"})
        disable: tuple[()] | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.direction = direction(args.direction[0], args.direction[1:], sim.dimension)
        self.acceleration = tuple(float(c) for c in args.magnitude * self.direction)
        self.bound = None

    def extract(self, name):
        """"gvec": the acceleration (3,), as LAMMPS's fix gravity gives it to fix rigid's gravity keyword."""
        return self.acceleration if name == "gvec" else None

    def setup(self, sim):
        if self.args.disable is not None:
            return
        # spheres of rigid clumps, whose weight their fix applies to the bodies (fix multisphere's)
        self.bound = next((name for fix in sim.fixes.values() if fix is not self
                           and (name := fix.extract("clump_body")) is not None), None)
        self.post_force(sim)

    def post_force(self, sim):
        if self.args.disable is not None:
            return
        p = sim.particles
        a = p.arrays
        ax, ay, az = self.acceleration
        if self.bound is not None:
            add_weight_unbound(a["f"], a["type"], sim.mass, a.get("rmass", NO_RMASS), a["mask"],
                               sim.groups.bit(self.group), a[self.bound], p.nlocal, ax, ay, az)
            return
        add_weight(a["f"], a["type"], sim.mass, a.get("rmass", NO_RMASS), a["mask"], sim.groups.bit(self.group),
                   p.nlocal, ax, ay, az)
