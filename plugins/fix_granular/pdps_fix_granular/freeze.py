r"""Fix ``freeze``: holds a group of particles in place (LAMMPS's and LIGGGHTS's fix freeze).

Every step, after the pair style and the fixes defined before this one have added their forces,

.. math::  \mathbf{F}_i \leftarrow \mathbf{0}, \qquad \mathbf{T}_i \leftarrow \mathbf{0}

(the torque only with ``particle_style sphere``). Velocities are left as they are, as LAMMPS's and
LIGGGHTS's fix freeze leave them (LIGGGHTS 3.8.0's numbers recorded in
plugins/fix_granular/tests/data/liggghts.cases.json, case freeze): a frozen particle that moves at
the start of a run goes on at that velocity, which a warning says; ``velocity GROUP set 0 0 0``
holds it in place. The total force on the group before it was
zeroed (LAMMPS's vector of this fix) is kept in ``total_force``, e.g. the load on a frozen floor.

As LAMMPS, fixes run in script order: a force fix defined after this one acts on frozen particles
again. That is warned about at the start of a run; define ``freeze`` after the force fixes.
Point particles are accepted (only their force is zeroed).

Syntax::

    fix ID GROUP freeze

Example::

    group floor region bottom
    fix 2 floor freeze
"""

import numpy as np

from pdps_core.api import Fix

from ._common import chosen


class FixFreeze(Fix):
    name = "freeze"
    holds_at_rest = True        # granular pair styles read it (Fix.holds_at_rest)
    minimize_idle = True         # LAMMPS's fix freeze has no min_post_force (recorded: a minimization ignores it)
    usage = "fix ID GROUP freeze"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.total_force = np.zeros(3)
        self._warned = set()
        self._told_moving = False

    def setup(self, sim):
        p = sim.particles
        selected = chosen(sim, self.group)
        moving = bool(np.any(p.v[: p.nlocal][selected]))
        if p.has("omega"):
            moving |= bool(np.any(p.omega[: p.nlocal][selected]))
        if sim.comm.max(int(moving)) and not self._told_moving:
            self._told_moving = True
            sim.warn(f"fix {self.id} (freeze) zeroes forces and torques only, as LAMMPS and LIGGGHTS: "
                     f"particles of group {self.group} that move or spin go on doing so "
                     f"(velocity {self.group} set 0 0 0 holds them in place)")
        self._warn_later_forces(sim, selected)
        self.post_force(sim)

    def _warn_later_forces(self, sim, selected):
        fixes = list(sim.fixes.values())
        for later in fixes[fixes.index(self) + 1:]:
            if callable(getattr(type(later), "post_force", None)) and \
                    (selected & chosen(sim, later.group)).any() and later.id not in self._warned:
                self._warned.add(later.id)
                sim.warn(f"fix {later.id} ({later.name}) is defined after fix {self.id} (freeze) and "
                         f"changes forces on its particles after they were zeroed: frozen particles "
                         f"may move (define freeze last)")

    def vector(self, sim):
        """``f_ID[1-3]``: the total force on the group before it was zeroed (LAMMPS's vector)."""
        return self.total_force

    def post_force(self, sim):
        p = sim.particles
        selected = chosen(sim, self.group)
        f = p.f[: p.nlocal]
        self.total_force = sim.comm.sum(f[selected].sum(axis=0))
        f[selected] = 0.0
        if p.has("torque"):
            p.torque[: p.nlocal][selected] = 0.0
