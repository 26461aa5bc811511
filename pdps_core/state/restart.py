"""Restart files: the whole state of a simulation, so that a run read back from one goes on exactly.

Format (version 1): a zip archive, members stored uncompressed:

    header.json      {"format": "pdps-restart", "version": 1, ...}: settings, styles, counters
    NAME.npy         numpy arrays: particles/x, particles/v, ..., mass, box/lo, neighbor/xhold, ...

Why this and not pickle: ``.npy`` keeps every bit, the dtype and the shape of each array; JSON keeps
the settings readable (``unzip -p FILE header.json``) and free of Python class paths, so a file stays
readable when modules move; nothing is unpickled, so reading a file runs no code from it; zip keeps
a CRC-32 per member and its directory at the end, so a truncated or damaged file is detected, never
half-read. ``version`` names the layout; a reader refuses versions it does not know. The file does
not depend on the machine (LAMMPS's binary restarts depend on the machine and the LAMMPS version).

What is saved: units, dimension, boundary, box, ntypes and masses, particle style, lattice; every
per-atom array of the owned particles in order, with its registry entry (width, dtype, default) and
the next free tag, so style-requested arrays (contact histories, ``vest`` of fix mvv/dpd) come back
as they were; groups (bits and definitions); regions, the pair style (arguments, coefficients, mix
rule), fixes, computes and analyze styles, each as style, id, group and parsed ``args``, plus what
its ``state()`` returns; the neighbor settings (skin, every, delay, check, sort interval, last sort)
and rebuild schedule (``ago``, ``xhold``, what the lists were built with); timestep, step, time, and
the last energy and virial. Not saved, as in LAMMPS: thermo settings, dumps, variables, the restart
schedule itself. Random numbers are keyed by (seed, step, tags): there is no generator state.

Style state protocol. The core always saves ``args`` and re-creates a style from them. A style that
keeps more than its arguments in the instance defines ``state()`` returning a dict and
``restore(state)``, called right after the style is re-created. Values: JSON values (numbers,
strings, booleans, None, lists, dicts with string keys) and numpy arrays, at any depth; tuples come
back as lists. Per-atom state belongs in ``particles.request`` arrays, which are saved anyway. A
fix, compute or analyze style given again after ``read_restart`` with the same ID and style
(LAMMPS scripts do) gets the saved state too, when it is made; states no style took up by the
next run (or restart written) are dropped.

What reading brings back depends on the script's dialect (``Dialect.restart_styles``): in PDPS, all
of the above. In LAMMPS and LIGGGHTS, what their manuals list: the particles, the box, groups,
masses and the pair style with its coefficients, the step and the timestep; regions, fixes, computes
and analyze styles are not made again (the script gives them, and regions it defined before
``read_restart`` stay), and a saved style's state waits for a style given with its ID and style.

Writing: to ``FILE.tmp`` in the same folder, flushed and fsynced, then renamed over ``FILE``
(``os.replace`` is atomic), then the folder fsynced: at every moment ``FILE`` is either the previous
complete restart or the new one.
"""

import glob
import io
import json
import math
import os
import re
import tokenize
import zipfile
import zlib

import numpy as np
from pydantic import ValidationError

from .. import __version__
from ..errors import ScriptError
from ..neighbor.neighbor import HISTORY_MASK, Neighbor
from ..run.shrink_wrap import BOUNDARY_STYLES, shrink_faces
from ..styles import StyleArgs, registry
from . import limits
from .box import Box
from .groups import Groups
from .particles import CORE, Particles, Property, style_properties, substyles
from .units import UNITS

FORMAT = "pdps-restart"
VERSION = 1
STYLE_TABLES = (("fix", "fixes"), ("compute", "computes"), ("analyze", "analyzes"))


# ---- writing --------------------------------------------------------------------------------------
def write_restart(sim, path):
    """Rank 0 writes what every rank captured; a failure to write stops every rank alike."""
    header, arrays = capture(sim)
    message = None
    if sim.comm.is_root:
        try:
            write_file(path, header, arrays)
        except ScriptError as exc:
            message = exc.message
    if sim.comm.nprocs > 1:
        sim.comm.agree(message)
    elif message:
        raise ScriptError(message)


