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


class DirectionArgs(StyleArgs):
    """X Y Z: a direction (dimensionless; only its direction counts)."""
    x: float = param(unit="dimensionless")
    y: float = param(unit="dimensionless")
    z: float = param(unit="dimensionless")


class DirectionForceFix(ForceFix):
    """A force fix keeping or removing the force along one unit direction (``self.direction``)."""
    Args = DirectionArgs

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        direction = np.array([args.x, args.y, args.z], dtype=np.float64)
        length = float(np.sqrt(direction @ direction))
        if length == 0.0:
            raise ScriptError(f"fix {self.name}: the direction 0 0 0 has no length")
        self.direction = direction / length

    def along(self, sim):
        """(the group's owned forces, their rows, the component of each along the direction)."""
        p = sim.particles
        selected = sim.groups.select(sim, self.group)
        f = p.f[: p.nlocal]
        return f, selected, f[selected] @ self.direction


class FixLineForce(DirectionForceFix):
    name = "lineforce"
    usage = "fix ID GROUP lineforce X Y Z"

    def post_force(self, sim):
        f, selected, along = self.along(sim)
        f[selected] = along[:, None] * self.direction
