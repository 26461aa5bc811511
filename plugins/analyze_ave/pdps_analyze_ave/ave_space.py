r"""Analyze ``ave/space`` (also ``fix ave/spatial``): profiles in bins of space, averaged in time.

The box is cut into slabs of width DELTA along one axis (or into columns or cells along two or three
axes). Over the NREPEAT samples of a window (see ave/time: NEVERY apart, ending on multiples of
NFREQ), with :math:`c_b` the particles of the group in bin b at a sample and :math:`V_b` the bin's
volume (area in 2-d):

.. math::

    N_b = \frac{\sum c_b}{N_\mathrm{repeat}}, \qquad
    \rho^{(n)}_b = \frac{N_b}{V_b}, \qquad
    \rho^{(m)}_b = \frac{\sum \sum_{i \in b} m_i}{N_\mathrm{repeat}\, V_b}, \qquad
    \bar{v}_{x,b} = \frac{\sum \sum_{i \in b} v_{x,i}}{\sum c_b}

(number density, mass density, and per-particle averages of vx vy vz fx fy fz: LAMMPS's
``norm all``; 0 in a bin no particle visited).

Bins: along each axis named, ``ORIGIN`` (``lower``, ``center``, ``upper`` or a coordinate) is a bin
boundary and bins of width DELTA (distance) are laid from it to cover the box, as LAMMPS's fix
ave/spatial does: ``z center 1`` in a box 0..10 gives bins 0-1, ..., 9-10; ``z center 3`` gives
-1-2, 2-5, 5-8, 8-11. A bin is reported at its centre (``-1-2`` at 0.5). Particles outside the box
on a periodic axis are wrapped; on a fixed axis they count in the nearest bin. :math:`V_b` is the
part of the bin inside the box times the box lengths along the axes not binned: the same as
LAMMPS's DELTA*area for bins inside the box, but for a bin that sticks out of the box LAMMPS
divides by the whole bin and so under-counts its density; pdps divides by the part in the box.

Values: ``density/number`` (1/volume), ``density/mass`` (mass/volume), ``vx vy vz`` (velocity),
``fx fy fz`` (force), and per-atom values averaged per particle as vx is: ``c_ID``, ``c_ID[k]``,
``f_ID``, ``f_ID[k]`` (from the dialect's first index), ``v_NAME`` (atom-style), as LAMMPS's and
LIGGGHTS's fix ave/spatial.

Keywords: ``file NAME`` (written at each average, LAMMPS's format, appended and closed at once);
``units box|lattice``: DELTA and a coordinate origin in distance units (``box``) or in lattice
spacings (``lattice``). ``analyze ave/space`` defaults to ``box`` (the PDPS manual's example bins
by distance); ``fix ave/spatial`` to ``lattice``, as LAMMPS (with no lattice defined a spacing is 1), and
to ``box`` in LIGGGHTS's dialect, as LIGGGHTS 3.8.0 (its source; its manual says lattice).

LAMMPS's and LIGGGHTS's keywords too: ``norm all|sample`` (``sample``: the per-particle values are
the mean over the window's samples of each sample's bin average, densities and counts as for all);
``ave one|running|window M`` (each output the window's average, the mean of every window's since
the command, or of the last M); ``overwrite`` (with ave running: the file keeps its header and the
last output);
``title1 S`` ``title2 S`` ``title3 S`` (the header's lines); ``write_ts yes|no`` (LIGGGHTS: the
``STEP NBINS`` line before each output, default yes); ``std LO HI FILE`` (LIGGGHTS: a line per
output in FILE of ``STEP count nbins count_max empty below above kept kept_average`` and, per value,
its count-weighted mean, the mean over the bins whose count is within LO..HI, and their standard
deviation about the former, with LIGGGHTS's sums over the windows combined).

File format (numbers as ``%g``)::

    # Spatial-averaged data for analyze ID and group GROUP
    # Timestep Number-of-bins
    # Bin Coord Ncount density/number
    1000 10
      1 0.5 40 0.4
      ...

(``Coord1 Coord2`` for bins along two axes.) The last average is the style's output ``array(sim)``:
one row per bin, columns: the bin's coordinates, N_b, then the values.

Syntax::

    analyze ID GROUP ave/space NEVERY NREPEAT NFREQ DIM ORIGIN DELTA [DIM ORIGIN DELTA]... value...
            [file NAME] [units box|lattice] [norm all|sample] [ave one|running|window M] [overwrite]
            [title1 S] [title2 S] [title3 S] [write_ts yes|no] [std LO HI FILE]
    fix ID GROUP ave/spatial NEVERY NREPEAT NFREQ DIM ORIGIN DELTA ... value... [file NAME] [units ...] ...

Examples::

    analyze 1 Al ave/space 1 1 1000 z center 1 density/number file vol_Al.txt
    fix 2 all ave/spatial 10 100 1000 y lower 0.5 vx density/mass file flow.profile units box
"""

