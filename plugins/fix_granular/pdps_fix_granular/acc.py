r"""Fix ``acc``: a constant acceleration along one axis (PDPS manual's fix acc), for gravity or a body
force driving a flow.

.. math::  F_{i,d} \mathrel{+}= m_i\, a

for the particles of the group (and, with ``region``, only those inside the region at that step),
where :math:`d` is the axis x, y or z and :math:`a` the acceleration; a negative value points
against the axis. :math:`m_i` is the per-particle mass (``rmass``) when the particle style has one,
else the type's mass. Applied in ``post_force`` and at setup, so the first step feels it.
``fix gravity`` does the same along any direction.

Parameters:

- ``gravity DIM VALUE``: the axis (x, y or z; not z in 2-d) and the acceleration (force/mass units).
- ``region RID`` (optional): act only on particles inside region RID.

Syntax::

    fix ID GROUP acc gravity DIM VALUE [region RID]

Example::

    fix 2 Al acc gravity z -0.592113 region box2
"""

from pdps_core.api import Fix, StyleArgs, keyword, observables

from ._common import AXES, Axis, chosen, require_plane


class FixAcc(Fix):
    name = "acc"
    minimize_idle = True         # a body force as fix gravity, which LAMMPS leaves out of a minimization
    usage = "fix ID GROUP acc gravity DIM VALUE [region RID]"

    class Args(StyleArgs):
        gravity: tuple[Axis, float] = keyword(..., unit="acceleration")
        region: str | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        require_plane(sim, args.gravity[0], "fix acc gravity")
        if args.region is not None:
            sim.region(args.region)

    def setup(self, sim):
        self.post_force(sim)

    def post_force(self, sim):
        p = sim.particles
        selected = chosen(sim, self.group, self.args.region)
        axis, value = AXES[self.args.gravity[0]], self.args.gravity[1]
        p.f[: p.nlocal, axis][selected] += value * observables.masses(sim, selected)
