r"""Fixes ``nvt``, ``npt`` and ``nph``: Nose-Hoover chain thermostats and the Martyna-Tobias-Klein
barostat, integrated as LAMMPS's fix nh (the time-reversible measure-preserving splitting of
Tuckerman, Alejandre, Lopez-Rendon, Jochim and Martyna, J. Phys. A 39, 5629 (2006); equations of
Martyna, Tobias and Klein, J. Chem. Phys. 101, 4177 (1994); chains of Martyna, Klein and
Tuckerman, J. Chem. Phys. 97, 2635 (1992); Shinoda, Shiga and Mikami, PRB 69, 134103 (2004)).

The particles' equations of motion, for barostatted axes a (no barostat: omega_dot = 0)::

    dx_a/dt = v_a + omega_dot_a x_a
    dv_a/dt = F_a / m - (omega_dot_a + mtk_2) v_a - eta_dot_1 v_a,    mtk_2 = sum_a omega_dot_a / (d_p N)
    W domega_dot_a/dt = (P_a - P_target) V + mtk_1 - etap_dot_1 W omega_dot_a,
                        mtk_1 = (N_dof k_B T or sum_a m v_a^2) / (d_p N)
    Q_1 deta_dot_1/dt = N_dof k_B T - N_dof k_B T_target - Q_1 eta_dot_1 eta_dot_2        (chain of M)

with the thermostat masses Q_1 = N_dof k_B T_t / omega_T^2, Q_k = k_B T_t / omega_T^2
(omega_T = 1/Tdamp), barostat masses W = (N + 1) k_B T_t / omega_P^2 (omega_P = 1/Pdamp), N the
number of particles, d_p the number of barostatted axes. Without a thermostat (nph) T_t is
``ptemp``, or else the temperature at the first run's start (an error below 1e-6, as in LAMMPS
2025: give ptemp). The box follows dL_a/dt = omega_dot_a L_a about the fixed point; particles of
the dilate group keep their fractional coordinates. The conserved quantity is pe + ke + ecouple,
ecouple being this fix's scalar ``f_ID`` (chain and barostat kinetic and potential terms,
P_target (V - V_0)).

Temperatures and pressures are LAMMPS's ``compute temp`` (of the fix's group for nvt, of all
particles for npt and nph: N_dof = d N - d less what other fixes remove) and ``compute pressure``
(its kinetic part from that temperature). ``fix_modify ID temp CTEMP`` makes the fix read the temp
compute CTEMP instead (its group's T and N_dof: the thermostat still scales the fix's group; a
warning when CTEMP is not of group all) and points the pressure at CTEMP too, as LAMMPS does: the
fix's own pressure, or the compute that ``fix_modify ID press CPRESS`` named, whose TEMP-ID is
changed to CTEMP. ``fix_modify ID press CPRESS`` makes the barostat read that pressure compute with
its own temperature; where that is another compute than the fix's, LAMMPS reuses its value within a
step, so the pressure of final_integrate has the kinetic part of initial_integrate's, and pdps does
the same. Targets ramp from start to stop over a run (LAMMPS's delta = (step - first) / (last -
first)).

Syntax (LAMMPS's)::

    fix ID GROUP nvt temp TSTART TSTOP TDAMP [keyword value ...]
    fix ID GROUP npt temp TSTART TSTOP TDAMP iso|aniso|x|y|z PSTART PSTOP PDAMP [keyword value ...]
    fix ID GROUP nph iso|aniso|x|y|z PSTART PSTOP PDAMP [keyword value ...]

    couple xyz|xy|yz|xz|none   axes whose pressures are averaged and driven together (iso: xyz)
    tchain M (3), pchain M (3) chain lengths of the particle and barostat thermostats
    mtk yes|no (yes)           the MTK correction terms
    tloop N (1), ploop N (1)   sub-cycles of the chain integration
    nreset N (0)               reference cell reset every N steps (x, y, z keywords)
    drag D (0)                 damping of the chain and barostat velocities
    dilate all|GROUP (all)     particles whose positions the box change carries
    fixedpoint X Y Z           the point that stays put when the box changes (the box's centre)
    ptemp T                    the barostat's temperature for its masses (nph only: with temp,
                               the target temperature is that, and LAMMPS refuses both)
    flip yes|no (yes)          accepted, no effect: it lets a tilted box flip (pdps has no tilt)
    disc                       accepted, no effect: LAMMPS's fix nh skips it; only its /sphere
                               variants read it (a 2-d disc's moment of inertia), which pdps lacks

``tri``, ``xy``, ``xz``, ``yz`` and ``scalexy``/``scalexz``/``scaleyz`` concern a triclinic box,
which pdps does not have: refused. ``fix_modify ID temp CTEMP`` and ``press CPRESS`` as above.

Examples::

    fix 1 all nvt temp 1.0 1.0 0.5
    fix 1 all npt temp 1.0 1.0 0.5 iso 0.5 0.5 5.0
    fix 1 all nph aniso 0.5 0.5 5.0 couple xy ptemp 1.2
    compute hot all temp
    fix_modify 1 temp hot
"""

