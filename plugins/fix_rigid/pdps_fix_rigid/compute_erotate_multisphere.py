r"""Compute ``erotate/multisphere``: the rotational kinetic energy of the bodies of the fix multisphere
(LIGGGHTS's compute erotate/multisphere):

.. math::  E = \tfrac12 \sum_B \sum_{k=1}^3 I_{B,k}\, w_{B,k}^2, \qquad w_{B,k} = \mathbf{L}_B\cdot\mathbf{e}_{B,k} / I_{B,k}

I_{B,k} the principal moments of body B's template, e_{B,k} its principal axes, L_B its angular
momentum. As LIGGGHTS's source does, the sum is not multiplied by ``mvv2e`` (the same in si and
lj units; real or metal units would need it). A global scalar, extensive; its group is not used.

Syntax::

    compute ID GROUP erotate/multisphere

Example::

    compute rms all erotate/multisphere
    thermo_style custom step atoms c_rms
"""

from pdps_core.api import Compute

from .compute_ke_multisphere import multisphere_fix


class ComputeERotateMultisphere(Compute):
    name = "erotate/multisphere"
    usage = "compute ID GROUP erotate/multisphere"
    extensive = True

    def init_run(self, sim):
        multisphere_fix(sim, self)

    def scalar(self, sim):
        return multisphere_fix(sim, self).rotational_energy(sim)