def capture(sim):
    """(header dict, {name: array}) of everything a run needs to go on (module docstring)."""
    if sim.system.topology.has_bonds(sim.particles):
        # the bonds would travel as per-atom arrays, their types, style and special_bonds not
        raise ScriptError("restart files do not keep bonds yet (their types, bond style and special_bonds): "
                          "write_data (it writes the bonds), then read_data and the bond commands again")
    if sim.styles.restored_states:
        drop_unclaimed_states(sim)     # a state no style took up is not written again
    p, neighbor = sim.particles, sim.neighbor
    parallel = sim.comm.nprocs > 1
    n = int(sim.comm.sum(p.nlocal))
    arrays = {"box/lo": sim.box.lo, "box/hi": sim.box.hi, "mass": sim.mass}
    properties = []
    for name, prop in p.properties.items():
        # in a parallel run rank 0 holds every rank's particles, in rank order
        values = p.arrays[name][: p.nlocal]
        arrays[f"particles/{name}"] = sim.comm.gather_rows(values) if parallel else values
        properties.append({"name": name, "width": prop.width, "dtype": np.dtype(prop.dtype).name,
                           "default": _plain(prop.default)})
    if sim.lattice is not None:
        arrays["lattice/spacing"], arrays["lattice/basis"] = sim.lattice.spacing, sim.lattice.basis
        arrays["lattice/cell"], arrays["lattice/offset"] = sim.lattice.cell, sim.lattice.offset
    states = _StateArrays(arrays)
    header = {
        "format": FORMAT, "version": VERSION, "written_by": f"pdps {__version__}",
        "units": sim.units.name, "dimension": sim.dimension,
        "periodicity": list(sim.system.periodicity), "periodic": list(sim.box.periodic),
        "ntypes": sim.ntypes, "particle_style": sim.particle_style,
        "lattice": sim.lattice is not None,
        "lattice_style": sim.lattice.style if sim.lattice is not None else None,
        "particles": {"nlocal": n, "next_tag": int(p.next_tag), "properties": properties},
        "groups": {"bits": dict(sim.groups.bits),
                   "definitions": {name: _plain(d) for name, d in sim.groups.definitions.items()}},
        "regions": [{"id": r.id, "style": r.name, "args": _dump_args(f"region {r.id}", r.args),
                     "state": states.encode(f"region {r.id}", r)} for r in sim.system.regions.values()],
        "pair": _pair_record(sim.pair, states),
        "neighbor": _neighbor_record(neighbor, p, arrays, resumable=not parallel),
        "step": sim.step, "time": sim.time, "dt": sim.dt, "ghost_velocity": sim.system.ghost_velocity,
        "random_epoch": sim.run_state.random_epoch, "highest_step": max(sim.run_state.highest_step, sim.step),
        "pe": float(sim.pe), "virial": [float(v) for v in sim.virial],
        # per-rank partial sums: a parallel restart has them recomputed by its first run
        "energy_step": None if parallel else sim.run_state.energy_step,
        "virial_step": None if parallel else sim.run_state.virial_step,
    }
    for kind, table in STYLE_TABLES:
        header[table] = [{"id": s.id, "group": s.group, "style": s.name, **_spelling(kind, s),
                          "args": _dump_args(f"{kind} {s.id}", s.args),
                          "state": states.encode(f"{kind} {s.id}", s)}
                         for s in getattr(sim, table).values()]
    return header, arrays


def _pair_record(pair, states):
    """The pair style's arguments, coefficients, mixing and state; a style made of others (hybrid:
    ``substyles``, name -> pair style) keeps its coefficients in them, each written as a pair style."""
    if pair is None:
        return None
    substyles = getattr(pair, "substyles", None)
    coeffs = []
    for (i, j), coeff in sorted(pair.coeffs.items()) if substyles is None else ():
        model = _coefficient_class_name(type(pair), type(coeff))
        if model is None:
            raise ScriptError(f"pair {pair.name}: coefficients of types {i} {j} are a {type(coeff).__name__}, "
                              "which is not a class of the pair style, so a restart cannot name it")
        coeffs.append([i, j, model, _dump_args(f"pair_coeff {i} {j}", coeff)])
    record = {"style": pair.name, "args": _dump_args(f"pair {pair.name}", pair.args), "coeffs": coeffs,
              "mix_rule": pair.mix_rule, "shift": pair.shift, "state": states.encode(f"pair {pair.name}", pair)}
    if substyles is not None:
        record["substyles"] = {name: _pair_record(sub, states) for name, sub in substyles.items()}
    return record


def _coefficient_class_name(style, model):
    """The name under which a pair style holds its coefficients' class, for the reader to find it
    again: the class's own name (``SigmaCoeff``), or the attribute naming it (``Coeff``, which is
    plain ``StyleArgs`` for styles with no coefficients, as the granular ones); None if neither."""
    if getattr(style, model.__name__, None) is model:
        return model.__name__
    return next((name for name in sorted(dir(style)) if getattr(style, name, None) is model), None)


def _neighbor_record(neighbor, particles, arrays, resumable=True):
    record = {"skin": neighbor.requested_skin, "style": neighbor.style, "every": neighbor.every,
              "delay": neighbor.delay, "check": neighbor.check, "sort_every": neighbor.sort_every,
              "last_sort": neighbor.last_sort, "ago": neighbor.ago, "builds": neighbor.builds,
              "dangerous": neighbor.dangerous, "one": neighbor.one, "history": neighbor.history,
              "built_with": None,
              "exclude": {"types": [[[int(t) for t in a], [int(t) for t in b]]
                                    for a, b in neighbor.excluded_type_pairs],
                          "groups": [list(pair) for pair in neighbor.excluded_group_pairs],
                          "molecules": [list(m) for m in neighbor.excluded_molecules]}}
    # the schedule and the lists' recipe go along only while they are current for the particles
    if resumable and neighbor.is_current(particles) and neighbor.built_with is not None:
        skin, lists, lo, hi, periodic = neighbor.built_with
        arrays["neighbor/xhold"] = neighbor.xhold
        arrays["neighbor/lo"], arrays["neighbor/hi"] = lo, hi
        for k, (_, cutoff) in enumerate(lists):
            arrays[f"neighbor/cutoff{k}"] = cutoff
        record["built_with"] = {"skin": skin, "kinds": [kind for kind, _ in lists],
                                "periodic": list(periodic)}
    return record


