r"""Fix ``langevin``: a Langevin thermostat (Schneider & Stoll, Phys. Rev. B 17, 1302 (1978); LAMMPS's
fix langevin), with the target temperature ramped linearly over a run, the rotation of spheres
thermostatted too (``omega yes``), the energy exchanged with the bath tallied (``tally yes``), and the
Gronbech-Jensen-Farago integrator (``gjf vfull|vhalf``).

**Translation.** Each particle of the group feels, besides its other forces, a friction and a random
force:

.. math::

    \mathbf{F}_i \mathrel{+}= -\frac{m_i}{\tau_i}\mathbf{v}_i
        + \sqrt{\frac{24\, k_B T(t)\, m_i}{\Delta t\,\tau_i}}\;(\mathbf{u}_i - \tfrac12),
    \qquad \tau_i = \mathrm{DAMP}\cdot\mathrm{ratio}(\mathrm{type}_i),
    \qquad T(t) = T_\mathrm{start} + (T_\mathrm{stop} - T_\mathrm{start})\,
                  \frac{t - t_\mathrm{first}}{t_\mathrm{last} - t_\mathrm{first}}

with :math:`\mathbf{u}_i` three uniform numbers in (0, 1) (variance 1/12, so the random force has
variance :math:`2 k_B T m_i / (\Delta t\,\tau_i)`, as LAMMPS's), drawn from the counter-based
generator keyed by (seed, step, particle id): the noise does not depend on particle order or on
the number of ranks. LAMMPS draws from a per-rank Marsaglia generator, so trajectories differ from
LAMMPS's while the statistics agree. The ramp runs over the run in which the fix is active (LAMMPS's
``ramp``): first step of the run at T_START, last at T_STOP. Applied in ``post_force`` and at setup.
The fix only adds forces: an integrator (fix nve) moves the particles. In real and metal units the
forces are divided by ftm2v, as LAMMPS's.

**Rotation** (``omega yes``, spheres of ``particle_style sphere``): each sphere of radius
:math:`R_i` and moment of inertia :math:`I_i = \tfrac25 m_i R_i^2` also feels a torque

.. math::

    \mathbf{T}_i \mathrel{+}= -\frac{10}{3}\frac{I_i}{\tau_i}\boldsymbol{\omega}_i
        + \sqrt{\frac{10}{3}\,\frac{24\, k_B T\, I_i}{\Delta t\,\tau_i}}\;(\mathbf{u}'_i - \tfrac12)

(uniform numbers of a second stream). The factor 10/3 (LAMMPS's) leaves the rotational temperature
at T and gives a free sphere the rotational diffusion that goes with its translational friction
(Stokes: :math:`\zeta_r / \zeta_t = \tfrac43 R^2`). Thermostat a sphere's rotation with an integrator
that turns it: fix nve/sphere. ``compute erotate/sphere`` reads
:math:`\tfrac12 \sum I\omega^2 \to \tfrac32 N k_B T`.

**Tally** (``tally yes``): the work the thermostat's forces do on the particles, accumulated as
LAMMPS does: :math:`W = \sum_n \tfrac{\Delta t}{2}\,(P_{n-1} + P_n)` with
:math:`P_n = \sum_i \mathbf{F}^\mathrm{L}_i(n)\cdot\mathbf{v}_i(n)` (friction plus noise, dotted
with the velocity at the end of step n; the translational forces only, as LAMMPS's). The fix's
scalar ``f_ID`` is :math:`-W`, the energy the bath took from the particles since the start of the
run (energy units, extensive: divided by N with ``thermo_modify norm yes``), and it is the fix's
``ecouple``: thermo ``econserve`` = pe + ke + ecouple stays flat over an NVE run with this
thermostat. Without ``tally``, ``f_ID`` is the target temperature of the last step the thermostat
acted on (pdps's; LAMMPS's reads 0) and ``ecouple`` gets nothing from the fix. ``fix_modify ID energy
yes`` is refused, as LAMMPS 22 Jul 2025 refuses it: ecouple carries the tally. With ``gjf`` the tally
counts the force GJF's velocities feel, :math:`(\mathbf{F}^\mathrm{drag} + \beta^{n-1})\sqrt b`, against
the half-step velocity, and a run starts from :math:`\Delta t\,P_0` rather than 0 (LAMMPS's sign).

**A temperature with a bias** (``fix_modify ID temp CID``, as LAMMPS's): with a temperature compute
that has a velocity bias (temp/partial, temp/region, temp/ramp), friction acts on each particle's
velocity less the bias, and a component of that thermal velocity that is exactly 0 gets no noise
(LAMMPS's remove_bias/restore_bias and its v = 0 test): temp/region thermostats only the group's
particles inside the region at that step, temp/partial only its chosen components, temp/ramp the
velocities about the ramp. A compute without a bias (temp) changes nothing, as in LAMMPS; the tally
dots the forces with the full velocities, as LAMMPS's; a compute of another group than the fix's is
warned of. Not supported with ``gjf`` (refused at the fix_modify line). Compared with LAMMPS 22 Jul
2025 at T = 0 (friction alone): temp/region then temp/partial, with tally yes, thermo to 1e-10 over
300 steps (plugins/fix_langevin/tests/test_langevin_temp.py).

**Gronbech-Jensen-Farago** (``gjf vfull|vhalf``; Gronbech-Jensen & Farago, Mol. Phys. 111, 983
(2013)): a discretisation of the Langevin equation that samples positions from the Boltzmann
distribution at any stable time step (a harmonic well holds :math:`\langle x^2\rangle = k_BT/k`
exactly). With :math:`\alpha = m/\tau`, :math:`b = 1/(1 + \alpha\Delta t/2m)`,
:math:`a = b\,(1 - \alpha\Delta t/2m)` and :math:`\beta^{n}` Gaussian with variance
:math:`2\alpha k_BT\Delta t`:

.. math::

    x^{n+1} = x^n + b\Delta t\, v^n + \frac{b\Delta t^2}{2m} f^n + \frac{b\Delta t}{2m}\beta^{n+1},
    \qquad
    v^{n+1} = a v^n + \frac{\Delta t}{2m}(a f^n + f^{n+1}) + \frac{b}{m}\beta^{n+1}

carried out, as LAMMPS does, inside fix nve's velocity Verlet: the fix scales the forces by
:math:`a` and adds :math:`a` times the friction and the mean of two successive noises in
``post_force``, undoes the scaling and restores the integrator's velocity in ``initial_integrate``,
and in ``end_of_step`` reports either the half-step velocity of the 2GJ method
(Gronbech-Jensen, Mol. Phys. 118, e1662506 (2020)),
:math:`u^{n+1/2} = (x^{n+1} - x^n)/(\sqrt b\,\Delta t)`, whose kinetic temperature is T at any
stable step for a linear system (``vhalf``), or GJF's on-site velocity, whose temperature falls
short of T by :math:`O(\Delta t^2)` (``vfull``). The velocities a run reports (thermo ``temp``,
dumps) are these. With ``scale``, a and b use DAMP, not DAMP times the ratio (LAMMPS's). The fix
must be defined before fix nve (its ``initial_integrate`` has to run first), and DAMP must not be
dt/2 (a = 0); pdps also refuses gjf without an nve fix (LAMMPS runs it, nothing moving). LAMMPS 22 Jul
2025 warns that its gjf keyword is deprecated; it still runs it as above.

Parameters:

- ``T_START``, ``T_STOP``: target temperature at the first and last step of a run (>= 0,
  temperature units).
- ``DAMP``: the damping time :math:`\tau` (> 0, time units): the friction relaxes velocities over
  :math:`\tau`, kinetic energy over :math:`\tau/2`.
- ``SEED``: integer >= 1.
- ``scale TYPE RATIO`` (repeatable): particles of TYPE are damped over DAMP * RATIO (LAMMPS's scale:
  a ratio of 2 halves the friction and the noise variance).
- ``zero yes``: the random forces of the group are shifted to sum to zero every step, so the
  thermostat adds no net momentum (LAMMPS's zero).
- ``omega yes``: thermostat the spheres' rotation too (needs ``particle_style sphere``).
- ``tally yes``: accumulate the energy exchanged with the bath (``f_ID``, thermo ``ecouple``).
- ``gjf no|vfull|vhalf``: the Gronbech-Jensen-Farago integrator, reporting the on-site (vfull) or
  the 2GJ half-step (vhalf) velocity.
- ``angmom``: LAMMPS's thermostat of the angular momentum of ellipsoids; pdps has no aspherical
  particles, so only ``angmom no`` is accepted.

Syntax::

    fix ID GROUP langevin T_START T_STOP DAMP SEED [scale TYPE RATIO]... [zero yes|no]
        [omega yes|no] [tally yes|no] [gjf no|vfull|vhalf]
    fix_modify ID temp CID

Example::

    fix heat all langevin 1.0 1.5 0.1 48279 tally yes
    fix 2 all nve
    thermo_style custom step temp pe etotal f_heat econserve
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import (Fix, NamedTemperature, ScriptError, StyleArgs, keyword, observables, param, particle_gaussians,
                           particle_uniforms)

STREAM = 1              # the translational noise
ROTATION_STREAM = 2     # the rotational noise (omega yes)
SETUP_STREAM = 3        # gjf's draw at a run's setup: a number of its own, as LAMMPS's generator gives
SPHERE_INERTIA = 0.4    # I = 2/5 m R^2
ROTATION_FACTOR = 10.0 / 3.0


@njit(cache=True, inline="always")
def friction_and_amplitude(m, ratio, damp, noise_scale):
    """A particle's friction coefficient m/(damp ratio) and noise amplitude noise_scale sqrt(m/ratio)."""
    return m / (damp * ratio), noise_scale * math.sqrt(m / ratio)


