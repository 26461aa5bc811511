r"""Compute ``displace/atom``: each particle's displacement since the compute was defined, four
values per particle (LAMMPS's and LIGGGHTS's compute displace/atom).

.. math::

    \Delta\mathbf{x}_i = \mathbf{x}^u_i - \mathbf{x}^0_i, \qquad |\Delta\mathbf{x}_i|

in distance units: columns ``c_ID[1]`` ``c_ID[2]`` ``c_ID[3]`` the x, y, z parts and ``c_ID[4]`` the
length (``[0]`` .. ``[3]`` in the PDPS dialect); 0 for particles outside the group.
:math:`\mathbf{x}^u = \mathbf{x} + \mathbf{n}L` is the position unwrapped through periodic images,
:math:`\mathbf{x}^0` its value at the definition, kept with each particle as compute msd keeps it
(a particle created later takes its origin the first time the compute is read). Syntax::

    compute ID GROUP displace/atom

Example::

    compute moved all displace/atom
    dump 1 all custom 1000 moved.dump id c_moved[4]
"""

import numpy as np

from .msd import KeptOrigins
from .peratom import unwrapped


class ComputeDisplaceAtom(KeptOrigins):
    name = "displace/atom"
    usage = "compute ID GROUP displace/atom"
    origin_prefix = "displace_origin"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.keep_origins(sim, unwrapped(sim))

    def peratom(self, sim):
        here = unwrapped(sim)
        delta = here - self.origins(sim, here)
        values = np.zeros((len(here), 4))
        chosen = sim.groups.select(sim, self.group)
        values[chosen, :3] = delta[chosen]
        values[chosen, 3] = np.sqrt((delta[chosen] ** 2).sum(axis=1))
        return values
