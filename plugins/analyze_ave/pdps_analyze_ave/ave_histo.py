r"""Fix ``ave/histo``: a histogram of values, sampled on LAMMPS's NEVERY NREPEAT NFREQ schedule
(LAMMPS's and LIGGGHTS's fix ave/histo).

Every sampled value v with :math:`lo \le v \le hi` goes into bin :math:`\lfloor (v - lo)/\Delta\rfloor`
(the last bin takes v = hi), :math:`\Delta = (hi - lo)/N_\mathrm{bin}`; the counts of the NREPEAT
samples of a window add up (they are counts, not averages). Values outside the range are counted
as missing (``beyond ignore``, the default), put in the first or last bin (``end``), or in two
extra bins at lo and hi (``extra``: N + 2 bins). ``ave running`` adds every window's counts since
the fix was defined, ``ave window M`` the last M windows'.

Values: ``x y z vx vy vz fx fy fz`` of the group's particles; ``c_ID``, ``c_ID[k]``, ``f_ID``,
``f_ID[k]`` of a compute or fix with per-atom values (each group particle's), with local data
(each row), or global ones (a scalar, an element; with ``mode vector`` every element of ``c_ID``
or column k of its array); per-atom and local values need ``mode vector``, as LAMMPS's; ``v_NAME``, an atom-style variable of the group's particles or an
equal-style one. ``kind global|peratom|local`` picks what a reference is read as where it offers
more than one (default: per-atom, then local, then global, as LAMMPS finds it).

Output: the vector ``f_ID[1-4]``: the values counted, the missing ones, their least and largest
(every value sampled, in range or not); the array ``f_ID[i][1-3]``: bin i's centre (lo and hi for
the extra bins), its count, and its share of the count. A file (``file NAME``) holds LAMMPS's
format, numbers as ``%g``: after three header lines (``title1``-``title3`` replace them), for
each output ``STEP NBIN COUNT MISSING MIN MAX`` and a line ``i coord count share`` per bin;
``overwrite`` keeps only the last output. ``start S``: no window ends before step S.

Syntax::

    fix ID GROUP ave/histo NEVERY NREPEAT NFREQ LO HI NBIN value... [mode scalar|vector]
        [kind global|peratom|local] [file NAME] [ave one|running|window M] [start S]
        [beyond ignore|end|extra] [overwrite] [title1 S] [title2 S] [title3 S]

Example::

    fix speeds all ave/histo 100 5 1000 0.0 2.0 40 vx vy vz file speeds.histo ave running
"""

from typing import Literal

import numpy as np
from pydantic import model_validator

from pdps_core.api import PERATOM_REFERENCE, Compute, Fix, PeratomReference, ScriptError, keyword, param

from .schedule import Schedule, ScheduleArgs

COMPONENTS = {"x": ("x", 0), "y": ("x", 1), "z": ("x", 2), "vx": ("v", 0), "vy": ("v", 1), "vz": ("v", 2),
              "fx": ("f", 0), "fy": ("f", 1), "fz": ("f", 2)}
BIG = 1.0e20


class AveHistoArgs(ScheduleArgs):
    lo: float = param(unit="as the property")     # the values' own units
    hi: float = param(unit="as the property")
    nbin: int = param(ge=1, unit="dimensionless")
    values: list[str] = param(min_length=1, names="value (x, vx, c_ID, c_ID[k], f_ID, f_ID[k], v_NAME)")
    mode: Literal["scalar", "vector"] = keyword("scalar")
    kind: Literal["global", "peratom", "local"] | None = keyword(None)
    file: str | None = keyword(None, names="file name")
    ave: tuple[Literal["one", "running"]] | tuple[Literal["window"], int] = keyword(("one",), unit="dimensionless")
    start: int = keyword(0, ge=0, unit="timesteps")
    beyond: Literal["ignore", "end", "extra"] = keyword("ignore")
    overwrite: tuple[()] | None = keyword(None)
    title1: str | None = keyword(None, names="file line")
    title2: str | None = keyword(None, names="file line")
    title3: str | None = keyword(None, names="file line")

    @model_validator(mode="after")
    def _range(self):
        if not self.lo < self.hi:
            raise ValueError(f"lo must be below hi (got {self.lo:g} {self.hi:g})")
        if self.ave[0] == "window" and self.ave[1] < 1:
            raise ValueError(f"ave window M needs M >= 1 (got {self.ave[1]})")
        return self


