r"""Fix ``ave/chunk``: per-chunk values averaged in time, as LAMMPS's fix ave/chunk, over the chunks
of a compute chunk/atom (spatial bins, types, molecules).

Over the NREPEAT samples of a window (NEVERY apart, the last on a multiple of NFREQ; see ave/time),
with :math:`c_k` the particles of chunk k that are in the fix's group at a sample, :math:`V_k` the
chunk's volume (compute chunk/atom) and :math:`d_a` ADOF, :math:`d_c` CDOF:

.. math::

    N_k = \frac{\sum c_k}{N_\mathrm{repeat}}, \quad
    \bar{q}_k = \frac{\sum \sum_{i \in k} q_i}{\sum c_k}, \quad
    \rho^{(n)}_k = \frac{N_k}{V_k}, \quad
    \rho^{(m)}_k = \frac{\sum \sum_{i \in k} m_i}{N_\mathrm{repeat} V_k}, \quad
    T_k = \frac{\sum \sum_{i \in k} m_i v_i^2}{k_B\,(N_\mathrm{repeat} d_c + d_a \sum c_k)}

(``norm all``, the default: sums over the window, then divided once). ``norm sample``: each
sample's chunk value (q over its count, T over its own degrees of freedom) averaged over the
samples; ``norm none``: as sample, but the per-particle values summed, not averaged, over the chunk.
Chunks no particle visited report 0.

Values: ``vx vy vz fx fy fz`` (velocity, force), ``mass`` (mean particle mass), ``density/number``
(1/volume), ``density/mass`` (mass/volume, times ``mv2d`` as LAMMPS's thermo density), ``temp``
(temperature, :math:`m v^2` in energy units through ``mvv2e``), and per-atom ``c_ID``, ``c_ID[k]``,
``f_ID``, ``f_ID[k]``, ``v_NAME`` averaged per particle as vx is.

Keywords (LAMMPS's, with its defaults): ``norm all|sample|none``; ``ave one|running|window M``
(each output the window's average, the mean of every window's since the command, or of the last M);
``adof A`` (degrees of freedom per particle, default the dimension) and ``cdof C`` (per chunk,
default 0) of temp (0 in a chunk they leave no degree of freedom); ``file NAME``, or ``append NAME`` (as file, after what NAME holds);
``overwrite`` (with ave running: the file keeps its header and the last output); ``format F`` (each
value's C format, in place of " %g"); ``title1 S``..``title3 S``.
LAMMPS's ``bias`` (a velocity bias compute) is refused at the line: pdps's temperature computes
give none.

File, LAMMPS's format (numbers %g; with compress a column OrigID after Chunk; Coord columns for
bins only)::

    # Chunk-averaged data for fix 2 and group all
    # Timestep Number-of-chunks Total-count
    # Chunk Coord1 Ncount v_temp
    1000 20 800
      1 0.025 40.2 1.187
      ...

The global array ``f_ID[i][j]`` (``array(sim)``) is the last output: one row per chunk, columns
[OrigID], the coordinates, N_k, then the values (zeros before the first output; a row past the
last chunk reads 0, as LAMMPS's).

Syntax::

    fix ID GROUP ave/chunk NEVERY NREPEAT NFREQ CHUNKID value... [norm all|sample|none]
        [ave one|running|window M] [adof A] [cdof C] [file|append NAME] [overwrite] [format F] [title1 S] ...

Examples::

    compute layers all chunk/atom bin/1d z lower 0.05 units reduced
    fix 2 all ave/chunk 10 100 1000 layers v_temp file profile.mp
    fix 4 all ave/chunk 20 250 5000 layers vx density/mass norm sample
"""

import re
from typing import Literal

import numpy as np
from pydantic import model_validator

from pdps_core.api import PERATOM_REFERENCE, Fix, PeratomReference, ScriptError, keyword, observables, param

from .ave_space import ATTRIBUTES, WindowCombination
from .chunk_atom import ComputeChunkAtom
from .schedule import Schedule, ScheduleArgs

# text with one %e, %f or %g conversion (flags, width, precision), %% elsewhere
ONE_NUMBER = re.compile(r"^(?:[^%]|%%)*%[-+ #0]*\d*(?:\.\d+)?[eEfFgG](?:[^%]|%%)*$")
VALUES = ("vx", "vy", "vz", "fx", "fy", "fz", "mass", "density/number", "density/mass", "temp")


