r"""Compute ``ke/multisphere``: the translational kinetic energy of the bodies of the fix multisphere
(LIGGGHTS's compute ke/multisphere):

.. math::  E = \tfrac12 \sum_B M_B V_B^2

in energy units (times ``mvv2e``), over the bodies present (its group is not used, as in
LIGGGHTS). A global scalar, extensive. Thermo's ``ke`` and ``compute ke`` give the same for a scene
of clumps alone: they count each body once, by its centre of mass (``pdps doc fix multisphere``).

Syntax::

    compute ID GROUP ke/multisphere

Example::

    fix integr all multisphere
    compute kms all ke/multisphere
    thermo_style custom step atoms c_kms
"""

from pdps_core.api import Compute, ScriptError

from .multisphere import FixMultisphere


def multisphere_fix(sim, compute):
    """The fix multisphere (one at most)."""
    fix = next((f for f in sim.fixes.values() if isinstance(f, FixMultisphere)), None)
    if fix is None:
        raise ScriptError(f"compute {compute.id} ({compute.name}): fix multisphere does not exist")
    return fix


class ComputeKEMultisphere(Compute):
    name = "ke/multisphere"
    usage = "compute ID GROUP ke/multisphere"
    extensive = True

    def init_run(self, sim):
        multisphere_fix(sim, self)

    def scalar(self, sim):
        return multisphere_fix(sim, self).kinetic_energy(sim)