@njit(cache=True)
def langevin_forces(v, f, tag, type_, mass, mask, groupbit, nlocal, damp, noise_scale, ratio, seed, step,
                    noise_sum, tally, flangevin, biased):
    """Friction -m v/(damp ratio) and noise sqrt(24 kT m/(dt damp ratio)) (u - 1/2), ``noise_scale``
    being sqrt(24 kT / (dt damp)) in force units; the noise added is summed into ``noise_sum`` (3,),
    friction plus noise stored in ``flangevin`` when ``tally``. ``biased``: ``v`` holds the thermal
    velocities (a temperature compute's bias taken off), and a component exactly 0 there gets no
    noise (LAMMPS's test: a compute masks the particles it leaves out by v = 0)."""
    noise_sum[:] = 0.0
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        friction, amplitude = friction_and_amplitude(mass[i], ratio[type_[i]], damp, noise_scale)
        u0, u1, u2, _ = particle_uniforms(seed, step, tag[i], STREAM)
        n0, n1, n2 = amplitude * (u0 - 0.5), amplitude * (u1 - 0.5), amplitude * (u2 - 0.5)
        if biased:
            n0 = 0.0 if v[i, 0] == 0.0 else n0
            n1 = 0.0 if v[i, 1] == 0.0 else n1
            n2 = 0.0 if v[i, 2] == 0.0 else n2
        d0, d1, d2 = -friction * v[i, 0], -friction * v[i, 1], -friction * v[i, 2]
        f[i, 0] += d0 + n0
        f[i, 1] += d1 + n1
        f[i, 2] += d2 + n2
        noise_sum[0] += n0
        noise_sum[1] += n1
        noise_sum[2] += n2
        if tally:
            flangevin[i, 0] = d0 + n0
            flangevin[i, 1] = d1 + n1
            flangevin[i, 2] = d2 + n2


