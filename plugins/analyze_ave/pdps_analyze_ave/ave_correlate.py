r"""Fix ``ave/correlate``: time correlations of global values (LAMMPS's and LIGGGHTS's fix
ave/correlate).

Every NEVERY steps (from the first multiple of NEVERY at or after the fix, or after ``start S``)
the values :math:`V_i` are sampled and kept for the last NREPEAT samples. Each sample adds, for each
delay :math:`k = 0 \ldots` (as many as samples kept, up to NREPEAT - 1) and each pair (i, j),
:math:`V_i(t - k\,\Delta)\,V_j(t)` to :math:`C_{ij}(k)` and 1 to its count, :math:`\Delta` = NEVERY
steps. On multiples of NFREQ the correlations :math:`P\,C_{ij}(k)/N(k)` are output (P the
``prefactor``, default 1); with ``ave one`` (the default) the sums then start again from the last
sample, with ``ave running`` they go on.

Pairs (``type``): ``auto`` each value with itself (default), ``upper`` i < j, ``lower`` i > j,
``auto/upper`` i <= j, ``auto/lower`` i >= j, ``full`` every (i, j), in that order (i the outer).

Values: ``c_ID`` (a scalar), ``c_ID[k]`` (an element of a vector), ``f_ID``, ``f_ID[k]``, ``v_NAME``
(an equal-style variable). Output: the array ``f_ID[k][m]``: row k (the delay, from the dialect's
first index), column 1 the delay in steps, 2 the count, then each pair's correlation. The file
(``file NAME``) holds LAMMPS's format: three header lines (``title1``-``title3`` replace them),
then per output ``STEP NREPEAT`` and a line ``k delay count C...`` per delay; ``overwrite`` keeps
the last output only.

Syntax::

    fix ID GROUP ave/correlate NEVERY NREPEAT NFREQ value... [type auto|upper|lower|auto/upper|auto/lower|full]
        [ave one|running] [start S] [prefactor P] [file NAME] [overwrite] [title1 S] [title2 S] [title3 S]

Example::

    fix vacf all ave/correlate 5 100 1000 c_p[1] c_p[2] c_p[3] type auto file p.correlate ave running
"""

from typing import Literal

import numpy as np
from pydantic import model_validator

from pdps_core.api import PERATOM_REFERENCE, Fix, ScriptError, StyleArgs, keyword, param

TYPES = ("auto", "upper", "lower", "auto/upper", "auto/lower", "full")


def pairs_of(kind, n):
    """The (i, j) pairs a correlation type takes, in LAMMPS's order."""
    keep = {"auto": lambda i, j: i == j, "upper": lambda i, j: j > i, "lower": lambda i, j: j < i,
            "auto/upper": lambda i, j: j >= i, "auto/lower": lambda i, j: j <= i, "full": lambda i, j: True}[kind]
    return [(i, j) for i in range(n) for j in range(n) if keep(i, j)]


class AveCorrelateArgs(StyleArgs):
    nevery: int = param(gt=0, unit="timesteps")
    nrepeat: int = param(gt=0, unit="dimensionless")
    nfreq: int = param(gt=0, unit="timesteps")
    values: list[str] = param(min_length=1, names="value (c_ID, c_ID[k], f_ID, f_ID[k], v_NAME)")
    type: Literal[TYPES] = keyword("auto")
    ave: Literal["one", "running"] = keyword("one")
    start: int = keyword(0, ge=0, unit="timesteps")
    prefactor: float = keyword(1.0, unit="as the formula")
    file: str | None = keyword(None, names="file name")
    overwrite: tuple[()] | None = keyword(None)
    title1: str | None = keyword(None, names="file line")
    title2: str | None = keyword(None, names="file line")
    title3: str | None = keyword(None, names="file line")

    @model_validator(mode="after")
    def _schedule(self):
        if self.nfreq % self.nevery or (self.nrepeat - 1) * self.nevery >= self.nfreq:
            raise ValueError(f"nfreq must be a multiple of nevery and (nrepeat - 1) * nevery below it (LAMMPS's; got "
                             f"{self.nevery} {self.nrepeat} {self.nfreq})")
        return self