import math
from typing import Annotated, Literal, NamedTuple

import numpy as np
from pydantic import Field, model_validator

from pdps_core.api import (PERATOM_REFERENCE, Analyze, Fix, PeratomReference, ScriptError, check_bins, keyword,
                           observables, param)

from .schedule import Schedule, ScheduleArgs

AXES = ("x", "y", "z")
ATTRIBUTES = {"vx": ("v", 0), "vy": ("v", 1), "vz": ("v", 2),
              "fx": ("f", 0), "fy": ("f", 1), "fz": ("f", 2)}
VALUES = ("density/number", "density/mass", "vx", "vy", "vz", "fx", "fy", "fz")


def bin_layout(lo, hi, origin, delta):
    """(first bin boundary, number of bins) covering [lo, hi] with a boundary at ``origin``."""
    if origin < lo:
        first = origin + int((lo - origin) / delta) * delta
    else:
        first = origin - int((origin - lo) / delta) * delta
        if first > lo:
            first -= delta
    if origin < hi:
        last = origin + int((hi - origin) / delta) * delta
        if last < hi:
            last += delta
    else:
        last = origin - int((origin - hi) / delta) * delta
    return first, max(1, int((last - first) / delta + 0.5))


def lay_bins(lo, hi, origin, delta, scale, what, axis):
    """(first boundary, width, number) of the bins along one axis from lo to hi: ORIGIN a word
    (``lower``, ``center``, ``upper``) or a number, it and DELTA times ``scale`` (lattice spacings);
    ``what`` names the style, ``axis`` the axis, in the too-many-bins error."""
    delta *= scale
    if isinstance(origin, str):
        origin = {"lower": lo, "upper": hi, "center": 0.5 * (lo + hi)}[origin]
    else:
        origin *= scale
    check_bins((hi - lo) / delta, f"{what}: bin width {delta:g} along {axis} over the box ({lo:g} to {hi:g})")
    first, layers = bin_layout(lo, hi, origin, delta)
    return first, delta, layers


def bin_centres(firsts, widths, layers, what):
    """The centres of the bins of one to three axes, one row each, the first axis slowest."""
    check_bins(math.prod(layers), f"{what}: bins of {' by '.join(map(str, layers))}")
    centres = [first + width * (np.arange(n) + 0.5) for first, width, n in zip(firsts, widths, layers)]
    grid = np.meshgrid(*centres, indexing="ij")
    return np.stack([g.ravel() for g in grid], axis=1)


def bin_index(coord, lo, length, periodic, first, delta):
    """Each coordinate's bin along one axis, LAMMPS's way: wrapped into the box on a periodic axis,
    ``floor((coord - first) * (1/delta))`` (its product, not a quotient, so that a particle on a
    boundary falls where LAMMPS puts it), unclamped: -1 or ``layers`` and beyond lie outside."""
    if periodic:
        coord = lo + np.mod(coord - lo, length)
    return np.floor((coord - first) * (1.0 / delta)).astype(np.int64)


