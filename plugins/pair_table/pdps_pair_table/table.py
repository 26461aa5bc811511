r"""Pair style ``table``: a pair potential tabulated in a file and interpolated as LAMMPS's
``pair_style table`` interpolates it (LAMMPS's pair_table.cpp; cubic splines after Numerical Recipes).

Syntax::

    pair_style table STYLE N            STYLE = lookup | linear | spline, N = table length (>= 2)
    pair_coeff I J FILE KEYWORD [CUTOFF]

``FILE`` is looked for beside the script, then in the working folder (LAMMPS: the working folder).
The file holds sections; a section starts with a line whose first word is its ``KEYWORD``, then a
parameter line ``N n [R rlo rhi | RSQ rlo rhi] [FPRIME fplo fphi]``, then ``n`` lines
``index r E(r) F(r)`` (distance, energy, force = -dE/dr). Blank lines and lines starting with ``#``
are skipped. With ``R``/``RSQ`` the r column is replaced by n points evenly spaced in r / in r^2
from rlo to rhi; ``FPRIME`` gives dF/dr at the two ends (older files write it ``FP``, and ``NOFP`` for
none: both are read too). ``BITMAP`` tables are refused.

What pdps computes from it, as LAMMPS does:

1. Cubic splines through the file's E(r) (end slopes -F at both ends) and F(r) (end slopes ``FPRIME``,
   else the first and last finite differences).
2. An internal table of N points evenly spaced in r^2 from the inner r (rlo, else the first r) to
   the cutoff (``CUTOFF``, else rhi, else the last r): E and F/r at each point, from the splines (or
   the file's values themselves when a linear table has N = n RSQ points ending at the cutoff).
3. Per pair, with k = floor((r^2 - r_in^2) / delta):

   - ``lookup``: E and F/r at the middle of bin k;
   - ``linear``: linear interpolation in r^2 between points k and k+1;
   - ``spline``: a cubic spline in r^2 through the N points (end slopes from the splines in r).

Units: r distance, E energy, F force. Pairs closer than the inner r stop the run with a message naming
the table, as LAMMPS's "Pair distance < table inner cutoff". Mixing does not apply: every type pair
needs its pair_coeff. Example::

    pair_style table linear 1000
    pair_coeff 1 1 lj.table LJ 2.5
"""

import math
from typing import Literal

import numpy as np
from numba import njit
from pdps_core.api import PairLaw, ScriptError, StyleArgs, param


@njit(cache=True, inline="always")
def _bin(rsq, coeff, state):
    """Row of the table, bin k of it (or -1 when r is inside the inner cutoff)."""
    row = int(coeff[0])
    if rsq < coeff[1]:
        too_close = state[7]
        if too_close[0] < 0.0 or rsq < too_close[0]:
            too_close[0] = rsq
            too_close[1] = row
        return row, -1
    k = int((rsq - coeff[1]) * coeff[2])
    # rsq < cut^2 always; rounding may still put it one bin past the last
    last = state[0].shape[1] - 2
    return row, k if k <= last else last


@njit(cache=True, inline="always")
def lookup_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    """coeff = (row, r_in^2, 1/delta, delta^2/6); state = (rsq, e, f, de, df, e2, f2, too_close)."""
    row, k = _bin(rsq, coeff, state)
    if k < 0:
        return 0.0, 0.0
    return state[2][row, k], state[1][row, k]


@njit(cache=True, inline="always")
def linear_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    row, k = _bin(rsq, coeff, state)
    if k < 0:
        return 0.0, 0.0
    fraction = (rsq - state[0][row, k]) * coeff[2]
    return (state[2][row, k] + fraction * state[4][row, k],
            state[1][row, k] + fraction * state[3][row, k])


@njit(cache=True, inline="always")
def spline_law(rsq, dx, dy, dz, coeff, i, j, atom, state):
    row, k = _bin(rsq, coeff, state)
    if k < 0:
        return 0.0, 0.0
    b = (rsq - state[0][row, k]) * coeff[2]
    a = 1.0 - b
    ca = a * a * a - a
    cb = b * b * b - b
    e, f, e2, f2 = state[1], state[2], state[5], state[6]
    fpair = a * f[row, k] + b * f[row, k + 1] + (ca * f2[row, k] + cb * f2[row, k + 1]) * coeff[3]
    energy = a * e[row, k] + b * e[row, k + 1] + (ca * e2[row, k] + cb * e2[row, k + 1]) * coeff[3]
    return fpair, energy


LAWS = {"lookup": lookup_law, "linear": linear_law, "spline": spline_law}


