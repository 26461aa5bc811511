r"""What fixes ``rigid/nph`` and ``rigid/npt`` share (LAMMPS's fix rigid/nh): the rigid bodies of fix
``rigid/nve`` under the barostat of Kamberaj, Low and Neal, optionally thermostatted by the Nose-Hoover
chains of fix ``rigid/nvt``.

The box lengths L_a of the barostatted axes a follow the strain rates epsilon_dot_a (LAMMPS's
epsilon_dot), each with a mass W = (g_f + d) k_B T / omega_P,a^2 (omega_P = 1 / PDAMP, g_f = N_f,t +
N_f,r the bodies' translational and rotational degrees of freedom, d the dimension):

.. math::

    W \dot\epsilon_a \mathrel{+}= \tfrac{\Delta t}{2}\,\big[(P_a - P_\mathrm{hydro}) V + \mathrm{mtk}_1\big],
    \qquad \mathrm{mtk}_1 = \frac{\sum_b M_b V_b^2 + \sum_b \mathbf{L}_b\cdot\boldsymbol\omega_b}{g_f},

then scaled by exp(-dt/2 eta_dot_b,1), after each step's forces (and at set-up); mtk_2 = sum_a
epsilon_dot_a / g_f. Each half step scales the bodies' velocities along a by exp(-dt/2 (epsilon_dot_a
+ mtk_2)) and their quaternion momenta by exp(-dt/2 d_p mtk_2) (d_p barostatted axes), besides the
chains' own exp(-dt/2 eta_dot_1) with ``temp``; the centres of mass move by V_a dt exp(dt/4
epsilon_dot_a) sinh(dt/4 epsilon_dot_a) / (dt/4 epsilon_dot_a). The box changes by exp(dt/4
epsilon_dot_a) about its centre twice a step, before and after the particles are placed on their
bodies: the centres of mass of every rigid fix's bodies (rigid/small's too), and the particles of the
``dilate`` group, keep their fractional coordinates. A chain of PCHAIN thermostats (masses d^2 k_B T / omega_max^2
for the first, k_B T / omega_max^2 for the others) acts on the barostat's kinetic energy, advanced
with the Yoshida-Suzuki weights of ``tparam`` after the bodies' first half step. T is the target
temperature of ``temp`` (rigid/npt), else the temperature of all particles at the run's start (1 in
lj units, 300 otherwise, where that is 0) (rigid/nph).

P_a is LAMMPS's compute pressure of all particles with their temperature compute: the scalar
(N_dof k_B T + sum_a W_aa) / (d V) for ``iso`` (and ``couple xyz``), the diagonal (sum m v_a^2 + W_aa)
/ V otherwise, averaged over the coupled axes; W includes the constraint virial of the whole step of
every rigid fix (LAMMPS wants the others defined before a box-changing fix). P_hydro is the mean
target of the barostatted axes, ramped from PSTART to PSTOP over the run.

``f_ID`` (extensive) and thermo ``ecouple``: LAMMPS's compute_scalar, fix rigid/nvt's (the bodies'
temperature, the chains' energy) plus sum_a W epsilon_dot_a^2 / (2 d_p) + P_0 V (P_0 the mean of the
three axes' targets, 0 for an axis not barostatted), plus the barostat chain's sum (k_B T eta_b,k +
Q_b,k eta_dot_b,k^2 / 2).

Limits of the scheme (LAMMPS's, which pdps follows to round-off): the constraint virial of scaled
bodies holds a term sum M X . V (epsilon_dot + mtk_2) that depends on the periodic image each body's
centre is counted in (re-imaged here at every step the box changes, by LAMMPS only at its neighbor
list builds), and the extended energy is not conserved (pe + kinetic + P_0 V + barostat and chain
energies: 2 % over 4 time units in a liquid of rigid triangles, alike at dt 0.001 and 0.002); the
mean pressure and temperature are the targets.

Keywords (LAMMPS's fix rigid page)::

    iso|aniso PSTART PSTOP PDAMP     every axis (x and y in 2d), coupled (iso) or each its own (aniso)
    x|y|z PSTART PSTOP PDAMP         one axis (pressure, pressure, time; PSTART, PSTOP >= 0, PDAMP > 0)
    couple none|xyz|xy|yz|xz         axes whose pressures are averaged and driven together
    pchain N                         the barostat chain's length (10)
    dilate all|GROUP                 particles whose positions the box change carries (all)
    tparam TCHAIN TITER TORDER       chain lengths, iterations and order 3|5 (10 1 3)
    temp TSTART TSTOP TDAMP          rigid/npt only

``fix_modify ID temp CTEMP`` and ``fix_modify ID press CPRESS`` (LAMMPS's): the pressure the barostat
reads takes its kinetic part from the temperature compute CTEMP's group (and its temperature), or is
that of the pressure compute CPRESS with its own temperature compute; rigid/nph's barostat
temperature is CTEMP's at the run's start.

Every barostatted axis must be periodic; coupled axes need the same settings; no z in 2d.

References: H. Kamberaj, R. J. Low and M. P. Neal, J. Chem. Phys. 122, 224114 (2005); G. J. Martyna,
D. J. Tobias and M. L. Klein, J. Chem. Phys. 101, 4177 (1994); T. F. Miller III et al., J. Chem.
Phys. 116, 8649 (2002).
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import ScriptError, StyleArgs, keyword, observables

from .rigid import EPSILON, MOL_REFUSED, FixRigid
from .rigid_nve import FixRigidNVE, _angmom_from_conjqm, _kick_rotation, free_rotation
from .rigid_nvt import CHAIN_LIMIT, chain_step, chain_substeps, check_tparam, maclaurin

Triple = tuple[float, float, float] | None
COUPLED = {"xyz": (0, 1, 2), "xy": (0, 1), "yz": (1, 2), "xz": (0, 2), "none": ()}


@njit(cache=True)
def nh_initial(xcm, vcm, fcm, angmom, torque, omega, quat, conjqm, ex, ey, ez, inertia, masstotal, fflag, tflag,
               dtv, dtf, dtq, scale_t, scale_r, drift):
    """The bodies' first half step: V kicked then scaled by scale_t (per axis), X moved by drift[a] V_a,
    the quaternion momenta kicked then scaled by scale_r, then NO_SQUISH; returns (sum M V^2,
    sum L . omega)."""
    akin_t = 0.0
    akin_r = 0.0
    for b in range(xcm.shape[0]):
        dtfm = dtf / masstotal[b]
        for d in range(3):
            vcm[b, d] += dtfm * fcm[b, d] * fflag[b, d]
            vcm[b, d] *= scale_t[d]
        akin_t += masstotal[b] * (vcm[b, 0] * vcm[b, 0] + vcm[b, 1] * vcm[b, 1] + vcm[b, 2] * vcm[b, 2])
        for d in range(3):
            xcm[b, d] += drift[d] * vcm[b, d]
        _kick_rotation(b, torque, quat, conjqm, ex, ey, ez, tflag, 2.0 * dtf)
        for c in range(4):
            conjqm[b, c] *= scale_r
        free_rotation(b, quat, conjqm, ex, ey, ez, inertia, angmom, omega, dtv, dtq)
        akin_r += angmom[b, 0] * omega[b, 0] + angmom[b, 1] * omega[b, 1] + angmom[b, 2] * omega[b, 2]
    return akin_t, akin_r


@njit(cache=True)
def nh_final(vcm, fcm, angmom, torque, omega, quat, conjqm, ex, ey, ez, inertia, masstotal, fflag, tflag, dtf,
             scale_t, scale_r):
    """The bodies' second half step: V scaled then kicked, the quaternion momenta likewise; returns
    (sum M V^2, sum L . omega) after it."""
    akin_t = 0.0
    akin_r = 0.0
    for b in range(vcm.shape[0]):
        dtfm = dtf / masstotal[b]
        for d in range(3):
            vcm[b, d] *= scale_t[d]
            vcm[b, d] += dtfm * fcm[b, d] * fflag[b, d]
        akin_t += masstotal[b] * (vcm[b, 0] * vcm[b, 0] + vcm[b, 1] * vcm[b, 1] + vcm[b, 2] * vcm[b, 2])
        for c in range(4):
            conjqm[b, c] *= scale_r
        _kick_rotation(b, torque, quat, conjqm, ex, ey, ez, tflag, 2.0 * dtf)
        _angmom_from_conjqm(b, quat, conjqm, ex, ey, ez, inertia, angmom, omega)
        akin_r += angmom[b, 0] * omega[b, 0] + angmom[b, 1] * omega[b, 1] + angmom[b, 2] * omega[b, 2]
    return akin_t, akin_r


BAROSTAT_WORDS = ("iso", "aniso", "x", "y", "z", "couple", "pchain", "dilate")


class BarostatArgs(StyleArgs):
    """The keywords of the barostat and its thermostat, added to a rigid fix's own (``Args(Base.Args,
    BarostatArgs)``)."""
    temp: tuple[float, float, float] | None = keyword(None, unit="temperature")
    tparam: tuple[int, int, int] = keyword((10, 1, 3), unit="1")
    iso: Triple = keyword(None, unit="pressure")
    aniso: Triple = keyword(None, unit="pressure")
    x: Triple = keyword(None, unit="pressure")
    y: Triple = keyword(None, unit="pressure")
    z: Triple = keyword(None, unit="pressure")
    couple: Literal["none", "xyz", "xy", "yz", "xz"] | None = keyword(None)
    pchain: int = keyword(10, unit="1")
    dilate: str = keyword("all")


def rigid_centres(sim):
    """(fix, the centres of mass of the bodies it moves on this rank) for every fix of rigid bodies:
    fix rigid's (all bodies, every rank) and rigid/small's (the bodies this rank owns)."""
    found = []
    for fix in sim.fixes.values():
        centres = fix.box_carried_centres() if hasattr(fix, "box_carried_centres") else None
        if centres is not None:
            found.append((fix, centres))
    return found


class NoseHooverBarostat:
    """LAMMPS's fix rigid/nh on the bodies of a rigid fix (fix rigid/nve's or rigid/nve/small's, the
    class after this one in the style's bases): the barostat and, with ``temp``, the thermostat. The
    fix gives its bodies through ``_nh_bodies`` (this rank's) and sums over ranks with ``_nh_sum``."""
    extensive = True
    extensive_array = False       # f_ID[i][j], the bodies' values, are not divided by the particle count (LAMMPS's extarray 0)
    virial_after = "final_integrate"

    def _nh_bodies(self):
        """xcm vcm fcm angmom torque omega quat conjqm ex ey ez inertia masstotal fflag tflag of the bodies
        this rank integrates."""
        return (self.xcm, self.vcm, self.fcm, self.angmom, self.torque, self.omega, self.quat, self.conjqm,
                self.ex, self.ey, self.ez, self.inertia, self.masstotal, self.fflag, self.tflag)

    def _nh_sum(self, sim, values):
        """Sums over the bodies of all ranks from this rank's sums (fix rigid: every rank has them all)."""
        return values

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        check_tparam(args.tparam)
        if not 1 <= args.pchain <= CHAIN_LIMIT:
            raise ScriptError(f"pchain: the barostat chain needs 1 to {CHAIN_LIMIT} thermostats (got {args.pchain})")
        if args.temp is not None:
            start, stop, damp = args.temp
            if not (start >= 0 and stop > 0 and damp > 0):
                raise ScriptError(f"temp: TSTART must be >= 0, TSTOP and TDAMP > 0 (got {start:g} {stop:g} {damp:g})")
        for word in ("iso", "aniso", "x", "y", "z"):
            setting = getattr(args, word)
            if setting is not None:
                start, stop, damp = setting
                if start < 0 or stop < 0:
                    raise ScriptError(f"{word}: target pressures of fix {cls.name} cannot be < 0 (got {start:g} {stop:g}; "
                                      "as LAMMPS)")
                if damp <= 0:
                    raise ScriptError(f"{word}: PDAMP must be > 0 (got {damp:g})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        a = args
        d = sim.dimension
        self.p_start, self.p_stop, self.p_period = np.zeros(3), np.zeros(3), np.zeros(3)
        self.p_flag = np.zeros(3, dtype=bool)
        pcouple = "none"
        for word, axes in (("iso", (0, 1, 2)), ("aniso", (0, 1, 2)), ("x", (0,)), ("y", (1,)), ("z", (2,))):
            setting = getattr(a, word)
            if setting is None:
                continue
            if word == "z" and d == 2:
                raise ScriptError("z: a 2d simulation has no z pressure to control (LAMMPS: invalid for 2d)")
            for axis in axes:
                if axis == 2 and d == 2:
                    continue
                self.p_start[axis], self.p_stop[axis], self.p_period[axis] = setting
                self.p_flag[axis] = True
            if word == "iso":
                pcouple = "xyz"
        if a.couple is not None:
            pcouple = a.couple
        if d == 2 and pcouple in ("yz", "xz"):
            raise ScriptError(f"couple {pcouple}: a 2d simulation has no z pressure to couple")
        self.pstat = self.changes_box = bool(self.p_flag.any())
        self.tstat = a.temp is not None
        coupled = [axis for axis in COUPLED[pcouple] if axis < d]
        if self.pstat:
            if any(not self.p_flag[axis] for axis in coupled):
                raise ScriptError(f"couple {pcouple}: every coupled axis needs a pressure (iso, aniso or x/y/z)")
            if len({(self.p_start[k], self.p_stop[k], self.p_period[k]) for k in coupled}) > 1:
                raise ScriptError(f"couple {pcouple}: coupled axes need the same PSTART PSTOP PDAMP (as LAMMPS)")
            for axis in np.flatnonzero(self.p_flag):
                if not sim.box.periodic[axis]:
                    raise ScriptError(f"fix {self.name} cannot change the non-periodic {'xyz'[axis]} length (as LAMMPS)")
        self.pcouple = pcouple
        self.iso = pcouple == "xyz" or (d == 2 and pcouple == "xy")
        self.p_freq = np.where(self.p_flag, 1.0 / np.where(self.p_flag, self.p_period, 1.0), 0.0)
        self.pdim = int(self.p_flag.sum())
        chain = a.tparam[0]
        self.eta_t, self.eta_r = np.zeros(chain), np.zeros(chain)
        self.eta_dot_t, self.eta_dot_r = np.zeros(chain), np.zeros(chain)
        self.f_eta_t, self.f_eta_r = np.zeros(chain), np.zeros(chain)
        self.q_t, self.q_r = np.zeros(chain), np.zeros(chain)
        self.eta_b, self.eta_dot_b = np.zeros(a.pchain), np.zeros(a.pchain)
        self.f_eta_b, self.q_b = np.zeros(a.pchain), np.zeros(a.pchain)
        self.epsilon, self.epsilon_dot, self.epsilon_mass = np.zeros(3), np.zeros(3), np.zeros(3)
        self.p_current, self.p_target = np.zeros(3), np.zeros(3)
        self.p_hydro = 0.0
        self.mtk_term1 = self.mtk_term2 = 0.0
        self.vol0 = 0.0
        self.t_target = a.temp[0] if self.tstat else 1.0
        self.scale_t, self.drift = np.ones(3), np.ones(3)
        self.akin_t = self.akin_r = 0.0
        self.nf_t = self.nf_r = self.g_f = 0
        self.temp_id = self.press_id = None     # fix_modify temp / press: computes named instead of group all's

    # ---- per run ------------------------------------------------------------------------------------
    def needs(self, step):
        return {"virial"} if self.pstat else set()

    def init_run(self, sim):
        super().init_run(sim)
        if self.args.dilate != "all":
            sim.require_group(self.args.dilate)
        # the computes fix_modify named must still be there (uncompute)
        if self.temp_id is not None:
            self._defined(sim, self.temp_id, "temperature")
        temp_id = self._pressure_temperature(sim)       # checks fix_modify press's compute too
        if temp_id is not None:
            self._defined(sim, temp_id, "temperature")
        for fix in sim.fixes.values():
            if any(self.p_flag[d] for d in fix.deformed_axes):
                raise ScriptError(f"fix {self.id} {self.name} and fix {fix.id} deform change the same box length")
        self.boltz, self.mvv2e, self.nktv2p = sim.units.boltz, sim.units.mvv2e, sim.units.nktv2p
        _, titer, order = self.args.tparam
        self.wdti1, self.wdti2, self.wdti4 = chain_substeps(order, sim.dt, titer)
        if self.pstat and self.vol0 == 0.0:
            self.vol0 = float(sim.box.volume)

    def _count_freedom(self, sim):
        """LAMMPS's compute_dof: d per body translating; 3 per body less its zero moments rotating (1 per
        body in 2d, 0 for a zero moment about z); all ranks' bodies (rigid/small's exist on each rank
        from the set-up's first neighbor list build on)."""
        d = sim.dimension
        inertia = self._nh_bodies()[11]
        nbody = len(inertia)
        if d == 3:
            rotating = 3 * nbody - int(np.count_nonzero(np.abs(inertia) < EPSILON))
        else:
            rotating = nbody - int(np.count_nonzero(np.abs(inertia[:, 2]) < EPSILON))
        self.nf_t, self.nf_r = (int(c) for c in self._nh_sum(sim, np.array([d * nbody, rotating], dtype=np.int64)))
        self.g_f = self.nf_t + self.nf_r

    def setup(self, sim):
        super().setup(sim)
        self._count_freedom(sim)
        _, vcm, _, angmom, _, omega, *_, masstotal, _, _ = self._nh_bodies()
        akin = np.array([float((masstotal * np.einsum("bd,bd->b", vcm, vcm)).sum()),
                         float(np.einsum("bd,bd->", angmom, omega))])
        self.akin_t, self.akin_r = (float(c) for c in self._nh_sum(sim, akin))
        if self.tstat:
            self.t_target = sim.ramp(self.args.temp[0], self.args.temp[1])
        elif self.pstat:
            t0 = sim.compute_value(self.temp_id) if self.temp_id is not None else observables.temperature(sim, "all")
            self.t_target = t0 if t0 != 0.0 else (1.0 if sim.units.name == "lj" else 300.0)
        if self.pstat:
            self._pressure(sim)
        kt = self.boltz * self.t_target
        if self.tstat:
            self._thermostat_masses(kt)
            for eta_dot, f_eta, q in ((self.eta_dot_t, self.f_eta_t, self.q_t), (self.eta_dot_r, self.f_eta_r, self.q_r)):
                f_eta[1:] = (q[:-1] * eta_dot[:-1] * eta_dot[:-1] - kt) / q[1:]
        if self.pstat:
            d = sim.dimension
            self.epsilon_mass[self.p_flag] = (self.g_f + d) * kt / self.p_freq[self.p_flag] ** 2
            self.epsilon[self.p_flag] = math.log(self.vol0) / d
            self._barostat_masses(sim, kt)
            self._press_target(sim)
            self._epsilon_dot(sim)

    # ---- the step -----------------------------------------------------------------------------------
    def _scales(self):
        """Velocity factors of a half step (chains and barostat) as they stand."""
        self.scale_t[:] = 1.0
        scale_r = 1.0
        if self.tstat:
            self.scale_t[:] = math.exp(-self.dtq * self.eta_dot_t[0])
            scale_r = math.exp(-self.dtq * self.eta_dot_r[0])
        if self.pstat:
            self.scale_t *= np.exp(-self.dtq * (self.epsilon_dot + self.mtk_term2))
            scale_r *= math.exp(-self.dtq * self.pdim * self.mtk_term2)
        return scale_r

    def advance_initial(self, sim):
        scale_r = self._scales()
        self.drift[:] = self.dtv
        if self.pstat:
            for d in range(3):
                x = self.dtq * self.epsilon_dot[d]
                self.drift[d] = self.dtv * math.exp(x) * maclaurin(x)
        akin = nh_initial(*self._nh_bodies(), self.dtv, self.dtf, self.dtq, self.scale_t, scale_r, self.drift)
        self.akin_t, self.akin_r = (float(c) for c in self._nh_sum(sim, np.array(akin)))
        titer = self.args.tparam[1]
        if self.tstat:
            self.t_target = sim.ramp(self.args.temp[0], self.args.temp[1])
            kt = self.boltz * self.t_target
            if self.g_f > 0:
                self._thermostat_masses(kt)
                self.f_eta_t[0] = (self.akin_t * self.mvv2e - self.nf_t * kt) / self.q_t[0]
                self.f_eta_r[0] = (self.akin_r * self.mvv2e - self.nf_r * kt) / self.q_r[0]
                chain_step(self.eta_t, self.eta_dot_t, self.f_eta_t, self.q_t, kt, self.wdti1, self.wdti2, self.wdti4,
                           titer)
                chain_step(self.eta_r, self.eta_dot_r, self.f_eta_r, self.q_r, kt, self.wdti1, self.wdti2, self.wdti4,
                           titer)
        if self.pstat:
            kt = self.boltz * self.t_target
            self._barostat_masses(sim, kt)
            d = sim.dimension
            self.epsilon_mass[self.p_flag] = (self.g_f + d) * kt / self.p_freq[self.p_flag] ** 2
            kecurrent = float((self.epsilon_mass * self.epsilon_dot ** 2)[self.p_flag].sum()) / self.pdim
            self.f_eta_b[0] = (kecurrent - kt) / self.q_b[0]
            chain_step(self.eta_b, self.eta_dot_b, self.f_eta_b, self.q_b, kt, self.wdti1, self.wdti2, self.wdti4,
                       titer, 0.5)

    def initial_integrate(self, sim):
        self.advance_initial(sim)
        if self.pstat:
            self._remap(sim)
        self.place_particles(sim)
        if self.pstat:
            self._remap(sim)

    def advance_final(self, sim):
        scale_r = self._scales()
        xcm, *bodies = self._nh_bodies()
        akin = nh_final(*bodies, self.dtf, self.scale_t, scale_r)
        self.akin_t, self.akin_r = (float(c) for c in self._nh_sum(sim, np.array(akin)))

    def final_integrate(self, sim):
        super().final_integrate(sim)
        if self.pstat:
            self._pressure(sim)
            self._press_target(sim)
            self._epsilon_dot(sim)

    # ---- the barostat -------------------------------------------------------------------------------
    def _thermostat_masses(self, kt):
        mass = kt / (1.0 / self.args.temp[2]) ** 2
        self.q_t[:] = self.q_r[:] = mass
        self.q_t[0], self.q_r[0] = self.nf_t * mass, self.nf_r * mass

    def _barostat_masses(self, sim, kt):
        mass = kt / float(self.p_freq.max()) ** 2
        self.q_b[:] = mass
        self.q_b[0] = sim.dimension * sim.dimension * mass
        self.f_eta_b[1:] = (self.q_b[:-1] * self.eta_dot_b[:-1] ** 2 - kt) / self.q_b[1:]

    def _press_target(self, sim):
        delta = sim.ramp(0.0, 1.0)
        self.p_target[self.p_flag] = (self.p_start + delta * (self.p_stop - self.p_start))[self.p_flag]
        self.p_hydro = float(self.p_target[self.p_flag].sum()) / self.pdim

    def _epsilon_dot(self, sim):
        if self.g_f == 0:
            return
        volume = float(sim.box.volume)
        self.mtk_term1 = (self.akin_t + self.akin_r) * self.mvv2e / self.g_f
        scale = math.exp(-self.dtq * self.eta_dot_b[0])
        for d in np.flatnonzero(self.p_flag):
            force = ((self.p_current[d] - self.p_hydro) * volume / self.nktv2p + self.mtk_term1) / self.epsilon_mass[d]
            self.epsilon_dot[d] = (self.epsilon_dot[d] + self.dtq * force) * scale
        self.mtk_term2 = float(self.epsilon_dot[self.p_flag].sum()) / self.g_f

    def _pressure(self, sim):
        """LAMMPS's compute pressure of all particles now (iso: its scalar; else its diagonal), the
        coupled axes averaged, into p_current; the virial is the forces' and, while on, this step's
        constraint virial of every fix of rigid bodies."""
        d = sim.dimension
        volume = float(sim.box.volume)
        # the constraint virials of this fix and of the rigid fixes before it, complete after their
        # final_integrate, join the others' only after every fix's (LAMMPS's compute pressure has them)
        constraints = np.zeros(3)
        for fix in sim.fixes.values():
            if fix.thermo_virial and fix.virial_after == "final_integrate":
                constraints += np.asarray(fix.compute_virial(sim), dtype=np.float64)[:3]
        constraints = np.asarray(sim.comm.sum(constraints))
        temp_id = self._pressure_temperature(sim)
        group = self._defined(sim, temp_id, "temperature").group if temp_id is not None else "all"
        if self.iso:
            virial = np.asarray(sim.comm.sum(np.asarray(sim.virial[:3], dtype=np.float64))) + constraints
            virial = virial + observables.tail_corrections(sim)[1]
            temperature = sim.compute_value(temp_id) if temp_id is not None else observables.temperature(sim, "all")
            dof = observables.degrees_of_freedom(sim, group)
            self.p_current[:] = ((dof * self.boltz * temperature + virial[:d].sum()) / (d * volume) * self.nktv2p)
            return
        # the kinetic tensor of the temperature's group and the forces' virial (core), then the constraints'
        tensor = observables.pressure_tensor(sim, group)[:3] + constraints / volume * self.nktv2p
        if d == 2:
            tensor[2] = 0.0
        self.p_current[:] = tensor
        coupled = list(COUPLED[self.pcouple])
        if coupled:
            self.p_current[coupled] = tensor[coupled].mean()

    def _pressure_temperature(self, sim):
        """The temperature compute of the pressure the barostat reads: fix_modify press's compute's own,
        else fix_modify temp's (LAMMPS points its pressure compute at it), else None (group all)."""
        if self.press_id is not None:
            return self._defined(sim, self.press_id, "pressure").args.temperature
        return self.temp_id

    # ---- fix_modify temp CTEMP, press CPRESS (LAMMPS's modify_param) ----------------------------------
    def modify_param(self, sim, keyword, value):
        if keyword not in ("temp", "press"):
            return super().modify_param(sim, keyword, value)
        style, what = ("temp", "temperature") if keyword == "temp" else ("pressure", "pressure")
        compute = self._defined(sim, value, what)
        if not (compute.gives_temperature if keyword == "temp" else compute.gives_pressure):
            raise ScriptError(f"{keyword}: compute {value} ({compute.name}) is not a {style} compute, so it gives no "
                              f"{what}")
        if keyword == "temp":
            self.temp_id = value
            if compute.group != "all":
                sim.warn(f"fix {self.id} {self.name}: temperature compute {value} is of group {compute.group}, not "
                         "all (LAMMPS's fix_modify warns so too)")
        else:
            self.press_id = value
        return True

    def _defined(self, sim, ident, what):
        compute = sim.computes.get(ident)
        if compute is None:
            raise ScriptError(f"compute {ident} is not defined ({what} of fix {self.id} {self.name})")
        return compute

    def _remap(self, sim):
        """Half the step's box change about the box's centre: body centres (of every rigid fix) and the
        dilate group's particles keep their fractional coordinates (LAMMPS's remap and deform)."""
        self.epsilon += self.dtq * self.epsilon_dot
        box = sim.box
        lo, hi = box.lo.copy(), box.hi.copy()
        length = box.length.copy()
        for d in np.flatnonzero(self.p_flag):
            centre = 0.5 * (lo[d] + hi[d])
            factor = math.exp(self.dtq * self.epsilon_dot[d])
            lo[d] = (lo[d] - centre) * factor + centre
            hi[d] = (hi[d] - centre) * factor + centre
        rigid = rigid_centres(sim)
        fractions = [(centres - box.lo) * (1.0 / length) for _, centres in rigid]
        sim.change_box(lo, hi, remap=self.args.dilate)
        for (fix, centres), fraction in zip(rigid, fractions):
            centres[:] = box.length * fraction + box.lo
            fix.box_carried(sim)

    # ---- thermo and restart files -------------------------------------------------------------------
    def _nh_base_scalar(self, sim):
        return FixRigid.scalar(self, sim)

    def scalar(self, sim):
        energy = self._nh_base_scalar(sim)
        if not hasattr(self, "boltz"):
            return energy
        kt = self.boltz * self.t_target
        if self.tstat:
            energy += kt * (self.nf_t * self.eta_t[0] + self.nf_r * self.eta_r[0])
            energy += kt * float(self.eta_t[1:].sum() + self.eta_r[1:].sum())
            energy += 0.5 * float((self.q_t * self.eta_dot_t ** 2).sum() + (self.q_r * self.eta_dot_r ** 2).sum())
        if self.pstat:
            energy += float((self.epsilon_mass * self.epsilon_dot ** 2)[self.p_flag].sum()) * 0.5 / self.pdim
            energy += float(self.p_target.sum()) / 3.0 * float(sim.box.volume) / self.nktv2p
            energy += kt * float(self.eta_b.sum()) + 0.5 * float((self.q_b * self.eta_dot_b ** 2).sum())
        return energy

    def ecouple(self, sim):
        return self.scalar(sim)

    SAVED = ("eta_t", "eta_r", "eta_dot_t", "eta_dot_r", "eta_b", "eta_dot_b", "epsilon", "epsilon_dot")

    def state(self):
        return {name: getattr(self, name).copy() for name in self.SAVED} | {"vol0": self.vol0}

    def restore(self, state):
        for name in self.SAVED:
            saved = np.asarray(state.get(name, ()), dtype=np.float64)
            if saved.shape == getattr(self, name).shape:
                getattr(self, name)[:] = saved
        self.vol0 = float(state.get("vol0", 0.0))


class FixRigidNH(NoseHooverBarostat, FixRigidNVE):
    """Fix rigid/nve with the barostat (and, with ``temp``, the thermostat) of LAMMPS's fix rigid/nh."""
    refused = {"langevin": "fix rigid/nph and rigid/npt take no langevin (LAMMPS's page: rigid and rigid/nve "
                           "only)"} | MOL_REFUSED

    class Args(FixRigid.Args, BarostatArgs):
        pass
