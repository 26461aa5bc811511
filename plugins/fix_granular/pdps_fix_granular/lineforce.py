r"""Fix ``lineforce``: only the force along a line is kept, so the group moves along it (LAMMPS's fix
lineforce).

.. math::  \mathbf{F}_i \leftarrow (\mathbf{F}_i\cdot\hat{\mathbf{d}})\,\hat{\mathbf{d}}, \qquad
           \hat{\mathbf{d}} = \mathbf{d}/|\mathbf{d}|

with :math:`\mathbf{d}` = (X, Y, Z) the line's direction (dimensionless; only its direction counts).
Particles starting with velocity off the line keep that part of it (the fix changes forces, not
velocities). Applied in ``post_force``, at setup and in each minimization step.

Syntax::

    fix ID GROUP lineforce X Y Z

Example::

    fix hold boundary lineforce 0.0 0.0 1.0
"""

import numpy as np

from pdps_core.api import ScriptError, StyleArgs, param

from ._common import ForceFix


def unit_direction(args, what):
    direction = np.array([args.x, args.y, args.z], dtype=np.float64)
    length = float(np.sqrt(direction @ direction))
    if length == 0.0:
        raise ScriptError(f"fix {what}: the direction 0 0 0 has no length")
    return direction / length


class FixLineForce(ForceFix):
    name = "lineforce"
    usage = "fix ID GROUP lineforce X Y Z"

    class Args(StyleArgs):
        x: float = param(unit="dimensionless")
        y: float = param(unit="dimensionless")
        z: float = param(unit="dimensionless")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.direction = unit_direction(args, self.name)

    def post_force(self, sim):
        p = sim.particles
        selected = sim.groups.select(sim, self.group)
        f = p.f[: p.nlocal]
        along = f[selected] @ self.direction
        f[selected] = along[:, None] * self.direction