@njit(cache=True)
def gjf_forces(v, f, tag, type_, mass, mask, groupbit, nlocal, damp, noise_scale, ratio, seed, step, stream,
               gjfa, gjfsib, lv, franprev, noise_sum, keep, flangevin):
    """GJF's post_force: f <- a (f + friction + (beta_new + beta_old)/2), Gaussian noise of variance
    2 kT m/(dt damp ratio) (``noise_scale`` = sqrt(2 kT/(dt damp)) in force units); lv <- sqrt(1/b) v,
    the 2GJ half-step velocity; ``flangevin`` (when ``keep``) the force LAMMPS tallies,
    (friction + beta_old) sqrt(b)."""
    noise_sum[:] = 0.0
    for i in range(nlocal):
        if not mask[i] & groupbit:
            continue
        friction, amplitude = friction_and_amplitude(mass[i], ratio[type_[i]], damp, noise_scale)
        g0, g1, g2, _ = particle_gaussians(seed, step, tag[i], stream)
        fresh = (amplitude * g0, amplitude * g1, amplitude * g2)
        for d in range(3):
            drag = -friction * v[i, d]
            previous = franprev[i, d]
            mean = 0.5 * (fresh[d] + previous)
            franprev[i, d] = fresh[d]
            lv[i, d] = gjfsib * v[i, d]
            f[i, d] = gjfa * (f[i, d] + drag + mean)
            noise_sum[d] += gjfa * mean
            if keep:
                flangevin[i, d] = (drag + previous) / gjfsib


