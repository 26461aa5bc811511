"""The files the text dumps write, named as LAMMPS names them.

- A ``*`` in the name writes each frame to a file of its own, the ``*`` replaced by the step.
- ``%`` (one file per processor) is refused: pdps writes one file per frame.
- A name ending in ``.gz`` is written gzip-compressed, as LAMMPS does (zcat, OVITO and LAMMPS's
  read_dump read it); each frame is flushed to a point from which everything before it decompresses.
- A name ending in ``.bin`` (LAMMPS's binary dump format) is refused at the dump line: pdps writes
  no binary dumps, and a text file under that name would be read as garbage by LAMMPS's tools.
"""

import gzip
import os
import tempfile

from pdps_core.api import ScriptError, SimulationError


def check_dump_file(sim, path):
    """Refuse what pdps cannot write, and a file it cannot open, at the dump command's line."""
    if "%" in path:
        raise ScriptError(f"per-processor dump files (% in {path}) are not supported: pdps writes one file per frame")
    if path.endswith(".bin"):
        raise ScriptError(f"dump file {path}: LAMMPS's binary dump format (.bin) is not written by pdps; "
                          "name the file without .bin (text), or with .gz (compressed text)")
    if sim.comm.is_root:            # rank 0 alone writes
        try:
            # checked now, opened (truncated unless appending) at the first frame
            if "*" in path:
                with tempfile.NamedTemporaryFile(dir=os.path.dirname(path) or ".", prefix=".pdps-probe-"):
                    pass
            else:
                open(path, "a").close()
        except OSError as exc:
            raise ScriptError(f"cannot open dump file {path}: {exc.strerror}") from None


def open_dump_file(path, mode="w"):
    """A text handle on the dump file: gzip-compressed where the name ends in .gz. An error is found by
    rank 0 alone, which writes: a SimulationError stops every rank, not only this one."""
    try:
        if path.endswith(".gz"):
            return gzip.open(path, mode + "t")
        return open(path, mode)
    except OSError as exc:
        raise SimulationError(f"cannot open dump file {path}: {exc.strerror}") from None


def write_frame(dump, sim, text, append=False):
    """Write one frame: to its own file where the name has a ``*``, else to the dump's open file
    (opened at the first frame), flushed so a run that stops leaves every complete frame readable."""
    if "*" in dump.path:
        with open_dump_file(dump.path.replace("*", str(sim.step))) as handle:
            handle.write(text)
        return
    if dump.handle is None:
        dump.handle = open_dump_file(dump.path, "a" if append else "w")
    dump.handle.write(text)
    dump.handle.flush()
