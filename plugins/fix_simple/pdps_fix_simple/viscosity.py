r"""Fix ``viscosity``: Muller-Plathe's reverse non-equilibrium momentum flux (Phys. Rev. E 59, 4894
(1999)), as LAMMPS's fix viscosity.

Every N steps (at the end of the step) the box is cut into NBIN slabs along PDIM; among the group's
particles the NSWAP of the lowest slab whose velocity component along VDIM is closest to +VTARGET
(and not negative) and the NSWAP of the slab just above half height closest to -VTARGET (and not
positive) are paired in that order, and each pair collides elastically along VDIM, in its centre-of-mass
frame (LAMMPS 22 Jul 2025's rule; for equal masses the two components are swapped):

.. math::

    v_\mathrm{cm} = \frac{m_a v_a + m_b v_b}{m_a + m_b}, \qquad v \leftarrow 2 v_\mathrm{cm} - v.

Total momentum and kinetic energy are conserved exactly, whatever the masses. The momentum the
lowest slab's particles lose to the middle one's, :math:`\sum m_a (v_\mathrm{cm} - v_a) - m_b
(v_\mathrm{cm} - v_b)` (negative: LAMMPS's sign), accumulates in the scalar ``f_ID`` (mass times
velocity); with the velocity profile it sets up (fix ave/chunk), the shear viscosity is
:math:`\eta = -J / (\mathrm{d}v_\mathrm{VDIM}/\mathrm{d}\,\mathrm{PDIM})`, the flux
:math:`\Delta p / (2 A t)` for a periodic box.

Syntax::

    fix ID GROUP viscosity N VDIM PDIM NBIN [swap NSWAP] [vtarget V|INF]

N (steps), VDIM and PDIM x, y or z, NBIN even and above 2, NSWAP (default 1) pairs per exchange,
VTARGET (velocity, default INF: the fastest each way; LAMMPS's 1e10, with the round-off it brings
to the closeness of two velocities). A particle outside a periodic box is taken back by one period
before its slab is found. Example::

    fix 4 all viscosity 100 x y 20
"""

from typing import Literal

import numpy as np
from pydantic import model_validator

from pdps_core.api import Fix, StyleArgs, keyword, observables, param

from .muller_plathe import AXES, best, check_slabs, owned_values, slab_members

# LAMMPS's INF: closeness to it ranks the fastest first
INFINITE_TARGET = 1.0e10


class FixViscosity(Fix):
    name = "viscosity"
    usage = "fix ID GROUP viscosity N VDIM PDIM NBIN [swap NSWAP] [vtarget V|INF]"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        vdim: Literal["x", "y", "z"] = param(...)
        pdim: Literal["x", "y", "z"] = param(...)
        nbin: int = param(unit="1")
        swap: int = keyword(1, ge=1, unit="particles")
        vtarget: Literal["INF"] | float = keyword("INF", unit="velocity")

        @model_validator(mode="after")
        def _positive_target(self):
            if self.vtarget != "INF" and self.vtarget <= 0:
                raise ValueError(f"vtarget must be > 0 or INF (got {self.vtarget:g})")
            return self

    @classmethod
    def check_args(cls, args):
        check_slabs(cls.name, args.nbin)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.vdim, self.pdim = AXES.index(args.vdim), AXES.index(args.pdim)
        self.target = INFINITE_TARGET if args.vtarget == "INF" else float(args.vtarget)
        self.exchanged = 0.0

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        p = sim.particles
        n = p.nlocal
        component = p.v[:n, self.vdim]
        mass = observables.masses(sim)
        low, middle = slab_members(sim, self.group, self.pdim, self.args.nbin)
        low, middle = low[component[low] >= 0.0], middle[component[middle] <= 0.0]
        upward = best(sim, low, np.abs(component[low] - self.target), self.args.swap)
        downward = best(sim, middle, np.abs(component[middle] + self.target), self.args.swap)
        pairs = min(len(upward), len(downward))
        state = np.column_stack([component, mass])
        up, down = owned_values(sim, upward[:pairs], state), owned_values(sim, downward[:pairs], state)
        swapped = 0.0
        rank = sim.comm.rank
        for k in range(pairs):
            (vu, mu), (vd, md) = up[k], down[k]
            vcm = (md * vd + mu * vu) / (md + mu)
            if downward[k, 2] == rank:
                p.v[int(downward[k, 3]), self.vdim] = 2.0 * vcm - vd
            if upward[k, 2] == rank:
                p.v[int(upward[k, 3]), self.vdim] = 2.0 * vcm - vu
            swapped += mu * (vcm - vu) - md * (vcm - vd)
        self.exchanged += swapped

    def scalar(self, sim):
        """The momentum the lowest slab gained from the middle one since the fix was defined."""
        return self.exchanged
