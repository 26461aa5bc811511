r"""Fix ``box/relax``: the box lengths join a minimization as degrees of freedom, so the minimizer
relaxes the box to a target pressure or stress (LAMMPS's fix box/relax; orthogonal boxes).

The minimized energy gains the work against the target pressure and, for a target stress with
differing components (deviatoric), the strain energy (Parrinello-Rahman's, LAMMPS's form), with
:math:`V_0` and :math:`L_{0,i}` the box at the minimization's start (or at the last ``nreset``) and
:math:`s_i = L_i / L_{0,i}`::

    E_box = P_hydro (s_x s_y s_z - 1) V_0  +  1/2 sum_i sigma_i L_i^2,    sigma_i = V_0 (P_i - P_hydro) / L_{0,i}^2

(iso: :math:`P (s^3 - 1) V_0`, :math:`s^2` in 2-d) in energy units (pressure times volume over
``nktv2p``); P_hydro is the mean target of the controlled axes. The force on box length i is
:math:`(P_{\mathrm{current},i} - P_\mathrm{hydro}) V_0 \prod_{j \ne i} s_j - \sigma_i L_i L_{0,i}`
(iso: :math:`(P_\mathrm{current} - P) \, 3 s^2 V_0`), with the current pressure from the virial
alone (no kinetic part). A line search step alpha changes length i by alpha times its direction
times :math:`L_{i}` of the fix's first minimization, about the fixed point (the box centre when the
fix is made), carrying every particle with the box (``dilate all``) or the group's (``dilate
partial``); no length changes by more than ``vmax`` of its own in one step. Iso in 2-d and ``couple
xyz`` give one degree of freedom, the others three; ``couple xy|yz|xz`` averages those components.
``f_ID`` is the box energy (0 at step 0, as LAMMPS). Only cg and sd minimize with it. Tilted boxes
(tri, xy, xz, yz, scalexy ...) are not in pdps. LAMMPS: Thompson's fix box/relax, whose
``compute_sigma``, strain energy and deviatoric force are the orthogonal box's case here.

Syntax::

    fix ID GROUP box/relax iso|aniso P | [x Px] [y Py] [z Pz] [couple xyz|xy|yz|xz|none]
        [vmax FRACTION] [nreset N] [dilate all|partial] [fixedpoint X Y Z]

Example (LAMMPS's examples/min/in.min.box)::

    fix 3 all box/relax iso 1.5 vmax 1.0e-3
    variable emin equal pe+f_3/atoms
    minimize 0.0 10.0 10000 100000
"""

from typing import Literal

import numpy as np

from pdps_core.api import Fix, ScriptError, StyleArgs, keyword, observables

Triple = tuple[float, float, float] | None