def spline(x, y, yp1, ypn):
    """Second derivatives of the cubic spline through (x, y) with end slopes yp1, ypn (a slope
    above 0.99e30 means a natural end), in the order of operations LAMMPS uses, so its tables come
    out to the last bit."""
    n = len(x)
    y2 = [0.0] * n
    u = [0.0] * n
    if yp1 > 0.99e30:
        y2[0] = u[0] = 0.0
    else:
        y2[0] = -0.5
        u[0] = (3.0 / (x[1] - x[0])) * ((y[1] - y[0]) / (x[1] - x[0]) - yp1)
    for i in range(1, n - 1):
        sig = (x[i] - x[i - 1]) / (x[i + 1] - x[i - 1])
        p = sig * y2[i - 1] + 2.0
        y2[i] = (sig - 1.0) / p
        u[i] = (y[i + 1] - y[i]) / (x[i + 1] - x[i]) - (y[i] - y[i - 1]) / (x[i] - x[i - 1])
        u[i] = (6.0 * u[i] / (x[i + 1] - x[i - 1]) - sig * u[i - 1]) / p
    if ypn > 0.99e30:
        qn = un = 0.0
    else:
        qn = 0.5
        un = (3.0 / (x[n - 1] - x[n - 2])) * (ypn - (y[n - 1] - y[n - 2]) / (x[n - 1] - x[n - 2]))
    y2[n - 1] = (un - qn * u[n - 2]) / (qn * y2[n - 2] + 1.0)
    for k in range(n - 2, -1, -1):
        y2[k] = y2[k] * y2[k + 1] + u[k]
    return y2


def splint(xa, ya, y2a, x):
    """The spline's value at x (bisection for the interval, as LAMMPS)."""
    klo, khi = 0, len(xa) - 1
    while khi - klo > 1:
        k = (khi + klo) >> 1
        if xa[k] > x:
            khi = k
        else:
            klo = k
    h = xa[khi] - xa[klo]
    a = (xa[khi] - x) / h
    b = (x - xa[klo]) / h
    return a * ya[klo] + b * ya[khi] + ((a * a * a - a) * y2a[klo] + (b * b * b - b) * y2a[khi]) * (h * h) / 6.0


class TableFile:
    """One section of a LAMMPS table file, read and checked: r, E, F as given (r replaced when the
    section says R or RSQ), the R/RSQ range and the FP end slopes."""

    def __init__(self, path, keyword, name=None):
        """``path`` to open; ``name`` the file as the script wrote it, for messages."""
        self.keyword = keyword
        self.path = name or path
        try:
            with open(path, encoding="utf-8", errors="replace") as handle:
                lines = handle.read().splitlines()
        except OSError as exc:
            raise ScriptError(f"cannot open table file {self.path} ({exc.strerror or exc})") from None
        path = self.path
        content = [(number, line.split()) for number, line in enumerate(lines, 1)
                   if line.strip() and not line.lstrip().startswith("#")]
        start = next((k for k, (_, words) in enumerate(content) if words[0] == keyword), None)
        if start is None:
            raise ScriptError(f"table file {path} has no section {keyword}")
        if start + 1 >= len(content):
            raise ScriptError(f"table file {path}:{content[start][0]}: section {keyword} has no parameter line")
        self._parameters(*content[start + 1])
        r, e, f = [], [], []
        for number, words in content[start + 2:]:
            if not _is_index(words[0]):
                break               # the next section's keyword
            if len(r) == self.n:
                raise ScriptError(f"table file {path}:{number}: section {keyword} declares N {self.n} but has "
                                  "more lines of values")
            if len(words) < 4:
                raise ScriptError(f"table file {path}:{number}: expected 'index r energy force', got "
                                  f"{' '.join(words)!r}")
            values = [_number(w, path, number, what) for w, what in zip(words[1:4], ("r", "energy", "force"))]
            r.append(values[0])
            e.append(values[1])
            f.append(values[2])
        if len(r) != self.n:
            raise ScriptError(f"table file {path}: section {keyword} declares N {self.n} but has {len(r)} "
                              "lines of values")
        if self.rflag == "R":
            r = [self.rlo + (self.rhi - self.rlo) * i / (self.n - 1) for i in range(self.n)]
        elif self.rflag == "RSQ":
            r = [math.sqrt(self.rlo * self.rlo + (self.rhi * self.rhi - self.rlo * self.rlo) * i / (self.n - 1))
                 for i in range(self.n)]
        if not (0.0 < r[0] and math.isfinite(r[-1] * r[-1])):
            raise ScriptError(f"table file {path}: section {keyword}: r must lie in (0, 1e154) "
                              f"(got {r[0]:g} to {r[-1]:g})")
        for k in range(1, self.n):
            if not r[k] > r[k - 1]:
                raise ScriptError(f"table file {path}: section {keyword}: r must increase (r = {r[k]:g} after "
                                  f"{r[k - 1]:g})")
        self.r, self.e, self.f = r, e, f

    def _parameters(self, number, words):
        path = self.path
        self.n = None
        self.rflag, self.fpflag = None, False
        k = 0
        while k < len(words):
            word = words[k]
            if word == "BITMAP":
                raise ScriptError(f"table file {path}:{number}: BITMAP tables are not supported; "
                                  "tabulate with R or RSQ")
            if word == "NOFP":
                self.fpflag = False
                k += 1
                continue
            arity = {"N": 1, "R": 2, "RSQ": 2, "FPRIME": 2, "FP": 2}.get(word)
            if arity is None:
                raise ScriptError(f"table file {path}:{number}: unknown table parameter {word!r} "
                                  "(expected N, R, RSQ, FPRIME)")
            values = words[k + 1:k + 1 + arity]
            if len(values) != arity:
                raise ScriptError(f"table file {path}:{number}: {word} needs {arity} value{'s' * (arity > 1)}")
            if word == "N":
                if not values[0].isdigit() or int(values[0]) < 2:
                    raise ScriptError(f"table file {path}:{number}: N must be an integer >= 2 (got {values[0]})")
                self.n = int(values[0])
            elif word in ("R", "RSQ"):
                self.rflag = word
                self.rlo, self.rhi = (_number(v, path, number, word) for v in values)
                if not 0 < self.rlo < self.rhi:
                    raise ScriptError(f"table file {path}:{number}: {word} needs 0 < rlo < rhi "
                                      f"(got {self.rlo:g} {self.rhi:g})")
            else:
                self.fpflag = True
                self.fplo, self.fphi = (_number(v, path, number, word) for v in values)
            k += 1 + arity
        if self.n is None:
            raise ScriptError(f"table file {path}:{number}: section {self.keyword} does not set N")