def _dump_args(what, model):
    """A style's parsed arguments as JSON, checked to read back equal to themselves."""
    data = model.model_dump(mode="json")
    try:
        again = type(model).model_validate(json.loads(json.dumps(data)))
    except ValidationError:
        again = None
    if again != model:
        raise ScriptError(f"{what}: its arguments do not read back equal from JSON, so a restart "
                          "cannot hold them (a bug of the style's Args model)")
    return data


class _StateArrays:
    """Encodes what styles' ``state()`` return: arrays go to the archive, the rest stays JSON."""

    def __init__(self, arrays):
        self.arrays = arrays
        self.count = 0

    def encode(self, what, style):
        method = getattr(style, "state", None)
        if not callable(method):
            return None
        try:
            return self._value(method())
        except TypeError as exc:
            raise ScriptError(f"{what}: state() holds {exc}, which a restart cannot keep "
                              "(use numbers, strings, lists, dicts and numpy arrays)") from None

    def _value(self, value):
        if isinstance(value, np.ndarray):
            key = f"state/{self.count}"
            self.count += 1
            self.arrays[key] = value
            return {"__array__": key}
        if isinstance(value, np.generic):
            return value.item()
        if isinstance(value, dict):
            if not all(isinstance(k, str) for k in value) or "__array__" in value:
                raise TypeError("a dict whose keys are not all strings (or a key __array__)")
            return {k: self._value(v) for k, v in value.items()}
        if isinstance(value, (list, tuple)):
            return [self._value(v) for v in value]
        if value is None or isinstance(value, (bool, int, float, str)):
            return value
        raise TypeError(f"a {type(value).__name__}")


def _plain(value):
    """Tuples to lists and numpy scalars to Python numbers, for JSON."""
    if isinstance(value, (list, tuple)):
        return [_plain(v) for v in value]
    if isinstance(value, np.generic):
        return value.item()
    return value


def write_file(path, header, arrays):
    """Write to PATH.tmp, flush and fsync it, rename it over PATH, fsync the folder."""
    temporary = f"{path}.tmp"
    try:
        with open(temporary, "wb") as handle:
            with zipfile.ZipFile(handle, "w", zipfile.ZIP_STORED) as archive:
                archive.writestr("header.json", json.dumps(header, indent=1))
                for name, array in arrays.items():
                    with archive.open(f"{name}.npy", "w", force_zip64=True) as member:
                        np.lib.format.write_array(member, np.ascontiguousarray(array),
                                                  allow_pickle=False)
            handle.flush()
            os.fsync(handle.fileno())
        os.replace(temporary, path)
    except OSError as exc:
        try:
            os.remove(temporary)
        except OSError:
            pass
        raise ScriptError(f"cannot write restart file {path}: {exc.strerror or exc}") from None
    _sync_folder(os.path.dirname(os.path.abspath(path)))


def _sync_folder(folder):
    """Make the rename itself durable (POSIX); folders cannot be opened for this everywhere."""
    try:
        descriptor = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(descriptor)
    except OSError:
        pass
    finally:
        os.close(descriptor)


class RestartOutput:
    """``restart N FILE [FILE2]``: a restart file every N steps of a run (not at a run's first
    step); with two files they take turns; a ``*`` in a name is replaced by the step, and one file
    named without a ``*`` gets ``.STEP`` after it, FILE.1000 (LAMMPS's, and LIGGGHTS's: measured)."""

    def __init__(self, every, files):
        self.every = every
        self.files = list(files)
        if len(self.files) == 1 and "*" not in self.files[0]:
            self.files[0] += ".*"
        self.turn = 0

    def write(self, sim, step):
        if step % self.every:
            return
        path = self.files[self.turn].replace("*", str(step))
        self.turn = (self.turn + 1) % len(self.files)
        sim.neighbor.mark_current(sim.particles)      # mid-run, the lists are current
        write_restart(sim, path)


# ---- reading --------------------------------------------------------------------------------------
def latest(pattern):
    """``restart.*``: the file whose ``*`` stands for the largest step (LAMMPS)."""
    head, _, tail = pattern.partition("*")
    steps = {}
    for name in glob.glob(glob.escape(head) + "*" + glob.escape(tail)):
        middle = name[len(head):len(name) - len(tail)]
        if re.fullmatch(r"\d+", middle):
            steps[int(middle)] = name
    if not steps:
        raise ScriptError(f"no restart file matches {pattern}")
    return steps[max(steps)]


