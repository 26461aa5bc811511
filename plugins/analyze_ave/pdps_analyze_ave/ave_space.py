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
``fx fy fz`` (force).

Keywords: ``file NAME`` (written at each average, LAMMPS's format, appended and closed at once);
``units box|lattice``: DELTA and a coordinate origin in distance units (``box``) or in lattice
spacings (``lattice``). ``analyze ave/space`` defaults to ``box`` (the PDPS manual's example bins
by distance); ``fix ave/spatial`` to the dialect's default: ``lattice`` as LAMMPS (with no lattice
defined a spacing is 1), ``box`` in the PDPS dialect and as LIGGGHTS 3.8.0 (its source; its manual
says lattice).

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
            [file NAME] [units box|lattice]
    fix ID GROUP ave/spatial NEVERY NREPEAT NFREQ DIM ORIGIN DELTA ... value... [file NAME] [units ...]

Examples::

    analyze 1 Al ave/space 1 1 1000 z center 1 density/number file vol_Al.txt
    fix 2 all ave/spatial 10 100 1000 y lower 0.5 vx density/mass file flow.profile units box
"""

import math
from typing import Annotated, Literal, NamedTuple

import numpy as np
from pydantic import Field

from pdps_core.api import Analyze, Fix, ScriptError, check_bins, keyword, observables, param

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


class Bins(NamedTuple):
    """``DIM ORIGIN DELTA``: bins of width DELTA along DIM with a boundary at ORIGIN."""
    dim: Literal["x", "y", "z"]
    origin: Literal["lower", "center", "upper"] | float
    delta: Annotated[float, Field(gt=0)]


class AveSpaceArgs(ScheduleArgs):
    bins: list[Bins] = param(min_length=1, max_length=3, unit=("1", "distance", "distance"))
    values: list[Literal[VALUES]] = param(min_length=1)
    file: str | None = keyword(None, names="file name")
    units: Literal["box", "lattice"] | None = keyword(None)


class AveSpace:
    """What analyze ave/space and fix ave/spatial share (all of it)."""
    Args = AveSpaceArgs
    default_units = "box"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.axes, self.origins, self.deltas = [], [], []
        for axis, origin, delta in args.bins:
            self._add_axis(sim, axis, origin, delta)
        self.values = list(args.values)
        self.path, self.units = args.file, args.units or self.default_units or sim.dialect.region_units
        self.schedule = Schedule(args.nevery, args.nrepeat, args.nfreq, sim.step)
        self.count_total = self.value_total = None
        self.average = None
        self.root = sim.comm.rank == 0      # every rank averages, one writes
        if self.path is not None and self.root:
            self._write_header()

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
        self.first, self.width, self.layers, centres, extents = [], [], [], [], []
        for d, origin, delta in zip(self.axes, self.origins, self.deltas):
            lo, hi = float(box.lo[d]), float(box.hi[d])
            scale = self._scale(sim, d)
            delta *= scale
            if isinstance(origin, str):
                origin = {"lower": lo, "upper": hi, "center": 0.5 * (lo + hi)}[origin]
            else:
                origin *= scale
            check_bins((hi - lo) / delta, f"{self.name} {self.id}: bin width {delta:g} along {AXES[d]} over the box ({lo:g} to {hi:g})")
            first, layers = bin_layout(lo, hi, origin, delta)
            edges = first + delta * np.arange(layers + 1)
            self.first.append(first)
            self.width.append(delta)
            self.layers.append(layers)
            centres.append(first + delta * (np.arange(layers) + 0.5))
            extents.append(np.diff(np.clip(edges, lo, hi)))
        check_bins(math.prod(self.layers), f"{self.name} {self.id}: bins of {' by '.join(map(str, self.layers))}")
        grid = np.meshgrid(*centres, indexing="ij")
        self.coords = np.stack([g.ravel() for g in grid], axis=1)
        volume = np.ones(1)
        for extent in extents:
            volume = np.multiply.outer(volume, extent)
        across = [float(box.length[d]) for d in range(sim.dimension) if d not in self.axes]
        self.volume = volume.ravel() * float(np.prod(across))

    def _bin_of(self, sim, x):
        box = sim.box
        index = []
        for d, first, delta, layers in zip(self.axes, self.first, self.width, self.layers):
            coord = x[:, d]
            if box.periodic[d]:
                coord = box.lo[d] + np.mod(coord - box.lo[d], box.length[d])
            index.append(np.clip(np.floor((coord - first) / delta).astype(np.int64), 0, layers - 1))
        return np.ravel_multi_index(index, self.layers)

    # ---- the timestep -----------------------------------------------------------------------------
    def needs(self, step):
        return set()

    def setup(self, sim):
        self.schedule.run_setup(sim.step)
        self.end_of_step(sim)

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
        self.count_total += sim.comm.sum(np.bincount(where, minlength=nbins).astype(float))
        for k, value in enumerate(self.values):
            if value == "density/number":
                continue
            if value == "density/mass":
                weight = observables.masses(sim, chosen)
            else:
                name, component = ATTRIBUTES[value]
                weight = p.arrays[name][:n][chosen][:, component]
            self.value_total[:, k] += sim.comm.sum(np.bincount(where, weights=weight, minlength=nbins))
        if self.schedule.advance(step):
            self._average()
            self._write(step)

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
            else:
                column[visited] = self.value_total[visited, k] / self.count_total[visited]
            columns.append(column)
        self.average = np.column_stack([self.coords, count, *columns])

    # ---- output -----------------------------------------------------------------------------------
    def _write_header(self):
        coords = "Coord" if len(self.axes) == 1 else " ".join(f"Coord{k + 1}" for k in range(len(self.axes)))
        text = (f"# Spatial-averaged data for {self.kind} {self.id} and group {self.group}\n"
                "# Timestep Number-of-bins\n"
                f"# Bin {coords} Ncount {' '.join(self.values)}\n")
        try:
            with open(self.path, "w") as handle:
                handle.write(text)
        except OSError as exc:
            raise ScriptError(f"cannot open {self.kind} {self.name} file {self.path}: "
                              f"{exc.strerror}") from None

    def _write(self, step):
        if self.path is None or not self.root:
            return
        rows = [f"{step} {len(self.average)}"]
        rows += [f"  {b + 1}" + "".join(" %g" % v for v in row)
                 for b, row in enumerate(self.average.tolist())]
        with open(self.path, "a") as handle:
            handle.write("\n".join(rows) + "\n")

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