class WindowCombination:
    """``ave one|running|window M`` over the averages of successive windows (LAMMPS's ave/spatial,
    ave/chunk) and the file written at each: the class sets ``self.args`` (with ``ave``, ``title1``..3,
    ``overwrite``), ``self.path``, ``self.root`` and ``self.window_average``, and says in
    ``_table(mean)`` how a combined mean becomes the output rows; with its ``self.schedule`` and
    per-atom ``self.references`` it also gets the samples' step logic (``needs``, ``setup``)."""

    def needs(self, step):
        if step != self.schedule.due or not self.references:
            return set()
        return set().union(*(reference.needs(self.sim) for reference in self.references.values()))

    def setup(self, sim):
        self.schedule.run_setup(sim.step)
        self.end_of_step(sim)

    def _combine(self):
        """This window's average combined as ``ave`` says; ``self.average`` the output table."""
        combine = self.args.ave[0]
        window = self.window_average
        if combine == "one":
            self.windows, self.combined = [window], 1
        elif combine == "running":
            self.windows = [window if not self.windows else self.windows[0] + window]
            self.combined += 1
        else:
            self.windows = (self.windows + [window])[-self.args.ave[1]:]
            self.combined = len(self.windows)
        total = self.windows[0] if combine != "window" else np.sum(self.windows, axis=0)
        self.total = total
        self.average = self._table(total / self.combined)

    def _start_file(self, lines, mode="w"):
        """The file's three header lines (title1..3 in their place), anew or (``mode`` "a") after
        what it holds; ``body_starts`` where the averages begin (overwrite rewrites from there)."""
        args = self.args
        text = "\n".join(title or line for title, line in zip((args.title1, args.title2, args.title3), lines)) + "\n"
        try:
            with open(self.path, mode) as handle:
                handle.write(text)
                self.body_starts = handle.tell()
        except OSError as exc:
            raise ScriptError(f"cannot open {self.kind} {self.name} file {self.path}: "
                              f"{exc.strerror}") from None

    def _append(self, rows):
        """One output's lines, after the last (overwrite: in place of the last)."""
        with open(self.path, "r+" if self.args.overwrite is not None else "a") as handle:
            if self.args.overwrite is not None:
                handle.seek(self.body_starts)
                handle.truncate()
            handle.write("\n".join(rows) + "\n")


class Bins(NamedTuple):
    """``DIM ORIGIN DELTA``: bins of width DELTA along DIM with a boundary at ORIGIN."""
    dim: Literal["x", "y", "z"]
    origin: Literal["lower", "center", "upper"] | float
    delta: Annotated[float, Field(gt=0)]


class AveSpaceArgs(ScheduleArgs):
    bins: list[Bins] = param(min_length=1, max_length=3, unit=("1", "distance", "distance"))
    values: list[str] = param(min_length=1, names="value (" + " ".join(VALUES) + " c_ID c_ID[k] f_ID f_ID[k] v_NAME)")
    file: str | None = keyword(None, names="file name")
    units: Literal["box", "lattice"] | None = keyword(None)
    norm: Literal["all", "sample"] = keyword("all")
    ave: tuple[Literal["one", "running"]] | tuple[Literal["window"], int] = keyword(("one",), unit="dimensionless")
    overwrite: tuple[()] | None = keyword(None)
    title1: str | None = keyword(None, names="file line")
    title2: str | None = keyword(None, names="file line")
    title3: str | None = keyword(None, names="file line")
    write_ts: bool = keyword(True)
    std: tuple[int, int, str] | None = keyword(None, unit=("1", "1", "1"))

    @model_validator(mode="after")
    def _combination(self):
        for value in self.values:
            if value not in VALUES and not PERATOM_REFERENCE.match(value):
                raise ValueError(f"values must be {', '.join(VALUES)}, c_ID, c_ID[k], f_ID, f_ID[k] or v_NAME "
                                 f"(got {value})")
        if self.ave[0] == "window" and self.ave[1] < 1:
            raise ValueError(f"ave window M needs M >= 1 (got {self.ave[1]})")
        if self.overwrite is not None and self.ave[0] != "running":
            raise ValueError("overwrite needs ave running (LAMMPS)")
        return self