def read_file(path, shown=None):
    """(header, arrays) of a restart file; any problem is one line naming the file (as ``shown``)."""
    shown = path if shown is None else shown
    damaged = f"restart file {shown} is truncated, damaged or not a pdps restart file"
    try:
        archive = zipfile.ZipFile(path)
    except FileNotFoundError:
        raise ScriptError(f"restart file {shown} does not exist") from None
    except (zipfile.BadZipFile, NotImplementedError, ValueError, EOFError):
        raise ScriptError(damaged) from None
    except OSError as exc:
        raise ScriptError(f"cannot read restart file {shown}: {exc.strerror or exc}") from None
    with archive:
        try:
            header = json.loads(archive.read("header.json"))
            if not isinstance(header, dict) or header.get("format") != FORMAT:
                raise ScriptError(f"{shown} is not a pdps restart file")
            version = header.get("version")
            if version != VERSION:
                newer = " (written by a newer pdps)" if isinstance(version, int) and version > VERSION else ""
                raise ScriptError(f"restart file {shown} has format version {version}{newer}; "
                                  f"pdps {__version__} reads version {VERSION}")
            arrays = {name[:-4]: _native(name[:-4], np.lib.format.read_array(
                          io.BytesIO(archive.read(name)), allow_pickle=False), shown)
                      for name in archive.namelist() if name.endswith(".npy")}
        except ScriptError:
            raise
        except (KeyError, ValueError, EOFError, OSError, zlib.error, zipfile.BadZipFile, RecursionError,
                SyntaxError, tokenize.TokenError, NotImplementedError):
            raise ScriptError(damaged) from None
    return header, arrays


# what write_restart writes; anything else (complex, strings, float16, ...) reaches no kernel
WRITTEN_DTYPES = {np.dtype(t) for t in (np.float64, np.float32, np.int64, np.int32, np.int16, np.int8,
                                        np.uint64, np.uint32, np.uint16, np.uint8, np.bool_)}


def _native(name, values, shown):
    """An array read from a restart file in this machine's byte order, of a dtype pdps writes."""
    native = values.dtype.newbyteorder("=")
    if native not in WRITTEN_DTYPES:
        raise ScriptError(f"restart file {shown}: array {name} holds {values.dtype} values, "
                          "which pdps does not write")
    return values.astype(native, copy=False)


def read_restart(sim, path, shown=None):
    """Replace the (empty) simulation by the one saved in ``path``; on any error it stays as it was."""
    shown = path if shown is None else shown
    header, arrays = read_file(path, shown)
    before = _parts(sim)
    try:
        restore(sim, header, arrays)
        sim.comm.distribute(sim.particles, sim.box)     # every rank read all: each keeps its own
    except ScriptError as exc:
        _put_back(sim, before)
        raise ScriptError(f"restart file {shown}: {exc.message}") from None
    except (KeyError, TypeError, ValueError, IndexError, AttributeError, OverflowError) as exc:
        _put_back(sim, before)
        raise ScriptError(f"restart file {shown} is damaged ({type(exc).__name__}: {exc})") from None


# what restore writes into: the parts of the simulation, and the neighbor settings it replaces
RESTORED_PARTS = ("system", "styles", "run_state")


def _parts(sim):
    """A copy of what ``restore`` writes: each part's slots as they are (every object restored into
    is new, so the values themselves need no copy), and the neighbor settings."""
    return {"neighbor": sim.neighbor,
            **{name: {slot: getattr(getattr(sim, name), slot) for slot in type(getattr(sim, name)).__slots__}
               for name in RESTORED_PARTS}}


def _put_back(sim, before):
    sim.neighbor = before["neighbor"]
    for name in RESTORED_PARTS:
        part = getattr(sim, name)
        for slot, value in before[name].items():
            setattr(part, slot, value)


def _field(record, name, kind, check=None, expected=""):
    """``record[name]`` of Python type ``kind`` (bool is not an int here) passing ``check``; else
    one line naming the field and the value."""
    value = record.get(name) if isinstance(record, dict) else None
    good = isinstance(value, kind) and not (kind is not bool and isinstance(value, bool))
    if good and isinstance(value, float):
        good = math.isfinite(value)
    if good and check is not None:
        good = bool(check(value))
    if not good:
        raise ScriptError(f"field {name} must be {expected or kind.__name__} (got {value!r:.60})")
    return value


def _array(arrays, name, shape, finite=True, kinds="fiu"):
    """``arrays[name]`` of ``shape`` and a dtype of ``kinds``; floats are float64, as written."""
    values = arrays.get(name)
    if values is None:
        raise ScriptError(f"array {name} is missing")
    if values.shape != shape:
        raise ScriptError(f"array {name} has shape {values.shape}, not {shape}")
    if values.dtype.kind not in kinds or (values.dtype.kind == "f" and values.dtype != np.float64):
        raise ScriptError(f"array {name} holds {values.dtype} values, not numbers of the saved kind")
    if finite and values.dtype.kind == "f" and not np.isfinite(values).all():
        raise ScriptError(f"array {name} holds non-finite values")
    return values


def _known_style(style):
    try:
        substyles(style)
    except ValueError:
        return False
    return True


