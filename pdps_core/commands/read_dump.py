"""``read_dump``: one snapshot of a dump file written by ``dump custom`` (or ``dump atom``) overwrites,
trims, purges or adds particles, sets the step to the snapshot's and, by default, the box to its box.

    read_dump FILE NSTEP FIELD... [box yes|no] [replace yes|no] [purge yes|no] [trim yes|no]
              [add yes|no] [label FIELD COLUMN]... [scaled yes|no] [wrapped yes|no] [format native]

FILE may end in ``.gz`` (read gzipped) or hold one ``*``: every file of its directory the pattern
matches, in the order of the number the ``*`` stands for, searched for the snapshot in turn. NSTEP
is the step the snapshot was written at; it becomes the current step (as reset_timestep sets it).
The FIELDs are columns to read: x y z (a column labelled x, xs, xu or xsu: the first in the file's
order; scaled columns are unscaled by the snapshot's box), vx vy vz, q, radius, ix iy iz (image
flags), omegax omegay omegaz and mass (LIGGGHTS's code reads these too). The file must have ``id``
and ``type`` columns. ``label FIELD COLUMN`` reads FIELD (one of the FIELDs, or id, type) from the
column so labelled; a labelled coordinate is scaled and wrapped as ``scaled`` and ``wrapped`` say
(defaults no and yes), an unlabelled one as its label says.

What it does, as LIGGGHTS 3.8.0 does (its ReadDump and ReaderNative, 3.8.0 source; recorded):
``purge yes`` deletes every particle first (it cannot go with replace or trim yes); ``replace yes``
(the default) overwrites the read fields of each particle whose id the snapshot holds: its radius
and nothing else when radius is read, its mass only when mass is read; its image flags are the ix,
iy, iz read or kept, and 0 in all three when the coordinates read are unwrapped or none are read;
``trim yes`` deletes the particles the snapshot does not hold; ``add yes`` adds the snapshot's
particles whose ids the system does not have, of the snapshot's type, at the coordinates read (0
where not read), with new ids from the largest id on, in the file's order, everything not read at
create_atoms's defaults (diameter 1, density 1: a radius read does not change that mass); ``box
yes`` (the default) takes the snapshot's box bounds (z only in 3-d). Then every particle is wrapped
into the box along its periodic axes (image flags counting), the shrink-wrapped faces fit the
particles again, and what lies outside a fixed face is for the next run to decide. The radius field
is required in the LIGGGHTS dialect (LIGGGHTS's rule: its granular particles need radii); a z field
in a 2-d simulation is refused; a snapshot whose boundary letters differ from the box's draws a
warning.

Where pdps differs, openly: LIGGGHTS 3.8.0 refuses every ``label`` ("Illegal read_dump command",
measured; its check compares with labels not yet set), which its manual allows and pdps reads as
the manual says. ``format xyz`` is refused at the line: LIGGGHTS requires the radius field, which an
XYZ file does not hold (its reader leaves the radii undefined). LAMMPS's read_dump page (nfile, fx
fy fz and the like) is not what this reads. A triclinic snapshot is refused, as pdps's box is
orthogonal (LIGGGHTS: "Read_dump triclinic status does not match simulation"). Under MPI, added
particles get their ids in the file's order (serial LIGGGHTS's; its ranks take turns).

Example::

    read_dump dump.bed 5000 x y z vx vy vz radius box no trim yes
"""

import gzip
import os
import re
from typing import Literal

import numpy as np

from ..errors import ScriptError
from ..run.shrink_wrap import set_initial_box, shrink_wrap
from ..state import limits
from ..state.box import remap
from ..styles import StyleArgs, keyword, param, parse_args
from . import command
from .control import reset_timestep

USAGE = ("read_dump FILE NSTEP FIELD... [box|replace|purge|trim|add|scaled|wrapped yes|no] [label FIELD COLUMN] "
         "[format native]")
FIELDS = ("x", "y", "z", "vx", "vy", "vz", "q", "radius", "ix", "iy", "iz", "omegax", "omegay", "omegaz", "mass")
YesNo = Literal["yes", "no"]
# the property each field sets, and its column there
TARGET = {"vx": ("v", 0), "vy": ("v", 1), "vz": ("v", 2), "q": ("q", None), "radius": ("radius", None),
          "omegax": ("omega", 0), "omegay": ("omega", 1), "omegaz": ("omega", 2), "mass": ("rmass", None)}