import math
from typing import Literal

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, observables

Triple = tuple[float, float, float] | None


@njit(cache=True, inline="always")
def scale_row(v, i, fx, fy, fz):
    v[i, 0] *= fx
    v[i, 1] *= fy
    v[i, 2] *= fz


@njit(cache=True)
def scale_velocities(v, mask, groupbit, nlocal, fx, fy, fz):
    for i in range(nlocal):
        if mask[i] & groupbit:
            scale_row(v, i, fx, fy, fz)


@njit(cache=True)
def press_scale_velocities(v, mask, groupbit, nlocal, fx, fy, fz):
    """The barostat's half-step velocity scaling (LAMMPS's nh_v_press: the factor applied twice,
    not its square, so that the rounding is LAMMPS's)."""
    for i in range(nlocal):
        if mask[i] & groupbit:
            scale_row(v, i, fx, fy, fz)
            scale_row(v, i, fx, fy, fz)


@njit(cache=True)
def kick(v, f, mass, mask, groupbit, nlocal, dtf):
    for i in range(nlocal):
        if mask[i] & groupbit:
            dtfm = dtf / mass[i]
            v[i, 0] += dtfm * f[i, 0]
            v[i, 1] += dtfm * f[i, 1]
            v[i, 2] += dtfm * f[i, 2]


@njit(cache=True)
def drift(x, v, mask, groupbit, nlocal, dt):
    for i in range(nlocal):
        if mask[i] & groupbit:
            x[i, 0] += dt * v[i, 0]
            x[i, 1] += dt * v[i, 1]
            x[i, 2] += dt * v[i, 2]


@njit(cache=True)
def mass_velocity_squares(v, mass, mask, groupbit, nlocal):
    """sum m v_x^2, sum m v_y^2, sum m v_z^2 and sum m v^2 over the group (this rank)."""
    out = np.zeros(4)
    for i in range(nlocal):
        if mask[i] & groupbit:
            m = mass[i]
            out[0] += m * v[i, 0] * v[i, 0]
            out[1] += m * v[i, 1] * v[i, 1]
            out[2] += m * v[i, 2] * v[i, 2]
            out[3] += (v[i, 0] * v[i, 0] + v[i, 1] * v[i, 1] + v[i, 2] * v[i, 2]) * m
    return out


COUPLE = {"xyz": (0, 1, 2), "xy": (0, 1), "yz": (1, 2), "xz": (0, 2), "none": ()}