def validate(header, arrays):
    """Every value restore() uses, checked before any is: a damaged or hand-edited file is one line
    naming the field, never a crash or a run on garbage."""
    number = (int, float)
    _field(header, "units", str, lambda u: u in UNITS, f"one of {', '.join(UNITS)}")
    dimension = _field(header, "dimension", int, lambda d: d in (2, 3), "2 or 3")
    _field(header, "periodicity", list, lambda p: len(p) == 3 and all(w in BOUNDARY_STYLES for w in p),
           "three of p, f, s, m (or two of f, s, m)")
    _field(header, "periodic", list, lambda p: len(p) == 3 and all(isinstance(w, bool) for w in p),
           "three booleans")
    ntypes = _field(header, "ntypes", int, lambda t: 1 <= t <= limits.MAX_TYPES, f"from 1 to {limits.MAX_TYPES}")
    _field(header, "particle_style", str, _known_style, "a particle style or hybrid S1 S2 ...")
    _field(header, "lattice", bool)
    _field(header, "step", int, lambda n: 0 <= n <= limits.MAX_STEP, f"from 0 to {limits.MAX_STEP}")
    _field(header, "time", number, None, "a finite number")
    _field(header, "dt", number, lambda dt: limits.MIN_SIZE <= dt <= limits.MAX_SIZE,
           f"from {limits.MIN_SIZE:g} to {limits.MAX_SIZE:g}")
    _field(header, "pe", number, None, "a finite number")
    _field(header, "virial", list, lambda v: len(v) == 6 and all(
        isinstance(c, number) and math.isfinite(c) for c in v), "six finite numbers")
    _field(header, "ghost_velocity", bool)
    for name in ("random_epoch", "highest_step"):
        if name in header:
            _field(header, name, int, lambda k: 0 <= k <= limits.MAX_STEP, "an integer >= 0")
    for name in ("energy_step", "virial_step"):
        value = header.get(name)
        if value is not None and not (isinstance(value, int) and not isinstance(value, bool)
                                      and 0 <= value <= limits.MAX_STEP):
            raise ScriptError(f"field {name} must be a step or null (got {value!r:.60})")
    particles = _field(header, "particles", dict)
    n = _field(particles, "nlocal", int, lambda k: 0 <= k <= limits.MAX_TAG, "a particle count")
    _field(particles, "next_tag", int, lambda t: 1 <= t <= limits.MAX_TAG + 1, "an id")
    _field(particles, "properties", list)
    neighbor = _field(header, "neighbor", dict)
    _field(neighbor, "skin", number, lambda s: 0 <= s <= limits.MAX_COORDINATE,
           f"a number from 0 to {limits.MAX_COORDINATE:g}")
    # counts of steps and builds: JSON integers have no bound, the arrays and kernels they meet do
    steps = f"from 0 to {limits.MAX_STEP}"
    _field(neighbor, "every", int, lambda k: 1 <= k <= limits.MAX_STEP, f"from 1 to {limits.MAX_STEP}")
    _field(neighbor, "check", bool)
    for name in ("delay", "sort_every", "ago", "builds", "dangerous"):
        _field(neighbor, name, int, lambda k: 0 <= k <= limits.MAX_STEP, steps)
    if "one" in neighbor:
        _field(neighbor, "one", int, lambda k: 1 <= k <= limits.MAX_NEIGHBORS_ONE,
               f"from 1 to {limits.MAX_NEIGHBORS_ONE}")
    if neighbor.get("last_sort") is not None:
        _field(neighbor, "last_sort", int, lambda k: 0 <= k <= limits.MAX_STEP, "a step or null")
    if "history" in neighbor:
        _field(neighbor, "history", int, lambda k: 0 <= k <= HISTORY_MASK, f"an integer from 0 to {HISTORY_MASK}")
    _field(neighbor, "style", str, lambda s: s in ("single", "multi", "bin", "nsq"), "a neighbor style")
    built = neighbor.get("built_with")
    if built is not None:
        _field(neighbor, "built_with", dict)
        _field(built, "skin", number, lambda s: 0 <= s <= limits.MAX_COORDINATE,
               f"a number from 0 to {limits.MAX_COORDINATE:g}")
        kinds = _field(built, "kinds", list, lambda k: all(isinstance(w, str) for w in k), "list names")
        _field(built, "periodic", list, lambda p: len(p) == 3 and all(isinstance(w, bool) for w in p),
               "three booleans")
        _array(arrays, "neighbor/xhold", (n, 3), kinds="f")
        _array(arrays, "neighbor/lo", (3,), kinds="f")
        _array(arrays, "neighbor/hi", (3,), kinds="f")
        for k in range(len(kinds)):
            _array(arrays, f"neighbor/cutoff{k}", (ntypes + 1, ntypes + 1), kinds="f")
    lo = _array(arrays, "box/lo", (3,), kinds="f")
    hi = _array(arrays, "box/hi", (3,), kinds="f")
    limits.check_box(lo, hi)
    # a skin is in effect from the run's first rebuild on (the saved lists' one until then): it must
    # fit the box as the neighbor command's would at a run's start
    for skin in (neighbor["skin"], (built or {}).get("skin", 0.0)):
        for d, axis in enumerate("xyz"[:dimension]):
            length = float(hi[d] - lo[d])
            if header["periodic"][d] and skin > limits.MAX_IMAGES * length:
                raise ScriptError(f"field skin {skin:g} spans {skin / length:.3g} periodic images of the box "
                                  f"(length {length:g} along {axis}; at most {limits.MAX_IMAGES})")
    if dimension == 2 and header["periodicity"][2] != "p":
        raise ScriptError("a 2-d box needs a periodic z boundary")
    if header["lattice"]:
        _array(arrays, "lattice/spacing", (3,), kinds="f")
        basis = arrays.get("lattice/basis")
        if basis is None or basis.ndim != 2 or basis.shape[1:] != (3,):
            raise ScriptError("array lattice/basis is missing or not n x 3")
        _array(arrays, "lattice/basis", basis.shape, kinds="f")
        for name, shape in (("lattice/cell", (3, 3)), ("lattice/offset", (3,))):
            if name in arrays:
                _array(arrays, name, shape, kinds="f")
    mass = _array(arrays, "mass", (ntypes + 1,), finite=False, kinds="f")
    set_mass = mass[1:][~np.isnan(mass[1:])]
    if not (np.isfinite(set_mass).all() and (set_mass > 0).all()):
        raise ScriptError("masses must be finite numbers > 0 (or unset)")
    for name, shape, kinds in (("tag", (n,), "iu"), ("type", (n,), "iu"), ("x", (n, 3), "f"),
                               ("v", (n, 3), "f"), ("image", (n, 3), "iu")):
        _array(arrays, f"particles/{name}", shape, kinds=kinds)
    for name, values in arrays.items():
        # every per-atom number within what squares hold, as the velocity and set commands allow
        if (name.startswith("particles/") and values.dtype.kind == "f"
                and not (np.abs(values) <= limits.MAX_COORDINATE).all()):
            raise ScriptError(f"array {name} holds values that are not finite or beyond "
                              f"+-{limits.MAX_COORDINATE:g}")
    groups = _field(header, "groups", dict)
    bits = _field(groups, "bits", dict)
    for name, bit in bits.items():
        if not (isinstance(bit, int) and not isinstance(bit, bool) and 0 <= bit < 32):
            raise ScriptError(f"group {name!r:.40} has bit {bit!r:.40}, not 0 to 31")
    _field(groups, "definitions", dict)
    for table in ("regions",) + tuple(t for _, t in STYLE_TABLES):
        records = _field(header, table, list)
        for record in records:
            for key in ("id", "style") + (("group",) if table != "regions" else ()):
                _field(record, key, str, None, "a name")
            if table != "regions" and record["group"] not in bits:
                raise ScriptError(f"{table} {record['id']!r:.40} uses group {record['group']!r:.40}, "
                                  "which the file does not define")
    has_rmass = any(isinstance(e, dict) and e.get("name") == "rmass" for e in particles["properties"])
    used = np.unique(arrays["particles/type"]) if n else np.zeros(0, dtype=int)
    unset = [int(t) for t in used if 1 <= t <= ntypes and np.isnan(mass[t])]
    if unset and not has_rmass:
        raise ScriptError(f"particles of type {unset[0]} have no mass (NaN in the file)")
    tags = arrays["particles/tag"]
    if n and not (tags.min() >= 1 and tags.max() <= limits.MAX_TAG):
        raise ScriptError(f"particle ids must be from 1 to {limits.MAX_TAG}")
    if len(np.unique(tags)) != n:
        raise ScriptError("particle ids must be unique (an id appears twice)")
    # the id the next particle made gets: at or below a particle's, create_atoms would reuse an id
    if n and particles["next_tag"] <= tags.max():
        raise ScriptError(f"field next_tag {particles['next_tag']} is not above the largest particle id "
                          f"{tags.max()} (new particles would reuse ids)")
    types = arrays["particles/type"]
    if n and not (types.min() >= 1 and types.max() <= ntypes):
        raise ScriptError(f"particle types must be from 1 to {ntypes} (got {types.min()} to {types.max()})")
    if np.abs(arrays["particles/x"]).max(initial=0.0) > limits.MAX_COORDINATE:
        raise ScriptError(f"positions must be within +-{limits.MAX_COORDINATE:g}")
    for name, low, high in (("rmass", limits.MIN_SIZE ** 3, limits.MAX_SIZE ** 3),
                            ("radius", limits.MIN_SIZE / 2, limits.MAX_SIZE / 2)):
        values = arrays.get(f"particles/{name}")
        if values is not None and n and not (np.isfinite(values).all() and (values >= low).all()
                                             and (values <= high).all()):
            raise ScriptError(f"per-atom {name} must be from {low:g} to {high:g}")


