r"""Compute ``msd``: the mean squared displacement of a group, a vector of 4 read as ``c_ID[0]`` ..
``c_ID[3]``.

.. math::

    \mathrm{msd}_d = \frac{1}{N}\sum_{i \in G} \big(x^u_{i,d} - x^0_{i,d}\big)^2 \quad (d = x, y, z),
    \qquad \mathrm{msd} = \mathrm{msd}_x + \mathrm{msd}_y + \mathrm{msd}_z

in distance² units, as LAMMPS's compute msd: ``[0]`` ``[1]`` ``[2]`` are the x, y, z parts and ``[3]``
the total, averaged over the N particles of the group. :math:`\mathbf{x}^u = \mathbf{x} +
\mathbf{n}L` are positions unwrapped through periodic images, so a particle crossing a periodic face
keeps its displacement. :math:`\mathbf{x}^0` is each particle's unwrapped position when the compute
was defined; it is kept per particle (array ``msd_origin_ID``), so it follows its particle through
re-sorting and between ranks, and is saved in restart files. A particle created after the compute
takes its origin the first time the compute is read. An empty group gives 0.

Syntax::

    compute ID GROUP msd

Example::

    compute m all msd
    thermo_style custom step c_m[3]
    analyze 2 all ave/time 10 1 10 c_m[*] file msd.txt
"""

import numpy as np

from pdps_core.api import Compute, observables

from .peratom import unwrapped


class ComputeMSD(Compute):
    name = "msd"
    usage = "compute ID GROUP msd"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        particles = sim.particles
        self.origin_name = f"msd_origin_{id}"
        existed = particles.has(self.origin_name)
        # NaN marks particles created later: they take their origin when first read
        origin = particles.request(self.origin_name, width=3, default=np.nan)
        n = particles.nlocal
        # read_restart re-creates the compute after the particles: restore() puts these back
        self.replaced = (particles.tag[:n].copy(), origin[:n].copy()) if existed else None
        origin[:n] = unwrapped(sim)

    def state(self):
        return {"origin": self.origin_name}

    def restore(self, state):
        """The origins saved with the particles, which __init__ replaced (read_restart)."""
        if self.replaced is None:
            return
        particles = self.sim.particles
        tags, saved = self.replaced
        n = particles.nlocal
        if len(tags) and n:
            order = np.argsort(tags)
            where = np.minimum(np.searchsorted(tags[order], particles.tag[:n]), len(tags) - 1)
            found = tags[order[where]] == particles.tag[:n]
            particles.arrays[self.origin_name][:n][found] = saved[order[where[found]]]
        self.replaced = None

    def vector(self, sim):
        p = sim.particles
        n = p.nlocal
        origin = p.arrays[self.origin_name][:n]
        here = unwrapped(sim)
        late = np.isnan(origin).any(axis=1)
        if late.any():
            origin[late] = here[late]
        chosen = sim.groups.select(sim, self.group)
        squares = sim.comm.sum(((here[chosen] - origin[chosen]) ** 2).sum(axis=0))
        count = observables.count(sim, self.group)
        if count == 0:
            return np.zeros(4)
        squares = np.asarray(squares, dtype=np.float64) / count
        return np.append(squares, squares.sum())
