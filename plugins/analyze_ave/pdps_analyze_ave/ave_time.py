r"""Analyze ``ave/time`` (also ``fix ave/time``): time averages of computes and variables.

At every step :math:`n` that is a multiple of NFREQ, the average of NREPEAT samples taken NEVERY
steps apart and ending at :math:`n`:

.. math::

    \bar{A}(n) = \frac{1}{N_\mathrm{repeat}} \sum_{k=0}^{N_\mathrm{repeat}-1} A(n - k\,N_\mathrm{every})

taken element by element for vectors and arrays (an RDF's g(r) and coordination number at every r).
NFREQ must be a multiple of NEVERY, and NREPEAT*NEVERY at most NFREQ (LAMMPS's fix ave/time rule);
a run's first step is sampled when it is due, so ``1 1 N`` averages step 0 too.

Values (any number, in the units of what they read):

- ``c_ID``: a compute's scalar; for a compute that has only a vector, each of its elements; for one
  that has only an array (``compute rdf``), the whole array, averaged element by element and written
  as a block of rows (LAMMPS's ``mode vector``). Whole arrays are averaged on their own or with
  arrays of as many rows, not with scalars.
- ``c_ID[i]``, ``c_ID[i][j]``: one element (0-based, as everywhere in pdps); ``c_ID[*]``: every
  element of the vector.
- ``v_NAME``: a variable, read as a number.

Keywords (LAMMPS's): ``ave one|running|window M``: each output is this window's average (one, the
default), the mean of every window's average since the command (running), or of the last M
(window M); ``start S``: no window ends before step S; ``off M``: column M (1-based, after c_ID[*]
is spread into its elements) is not averaged: each output holds its last sample; ``overwrite``
(with ave running): the file keeps the header and the latest output only; ``title1 S``,
``title2 S``, ``title3 S`` (mode vector): the file's header lines instead of the default ones.
``file NAME`` writes each average to NAME (created when the command is read, written
when the first average is complete, each block appended and closed at once, so nothing written is
lost); ``mode scalar|vector`` as LAMMPS: in ``mode vector`` each value is a column (``c_ID``: the
compute's vector, or every column of its array; ``c_ID[j]``: column j of its array; ``c_ID[*]``:
every column).

File format (LAMMPS's; numbers as ``%g``)::

    # Time-averaged data for analyze ID            # one row per average
    # TimeStep c_t v_s
    100 1.0213 95
    # Time-averaged data for analyze ID            # a block per average
    # TimeStep Number-of-rows
    # Row c_1[0] c_1[1] c_1[2]                     # c_1[1] c_1[2] c_1[3] in LAMMPS's dialects
    100 50
    1 0.025 0 0
    ...

Energy and the virial are computed on the sampled steps when a value needs them (a pressure or
energy compute, any variable). The fix spelling cannot ask for them yet (the core asks analyze
styles only): there, such values work on thermo steps only; use the analyze spelling.

The last average is the style's output: ``scalar(sim)`` (one number), ``vector(sim)`` (one row or
one column) and ``array(sim)`` (rows x columns), read in scripts as ``f_ID``, ``f_ID[i]``,
``f_ID[i][j]``; before the first average they read 0, as in LAMMPS (a vector of single values has
its length from the start).

Syntax::

    analyze ID GROUP ave/time NEVERY NREPEAT NFREQ value... [file NAME] [mode scalar|vector]
        [ave one|running|window M] [start S] [off M] [overwrite] [title1 S] [title2 S] [title3 S]
    fix ID GROUP ave/time NEVERY NREPEAT NFREQ value... [same keywords]

GROUP is not used (LAMMPS). Examples::

    analyze 3 all ave/time 1 10000 10000 c_1 file Al-Al.rdf     # PDPS: c_1 a compute rdf
    fix 4 all ave/time 10 5 100 c_t c_c[0] v_e file thermo.avg       # c_c a centroid
    fix 5 all ave/time 100 1 100 c_rdf[*] file tmp.rdf mode vector
"""

import re
from typing import Literal

import numpy as np
from pydantic import model_validator

from pdps_core.api import Analyze, Compute, Fix, ScriptError, keyword, param

from .schedule import Schedule, ScheduleArgs

REFERENCE = re.compile(r"^(c|v|f)_([A-Za-z0-9_]+)((?:\[(?:\d+|\*)\])*)$")


def provides(compute, kind):
    """Whether a compute defines ``scalar``, ``vector`` or ``array`` itself."""
    return getattr(type(compute), kind) is not getattr(Compute, kind)


