r"""Fix ``momentum``: every N steps, take away the group's centre-of-mass velocity and/or its
angular momentum (LAMMPS's fix momentum).

.. math::

    \mathbf{v}_i \leftarrow \mathbf{v}_i - \frac{\sum_j m_j \mathbf{v}_j}{\sum_j m_j}
    \quad \text{(linear, per flagged axis)}, \qquad
    \mathbf{v}_i \leftarrow \mathbf{v}_i - \boldsymbol{\omega}\times(\mathbf{x}_i - \mathbf{x}_{cm}),
    \ \boldsymbol{\omega} = I^{-1}\mathbf{L} \quad \text{(angular)}

with unwrapped positions. ``rescale`` scales the velocities afterwards so the group's kinetic energy
is what it was before.

Syntax::

    fix ID GROUP momentum N [linear XFLAG YFLAG ZFLAG] [angular] [rescale]

N the interval (steps); at least one of linear (flags 0 or 1) and angular. Example::

    fix drift all momentum 100 linear 1 1 1 angular
"""

from typing import Literal

import numpy as np
from pydantic import model_validator

from pdps_core.api import Fix, StyleArgs, keyword, observables, param

Flag = Literal["0", "1"]


class FixMomentum(Fix):
    name = "momentum"
    usage = "fix ID GROUP momentum N [linear XFLAG YFLAG ZFLAG] [angular] [rescale]"

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        linear: tuple[Flag, Flag, Flag] | None = keyword(None)
        angular: tuple[()] | None = keyword(None)
        rescale: tuple[()] | None = keyword(None)

        @model_validator(mode="after")
        def _something_to_remove(self):
            if self.linear is None and self.angular is None:
                raise ValueError("fix momentum needs linear and/or angular")
            return self

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.linear = None if args.linear is None else np.array([flag == "1" for flag in args.linear])
        self.angular, self.rescale = args.angular is not None, args.rescale is not None

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        v = p.v[:n]
        m = observables.masses(sim, chosen)
        before = observables.kinetic_energy(sim, self.group) if self.rescale else 0.0
        total = sim.comm.sum(float(m.sum()))
        if total <= 0.0:
            return
        if self.linear is not None:
            vcm = sim.comm.sum((m[:, None] * v[chosen]).sum(axis=0)) / total
            v[chosen] -= np.where(self.linear, vcm, 0.0)
        if self.angular:
            x = p.x[:n][chosen] + p.image[:n][chosen] * sim.box.length
            xcm = sim.comm.sum((m[:, None] * x).sum(axis=0)) / total
            d = x - xcm
            angmom = sim.comm.sum((m[:, None] * np.cross(d, v[chosen])).sum(axis=0))
            inertia = sim.comm.sum(np.einsum("i,ij,ik->jk", m, d, d))
            tensor = np.trace(inertia) * np.eye(3) - inertia
            omega = np.linalg.solve(tensor, angmom) if abs(np.linalg.det(tensor)) > 0 else np.zeros(3)
            v[chosen] -= np.cross(omega, d)
        if self.rescale:
            after = observables.kinetic_energy(sim, self.group)
            if after > 0.0:
                v[chosen] *= np.sqrt(before / after)
