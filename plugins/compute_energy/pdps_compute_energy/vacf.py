r"""Compute ``vacf``: the velocity autocorrelation function of a group (LAMMPS's compute vacf), a
vector of four values ``c_ID[1..4]`` (LAMMPS dialect; 0..3 in PDPS's):

.. math::

    \frac{1}{N}\sum_{i \in G} v_{i,x}(0) v_{i,x}(t), \quad \ldots y, \quad \ldots z, \quad
    \frac{1}{N}\sum_{i \in G} \mathbf{v}_i(0)\cdot\mathbf{v}_i(t)

in velocity^2 units, v(0) the velocities when the compute is defined (stored per particle, carried with
it between ranks), N the group's size then. Syntax::

    compute ID GROUP vacf

Example::

    compute c all vacf
    fix 1 all ave/time 1 1 10 c_c[4] file vacf.txt
"""

import numpy as np

from pdps_core.api import Compute


class ComputeVACF(Compute):
    name = "vacf"
    usage = "compute ID GROUP vacf"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        p = sim.particles
        self.store = f"vacf_v0_{id}"
        origin = p.request(self.store, 3)
        n = p.nlocal
        chosen = sim.groups.select(sim, group)
        origin[:n] = np.where(chosen[:, None], p.v[:n], 0.0)
        self.count = int(sim.comm.sum(int(chosen.sum())))

    def vector(self, sim):
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        product = (p.arrays[self.store][:n] * p.v[:n])[chosen]
        local = product.sum(axis=0)
        sums = np.array([float(sim.comm.sum(float(local[d]))) for d in range(3)])
        values = np.array([sums[0], sums[1], sums[2], sums[0] + sums[1] + sums[2]])
        return values / self.count if self.count else values
