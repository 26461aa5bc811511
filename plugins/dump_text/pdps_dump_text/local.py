"""Dump ``local``: rows of local data (one per contact, bond, ...) that computes give, in LAMMPS's text
format (LAMMPS's and LIGGGHTS's dump local).

Syntax::

    dump ID GROUP local N FILE ATTRIBUTE ...

ATTRIBUTE: ``index`` (the row's number in the frame, from 1), ``c_ID`` (the only column of a
compute's local data), ``c_ID[k]`` (its column k, counted from the dialect's first index: 1 in
LAMMPS's and LIGGGHTS's, 0 in PDPS's) or ``c_ID[*]`` (all its columns, named one by one in the
header, as LAMMPS expands them). Every compute named must give the same number of rows (they
describe the same contacts or bodies). Computes with local data: ``wall/gran/local``,
``pair/gran/local``, ``rigid/local``. The group is not used (each compute has its own). A ``*`` in
the file name writes each frame to a file of its own, the ``*`` replaced by the step (LAMMPS's
wildcard); ``%`` (one file per processor) is refused. Each frame::

    ITEM: TIMESTEP / step / ITEM: NUMBER OF ENTRIES / n / ITEM: BOX BOUNDS ... / 3 lines lo hi /
    ITEM: ENTRIES index c_walls[1] ... / n rows

written whole and flushed; in a parallel run rank 0 gathers every rank's rows (in rank order).

Example::

    compute walls all wall/gran/local pos force
    dump contacts all local 1000 contacts.txt index c_walls[1] c_walls[2] c_walls[3] c_walls[7]
"""

import re

import numpy as np

from pdps_core.api import Compute, Dump, ScriptError, StyleArgs, param

from .files import check_dump_file, write_frame

REFERENCE = re.compile(r"^c_([^\[\]]+)(?:\[(\d+|\*)\])?$")
EVERY_COLUMN = "*"


class DumpLocal(Dump):
    name = "local"
    usage = "dump ID GROUP local N FILE index|c_ID|c_ID[k]|c_ID[*] ..."

    class Args(StyleArgs):
        every: int = param(ge=1, unit="timesteps")
        file: str
        attributes: list[str] = param([], names="attribute")

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        if not args.attributes:
            raise ScriptError(f"dump local needs at least one attribute; usage: {self.usage}")
        self.attributes = []
        for word in args.attributes:
            if word == "index":
                self.attributes.append(("index", None, None))
                continue
            match = REFERENCE.match(word)
            if match is None:
                raise ScriptError(f"attribute must be index, c_ID, c_ID[k] or c_ID[*] (got {word})")
            column = match.group(2)
            if column is not None and column != EVERY_COLUMN:
                column = sim.dialect_index(int(column), word)
            self.attributes.append((word, match.group(1), column))
        self.path = args.file
        self.handle = None
        check_dump_file(sim, self.path)

    def _columns(self, sim):
        """The frame's columns (None for index), their header names and the row count."""
        cache, columns, names, rows = {}, [], [], None
        for word, ident, column in self.attributes:
            if ident is None:
                columns.append(None)
                names.append(word)
                continue
            if ident not in cache:
                compute = sim.computes.get(ident)
                if compute is None:
                    raise ScriptError(f"dump {self.id}: compute {ident} is not defined ({word})")
                if type(compute).local is Compute.local:
                    raise ScriptError(f"dump {self.id}: compute {ident} ({compute.name}) has no local data ({word})")
                values = np.asarray(compute.local(sim), dtype=np.float64)
                cache[ident] = values[:, None] if values.ndim == 1 else values
            values = cache[ident]
            if rows is not None and len(values) != rows:
                raise ScriptError(f"dump {self.id}: {word} has {len(values)} rows, the columns before it {rows}")
            rows = len(values)
            if column is None:
                if values.shape[1] != 1:
                    raise ScriptError(f"dump {self.id}: compute {ident} has {values.shape[1]} columns: "
                                      f"name one as c_{ident}[k]")
                columns.append(values[:, 0])
                names.append(word)
            elif column == EVERY_COLUMN:
                first = 0 if sim.dialect.name == "pdps" else 1      # the dialect's first index
                columns += [values[:, k] for k in range(values.shape[1])]
                names += [f"c_{ident}[{k + first}]" for k in range(values.shape[1])]
            elif not 0 <= column < values.shape[1]:
                raise ScriptError(f"dump {self.id}: {word} is out of range (compute {ident} has "
                                  f"{values.shape[1]} columns)")
            else:
                columns.append(values[:, column])
                names.append(word)
        return columns, names, rows or 0

    def write(self, sim):
        columns, names, rows = self._columns(sim)
        index = [k for k, c in enumerate(columns) if c is None]
        columns = [np.zeros(rows) if c is None else c for c in columns]
        local = np.column_stack(columns) if columns else np.zeros((rows, 0))
        table = sim.comm.gather_rows(local.reshape(rows, len(columns)))
        if not sim.comm.is_root:
            return
        for k in index:
            table[:, k] = np.arange(1, len(table) + 1)
        box = sim.box
        header = [f"ITEM: TIMESTEP\n{sim.step}\n", f"ITEM: NUMBER OF ENTRIES\n{len(table)}\n",
                  f"ITEM: BOX BOUNDS {box.bounds_label(sim.periodicity)}\n"]
        header += ["%-1.16e %-1.16e\n" % (lo, hi) for lo, hi in zip(box.lo.tolist(), box.hi.tolist())]
        header.append(f"ITEM: ENTRIES {' '.join(names)}\n")
        formats = ["%d" if k in index else "%.16g" for k in range(len(columns))]
        body = ((" ".join(formats) + "\n") * len(table)) % tuple(table.ravel().tolist()) if len(table) else ""
        write_frame(self, sim, "".join(header) + body)

    def close(self):
        if self.handle is not None and not self.handle.closed:
            self.handle.close()
