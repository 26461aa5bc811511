r"""Fix ``deform``: change the box's x, y or z length during a run at a prescribed rate or to a
prescribed size (LAMMPS's fix deform, orthogonal boxes).

Each deformed axis goes from its bounds at the run's start (lo_0, hi_0, length L_0, centre c) to its
bounds at the run's end, linearly in the step (delta = (step - first) / (last - first))::

    final LO HI        lo_1 = LO, hi_1 = HI
    delta DLO DHI      lo_1 = lo_0 + DLO, hi_1 = hi_0 + DHI
    scale F            lo_1, hi_1 = c -/+ F L_0 / 2
    vel V              lo_1, hi_1 = lo_0 - V T / 2, hi_0 + V T / 2       (T the run's duration)
    erate R            lo_1, hi_1 = lo_0 - R L_0 T / 2, hi_0 + R L_0 T / 2   (engineering strain rate)
    trate R            L(t) = L_0 exp(R t) about c                        (true strain rate, not linear)

every N steps (at the end of the step, before output). ``remap x`` (the default) carries the
group's particles with the box (fractional coordinates kept), ``remap v`` leaves positions alone and
changes the velocity of a group particle crossing a deformed periodic face by the box's rate of
change dL/dt (so a streaming profile stays continuous across the face), ``remap none`` leaves
particles alone. ``units lattice`` (LAMMPS's default) multiplies final, delta and vel distances by
the lattice spacing (1 without a lattice command); ``units box`` takes them as they are. ``flip``
is accepted and has no effect (it concerns tilted boxes, which pdps does not have).

Syntax (LAMMPS's)::

    fix ID GROUP deform N x|y|z STYLE VALUES... [x|y|z STYLE VALUES...] [remap x|v|none]
        [flip yes|no] [units lattice|box]

Examples::

    fix 1 all deform 1 x erate 0.01 remap x units box
    fix 2 all deform 10 y final 0.0 12.0 z scale 0.9 remap none
"""

import math

import numpy as np
from numba import njit

from pdps_core.api import Fix, ScriptError, StyleArgs, param

ARITY = {"final": 2, "delta": 2, "scale": 1, "vel": 1, "erate": 1, "trate": 1}
REFUSED = {"xy", "xz", "yz"}


@njit(cache=True)
def shift_crossers(v, image, seen, mask, groupbit, nlocal, h_rate):
    """LAMMPS's deform_vremap: a particle wrapped k times through a deforming face changes velocity
    by -k dL/dt along that axis; ``seen`` keeps the images it had."""
    for i in range(nlocal):
        for d in range(3):
            k = image[i, d] - seen[i, d]
            if k != 0:
                if mask[i] & groupbit:
                    v[i, d] -= k * h_rate[d]
                seen[i, d] = image[i, d]


