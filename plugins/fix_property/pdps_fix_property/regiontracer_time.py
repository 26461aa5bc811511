r"""Fix ``property/atom/regiontracer/time``: each particle's residence time in the simulation and in
a list of regions (LIGGGHTS 3.8.0's fix property/atom/regiontracer/time).

Every step, each particle of the group adds the timestep to its time in the simulation, and to its
time in each region it was found in at the last check: the regions are looked at every
``check_region_every`` steps (at steps that are multiples of it; LIGGGHTS's default 10), and a
particle counts as in a region from one look to the next. So a particle's time in a region is
:math:`\Delta t` times the steps since it was first seen inside, to within ``check_region_every``
steps at each crossing.

Per-atom values (a property named by the fix's ID): without regions one, the time in the
simulation (time units); with N regions N + 2 columns, ``f_ID[1]`` the time in the simulation,
``f_ID[2..N+1]`` the times in the regions in the order given, and ``f_ID[N+2]`` the bitmap of the
regions the particle was last found in (bit k for region k + 1, as LIGGGHTS keeps it).

Global vector ``f_ID[1..N+1]``: the sums of those times over the group divided by the number of
particles in the whole simulation (LIGGGHTS's compute_vector, which so divides however many of them
are in the group or have a time), 0 while no particle of the group has any.

Syntax::

    fix ID GROUP property/atom/regiontracer/time [add_region REGION ...] [check_region_every N]

- ``add_region REGION``: a region to trace, as often as wanted (at most 53, LIGGGHTS's limit);
- ``check_region_every N`` (>= 1 timesteps, default 10).

Example::

    region mixer cylinder z 0 0 0.05 0 0.1 units box
    fix restime all property/atom/regiontracer/time add_region mixer check_region_every 5
    thermo_style custom step f_restime[1] f_restime[2]
"""

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword


@njit(cache=True)
def add_times(data, mask, groupbit, nlocal, dt, inside, look, nregions):
    """Add dt to each group particle's time and to its times in the regions of its bitmap; where
    ``look``, set the bitmap from ``inside`` (nlocal, nregions) first."""
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        data[i, 0] += dt
        if nregions == 0:
            continue
        bits = np.int64(data[i, nregions + 1])
        for k in range(nregions):
            flag = np.int64(1) << k
            if look:
                if inside[i, k]:
                    bits |= flag
                else:
                    bits &= ~flag
            if bits & flag:
                data[i, 1 + k] += dt
        data[i, nregions + 1] = float(bits)


class FixPropertyAtomRegiontracerTime(Fix):
    name = "property/atom/regiontracer/time"
    usage = "fix ID GROUP property/atom/regiontracer/time [add_region REGION ...] [check_region_every N]"

    class Args(StyleArgs):
        add_region: list[str] = keyword([], names="region ID")
        check_region_every: int = keyword(10, ge=1, unit="timesteps")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if len(args.add_region) > 53:
            raise ScriptError(f"at most 53 regions (a bitmap in a double, as LIGGGHTS; got {len(args.add_region)})")
        for region in args.add_region:
            sim.region(region)
        self.regions = list(args.add_region)
        self.width = 1 if not self.regions else len(self.regions) + 2
        self.times = id
        if self.width == 1:
            sim.particles.request(self.times)
        else:
            sim.particles.request(self.times, width=self.width)
        self.no_inside = np.zeros((0, max(1, len(self.regions))), dtype=np.bool_)

    def init_run(self, sim):
        if any(f.extract("clump_body") is not None for f in sim.fixes.values()):
            raise ScriptError(f"fix {self.id} (property/atom/regiontracer/time) may not be used together with fix "
                              "multisphere (as LIGGGHTS)")

    def _data(self, sim):
        data = sim.particles.arrays[self.times]
        return data.reshape(len(data), self.width)

    def end_of_step(self, sim):
        p = sim.particles
        n = p.nlocal
        look = bool(self.regions) and sim.step % self.args.check_region_every == 0
        inside = self.no_inside
        if look:
            inside = np.column_stack([np.asarray(sim.region(r).match(p.x[:n]), dtype=np.bool_)
                                      for r in self.regions])
        add_times(self._data(sim), p.mask, sim.groups.bit(self.group), n, sim.dt, inside, look, len(self.regions))

    def vector(self, sim):
        p = sim.particles
        n = p.nlocal
        data = self._data(sim)[:n, :1 + len(self.regions)]
        chosen = (p.mask[:n] & sim.groups.bit(self.group)) != 0
        sums = np.asarray(sim.comm.sum(data[chosen].sum(axis=0)), dtype=np.float64)
        timed = np.asarray(sim.comm.sum((data[chosen] > 0.0).sum(axis=0)), dtype=np.int64)
        natoms = int(sim.comm.sum(n))
        return np.where(timed > 0, sums / max(natoms, 1), 0.0)

    def peratom(self, sim):
        return sim.particles.arrays[self.times][: sim.particles.nlocal]
