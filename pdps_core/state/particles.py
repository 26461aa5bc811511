"""Per-particle state as structure-of-arrays: owned particles first (``0..nlocal``), ghosts after.

Every particle has ``x, v, f`` (float64, n x 3), ``tag`` (int64 global id, from 1), ``type`` (int32,
from 1), ``mask`` (uint32 group bits) and ``image`` (int32, n x 3). Any other per-atom array, such as
``radius``, ``rmass``, ``omega``, ``torque``, ``molecule`` (int64 molecule id, 0 for none) or ``q``
(charge), exists only after a style has asked for it with
``request``: a scene that needs no rotation never allocates ``omega``.
"""

from dataclasses import dataclass

import numpy as np

from ..errors import ScriptError


@dataclass(frozen=True)
class Property:
    name: str
    width: int          # values per particle: 1 (scalar) or 3 (vector)
    dtype: type
    default: float = 0.0


CORE = {
    "x": Property("x", 3, np.float64),
    "v": Property("v", 3, np.float64),
    "f": Property("f", 3, np.float64),
    "tag": Property("tag", 1, np.int64),
    "type": Property("type", 1, np.int32, 1),
    "mask": Property("mask", 1, np.uint32, 1),
    "image": Property("image", 3, np.int32),
}

# Properties styles commonly ask for, so that two styles asking for "radius" agree on its shape.
KNOWN = {
    "radius": Property("radius", 1, np.float64, 0.5),
    "rmass": Property("rmass", 1, np.float64, 1.0),
    "omega": Property("omega", 3, np.float64),
    "torque": Property("torque", 3, np.float64),
    "molecule": Property("molecule", 1, np.int64),
    "q": Property("q", 1, np.float64),
}

# The particle styles (LAMMPS's atom styles) pdps reads: the per-atom arrays each one adds to the core
# ones, and the columns of its lines in a data file's Atoms section (image flags may follow). The bond,
# angle and full styles read molecule ids; their bonds and angles are skipped, as pdps has no bond styles.
PARTICLE_STYLES = {
    "atomic": ((), ("id", "type", "x", "y", "z")),
    "sphere": (("radius", "rmass", "omega", "torque"), ("id", "type", "diameter", "density", "x", "y", "z")),
    "charge": (("q",), ("id", "type", "q", "x", "y", "z")),
    "molecular": (("molecule",), ("id", "molecule", "type", "x", "y", "z")),
    "bond": (("molecule",), ("id", "molecule", "type", "x", "y", "z")),
    "angle": (("molecule",), ("id", "molecule", "type", "x", "y", "z")),
    "full": (("molecule", "q"), ("id", "molecule", "type", "q", "x", "y", "z")),
}