@njit(cache=True)
def shift_forces(f, flangevin, mask, groupbit, nlocal, mean, tally):
    """zero yes: the group's mean random force taken off each of its particles (and off the tally)."""
    for i in range(nlocal):
        if mask[i] & groupbit:
            for d in range(3):
                f[i, d] -= mean[d]
                if tally:
                    flangevin[i, d] -= mean[d]


@njit(cache=True)
def omega_torques(omega, torque, radius, mass, tag, type_, mask, groupbit, nlocal, damp, noise_scale, ratio,
                  seed, step):
    """Rotational friction -(10/3) I omega/(damp ratio) and noise sqrt(I/ratio) ``noise_scale``
    (u - 1/2), ``noise_scale`` = sqrt(80 kT/(dt damp)) in torque units, on spheres of radius > 0."""
    for i in range(nlocal):
        if not mask[i] & groupbit or radius[i] <= 0.0:
            continue
        inertia = SPHERE_INERTIA * mass[i] * radius[i] * radius[i]
        r = ratio[type_[i]]
        friction = ROTATION_FACTOR * inertia / (damp * r)
        amplitude = noise_scale * math.sqrt(inertia / r)
        u0, u1, u2, _ = particle_uniforms(seed, step, tag[i], ROTATION_STREAM)
        torque[i, 0] += -friction * omega[i, 0] + amplitude * (u0 - 0.5)
        torque[i, 1] += -friction * omega[i, 1] + amplitude * (u1 - 0.5)
        torque[i, 2] += -friction * omega[i, 2] + amplitude * (u2 - 0.5)


@njit(cache=True)
def power(flangevin, v, mask, groupbit, nlocal):
    """sum_i F_i . v_i over the group: the rate at which the thermostat's forces do work."""
    total = 0.0
    for i in range(nlocal):
        if mask[i] & groupbit:
            total += flangevin[i, 0] * v[i, 0] + flangevin[i, 1] * v[i, 1] + flangevin[i, 2] * v[i, 2]
    return total


@njit(cache=True)
def gjf_setup_before(v, f, mass, mask, groupbit, nlocal, half_dt, divisor):
    """Before the setup forces of a gjf run: the reported velocity taken back half a kick and
    divided by a/b, as LAMMPS's setup."""
    for i in range(nlocal):
        if mask[i] & groupbit:
            for d in range(3):
                v[i, d] = (v[i, d] - half_dt / mass[i] * f[i, d]) / divisor


@njit(cache=True)
def gjf_setup_after(v, f, lv, mass, mask, groupbit, nlocal, half_dt):
    """After them: half a kick with the scaled forces, kept as the integrator's velocity."""
    for i in range(nlocal):
        if mask[i] & groupbit:
            for d in range(3):
                v[i, d] += half_dt / mass[i] * f[i, d]
                lv[i, d] = v[i, d]