class Value:
    """One value of the command: ``read(sim)`` gives a rows x columns block; ``many_rows`` tells a
    whole vector column or array (a block of rows per average) from a row of numbers."""

    def __init__(self, word, read, many_rows, indexed_names, needs):
        self.word, self.read, self.many_rows = word, read, many_rows
        self.indexed_names = indexed_names      # columns named word[k] rather than word itself
        self.needs = needs

    def names(self, width, base=0):
        """The file's column names, indexed from ``base`` (the dialect's first index)."""
        if not self.indexed_names:
            return [self.word]
        stem = self.word.removesuffix("[*]")
        return [f"{stem}[{k + base}]" for k in range(width)]


VALUE_WORDS = "c_ID, c_ID[i], c_ID[i][j], c_ID[*], f_ID, f_ID[i], f_ID[*] or v_NAME"


class AveTimeArgs(ScheduleArgs):
    values: list[str] = param(min_length=1, names=VALUE_WORDS)
    file: str | None = keyword(None, names="file name")
    mode: Literal["scalar", "vector"] = keyword("scalar")
    ave: tuple[Literal["one", "running"]] | tuple[Literal["window"], int] = keyword(("one",), unit="dimensionless")
    start: int = keyword(0, ge=0, unit="timesteps")
    off_columns: list[tuple[Literal["off"], int]] = keyword(default_factory=list, spelled_by_entries=True,
                                                            unit="1")
    overwrite: tuple[()] | None = keyword(None)
    title1: str | None = keyword(None, names="file line")
    title2: str | None = keyword(None, names="file line")
    title3: str | None = keyword(None, names="file line")

    @model_validator(mode="after")
    def _combination(self):
        if self.ave[0] == "window" and self.ave[1] < 1:
            raise ValueError(f"ave window M needs M >= 1 (got {self.ave[1]})")
        if self.overwrite is not None and self.ave[0] != "running":
            raise ValueError("overwrite needs ave running (LAMMPS)")
        for _, column in self.off_columns:
            if column < 1:
                raise ValueError(f"off M needs a column M >= 1 (got {column})")
        return self


