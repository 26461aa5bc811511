r"""Fix ``drag``: a force of constant size pulling each particle of the group towards a point
(LAMMPS's and LIGGGHTS's fix drag).

.. math::  \mathbf{F}_i = -F\,\frac{\mathbf{d}_i}{|\mathbf{d}_i|} \quad \text{where } |\mathbf{d}_i| > \delta

with :math:`\mathbf{d}_i` the separation of the particle from the point (X, Y, Z) by minimum image
on periodic axes, a coordinate given as ``NULL`` not counted (the pull is then parallel to that
axis's plane), F the force's magnitude (force units) and :math:`\delta` (distance) the distance
within which no force acts. ``f_ID[1..3]`` (``[0..2]`` in the PDPS dialect) is the total drag force
on the group. Applied in ``post_force`` and at setup.

Syntax::

    fix ID GROUP drag X|NULL Y|NULL Z|NULL F DELTA

Example::

    fix center probe drag 0.0 10.0 NULL 5.0 2.0
"""

import numpy as np

from pdps_core.api import StyleArgs, param

from ._common import ForceFix
from .setforce import Component


class FixDrag(ForceFix):
    name = "drag"
    usage = "fix ID GROUP drag X|NULL Y|NULL Z|NULL F DELTA"

    class Args(StyleArgs):
        x: Component = param(unit="distance")
        y: Component = param(unit="distance")
        z: Component = param(unit="distance")
        force: float = param(unit="force")
        delta: float = param(ge=0, unit="distance")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        point = (args.x, args.y, args.z)
        self.counted = np.array([c is not None for c in point], dtype=np.float64)
        self.point = np.array([0.0 if c is None else c for c in point])
        self.total = np.zeros(3)

    def post_force(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        d = (p.x[:n][chosen] - self.point) * self.counted
        box = sim.box
        for axis in range(3):
            if box.periodic[axis]:
                length = box.length[axis]
                d[:, axis] -= length * np.round(d[:, axis] / length)
        r = np.sqrt((d * d).sum(axis=1))
        far = r > self.args.delta
        pull = np.zeros_like(d)
        pull[far] = (self.args.force / r[far])[:, None] * d[far]
        p.f[:n][chosen] -= pull
        self.total = -pull.sum(axis=0)

    def vector(self, sim):
        return np.asarray(sim.comm.sum(self.total), dtype=np.float64)
