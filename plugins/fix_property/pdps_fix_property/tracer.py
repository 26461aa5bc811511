r"""Fix ``property/atom/tracer`` and compute ``nparticles/tracer/region``: particles marked as they
pass through a region, and the marked ones counted in another (LIGGGHTS's residence-time tracers).

The fix gives every particle a marker, a per-atom property named by the fix's ID (``f_ID`` in
dumps, compute reduce), 0 at first. Every ``check_mark_every`` steps (default 10) from step
``mark_step`` on, the group's particles inside region ``region_mark`` are marked 1: at the first such
check only (``marker_style dirac``, the default), at every one (``heaviside``), or never (``none``).
Its scalar ``f_ID`` is the number newly marked since it was last read.

The compute counts, among its group's particles in region ``region_count``, all and those marked,
and their masses: the vector ``c_ID[1-4]`` (count, marked count, mass, marked mass), counted
once a step however often it is read. With
``reset_marker yes`` (the default, as LIGGGHTS's) the marked particles it finds are unmarked, so an
outlet counts each particle once. ``periodic DIM all|N``: only particles of periodic image N along
DIM (all: every image).

Syntax::

    fix ID GROUP property/atom/tracer region_mark RID mark_step N [marker_style dirac|heaviside|none]
        [check_mark_every N]
    compute ID GROUP nparticles/tracer/region region_count RID tracer FIX_ID [reset_marker yes|no]
        [periodic x|y|z all|N]

Example::

    fix tracer all property/atom/tracer region_mark inlet mark_step 1000 marker_style dirac
    compute outflow all nparticles/tracer/region region_count outlet tracer tracer
"""

from typing import Literal

import numpy as np

from pdps_core.api import Compute, Fix, ScriptError, StyleArgs, keyword, observables


class FixPropertyAtomTracer(Fix):
    name = "property/atom/tracer"
    usage = ("fix ID GROUP property/atom/tracer region_mark RID mark_step N [marker_style dirac|heaviside|none] "
             "[check_mark_every N]")

    class Args(StyleArgs):
        region_mark: str | None = keyword(None, names="region ID")
        mark_step: int | None = keyword(None, ge=0, unit="timesteps")
        marker_style: Literal["dirac", "heaviside", "none"] = keyword("dirac")
        check_mark_every: int = keyword(10, ge=1, unit="timesteps")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if args.region_mark is None:
            raise ScriptError("fix property/atom/tracer needs region_mark RID")
        if args.mark_step is None:
            raise ScriptError("fix property/atom/tracer needs mark_step N")
        sim.region(args.region_mark)
        self.marker = id
        sim.particles.request(self.marker, replicate="copy")     # a copy of a marked particle is marked
        self.first_mark = args.mark_step >= sim.step
        self.marked = self.read = 0

    def end_of_step(self, sim):
        args = self.args
        step = sim.step
        if step % args.check_mark_every or step < args.mark_step or args.marker_style == "none" \
                or (args.marker_style == "dirac" and not self.first_mark):
            return
        p = sim.particles
        n = p.nlocal
        marker = p.arrays[self.marker][:n]
        inside = np.asarray(sim.region(args.region_mark).match(p.x[:n]), dtype=bool)
        fresh = sim.groups.select(sim, self.group) & inside & ~np.isclose(marker, 1.0, rtol=0.0, atol=1e-5)
        marker[fresh] = 1.0
        self.marked += int(sim.comm.sum(int(fresh.sum())))
        self.first_mark = False

    def scalar(self, sim):
        newly, self.read = self.marked - self.read, self.marked
        return float(newly)

    def peratom(self, sim):
        return sim.particles.arrays[self.marker][: sim.particles.nlocal]


class ComputeNparticlesTracerRegion(Compute):
    name = "nparticles/tracer/region"
    usage = ("compute ID GROUP nparticles/tracer/region region_count RID tracer FIX_ID [reset_marker yes|no] "
             "[periodic x|y|z all|N]")

    class Args(StyleArgs):
        region_count: str | None = keyword(None, names="region ID")
        tracer: str | None = keyword(None, names="fix ID")
        reset_marker: Literal["yes", "no"] = keyword("yes")
        periodic: tuple[Literal["x", "y", "z"], str] | None = keyword(None)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if args.region_count is None or args.tracer is None:
            raise ScriptError("compute nparticles/tracer/region needs region_count RID and tracer FIX_ID")
        sim.region(args.region_count)
        fix = sim.fixes.get(args.tracer)
        # a tracer is a fix that keeps a marker (property/atom/tracer and its /stream)
        if getattr(fix, "marker", None) is None:
            raise ScriptError(f"compute {id} (nparticles/tracer/region): fix {args.tracer} is not a fix "
                              "property/atom/tracer")
        self.image = None
        self.counted = (None, None)       # (step, counts): read once a step, as LAMMPS's invoked_vector
        if args.periodic is not None:
            axis = "xyz".index(args.periodic[0])
            if not sim.box.periodic[axis]:
                raise ScriptError(f"compute {id} (nparticles/tracer/region): periodic {args.periodic[0]} needs a "
                                  "periodic boundary along it")
            if args.periodic[1] != "all":
                try:
                    self.image = (axis, int(args.periodic[1]))
                except ValueError:
                    raise ScriptError(f"periodic {args.periodic[0]}: expected all or an image number "
                                      f"(got {args.periodic[1]})") from None

    def vector(self, sim):
        # the markers it resets make a second count of the step a different one: the first is kept
        if self.counted[0] == sim.step:
            return self.counted[1].copy()
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group) & np.asarray(
            sim.region(self.args.region_count).match(p.x[:n]), dtype=bool)
        if self.image is not None:
            chosen &= p.image[:n, self.image[0]] == self.image[1]
        marker = p.arrays[sim.fixes[self.args.tracer].marker][:n]
        marked = chosen & np.isclose(marker, 1.0, rtol=0.0, atol=1e-5)
        mass = np.asarray(observables.masses(sim), dtype=np.float64)
        counts = np.array([chosen.sum(), marked.sum(), mass[chosen].sum(), mass[marked].sum()], dtype=np.float64)
        if self.args.reset_marker == "yes":
            marker[marked] = 0.0
        self.counted = (sim.step, np.asarray(sim.comm.sum(counts), dtype=np.float64))
        return self.counted[1].copy()