def _is_index(word):
    return word.lstrip("+-").isdigit()


def _number(word, path, line, what):
    try:
        value = float(word)
    except ValueError:
        value = math.nan
    if not math.isfinite(value):
        raise ScriptError(f"table file {path}:{line}: {what} {word!r} is not a finite number")
    return value


class Table:
    """The internal table LAMMPS's compute_table builds from one file section (see the module
    docstring): arrays of length N (e, f, e2, f2, rsq; de, df of length N-1)."""

    def __init__(self, source, style, length, cutoff):
        try:
            self._build(source, style, length, cutoff)
            finite = all(np.isfinite(a).all() for a in (self.rsq, self.e, self.f, self.de, self.df, self.e2, self.f2))
        except (ZeroDivisionError, OverflowError):
            finite = False
        if not finite:
            raise ScriptError(f"table {source.keyword} ({source.path}): interpolating it with {length} points "
                              "gives non-finite values (r values too close together, or values too large)")

    def _build(self, source, style, length, cutoff):
        self.source, self.style, self.length = source, style, length
        if cutoff is None:
            cutoff = source.rhi if source.rflag else source.r[-1]
        rlo, rhi = (source.rlo, source.rhi) if source.rflag else (source.r[0], source.r[-1])
        if not rlo < cutoff <= rhi:
            raise ScriptError(f"cutoff {cutoff:g} is outside table {source.keyword} "
                              f"(r from {rlo:g} to {rhi:g})")
        self.cut = cutoff
        match = (style == "linear" and source.n == length and source.rflag == "RSQ" and source.rhi == cutoff)
        r, e, f = source.r, source.e, source.f
        if not match:
            e2file = spline(r, e, -f[0], -f[-1])
            if not source.fpflag:
                source.fplo = (f[1] - f[0]) / (r[1] - r[0])
                source.fphi = (f[-1] - f[-2]) / (r[-1] - r[-2])
            f2file = spline(r, f, source.fplo, source.fphi)
        tlm1 = length - 1
        inner = rlo
        self.innersq = inner * inner
        self.delta = (cutoff * cutoff - self.innersq) / tlm1
        self.invdelta = 1.0 / self.delta
        self.deltasq6 = self.delta * self.delta / 6.0
        size = length
        self.rsq = np.zeros(size)
        self.e = np.zeros(size)
        self.f = np.zeros(size)
        self.de = np.zeros(size)
        self.df = np.zeros(size)
        self.e2 = np.zeros(size)
        self.f2 = np.zeros(size)
        if style == "lookup":
            for i in range(tlm1):
                rr = math.sqrt(self.innersq + (i + 0.5) * self.delta)
                self.e[i] = splint(r, e, e2file, rr)
                self.f[i] = splint(r, f, f2file, rr) / rr
            return
        for i in range(length):
            rsq = self.innersq + i * self.delta
            rr = math.sqrt(rsq)
            self.rsq[i] = rsq
            if match:
                self.e[i], self.f[i] = e[i], f[i] / rr
            else:
                self.e[i] = splint(r, e, e2file, rr)
                self.f[i] = splint(r, f, f2file, rr) / rr if style == "linear" else splint(r, f, f2file, rr)
        if style == "linear":
            self.de[:tlm1] = [self.e[i + 1] - self.e[i] for i in range(tlm1)]
            self.df[:tlm1] = [self.f[i + 1] - self.f[i] for i in range(tlm1)]
            return
        # spline in r^2: E's end slopes dE/d(r^2) = -F / 2r; F/r's from the file's F slope or a
        # secant through the spline in r
        e_list, f_list = self.e.tolist(), self.f.tolist()
        self.e2[:] = spline(self.rsq.tolist(), e_list, -f_list[0] / (2.0 * math.sqrt(self.innersq)),
                            -f_list[tlm1] / (2.0 * cutoff))
        secant = 0.1
        if source.fpflag:
            fp0 = (source.fplo / math.sqrt(self.innersq) - f_list[0] / self.innersq) / (2.0 * math.sqrt(self.innersq))
        else:
            rsq1 = self.innersq
            rsq2 = rsq1 + secant * self.delta
            fp0 = (splint(r, f, f2file, math.sqrt(rsq2)) / math.sqrt(rsq2) - f_list[0] / math.sqrt(rsq1)) \
                / (secant * self.delta)
        if source.fpflag and cutoff == r[-1]:
            fpn = (source.fphi / cutoff - f_list[tlm1] / (cutoff * cutoff)) / (2.0 * cutoff)
        else:
            rsq2 = cutoff * cutoff
            rsq1 = rsq2 - secant * self.delta
            fpn = (f_list[tlm1] / math.sqrt(rsq2) - splint(r, f, f2file, math.sqrt(rsq1)) / math.sqrt(rsq1)) \
                / (secant * self.delta)
        f_over_r = [f_list[i] / math.sqrt(self.rsq[i]) for i in range(length)]
        self.f[:] = f_over_r
        self.f2[:] = spline(self.rsq.tolist(), f_over_r, fp0, fpn)


