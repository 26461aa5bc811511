r"""Fix ``deform``: change the box's x, y or z length during a run at a prescribed rate or to a
prescribed size (LAMMPS's fix deform, orthogonal boxes).

Each deformed axis goes from its bounds at the run's start (lo_0, hi_0, length L_0, centre c) to its
bounds at the run's end, linearly in the step (delta = (step - first) / (last - first))::

    final LO HI        lo_1 = LO, hi_1 = HI
    delta DLO DHI      lo_1 = lo_0 + DLO, hi_1 = hi_0 + DHI
    scale F            lo_1, hi_1 = c -/+ F L_0 / 2
    vel V              lo_1, hi_1 = lo_0 - V T / 2, hi_0 + V T / 2       (T the run's duration)
    erate R            lo_1, hi_1 = lo_0 - R L_0 T / 2, hi_0 + R L_0 T / 2   (engineering strain rate)

or, not linearly, at the time t since the run's start::

    trate R            L(t) = L_0 exp(R t) about c                        (true strain rate)
    wiggle A TP        L(t) = L_0 + A sin(2 pi t / TP), lo and hi moving by -/+ A sin(...) / 2
    variable v_DL v_R  L(t) = L_0 + DL (equal-style variable DL: the change of length, box units),
                       lo and hi moving by -/+ DL / 2; v_R is its rate dDL/dt (read for remap v)
    volume             the length that keeps the volume at the run's start, V_0 = Lx Ly Lz, about c,
                       given the others' new lengths: with one other axis deformed and one left
                       alone, L = V_0 / (L_deformed L_alone,0); with both others deformed,
                       L = V_0 / (L_1 L_2); two volume axes share the third's change,
                       L = sqrt(V_0 L_0 / (L_deformed L_other volume,0)) (LAMMPS's three cases)

every N steps (at the end of the step, before output). ``remap x`` (the default) carries the
group's particles with the box (fractional coordinates kept), ``remap v`` leaves positions alone and
changes the velocity of a group particle crossing a deformed periodic face by the box's rate of
change dL/dt (so a streaming profile stays continuous across the face), ``remap none`` leaves
particles alone. The rate is LAMMPS's: constant for the linear styles, R L before the step's change
for trate, 2 pi A / TP cos(2 pi t / TP) for wiggle, v_R for variable, and for volume LAMMPS's
(L_new / L_old - 1) / dt (a relative rate, as LAMMPS 2025 has it). ``units lattice`` (LAMMPS's
default; LIGGGHTS 3.8.0's default is box, measured; its manual says lattice) multiplies final, delta and vel distances and wiggle amplitudes by the lattice spacing (1
without a lattice command); ``units box`` takes them as they are (variable lengths are always box
units). ``flip`` is accepted and has no effect (it concerns tilted boxes, which pdps does not have).

Syntax (LAMMPS's)::

    fix ID GROUP deform N x|y|z STYLE VALUES... [x|y|z STYLE VALUES...] [remap x|v|none]
        [flip yes|no] [units lattice|box]

Examples::

    fix 1 all deform 1 x erate 0.01 remap x units box
    fix 2 all deform 10 y final 0.0 12.0 z scale 0.9 remap none
    fix 3 all deform 1 x wiggle 0.5 2.0 y volume
    variable dl equal 0.1*sin(elapsed*dt)
    variable rate equal 0.1*cos(elapsed*dt)
    fix 4 all deform 1 z variable v_dl v_rate remap v
"""

import math
from typing import Annotated, Literal

import numpy as np
from numba import njit
from pydantic import BeforeValidator
from pydantic_core import PydanticCustomError

from pdps_core.api import Fix, ScriptError, StyleArgs, VariableRef, keyword, param

LINEAR = ("final", "delta", "scale", "vel", "erate")


def _variable(word):
    if not isinstance(word, str):
        return word             # a VariableRef, or its JSON form in a restart
    if not (word.startswith("v_") and len(word) > 2):
        raise PydanticCustomError("variable", "variable takes two equal-style variables v_LENGTH v_RATE")
    return VariableRef(word[2:])