def restore(sim, header, arrays):
    # every object restored into is new, so that read_restart can undo by putting the parts' values back
    validate(header, arrays)
    sim.system.units = UNITS[header["units"]]
    sim.system.dimension = int(header["dimension"])
    sim.system.periodicity = tuple(header["periodicity"])
    sim.system.box = Box(arrays["box/lo"].copy(), arrays["box/hi"].copy(), header["periodic"], sim.dimension)
    # an m face never moves inside where the restart file has it (LAMMPS's set_initial_box)
    sim.system.shrink_faces = shrink_faces(sim.system.periodicity, sim.box.lo, sim.box.hi)
    sim.system.ntypes = int(header["ntypes"])
    sim.system.mass = arrays["mass"].copy()
    sim.system.particle_style = header["particle_style"]
    sim.system.lattice = _lattice(header, arrays)
    sim.system.particles = _particles(header["particles"], arrays)
    missing = [name for name in style_properties(sim.particle_style) if not sim.particles.has(name)]
    if missing:
        raise ValueError(f"particle_style {sim.particle_style} needs the per-atom arrays {', '.join(missing)}")
    groups = Groups()
    groups.bits = {name: int(bit) for name, bit in header["groups"]["bits"].items()}
    groups.definitions = {name: tuple(tuple(w) if isinstance(w, list) else w for w in definition)
                          for name, definition in header["groups"]["definitions"].items()}
    sim.system.groups = groups
    sim.styles.restored_states = {}
    whole = sim.dialect.restart_styles
    if whole:
        sim.system.regions = {}
    for record in header["regions"] if whole else ():
        cls = registry.lookup("region", record["style"])
        region = cls(sim, record["id"], _load_args(cls.Args, record["args"], f"region {record['id']}"))
        sim.system.regions[record["id"]] = region
        _restore_state(region, record["state"], arrays, f"region {record['id']}")
    groups.update(sim)          # a damaged group definition fails here, not at the next run
    sim.styles.pair = _pair(sim, header["pair"], arrays)
    sim.styles.pair_list = None
    for kind, table in STYLE_TABLES:
        styles = {}
        setattr(sim.styles, table, styles)
        for record in header[table]:
            what = f"{kind} {record['id']}"
            if not whole:
                # held for a style the script gives again with this ID and style (take_up_state)
                if record["state"] is not None:
                    sim.styles.restored_states[(kind, record["id"])] = (
                        record["style"], _decode(record["state"], arrays), None)
                continue
            cls = _spelled(registry.lookup(kind, record["style"]), record, what)
            style = cls(sim, record["id"], record["group"], _load_args(cls.Args, record["args"], what))
            sim.particles.request_all(cls.per_atom)
            styles[record["id"]] = style
            state = _restore_state(style, record["state"], arrays, what)
            if state is not None:
                sim.styles.restored_states[(kind, record["id"])] = (record["style"], state, style)
    sim.neighbor = _neighbor(header["neighbor"], arrays, sim.particles)
    _exclusions(sim.neighbor, header["neighbor"].get("exclude"), sim.ntypes, sim.groups)
    sim.run_state.step = int(header["step"])
    sim.run_state.random_epoch = int(header.get("random_epoch", 0))
    sim.run_state.highest_step = int(header.get("highest_step", sim.step))
    sim.run_state.run_first_step = sim.step
    sim.run_state.time = float(header["time"])
    sim.run_state.dt = float(header["dt"])
    sim.system.ghost_velocity = bool(header["ghost_velocity"])
    sim.run_state.pe = float(header["pe"])
    sim.run_state.virial = np.array(header["virial"], dtype=np.float64)
    sim.run_state.energy_step, sim.run_state.virial_step = header["energy_step"], header["virial_step"]