class FixNH(Fix):
    """What nvt, npt and nph share (LAMMPS's FixNH); the subclasses say which controls they need."""
    can_energy = False
    extensive = True
    needs_temp: bool | None = None       # True: temp required; False: refused
    needs_press: bool | None = None

    class Args(StyleArgs):
        temp: Triple = keyword(None, unit="temperature")
        iso: Triple = keyword(None, unit="pressure")
        aniso: Triple = keyword(None, unit="pressure")
        x: Triple = keyword(None, unit="pressure")
        y: Triple = keyword(None, unit="pressure")
        z: Triple = keyword(None, unit="pressure")
        tri: Triple = keyword(None, unit="pressure")
        xy: Triple = keyword(None, unit="pressure")
        xz: Triple = keyword(None, unit="pressure")
        yz: Triple = keyword(None, unit="pressure")
        couple: Literal["xyz", "xy", "yz", "xz", "none"] | None = keyword(None)
        tchain: int = keyword(3, ge=1, le=100, unit="1")
        pchain: int = keyword(3, ge=0, le=100, unit="1")
        mtk: Literal["yes", "no"] = keyword("yes")
        tloop: int = keyword(1, ge=1, le=1000, unit="1")
        ploop: int = keyword(1, ge=1, le=1000, unit="1")
        nreset: int = keyword(0, ge=0, unit="timesteps")
        drag: float = keyword(0.0, ge=0, unit="dimensionless")
        dilate: str = keyword("all")
        fixedpoint: Triple = keyword(None, unit="distance")
        ptemp: float | None = keyword(None, unit="temperature", gt=0)
        flip: Literal["yes", "no"] = keyword("yes")
        disc: tuple[()] | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        a = args
        sim.require_box(f"fix {self.name}")
        for tilt in ("tri", "xy", "xz", "yz"):
            if getattr(a, tilt) is not None:
                raise ScriptError(f"{tilt}: pdps boxes are orthogonal (no tilt), so only iso, aniso, x, y "
                                  "and z can be barostatted")
        dim = sim.dimension
        self.tstat = a.temp is not None
        if self.tstat:
            self.t_start, self.t_stop, t_period = a.temp
            if self.t_start <= 0 or self.t_stop <= 0:
                raise ScriptError(f"temp: target temperatures must be > 0 (got {self.t_start:g} {self.t_stop:g})")
            if t_period <= 0:
                raise ScriptError(f"temp: damping must be > 0 (got {t_period:g})")
            self.t_freq = 1.0 / t_period
        self.p_start, self.p_stop = np.zeros(3), np.zeros(3)
        self.p_period, self.p_flag = np.zeros(3), np.zeros(3, dtype=bool)
        pcouple = "none"
        for word in ("iso", "aniso"):
            values = getattr(a, word)
            if values is not None:
                pcouple = "xyz" if word == "iso" else "none"
                self.p_start[:dim], self.p_stop[:dim], self.p_period[:dim] = values
                self.p_flag[:dim] = True
        self.deviatoric = False
        for d, word in enumerate("xyz"):
            values = getattr(a, word)
            if values is not None:
                if d == 2 and dim == 2:
                    raise ScriptError("z: a 2-d simulation has no z pressure to control")
                self.p_start[d], self.p_stop[d], self.p_period[d] = values
                self.p_flag[d] = True
                self.deviatoric = True
        if a.couple is not None:
            pcouple = a.couple
        self.pstat = self.changes_box = bool(self.p_flag.any())
        controls = f"fix {self.name}"
        if self.needs_temp is True and not self.tstat:
            raise ScriptError(f"{controls} needs temp TSTART TSTOP TDAMP")
        if self.needs_temp is False and self.tstat:
            raise ScriptError(f"{controls} controls no temperature (use fix npt for temp and pressure)")
        if self.needs_press is True and not self.pstat:
            raise ScriptError(f"{controls} needs a pressure: iso, aniso, x, y or z PSTART PSTOP PDAMP")
        if self.needs_press is False and self.pstat:
            raise ScriptError(f"{controls} controls no pressure (use fix npt for temp and pressure)")
        if a.ptemp is not None and self.tstat:
            raise ScriptError(f"ptemp: {controls} has a thermostat, whose target temperature sets the "
                              "barostat's mass (ptemp is for nph)")
        axes = COUPLE[pcouple]
        if dim == 2 and 2 in axes and pcouple != "xyz":
            raise ScriptError(f"couple {pcouple}: a 2-d simulation has no z pressure to couple")
        coupled = tuple(d for d in axes if d < dim)
        if self.pstat:
            if any(not self.p_flag[d] for d in coupled):
                raise ScriptError(f"couple {pcouple}: every coupled axis needs a pressure (iso, aniso or x/y/z)")
            if any((self.p_start[d], self.p_stop[d], self.p_period[d])
                   != (self.p_start[coupled[0]], self.p_stop[coupled[0]], self.p_period[coupled[0]])
                   for d in coupled):
                raise ScriptError(f"couple {pcouple}: coupled axes need the same PSTART PSTOP PDAMP")
            for d in range(3):
                if self.p_flag[d] and self.p_period[d] <= 0:
                    raise ScriptError(f"{'xyz'[d]}: pressure damping must be > 0 (got {self.p_period[d]:g})")
                if self.p_flag[d] and not sim.box.periodic[d]:
                    raise ScriptError(f"{'xyz'[d]} is not periodic: a barostat needs periodic axes it changes")
        self.pcouple = pcouple
        self.iso = pcouple == "xyz" or (dim == 2 and pcouple == "xy")
        self.p_freq = np.where(self.p_flag, 1.0 / np.where(self.p_flag, self.p_period, 1.0), 0.0)
        self.mtchain, self.mpchain = a.tchain, a.pchain
        self.mtk = a.mtk == "yes"
        self.dilate = a.dilate
        if self.dilate != "all":
            sim.require_group(self.dilate)
        self.fixedpoint = (0.5 * (sim.box.lo + sim.box.hi) if a.fixedpoint is None
                           else np.asarray(a.fixedpoint, dtype=np.float64))
        # the chain variables carry over from run to run (LAMMPS keeps them in the fix)
        self.eta = np.zeros(self.mtchain)
        self.eta_dot = np.zeros(self.mtchain + 1)       # one extra, always 0, ends the chain
        self.eta_dotdot = np.zeros(self.mtchain)
        self.eta_mass = np.zeros(self.mtchain)
        self.omega = np.zeros(3)
        self.omega_dot = np.zeros(3)
        self.omega_mass = np.zeros(3)
        self.etap = np.zeros(self.mpchain)
        self.etap_dot = np.zeros(self.mpchain + 1)
        self.etap_dotdot = np.zeros(self.mpchain)
        self.etap_mass = np.zeros(self.mpchain)
        self.vol0 = self.t0 = 0.0
        self.h0_inv = np.zeros(3)
        self.p_target, self.p_current = np.zeros(3), np.zeros(3)
        self.p_hydro = 0.0
        self.t_target = self.ke_target = self.t_current = 0.0
        self.mtk_term1 = self.mtk_term2 = 0.0
        self.sigma, self.fdev = np.zeros(3), np.zeros(3)
        self.own_temp_group = self.temp_group = group if self.name == "nvt" else "all"
        # fix_modify temp/press: the computes named (None: the fix's own, LAMMPS's ID_temp, ID_press)
        self.temp_id = self.press_id = None
        self.press_temp_group = self.temp_group
        self.press_tdof = 0.0
        self.press_temp_shared = True     # the pressure's temperature is the fix's own
        self.press_temp_cached = False    # ... or another compute, reused within a step
        self.press_temp_cache = {"scalar": (None, 0.0), "vector": (None, np.zeros(3))}
        self.mvv = np.zeros(3)           # LAMMPS's temperature->vector: sum m v_a^2 (energy units)
        self.virial_diag = np.zeros(3)

    # ---- what the core asks -----------------------------------------------------------------------
    def needs(self, step):
        return {"virial"} if self.pstat else set()

    def _step_constants(self, sim):
        dt = sim.dt
        self.dtv, self.dtf = dt, 0.5 * dt * sim.units.ftm2v
        self.dthalf, self.dt4, self.dt8 = 0.5 * dt, 0.25 * dt, 0.125 * dt
        self.dto = self.dthalf

    def reset_dt(self, sim):
        """A new step mid-run (fix dt/reset): LAMMPS's FixNH::reset_dt redoes these and the drags."""
        self._step_constants(sim)
        self._drags(sim)

    def _drags(self, sim):
        if self.pstat:
            self.p_freq_max = float(self.p_freq.max())
            self.pdrag_factor = 1.0 - sim.dt * self.p_freq_max * self.args.drag / self.args.ploop
        if self.tstat:
            self.tdrag_factor = 1.0 - sim.dt * self.t_freq * self.args.drag / self.args.tloop

    def init_run(self, sim):
        self._step_constants(sim)
        self.boltz, self.nktv2p = sim.units.boltz, sim.units.nktv2p
        self.dim = sim.dimension
        self._drags(sim)
        if self.pstat:
            self.pdim = int(self.p_flag.sum())
            if self.vol0 == 0.0:
                self.vol0 = self._volume(sim)
                self.h0_inv = 1.0 / sim.box.length
            for fix in sim.fixes.values():
                if any(self.p_flag[d] for d in fix.deformed_axes):
                    raise ScriptError(f"fix {self.id} {self.name} and fix {fix.id} deform change the same "
                                      "box length")
        if self.dilate != "all":
            sim.require_group(self.dilate)
        self._resolve_computes(sim)

    def setup(self, sim):
        self.tdof = observables.degrees_of_freedom(sim, self.temp_group)
        if not self.press_temp_shared:
            self.press_tdof = observables.degrees_of_freedom(sim, self.press_temp_group)
        self.natoms = observables.count(sim, "all")
        if self.pstat and self.natoms == 0:
            raise ScriptError(f"fix {self.id} {self.name}: no particles, so no pressure to control")
        self._read_virial(sim)
        if self.tstat:
            self._temp_target(sim)
        elif self.pstat:
            # LAMMPS 2025: ptemp, else the temperature now (no longer a guess of 1 or 300 at T = 0)
            if self.t0 == 0.0:
                if self.args.ptemp is not None:
                    self.t0 = self.args.ptemp
                else:
                    t0 = self._temperature(sim)
                    if t0 < 1e-6:
                        raise ScriptError(f"fix {self.id} {self.name}: the temperature is {t0:g}, too close "
                                          "to 0 to set the barostat's mass; give ptemp T")
                    self.t0 = t0
            self.t_target = self.t0
        if self.pstat:
            self._press_target(sim)
        sums = self._sums(sim, self.temp_group)
        self.t_current = self._temperature(sim, sums)
        if self.pstat:
            self.mvv = sums[:3]
            self._pressure(sim, self.t_current)
        boltz, t_target = self.boltz, self.t_target
        if self.tstat:
            self.eta_mass[0] = self.tdof * boltz * t_target / (self.t_freq * self.t_freq)
            self.eta_mass[1:] = boltz * t_target / (self.t_freq * self.t_freq)
            for ich in range(1, self.mtchain):
                self.eta_dotdot[ich] = ((self.eta_mass[ich - 1] * self.eta_dot[ich - 1] * self.eta_dot[ich - 1]
                                         - boltz * t_target) / self.eta_mass[ich])
        if self.pstat:
            nkt = (self.natoms + 1) * boltz * t_target
            for d in range(3):
                if self.p_flag[d]:
                    self.omega_mass[d] = nkt / (self.p_freq[d] * self.p_freq[d])
            if self.mpchain:
                self.etap_mass[:] = boltz * t_target / (self.p_freq_max * self.p_freq_max)
                for ich in range(1, self.mpchain):
                    self.etap_dotdot[ich] = ((self.etap_mass[ich - 1] * self.etap_dot[ich - 1] * self.etap_dot[ich - 1]
                                              - boltz * t_target) / self.etap_mass[ich])

    def initial_integrate(self, sim):
        if self.pstat and self.mpchain:
            self._nhc_press_integrate()
        if self.tstat:
            self._temp_target(sim)
            self._nhc_temp_integrate(sim)
        if self.pstat:
            # the kinetic energy changed with the thermostat: a fresh pressure (t_current is not reset)
            sums = self._sums(sim, self.temp_group)
            self.mvv = sums[:3]
            self._pressure(sim, self._temperature(sim, sums))
            self._press_target(sim)
            self._omega_dot(sim)
            self._press_velocities(sim)
        p = sim.particles
        kick(p.v, p.f, observables.masses(sim), p.mask, sim.groups.bit(self.group), p.nlocal, self.dtf)
        if self.pstat:
            self._remap(sim)
        drift(p.x, p.v, p.mask, sim.groups.bit(self.group), p.nlocal, self.dtv)
        if self.pstat:
            self._remap(sim)

    def final_integrate(self, sim):
        p = sim.particles
        kick(p.v, p.f, observables.masses(sim), p.mask, sim.groups.bit(self.group), p.nlocal, self.dtf)
        if self.pstat:
            self._press_velocities(sim)
        sums = self._sums(sim, self.temp_group)
        self.t_current = self._temperature(sim, sums)
        if self.pstat:
            self._read_virial(sim)
            self.mvv = sums[:3]
            self._pressure(sim, self.t_current)
            self._omega_dot(sim)
        if self.tstat:
            self._nhc_temp_integrate(sim)
        if self.pstat and self.mpchain:
            self._nhc_press_integrate()

    # ---- fix_modify temp CTEMP, press CPRESS (LAMMPS's modify_param) ----------------------------------
    def modify_param(self, sim, keyword, value):
        if keyword == "temp":
            compute = self._named_compute(sim, value, "gives_temperature", "temperature")
            self.temp_id = value
            if compute.group != "all":
                sim.warn(f"fix {self.id} {self.name}: temperature compute {value} is of group {compute.group}, "
                         "not all (LAMMPS's fix_modify warns so too)")
            if self.pstat and self.press_id is not None:
                # LAMMPS points the pressure compute at the new temperature (reset_extra_compute_fix)
                pressure = sim.computes.get(self.press_id)
                if pressure is None:
                    raise ScriptError(f"temp: pressure compute {self.press_id} of fix {self.id} is not defined")
                pressure.args = pressure.args.model_copy(update={"temperature": value})
            return True
        if keyword == "press":
            if not self.pstat:
                raise ScriptError(f"press: fix {self.id} ({self.name}) controls no pressure")
            self._named_compute(sim, value, "gives_pressure", "pressure")
            self.press_id = value
            return True
        return False

    def _named_compute(self, sim, ident, capability, what):
        """The compute ``ident`` if it gives a ``what`` (its ``capability`` flag), else a one-line error."""
        compute = sim.computes.get(ident)
        if compute is None:
            raise ScriptError(f"compute {ident} is not defined ({what} of fix {self.id})")
        if not getattr(type(compute), capability):
            kind = "temp" if capability == "gives_temperature" else "pressure"
            raise ScriptError(f"compute {ident} ({compute.name}) is not a {kind} compute, so it gives no {what}")
        return compute

    def _resolve_computes(self, sim):
        """The groups whose velocities make the fix's temperature and its pressure's kinetic part, as
        the computes named by fix_modify say at this run (LAMMPS's init)."""
        self.temp_group = self.own_temp_group
        if self.temp_id is not None:
            self.temp_group = self._defined(sim, self.temp_id, "temperature").group
        self.press_temp_shared, self.press_temp_cached = True, False
        self.press_temp_group = self.temp_group
        if self.press_id is None or not self.pstat:
            return
        press_temp = getattr(self._defined(sim, self.press_id, "pressure").args, "temperature", None)
        if press_temp == self.temp_id and press_temp is not None:
            return
        self.press_temp_shared = False
        self.press_temp_group = "all"
        if press_temp is not None:
            self.press_temp_cached = True
            self.press_temp_group = self._defined(sim, press_temp, "temperature").group

    def _defined(self, sim, ident, what):
        compute = sim.computes.get(ident)
        if compute is None:
            raise ScriptError(f"fix {self.id} {self.name}: {what} compute {ident} is not defined")
        return compute

    # ---- restart files: the chains, the barostat and the reference cell go on ---------------------
    def state(self):
        return {name: getattr(self, name).copy() for name in self.SAVED_ARRAYS} | {
            "vol0": self.vol0, "t0": self.t0}

    def restore(self, state):
        for name in self.SAVED_ARRAYS:
            saved = np.asarray(state[name], dtype=np.float64)
            if saved.shape == getattr(self, name).shape:
                getattr(self, name)[:] = saved
        self.vol0, self.t0 = float(state["vol0"]), float(state["t0"])

    SAVED_ARRAYS = ("eta", "eta_dot", "omega", "omega_dot", "etap", "etap_dot", "h0_inv", "fixedpoint")

    # ---- thermo ---------------------------------------------------------------------------------
    def ecouple(self, sim):
        """The energy the fix exchanged with the reservoir (LAMMPS's ecouple; thermo econserve =
        etotal + this)."""
        return self.scalar(sim)

    def scalar(self, sim):
        kt = self.boltz * self.t_target if hasattr(self, "boltz") else 0.0
        energy = 0.0
        if not hasattr(self, "tdof"):
            return 0.0
        if self.tstat:
            energy += self.ke_target * self.eta[0] + 0.5 * self.eta_mass[0] * self.eta_dot[0] * self.eta_dot[0]
            for ich in range(1, self.mtchain):
                energy += kt * self.eta[ich] + 0.5 * self.eta_mass[ich] * self.eta_dot[ich] * self.eta_dot[ich]
        if self.pstat:
            volume = self._volume(sim)
            for d in range(3):
                if self.p_flag[d]:
                    energy += (0.5 * self.omega_dot[d] * self.omega_dot[d] * self.omega_mass[d]
                               + self.p_hydro * (volume - self.vol0) / (self.pdim * self.nktv2p))
            if self.mpchain:
                # LAMMPS's compute_scalar: d_p k_B T for the first barostat chain element, iso too
                energy += self.pdim * kt * self.etap[0] + 0.5 * self.etap_mass[0] * self.etap_dot[0] * self.etap_dot[0]
                for ich in range(1, self.mpchain):
                    energy += kt * self.etap[ich] + 0.5 * self.etap_mass[ich] * self.etap_dot[ich] * self.etap_dot[ich]
            if self.deviatoric:
                energy += self._strain_energy(sim)
        return energy

    # ---- pieces of the integrator (LAMMPS's fix_nh.cpp names) --------------------------------------
    def _volume(self, sim):
        length = sim.box.length
        return float(length[0] * length[1] * length[2]) if sim.dimension == 3 else float(length[0] * length[1])

    def _read_virial(self, sim):
        self.virial_diag = np.asarray(sim.comm.sum(np.asarray(sim.virial[:3], dtype=np.float64)))

    def _sums(self, sim, group):
        p = sim.particles
        local = mass_velocity_squares(p.v, observables.masses(sim), p.mask, sim.groups.bit(group), p.nlocal)
        return np.asarray(sim.comm.sum(local)) * sim.units.mvv2e

    def _temperature(self, sim, sums=None):
        """The fix's temperature; ``sums``: this step's _sums of its group, when already made."""
        if self.tdof <= 0:
            return 0.0
        if sums is None:
            sums = self._sums(sim, self.temp_group)
        return float(sums[3]) / (self.tdof * self.boltz)

    def _pressure(self, sim, t):
        """p_current from LAMMPS's compute pressure (scalar for iso, else the diagonal, then couple).
        Its kinetic part is the fix's temperature ``t`` (iso) or ``self.mvv`` (sum m v_a^2, which
        mtk_term1 reads too), unless fix_modify press named a compute with another temperature."""
        inv_volume = 1.0 / self._volume(sim)
        vir = self.virial_diag
        if self.iso:
            dof = self.tdof
            if not self.press_temp_shared:
                dof, t = self.press_tdof, self._press_temperature(sim, "scalar")
            if self.dim == 3:
                value = (dof * self.boltz * t + vir[0] + vir[1] + vir[2]) / 3.0 * inv_volume * self.nktv2p
            else:
                value = (dof * self.boltz * t + vir[0] + vir[1]) / 2.0 * inv_volume * self.nktv2p
            self.p_current[:] = value
            return
        mvv = self.mvv if self.press_temp_shared else self._press_temperature(sim, "vector")
        tensor = (mvv + vir) * inv_volume * self.nktv2p
        c = self.pcouple
        if c == "xyz":
            self.p_current[:] = 1.0 / 3.0 * (tensor[0] + tensor[1] + tensor[2])
        elif c == "none":
            self.p_current[:] = tensor
        else:
            i, j = COUPLE[c]
            self.p_current[:] = tensor
            self.p_current[i] = self.p_current[j] = 0.5 * (tensor[i] + tensor[j])

    def _press_temperature(self, sim, kind):
        """The pressure compute's own temperature (scalar) or sum m v_a^2 (vector). Where it is
        another compute than the fix's, LAMMPS's compute pressure reuses the value that compute
        gave earlier in the same step: the fix's second pressure of a step (final_integrate) reads
        the kinetic energy of its first (initial_integrate)."""
        step, value = self.press_temp_cache[kind]
        if self.press_temp_cached and step == sim.step:
            return value
        sums = self._sums(sim, self.press_temp_group)
        if kind == "vector":
            value = sums[:3]
        else:
            value = float(sums[3]) / (self.press_tdof * self.boltz) if self.press_tdof > 0 else 0.0
        self.press_temp_cache[kind] = (sim.step, value)
        return value

    def _temp_target(self, sim):
        delta = sim.ramp(0.0, 1.0)
        self.t_target = self.t_start + delta * (self.t_stop - self.t_start)
        self.ke_target = self.tdof * self.boltz * self.t_target

    def _press_target(self, sim):
        delta = sim.ramp(0.0, 1.0)
        self.p_hydro = 0.0
        for d in range(3):
            if self.p_flag[d]:
                self.p_target[d] = self.p_start[d] + delta * (self.p_stop[d] - self.p_start[d])
                self.p_hydro += self.p_target[d]
        self.p_hydro /= self.pdim
        if self.deviatoric:
            self._sigma(sim)

    def _sigma(self, sim):
        n = self.args.nreset
        if n > 0 and (sim.step - sim.run_first_step) % n == 0:
            self.vol0 = self._volume(sim)
            self.h0_inv = 1.0 / sim.box.length
        h0 = self.h0_inv
        for d in range(3):
            self.sigma[d] = self.vol0 * (h0[d] * ((self.p_target[d] - self.p_hydro) * h0[d]))

    def _strain_energy(self, sim):
        h = sim.box.length
        return 0.5 * float(sum(self.sigma[d] * (h[d] * h[d]) for d in range(3))) / self.nktv2p

    def _omega_dot(self, sim):
        volume = self._volume(sim)
        if self.deviatoric:
            h = sim.box.length
            self.fdev = h * (self.sigma * h)
        self.mtk_term1 = 0.0
        if self.mtk:
            if self.iso:
                self.mtk_term1 = self.tdof * self.boltz * self.t_current
            else:
                self.mtk_term1 = float(sum(self.mvv[d] for d in range(3) if self.p_flag[d]))
            self.mtk_term1 /= self.pdim * self.natoms
        for d in range(3):
            if self.p_flag[d]:
                f_omega = ((self.p_current[d] - self.p_hydro) * volume / (self.omega_mass[d] * self.nktv2p)
                           + self.mtk_term1 / self.omega_mass[d])
                if self.deviatoric:
                    f_omega -= self.fdev[d] / (self.omega_mass[d] * self.nktv2p)
                self.omega_dot[d] += f_omega * self.dthalf
                self.omega_dot[d] *= self.pdrag_factor
        self.mtk_term2 = 0.0
        if self.mtk:
            self.mtk_term2 = float(sum(self.omega_dot[d] for d in range(3) if self.p_flag[d]))
            self.mtk_term2 /= self.pdim * self.natoms

    def _press_velocities(self, sim):
        factor = [_exp(-self.dt4 * (self.omega_dot[d] + self.mtk_term2)) for d in range(3)]
        p = sim.particles
        press_scale_velocities(p.v, p.mask, sim.groups.bit(self.group), p.nlocal, *factor)

    def _remap(self, sim):
        self.omega += self.dto * self.omega_dot
        box = sim.box
        lo, hi = box.lo.copy(), box.hi.copy()
        fixed = self.fixedpoint
        for d in range(3):
            if self.p_flag[d]:
                expfac = _exp(self.dto * self.omega_dot[d])
                lo[d] = (lo[d] - fixed[d]) * expfac + fixed[d]
                hi[d] = (hi[d] - fixed[d]) * expfac + fixed[d]
        sim.change_box(lo, hi, remap=self.dilate)

    def _nhc_temp_integrate(self, sim):
        boltz, t_target, tf = self.boltz, self.t_target, self.t_freq
        eta, eta_dot, eta_dotdot, eta_mass = self.eta, self.eta_dot, self.eta_dotdot, self.eta_mass
        kecurrent = self.tdof * boltz * self.t_current
        eta_mass[0] = self.tdof * boltz * t_target / (tf * tf)
        eta_mass[1:] = boltz * t_target / (tf * tf)
        eta_dotdot[0] = (kecurrent - self.ke_target) / eta_mass[0] if eta_mass[0] > 0 else 0.0
        ncfac = 1.0 / self.args.tloop
        dt4, dt8, dthalf, drag = self.dt4, self.dt8, self.dthalf, self.tdrag_factor
        p = sim.particles
        for _ in range(self.args.tloop):
            for ich in range(self.mtchain - 1, 0, -1):
                expfac = _exp(-ncfac * dt8 * eta_dot[ich + 1])
                eta_dot[ich] *= expfac
                eta_dot[ich] += eta_dotdot[ich] * ncfac * dt4
                eta_dot[ich] *= drag
                eta_dot[ich] *= expfac
            expfac = _exp(-ncfac * dt8 * eta_dot[1])
            eta_dot[0] *= expfac
            eta_dot[0] += eta_dotdot[0] * ncfac * dt4
            eta_dot[0] *= drag
            eta_dot[0] *= expfac
            factor_eta = _exp(-ncfac * dthalf * eta_dot[0])
            scale_velocities(p.v, p.mask, sim.groups.bit(self.group), p.nlocal, factor_eta, factor_eta, factor_eta)
            self.t_current *= factor_eta * factor_eta
            kecurrent = self.tdof * boltz * self.t_current
            eta_dotdot[0] = (kecurrent - self.ke_target) / eta_mass[0] if eta_mass[0] > 0 else 0.0
            for ich in range(self.mtchain):
                eta[ich] += ncfac * dthalf * eta_dot[ich]
            eta_dot[0] *= expfac
            eta_dot[0] += eta_dotdot[0] * ncfac * dt4
            eta_dot[0] *= expfac
            for ich in range(1, self.mtchain):
                expfac = _exp(-ncfac * dt8 * eta_dot[ich + 1])
                eta_dot[ich] *= expfac
                eta_dotdot[ich] = (eta_mass[ich - 1] * eta_dot[ich - 1] * eta_dot[ich - 1] - boltz * t_target) / eta_mass[ich]
                eta_dot[ich] += eta_dotdot[ich] * ncfac * dt4
                eta_dot[ich] *= expfac

    def _nhc_press_integrate(self):
        kt = self.boltz * self.t_target
        etap, etap_dot, etap_dotdot, etap_mass = self.etap, self.etap_dot, self.etap_dotdot, self.etap_mass
        flags, omega_dot, omega_mass = self.p_flag, self.omega_dot, self.omega_mass

        def barostat_ke():
            return sum(omega_mass[d] * omega_dot[d] * omega_dot[d] for d in range(3) if flags[d])

        # the first chain element couples to the d_p barostat velocities (one for iso)
        lkt_press = kt if self.iso else self.pdim * kt
        etap_dotdot[0] = (barostat_ke() - lkt_press) / etap_mass[0]
        ncfac = 1.0 / self.args.ploop
        dt4, dt8, dthalf, drag = self.dt4, self.dt8, self.dthalf, self.pdrag_factor
        for _ in range(self.args.ploop):
            for ich in range(self.mpchain - 1, 0, -1):
                expfac = _exp(-ncfac * dt8 * etap_dot[ich + 1])
                etap_dot[ich] *= expfac
                etap_dot[ich] += etap_dotdot[ich] * ncfac * dt4
                etap_dot[ich] *= drag
                etap_dot[ich] *= expfac
            expfac = _exp(-ncfac * dt8 * etap_dot[1])
            etap_dot[0] *= expfac
            etap_dot[0] += etap_dotdot[0] * ncfac * dt4
            etap_dot[0] *= drag
            etap_dot[0] *= expfac
            for ich in range(self.mpchain):
                etap[ich] += ncfac * dthalf * etap_dot[ich]
            factor_etap = _exp(-ncfac * dthalf * etap_dot[0])
            for d in range(3):
                if flags[d]:
                    omega_dot[d] *= factor_etap
            etap_dotdot[0] = (barostat_ke() - lkt_press) / etap_mass[0]
            etap_dot[0] *= expfac
            etap_dot[0] += etap_dotdot[0] * ncfac * dt4
            etap_dot[0] *= expfac
            for ich in range(1, self.mpchain):
                expfac = _exp(-ncfac * dt8 * etap_dot[ich + 1])
                etap_dot[ich] *= expfac
                etap_dotdot[ich] = (etap_mass[ich - 1] * etap_dot[ich - 1] * etap_dot[ich - 1] - kt) / etap_mass[ich]
                etap_dot[ich] += etap_dotdot[ich] * ncfac * dt4
                etap_dot[ich] *= expfac


