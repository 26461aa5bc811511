"""Energy minimisation: LAMMPS's ``minimize etol ftol maxiter maxeval`` with ``min_style cg|sd|fire``
and ``min_modify dmax D line quadratic|backtrack``.

cg (the default) is LAMMPS's Polak-Ribiere conjugate gradient: each iteration a line search along
h, then h = f + beta h with beta = max(0, (f.f - f.g) / g.g) (restarted when not downhill and every
3N iterations); sd searches along the force itself. The line search is LAMMPS's: the step alpha
starts at min(1, dmax / max|h|) (no coordinate moves more than dmax), is halved until the energy
drops by at least 0.4 alpha f.h (backtrack), and with ``line quadratic`` (the default) the minimum of
the quadratic through the last two points is taken once the energy is within 10 % of quadratic.
Energies (and f.h) are per particle when thermo normalises (lj units), as in LAMMPS.

fire is FIRE 2.0 (Guenole et al., Comput. Mater. Sci. 175, 109584 (2020)) with LAMMPS's defaults:
implicit Euler steps from the timestep, dt grown by 1.1 (to 10 dt) after 20 downhill steps and halved
(to 0.02 dt) with a half step back and zeroed velocities when uphill, mixing alpha from 0.25 shrinking
by 0.99, and no atom moving more than dmax in a step.

Stopping: |E_k - E_k-1| < etol (|E_k| + |E_k-1| + 1e-8) / 2, |f| < ftol (two-norm over all degrees
of freedom), maxiter iterations, maxeval force evaluations, or the line search finding no lower
energy. Each iteration is a timestep (the step counter advances). Fixes act as in LAMMPS, which
calls only the fixes with a min_setup/min_post_force: a fix defining ``min_post_force`` (addforce,
setforce, viscous, enforce2d, wall/lj93, wall/lj126, wall/harmonic) applies its forces after every
force evaluation, the setup's included, and its energy joins the minimized one after ``fix_modify ID
energy yes``; integrators, thermostats and the fixes LAMMPS leaves out (``minimize_idle``: gravity,
freeze, langevin, granular walls) are not called at all; any other fix that changes forces is
refused at the ``minimize`` line.

Fixes may add global degrees of freedom to the search (LAMMPS's extra global dof: fix box/relax's
box lengths): a fix with ``min_dof`` > 0 gives their energy and forces in ``min_energy(sim, fextra)``
(energy units; joined to the minimized energy, its forces to every dot product and norm), keeps the
line search's starting point in ``min_store(sim)``, moves them (and the particles with them) to the
start plus ``alpha`` times its direction in ``min_step(sim, alpha, hextra)``, bounds the step in
``max_alpha(hextra)``, and may reset its reference after a successful line search in
``min_reset_ref(sim)`` (True: the energy is evaluated again). cg and sd only, as LAMMPS.
"""

import math
import time

import numpy as np

from ..errors import ScriptError
from ..state import observables
from .hookspec import FORCE_HOOKS, implements
from .shrink_wrap import shrink_wrap
from .verlet import Verlet

ALPHA_MAX = 1.0
ALPHA_REDUCE = 0.5
BACKTRACK_SLOPE = 0.4
QUADRATIC_TOL = 0.1
EMACH = 1.0e-8
EPS_QUAD = 1.0e-28
EPS_ENERGY = 1.0e-8

STOPPED = {"etol": "energy tolerance", "ftol": "force tolerance", "maxiter": "max iterations",
           "maxeval": "max force evaluations", "downhill": "search direction is not downhill",
           "zeroalpha": "linesearch alpha is zero", "zeroforce": "forces are zero",
           "zeroquad": "quadratic factors are zero"}


class MinSettings:
    """min_style and min_modify: what ``minimize`` uses."""

    def __init__(self):
        self.style = "cg"
        self.dmax = 0.1
        self.line = "quadratic"