class FixBoxRelax(Fix):
    name = "box/relax"
    usage = ("fix ID GROUP box/relax iso|aniso P | [x Px] [y Py] [z Pz] [couple xyz|xy|yz|xz|none] "
             "[vmax FRACTION] [nreset N] [dilate all|partial] [fixedpoint X Y Z]")
    extensive = True
    changes_box = True

    class Args(StyleArgs):
        iso: float | None = keyword(None, unit="pressure")
        aniso: float | None = keyword(None, unit="pressure")
        x: float | None = keyword(None, unit="pressure")
        y: float | None = keyword(None, unit="pressure")
        z: float | None = keyword(None, unit="pressure")
        couple: Literal["xyz", "xy", "yz", "xz", "none"] | None = keyword(None)
        vmax: float = keyword(1.0e-4, gt=0, unit="dimensionless")
        nreset: int = keyword(0, ge=0, unit="timesteps")
        dilate: Literal["all", "partial"] = keyword("all")
        fixedpoint: Triple = keyword(None, unit="distance")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box(f"fix {self.name}")
        what = f"fix {id} box/relax"
        dimension = sim.dimension
        target, flag = [0.0, 0.0, 0.0], [False, False, False]
        couple, deviatoric = "none", False
        for word in ("iso", "aniso"):
            value = getattr(args, word)
            if value is not None:
                couple = "xyz" if word == "iso" else "none"
                target, flag = [value] * 3, [True, True, dimension == 3]
                if dimension == 2:
                    target[2] = 0.0
        for axis, word in enumerate("xyz"):
            value = getattr(args, word)
            if value is not None:
                if word == "z" and dimension == 2:
                    raise ScriptError(f"{what}: z is not allowed for a 2d simulation")
                target[axis], flag[axis], deviatoric = value, True, True
        if args.couple is not None:
            couple = args.couple
        if dimension == 2 and couple in ("yz", "xz"):
            raise ScriptError(f"{what}: couple {couple} is not allowed for a 2d simulation")
        if not any(flag):
            raise ScriptError(f"{what}: give iso, aniso, x, y or z")
        pairs = {"xyz": (0, 1, 2) if dimension == 3 else (0, 1), "xy": (0, 1), "yz": (1, 2), "xz": (0, 2)}
        for axis in pairs.get(couple, ()):
            if not flag[axis]:
                raise ScriptError(f"{what}: couple {couple} needs a pressure for {'xyz'[axis]}")
        coupled = pairs.get(couple, ())
        if len({target[a] for a in coupled}) > 1:
            raise ScriptError(f"{what}: the pressures of {''.join('xyz'[a] for a in coupled)} must be the same "
                              f"with couple {couple}")
        for axis in range(3):
            if flag[axis] and not sim.box.periodic[axis]:
                raise ScriptError(f"{what}: the {'xyz'[axis]} dimension is not periodic")
        self.target, self.flag, self.couple = np.array(target), flag, couple
        self.iso = couple == "xyz" or (dimension == 2 and couple == "xy")
        self.min_dof = 1 if self.iso else 3
        self.deviatoric = deviatoric
        self.fixedpoint = (0.5 * (sim.box.lo + sim.box.hi) if args.fixedpoint is None
                           else np.array(args.fixedpoint, dtype=np.float64))
        self.remap_group = "all" if args.dilate == "all" else group
        self.h0 = None

    # ---- the minimizer's extra degrees of freedom --------------------------------------------------
    def init_run(self, sim):
        length = sim.box.length.copy()
        if sim.dimension == 2:
            length[2] = 1.0
        self.h0 = sim.box.length.copy()         # the unit of a step's length change (LAMMPS's h0)
        self.initial = length                   # the reference box (xprdinit ...), reset by nreset
        self.vol0 = float(np.prod(length))
        flagged = [t for t, f in zip(self.target, self.flag) if f]
        self.p_hydro = sum(flagged) / len(flagged)
        if any(f and abs(self.p_hydro - t) > 1.0e-6 for t, f in zip(self.target, self.flag)):
            self.deviatoric = True
        self.sigma = np.zeros(3)
        if self.deviatoric:
            self._sigma(sim)
        self.lo0, self.hi0 = sim.box.lo.copy(), sim.box.hi.copy()

    def _sigma(self, sim):
        """LAMMPS's compute_sigma for an orthogonal box: the reference box becomes the current one."""
        length = sim.box.length.copy()
        if sim.dimension == 2:
            length[2] = 1.0
        self.initial, self.vol0 = length, float(np.prod(length))
        deviation = np.where(self.flag, self.target - self.p_hydro, 0.0)
        self.sigma = self.vol0 * deviation / (length * length)

    def _current_pressure(self, sim):
        units = sim.units.nktv2p
        if self.iso:
            return np.full(3, observables.virial_trace(sim) / (sim.dimension * sim.box.volume) * units)
        virial = observables.virial_parts(sim)
        tensor = (virial[0] + virial[1])[:3] / sim.box.volume * units
        current = tensor.copy()
        # couple xyz (and xy in 2-d) is the iso case above
        if self.couple in ("xy", "yz", "xz"):
            axes = ["xyz".index(c) for c in self.couple]
            current[axes] = tensor[axes].mean()
        if not np.isfinite(current).all():
            raise ScriptError(f"fix {self.id} box/relax: non-numeric pressure: simulation unstable")
        return current

    def min_energy(self, sim, fextra):
        pv2e = 1.0 / sim.units.nktv2p
        current = self._current_pressure(sim)
        length = sim.box.length
        if self.iso:
            scale = length[0] / self.initial[0]
            if sim.dimension == 3:
                fextra[0] = pv2e * (current[0] - self.target[0]) * 3.0 * scale * scale * self.vol0
                return pv2e * self.target[0] * (scale ** 3 - 1.0) * self.vol0
            fextra[0] = pv2e * (current[0] - self.target[0]) * 2.0 * scale * self.vol0
            return pv2e * self.target[0] * (scale * scale - 1.0) * self.vol0
        scales = np.where(self.flag, length / self.initial, 1.0)
        energy = pv2e * self.p_hydro * (float(np.prod(scales)) - 1.0) * self.vol0
        for axis in range(3):
            others = float(np.prod(np.delete(scales, axis)))
            fextra[axis] = pv2e * (current[axis] - self.p_hydro) * others * self.vol0 if self.flag[axis] else 0.0
        if self.deviatoric:
            dimensions = sim.dimension
            for axis in range(dimensions):
                if self.flag[axis]:
                    fextra[axis] -= pv2e * length[axis] * self.sigma[axis] * self.initial[axis]
            energy += 0.5 * pv2e * float(sum(self.sigma[a] * length[a] * length[a] for a in range(dimensions)))
        return energy

    def min_store(self, sim):
        self.lo0, self.hi0 = sim.box.lo.copy(), sim.box.hi.copy()

    def min_step(self, sim, alpha, hextra):
        ds = np.full(3, alpha * hextra[0]) if self.iso else alpha * np.asarray(hextra, dtype=np.float64)
        lo, hi = sim.box.lo.copy(), sim.box.hi.copy()
        current = sim.box.length.copy()
        for axis in range(3):
            if self.flag[axis]:
                stretch = ds[axis] * self.h0[axis] / current[axis]
                lo[axis] = self.lo0[axis] + (self.lo0[axis] - self.fixedpoint[axis]) * stretch
                hi[axis] = self.hi0[axis] + (self.hi0[axis] - self.fixedpoint[axis]) * stretch
                if lo[axis] >= hi[axis]:
                    raise ScriptError(f"fix {self.id} box/relax generated a negative box length")
        sim.change_box(lo, hi, remap=self.remap_group)

    def max_alpha(self, hextra):
        if self.iso:
            return self.args.vmax / abs(hextra[0])
        alpha = 1.0
        for axis in range(3):
            if self.flag[axis]:
                alpha = min(alpha, self.args.vmax / abs(hextra[axis]))
        return alpha

    def min_reset_ref(self, sim):
        if self.deviatoric and self.args.nreset > 0 and \
                (sim.step - sim.run_first_step) % self.args.nreset == 0:
            self._sigma(sim)
            return True
        return False

    def scalar(self, sim):
        if sim.step == 0 or self.h0 is None:
            return 0.0
        return self.min_energy(sim, np.zeros(self.min_dof))