def _lattice(header, arrays):
    from .lattice import Lattice
    if not header["lattice"]:
        return None
    spacing = arrays["lattice/spacing"].copy()
    cell = arrays["lattice/cell"].copy() if "lattice/cell" in arrays else np.diag(spacing)
    offset = arrays["lattice/offset"].copy() if "lattice/offset" in arrays else np.zeros(3)
    return Lattice(spacing, arrays["lattice/basis"].copy(), cell, offset, str(header.get("lattice_style", "")))


def _particles(record, arrays):
    particles = Particles()
    n = int(record["nlocal"])
    properties, loaded = {}, {}
    for entry in record["properties"]:
        name = entry["name"]
        prop = Property(name, int(entry["width"]), np.dtype(entry["dtype"]).type, entry["default"])
        try:
            np.full(1, prop.default, dtype=prop.dtype)
        except (OverflowError, ValueError, TypeError):
            raise ScriptError(f"per-atom array {name} has a default {prop.default!r} that is not an "
                              f"{np.dtype(prop.dtype).name}") from None
        values = arrays[f"particles/{name}"]
        shape = (n, prop.width) if prop.width > 1 else (n,)
        if values.shape != shape or values.dtype != np.dtype(prop.dtype):
            raise ValueError(f"per-atom array {name} has shape {values.shape} and dtype {values.dtype}, "
                             f"expected {shape} and {np.dtype(prop.dtype).name}")
        properties[name], loaded[name] = prop, values
    missing = [name for name in CORE if name not in properties]
    if missing:
        raise ValueError(f"per-atom arrays {', '.join(missing)} are missing")
    particles.load(properties, loaded, n)
    particles.next_tag = int(record["next_tag"])
    return particles


def _pair(sim, record, arrays):
    if record is None:
        return None
    cls = registry.lookup("pair", record["style"])
    what = f"pair {record['style']}"
    pair = cls(sim, _load_args(cls.Args, record["args"], what))
    _restore_pair(pair, record, arrays)
    substyles = getattr(pair, "substyles", None)
    for name, sub_record in (record.get("substyles") or {}).items():
        if substyles is None or name not in substyles or sub_record.get("style") != name:
            raise ScriptError(f"{what}: the file names a sub-style {name} the pair style does not have")
        _restore_pair(substyles[name], sub_record, arrays)
    return pair


