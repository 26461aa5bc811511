r"""Compute ``msd``: the mean squared displacement of a group, a vector of 4 read as ``c_ID[0]`` ..
``c_ID[3]`` (``c_ID[1]`` .. ``c_ID[4]`` in the LAMMPS dialect).

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

Keywords (LAMMPS's):

- ``com yes``: positions are taken relative to the group's centre of mass (unwrapped, mass-weighted),
  at the definition for the origins and now for the current positions, so a drift of the whole group
  does not count as diffusion.
- ``average yes``: at each evaluation the origin of every particle first becomes the running average
  of its positions over the evaluations so far, this one included (the definition counting as one):
  the msd then measures fluctuations about the mean position (a solid's vibrations). As in LAMMPS,
  the average is over the steps the compute is read (thermo, dumps), once per step. The count of evaluations
  is not saved in restart files (LAMMPS does not either).

Syntax::

    compute ID GROUP msd [com yes|no] [average yes|no]

Example::

    compute m all msd com yes
    thermo_style custom step c_m[3]
    analyze 2 all ave/time 10 1 10 c_m[*] file msd.txt
"""

import numpy as np

from typing import Literal

from pdps_core.api import Compute, StyleArgs, keyword, observables

from .peratom import unwrapped


class KeptOrigins(Compute):
    """A compute that keeps each particle's unwrapped position at its definition (array
    ``ORIGIN_PREFIX_ID``, NaN for particles created later, who take their origin when first read),
    through re-sorting, ranks and restart files (msd, displace/atom)."""
    origin_prefix = "origin"

    def keep_origins(self, sim, here):
        particles = sim.particles
        self.origin_name = f"{self.origin_prefix}_{self.id}"
        existed = particles.has(self.origin_name)
        origin = particles.request(self.origin_name, width=3, default=np.nan)
        n = particles.nlocal
        # read_restart re-creates the compute after the particles: restore() puts these back
        self.replaced = (particles.tag[:n].copy(), origin[:n].copy()) if existed else None
        origin[:n] = here

    def origins(self, sim, here):
        """This rank's origins, the late particles' taken now (``here``: their positions)."""
        origin = sim.particles.arrays[self.origin_name][:sim.particles.nlocal]
        late = np.isnan(origin).any(axis=1)
        if late.any():
            origin[late] = here[late]
        return origin

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


class ComputeMSD(KeptOrigins):
    name = "msd"
    usage = "compute ID GROUP msd [com yes|no] [average yes|no]"
    origin_prefix = "msd_origin"

    class Args(StyleArgs):
        com: Literal["yes", "no"] = keyword("no")
        average: Literal["yes", "no"] = keyword("no")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.com = args.com == "yes"
        self.average = args.average == "yes"
        self.evaluations = 1        # the definition is the first position of the running average
        self.averaged = None        # (step, vector): one update of the averages per step
        self.keep_origins(sim, unwrapped(sim) - self._centre(sim))

    def _centre(self, sim):
        """The group's unwrapped centre of mass with ``com yes``, else 0."""
        if not self.com:
            return np.zeros(3)
        chosen = sim.groups.select(sim, self.group)
        mass = observables.masses(sim, chosen)
        moment = sim.comm.sum(mass @ unwrapped(sim)[chosen])
        total = sim.comm.sum(float(mass.sum()))
        return np.asarray(moment, dtype=np.float64) / total if total > 0 else np.zeros(3)

    def vector(self, sim):
        if self.average and self.averaged is not None and self.averaged[0] == sim.step:
            return self.averaged[1]
        here = unwrapped(sim) - self._centre(sim)
        origin = self.origins(sim, here)
        chosen = sim.groups.select(sim, self.group)
        if self.average:
            origin[chosen] = (origin[chosen] * self.evaluations + here[chosen]) / (self.evaluations + 1)
            self.evaluations += 1
        squares = sim.comm.sum(((here[chosen] - origin[chosen]) ** 2).sum(axis=0))
        count = observables.count(sim, self.group)
        squares = np.asarray(squares, dtype=np.float64) / max(count, 1)
        result = np.append(squares, squares.sum())
        if self.average:
            self.averaged = (sim.step, result)
        return result