class FixDeform(Fix):
    name = "deform"
    usage = ("fix ID GROUP deform N x|y|z final|delta|scale|vel|erate|trate VALUES... [remap x|v|none] "
             "[flip yes|no] [units lattice|box]")

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        words: list[str] = []

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box("fix deform")
        words, k = list(args.words), 0
        self.axes = {}                  # axis -> (style, values)
        self.remap, self.units = "x", "lattice"
        while k < len(words):
            word = words[k]
            if word in ("x", "y", "z"):
                style = words[k + 1] if k + 1 < len(words) else "none"
                if style not in ARITY:
                    raise ScriptError(f"{word} {style}: styles are final, delta, scale, vel, erate and trate "
                                      "(volume, wiggle and variable are not supported)")
                values = words[k + 2:k + 2 + ARITY[style]]
                try:
                    numbers = [float(v) for v in values]
                except ValueError:
                    numbers = []
                if len(numbers) != ARITY[style] or not all(math.isfinite(v) for v in numbers):
                    raise ScriptError(f"{word} {style} takes {ARITY[style]} number(s) (got {' '.join(values) or 'none'})")
                d = "xyz".index(word)
                if d == 2 and sim.dimension == 2:
                    raise ScriptError("z: a 2-d simulation's box cannot deform along z")
                self.axes[d] = (style, numbers)
                k += 2 + ARITY[style]
            elif word in REFUSED:
                raise ScriptError(f"{word}: pdps boxes are orthogonal (no tilt), so only x, y and z can deform")
            elif word in ("remap", "flip", "units"):
                value = words[k + 1] if k + 1 < len(words) else ""
                allowed = {"remap": ("x", "v", "none"), "flip": ("yes", "no"), "units": ("lattice", "box")}[word]
                if value not in allowed:
                    raise ScriptError(f"{word} must be one of {', '.join(allowed)} (got {value or 'nothing'})")
                if word != "flip":
                    setattr(self, word, value)
                k += 2
            else:
                raise ScriptError(f"unknown keyword {word} (known: x, y, z, remap, flip, units)")
        if not self.axes:
            raise ScriptError("fix deform needs at least one of x, y, z with a style")
        self.deformed_axes = tuple(sorted(self.axes))
        if self.remap == "v":
            self.per_atom = (("deform_image", 3, np.int32),)

    def init_run(self, sim):
        box = sim.box
        spacing = sim.lattice.spacing if (self.units == "lattice" and sim.lattice is not None) else np.ones(3)
        self.lo_start, self.hi_start = box.lo.copy(), box.hi.copy()
        self.lo_stop, self.hi_stop = box.lo.copy(), box.hi.copy()
        self.duration = (sim.run_last_step - sim.run_first_step) * sim.dt
        self.h_rate = np.zeros(3)
        for d, (style, values) in self.axes.items():
            lo, hi = self.lo_start[d], self.hi_start[d]
            if style == "final":
                self.lo_stop[d], self.hi_stop[d] = values[0] * spacing[d], values[1] * spacing[d]
            elif style == "delta":
                self.lo_stop[d], self.hi_stop[d] = lo + values[0] * spacing[d], hi + values[1] * spacing[d]
            elif style == "scale":
                shift = 0.5 * values[0] * (hi - lo)
                self.lo_stop[d], self.hi_stop[d] = 0.5 * (lo + hi) - shift, 0.5 * (lo + hi) + shift
            elif style == "vel":
                self.lo_stop[d] = lo - 0.5 * self.duration * values[0] * spacing[d]
                self.hi_stop[d] = hi + 0.5 * self.duration * values[0] * spacing[d]
            elif style == "erate":
                shift = 0.5 * self.duration * values[0] * (hi - lo)
                self.lo_stop[d], self.hi_stop[d] = lo - shift, hi + shift
            else:
                shift = 0.5 * (hi - lo) * _exp(values[0] * self.duration)
                self.lo_stop[d], self.hi_stop[d] = 0.5 * (lo + hi) - shift, 0.5 * (lo + hi) + shift
            if self.hi_stop[d] <= self.lo_stop[d]:
                raise ScriptError(f"fix {self.id} deform: the box's {'xyz'[d]} length would reach "
                                  f"{self.hi_stop[d] - self.lo_stop[d]:g} by the run's end (it must stay > 0)")
            if style != "trate" and self.duration > 0:
                self.h_rate[d] = ((self.hi_stop[d] - self.hi_start[d]) - (self.lo_stop[d] - self.lo_start[d])) \
                    / self.duration
        if self.remap == "v":
            p = sim.particles
            p.arrays["deform_image"][: p.nlocal] = p.image[: p.nlocal]

    def pre_neighbor(self, sim):
        if self.remap != "v":
            return
        p = sim.particles
        shift_crossers(p.v, p.image, p.arrays["deform_image"], p.mask, sim.groups.bit(self.group), p.nlocal,
                       self.h_rate)

    def end_of_step(self, sim):
        if sim.step % self.args.every:
            return
        delta = sim.ramp(0.0, 1.0)
        lo, hi = sim.box.lo.copy(), sim.box.hi.copy()
        for d, (style, values) in self.axes.items():
            if style == "trate":
                elapsed = (sim.step - sim.run_first_step) * sim.dt
                mid = 0.5 * (self.lo_start[d] + self.hi_start[d])
                shift = 0.5 * (self.hi_start[d] - self.lo_start[d]) * _exp(values[0] * elapsed)
                # LAMMPS's rate: of the length before this step's change (0 until the first change)
                self.h_rate[d] = values[0] * (hi[d] - lo[d])
                lo[d], hi[d] = mid - shift, mid + shift
            else:
                lo[d] = self.lo_start[d] + delta * (self.lo_stop[d] - self.lo_start[d])
                hi[d] = self.hi_start[d] + delta * (self.hi_stop[d] - self.hi_start[d])
        sim.change_box(lo, hi, remap=self.group if self.remap == "x" else None)


def _exp(x):
    """exp, inf past the float range (a run that far gone is stopped by the box or finiteness checks)."""
    return math.exp(x) if x < 709.0 else math.inf
