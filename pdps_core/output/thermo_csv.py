"""A machine-readable copy of the thermo table: one CSV row per thermo line.

By default it sits next to the log: ``log.pdps`` -> ``log.pdps.csv`` (``-log none`` or ``log none``:
no CSV; ``log FILE``: a new series at ``FILE.csv``). The first row holds the column names as the
thermo header shows them (``Step,Temp,PotEng,...``); values are written at full precision (the
shortest text that reads back to the same double), where the log keeps 8 digits.

Runs that follow one another append rows to the same file while the columns stay the same. When a
run's columns differ (a new ``thermo_style``), the CSV goes on in a new file with its own header:
``log.pdps.2.csv``, then ``log.pdps.3.csv``, ... Starting a series (at the first run after the log is
opened) removes numbered files an earlier series of the same name left behind, as the log itself
is overwritten, unless the log is appended to (``log FILE append``): then its CSV is too, when its
columns are the run's. Nothing is written before the first run. Rows are flushed with the log.
"""

import csv
import os

from ..errors import ScriptError


def _header(path):
    """The column names of an existing CSV, or None."""
    try:
        with open(path, newline="") as handle:
            return next(csv.reader(handle), None)
    except OSError:
        return None


def numbered(path, index):
    """``log.pdps.csv`` -> ``log.pdps.2.csv`` for index 2; index 1 is the path itself."""
    if index == 1:
        return path
    stem, suffix = (path[:-4], ".csv") if path.endswith(".csv") else (path, "")
    return f"{stem}.{index}{suffix}"


class ThermoCSV:
    def __init__(self, path=None):
        self.path = None
        self.handle = None
        self.writer = None
        self.names = None
        self.index = 0
        self.current = None          # the file rows go to now
        self.use(path)

    def use(self, path, append=False):
        """Write the series to ``path`` from the next run on (None: no CSV); with ``append``, after
        the rows ``path`` holds when its header is the run's."""
        self.close()
        self.path = path
        self.names = None
        self.index = 0
        self.append = append

    def start(self, names):
        """At the start of a run: a header row, in a new file if the columns changed.
        Returns the path of a file begun for changed columns (for a notice), else None."""
        if self.path is None or names == self.names:
            return None
        self.close()
        if self.append and self.index == 0 and _header(self.path) == list(names):
            self.index, self.current, self.names = 1, self.path, list(names)
            try:
                self.handle = open(self.path, "a", newline="")
            except OSError as exc:
                raise ScriptError(f"cannot open thermo CSV file {self.path}: {exc.strerror}") from None
            self.writer = csv.writer(self.handle)
            return None
        self.index += 1
        if self.index == 1:
            self._remove_stale()
        self.current = numbered(self.path, self.index)
        try:
            self.handle = open(self.current, "w", newline="")
        except OSError as exc:
            raise ScriptError(f"cannot open thermo CSV file {self.current}: {exc.strerror}") from None
        self.writer = csv.writer(self.handle)
        self.writer.writerow(names)
        self.names = list(names)
        return self.current if self.index > 1 else None

    def _remove_stale(self):
        index = 2
        while os.path.exists(numbered(self.path, index)):
            os.remove(numbered(self.path, index))
            index += 1

    def row(self, values, integer):
        if self.writer is None:
            return
        self.writer.writerow([int(v) if is_int else repr(float(v)) for v, is_int in zip(values, integer)])

    def flush(self):
        if self.handle is not None:
            self.handle.flush()

    def close(self):
        if self.handle is not None:
            self.handle.close()
        self.handle = self.writer = None