class Args(StyleArgs):
    file: str = param()
    nstep: int = param(ge=0, le=limits.MAX_STEP, unit="1")
    fields: list[Literal[FIELDS]] = param(default_factory=list)
    box: YesNo = keyword("yes")
    replace: YesNo = keyword("yes")
    purge: YesNo = keyword("no")
    trim: YesNo = keyword("no")
    add: YesNo = keyword("no")
    label: list[tuple[str, str]] = keyword(default_factory=list)
    scaled: YesNo = keyword("no")
    wrapped: YesNo = keyword("yes")
    format: Literal["native", "xyz"] = keyword("native")


@command("read_dump")
def read_dump(sim, args):
    sim.require_box("read_dump")
    if "format" in args and args.index("format") + 2 < len(args):
        raise ScriptError(f"format must be the last keyword (got {' '.join(args[args.index('format') + 2:])} after "
                          f"it); usage: {USAGE}")
    args = parse_args(Args, args, usage=USAGE)
    fields = list(args.fields)
    _check_fields(sim, args, fields)
    labels = _labels(args, fields)
    files = _files(sim, args.file)
    sim.output.message("Scanning dump file ...")
    snapshot = _find(files, args.nstep, args.file)
    if snapshot is None:
        raise ScriptError(f"{args.file} holds no snapshot of step {args.nstep}")
    where, lines, start = snapshot
    header = _header(lines, start, where)
    if header.triclinic:
        raise ScriptError(f"{where}: the snapshot of step {args.nstep} has a triclinic box, pdps's is orthogonal "
                          "(LIGGGHTS: Read_dump triclinic status does not match simulation)")
    if header.boundary and header.boundary != _boundary_letters(sim):
        sim.warn(f"read_dump {args.file}: the snapshot's boundaries ({' '.join(header.boundary)}) differ from the "
                 f"box's ({' '.join(_boundary_letters(sim))}); the box's are kept")
    columns, scaled, wrapped = _columns(header.labels, labels, args, where)
    values = _values(lines, header, columns, where)
    reset_timestep(sim, [str(args.nstep)])
    sim.output.message("Reading snapshot from dump file ...")
    counts = _apply(sim, args, values, header, scaled, wrapped, where)
    box = sim.box
    sim.output.message("  orthogonal box = ({}) to ({})\n".format(" ".join(f"{v:.8g}" for v in box.lo),
                                                                  " ".join(f"{v:.8g}" for v in box.hi))
                       + "\n".join(f"  {n} atoms {what}" for what, n in counts))


def _check_fields(sim, args, fields):
    if not fields:
        raise ScriptError(f"no field to read; usage: {USAGE}")
    if "radius" not in fields and sim.dialect.name == "liggghts":
        raise ScriptError("the radius field is required to be read (LIGGGHTS's rule)")
    if args.format == "xyz":
        raise ScriptError("format xyz: LIGGGHTS requires the radius field, which an XYZ file does not "
                          "hold (its reader leaves the radii undefined); write the snapshot with dump custom")
    duplicate = next((f for f in fields if fields.count(f) > 1), None)
    if duplicate:
        raise ScriptError(f"field {duplicate} given twice")
    if sim.dimension == 2 and {"z", "vz", "iz"} & set(fields):
        raise ScriptError("a 2-d simulation reads no z, vz or iz field")
    p = sim.particles
    for field in fields:
        target = TARGET.get(field, (None,))[0]
        if target is not None and not p.has(target):
            raise ScriptError(f"field {field}: the particles have no {target} (atom_style)")
    if args.purge == "yes" and (args.replace == "yes" or args.trim == "yes"):
        raise ScriptError("purge yes cannot go with replace yes or trim yes (LIGGGHTS's rule; "
                          "replace is yes by default)")


def _labels(args, fields):
    """{field: the column label given with label}, checked against the fields read and id, type."""
    labels = {}
    for field, column in args.label:
        if field not in (*fields, "id", "type"):
            raise ScriptError(f"label {field}: not a field read (fields: {' '.join(fields)}, id, type)")
        labels[field] = column
    return labels


def _files(sim, pattern):
    """The files to search, LIGGGHTS's way: one, or those matching the one ``*``, by its number."""
    path = sim.resolve(pattern)
    if "*" not in os.path.basename(path):
        if not os.path.isfile(path):
            raise ScriptError(f"cannot open dump file {pattern}")
        return [(path, pattern)]
    folder, name = os.path.split(path)
    shown_folder = os.path.dirname(pattern)
    head, _, tail = name.partition("*")
    if "*" in tail:
        raise ScriptError(f"dump file pattern {pattern}: one * only")
    found = []
    try:
        entries = sorted(os.listdir(folder or "."))
    except OSError as exc:
        raise ScriptError(f"cannot search {os.path.dirname(pattern) or '.'} for dump files {pattern}: "
                          f"{exc.strerror}") from None
    for entry in entries:
        if entry.startswith(head) and entry.endswith(tail) and len(entry) >= len(head) + len(tail):
            middle = entry[len(head):len(entry) - len(tail)]
            number = re.match(r"[+-]?\d+", middle)
            found.append((int(number.group()) if number else 0, os.path.join(folder, entry),
                          os.path.join(shown_folder, entry)))
    if not found:
        raise ScriptError(f"no dump file matches {pattern}")
    return [(path, shown) for _, path, shown in sorted(found, key=lambda item: item[0])]