class PairTable(PairLaw):
    name = "table"
    usage = "pair_style table lookup|linear|spline N"
    coeff_usage = "FILE KEYWORD [CUTOFF]"
    params = ("row", "inner_rsq", "inverse_delta", "delta_squared_over_6")

    class Args(StyleArgs):
        style: Literal["lookup", "linear", "spline"] = param()
        length: int = param(ge=2, le=1_000_000, unit="1")

    class Coeff(StyleArgs):
        file: str = param()
        keyword: str = param()
        cutoff: float | None = param(None, gt=0, unit="distance")

    def __init__(self, sim, args):
        super().__init__(sim, args)
        self.tables = {}        # (file, keyword, cutoff) -> Table

    def _table(self, coeff):
        key = (coeff.file, coeff.keyword, coeff.cutoff)
        if key not in self.tables:
            source = TableFile(self.sim.resolve(coeff.file), coeff.keyword, name=coeff.file)
            self.tables[key] = Table(source, self.args.style, self.args.length, coeff.cutoff)
        return self.tables[key]

    def parse_coeff(self, words):
        coeff = super().parse_coeff(words)
        self._table(coeff)      # as LAMMPS, the file is read (and its faults reported) at pair_coeff
        return coeff

    def init(self, ntypes, pairs=None):
        self._rows = []
        cut = super().init(ntypes, pairs)
        n = self.args.length
        arrays = [np.zeros((max(len(self._rows), 1), n)) for _ in range(7)]
        for row, table in enumerate(self._rows):
            for array, values in zip(arrays, (table.rsq, table.e, table.f, table.de, table.df, table.e2, table.f2)):
                array[row] = values
        self._state = (*arrays, np.array([-1.0, 0.0]))
        return cut

    def mix(self, i, j):
        raise ScriptError(f"pair coefficients are not set for types {i} {j} (pair style table does not mix; "
                          "give pair_coeff for every type pair)")

    def init_one(self, i, j):
        table = self._table(self.resolved[(i, j)])
        if table not in self._rows:
            self._rows.append(table)
        row = self._rows.index(table)
        return table.cut, (row, table.innersq, table.invdelta, table.deltasq6)

    def force_law(self):
        return LAWS[self.args.style]

    def law_state(self, sim):
        return self._state

    def compute(self, sim, nlist, eflag, vflag):
        too_close = self._state[7]
        too_close[0] = -1.0
        super().compute(sim, nlist, eflag, vflag)
        message = None
        if too_close[0] >= 0.0:
            table = self._rows[int(too_close[1])]
            inner = math.sqrt(table.innersq)
            message = (f"pair table: two particles {math.sqrt(too_close[0]):.6g} apart, inside the inner "
                       f"cutoff {inner:g} of table {table.source.keyword} ({table.source.path}) at step {sim.step}")
        sim.comm.agree(message)