class Particles:
    """``arrays[name]`` is a view of the first ``nall`` rows of a larger buffer (``_store``), grown
    by a quarter when full: ghosts made at every rebuild and particles arriving from other ranks
    are written in place instead of allocating every array anew. A view taken before particles are
    added, deleted or ghosts are made may be stale afterwards: read ``p.x`` again."""

    def __init__(self):
        self.properties = dict(CORE)
        self._store = {name: self._empty(p, 0) for name, p in self.properties.items()}
        self.arrays = dict(self._store)
        self.nlocal = 0
        self.nghost = 0
        self.next_tag = 1

    @staticmethod
    def _empty(prop, n):
        shape = (n, prop.width) if prop.width > 1 else (n,)
        return np.full(shape, prop.default, dtype=prop.dtype)

    def _capacity(self):
        return len(self._store["tag"])

    def _reserve(self, rows):
        """Room for ``rows`` particles in every buffer (the values of the current ones kept)."""
        if rows <= self._capacity():
            return
        size = max(rows, int(1.25 * self._capacity()) + 16)
        used = self.nlocal + self.nghost
        for name, prop in self.properties.items():
            shape = (size, prop.width) if prop.width > 1 else (size,)
            grown = np.empty(shape, dtype=prop.dtype)
            grown[:used] = self._store[name][:used]
            self._store[name] = grown

    def _views(self):
        n = self.nlocal + self.nghost
        for name in self.properties:
            self.arrays[name] = self._store[name][:n]

    def load(self, properties, values, nlocal):
        """Set every per-atom array at once (a restart file read): ``values[name]`` holds ``nlocal``
        owned particles for each of ``properties`` (name -> Property)."""
        self.properties = dict(properties)
        self._store = {name: np.array(values[name], dtype=prop.dtype) for name, prop in self.properties.items()}
        self.arrays = {}
        self.nlocal, self.nghost = nlocal, 0
        self._views()

    # ---- properties -------------------------------------------------------------------------------
    def request(self, name, width=None, dtype=np.float64, default=0.0):
        """Allocate a per-atom array (idempotent); known names have a fixed shape."""
        prop = KNOWN.get(name) or Property(name, width or 1, dtype, default)
        existing = self.properties.get(name)
        if existing is not None:
            if existing.width != prop.width or existing.dtype != prop.dtype:
                raise ScriptError(f"per-atom property {name} requested with two different shapes")
            return self.arrays[name]
        self.properties[name] = prop
        self._store[name] = self._empty(prop, self._capacity())
        self.arrays[name] = self._store[name][:self.nlocal + self.nghost]
        return self.arrays[name]

    def request_all(self, entries):
        """Allocate what a style's ``per_atom`` lists: names, or (name, width) pairs."""
        for entry in entries:
            if isinstance(entry, str):
                self.request(entry)
            else:
                self.request(*entry)

    def has(self, name):
        return name in self.arrays

    def __getattr__(self, name):
        arrays = self.__dict__.get("arrays")
        if arrays is not None and name in arrays:
            return arrays[name]
        raise AttributeError(name)

    # ---- counts ---------------------------------------------------------------------------------
    @property
    def nall(self):
        return self.nlocal + self.nghost

    # ---- owned particles ------------------------------------------------------------------------
    def check_room(self, n):
        """MemoryError now when ``n`` more particles cannot fit: the rows they need are allocated and
        freed at once (add() copies every array, so twice), before a command spends time and memory
        placing them; near the address-space limit the interpreter can crash instead of raising."""
        if n > 0:
            np.empty((self.nlocal + n, 2 * self.row_width()))

    def add(self, x, type_, tags=None, **values):
        """Append owned particles at positions x (n x 3) of the given type(s), with ids ``tags``
        (default: from ``next_tag`` on); returns their indices."""
        self.clear_ghosts()
        x = np.atleast_2d(np.asarray(x, dtype=np.float64))
        n = len(x)
        start = self.nlocal
        self._reserve(start + n)
        for name, prop in self.properties.items():
            self._store[name][start:start + n] = prop.default
        self.nlocal += n
        self._views()
        self.arrays["x"][start:] = x
        self.arrays["type"][start:] = type_
        if tags is None:
            tags = np.arange(self.next_tag, self.next_tag + n)
            self.next_tag += n
        self.arrays["tag"][start:] = tags
        for name, value in values.items():
            if name not in self.arrays:
                raise ScriptError(f"per-atom property {name} does not exist (a style must request it)")
            self.arrays[name][start:] = value
        return np.arange(start, start + n)

    def keep(self, selection):
        """Keep only the owned particles selected (boolean mask or index array), in that order."""
        self.clear_ghosts()
        kept = 0
        for name in self.properties:
            values = self._store[name][:self.nlocal][selection]
            kept = len(values)
            self._store[name][:kept] = values
        self.nlocal = kept
        self._views()

    # ---- ghosts ---------------------------------------------------------------------------------
    def clear_ghosts(self):
        if self.nghost:
            self.nghost = 0
            self._views()

    def set_ghosts(self, source, shift):
        """Replace the ghosts by copies of owned particles ``source`` displaced by ``shift`` (n x 3)."""
        self.clear_ghosts()
        n = len(source)
        self._reserve(self.nlocal + n)
        for name in self.properties:
            store = self._store[name]
            np.take(store[:self.nlocal], source, axis=0, out=store[self.nlocal:self.nlocal + n])
        self._store["x"][self.nlocal:self.nlocal + n] += shift
        self.nghost = n
        self._views()

    # ---- rows: every per-atom value of a particle as one float64 row (migration, ghosts) ----------
    def row_width(self):
        return sum(prop.width for prop in self.properties.values())

    def pack(self, index):
        """Rows of all per-atom values of the particles ``index``, in property order; every rank
        requests properties in script order, so the layout agrees between ranks."""
        rows = np.empty((len(index), self.row_width()))
        column = 0
        for name, prop in self.properties.items():
            values = self.arrays[name][index]
            rows[:, column:column + prop.width] = values.reshape(len(index), prop.width)
            column += prop.width
        return rows

    def _unpack(self, rows):
        column, out = 0, {}
        for name, prop in self.properties.items():
            block = rows[:, column:column + prop.width]
            values = block.astype(prop.dtype)
            out[name] = values if prop.width > 1 else values[:, 0]
            column += prop.width
        return out

    def append_owned(self, rows):
        """Particles arriving from another rank become owned (ghosts are cleared first)."""
        self.clear_ghosts()
        n, start = len(rows), self.nlocal
        self._reserve(start + n)
        for name, values in self._unpack(rows).items():
            self._store[name][start:start + n] = values
        self.nlocal += n
        self._views()

    def set_ghost_rows(self, rows):
        """Replace the ghosts by particles received as rows."""
        self.clear_ghosts()
        n, start = len(rows), self.nlocal
        self._reserve(start + n)
        for name, values in self._unpack(rows).items():
            self._store[name][start:start + n] = values
        self.nghost = n
        self._views()

    # ---- lookup ---------------------------------------------------------------------------------
    def index_of_tag(self, tag):
        hits = np.flatnonzero(self.arrays["tag"][: self.nlocal] == tag)
        return int(hits[0]) if len(hits) else -1
