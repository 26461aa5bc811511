r"""Fix ``rigid/nve/small``: the small bodies of fix ``rigid/small`` integrated with fix ``rigid/nve``'s
symplectic scheme (Miller et al.'s NO_SQUISH splitting in Kamberaj, Low and Neal's quaternion
momentum p = 2 S(q) (0, L_body)), as LAMMPS's fix rigid/nve/small: V and p take half kicks from F and
the body-frame torque, X a full step, and the free rotation is split into exact rotations about the
principal axes (3, 2 for dt/2, 1 for dt, 2, 3 for dt/2). ``pdps doc fix rigid/nve`` says more.

Bodies, their owners and communication, degrees of freedom, the virial and the langevin keyword are
fix ``rigid/small``'s
(``pdps doc fix rigid/small``).

``f_ID``: LAMMPS's scalar of rigid/nve/small, the kinetic part of Kamberaj et al.'s Hamiltonian,
sum M V^2 + sum_k (p . P_k q)^2 / (8 I_k) (energy; twice the translational kinetic energy plus the
rotational one, as LAMMPS computes it; a moment below 1e-6 counts 0).

Syntax::

    fix ID GROUP rigid/nve/small molecule [reinit yes|no] [infile FILE] [langevin TSTART TSTOP TPERIOD SEED]

Example::

    fix 1 bodies rigid/nve/small molecule

References: T. F. Miller III et al., J. Chem. Phys. 116, 8649 (2002); H. Kamberaj, R. J. Low and M. P.
Neal, J. Chem. Phys. 122, 224114 (2005).
"""

import numpy as np
from numba import njit

from .rigid_nve import conjugate_momenta, no_squish_final, no_squish_initial
from .rigid_small import FixRigidSmall


@njit(cache=True)
def hamiltonian_kinetic(masstotal, vcm, quat, conjqm, inertia, nbody):
    """LAMMPS's rigid/nh/small ke_t + ke_q: sum M V^2 and sum_k (p . P_k q)^2 / (8 I_k)."""
    ke_t = 0.0
    ke_q = 0.0
    for b in range(nbody):
        ke_t += masstotal[b] * (vcm[b, 0] * vcm[b, 0] + vcm[b, 1] * vcm[b, 1] + vcm[b, 2] * vcm[b, 2])
        w, i, j, k = quat[b, 0], quat[b, 1], quat[b, 2], quat[b, 3]
        p0, p1, p2, p3 = conjqm[b, 0], conjqm[b, 1], conjqm[b, 2], conjqm[b, 3]
        for axis, component in ((0, -p0 * i + p1 * w + p2 * k - p3 * j),
                                (1, -p0 * j - p1 * k + p2 * w + p3 * i),
                                (2, -p0 * k + p1 * j - p2 * i + p3 * w)):
            if abs(inertia[b, axis]) >= 1e-6:
                ke_q += component * component / (8.0 * inertia[b, axis])
    return ke_t, ke_q


class FixRigidNVESmall(FixRigidSmall):
    name = "rigid/nve/small"
    usage = ("fix ID GROUP rigid/nve/small molecule [reinit yes|no] [infile FILE] "
             "[langevin TSTART TSTOP TPERIOD SEED]")

    def setup(self, sim):
        super().setup(sim)
        nl = self.nlocal_body
        conjugate_momenta(self.angmom[:nl], self.quat[:nl], self.ex[:nl], self.ey[:nl], self.ez[:nl], self.conjqm[:nl])

    def advance_initial(self, sim):
        xcm, vcm, fcm, angmom, torque, omega, quat, ex, ey, ez, inertia, masstotal, fflag, tflag = self._local()
        no_squish_initial(xcm, vcm, fcm, angmom, torque, omega, quat, self.conjqm[: self.nlocal_body], ex, ey, ez,
                          inertia, masstotal, fflag, tflag, self.dtv, self.dtf, self.dtq)

    def advance_final(self, sim):
        xcm, vcm, fcm, angmom, torque, omega, quat, ex, ey, ez, inertia, masstotal, fflag, tflag = self._local()
        no_squish_final(vcm, fcm, angmom, torque, omega, quat, self.conjqm[: self.nlocal_body], ex, ey, ez, inertia,
                        masstotal, fflag, tflag, self.dtf)

    def scalar(self, sim):
        if not self.set_up or not self.compact:
            return 0.0
        ke = np.array(hamiltonian_kinetic(self.masstotal, self.vcm, self.quat, self.conjqm, self.inertia,
                                          self.nlocal_body))
        return float(np.sum(sim.comm.sum(ke))) * sim.units.mvv2e
