r"""Fix ``rigid/nvt/small``: the small bodies of fix ``rigid/nve/small`` at constant temperature, with
fix ``rigid/nvt``'s Nose-Hoover chains (Kamberaj, Low and Neal) on their translational and
rotational degrees of freedom, as LAMMPS's fix rigid/nvt/small (its rigid/nh/small).

Two chains of M thermostats (masses Q_1 = N_f k_B T / omega^2, Q_k = k_B T / omega^2, omega =
1 / TDAMP) act on sum M V^2 (N_f = d per body) and on sum L . omega (N_f = 3 per body less its zero
principal moments; 1 per body in 2d). Each half step scales V by exp(-dt/2 eta_dot_t,1) and the
quaternion momenta by exp(-dt/2 eta_dot_r,1); after the bodies' first half step the chains advance
dt (Yoshida-Suzuki, order TORDER, TITER times) with the kinetic sums of all ranks' bodies. T ramps
from TSTART to TSTOP over a run. ``pdps doc fix rigid/nvt`` gives the chains' equations.

``f_ID`` (extensive) and thermo ``ecouple``: LAMMPS's scalar of this fix, fix rigid/nve/small's
kinetic part of the Hamiltonian plus the chains' energy
sum_k (N_f,k k_B T eta_1 + k_B T eta_k + Q_k eta_dot_k^2 / 2) over both chains.

Syntax::

    fix ID GROUP rigid/nvt/small molecule temp TSTART TSTOP TDAMP [tparam TCHAIN TITER TORDER]
        [reinit yes|no] [infile FILE]

- ``temp``: target temperature at the run's start and end (temperature) and damping time TDAMP
  (time); required.
- ``tparam``: chain length TCHAIN (default 10), TITER iterations (1), each at most 1000, and the
  order TORDER, 3 or 5 (3).

Everything else is fix ``rigid/small``'s (``pdps doc fix rigid/small``).

Example::

    fix 1 bodies rigid/nvt/small molecule temp 1.0 1.0 5.0

References: H. Kamberaj, R. J. Low and M. P. Neal, J. Chem. Phys. 122, 224114 (2005); G. J. Martyna,
M. L. Klein and M. Tuckerman, J. Chem. Phys. 97, 2635 (1992).
"""

import math

import numpy as np

from pdps_core.api import keyword

from .rigid import EPSILON
from .rigid_nve_small import FixRigidNVESmall
from .rigid_nvt import (FixRigidNVT, chain_step, chain_substeps, check_thermostat, nvt_final, nvt_initial,
                        start_chains)
from .rigid_small import BAROSTAT_REFUSED, NOT_YET


class FixRigidNVTSmall(FixRigidNVESmall):
    name = "rigid/nvt/small"
    usage = ("fix ID GROUP rigid/nvt/small molecule temp TSTART TSTOP TDAMP [tparam TCHAIN TITER TORDER] "
             "[reinit yes|no] [infile FILE]")
    extensive = True
    refused = {"langevin": "fix rigid/nvt/small thermostats with temp; langevin is for rigid/small and "
                           "rigid/nve/small (as LAMMPS)"} | BAROSTAT_REFUSED | NOT_YET

    class Args(FixRigidNVESmall.Args):
        temp: tuple[float, float, float] | None = keyword(None, unit="temperature")
        tparam: tuple[int, int, int] = keyword((10, 1, 3), unit="1")

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        check_thermostat(cls.name, args)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        start_chains(self, args)
        self.nf_t = self.nf_r = 0
        self.akin = np.zeros(2)

    # fix rigid/nvt's target ramp, chain masses and restart state
    _temperature_target = FixRigidNVT._temperature_target
    _masses = FixRigidNVT._masses
    state = FixRigidNVT.state
    restore = FixRigidNVT.restore

    def init_run(self, sim):
        super().init_run(sim)
        self.boltz, self.mvv2e = sim.units.boltz, sim.units.mvv2e
        self.wdti1, self.wdti2, self.wdti4 = chain_substeps(self.args.tparam[2], sim.dt, self.args.tparam[1])

    def _count_freedom(self, sim):
        """LAMMPS's compute_dof: d per body translating; 3 per body less its zero moments rotating
        (1 per body in 2d, 0 for a zero moment about z)."""
        nl = self.nlocal_body
        inertia = self.inertia[:nl]
        d = sim.dimension
        if d == 3:
            rotating = 3 * nl - int(np.count_nonzero(np.abs(inertia) < EPSILON))
        else:
            rotating = nl - int(np.count_nonzero(np.abs(inertia[:, 2]) < EPSILON))
        self.nf_t, self.nf_r = (int(c) for c in sim.comm.sum(np.array([d * nl, rotating], dtype=np.int64)))

    def setup(self, sim):
        super().setup(sim)
        self._count_freedom(sim)
        self._temperature_target(sim)
        kt = self.boltz * self.t_target
        self._masses(kt)
        for eta_dot, f_eta, q in ((self.eta_dot_t, self.f_eta_t, self.q_t), (self.eta_dot_r, self.f_eta_r, self.q_r)):
            f_eta[1:] = (q[:-1] * eta_dot[:-1] * eta_dot[:-1] - kt) / q[1:]

    def advance_initial(self, sim):
        xcm, vcm, fcm, angmom, torque, omega, quat, ex, ey, ez, inertia, masstotal, fflag, tflag = self._local()
        self.akin[:] = nvt_initial(xcm, vcm, fcm, angmom, torque, omega, quat, self.conjqm[: self.nlocal_body], ex, ey,
                                   ez, inertia, masstotal, fflag, tflag, self.dtv, self.dtf, self.dtq,
                                   math.exp(-self.dtq * self.eta_dot_t[0]), math.exp(-self.dtq * self.eta_dot_r[0]))
        akin_t, akin_r = sim.comm.sum(self.akin)
        self._temperature_target(sim)
        if self.nf_t + self.nf_r == 0:
            return
        kt = self.boltz * self.t_target
        self._masses(kt)
        self.f_eta_t[0] = (akin_t * self.mvv2e - self.nf_t * kt) / self.q_t[0]
        self.f_eta_r[0] = (akin_r * self.mvv2e - self.nf_r * kt) / self.q_r[0]
        titer = self.args.tparam[1]
        chain_step(self.eta_t, self.eta_dot_t, self.f_eta_t, self.q_t, kt, self.wdti1, self.wdti2, self.wdti4, titer)
        chain_step(self.eta_r, self.eta_dot_r, self.f_eta_r, self.q_r, kt, self.wdti1, self.wdti2, self.wdti4, titer)

    def advance_final(self, sim):
        xcm, vcm, fcm, angmom, torque, omega, quat, ex, ey, ez, inertia, masstotal, fflag, tflag = self._local()
        nvt_final(vcm, fcm, angmom, torque, omega, quat, self.conjqm[: self.nlocal_body], ex, ey, ez, inertia,
                  masstotal, fflag, tflag, self.dtf, math.exp(-self.dtq * self.eta_dot_t[0]),
                  math.exp(-self.dtq * self.eta_dot_r[0]))

    def scalar(self, sim):
        energy = super().scalar(sim)
        kt = self.boltz * self.t_target if hasattr(self, "boltz") else 0.0
        energy += kt * (self.nf_t * self.eta_t[0] + self.nf_r * self.eta_r[0])
        energy += kt * float(self.eta_t[1:].sum() + self.eta_r[1:].sum())
        energy += 0.5 * float((self.q_t * self.eta_dot_t ** 2).sum() + (self.q_r * self.eta_dot_r ** 2).sum())
        return energy

    def ecouple(self, sim):
        return self.scalar(sim)