class AveTime:
    """What analyze ave/time and fix ave/time share (all of it)."""
    Args = AveTimeArgs

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.path, self.mode = args.file, args.mode
        self.values = [self._value(sim, word) for word in args.values]
        self.many_rows = any(value.many_rows for value in self.values)
        if self.many_rows and not all(value.many_rows for value in self.values):
            single = next(v.word for v in self.values if not v.many_rows)
            block = next(v.word for v in self.values if v.many_rows)
            raise ScriptError(f"{block} is averaged as a block of rows and {single} as a single "
                              f"number: average them in two {self.kind} commands")
        single = all(not v.many_rows and not v.indexed_names for v in self.values)
        if args.off_columns and single and max(c for _, c in args.off_columns) > len(self.values):
            raise ScriptError(f"off {max(c for _, c in args.off_columns)}: there are {len(self.values)} values")
        self.schedule = Schedule(args.nevery, args.nrepeat, args.nfreq, sim.step, args.start)
        self.combine = args.ave[0]                      # one, running or window
        self.window = args.ave[1] if self.combine == "window" else None
        self.off = sorted({column - 1 for _, column in args.off_columns})
        self.overwrite = args.overwrite is not None
        self.titles = (args.title1, args.title2, args.title3)
        self.total = None           # sum of this window's samples
        self.windows = []           # the window averages the combination holds (running: their sum)
        self.combined = 0           # how many window averages that sum holds (LAMMPS's norm)
        self.average = None         # the last output: the combination of window averages
        self.columns = None         # column names, known from the first sample
        self.header_written = False
        self.root = sim.comm.rank == 0      # every rank averages, one writes
        if self.path is not None and self.root:
            try:
                open(self.path, "w").close()
            except OSError as exc:
                raise ScriptError(f"cannot open {self.kind} {self.name} file {self.path}: "
                                  f"{exc.strerror}") from None

    # ---- what the values are ----------------------------------------------------------------------
    def _value(self, sim, word):
        match = REFERENCE.match(word)
        if not match:
            raise ScriptError(f"value must be {VALUE_WORDS} (got {word})")
        prefix, ident, brackets = match.groups()
        indices = re.findall(r"\[(\d+|\*)\]", brackets)
        if prefix == "v":
            if indices or self.mode == "vector":
                raise ScriptError(f"a variable is a single number: {word} cannot be indexed or used "
                                  "in mode vector")
            if ident not in sim.variables:
                raise ScriptError(f"variable {ident} is not defined (value {word})")
            # a variable may read anything, as thermo assumes
            return Value(word, lambda s: np.array([[s.variables.value(ident)]]), False, False,
                         lambda s: {"energy", "virial"})
        if prefix == "f":
            return self._fix_value(sim, word, ident, indices)
        return self._compute_value(sim, word, ident, indices)

    def _fix_value(self, sim, word, ident, indices):
        """f_ID (a scalar), f_ID[i] (an element) or f_ID[*] (the whole vector) of a fix or analyze."""
        style = sim.fixes.get(ident) or sim.analyzes.get(ident)
        if style is None:
            raise ScriptError(f"fix {ident} is not defined (value {word})")
        if style is self:
            raise ScriptError(f"{word}: {self.kind} {ident} cannot average its own output")
        if self.mode == "vector":
            raise ScriptError(f"mode vector averages computes' columns; {word} is a fix value")
        if indices == ["*"]:
            def whole(s):
                found = s.fixes.get(ident) or s.analyzes.get(ident)
                return np.asarray(found.vector(s), dtype=float)[None, :]
            return Value(word, whole, False, True, lambda s: set())
        if "*" in indices:
            raise ScriptError(f"only f_ID[*] takes a wildcard (got {word})")
        numbers = tuple(int(i) for i in indices)
        return Value(word, lambda s: np.array([[s.fix_value(ident, numbers)]]), False, False, lambda s: set())

    def _compute_value(self, sim, word, ident, indices):
        compute = sim.computes.get(ident)
        if compute is None:
            raise ScriptError(f"compute {ident} is not defined (value {word})")
        star = indices == ["*"]
        if "*" in indices and not star:
            raise ScriptError(f"only c_ID[*] takes a wildcard (got {word})")
        numbers = () if star else tuple(int(i) for i in indices)

        def whole(s, part):
            found = s.computes.get(ident)
            if found is None:
                raise ScriptError(f"compute {ident} is not defined (value {word} of {self.kind} {self.id})")
            return np.asarray(getattr(found, part)(s), dtype=float)

        def element(s):
            return np.array([[s.compute_value(ident, numbers)]])

        def column(s):
            table = whole(s, "array")
            k = s.dialect_index(numbers[0], word)
            if k >= table.shape[1]:
                raise ScriptError(f"{word} is out of range (compute {ident} has {table.shape[1]} columns, "
                                  f"from {s.dialect.index_base})")
            return table[:, k:k + 1]

        def value(read, many_rows, indexed=False):
            return Value(word, read, many_rows, indexed, lambda s: s.compute_needs(ident))

        only_vector = not provides(compute, "scalar") and provides(compute, "vector")
        only_array = not provides(compute, "scalar") and not provides(compute, "vector") \
            and provides(compute, "array")
        if self.mode == "vector":
            if len(numbers) > 1:
                raise ScriptError(f"mode vector averages columns: {word} is a single element")
            if numbers:
                return value(column, True)
            if not star and provides(compute, "vector"):
                return value(lambda s: whole(s, "vector")[:, None], True)
            return value(lambda s: whole(s, "array"), True, indexed=True)
        if numbers:
            return value(element, False)
        if star or only_vector:
            return value(lambda s: whole(s, "vector")[None, :], False, indexed=True)
        if only_array:
            return value(lambda s: whole(s, "array"), True, indexed=True)
        return value(element, False)

    # ---- the timestep -----------------------------------------------------------------------------
    def needs(self, step):
        """Energy/virial for the computes read on a sampling step (output flags)."""
        if step != self.schedule.due:
            return set()
        wanted = set()
        for value in self.values:
            wanted |= value.needs(self.sim)
        return wanted

    def setup(self, sim):
        self.schedule.run_setup(sim.step)
        self.end_of_step(sim)

    def end_of_step(self, sim):
        step = sim.step
        if step != self.schedule.due:
            return
        sample = self._sample(sim)
        if self.schedule.irepeat == 0:
            self.total = np.zeros_like(sample)
        elif sample.shape != self.total.shape:
            raise ScriptError(f"{self.kind} {self.id} ({self.name}): the values changed shape from "
                              f"{self.total.shape} to {sample.shape} within an average at step {step}")
        self.total += sample
        if self.off:
            self._check_off(sample)
            self.total[:, self.off] = sample[:, self.off]       # off: the last sample, not averaged
        if self.schedule.advance(step):
            mean = self.total / self.schedule.nrepeat
            if self.off:
                mean[:, self.off] = self.total[:, self.off]
            self.average = self._combined(mean)
            self._write(step)

    def _check_off(self, sample):
        if self.off[-1] >= sample.shape[1]:
            raise ScriptError(f"{self.kind} {self.id} ({self.name}): off {self.off[-1] + 1} is beyond its "
                              f"{sample.shape[1]} column(s)")

    def _combined(self, mean):
        """The output from this window's average: itself (ave one), the mean of every window so far
        (running) or of the last M (window M); off columns keep this window's value (LAMMPS)."""
        if self.combine == "one":
            return mean
        if self.windows and self.windows[0].shape != mean.shape:
            raise ScriptError(f"{self.kind} {self.id} ({self.name}): the values changed shape from "
                              f"{self.windows[0].shape} to {mean.shape} between averages (ave {self.combine})")
        if self.combine == "running":
            self.windows = [mean.copy()] if not self.windows else [self.windows[0] + mean]
            self.combined += 1
            out = self.windows[0] / self.combined
        else:
            self.windows = (self.windows + [mean.copy()])[-self.window:]
            out = sum(self.windows) / len(self.windows)
        if self.off:
            out[:, self.off] = mean[:, self.off]
        return out

    def _sample(self, sim):
        blocks = [value.read(sim) for value in self.values]
        rows = {block.shape[0] for block in blocks}
        if len(rows) > 1:
            sizes = ", ".join(f"{v.word} {b.shape[0]}" for v, b in zip(self.values, blocks))
            raise ScriptError(f"values averaged together need as many rows (got {sizes})")
        if self.columns is None:
            base = sim.dialect.index_base
            self.columns = [name for v, b in zip(self.values, blocks) for name in v.names(b.shape[1], base)]
        return np.hstack(blocks)

    def _write(self, step):
        if self.path is None or not self.root:
            return
        lines = []
        if not self.header_written or self.overwrite:
            names = self.columns
            title1, title2, title3 = self.titles
            lines.append(title1 if title1 is not None else f"# Time-averaged data for {self.kind} {self.id}")
            if self.many_rows:
                lines += [title2 if title2 is not None else "# TimeStep Number-of-rows",
                          title3 if title3 is not None else "# Row " + " ".join(names)]
            else:
                lines.append(title2 if title2 is not None else "# TimeStep " + " ".join(names))
            self.header_written = True
        if self.many_rows:
            lines.append(f"{step} {self.average.shape[0]}")
            lines += [f"{i + 1}" + "".join(" %g" % v for v in row)
                      for i, row in enumerate(self.average.tolist())]
        else:
            lines.append(f"{step}" + "".join(" %g" % v for v in self.average[0].tolist()))
        # overwrite: the file holds the header and the latest output only (LAMMPS's)
        with open(self.path, "w" if self.overwrite else "a") as handle:
            handle.write("\n".join(lines) + "\n")

    # ---- the averages as output -------------------------------------------------------------------
    def scalar(self, sim):
        if self.average is None:
            return 0.0
        if self.average.size != 1:
            raise ScriptError(f"{self.kind} {self.id} ({self.name}) averages {self.average.size} "
                              "numbers, not one: read one of them by index")
        return float(self.average[0, 0])

    def vector(self, sim):
        if self.average is None:
            # LAMMPS reads 0 before the first average; the length is known when every value is one number
            single = all(not v.many_rows and not v.indexed_names for v in self.values)
            return np.zeros(len(self.values) if single else 0)
        if self.average.shape[0] == 1:
            return self.average[0].copy()
        if self.average.shape[1] == 1:
            return self.average[:, 0].copy()
        raise ScriptError(f"{self.kind} {self.id} ({self.name}) averages an array of shape "
                          f"{self.average.shape}: read it as an array")

    def array(self, sim):
        return np.zeros((0, 0)) if self.average is None else self.average.copy()


class AnalyzeAveTime(AveTime, Analyze):
    name = "ave/time"
    usage = ("analyze ID GROUP ave/time NEVERY NREPEAT NFREQ value... [file NAME] [mode scalar|vector] "
             "[ave one|running|window M] [start S] [off M] [overwrite] [title1|title2|title3 S]")


class FixAveTime(AveTime, Fix):
    name = "ave/time"
    usage = ("fix ID GROUP ave/time NEVERY NREPEAT NFREQ value... [file NAME] [mode scalar|vector] "
             "[ave one|running|window M] [start S] [off M] [overwrite] [title1|title2|title3 S]")