class AveChunkArgs(ScheduleArgs):
    chunk: str = param(names="compute chunk/atom ID")
    values: list[str] = param(min_length=1, names="value (" + " ".join(VALUES) + " c_ID c_ID[k] f_ID f_ID[k] v_NAME)")
    norm: Literal["all", "sample", "none"] = keyword("all")
    ave: tuple[Literal["one", "running"]] | tuple[Literal["window"], int] = keyword(("one",), unit="dimensionless")
    adof: float | None = keyword(None, unit="dimensionless")
    cdof: float = keyword(0.0, unit="dimensionless")
    file: str | None = keyword(None, names="file name")
    append: str | None = keyword(None, names="file name")
    bias: str | None = keyword(None, names="compute ID")
    overwrite: tuple[()] | None = keyword(None)
    format: str | None = keyword(None, names="C format")
    title1: str | None = keyword(None, names="file line")
    title2: str | None = keyword(None, names="file line")
    title3: str | None = keyword(None, names="file line")

    @model_validator(mode="after")
    def _combination(self):
        for value in self.values:
            if value not in VALUES and not PERATOM_REFERENCE.match(value):
                raise ValueError(f"values must be {', '.join(VALUES)}, c_ID, c_ID[k], f_ID, f_ID[k] or v_NAME "
                                 f"(got {value})")
        if self.ave[0] == "window" and self.ave[1] < 1:
            raise ValueError(f"ave window M needs M >= 1 (got {self.ave[1]})")
        if self.bias is not None:
            raise ValueError("bias is not in pdps: it has no velocity-bias temperature computes")
        if self.file is not None and self.append is not None:
            raise ValueError("file and append name one file: give one")
        if self.overwrite is not None and self.ave[0] != "running":
            raise ValueError("overwrite needs ave running (LAMMPS)")
        if self.format is not None and not ONE_NUMBER.match(self.format):
            raise ValueError(f"format must be a C format of one number, %e %f or %g (got {self.format})")
        return self


def temperature(twice_kinetic, dof, units):
    """m v^2 summed over a chunk as a temperature over ``dof`` degrees of freedom; 0 where there
    are none (a chunk of one particle with cdof taking its own away: LAMMPS prints inf there)."""
    return np.divide(twice_kinetic * units.mvv2e, dof * units.boltz, out=np.zeros_like(twice_kinetic), where=dof > 0)


def shortest(number):
    """A number as LAMMPS's fmt ``{}`` prints a double: the shortest form that reads back, no ``.0``."""
    text = repr(float(number))
    return text[:-2] if text.endswith(".0") else text


