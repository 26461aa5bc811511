r"""Fix ``rigid/nve``: the rigid bodies of fix ``rigid``, integrated with the symplectic splitting of
Miller et al. (NO_SQUISH) in Kamberaj, Low and Neal's quaternion momentum, as LAMMPS's fix rigid/nve.

The body's rotation is carried by the conjugate quaternion momentum p = 2 S(q) (0, L_body), L_body
the angular momentum in the body frame. A step is

.. math::

    V \mathrel{+}= \tfrac{\Delta t}{2M} F, \quad X \mathrel{+}= \Delta t\, V, \quad
    p \mathrel{+}= \Delta t\, S(q) (0, \tau_\mathrm{body}),

then the free rotation split into rotations about the principal axes, 3, 2 for dt/2, 1 for dt, 2, 3
for dt/2, each an exact rotation of (p, q) by the angle dt (p . P_k q) / (4 I_k); after the forces,
V and p take the second half kick. L = R(q) (S(q)^T p)_vec / 2 and omega = I^-1 L set the particles'
velocities. The scheme is time-reversible and symplectic: energy does not drift, where fix
``rigid``'s Richardson iteration drifts slowly (LAMMPS's documentation: "thought to provide better
energy conservation than an iterative approach").

Everything else (body styles, force and torque flags, degrees of freedom, virial, f_ID values) is fix
``rigid``'s: see ``pdps doc fix rigid``.

Syntax::

    fix ID GROUP rigid/nve BODYSTYLE [ARGS] [force M XFLAG YFLAG ZFLAG] [torque M XFLAG YFLAG ZFLAG]
        [reinit yes|no] [infile FILE] [langevin TSTART TSTOP TPERIOD SEED]

Example::

    fix 1 bodies rigid/nve molecule

References: T. F. Miller III, M. Eleftheriou, P. Pattnaik, A. Ndirango, D. Newns and G. J. Martyna,
J. Chem. Phys. 116, 8649 (2002); H. Kamberaj, R. J. Low and M. P. Neal, J. Chem. Phys. 122, 224114
(2005).
"""

import numpy as np
from numba import njit

from .quaternion import (axes_from_quaternion, conjugate_times, no_squish_rotate, omega_from_angmom,
                         quaternion_times_vector)
from .rigid import FixRigid


@njit(cache=True, inline="always")
def _kick_rotation(b, torque, quat, conjqm, ex, ey, ez, tflag, dtf2):
    for d in range(3):
        torque[b, d] *= tflag[b, d]
    t0, t1, t2 = torque[b, 0], torque[b, 1], torque[b, 2]
    fquat = quaternion_times_vector(quat, b, ex[b, 0] * t0 + ex[b, 1] * t1 + ex[b, 2] * t2,
                                    ey[b, 0] * t0 + ey[b, 1] * t1 + ey[b, 2] * t2,
                                    ez[b, 0] * t0 + ez[b, 1] * t1 + ez[b, 2] * t2)
    for c in range(4):
        conjqm[b, c] += dtf2 * fquat[c]


@njit(cache=True, inline="always")
def _angmom_from_conjqm(b, quat, conjqm, ex, ey, ez, inertia, angmom, omega):
    mbody = conjugate_times(quat, conjqm, b)
    for d in range(3):
        angmom[b, d] = 0.5 * (ex[b, d] * mbody[0] + ey[b, d] * mbody[1] + ez[b, d] * mbody[2])
    omega_from_angmom(angmom, ex, ey, ez, inertia, omega, b)


@njit(cache=True, inline="always")
def free_rotation(b, quat, conjqm, ex, ey, ez, inertia, angmom, omega, dtv, dtq):
    """Body b's free rotation over a step (NO_SQUISH: axes 3, 2 for dt/2, 1 for dt, 2, 3 for dt/2),
    then its axes, angular momentum and angular velocity from (p, q)."""
    no_squish_rotate(3, conjqm, quat, inertia, b, dtq)
    no_squish_rotate(2, conjqm, quat, inertia, b, dtq)
    no_squish_rotate(1, conjqm, quat, inertia, b, dtv)
    no_squish_rotate(2, conjqm, quat, inertia, b, dtq)
    no_squish_rotate(3, conjqm, quat, inertia, b, dtq)
    axes_from_quaternion(quat, b, ex, ey, ez)
    _angmom_from_conjqm(b, quat, conjqm, ex, ey, ez, inertia, angmom, omega)


@njit(cache=True)
def no_squish_initial(xcm, vcm, fcm, angmom, torque, omega, quat, conjqm, ex, ey, ez, inertia, masstotal,
                      fflag, tflag, dtv, dtf, dtq):
    for b in range(xcm.shape[0]):
        dtfm = dtf / masstotal[b]
        for d in range(3):
            vcm[b, d] += dtfm * fcm[b, d] * fflag[b, d]
            xcm[b, d] += dtv * vcm[b, d]
        _kick_rotation(b, torque, quat, conjqm, ex, ey, ez, tflag, 2.0 * dtf)
        free_rotation(b, quat, conjqm, ex, ey, ez, inertia, angmom, omega, dtv, dtq)


@njit(cache=True)
def no_squish_final(vcm, fcm, angmom, torque, omega, quat, conjqm, ex, ey, ez, inertia, masstotal, fflag, tflag,
                    dtf):
    for b in range(vcm.shape[0]):
        dtfm = dtf / masstotal[b]
        for d in range(3):
            vcm[b, d] += dtfm * fcm[b, d] * fflag[b, d]
        _kick_rotation(b, torque, quat, conjqm, ex, ey, ez, tflag, 2.0 * dtf)
        _angmom_from_conjqm(b, quat, conjqm, ex, ey, ez, inertia, angmom, omega)


@njit(cache=True)
def conjugate_momenta(angmom, quat, ex, ey, ez, conjqm):
    """p = 2 S(q) (0, L_body) from the space-frame angular momentum."""
    for b in range(angmom.shape[0]):
        m0, m1, m2 = angmom[b, 0], angmom[b, 1], angmom[b, 2]
        p = quaternion_times_vector(quat, b, ex[b, 0] * m0 + ex[b, 1] * m1 + ex[b, 2] * m2,
                                    ey[b, 0] * m0 + ey[b, 1] * m1 + ey[b, 2] * m2,
                                    ez[b, 0] * m0 + ez[b, 1] * m1 + ez[b, 2] * m2)
        for c in range(4):
            conjqm[b, c] = 2.0 * p[c]


class FixRigidNVE(FixRigid):
    name = "rigid/nve"
    usage = ("fix ID GROUP rigid/nve single|molecule|group N G1 .. GN [force M XFLAG YFLAG ZFLAG] "
             "[torque M XFLAG YFLAG ZFLAG] [reinit yes|no] [infile FILE] [langevin TSTART TSTOP TPERIOD SEED]")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.conjqm = np.zeros((self.nbody, 4))

    def setup(self, sim):
        super().setup(sim)
        conjugate_momenta(self.angmom, self.quat, self.ex, self.ey, self.ez, self.conjqm)

    def advance_initial(self, sim):
        no_squish_initial(self.xcm, self.vcm, self.fcm, self.angmom, self.torque, self.omega, self.quat, self.conjqm,
                          self.ex, self.ey, self.ez, self.inertia, self.masstotal, self.fflag, self.tflag,
                          self.dtv, self.dtf, self.dtq)

    def advance_final(self, sim):
        no_squish_final(self.vcm, self.fcm, self.angmom, self.torque, self.omega, self.quat, self.conjqm,
                        self.ex, self.ey, self.ez, self.inertia, self.masstotal, self.fflag, self.tflag, self.dtf)
