r"""Fix ``numdiff``: every N steps, the force on each particle of the group from a central finite
difference of the system's potential energy, a per-atom array ``f_ID[1..3]`` to compare with the
forces the styles compute (LAMMPS's fix numdiff).

.. math::

    F^\mathrm{num}_{i,a} = -\frac{U(\mathbf{x}_i + \delta\,\hat{e}_a) - U(\mathbf{x}_i - \delta\,\hat{e}_a)}{2\delta}

with U the pair and bond energy of the whole system (every periodic image of particle i moved
alike), on the step's neighbor lists, and :math:`\delta` the displacement (distance). Particles
outside the group read 0. The step's forces and positions are left as they were: the fix only
measures. It costs 6 energy evaluations per particle of the group each time, so choose N large
and the group small; on the steps between, ``f_ID`` keeps its last values.

Syntax::

    fix ID GROUP numdiff NEVERY DELTA

Example (LAMMPS's numdiff example)::

    fix numdiff all numdiff 200 0.0001
    variable errx atom fx-f_numdiff[1]
"""

import numpy as np

from pdps_core.api import Fix, StyleArgs, param


class FixNumDiff(Fix):
    name = "numdiff"
    usage = "fix ID GROUP numdiff NEVERY DELTA"

    class Args(StyleArgs):
        every: int = param(gt=0, unit="timesteps")
        delta: float = param(gt=0, unit="distance")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.column = f"numdiff_{id}"
        sim.particles.request(self.column, width=3, default=0.0, ghost=False)

    def setup(self, sim):
        self.post_force(sim)

    def min_post_force(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        if sim.step % self.args.every == 0:
            self.measure(sim)

    def measure(self, sim):
        p = sim.particles
        n, nall = p.nlocal, p.nlocal + p.nghost
        forces = p.arrays[self.column][:n]
        forces[:] = 0.0
        kept_x, kept_f = p.x[:nall].copy(), p.f[:nall].copy()
        mine = p.tag[:n][sim.groups.select(sim, self.group)]
        tags = np.unique(sim.comm.allgather_rows(mine))
        # every copy of a particle on this rank (owned and ghost images), by id
        order = np.argsort(p.tag[:nall], kind="stable")
        sorted_tags = p.tag[:nall][order]
        for tag in tags:
            lo, hi = np.searchsorted(sorted_tags, tag), np.searchsorted(sorted_tags, tag, side="right")
            rows = order[lo:hi]
            owned = rows[rows < n]
            for axis in range(3):
                p.x[rows, axis] += self.args.delta
                above = sim.interaction_energy()
                p.x[rows, axis] -= 2.0 * self.args.delta
                below = sim.interaction_energy()
                p.x[rows, axis] = kept_x[rows, axis]
                if len(owned):
                    forces[owned, axis] = (below - above) * (0.5 / self.args.delta)
        p.f[:nall] = kept_f

    def peratom(self, sim):
        return sim.particles.arrays[self.column][:sim.particles.nlocal]