def _read_lines(path, shown):
    try:
        opener = gzip.open if path.endswith(".gz") else open
        with opener(path, "rt", errors="replace") as handle:
            return handle.read().splitlines()
    except (OSError, EOFError) as exc:
        raise ScriptError(f"cannot read dump file {shown}: {exc}") from None


def _find(files, nstep, name):
    """(file, its lines, index of the snapshot's TIMESTEP line) of the first snapshot at step >=
    nstep in the files in turn, when that step is nstep; None otherwise (LIGGGHTS's seek)."""
    for full, path in files:
        lines = _read_lines(full, path)
        i = 0
        while i < len(lines):
            if not lines[i].startswith("ITEM: TIMESTEP"):
                raise ScriptError(f"{path}:{i + 1}: dump file is incorrectly formatted (expected ITEM: TIMESTEP, "
                                  f"got {lines[i][:40]!r})")
            step = _integer(lines, i + 1, path, "timestep")
            if step >= nstep:
                return (path, lines, i) if step == nstep else None
            natoms = _integer(lines, i + 3, path, "number of atoms")
            i += 9 + natoms
    return None


def _integer(lines, i, path, what):
    if i >= len(lines):
        raise ScriptError(f"{path}: unexpected end of dump file (expected the {what})")
    try:
        value = int(lines[i].split()[0])
    except (ValueError, IndexError):
        raise ScriptError(f"{path}:{i + 1}: the {what} must be an integer (got {lines[i][:40]!r})") from None
    if value < 0:
        raise ScriptError(f"{path}:{i + 1}: the {what} must be >= 0 (got {value})")
    return value


class _Header:
    def __init__(self, natoms, lo, hi, triclinic, boundary, labels, first):
        self.natoms, self.lo, self.hi, self.triclinic = natoms, lo, hi, triclinic
        self.boundary, self.labels, self.first = boundary, labels, first


def _header(lines, start, path):
    natoms = _integer(lines, start + 3, path, "number of atoms")
    if start + 8 >= len(lines) or not lines[start + 4].startswith("ITEM: BOX BOUNDS") \
            or not lines[start + 8].startswith("ITEM: ATOMS"):
        raise ScriptError(f"{path}:{start + 5}: dump file is incorrectly formatted (expected ITEM: BOX BOUNDS, "
                          "three lines of bounds, ITEM: ATOMS)")
    words = lines[start + 4].split()[3:]
    triclinic = words[:3] == ["xy", "xz", "yz"]
    boundary = tuple(words[3:6] if triclinic else words[:3])
    lo, hi = np.zeros(3), np.zeros(3)
    for d in range(3):
        row = start + 5 + d
        try:
            lo[d], hi[d] = (float(v) for v in lines[row].split()[:2])
        except ValueError:
            raise ScriptError(f"{path}:{row + 1}: box bounds must be two numbers (got {lines[row][:40]!r})") from None
        if not (np.isfinite(lo[d]) and np.isfinite(hi[d]) and lo[d] < hi[d]):
            raise ScriptError(f"{path}:{row + 1}: box bounds must be finite with lo < hi (got {lines[row][:40]!r})")
    return _Header(natoms, lo, hi, triclinic, boundary if len(boundary) == 3 else (), lines[start + 8].split()[2:],
                   start + 9)


def _boundary_letters(sim):
    return tuple(("pp" if word == "p" else word * 2) if len(word) == 1 else word
                 for word in sim.system.periodicity)


# the column labels of a coordinate, in the order LIGGGHTS tries them, with (scaled, wrapped)
COORDINATE_LABELS = (("", False, True), ("s", True, True), ("u", False, False), ("su", True, False))