@njit(cache=True)
def gjf_initial(v, f, lv, mask, groupbit, nlocal, gjfa):
    """Before fix nve's first half-kick: the forces unscaled, the integrator's velocity restored."""
    for i in range(nlocal):
        if mask[i] & groupbit:
            for d in range(3):
                f[i, d] /= gjfa
                v[i, d] = lv[i, d]


@njit(cache=True)
def gjf_report(v, f, lv, flangevin, franprev, mass, mask, groupbit, nlocal, half_dt, gjfa, gjfsib, dt_over_damp,
               full):
    """End of step: the integrator's velocity kept in ``lv``, the reported one put in ``v``: the 2GJ
    half-step velocity (vhalf) or GJF's on-site velocity (vfull), as LAMMPS computes them."""
    b_inv = gjfsib * gjfsib
    for i in range(nlocal):
        if mask[i] & groupbit:
            dtfm = half_dt / mass[i]
            for d in range(3):
                kept = v[i, d]
                if full:
                    v[i, d] = (0.5 * b_inv * (kept + dtfm * f[i, d] / gjfa)
                               + 0.5 * dtfm * (gjfsib * flangevin[i, d] - franprev[i, d])
                               + (0.5 * gjfsib * gjfa + 0.25 * dt_over_damp / gjfsib) * lv[i, d])
                else:
                    v[i, d] = lv[i, d]
                lv[i, d] = kept