class FixAveChunk(WindowCombination, Fix):
    name = "ave/chunk"
    usage = ("fix ID GROUP ave/chunk NEVERY NREPEAT NFREQ CHUNKID value... [norm all|sample|none] "
             "[ave one|running|window M] [adof A] [cdof C] [file|append NAME] [overwrite] [format F] [title1 S]")
    Args = AveChunkArgs
    array_rows_vary = True      # chunks come and go (compress, nchunk every)

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        chunk = sim.computes.get(args.chunk)
        if not isinstance(chunk, ComputeChunkAtom):
            what = "is not defined" if chunk is None else f"is {chunk.name}, not chunk/atom"
            raise ScriptError(f"fix {id} ave/chunk: compute {args.chunk} {what}")
        self.chunk = chunk
        self.values = list(args.values)
        self.references = {value: PeratomReference(sim, value, f"fix {id} ave/chunk: {value}")
                           for value in self.values if value not in VALUES}
        self.adof = float(sim.dimension) if args.adof is None else args.adof
        self.format = args.format if args.format is not None else " %g"
        self.path = args.file or args.append
        self.schedule = Schedule(args.nevery, args.nrepeat, args.nfreq, sim.step)
        # the chunks stay as set up for a window of several samples, and for good under ave running|window
        self.holds = args.nrepeat > 1 or args.ave[0] != "one"
        if self.holds:
            way = (args.nevery, args.nrepeat, args.nfreq, args.ave[0])
            other = next((fix for fix, held in chunk.holders.items() if held != way and fix != id), None)
            if other is not None:
                raise ScriptError(f"fix {id} ave/chunk: compute {args.chunk} is held by fix {other} over other "
                                  "windows (LAMMPS: \"Two fix commands using same compute chunk/atom command in "
                                  "incompatible ways\"); give each its own compute chunk/atom")
            chunk.holders[id] = way
        self.average = None
        self.windows, self.combined = [], 0
        self.root = sim.comm.rank == 0
        self.body_starts = 0
        if self.path is not None and self.root:
            columns = (["OrigID"] if chunk.compress else []) + [f"Coord{k + 1}" for k in range(chunk.ncoord)]
            self._start_file([f"# Chunk-averaged data for fix {id} and group {group}",
                              "# Timestep Number-of-chunks Total-count",
                              " ".join(["# Chunk", *columns, "Ncount", *self.values])],
                             mode="w" if args.append is None else "a")

    def removed(self, sim):
        """unfix: the chunks are let go once no fix holds them (LAMMPS's unlock)."""
        if self.chunk.holders.pop(self.id, None) is not None and not self.chunk.holders:
            self.chunk.locked = False

    def end_of_step(self, sim):
        step = sim.step
        if step != self.schedule.due:
            return
        if self.schedule.irepeat == 0:
            self.nchunk = self.chunk.setup_chunks(sim)
            # a fix of one-sample windows neither holds the chunks nor lets them go (another may hold them)
            if self.holds:
                self.chunk.locked = True
            self.count_total = np.zeros(self.nchunk)
            self.value_total = np.zeros((self.nchunk, len(self.values)))
        self._sample(sim)
        if self.schedule.advance(step):
            if self.holds and self.args.ave[0] == "one":
                self.chunk.locked = False
            self._average()
            self._combine()
            self._write(step)

    def _sample(self, sim):
        p = sim.particles
        n = p.nlocal
        ids = self.chunk.chunk_ids(sim)
        chosen = sim.groups.select(sim, self.group) & (ids > 0)
        where = ids[chosen] - 1
        nchunk = self.nchunk
        count = np.asarray(sim.comm.sum(np.bincount(where, minlength=nchunk).astype(np.float64)), dtype=np.float64)
        self.count_total += count
        units = sim.units
        per_sample = self.args.norm != "all"
        for k, value in enumerate(self.values):
            if value == "density/number":
                weight = np.ones(len(where))
            elif value in ("density/mass", "mass"):
                weight = observables.masses(sim, chosen)
            elif value == "temp":
                weight = observables.masses(sim, chosen) * (p.v[:n][chosen] ** 2).sum(axis=1)
            elif value in self.references:
                weight = self.references[value].values(sim)[chosen]
            else:
                name, component = ATTRIBUTES[value]
                weight = p.arrays[name][:n][chosen][:, component]
            sums = np.asarray(sim.comm.sum(np.bincount(where, weights=weight, minlength=nchunk)), dtype=np.float64)
            if per_sample:
                # this sample's chunk value joins the window's (LAMMPS's values_one into values_many)
                seen = count > 0
                if value == "temp":
                    sums = temperature(sums, self.args.cdof + self.adof * count, units)
                elif value == "density/number":
                    sums = sums / self.chunk.volume
                elif value == "density/mass":
                    sums = units.mv2d * (sums / self.chunk.volume)
                elif self.args.norm == "sample":
                    sums = np.divide(sums, count, out=np.zeros(nchunk), where=seen)
            self.value_total[:, k] += sums

    def _average(self):
        repeat = self.schedule.nrepeat
        seen = self.count_total > 0
        units = self.sim.units
        values = self.value_total / repeat if self.args.norm != "all" else self.value_total.copy()
        if self.args.norm == "all":
            for k, value in enumerate(self.values):
                column = values[:, k]
                if value == "temp":
                    values[:, k] = temperature(column, repeat * self.args.cdof + self.adof * self.count_total, units)
                elif value == "density/number":
                    column[seen] = column[seen] / self.chunk.volume / repeat
                elif value == "density/mass":
                    column[seen] = column[seen] / self.chunk.volume * (units.mv2d / repeat)
                else:
                    column[seen] /= self.count_total[seen]
        self.window_average = np.column_stack([self.count_total / repeat, values])

    def _table(self, mean):
        return np.column_stack([self.chunk.labels(), mean])

    def _write(self, step):
        if self.path is None or not self.root:
            return
        labels = self.chunk.labels()
        mean = self.total / self.combined
        rows = [f"{step} {self.nchunk} {shortest(self.total[:, 0].sum())}"]
        for m in range(self.nchunk):
            head = [str(m + 1)]
            if self.chunk.compress:
                head.append(str(int(labels[m, 0])))
            head += ["%g" % c for c in labels[m, int(self.chunk.compress):]]
            head.append("%g" % mean[m, 0])
            rows.append("  " + " ".join(head) + "".join(self.format % v for v in mean[m, 1:]))
        self._append(rows)

    def array(self, sim):
        if self.average is not None:
            return self.average.copy()
        # before the first output, as LAMMPS's: zeros (a row for each chunk there is now)
        columns = int(self.chunk.compress) + self.chunk.ncoord + 1 + len(self.values)
        return np.zeros((self.chunk.setup_chunks(sim), columns))
