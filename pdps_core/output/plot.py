"""``pdps plot LOG [-o PNG] [--columns COLUMN...]``: thermo columns against the step, one panel each.

LOG is a thermo CSV (``log.pdps.csv``, read when the name ends in ``.csv``) or a log file, whose
thermo tables are read from the text: a header line of names directly followed by a line of as many
numbers; its rows run to the run's ``Loop time`` line (other lines in between, such as warnings, are
skipped). The tables of several runs are joined; a column missing from a run is left blank there.
Columns are named as in the header (``Temp``) or by thermo keyword (``temp``); by default every
column but the step. The PNG (default ``LOG.png``) is drawn without a display (matplotlib's Agg);
matplotlib is needed only here (``pip install matplotlib``).

Example::

    pdps plot log.pdps.csv --columns temp pe press -o water.png
"""

import csv
import math

from ..errors import ScriptError
from .thermo import HEADERS

PANEL_HEIGHT = 2.0      # inches per panel
MARGIN = 0.8            # inches for the title and the x label
WIDTH = 8.0
DPI = 100


class ThermoTable:
    """Column names and rows of numbers, as read from a CSV or a log."""

    def __init__(self, names=None, rows=None):
        self.names = list(names or [])
        self.rows = [list(row) for row in rows or []]

    def append(self, names, rows):
        """Rows under their own header; columns new to the table are added, blank before."""
        for name in names:
            if name not in self.names:
                self.names.append(name)
                for row in self.rows:
                    row.append(math.nan)
        where = [self.names.index(name) for name in names]
        for values in rows:
            row = [math.nan] * len(self.names)
            for k, value in zip(where, values):
                row[k] = value
            self.rows.append(row)

    def column(self, name):
        k = self.names.index(name)
        return [row[k] for row in self.rows]


def _number(word):
    try:
        return float(word)
    except ValueError:
        return None


def read_csv(path):
    table = ThermoTable()
    with open(path, newline="") as handle:
        reader = csv.reader(handle)
        names = next(reader, None)
        if not names:
            raise ScriptError("empty thermo CSV", source=path)
        rows = []
        for row in reader:
            if not row:
                continue
            values = [_number(word) for word in row]
            if len(values) != len(names) or None in values:
                raise ScriptError(f"line {reader.line_num} is not {len(names)} numbers: {','.join(row)}",
                                  source=path)
            rows.append(values)
    table.append(names, rows)
    return table


def read_log(path):
    """Every thermo table of a log, joined (module docstring)."""
    with open(path) as handle:
        lines = handle.read().splitlines()
    table, found, k = ThermoTable(), False, 0
    while k < len(lines):
        names = lines[k].split()
        following = lines[k + 1].split() if k + 1 < len(lines) else []
        numbers = [_number(word) for word in following]
        is_header = (names and len(following) == len(names) and None not in numbers
                     and all(_number(word) is None for word in names))
        if not is_header:
            k += 1
            continue
        rows, k = [], k + 1
        while k < len(lines) and not lines[k].startswith(("Loop time", "ERROR")):
            values = [_number(word) for word in lines[k].split()]
            if len(values) == len(names) and None not in values:
                rows.append(values)
            k += 1
        table.append(names, rows)
        found = True
    if not found:
        raise ScriptError("no thermo table found (a header line followed by a line of numbers)",
                          source=path)
    return table


def read_thermo(path):
    try:
        return read_csv(path) if path.endswith(".csv") else read_log(path)
    except OSError as exc:
        raise ScriptError(f"cannot read {path}: {exc.strerror}") from None


def choose_columns(table, wanted, path):
    """Header names for the columns asked for (header names or thermo keywords)."""
    if not wanted:
        return [name for name in table.names if name != "Step"]
    chosen = []
    for word in wanted:
        folded = [name for name in table.names if name.lower() == word.lower()]
        if word in table.names:
            chosen.append(word)
        elif HEADERS.get(word) in table.names:
            chosen.append(HEADERS[word])
        elif len(folded) == 1:
            chosen.append(folded[0])
        else:
            raise ScriptError(f"no column {word} (columns: {', '.join(table.names)})", source=path)
    return chosen


def build_figure(table, columns, title=""):
    """A matplotlib Figure: one panel per column against Step (the row number if there is none),
    sharing the x axis; WIDTH x (PANEL_HEIGHT per panel + MARGIN) inches at DPI."""
    from matplotlib.figure import Figure
    if not columns:
        raise ScriptError("no column to plot besides the step")
    if "Step" in table.names:
        x, xlabel = table.column("Step"), "Step"
    else:
        x, xlabel = list(range(len(table.rows))), "row"
    figure = Figure(figsize=(WIDTH, PANEL_HEIGHT * len(columns) + MARGIN), dpi=DPI)
    axes = figure.subplots(len(columns), 1, sharex=True, squeeze=False)[:, 0]
    for ax, name in zip(axes, columns):
        points = [(a, b) for a, b in zip(x, table.column(name)) if not math.isnan(b)]
        ax.plot([p[0] for p in points], [p[1] for p in points], linewidth=1.0)
        ax.set_ylabel(name)
        ax.grid(alpha=0.3)
    axes[-1].set_xlabel(xlabel)
    if title:
        figure.suptitle(title)
    figure.align_ylabels(axes)
    figure.tight_layout()
    return figure


def plot_thermo(path, output=None, columns=None):
    """Read ``path``, draw the chosen columns and write the PNG; returns its path."""
    try:
        import matplotlib  # noqa: F401  (checked here for a one-line error)
    except ImportError:
        raise ScriptError("pdps plot needs matplotlib: pip install matplotlib") from None
    table = read_thermo(path)
    if not table.rows:
        raise ScriptError("the thermo table has no rows", source=path)
    figure = build_figure(table, choose_columns(table, columns, path), title=path)
    output = output or f"{path}.png"
    try:
        figure.savefig(output, dpi=DPI, format="png")
    except OSError as exc:
        raise ScriptError(f"cannot write {output}: {exc.strerror}") from None
    return output