def _columns(file_labels, labels, args, path):
    """{field or id/type: column index}, and whether the coordinates read are scaled and wrapped."""
    columns, styles = {}, {}
    for field in ("id", "type", *args.fields):
        if field in labels:
            found = _index(file_labels, labels[field])
            if field in "xyz":
                styles[field] = (args.scaled == "yes", args.wrapped == "yes")
        elif field in ("x", "y", "z"):
            found = _index(file_labels, field)
            styles[field] = (False, True)
            if found is None:
                tried = [(file_labels.index(field + suffix), (s, w)) for suffix, s, w in COORDINATE_LABELS[1:]
                         if field + suffix in file_labels]
                if tried:
                    found, styles[field] = min(tried, key=lambda item: item[0])
        else:
            found = _index(file_labels, field)
        if found is None:
            raise ScriptError(f"{path}: field {field} not found in the dump file's columns "
                              f"({' '.join(file_labels)})")
        columns[field] = found
    if len(set(styles.values())) > 1:
        raise ScriptError(f"{path}: the x, y, z columns read do not have one scaling and wrapping (LIGGGHTS's rule)")
    scaled, wrapped = next(iter(styles.values()), (False, False))
    return columns, scaled, wrapped


def _index(file_labels, label):
    return file_labels.index(label) if label in file_labels else None


def _values(lines, header, columns, path):
    """{field: one value per snapshot particle} (floats; ids, types and image flags checked integers)."""
    rows = lines[header.first:header.first + header.natoms]
    if len(rows) < header.natoms:
        raise ScriptError(f"{path}: unexpected end of dump file ({len(rows)} of {header.natoms} atom lines)")
    width = max(columns.values()) + 1
    table = np.empty((header.natoms, len(columns)))
    order = list(columns)
    for k, row in enumerate(rows):
        words = row.split()
        if len(words) < width:
            raise ScriptError(f"{path}:{header.first + k + 1}: {len(words)} columns, expected {len(header.labels)}")
        try:
            table[k] = [float(words[columns[field]]) for field in order]
        except ValueError:
            raise ScriptError(f"{path}:{header.first + k + 1}: not a number in {row[:60]!r}") from None
        if not np.isfinite(table[k]).all():
            raise ScriptError(f"{path}:{header.first + k + 1}: a value is not finite in {row[:60]!r}")
    values = {field: table[:, k] for k, field in enumerate(order)}
    ranges = {"id": (1, limits.MAX_TAG), "type": (1, limits.MAX_TAG)}
    for field in ("id", "type", "ix", "iy", "iz"):
        if field in values:
            v = values[field]
            low, high = ranges.get(field, (-limits.MAX_IMAGE, limits.MAX_IMAGE))
            bad = np.flatnonzero((v != np.round(v)) | (v < low) | (v > high))
            if len(bad):
                raise ScriptError(f"{path}:{header.first + bad[0] + 1}: {field} must be an integer in "
                                  f"{low}..{high} (got {v[bad[0]]:g})")
            values[field] = v.astype(np.int64)
    if "radius" in values and (values["radius"] <= 0).any():
        k = int(np.flatnonzero(values["radius"] <= 0)[0])
        raise ScriptError(f"{path}:{header.first + k + 1}: radius must be > 0 (got {values['radius'][k]:g})")
    if "mass" in values and (values["mass"] <= 0).any():
        k = int(np.flatnonzero(values["mass"] <= 0)[0])
        raise ScriptError(f"{path}:{header.first + k + 1}: mass must be > 0 (got {values['mass'][k]:g})")
    return values


def _coordinates(values, header, scaled, rows):
    """The snapshot's coordinates of ``rows`` (n x 3; None where not read), unscaled by its box."""
    out = {}
    for d, field in enumerate("xyz"):
        if field in values:
            c = values[field][rows]
            out[d] = c * (header.hi[d] - header.lo[d]) + header.lo[d] if scaled else c
    return out