class AveSpace(WindowCombination):
    """What analyze ave/space and fix ave/spatial share (all of it)."""
    Args = AveSpaceArgs
    default_units = "box"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.axes, self.origins, self.deltas = [], [], []
        for axis, origin, delta in args.bins:
            self._add_axis(sim, axis, origin, delta)
        self.values = list(args.values)
        # per-atom values of computes, fixes and atom-style variables, averaged per particle as vx is
        self.references = {value: PeratomReference(sim, value, f"{self.kind} {id} {self.name}: {value}")
                           for value in self.values if value not in VALUES}
        self.path, self.units = args.file, args.units or self.default_units or sim.dialect.command_units
        self.schedule = Schedule(args.nevery, args.nrepeat, args.nfreq, sim.step)
        self.count_total = self.value_total = None
        self.average = None
        self.windows = []           # the window averages the combination holds (ave running: their sum)
        self.combined = 0           # how many window averages that is (LAMMPS's norm)
        self.root = sim.comm.rank == 0      # every rank averages, one writes
        self.body_starts = 0
        if self.path is not None and self.root:
            self._write_header()
        self.std_path = args.std[2] if args.std is not None else None
        if self.std_path is not None and self.root:
            low, high, _ = args.std
            try:
                with open(self.std_path, "w") as handle:
                    # LIGGGHTS's header, spacing and all
                    handle.write(f"# Spatial-averaged data for fix {id} and group {group}\n"
                                 f"# Mean and standard deviation for all bins including between N1={low} and "
                                 f"N2={high} particles\n# Timestep  Natoms  Nbins  MaxAtomsPerBin  NbinsEmpty  "
                                 "Nbins<N1  Nbins>N2  Nsamples  NatomsPerSample  "
                                 + "".join(f"{{{value}: trueMean samplesMean Std}}   " for value in self.values) + "\n")
            except OSError as exc:
                raise ScriptError(f"cannot open {self.kind} {self.name} std file {self.std_path}: "
                                  f"{exc.strerror}") from None

    def _add_axis(self, sim, axis, origin, delta):
        d = AXES.index(axis)
        if d in self.axes:
            raise ScriptError(f"axis {axis} is binned twice")
        if d == 2 and sim.dimension == 2:
            raise ScriptError("cannot bin along z in a 2-d simulation")
        self.axes.append(d)
        self.origins.append(origin)
        self.deltas.append(delta)

    # ---- bins -------------------------------------------------------------------------------------
    def _scale(self, sim, d):
        if self.units == "box" or sim.lattice is None:
            return 1.0
        return float(sim.lattice.spacing[d])

    def _setup_bins(self, sim):
        """Bin boundaries, centres and volumes for the current box (called at each window start)."""
        box = sim.box
        self.first, self.width, self.layers, extents = [], [], [], []
        for d, origin, delta in zip(self.axes, self.origins, self.deltas):
            lo, hi = float(box.lo[d]), float(box.hi[d])
            first, delta, layers = lay_bins(lo, hi, origin, delta, self._scale(sim, d), f"{self.name} {self.id}",
                                            AXES[d])
            edges = first + delta * np.arange(layers + 1)
            self.first.append(first)
            self.width.append(delta)
            self.layers.append(layers)
            extents.append(np.diff(np.clip(edges, lo, hi)))
        self.coords = bin_centres(self.first, self.width, self.layers, f"{self.name} {self.id}")
        volume = np.ones(1)
        for extent in extents:
            volume = np.multiply.outer(volume, extent)
        across = [float(box.length[d]) for d in range(sim.dimension) if d not in self.axes]
        self.volume = volume.ravel() * float(np.prod(across))

    def _bin_of(self, sim, x):
        box = sim.box
        index = []
        for d, first, delta, layers in zip(self.axes, self.first, self.width, self.layers):
            where = bin_index(x[:, d], box.lo[d], box.length[d], box.periodic[d], first, delta)
            index.append(np.clip(where, 0, layers - 1))
        return np.ravel_multi_index(index, self.layers)

    # ---- the timestep -----------------------------------------------------------------------------
    def end_of_step(self, sim):
        step = sim.step
        if step != self.schedule.due:
            return
        if self.schedule.irepeat == 0:
            self._setup_bins(sim)
            nbins = len(self.volume)
            self.count_total = np.zeros(nbins)
            self.value_total = np.zeros((nbins, len(self.values)))
        p = sim.particles
        n = p.nlocal
        chosen = sim.groups.select(sim, self.group)
        where = self._bin_of(sim, p.x[:n][chosen])
        nbins = len(self.volume)
        count = np.asarray(sim.comm.sum(np.bincount(where, minlength=nbins).astype(float)), dtype=np.float64)
        self.count_total += count
        per_sample = self.args.norm == "sample"
        for k, value in enumerate(self.values):
            if value == "density/number":
                continue
            if value == "density/mass":
                weight = observables.masses(sim, chosen)
            elif value in self.references:
                weight = self.references[value].values(sim)[chosen]
            else:
                name, component = ATTRIBUTES[value]
                weight = p.arrays[name][:n][chosen][:, component]
            sums = np.asarray(sim.comm.sum(np.bincount(where, weights=weight, minlength=nbins)), dtype=np.float64)
            if per_sample and value != "density/mass":
                # norm sample: this sample's bin average joins the window's (LAMMPS's values_one/count)
                sums = np.divide(sums, count, out=np.zeros(nbins), where=count > 0)
            self.value_total[:, k] += sums
        if self.schedule.advance(step):
            self._average()
            self._combine()
            self._write(step)
            self._write_std(step)

    def _average(self):
        repeat = self.schedule.nrepeat
        count = self.count_total / repeat
        visited = self.count_total > 0
        inside = self.volume > 0
        columns = []
        for k, value in enumerate(self.values):
            column = np.zeros_like(count)
            if value == "density/number":
                column[inside] = count[inside] / self.volume[inside]
            elif value == "density/mass":
                column[inside] = self.value_total[inside, k] / repeat / self.volume[inside]
            elif self.args.norm == "sample":
                column = self.value_total[:, k] / repeat
            else:
                column[visited] = self.value_total[visited, k] / self.count_total[visited]
            columns.append(column)
        self.window_average = np.column_stack([count, *columns])

    def _table(self, mean):
        return np.column_stack([self.coords, mean])

    # ---- output -----------------------------------------------------------------------------------
    def _write_header(self):
        coords = "Coord" if len(self.axes) == 1 else " ".join(f"Coord{k + 1}" for k in range(len(self.axes)))
        self._start_file([f"# Spatial-averaged data for {self.kind} {self.id} and group {self.group}",
                          "# Timestep Number-of-bins", f"# Bin {coords} Ncount {' '.join(self.values)}"])

    def _write(self, step):
        if self.path is None or not self.root:
            return
        rows = [f"{step} {len(self.average)}"] if self.args.write_ts else []
        rows += [f"  {b + 1}" + "".join(" %g" % v for v in row)
                 for b, row in enumerate(self.average.tolist())]
        self._append(rows)

    def _write_std(self, step):
        """LIGGGHTS's std file line: the values' spread over the bins whose count is within LO..HI,
        from the sums over the windows combined (count_total, values_total), as LIGGGHTS takes them."""
        if self.std_path is None or not self.root:
            return
        low, high, _ = self.args.std
        count, values = self.total[:, 0], self.total[:, 1:]
        count_sum = float(count.sum())
        true_mean = values.T @ count / count_sum if count_sum else np.zeros(values.shape[1])
        empty = count == 0
        below = ~empty & (count < low)
        above = ~empty & ~below & (count > high)
        kept = ~(empty | below | above)
        n_kept = int(kept.sum())
        samples_mean, std, kept_average = np.zeros(values.shape[1]), np.zeros(values.shape[1]), 0.0
        if n_kept:
            kept_average = float(count[kept].sum()) / n_kept
            samples_mean = values[kept].mean(axis=0) / self.combined
            std = np.sqrt(((values[kept] - true_mean) ** 2).mean(axis=0)) / self.combined
        line = (f"{step} {count_sum:g} {len(count)} {float(count.max()):g} {int(empty.sum())} {int(below.sum())} "
                f"{int(above.sum())} {n_kept} {kept_average:g}"
                + "".join(f" {m:g} {a:g} {d:g}" for m, a, d in zip(true_mean, samples_mean, std)))
        with open(self.std_path, "a") as handle:
            handle.write(line + "\n")

    def array(self, sim):
        if self.average is not None:
            return self.average.copy()
        # before the first average, as LAMMPS's: the bins' coordinates, every value 0
        if getattr(self, "coords", None) is None:
            self._setup_bins(sim)
        return np.column_stack([self.coords, np.zeros((len(self.coords), 1 + len(self.values)))])


class AnalyzeAveSpace(AveSpace, Analyze):
    name = "ave/space"
    usage = ("analyze ID GROUP ave/space NEVERY NREPEAT NFREQ DIM ORIGIN DELTA [DIM ORIGIN DELTA]... "
             "value... [file NAME] [units box|lattice]")


class FixAveSpatial(AveSpace, Fix):
    name = "ave/spatial"
    usage = ("fix ID GROUP ave/spatial NEVERY NREPEAT NFREQ DIM ORIGIN DELTA [DIM ORIGIN DELTA]... "
             "value... [file NAME] [units box|lattice]")
    default_units = None        # the dialect's: LAMMPS lattice, LIGGGHTS box
