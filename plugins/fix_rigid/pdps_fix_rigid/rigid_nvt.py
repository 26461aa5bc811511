r"""Fix ``rigid/nvt``: the rigid bodies of fix ``rigid/nve`` at constant temperature, with Nose-Hoover
chains on their translational and rotational degrees of freedom (Kamberaj, Low and Neal), as LAMMPS's
fix rigid/nvt.

Two chains of M thermostats (positions eta, velocities eta_dot, masses Q_1 = N_f k_B T / omega^2,
Q_k = k_B T / omega^2, omega = 1 / TDAMP) act on the bodies: one on the translational kinetic energy
sum M V^2 (N_f = d N_bodies), one on the rotational sum L . omega (N_f = 3 per body less its zero
principal moments; 1 per body in 2d). Each half step scales V by exp(-dt/2 eta_dot_t,1) and the
quaternion momenta by exp(-dt/2 eta_dot_r,1); after the bodies' first half step the chains advance
dt by a Yoshida-Suzuki scheme of order 3 or 5 (``tparam``'s Torder), Titer times, the forces on the
first thermostats being (2 KE - N_f k_B T) / Q_1. T ramps linearly from TSTART to TSTOP over a run.

``f_ID`` (extensive) and thermo ``ecouple``: LAMMPS's compute_scalar of this fix, the bodies'
temperature (as fix rigid's f_ID) plus the chains' energy
sum_k (N_f,k k_B T eta_1 + k_B T eta_k + Q_k eta_dot_k^2 / 2) over both chains.

Syntax::

    fix ID GROUP rigid/nvt BODYSTYLE [ARGS] temp TSTART TSTOP TDAMP [tparam TCHAIN TITER TORDER]
        [force M XFLAG YFLAG ZFLAG] [torque M XFLAG YFLAG ZFLAG] [reinit yes|no] [infile FILE]

- ``temp``: the target temperature at the run's start and end (temperature) and the damping time
  TDAMP (time); required.
- ``tparam``: chain length TCHAIN (default 10), TITER iterations (1) and the order TORDER, 3 or 5
  (3), of the chains' integration.

Everything else is fix ``rigid``'s and ``rigid/nve``'s (``pdps doc fix rigid``).

Example::

    fix 1 polychains rigid/nvt molecule temp 1.0 1.0 5.0

References: H. Kamberaj, R. J. Low and M. P. Neal, J. Chem. Phys. 122, 224114 (2005); G. J. Martyna,
M. L. Klein and M. Tuckerman, J. Chem. Phys. 97, 2635 (1992).
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import ScriptError, keyword

from .rigid import BAROSTAT_REFUSED, EPSILON, MOL_REFUSED, FixRigid
from .rigid_nve import FixRigidNVE, _angmom_from_conjqm, _kick_rotation, free_rotation

# longest chain and most iterations a step: beyond, each step's chain work would stall a run
CHAIN_LIMIT = 1000


@njit(cache=True, inline="always")
def maclaurin(x):
    """sinh(x)/x by its series, exact near 0."""
    x2 = x * x
    x4 = x2 * x2
    return 1.0 + (1.0 / 6.0) * x2 + (1.0 / 120.0) * x4 + (1.0 / 5040.0) * x2 * x4 + (1.0 / 362880.0) * x4 * x4


@njit(cache=True)
def nvt_initial(xcm, vcm, fcm, angmom, torque, omega, quat, conjqm, ex, ey, ez, inertia, masstotal, fflag,
                tflag, dtv, dtf, dtq, scale_t, scale_r):
    """The bodies' first half step with the chains' scaling; returns (sum M V^2, sum L . omega)."""
    akin_t = 0.0
    akin_r = 0.0
    for b in range(xcm.shape[0]):
        dtfm = dtf / masstotal[b]
        for d in range(3):
            vcm[b, d] += dtfm * fcm[b, d] * fflag[b, d]
            vcm[b, d] *= scale_t
        akin_t += masstotal[b] * (vcm[b, 0] * vcm[b, 0] + vcm[b, 1] * vcm[b, 1] + vcm[b, 2] * vcm[b, 2])
        for d in range(3):
            xcm[b, d] += dtv * vcm[b, d]
        _kick_rotation(b, torque, quat, conjqm, ex, ey, ez, tflag, 2.0 * dtf)
        for c in range(4):
            conjqm[b, c] *= scale_r
        free_rotation(b, quat, conjqm, ex, ey, ez, inertia, angmom, omega, dtv, dtq)
        akin_r += angmom[b, 0] * omega[b, 0] + angmom[b, 1] * omega[b, 1] + angmom[b, 2] * omega[b, 2]
    return akin_t, akin_r


@njit(cache=True)
def nvt_final(vcm, fcm, angmom, torque, omega, quat, conjqm, ex, ey, ez, inertia, masstotal, fflag, tflag, dtf,
              scale_t, scale_r):
    for b in range(vcm.shape[0]):
        dtfm = dtf / masstotal[b]
        for d in range(3):
            vcm[b, d] *= scale_t
            vcm[b, d] += dtfm * fcm[b, d] * fflag[b, d]
        for c in range(4):
            conjqm[b, c] *= scale_r
        _kick_rotation(b, torque, quat, conjqm, ex, ey, ez, tflag, 2.0 * dtf)
        _angmom_from_conjqm(b, quat, conjqm, ex, ey, ez, inertia, angmom, omega)


def chain_substeps(order, dt, titer):
    """(w dt/titer, w dt/(2 titer), w dt/(4 titer)) for the Suzuki-Yoshida weights w of a chain step
    of ``order`` 3 or 5 (LAMMPS's wdti1, wdti2, wdti4)."""
    if order == 3:
        w0 = 1.0 / (2.0 - 2.0 ** (1.0 / 3.0))
        weights = [w0, 1.0 - 2.0 * w0, w0]
    else:
        w0 = 1.0 / (4.0 - 4.0 ** (1.0 / 3.0))
        weights = [w0, w0, 1.0 - 4.0 * w0, w0, w0]
    wdti1 = np.array(weights) * dt / titer
    return wdti1, wdti1 / 2.0, wdti1 / 4.0


@njit(cache=True)
def chain_step(eta, eta_dot, f_eta, q, kt, wdti1, wdti2, wdti4, titer, decay=1.0):
    """Advance one Nose-Hoover chain a full step (its first force f_eta[0] set by the caller). The
    velocity factors are exp(-decay x): 1 for the bodies' chains, 1/2 for rigid/nh's barostat chain
    (LAMMPS's fix rigid/nh)."""
    m = len(eta)
    for _ in range(titer):
        for j in range(len(wdti1)):
            eta_dot[m - 1] += wdti2[j] * f_eta[m - 1]
            for k in range(1, m):
                x = wdti4[j] * eta_dot[m - k]
                s = math.exp(-decay * x)
                eta_dot[m - k - 1] = eta_dot[m - k - 1] * (s * s) + wdti2[j] * f_eta[m - k - 1] * s * maclaurin(x)
            for k in range(m):
                eta[k] += wdti1[j] * eta_dot[k]
            for k in range(1, m):
                f_eta[k] = (q[k - 1] * eta_dot[k - 1] * eta_dot[k - 1] - kt) / q[k]
            for k in range(m - 1):
                x = wdti4[j] * eta_dot[k + 1]
                s = math.exp(-decay * x)
                eta_dot[k] = eta_dot[k] * (s * s) + wdti2[j] * f_eta[k] * s * maclaurin(x)
                f_eta[k + 1] = (q[k] * eta_dot[k] * eta_dot[k] - kt) / q[k + 1]
            eta_dot[m - 1] += wdti2[j] * f_eta[m - 1]


def check_tparam(tparam):
    """tparam TCHAIN TITER TORDER as LAMMPS takes them; longer chains or more iterations than
    CHAIN_LIMIT buy nothing and would exhaust memory or time."""
    chain, titer, order = tparam
    if not (1 <= chain <= CHAIN_LIMIT and 1 <= titer <= CHAIN_LIMIT) or order not in (3, 5):
        raise ScriptError(f"tparam: TCHAIN and TITER must be from 1 to {CHAIN_LIMIT} and TORDER 3 or 5 "
                          f"(got {chain} {titer} {order})")


def check_thermostat(name, args):
    """The thermostat of an nvt form: temp given and positive, tparam within its limits."""
    if args.temp is None:
        raise ScriptError(f"fix {name} needs temp TSTART TSTOP TDAMP")
    start, stop, damp = args.temp
    if start <= 0 or stop <= 0 or damp <= 0:
        raise ScriptError(f"temp: TSTART, TSTOP and TDAMP must be > 0 (got {start:g} {stop:g} {damp:g})")
    check_tparam(args.tparam)


def start_chains(fix, args):
    """The translational and rotational Nose-Hoover chains of a thermostatted fix, at rest."""
    chain = args.tparam[0]
    fix.eta_t, fix.eta_r = np.zeros(chain), np.zeros(chain)
    fix.eta_dot_t, fix.eta_dot_r = np.zeros(chain), np.zeros(chain)
    fix.f_eta_t, fix.f_eta_r = np.zeros(chain), np.zeros(chain)
    fix.q_t, fix.q_r = np.zeros(chain), np.zeros(chain)
    fix.t_target = args.temp[0]

class FixRigidNVT(FixRigidNVE):
    name = "rigid/nvt"
    usage = ("fix ID GROUP rigid/nvt single|molecule|group N G1 .. GN temp TSTART TSTOP TDAMP "
             "[tparam TCHAIN TITER TORDER] [force M X Y Z] [torque M X Y Z] [reinit yes|no]")
    extensive = True
    extensive_array = False       # f_ID[i][j], the bodies' values, are not divided by the particle count (LAMMPS's extarray 0)
    refused = {"langevin": "fix rigid/nvt thermostats with temp; langevin is for rigid and rigid/nve "
                           "(LAMMPS's page: it cannot be used with rigid/nvt)"} | BAROSTAT_REFUSED | MOL_REFUSED

    class Args(FixRigid.Args):
        temp: tuple[float, float, float] | None = keyword(None, unit="temperature")
        tparam: tuple[int, int, int] = keyword((10, 1, 3), unit="1")

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        check_thermostat(cls.name, args)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        start_chains(self, args)

    def init_run(self, sim):
        super().init_run(sim)
        self.boltz, self.mvv2e = sim.units.boltz, sim.units.mvv2e
        d = sim.dimension
        self.nf_t = d * self.nbody
        if d == 3:
            self.nf_r = 3 * self.nbody - int(np.count_nonzero(np.abs(self.inertia) < EPSILON))
        else:
            self.nf_r = self.nbody - int(np.count_nonzero(np.abs(self.inertia[:, 2]) < EPSILON))
        self.wdti1, self.wdti2, self.wdti4 = chain_substeps(self.args.tparam[2], sim.dt, self.args.tparam[1])

    def _temperature_target(self, sim):
        start, stop, _ = self.args.temp
        first, last = sim.run_first_step, sim.run_last_step
        delta = (sim.step - first) / (last - first) if last != first else 0.0
        self.t_target = start + delta * (stop - start)

    def _masses(self, kt):
        frequency = 1.0 / self.args.temp[2]
        mass = kt / (frequency * frequency)
        self.q_t[:] = self.q_r[:] = mass
        self.q_t[0], self.q_r[0] = self.nf_t * mass, self.nf_r * mass

    def setup(self, sim):
        super().setup(sim)
        self._temperature_target(sim)
        kt = self.boltz * self.t_target
        self._masses(kt)
        for eta_dot, f_eta, q in ((self.eta_dot_t, self.f_eta_t, self.q_t), (self.eta_dot_r, self.f_eta_r, self.q_r)):
            f_eta[1:] = (q[:-1] * eta_dot[:-1] * eta_dot[:-1] - kt) / q[1:]

    def advance_initial(self, sim):
        akin_t, akin_r = nvt_initial(self.xcm, self.vcm, self.fcm, self.angmom, self.torque, self.omega, self.quat,
                                     self.conjqm, self.ex, self.ey, self.ez, self.inertia, self.masstotal, self.fflag,
                                     self.tflag, self.dtv, self.dtf, self.dtq, math.exp(-self.dtq * self.eta_dot_t[0]),
                                     math.exp(-self.dtq * self.eta_dot_r[0]))
        self._temperature_target(sim)
        kt = self.boltz * self.t_target
        self._masses(kt)
        self.f_eta_t[0] = (akin_t * self.mvv2e - self.nf_t * kt) / self.q_t[0]
        self.f_eta_r[0] = (akin_r * self.mvv2e - self.nf_r * kt) / self.q_r[0]
        titer = self.args.tparam[1]
        chain_step(self.eta_t, self.eta_dot_t, self.f_eta_t, self.q_t, kt, self.wdti1, self.wdti2, self.wdti4, titer)
        chain_step(self.eta_r, self.eta_dot_r, self.f_eta_r, self.q_r, kt, self.wdti1, self.wdti2, self.wdti4, titer)

    def advance_final(self, sim):
        nvt_final(self.vcm, self.fcm, self.angmom, self.torque, self.omega, self.quat, self.conjqm, self.ex, self.ey,
                  self.ez, self.inertia, self.masstotal, self.fflag, self.tflag, self.dtf,
                  math.exp(-self.dtq * self.eta_dot_t[0]), math.exp(-self.dtq * self.eta_dot_r[0]))

    def scalar(self, sim):
        energy = super().scalar(sim)
        kt = self.boltz * self.t_target if hasattr(self, "boltz") else 0.0
        energy += kt * (self.nf_t * self.eta_t[0] + self.nf_r * self.eta_r[0]) if hasattr(self, "nf_t") else 0.0
        energy += kt * float(self.eta_t[1:].sum() + self.eta_r[1:].sum())
        energy += 0.5 * float((self.q_t * self.eta_dot_t ** 2).sum() + (self.q_r * self.eta_dot_r ** 2).sum())
        return energy

    def ecouple(self, sim):
        return self.scalar(sim)

    def state(self):
        return {"eta_t": self.eta_t, "eta_r": self.eta_r, "eta_dot_t": self.eta_dot_t, "eta_dot_r": self.eta_dot_r}

    def restore(self, state):
        for name, values in state.items():
            getattr(self, name)[:] = values