class FixLangevin(NamedTemperature, Fix):
    name = "langevin"
    minimize_idle = True         # LAMMPS's fix langevin has no min_post_force (recorded: a minimization ignores it)
    usage = ("fix ID GROUP langevin T_START T_STOP DAMP SEED [scale TYPE RATIO]... [zero yes|no] "
             "[omega yes|no] [tally yes|no] [gjf no|vfull|vhalf]")

    class Args(StyleArgs):
        t_start: float = param(ge=0, unit="temperature")
        t_stop: float = param(ge=0, unit="temperature")
        damp: float = param(gt=0, unit="time")
        seed: int = param(ge=1, lt=2 ** 63, unit="dimensionless")
        scale: list[tuple[int, float]] = keyword(default_factory=list, unit="dimensionless")
        zero: bool = keyword(False)
        omega: bool = keyword(False)
        tally: bool = keyword(False)
        gjf: Literal["no", "vfull", "vhalf"] = keyword("no")
        angmom: str | None = keyword(None)

    def __new__(cls, sim, id, group, args):
        # only the hooks a scene calls for: end_of_step with tally or gjf, initial_integrate with gjf
        if cls is FixLangevin and args.gjf != "no":
            cls = FixLangevinGJF
        elif cls is FixLangevin and args.tally:
            cls = FixLangevinTally
        return super().__new__(cls)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if args.angmom not in (None, "no"):
            raise ScriptError("angmom thermostats the angular momentum of aspherical (ellipsoid) particles, "
                              "which pdps does not have (use omega yes for spheres)")
        self.ratio = np.ones(sim.ntypes + 1)
        for ptype, ratio in args.scale:
            if not 1 <= ptype <= sim.ntypes:
                raise ScriptError(f"scale: type {ptype} is out of range 1..{sim.ntypes}")
            if not ratio > 0:
                raise ScriptError(f"scale: ratio must be > 0 (got {ratio:g})")
            self.ratio[ptype] = ratio
        p = sim.particles
        if args.omega and not all(p.has(name) for name in ("radius", "rmass", "omega", "torque")):
            raise ScriptError("omega yes needs finite-size particles (per-particle radius, mass, omega and "
                              "torque): use particle_style sphere before creating the box")
        self.gjf = args.gjf != "no"
        # f_ID is the bath's energy (extensive) with tally, else the target temperature
        self.extensive = args.tally
        self.noise_sum = np.zeros(3)
        self.no_forces = np.zeros((0, 3))
        self.last_target = None
        self.energy_total = 0.0      # this rank's sum of dt P_n, from half a step before the run
        self.energy_onestep = 0.0    # this rank's P_n of the last step
        # per-particle arrays follow their particles through sorting and migration
        self.force_name = f"langevin_force_{id}"
        if args.tally or args.gjf == "vfull":
            self._fresh_array(self.force_name)

    def check_temperature(self, ident, compute):
        if self.gjf and hasattr(compute, "velocity_bias"):
            raise ScriptError(f"fix {self.id} langevin gjf with a temperature that has a bias ({ident}, "
                              f"{compute.name}) is not supported; use gjf no")

    def _fresh_array(self, name):
        p = self.sim.particles
        p.request(name, width=3)
        p.arrays[name][:] = 0.0         # a fix defined again starts afresh, as LAMMPS's

    def target(self, sim):
        """The temperature the thermostat holds at this step (the ramp)."""
        return sim.ramp(self.args.t_start, self.args.t_stop)

    def _forces(self, sim):
        """Friction and noise on this step (uniform noise; Gaussian and GJF's scaling with gjf)."""
        p = sim.particles
        self.last_target = self.target(sim)
        kt = sim.units.boltz * self.last_target / sim.units.mvv2e
        # forces in force units: m v / damp and the noise are divided by ftm2v (1 in lj and si), as LAMMPS
        ftm2v = sim.units.ftm2v
        groupbit = sim.groups.bit(self.group)
        key = sim.random_key(self.args.seed)
        mass = observables.masses(sim)
        tally = self.args.tally
        forces = p.arrays[self.force_name] if self.force_name in p.arrays else self.no_forces
        if self.gjf:
            noise_scale = math.sqrt(2.0 * kt / (sim.dt * self.args.damp)) / ftm2v
            stream = SETUP_STREAM if sim.in_setup else STREAM
            gjf_forces(p.v, p.f, p.tag, p.type, mass, p.mask, groupbit, p.nlocal, self.args.damp * ftm2v,
                       noise_scale, self.ratio, key, sim.step, stream, self.gjfa, self.gjfsib,
                       p.arrays[self.lv_name], p.arrays[self.franprev_name], self.noise_sum,
                       tally or self.args.gjf == "vfull", forces)
        else:
            noise_scale = math.sqrt(24.0 * kt / (sim.dt * self.args.damp)) / ftm2v
            thermal = self.thermal_velocities(sim)
            langevin_forces(p.v if thermal is None else thermal, p.f, p.tag, p.type, mass, p.mask, groupbit,
                            p.nlocal, self.args.damp * ftm2v, noise_scale, self.ratio, key, sim.step,
                            self.noise_sum, tally, forces, thermal is not None)
        if self.args.zero:
            # LAMMPS's zero yes: the mean random force of the group taken off each of its particles
            count = observables.count(sim, self.group)
            if count:
                mean = np.asarray(sim.comm.sum(self.noise_sum), dtype=np.float64) / count
                shift_forces(p.f, forces, p.mask, groupbit, p.nlocal, mean, tally)
        if self.args.omega:
            rotation_scale = math.sqrt(80.0 * kt / (sim.dt * self.args.damp)) / ftm2v
            omega_torques(p.omega, p.torque, p.radius, mass, p.tag, p.type, p.mask, groupbit, p.nlocal,
                          self.args.damp * ftm2v, rotation_scale, self.ratio, key, sim.step)

    def setup(self, sim):
        self._forces(sim)
        self._start_tally(sim)

    def post_force(self, sim):
        self._forces(sim)

    def _start_tally(self, sim, velocities="v", sign=1.0):
        """LAMMPS's tally restarts with each run, from half a step of its first power."""
        if self.args.tally:
            p = sim.particles
            self.energy_onestep = power(p.arrays[self.force_name], p.arrays[velocities], p.mask,
                                        sim.groups.bit(self.group), p.nlocal)
            self.energy_total = sign * 0.5 * self.energy_onestep * sim.dt

    def _add_power(self, sim, velocities="v"):
        p = sim.particles
        self.energy_onestep = power(p.arrays[self.force_name], p.arrays[velocities], p.mask,
                                    sim.groups.bit(self.group), p.nlocal)
        self.energy_total += self.energy_onestep * sim.dt

    def energy_exchanged(self, sim):
        """The energy the bath took from the particles since the run started (all ranks), -W."""
        return -float(sim.comm.sum(self.energy_total - 0.5 * self.energy_onestep * sim.dt))

    def ecouple(self, sim):
        """LAMMPS's ecouple: the tallied energy (tally yes), else nothing."""
        return self.energy_exchanged(sim) if self.args.tally else 0.0

    def scalar(self, sim):
        """f_ID: with tally yes the energy the bath took (ecouple); else the target temperature of
        the last step the thermostat acted on (between runs, the one the last run ended at)."""
        if self.args.tally:
            return self.energy_exchanged(sim)
        return self.last_target if self.last_target is not None else self.target(sim)


