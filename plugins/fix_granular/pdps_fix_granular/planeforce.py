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

from .lineforce import DirectionForceFix


class FixPlaneForce(DirectionForceFix):
    name = "planeforce"
    usage = "fix ID GROUP planeforce X Y Z"

    def post_force(self, sim):
        f, selected, across = self.along(sim)
        f[selected] -= across[:, None] * self.direction