class Minimizer(Verlet):
    setup_hook = "min_post_force"

    def __init__(self, sim, settings):
        super().__init__(sim)
        self.settings = settings
        self.neval = 0
        self.extra = []
        self.fextra = self.gextra = self.hextra = np.zeros(0)
        self.box0_length = sim.box.length.copy()
        self.last_thermo = None

    # ---- energy and forces ----------------------------------------------------------------------
    def _norm(self):
        sim = self.sim
        norm = sim.output.thermo.norm
        if norm is None:
            norm = sim.units.name == "lj"
        return float(max(sim.comm.sum(sim.particles.nlocal), 1)) if norm else 1.0

    def energy_force(self):
        """Forces and the energy (per particle where thermo normalises) at the current positions,
        the extra degrees of freedom's energy with it (their forces in ``self.fextra``)."""
        sim, particles = self.sim, self.sim.particles
        # a box a fix changed shifts every periodic image: ghosts made again with the new lengths
        box_changed, sim.run_state.box_changed = sim.run_state.box_changed, False
        if sim.neighbor.decide(particles, sim.comm) or box_changed:
            shrink_wrap(sim)            # as a run's rebuild: a shrink-wrapped box follows the particles
            sim.comm.exchange(particles, sim.box, sim.step)
            self._reneighbor()
            self._follow_wrapped_x0()
        else:
            sim.comm.forward_comm(particles, self.forward)
        self._forces(eflag=True, vflag=True)
        self._call("min_post_force")
        self._fix_contributions()
        self._check_finite()
        self.neval += 1
        return self._energy()

    def _energy(self):
        """The minimized energy of the forces just computed: pe and the extra dof's."""
        energy = observables.potential_energy(self.sim)
        for fix, part in self.extra:
            energy += fix.min_energy(self.sim, self.fextra[part])
        return energy / self._norm()

    def _follow_wrapped_x0(self):
        """After a rebuild wrapped particles across periodic faces, their line-search origins follow
        by whole box lengths (LAMMPS's FixMinimize::reset_coords), so that x0 + alpha h is the same
        point and the next evaluation does not read the wrap as a move past the skin."""
        sim, p = self.sim, self.sim.particles
        n = p.nlocal
        x0, x = p.arrays["minimize_x0"][:n], p.x[:n]
        for d in range(3):
            if not sim.box.periodic[d]:
                continue
            # the origins are positions in the box of the search's start (LAMMPS's box_swap)
            length = self.box0_length[d]
            delta = x[:, d] - x0[:, d]
            wrapped = np.abs(delta) > 0.5 * length
            if wrapped.any():
                x0[wrapped, d] = x[wrapped, d] - (delta[wrapped] - length * np.round(delta[wrapped] / length))

    def _dot(self, a, b):
        return float(self.sim.comm.sum(float(np.einsum("ij,ij->", a, b))))

    # ---- the line search ---------------------------------------------------------------------------
    def _step(self, alpha):
        p = self.sim.particles
        n = p.nlocal
        if not self.extra:
            p.x[:n] = p.arrays["minimize_x0"][:n] + alpha * p.arrays["minimize_h"][:n]
            return self.energy_force()
        # as LAMMPS's alpha_step: back to the start, then the fixes' step (which carries the
        # particles with the box), then the particles' own
        for fix, part in self.extra:
            fix.min_step(self.sim, 0.0, self.hextra[part])
        p.x[:n] = p.arrays["minimize_x0"][:n]
        if alpha > 0.0:
            for fix, part in self.extra:
                fix.min_step(self.sim, alpha, self.hextra[part])
            p.x[:n] += alpha * p.arrays["minimize_h"][:n]
        return self.energy_force()

    def _success(self, ecurrent):
        """A line search's end: a fix resetting its reference (box/relax nreset) evaluates again."""
        if any([fix.min_reset_ref(self.sim) for fix, _ in self.extra]):
            ecurrent = self.energy_force()
            self.neval -= 1         # LAMMPS counts the line search's steps, not this evaluation
        return ecurrent, None

    def linemin(self, eoriginal):
        """(energy, status): LAMMPS's linemin_quadratic or linemin_backtrack along h."""
        sim = self.sim
        p = sim.particles
        norm = self._norm()
        # particles' arrays are new after every rebuild of the ghosts: read them after each step
        fdothall = (self._dot(p.f[:p.nlocal], self._vector("minimize_h")) + float(self.fextra @ self.hextra)) / norm
        if fdothall <= 0.0:
            return eoriginal, "downhill"
        h = self._vector("minimize_h")
        hmaxall = float(sim.comm.max(float(np.abs(h).max()) if len(h) else 0.0))
        alphamax = min(ALPHA_MAX, self.settings.dmax / hmaxall) if hmaxall > 0.0 else ALPHA_MAX
        for fix, part in self.extra:
            alphamax = min(alphamax, fix.max_alpha(self.hextra[part]))
        if len(self.hextra):
            hmaxall = max(hmaxall, float(np.abs(self.hextra).max()))
        if hmaxall == 0.0:
            return eoriginal, "zeroforce"
        self.box0_length = sim.box.length.copy()
        for fix, _ in self.extra:
            fix.min_store(sim)
        self._vector("minimize_x0")[:] = p.x[:p.nlocal]
        alpha, alphaprev, engprev, fhprev = alphamax, 0.0, eoriginal, fdothall
        while True:
            ecurrent = self._step(alpha)
            if self.settings.line == "quadratic":
                fh = (self._dot(p.f[:p.nlocal], self._vector("minimize_h")) + float(self.fextra @ self.hextra)) / norm
                delfh = fh - fhprev
                if abs(fh) < EPS_QUAD or abs(delfh) < EPS_QUAD:
                    return self._step(0.0), "zeroquad"
                relerr = abs(1.0 - (0.5 * (alpha - alphaprev) * (fh + fhprev) + ecurrent) / engprev)
                alpha0 = alpha - (alpha - alphaprev) * fh / delfh
                if relerr <= QUADRATIC_TOL and 0.0 < alpha0 < alphamax:
                    ecurrent = self._step(alpha0)
                    if ecurrent - eoriginal < EMACH:
                        return self._success(ecurrent)
                fhprev, engprev = fh, ecurrent
            de_ideal = -BACKTRACK_SLOPE * alpha * fdothall
            if ecurrent - eoriginal <= de_ideal:
                return self._success(ecurrent)
            alphaprev = alpha
            alpha *= ALPHA_REDUCE
            if alpha <= 0.0 or de_ideal >= -EMACH:
                return self._step(0.0), "zeroalpha"

    # ---- the iterations ------------------------------------------------------------------------------
    def minimize(self, etol, ftol, maxiter, maxeval):
        sim = self.sim
        refuse_fixes_left_out(sim)
        neighbor = sim.neighbor
        settings = neighbor.every, neighbor.delay, neighbor.check
        # as LAMMPS: a line search may move particles far in one evaluation, so lists are checked at
        # every one (a delay would let it read energies with pairs missing)
        if settings != (1, 0, True):
            sim.warn("Using 'neigh_modify every 1 delay 0 check yes' setting during minimization")
        neighbor.every, neighbor.delay, neighbor.check = 1, 0, True
        try:
            return self._minimize(etol, ftol, maxiter, maxeval)
        finally:
            neighbor.every, neighbor.delay, neighbor.check = settings

    def _minimize(self, etol, ftol, maxiter, maxeval):
        sim = self.sim
        for name in ("minimize_g", "minimize_h", "minimize_x0", "minimize_v"):
            sim.particles.request(name, 3, replicate="copy")     # worked out anew by each minimize
        self._extra_dof()
        self.setup()
        n = sim.particles.nlocal
        ecurrent = self._energy()
        self.neval = 0
        sim.output.setup(sim.step, sim.step + maxiter)
        initial = previous = ecurrent
        self.energies = [ecurrent]
        t0 = time.perf_counter()
        if self.settings.style == "fire":
            stop, iterations, ecurrent, previous = self._fire(etol, ftol, maxiter, maxeval, ecurrent)
        else:
            stop, iterations, ecurrent, previous = self._cg(etol, ftol, maxiter, maxeval, ecurrent)
        loop = time.perf_counter() - t0
        sim.run_state.energy_step = sim.step
        if self.last_thermo != sim.step:        # the last iteration may have written it already
            sim.output.write(sim.step, sim.step)
        sim.neighbor.mark_current(sim.particles)
        fnorm = math.sqrt(self._dot(sim.particles.f[:sim.particles.nlocal], sim.particles.f[:sim.particles.nlocal])
                          + float(self.fextra @ self.fextra))
        fmax = float(sim.comm.max(float(np.abs(sim.particles.f[:sim.particles.nlocal]).max()) if n else 0.0))
        fmax = max([fmax] + [abs(float(value)) for value in self.fextra])
        sim.output.message(f"Loop time of {loop:g} on {sim.comm.nprocs} procs for {iterations} steps with "
                           f"{int(sim.comm.sum(sim.particles.nlocal))} particles")
        sim.output.message("Minimization stats:")
        sim.output.message(f"  Stopping criterion = {STOPPED[stop]}")
        sim.output.message(f"  Energy initial, next-to-last, final = \n    {initial:18.15g} {previous:18.15g} "
                           f"{ecurrent:18.15g}")
        sim.output.message(f"  Iterations, force evaluations = {iterations} {self.neval}")
        sim.output.message(f"  Force two-norm, max component = {fnorm:g} {fmax:g}")
        self.result = {"stop": stop, "initial": initial, "final": ecurrent, "iterations": iterations,
                       "evaluations": self.neval, "fnorm": fnorm, "energies": self.energies}
        return self.result

    def _extra_dof(self):
        """The fixes' extra global degrees of freedom (LAMMPS's nextra_global): each fix's slice of
        fextra, gextra and hextra."""
        sim = self.sim
        self.extra, start = [], 0
        for fix in sim.fixes.values():
            dof = int(getattr(fix, "min_dof", 0))
            if dof:
                self.extra.append((fix, slice(start, start + dof)))
                start += dof
        if start and self.settings.style == "fire":
            raise ScriptError(f"min_style fire cannot minimize with fix {self.extra[0][0].id} "
                              f"({self.extra[0][0].name}): use cg or sd (as LAMMPS)")
        self.fextra, self.gextra, self.hextra = np.zeros(start), np.zeros(start), np.zeros(start)
        self.box0_length = sim.box.length.copy()
        if start:
            sim.warn(f"Energy due to {start} extra global DOFs will be included in minimizer energies")

    def _converged(self, ecurrent, eprevious, etol):
        return abs(ecurrent - eprevious) < etol * 0.5 * (abs(ecurrent) + abs(eprevious) + EPS_ENERGY)

    def _vector(self, name):
        """A per-atom vector of the search (g, h, x0): it travels with its particles when they
        migrate or are re-sorted during a line search, as LAMMPS's fix minimize keeps them."""
        p = self.sim.particles
        return p.arrays[name][:p.nlocal]

    def _cg(self, etol, ftol, maxiter, maxeval, ecurrent):
        sim = self.sim
        p = sim.particles
        nlimit = max(1, 3 * int(sim.comm.sum(p.nlocal)) + len(self.fextra))
        self._vector("minimize_g")[:] = p.f[:p.nlocal]
        self._vector("minimize_h")[:] = p.f[:p.nlocal]
        self.gextra[:] = self.hextra[:] = self.fextra
        gg = self._dot(self._vector("minimize_g"), self._vector("minimize_g")) + float(self.fextra @ self.fextra)
        eprevious = ecurrent
        for iteration in range(1, maxiter + 1):
            sim.run_state.step += 1
            eprevious = ecurrent
            ecurrent, fail = self.linemin(ecurrent)
            self.energies.append(ecurrent)
            if fail is not None:
                return fail, iteration, ecurrent, eprevious
            if self.neval >= maxeval:
                return "maxeval", iteration, ecurrent, eprevious
            if self._converged(ecurrent, eprevious, etol):
                return "etol", iteration, ecurrent, eprevious
            f, g, h = p.f[:p.nlocal], self._vector("minimize_g"), self._vector("minimize_h")
            ff = self._dot(f, f) + float(self.fextra @ self.fextra)
            fg = self._dot(f, g) + float(self.fextra @ self.gextra)
            if ff < ftol * ftol:
                return "ftol", iteration, ecurrent, eprevious
            beta = 0.0 if self.settings.style == "sd" else max(0.0, (ff - fg) / gg)
            if (iteration + 1) % nlimit == 0:
                beta = 0.0
            gg = ff
            g[:] = f
            h[:] = g + beta * h
            self.gextra[:] = self.fextra
            self.hextra[:] = self.gextra + beta * self.hextra
            if self._dot(g, h) + float(self.gextra @ self.hextra) <= 0.0:
                h[:] = g
                self.hextra[:] = self.gextra
            self._thermo()
        return "maxiter", maxiter, ecurrent, eprevious

    def _thermo(self):
        sim = self.sim
        every = sim.output.thermo.every
        if every and sim.step % every == 0:
            sim.output.write(sim.step, sim.run_last_step)
            self.last_thermo = sim.step

    def _fire(self, etol, ftol, maxiter, maxeval, ecurrent):
        sim = self.sim
        p = sim.particles
        dt0 = sim.dt
        dt, dtmax, dtmin = dt0, 10.0 * dt0, 0.02 * dt0
        alpha, alpha0 = 0.25, 0.25
        delaystep, last_negative = 20, sim.step
        start = sim.step
        self._vector("minimize_v")[:] = 0.0
        eprevious = ecurrent
        for iteration in range(1, maxiter + 1):
            sim.run_state.step += 1
            n = p.nlocal
            v = self._vector("minimize_v")
            f = p.f[:n]
            vdotf = self._dot(v, f)
            if vdotf > 0.0:
                vdotv, fdotf = self._dot(v, v), self._dot(f, f)
                scale1 = 1.0 - alpha
                scale2 = alpha * math.sqrt(vdotv / fdotf) if fdotf > 1e-20 else 0.0
                if sim.step - last_negative > delaystep:
                    dt = min(dt * 1.1, dtmax)
                    alpha *= 0.99
            else:
                last_negative = sim.step
                if sim.step - start >= delaystep:
                    alpha = alpha0
                    if dt * 0.5 >= dtmin:
                        dt *= 0.5
                p.x[:n] -= 0.5 * dt * v
                v[:] = 0.0
            vmax = float(sim.comm.max(float(np.abs(v).max()) if n else 0.0))
            dtv = min(dt, self.settings.dmax / vmax) if vmax > 0 else dt
            mass = observables.masses(sim, np.ones(n, dtype=bool))
            v += (dtv * sim.units.ftm2v / mass)[:, None] * f
            if vdotf > 0.0:
                v[:] = scale1 * v + scale2 * f
            p.x[:n] += dtv * v
            eprevious = ecurrent
            ecurrent = self.energy_force()
            self.energies.append(ecurrent)
            if self.neval >= maxeval:
                return "maxeval", iteration, ecurrent, eprevious
            if etol > 0.0 and sim.step - last_negative > delaystep and self._converged(ecurrent, eprevious, etol):
                return "etol", iteration, ecurrent, eprevious
            f = p.f[:p.nlocal]
            if ftol > 0.0 and self._dot(f, f) < ftol * ftol:
                return "ftol", iteration, ecurrent, eprevious
            self._thermo()
        return "maxiter", maxiter, ecurrent, eprevious


def refuse_fixes_left_out(sim):
    """A fix that changes forces in a run but neither acts in a minimization (min_post_force) nor
    says LAMMPS leaves it out there (minimize_idle) would be silently ignored: refuse it."""
    for fix in sim.fixes.values():
        if (any(implements(fix, hook) for hook in FORCE_HOOKS) and not implements(fix, "min_post_force")
                and not fix.minimize_idle):
            raise ScriptError(f"fix {fix.id} ({fix.name}) changes forces in a run but cannot take part in a "
                              "minimization (it has no min_post_force); unfix it before minimize")


def check_tolerances(etol, ftol, maxiter, maxeval):
    if etol < 0 or ftol < 0:
        raise ScriptError("etol and ftol must be >= 0")
    if maxiter < 1 or maxeval < 1:
        raise ScriptError("maxiter and maxeval must be >= 1")