def _restore_pair(pair, record, arrays):
    """Coefficients, mixing and state of a pair style made from its arguments."""
    cls, what = type(pair), f"pair {record['style']}"
    for i, j, model_name, values in record["coeffs"]:
        model = getattr(cls, model_name, None)
        if not (isinstance(model, type) and issubclass(model, StyleArgs)):
            raise ScriptError(f"pair style {record['style']} has no coefficient class {model_name}")
        pair.coeffs[(int(i), int(j))] = _load_args(model, values, f"pair_coeff {i} {j}")
    pair.mix_rule = record["mix_rule"]
    pair.shift = bool(record.get("shift", False))
    _restore_state(pair, record["state"], arrays, what)


def _neighbor(record, arrays, particles):
    neighbor = Neighbor(skin=float(record["skin"]))
    neighbor.style = record["style"]
    neighbor.modify(every=int(record["every"]), delay=int(record["delay"]), check=bool(record["check"]))
    neighbor.sort_every = int(record["sort_every"])
    neighbor.last_sort = record["last_sort"]
    neighbor.ago = int(record["ago"])
    neighbor.builds, neighbor.dangerous = int(record["builds"]), int(record["dangerous"])
    neighbor.one = int(record.get("one", neighbor.one))
    neighbor.history = int(record.get("history", 0))
    built = record["built_with"]
    if built is not None:
        neighbor.xhold = arrays["neighbor/xhold"].copy()
        lists = [(kind, arrays[f"neighbor/cutoff{k}"].copy()) for k, kind in enumerate(built["kinds"])]
        neighbor.built_with = (float(built["skin"]), lists, arrays["neighbor/lo"].copy(),
                               arrays["neighbor/hi"].copy(), tuple(bool(p) for p in built["periodic"]))
        neighbor.use_built_skin()
        neighbor.mark_current(particles)      # saved while current: the next run resumes them
    return neighbor


def _exclusions(neighbor, record, ntypes, groups):
    """neigh_modify exclude as written, checked as the command checks it (types in 1..ntypes,
    groups defined, molecule/intra or inter)."""
    if record is None:
        return
    try:
        for a, b in record["types"]:
            pair = tuple((int(lo), int(hi)) for lo, hi in (a, b))
            if not all(1 <= lo <= hi <= ntypes for lo, hi in pair):
                raise ValueError(f"type range {a} {b} outside 1..{ntypes}")
            neighbor.excluded_type_pairs.append(pair)
        for first, second in record["groups"]:
            if first not in groups or second not in groups:
                raise ValueError(f"group {first if first not in groups else second} is not defined")
            neighbor.excluded_group_pairs.append((str(first), str(second)))
        for group, kind in record["molecules"]:
            if group not in groups or kind not in ("intra", "inter"):
                raise ValueError(f"molecule/{kind} {group}")
            neighbor.excluded_molecules.append((str(group), str(kind)))
    except (TypeError, ValueError, KeyError) as exc:
        raise ScriptError(f"neighbor exclusions: {exc} (a damaged restart file)") from None


def _spelling(kind, style):
    """{"spelling": class name} for a style made by another spelling of its name (``respell``: fix
    wall/gran's LIGGGHTS spelling), which a restart must make again; {} for the registered class."""
    if type(style) is registry.lookup(kind, style.name):
        return {}
    return {"spelling": type(style).__name__}


def _spelled(cls, record, what):
    """The class a restart record makes: the registered one, or the spelling it names."""
    name = record.get("spelling")
    if name is None:
        return cls
    found = next((other for other in cls.spellings() if other.__name__ == name), None)
    if found is None:
        raise ScriptError(f"{what}: the file spells {record['style']} as {name!r:.40}, which the style does not know")
    return found


def _load_args(model, data, what):
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        raise ScriptError(f"{what}: saved arguments no longer fit the style "
                          f"({exc.errors()[0]['msg']})") from None


def _restore_state(style, encoded, arrays, what):
    """Give the style its saved state; returns a copy of it, untouched by the style, or None."""
    if encoded is None:
        return None
    method = getattr(style, "restore", None)
    if not callable(method):
        raise ScriptError(f"{what} ({style.name}): the file holds a state but the style has no restore()")
    method(_decode(encoded, arrays))
    return _decode(encoded, arrays)


def _decode(value, arrays):
    if isinstance(value, dict):
        if set(value) == {"__array__"}:
            return arrays[value["__array__"]].copy()
        return {k: _decode(v, arrays) for k, v in value.items()}
    if isinstance(value, list):
        return [_decode(v, arrays) for v in value]
    return value


def take_up_state(sim, kind, ident, style):
    """A fix, compute or analyze style given again after read_restart with the ID and style it had
    takes up the state saved for it, when it is made (as LAMMPS's fixes do), so that the commands
    after it (reset_timestep) act on that state."""
    held = sim.styles.restored_states.get((kind, ident))
    if held is not None and held[0] == style.name and held[2] is not style and callable(
            getattr(style, "restore", None)):
        style.restore(held[1])
        del sim.styles.restored_states[(kind, ident)]


def drop_unclaimed_states(sim):
    """The saved states no style took up by the next run (or restart written) are dropped, as
    LAMMPS drops the restart information of fixes not given again."""
    sim.styles.restored_states = {}