class FixNVT(FixNH):
    name = "nvt"
    time_integrate = True
    usage = "fix ID GROUP nvt temp TSTART TSTOP TDAMP [tchain M] [tloop N] [drag D] [disc]"
    needs_temp, needs_press = True, False


class FixNPT(FixNH):
    name = "npt"
    time_integrate = True
    usage = ("fix ID GROUP npt temp TSTART TSTOP TDAMP iso|aniso|x|y|z PSTART PSTOP PDAMP [couple C] "
             "[tchain M] [pchain M] [mtk yes|no] [tloop N] [ploop N] [nreset N] [drag D] [dilate all|GROUP] "
             "[fixedpoint X Y Z] [flip yes|no] [disc]")
    needs_temp, needs_press = True, True


class FixNPH(FixNH):
    name = "nph"
    time_integrate = True
    usage = ("fix ID GROUP nph iso|aniso|x|y|z PSTART PSTOP PDAMP [couple C] [pchain M] [mtk yes|no] "
             "[ploop N] [nreset N] [drag D] [dilate all|GROUP] [fixedpoint X Y Z] [ptemp T] [flip yes|no] [disc]")
    needs_temp, needs_press = False, True


def _exp(x):
    """exp, inf past the float range (a run that far gone is stopped by the box or finiteness checks)."""
    return math.exp(x) if x < 709.0 else math.inf
