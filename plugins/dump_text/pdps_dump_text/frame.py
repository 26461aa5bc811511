"""What the atom and custom dumps share: LAMMPS's text frame, written and flushed whole each time.

    ITEM: TIMESTEP / step / ITEM: NUMBER OF ATOMS / n / ITEM: BOX BOUNDS pp pp pp / 3 lines lo hi /
    ITEM: ATOMS col1 col2 ... / one row per particle, sorted by id

Rows are formatted in one C-level ``%`` operation per frame; the frame is written with one call and
flushed, so a run that stops leaves every complete frame readable.
"""

import numpy as np

from pdps_core.api import Dump, ScriptError


class TextDump(Dump):
    columns: tuple = ()

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.path = args.file
        self.handle = None
        if sim.comm.is_root:           # rank 0 alone writes
            try:
                self.handle = open(self.path, "w")
            except OSError as exc:
                raise ScriptError(f"cannot open dump file {self.path}: {exc.strerror}") from None

    def column_values(self, sim, chosen):
        """(list of 1-d arrays, list of printf formats), one per column."""
        raise NotImplementedError

    def write(self, sim):
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
        header = [f"ITEM: TIMESTEP\n{sim.step}\n", f"ITEM: NUMBER OF ATOMS\n{len(table)}\n",
                  f"ITEM: BOX BOUNDS {box.bounds_label()}\n"]
        # shortest repr that reads back to the same double (LAMMPS prints 17 digits, %-1.16e)
        header += [f"{lo!r} {hi!r}\n" for lo, hi in zip(box.lo.tolist(), box.hi.tolist())]
        header.append(f"ITEM: ATOMS {' '.join(self.columns)}\n")
        rows = ""
        if len(table):
            rows = ((" ".join(formats) + "\n") * len(table)) % tuple(table.ravel().tolist())
        self.handle.write("".join(header) + rows)
        self.handle.flush()

    def close(self):
        if self.handle is not None and not self.handle.closed:
            self.handle.close()
