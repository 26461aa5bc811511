r"""Fix ``thermal/conductivity``: Muller-Plathe's reverse non-equilibrium heat flux (J. Chem. Phys.
106, 6082 (1997)), as LAMMPS's fix thermal/conductivity.

Every N steps (at the end of the step) the box is cut into NBIN slabs along EDIM; the NSWAP
particles of the group with the largest kinetic energy :math:`\tfrac12 m v^2` in the lowest slab and
the NSWAP with the smallest in the slab just above half height are paired (hottest with coldest) and
each pair exchanges its velocities in its centre-of-mass frame,

.. math::

    \mathbf{v}_\mathrm{cm} = \frac{m_h \mathbf{v}_h + m_c \mathbf{v}_c}{m_h + m_c}, \qquad
    \mathbf{v} \leftarrow 2\mathbf{v}_\mathrm{cm} - \mathbf{v},

an elastic collision: momentum and kinetic energy are conserved exactly, and for equal masses the
two velocities are swapped. The heat driven from the middle slab to the lowest (the kinetic
energy moved, energy units) accumulates in the scalar ``f_ID``; with the temperature gradient it
sets up (fix ave/chunk), :math:`\kappa = -J_z / (\mathrm{d}T/\mathrm{d}z)`, the flux being
:math:`\Delta E / (2 A t)` for a periodic box.

Syntax::

    fix ID GROUP thermal/conductivity N EDIM NBIN [swap NSWAP]

N (steps), EDIM x, y or z, NBIN even and above 2, NSWAP (default 1) pairs per exchange. A particle
outside a periodic box is taken back by one period before its slab is found. Example::

    fix 3 all thermal/conductivity 10 z 20
"""

from typing import Literal

import numpy as np

from pdps_core.api import Fix, StyleArgs, keyword, observables, param

from .muller_plathe import AXES, best, check_slabs, owned_values, slab_members


class FixThermalConductivity(Fix):
    name = "thermal/conductivity"
    usage = "fix ID GROUP thermal/conductivity N EDIM NBIN [swap NSWAP]"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        edim: Literal["x", "y", "z"] = param(...)
        nbin: int = param(unit="1")
        swap: int = keyword(1, ge=1, unit="particles")

    @classmethod
    def check_args(cls, args):
        check_slabs(cls.name, args.nbin)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.dim = AXES.index(args.edim)
        self.exchanged = 0.0

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        p = sim.particles
        n = p.nlocal
        v = p.v[:n]
        mass = observables.masses(sim)
        ke = (v[:, 0] * v[:, 0] + v[:, 1] * v[:, 1] + v[:, 2] * v[:, 2]) * (0.5 * mass)
        low, middle = slab_members(sim, self.group, self.dim, self.args.nbin)
        hot = best(sim, low, -ke[low], self.args.swap)
        cold = best(sim, middle, ke[middle], self.args.swap)
        pairs = min(len(hot), len(cold))
        state = np.column_stack([v, mass])
        hot_state, cold_state = owned_values(sim, hot[:pairs], state), owned_values(sim, cold[:pairs], state)
        swapped = 0.0
        rank = sim.comm.rank
        for k in range(pairs):
            vh, mh = hot_state[k, :3], hot_state[k, 3]
            vc, mc = cold_state[k, :3], cold_state[k, 3]
            vcm = (mc * vc + mh * vh) / (mc + mh)
            # LAMMPS's tally: the energy the cold particle gains less what the hot one gains
            swapped += mc * float(vcm[0] * (vcm[0] - vc[0]) + vcm[1] * (vcm[1] - vc[1]) + vcm[2] * (vcm[2] - vc[2]))
            swapped -= mh * float(vcm[0] * (vcm[0] - vh[0]) + vcm[1] * (vcm[1] - vh[1]) + vcm[2] * (vcm[2] - vh[2]))
            if cold[k, 2] == rank:
                v[int(cold[k, 3])] = 2.0 * vcm - vc
            if hot[k, 2] == rank:
                v[int(hot[k, 3])] = 2.0 * vcm - vh
        self.exchanged += sim.units.mvv2e * swapped

    def scalar(self, sim):
        """The kinetic energy moved from the middle slab to the lowest since the fix was defined."""
        return self.exchanged