class FixLangevinTally(FixLangevin):
    """tally yes: the work of the thermostat's forces added up at the end of each step."""

    def end_of_step(self, sim):
        self._add_power(sim)


class FixLangevinGJF(FixLangevin):
    """gjf vfull|vhalf: the Gronbech-Jensen-Farago integrator woven into fix nve's steps."""

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.lv_name = f"langevin_lv_{id}"
        self.franprev_name = f"langevin_franprev_{id}"
        self._fresh_array(self.lv_name)
        self._fresh_array(self.franprev_name)

    def reset_dt(self, sim):
        """GJF's constants of the step (each run's start; a new step mid-run, as LAMMPS's reset_dt)."""
        if 2.0 * self.args.damp == sim.dt:
            raise ScriptError(f"fix {self.id} langevin gjf: DAMP must not be dt/2 (got {self.args.damp:g} "
                              f"with timestep {sim.dt:g}), which makes GJF's a = 0")
        half = sim.dt / (2.0 * self.args.damp)
        self.gjfa = (1.0 - half) / (1.0 + half)
        self.gjfsib = math.sqrt(1.0 + half)

    def init_run(self, sim):
        super().init_run(sim)
        if 2.0 * self.args.damp == sim.dt:
            raise ScriptError(f"fix {self.id} langevin gjf: DAMP must not be dt/2 (got {self.args.damp:g} "
                              f"with timestep {sim.dt:g}), which makes GJF's a = 0")
        names = list(sim.fixes)
        integrators = [fix for fix in sim.fixes.values() if fix.time_integrate]
        if not integrators:
            raise ScriptError(f"fix {self.id} langevin gjf needs an integrator (fix nve, nve/sphere, nve/limit...) "
                              "to move the particles; define it after this fix")
        first = integrators[0]
        if names.index(first.id) < names.index(self.id):
            raise ScriptError(f"fix {self.id} langevin gjf must be defined before fix {first.id} "
                              f"({first.name}), whose steps it wraps")
        self.reset_dt(sim)

    def setup(self, sim):
        p = sim.particles
        groupbit = sim.groups.bit(self.group)
        half_dt = 0.5 * sim.dt * sim.units.ftm2v
        mass = observables.masses(sim)
        gjf_setup_before(p.v, p.f, mass, p.mask, groupbit, p.nlocal, half_dt, self.gjfa * self.gjfsib ** 2)
        self._forces(sim)
        gjf_setup_after(p.v, p.f, p.arrays[self.lv_name], mass, p.mask, groupbit, p.nlocal, half_dt)
        self._start_tally(sim, velocities=self.lv_name, sign=-1.0)

    def initial_integrate(self, sim):
        p = sim.particles
        gjf_initial(p.v, p.f, p.arrays[self.lv_name], p.mask, sim.groups.bit(self.group), p.nlocal, self.gjfa)

    def end_of_step(self, sim):
        p = sim.particles
        if self.args.tally:
            self._add_power(sim, velocities=self.lv_name)
        forces = p.arrays[self.force_name] if self.force_name in p.arrays else self.no_forces
        gjf_report(p.v, p.f, p.arrays[self.lv_name], forces, p.arrays[self.franprev_name],
                   observables.masses(sim), p.mask, sim.groups.bit(self.group), p.nlocal,
                   0.5 * sim.dt * sim.units.ftm2v, self.gjfa, self.gjfsib, sim.dt / self.args.damp,
                   self.args.gjf == "vfull")