def _apply(sim, args, values, header, scaled, wrapped, path):
    p = sim.particles
    p.clear_ghosts()
    before = int(sim.comm.sum(p.nlocal))
    purged = 0
    if args.purge == "yes":
        purged = before
        p.remove(np.ones(p.nlocal, dtype=np.bool_))
    tags = values["id"]
    owned_tag = p.tag[:p.nlocal]
    order = np.argsort(owned_tag, kind="stable")
    held = np.zeros(len(tags), dtype=bool)
    local = np.zeros(0, dtype=np.int64)
    if len(order):
        slot = np.minimum(np.searchsorted(owned_tag[order], tags), len(order) - 1)
        held = owned_tag[order][slot] == tags
        local = order[slot[held]]
    rows_in_file = np.flatnonzero(held)
    replaced = 0
    if args.replace == "yes" and len(local):
        replaced = len(local)
        for d, c in _coordinates(values, header, scaled, rows_in_file).items():
            p.x[local, d] = c
        for field, (target, column) in TARGET.items():
            if field in values:
                if column is None:
                    p.arrays[target][local] = values[field][rows_in_file]
                else:
                    p.arrays[target][local, column] = values[field][rows_in_file]
        for d, field in enumerate(("ix", "iy", "iz")):
            if field in values:
                p.image[local, d] = values[field][rows_in_file]
        if not wrapped:
            p.image[local] = 0
    in_dump = np.zeros(p.nlocal, dtype=np.bool_)
    in_dump[local] = True
    everywhere = sim.comm.allgather_rows(held.astype(np.int64).reshape(-1, 1)).reshape(sim.comm.nprocs, -1) \
        if sim.comm.nprocs > 1 else held.reshape(1, -1)
    new_rows = np.flatnonzero(~everywhere.any(axis=0))
    added = 0
    if args.add == "yes" and len(new_rows):
        largest = int(sim.comm.max(int(p.tag[:p.nlocal].max()) if p.nlocal else 0))
        added = _add(sim, values, header, scaled, new_rows, largest, path)
    trimmed = 0
    if args.trim == "yes":
        n_old = len(in_dump)
        gone = np.zeros(p.nlocal, dtype=np.bool_)
        gone[:n_old] = ~in_dump
        trimmed = int(sim.comm.sum(int(gone.sum())))
        p.remove(gone)
    replaced = int(sim.comm.sum(replaced))
    if args.box == "yes":
        lo, hi = sim.box.lo.copy(), sim.box.hi.copy()
        axes = 3 if sim.dimension == 3 else 2
        lo[:axes], hi[:axes] = header.lo[:axes], header.hi[:axes]
        limits.check_box(lo, hi, f"{path}: the snapshot's")
        lo, hi, sim.system.shrink_faces = set_initial_box(sim.system.periodicity, lo, hi)
        sim.box.set_bounds(lo, hi)
    _wrap(sim)
    shrink_wrap(sim)
    sim.comm.migrate(p, sim.box)
    sim.groups.update(sim)
    sim.run_state.box_changed = True
    after = int(sim.comm.sum(p.nlocal))
    return [("before read", before), ("in snapshot", header.natoms), ("purged", purged), ("replaced", replaced),
            ("trimmed", trimmed), ("added", int(sim.comm.sum(added))), ("after read", after)]


def _add(sim, values, header, scaled, rows, largest, path):
    """The snapshot's particles no rank holds, on rank 0, as create_atoms makes them, then the fields
    read; every rank checks them (each read the whole file)."""
    p = sim.particles
    types = values["type"][rows]
    ntypes = sim.system.ntypes
    bad = np.flatnonzero((types < 1) | (types > ntypes))
    if len(bad):
        raise ScriptError(f"{path}: add: atom {values['id'][rows[bad[0]]]} has type {types[bad[0]]}, "
                          f"out of range 1..{ntypes}")
    if largest + len(rows) > limits.MAX_TAG:
        raise ScriptError(f"add: ids beyond {limits.MAX_TAG}")
    p.next_tag = max(p.next_tag, largest + len(rows) + 1)
    if sim.comm.rank != 0:
        return 0
    from .particles import _sphere_values
    x = np.zeros((len(rows), 3))
    for d, c in _coordinates(values, header, scaled, rows).items():
        x[:, d] = c
    p.check_room(len(rows))
    start = p.nlocal
    p.add(x, types, tags=np.arange(largest + 1, largest + 1 + len(rows)), **_sphere_values(sim, {}))
    new = slice(start, p.nlocal)
    for field, (target, column) in TARGET.items():
        if field in values:
            if column is None:
                p.arrays[target][new] = values[field][rows]
            else:
                p.arrays[target][new, column] = values[field][rows]
    for d, field in enumerate(("ix", "iy", "iz")):
        if field in values:
            p.image[new, d] = values[field][rows]
    return len(rows)


def _wrap(sim):
    """Every owned particle into the box along its periodic axes, image flags counting (LIGGGHTS's
    Domain::remap after read_dump)."""
    p, box = sim.particles, sim.box
    n = p.nlocal
    x, shifts = p.x[:n].copy(), np.zeros((n, 3), dtype=np.int64)
    remap(x, shifts, box.lo, box.hi, np.asarray(box.periodic, dtype=np.bool_))
    image = p.image[:n] + shifts
    if sim.comm.sum(int(np.abs(image).max(initial=0) > limits.MAX_IMAGE)):
        raise ScriptError(f"the box leaves particles more than {limits.MAX_IMAGE} box lengths from the box")
    p.x[:n], p.image[:n] = x, image
