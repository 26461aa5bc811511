"""What the atom and custom dumps share: LAMMPS's text frame, written and flushed whole each time.

    ITEM: TIMESTEP / step / ITEM: NUMBER OF ATOMS / n / ITEM: BOX BOUNDS pp pp pp / 3 lines lo hi /
    ITEM: ATOMS col1 col2 ... / one row per particle, sorted by id

Rows are formatted in one C-level ``%`` operation per frame; the frame is written with one call and
flushed, so a run that stops leaves every complete frame readable.

``dump_modify`` keywords: ``sort id`` (the default here; LAMMPS's is unsorted), ``sort N`` / ``sort -N``
(by column N, ascending or descending; ``sort off`` keeps id order, so frames stay comparable),
``format line "F1 F2 ..."``, ``format int F``, ``format float F``, ``format N F`` (C formats;
``format none`` resets), ``append yes`` (frames added to an existing file), plus every and first.

A ``*`` in the file name (LAMMPS's wildcard) writes each frame to a file of its own, the ``*``
replaced by the step (``dump.*.txt`` -> ``dump.0.txt``, ``dump.100.txt``, ...); ``%`` (one file per
processor) is refused: pdps writes one file per frame. A name ending in ``.gz`` is written
gzip-compressed, as LAMMPS; ``.bin`` (LAMMPS's binary format) is refused at the dump line (files.py).
"""

import numpy as np

from pdps_core.api import Dump, ScriptError

from .files import check_dump_file, write_frame


def _check_format(fmt):
    fmt = fmt.strip('"\'')
    try:
        fmt % (1,)
    except (TypeError, ValueError):
        raise ScriptError(f"{fmt} is not a C format for one number") from None
    return fmt


class TextDump(Dump):
    columns: tuple = ()

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.path = args.file
        self.handle = None
        self.sort_column = 0            # 0: by id; k > 0: by column k ascending, k < 0 descending
        self.formats = {"line": None, "int": None, "float": None, "columns": {}}
        self.frames = 0
        self.append = False
        check_dump_file(sim, self.path)

    def column_values(self, sim, chosen):
        """(list of 1-d arrays, list of printf formats), one per column."""
        raise NotImplementedError

    def modify(self, sim, keyword, values):
        if keyword == "sort":
            word = values[0]
            if word in ("id", "off"):
                self.sort_column = 0
            else:
                try:
                    column = int(word)
                except ValueError:
                    raise ScriptError(f"sort must be id, off or a column number N or -N (got {word})") from None
                if not 1 <= abs(column) <= len(self.columns):
                    raise ScriptError(f"sort {word}: the dump has columns 1 to {len(self.columns)}")
                self.sort_column = column
        elif keyword == "format":
            self._format(values)
        elif keyword == "append":
            if values[0] not in ("yes", "no"):
                raise ScriptError(f"append must be yes or no (got {values[0]})")
            if self.frames:
                raise ScriptError("append must be set before the dump writes its first frame")
            self.append = values[0] == "yes"
        else:
            super().modify(sim, keyword, values)

    def _format(self, values):
        kind = values[0]
        if kind == "none":
            self.formats = {"line": None, "int": None, "float": None, "columns": {}}
            return
        fmt = values[1]
        if kind == "line":
            parts = fmt.split()
            if len(parts) != len(self.columns):
                raise ScriptError(f"format line has {len(parts)} formats for {len(self.columns)} columns")
            for part in parts:
                _check_format(part)
            self.formats["line"] = parts
        elif kind in ("int", "float"):
            self.formats[kind] = _check_format(fmt)
        else:
            try:
                column = int(kind)
            except ValueError:
                raise ScriptError(f"format must be line, int, float, none or a column number (got {kind})") from None
            if not 1 <= column <= len(self.columns):
                raise ScriptError(f"format {column}: the dump has columns 1 to {len(self.columns)}")
            self.formats["columns"][column] = _check_format(fmt)

    def _formats(self, formats):
        """The formats of this frame: the style's, with dump_modify's in their place."""
        out = []
        for k, fmt in enumerate(formats):
            chosen = self.formats["columns"].get(k + 1)
            if chosen is None and self.formats["line"] is not None:
                chosen = self.formats["line"][k]
            if chosen is None:
                chosen = self.formats["int" if fmt == "%d" else "float"]
            out.append(chosen or fmt)
        return out

    def write(self, sim):
        self.frames += 1
        p, box = sim.particles, sim.box
        chosen = np.flatnonzero(sim.groups.select(sim, self.group))
        values, formats = self.column_values(sim, chosen)
        # one float table, led by the tag to sort on: "%d" prints a float's integer part, and ids
        # stay exact below 2**53; in a parallel run rank 0 gathers every rank's rows and writes
        local = np.column_stack([p.tag[chosen].astype(np.float64)]
                                + [np.asarray(column, dtype=np.float64) for column in values])
        table = sim.comm.gather_rows(local.reshape(len(chosen), len(values) + 1))
        if not sim.comm.is_root:
            return
        table = table[np.argsort(table[:, 0], kind="stable"), 1:]
        if self.sort_column:
            key = table[:, abs(self.sort_column) - 1]
            order = np.argsort(key if self.sort_column > 0 else -key, kind="stable")
            table = table[order]
        formats = self._formats(formats)
        header = [f"ITEM: TIMESTEP\n{sim.step}\n", f"ITEM: NUMBER OF ATOMS\n{len(table)}\n",
                  f"ITEM: BOX BOUNDS {box.bounds_label(sim.periodicity)}\n"]
        # LAMMPS's 17 digits: the same text, and the same double read back
        header += ["%-1.16e %-1.16e\n" % (lo, hi) for lo, hi in zip(box.lo.tolist(), box.hi.tolist())]
        header.append(f"ITEM: ATOMS {' '.join(self.columns)}\n")
        rows = ""
        if len(table):
            rows = ((" ".join(formats) + "\n") * len(table)) % tuple(table.ravel().tolist())
        write_frame(self, sim, "".join(header) + rows, append=self.append)

    def close(self):
        if self.handle is not None and not self.handle.closed:
            self.handle.close()
