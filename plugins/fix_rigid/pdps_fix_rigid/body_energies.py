"""The kinetic energies of the bodies of a fix rigid (or rigid/small and their variants), shared by
compute ke/rigid and erotate/rigid, as LAMMPS's fix rigid extract_ke and extract_erotational:

.. math::

    E_\\mathrm{trans} = \\sum_B \\tfrac12 M_B V_B^2, \\qquad
    E_\\mathrm{rot} = \\sum_B \\tfrac12 \\sum_{k=1}^3 I_{B,k}\\, \\omega_{B,k}^2, \\quad
    \\omega_{B,k} = \\mathbf{L}_B \\cdot \\mathbf{e}_{B,k} / I_{B,k}

(mass velocity^2; the angular velocity taken in the body frame from the angular momentum L and the
principal axes e_k, a zero moment giving no term). fix rigid keeps every body on every rank; rigid/small
each body on the rank owning it, whose sums are added over the ranks.
"""

import numpy as np

from pdps_core.api import Compute, ScriptError, StyleArgs, param

from .rigid import FixRigid
from .rigid_small import FixRigidSmall


def rigid_fix(sim, compute, fix_id):
    """The fix of rigid bodies ``fix_id`` a compute reads, or a one-line error."""
    fix = sim.fixes.get(fix_id)
    if fix is None:
        raise ScriptError(f"compute {compute.id} ({compute.name}): fix {fix_id} is not defined")
    if not isinstance(fix, (FixRigid, FixRigidSmall)):
        raise ScriptError(f"compute {compute.id} ({compute.name}): fix {fix_id} ({fix.name}) is not a fix of rigid "
                          "bodies (rigid, rigid/small or their variants)")
    return fix


def _bodies(fix):
    """How many of the fix's body rows this rank sums, and whether the ranks' sums are added."""
    if isinstance(fix, FixRigidSmall):
        return (fix.nlocal_body if fix.set_up else 0), True
    return (fix.nbody if fix.set_up else 0), False


def translational(sim, fix):
    """sum 1/2 M V^2 over all bodies (mass velocity^2)."""
    n, spread = _bodies(fix)
    v = fix.vcm[:n]
    local = 0.5 * float(np.sum(fix.masstotal[:n] * np.einsum("ij,ij->i", v, v)))
    return sim.comm.sum(local) if spread else local


def rotational(sim, fix):
    """sum 1/2 sum_k I_k w_k^2 over all bodies, w_k the angular velocity about principal axis k."""
    n, spread = _bodies(fix)
    inertia = fix.inertia[:n]
    total = 0.0
    for axis, moment in zip((fix.ex[:n], fix.ey[:n], fix.ez[:n]), inertia.T):
        projected = np.einsum("ij,ij->i", fix.angmom[:n], axis)
        # L_k^2 / I_k = I_k w_k^2; a zero moment (a linear body's axis) has no rotation about it
        total += float(np.sum(np.divide(projected * projected, moment, out=np.zeros(n), where=moment > 0.0)))
    local = 0.5 * total
    return sim.comm.sum(local) if spread else local


class BodyEnergyCompute(Compute):
    """A global scalar, extensive, of the bodies of fix FIX_ID: ``energy(sim, fix)`` (mass
    velocity^2) times mvv2e. ke/rigid and erotate/rigid name their energy."""
    extensive = True
    energy = None

    class Args(StyleArgs):
        fix_id: str = param()

    def init_run(self, sim):
        rigid_fix(sim, self, self.args.fix_id)

    def scalar(self, sim):
        return type(self).energy(sim, rigid_fix(sim, self, self.args.fix_id)) * sim.units.mvv2e