class FixAveCorrelate(Fix):
    name = "ave/correlate"
    usage = ("fix ID GROUP ave/correlate NEVERY NREPEAT NFREQ value... [type auto|upper|lower|auto/upper|"
             "auto/lower|full] [ave one|running] [start S] [prefactor P] [file NAME] [overwrite] [title1 S] "
             "[title2 S] [title3 S]")
    Args = AveCorrelateArgs

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.readers = [self._reader(sim, word) for word in args.values]
        self.pairs = pairs_of(args.type, len(args.values))
        if not self.pairs:
            raise ScriptError(f"type {args.type} of one value has no pair to correlate")
        self.first = np.array([i for i, _ in self.pairs])
        self.second = np.array([j for _, j in self.pairs])
        self.samples = np.zeros((args.nrepeat, len(args.values)))    # newest first
        self.kept = 0
        self.count = np.zeros(args.nrepeat)
        self.sums = np.zeros((args.nrepeat, len(self.pairs)))
        self.saved = np.zeros((args.nrepeat, 2 + len(self.pairs)))
        self.saved[:, 0] = np.arange(args.nrepeat) * args.nevery
        self.due = self._next_due(sim.step)
        self.handle = None
        if args.file is not None and sim.comm.rank == 0:
            try:
                self.handle = open(args.file, "w")
            except OSError as exc:
                raise ScriptError(f"cannot open fix ave/correlate file {args.file}: {exc.strerror}") from None
            names = " ".join(f"{args.values[i]}*{args.values[j]}" for i, j in self.pairs)
            self.handle.write("\n".join([args.title1 or f"# Time-correlated data for fix {id}",
                                         args.title2 or "# Timestep Number-of-time-windows",
                                         args.title3 or f"# Index TimeDelta Ncount {names}"]) + "\n")
            self.handle.flush()
            self.body_starts = self.handle.tell()

    def _next_due(self, step):
        due = max(step, self.args.start)
        return -(-due // self.args.nevery) * self.args.nevery

    def _reader(self, sim, word):
        match = PERATOM_REFERENCE.match(word)
        if match is None:
            raise ScriptError(f"value must be c_ID, c_ID[k], f_ID, f_ID[k] or v_NAME (got {word})")
        prefix, ident, column = match.groups()
        if prefix == "v":
            if ident not in sim.variables:
                raise ScriptError(f"variable {ident} is not defined (value {word})")
            return lambda s: float(s.variables.value(ident))
        table = sim.computes if prefix == "c" else sim.fixes
        if ident not in table:
            raise ScriptError(f"{'compute' if prefix == 'c' else 'fix'} {ident} is not defined (value {word})")
        if column is None:
            return (lambda s: float(s.compute_value(ident))) if prefix == "c" else \
                (lambda s: float(s.fix_value(ident)))
        indices = (int(column),)
        return (lambda s: float(s.compute_value(ident, indices))) if prefix == "c" else \
            (lambda s: float(s.fix_value(ident, indices)))

    def needs(self, step):
        return {"energy", "virial"} if step == self.due else set()

    def setup(self, sim):
        if self.due < sim.step:
            self.kept = 0
            self.due = self._next_due(sim.step)
        self.end_of_step(sim)

    def _accumulate(self):
        kept = self.kept
        self.count[:kept] += 1.0
        # delay k: the sample k back times the newest
        self.sums[:kept] += self.samples[:kept][:, self.first] * self.samples[0, self.second]

    def end_of_step(self, sim):
        step = sim.step
        if step != self.due:
            return
        self.samples[1:] = self.samples[:-1].copy()
        self.samples[0] = [read(sim) for read in self.readers]
        self.kept = min(self.kept + 1, self.args.nrepeat)
        self.due += self.args.nevery
        self._accumulate()
        if step % self.args.nfreq:
            return
        seen = self.count > 0
        self.saved[:, 1] = self.count
        self.saved[:, 2:] = 0.0
        self.saved[seen, 2:] = self.args.prefactor * self.sums[seen] / self.count[seen][:, None]
        self._write(step)
        if self.args.ave == "one":
            self.count[:] = 0.0
            self.sums[:] = 0.0
            self.kept = 1
            self._accumulate()

    def _write(self, step):
        if self.handle is None:
            return
        if self.args.overwrite is not None:
            self.handle.seek(self.body_starts)
            self.handle.truncate()
        lines = [f"{step} {self.args.nrepeat}"]
        for k in range(self.args.nrepeat):
            count = int(self.count[k])
            values = " ".join(f"{v:g}" for v in self.saved[k, 2:]) if count else " ".join("0.0" for _ in self.pairs)
            lines.append(f"{k + 1} {k * self.args.nevery} {count} {values}")
        self.handle.write("\n".join(lines) + "\n")
        self.handle.flush()

    def array(self, sim):
        return self.saved.copy()

    def removed(self, sim):
        if self.handle is not None:
            self.handle.close()
            self.handle = None