class FixAveHisto(Fix):
    name = "ave/histo"
    usage = ("fix ID GROUP ave/histo NEVERY NREPEAT NFREQ LO HI NBIN value... [mode scalar|vector] "
             "[kind global|peratom|local] [file NAME] [ave one|running|window M] [start S] "
             "[beyond ignore|end|extra] [overwrite] [title1 S] [title2 S] [title3 S]")
    Args = AveHistoArgs

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.readers = [self._reader(sim, word) for word in args.values]
        if args.mode == "scalar" and any(many for _, many in self.readers):
            raise ScriptError("per-atom and local values are histogrammed in mode vector (LAMMPS's: fix "
                              "ave/histo cannot input per-atom values in scalar mode)")
        self.extra = args.beyond == "extra"
        self.nbins = args.nbin + 2 if self.extra else args.nbin
        self.width = (args.hi - args.lo) / args.nbin
        inner = args.lo + (np.arange(args.nbin) + 0.5) * self.width
        self.coords = np.concatenate([[args.lo], inner, [args.hi]]) if self.extra else inner
        self.schedule = Schedule(args.nevery, args.nrepeat, args.nfreq, sim.step, args.start)
        self.counts = np.zeros(self.nbins)          # this window's
        self.stats = np.zeros(4)
        self.windows = []                           # ave window: the last M windows' (counts, stats)
        self.total_counts = np.zeros(self.nbins)
        # LAMMPS starts the totals at 0, least and largest too (a running min or max keeps 0 in them)
        self.total_stats = np.zeros(4)
        self.root = sim.comm.rank == 0
        self.handle = None
        if args.file is not None and self.root:
            try:
                self.handle = open(args.file, "w")
            except OSError as exc:
                raise ScriptError(f"cannot open fix ave/histo file {args.file}: {exc.strerror}") from None
            self.handle.write("\n".join([
                args.title1 or f"# Histogrammed data for fix {id}",
                args.title2 or "# TimeStep Number-of-bins Total-counts Missing-counts Min-value Max-value",
                args.title3 or "# Bin Coord Count Count/Total"]) + "\n")
            self.handle.flush()
            self.body_starts = self.handle.tell()

    # ---- the values -------------------------------------------------------------------------------
    def _reader(self, sim, word):
        """A function of sim giving this rank's values of ``word`` (and whether they are to be summed
        over ranks: per-atom and local values are, global ones are the same on every rank)."""
        group = self.group
        if word in COMPONENTS:
            array, d = COMPONENTS[word]

            def components(s):
                p = s.particles
                return p.arrays[array][: p.nlocal, d][s.groups.select(s, group)]
            return components, True
        match = PERATOM_REFERENCE.match(word)
        if match is None:
            raise ScriptError(f"value must be x, y, z, vx, vy, vz, fx, fy, fz, c_ID, c_ID[k], f_ID, f_ID[k] "
                              f"or v_NAME (got {word})")
        prefix, ident, column = match.groups()
        kind = self.args.kind
        if prefix == "v":
            if ident not in sim.variables:
                raise ScriptError(f"variable {ident} is not defined (value {word})")
            if sim.variables.style(ident) == "atom" and kind in (None, "peratom"):
                reference = PeratomReference(sim, word, f"fix {self.id} ave/histo")
                return (lambda s: reference.values(s)[s.groups.select(s, group)]), True
            return (lambda s: np.array([s.variables.value(ident)])), False
        style = sim.computes.get(ident) if prefix == "c" else (sim.fixes.get(ident) or sim.analyzes.get(ident))
        if style is None:
            raise ScriptError(f"{'compute' if prefix == 'c' else 'fix'} {ident} is not defined (value {word})")
        if style is self:
            raise ScriptError(f"{word}: fix ave/histo {ident} cannot histogram its own output")
        peratom = (type(style).peratom is not Compute.peratom) if isinstance(style, Compute) \
            else callable(getattr(style, "peratom", None))
        local = isinstance(style, Compute) and type(style).local is not Compute.local
        if kind == "peratom" or (kind is None and peratom):
            reference = PeratomReference(sim, word, f"fix {self.id} ave/histo")
            return (lambda s: reference.values(s)[s.groups.select(s, group)]), True
        k = None if column is None else sim.dialect_index(int(column), word)
        if kind == "local" or (kind is None and local):
            def rows(s):
                values = np.asarray(style.local(s), dtype=np.float64)
                return values if k is None else values[:, k]
            return rows, True
        if self.args.mode == "vector":
            def whole(s):
                values = np.asarray(style.vector(s) if k is None else style.array(s)[:, k], dtype=np.float64)
                return values
            return whole, False
        if k is None:
            return (lambda s: np.array([float(style.scalar(s))])), False
        return (lambda s: np.array([float(np.asarray(style.vector(s))[k])])), False

    def needs(self, step):
        return {"energy", "virial"} if step == self.schedule.due else set()

    # ---- the schedule -----------------------------------------------------------------------------
    def setup(self, sim):
        self.schedule.run_setup(sim.step)
        self.end_of_step(sim)

    def _bin(self, values):
        args = self.args
        if len(values) == 0:
            return
        self.stats[2] = min(self.stats[2], float(values.min()))
        self.stats[3] = max(self.stats[3], float(values.max()))
        below, above = values < args.lo, values > args.hi
        inside = ~(below | above)
        index = np.minimum(((values[inside] - args.lo) / self.width).astype(np.int64), args.nbin - 1)
        if self.extra:
            index += 1
        np.add.at(self.counts, index, 1.0)
        if args.beyond == "ignore":
            self.stats[1] += float(below.sum() + above.sum())
            self.stats[0] += float(inside.sum())
            return
        self.counts[0] += float(below.sum())
        self.counts[-1] += float(above.sum())
        self.stats[0] += float(len(values))

    def end_of_step(self, sim):
        step = sim.step
        if step != self.schedule.due:
            return
        if self.schedule.irepeat == 0:
            self.counts[:] = 0.0
            self.stats[:] = (0.0, 0.0, BIG, -BIG)
        for read, summed in self.readers:
            values = np.asarray(read(sim), dtype=np.float64)
            if summed or sim.comm.rank == 0:
                self._bin(values)
        if not self.schedule.advance(step):
            return
        counts = np.array(sim.comm.sum(self.counts), dtype=np.float64)     # a copy: the window keeps it
        stats = np.array([sim.comm.sum(self.stats[0]), sim.comm.sum(self.stats[1]),
                          sim.comm.min(self.stats[2]), sim.comm.max(self.stats[3])])
        combine = self.args.ave[0]
        if combine == "one":
            self.total_counts, self.total_stats = counts, stats
        elif combine == "running":
            self.total_counts = self.total_counts + counts
            self.total_stats = np.array([self.total_stats[0] + stats[0], self.total_stats[1] + stats[1],
                                         min(self.total_stats[2], stats[2]), max(self.total_stats[3], stats[3])])
        else:
            self.windows = (self.windows + [(counts, stats)])[-self.args.ave[1]:]
            self.total_counts = np.sum([c for c, _ in self.windows], axis=0)
            kept = np.array([s for _, s in self.windows])
            self.total_stats = np.array([kept[:, 0].sum(), kept[:, 1].sum(), kept[:, 2].min(), kept[:, 3].max()])
        self._write(step)

    def _write(self, step):
        if self.handle is None:
            return
        if self.args.overwrite is not None:
            self.handle.seek(self.body_starts)
            self.handle.truncate()
        total, counts = self.total_stats[0], self.total_counts
        lines = [f"{step} {self.nbins} {total:g} {self.total_stats[1]:g} {self.total_stats[2]:g} "
                 f"{self.total_stats[3]:g}"]
        for i in range(self.nbins):
            share = counts[i] / total if total != 0 else 0.0
            lines.append(f"{i + 1} {self.coords[i]:g} {counts[i] if total != 0 else 0.0:g} {share:g}")
        self.handle.write("\n".join(lines) + "\n")
        self.handle.flush()

    # ---- what scripts read ------------------------------------------------------------------------
    def vector(self, sim):
        return self.total_stats.copy()

    def array(self, sim):
        total = self.total_stats[0]
        share = self.total_counts / total if total != 0 else np.zeros(self.nbins)
        return np.column_stack([self.coords, self.total_counts, share])

    def removed(self, sim):
        if self.handle is not None:
            self.handle.close()
            self.handle = None
