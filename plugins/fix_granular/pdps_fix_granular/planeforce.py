r"""Fix ``planeforce``: the force along a plane's normal is removed, so the group moves in the plane
(LAMMPS's fix planeforce).

.. math::  \mathbf{F}_i \leftarrow \mathbf{F}_i - (\mathbf{F}_i\cdot\hat{\mathbf{n}})\,\hat{\mathbf{n}},
           \qquad \hat{\mathbf{n}} = \mathbf{n}/|\mathbf{n}|

with :math:`\mathbf{n}` = (X, Y, Z) the plane's normal (dimensionless; only its direction counts).
Velocities along the normal are kept (the fix changes forces only). Applied in ``post_force``, at
setup and in each minimization step.

Syntax::

    fix ID GROUP planeforce X Y Z

Example::

    fix flat all planeforce 0.0 0.0 1.0
"""

from pdps_core.api import StyleArgs, param

from ._common import ForceFix
from .lineforce import unit_direction


class FixPlaneForce(ForceFix):
    name = "planeforce"
    usage = "fix ID GROUP planeforce X Y Z"

    class Args(StyleArgs):
        x: float = param(unit="dimensionless")
        y: float = param(unit="dimensionless")
        z: float = param(unit="dimensionless")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.normal = unit_direction(args, self.name)

    def post_force(self, sim):
        p = sim.particles
        selected = sim.groups.select(sim, self.group)
        f = p.f[: p.nlocal]
        across = f[selected] @ self.normal
        f[selected] -= across[:, None] * self.normal