Variable = Annotated[VariableRef, BeforeValidator(_variable)]
# how one axis changes: its style word, then that style's values
Change = (tuple[Literal["final", "delta"], float, float]
          | tuple[Literal["scale", "vel", "erate", "trate"], float]
          | Literal["volume"]
          | tuple[Literal["wiggle"], float, float]
          | tuple[Literal["variable"], Variable, Variable])
CHANGE_UNITS = {"final": "distance", "delta": "distance", "scale": "dimensionless", "vel": "velocity",
                "erate": "1/time", "trate": "1/time", "wiggle": ("distance", "time"),
                "variable": ("distance", "velocity")}


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
    usage = ("fix ID GROUP deform N x|y|z final|delta|scale|vel|erate|trate|volume|wiggle|variable VALUES... "
             "[remap x|v|none] [flip yes|no] [units lattice|box]")

    refused = dict.fromkeys(("xy", "xz", "yz"), "pdps boxes are orthogonal (no tilt), so only x, y and z can deform")

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        x: Change | None = keyword(None, unit=CHANGE_UNITS)
        y: Change | None = keyword(None, unit=CHANGE_UNITS)
        z: Change | None = keyword(None, unit=CHANGE_UNITS)
        remap: Literal["x", "v", "none"] = keyword("x")
        flip: Literal["yes", "no"] = keyword("yes")     # of tilted boxes: read, no effect here
        units: Literal["box", "lattice"] | None = keyword(None)    # the dialect's default

    @classmethod
    def check_args(cls, args):
        super().check_args(args)
        changes = [(axis, getattr(args, axis)) for axis in "xyz" if getattr(args, axis) is not None]
        if not changes:
            raise ScriptError("fix deform needs at least one of x, y, z with a style")
        for axis, change in changes:
            if change[0] == "wiggle" and change[2] <= 0:
                raise ScriptError(f"{axis} wiggle: the period must be > 0 (got {change[2]:g})")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        sim.require_box("fix deform")
        if args.z is not None and sim.dimension == 2:
            raise ScriptError("z: a 2-d simulation's box cannot deform along z")
        self.axes = {}                  # axis -> (style, values)
        for d, change in enumerate((args.x, args.y, args.z)):
            if change == "volume":
                self.axes[d] = ("volume", [])
            elif change is not None:
                self.axes[d] = (change[0], list(change[1:]))
        self.remap, self.units = args.remap, args.units or sim.dialect.command_units
        self.links = {d: self._volume_links(d) for d, (style, _) in self.axes.items() if style == "volume"}
        self.deformed_axes = tuple(sorted(self.axes))
        self.changes_box = True
        if self.remap == "v":
            self.per_atom = (("deform_image", 3, np.int32),)

    def _volume_links(self, d):
        """LAMMPS's links of a volume axis: (kind, fixed, dynamic1, dynamic2). One other axis
        deformed and one left alone: one_from_one; both deformed: one_from_two; the third axis also
        volume: two_from_one (the two share what the deformed one leaves)."""
        other1, other2 = (d + 1) % 3, (d + 2) % 3
        style1, style2 = (self.axes.get(o, (None,))[0] for o in (other1, other2))
        if style1 in (None, "volume") and style2 in (None, "volume"):
            raise ScriptError(f"{'xyz'[d]} volume: another of x, y, z must change by a style other than "
                              "volume for this one to keep the volume")
        if style1 is None:
            return "one_from_one", other1, other2, None
        if style2 is None:
            return "one_from_one", other2, other1, None
        if style1 == "volume":
            return "two_from_one", other1, other2, None
        if style2 == "volume":
            return "two_from_one", other2, other1, None
        return "one_from_two", None, other1, other2

    def init_run(self, sim):
        box = sim.box
        spacing = sim.lattice.spacing if (self.units == "lattice" and sim.lattice is not None) else np.ones(3)
        self.lo_start, self.hi_start = box.lo.copy(), box.hi.copy()
        self.lo_stop, self.hi_stop = box.lo.copy(), box.hi.copy()
        length = box.hi - box.lo
        self.vol_start = float(length[0] * length[1] * length[2])
        self.duration = (sim.run_last_step - sim.run_first_step) * sim.dt
        self.h_rate = np.zeros(3)
        for d, (style, values) in self.axes.items():
            if style == "variable":
                for ref in values:
                    if ref.name not in sim.variables:
                        raise ScriptError(f"fix {self.id} deform: variable {ref.name} is not defined "
                                          f"({'xyz'[d]} variable)")
            if style not in LINEAR:
                continue
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
            else:
                shift = 0.5 * self.duration * values[0] * (hi - lo)
                self.lo_stop[d], self.hi_stop[d] = lo - shift, hi + shift
            if self.hi_stop[d] <= self.lo_stop[d]:
                raise ScriptError(f"fix {self.id} deform: the box's {'xyz'[d]} length would reach "
                                  f"{self.hi_stop[d] - self.lo_stop[d]:g} by the run's end (it must stay > 0)")
            if self.duration > 0:
                self.h_rate[d] = ((self.hi_stop[d] - self.hi_start[d]) - (self.lo_stop[d] - self.lo_start[d])) \
                    / self.duration
        self.amplitude = {d: values[0] * spacing[d] for d, (style, values) in self.axes.items() if style == "wiggle"}
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
        elapsed = (sim.step - sim.run_first_step) * sim.dt
        lo, hi = sim.box.lo.copy(), sim.box.hi.copy()
        old_length = hi - lo
        start_lo, start_hi = self.lo_start, self.hi_start
        for d, (style, values) in self.axes.items():
            mid = 0.5 * (start_lo[d] + start_hi[d])
            if style == "trate":
                shift = 0.5 * (start_hi[d] - start_lo[d]) * _exp(values[0] * elapsed)
                # LAMMPS's rate: of the length before this step's change (0 until the first change)
                self.h_rate[d] = values[0] * old_length[d]
                lo[d], hi[d] = mid - shift, mid + shift
            elif style == "wiggle":
                phase = 2.0 * math.pi * elapsed / values[1]
                sine, cosine = (math.sin(phase), math.cos(phase)) if math.isfinite(phase) else (math.nan, math.nan)
                shift = 0.5 * self.amplitude[d] * sine
                lo[d], hi[d] = start_lo[d] - shift, start_hi[d] + shift
                self.h_rate[d] = 2.0 * math.pi / values[1] * self.amplitude[d] * cosine
            elif style == "variable":
                change = sim.evaluate(values[0])
                lo[d], hi[d] = start_lo[d] - 0.5 * change, start_hi[d] + 0.5 * change
                self.h_rate[d] = sim.evaluate(values[1])
            elif style in LINEAR:
                lo[d] = start_lo[d] + delta * (self.lo_stop[d] - start_lo[d])
                hi[d] = start_hi[d] + delta * (self.hi_stop[d] - start_hi[d])
        # volume axes last, from the others' new lengths (LAMMPS's apply_volume, its order of operations)
        start_length = start_hi - start_lo
        for d, (kind, fixed, dynamic1, dynamic2) in self.links.items():
            if kind == "one_from_one":
                half = 0.5 * _quotient(_quotient(self.vol_start, hi[dynamic1] - lo[dynamic1]), start_length[fixed])
            elif kind == "one_from_two":
                half = 0.5 * _quotient(_quotient(self.vol_start, hi[dynamic1] - lo[dynamic1]),
                                       hi[dynamic2] - lo[dynamic2])
            else:
                squared = _quotient(_quotient(self.vol_start * start_length[d], hi[dynamic1] - lo[dynamic1]),
                                    start_length[fixed])
                half = 0.5 * math.sqrt(squared) if squared >= 0 else math.nan
            # LAMMPS's rate of a volume axis: its relative change this step over dt (not a length rate)
            self.h_rate[d] = (2.0 * half / old_length[d] - 1.0) / sim.dt
            mid = 0.5 * (start_lo[d] + start_hi[d])
            lo[d], hi[d] = mid - half, mid + half
        sim.change_box(lo, hi, remap=self.group if self.remap == "x" else None)


def _exp(x):
    """exp, inf past the float range (a run that far gone is stopped by the box or finiteness checks)."""
    return math.exp(x) if x < 709.0 else math.inf


def _quotient(a, b):
    """a / b, NaN where a deformed length reached 0 (the box check then stops the run with one line)."""
    return a / b if b != 0 else math.nan
