"""Per-particle state as structure-of-arrays: owned particles first (``0..nlocal``), ghosts after.

Every particle has ``x, v, f`` (float64, n x 3), ``tag`` (int64 global id, from 1), ``type`` (int32,
from 1), ``mask`` (uint32 group bits) and ``image`` (int32, n x 3). Any other per-atom array, such as
``radius``, ``rmass``, ``omega``, ``torque``, ``molecule`` (int64 molecule id, 0 for none) or ``q``
(charge), exists only after a style has asked for it with
``request``: a scene that needs no rotation never allocates ``omega``.

Ghosts carry every per-atom value a pair or a fix may read of a neighbour. They do not carry the
values the force computation sums into (``f``, ``torque``: zeroed at every step, then summed back onto
the owners) nor image flags, which only owned particles have; such properties are requested with
``ghost=False`` and their ghost rows are zero after ghosts are made.
"""

from dataclasses import dataclass, replace

import numpy as np
from numba import njit

from ..errors import ScriptError


REPLICATE_RULES = ("copy", "contacts", "refuse")


@dataclass(frozen=True)
class Property:
    name: str
    width: int          # values per particle: 1 (scalar) or 3 (vector)
    dtype: type
    default: float = 0.0
    ghost: bool = True  # ghosts receive it when they are made
    # what the replicate command does with it: "copy" (each copy of a particle takes its values),
    # "contacts" (contact partners: refused while any contact is open, else copied), "refuse" (a
    # style's own values a copy must not take, or no style said: replicate refuses while it exists)
    replicate: str = "refuse"


# (replicate gives each copy its own position, image flags, id and molecule id, copies the rest)
CORE = {
    "x": Property("x", 3, np.float64, replicate="copy"),
    "v": Property("v", 3, np.float64, replicate="copy"),
    "f": Property("f", 3, np.float64, ghost=False, replicate="copy"),
    "tag": Property("tag", 1, np.int64, replicate="copy"),
    "type": Property("type", 1, np.int32, 1, replicate="copy"),
    "mask": Property("mask", 1, np.uint32, 1, replicate="copy"),
    "image": Property("image", 3, np.int32, ghost=False, replicate="copy"),
}

# Properties styles commonly ask for, so that two styles asking for "radius" agree on its shape.
KNOWN = {
    "radius": Property("radius", 1, np.float64, 0.5, replicate="copy"),
    "rmass": Property("rmass", 1, np.float64, 1.0, replicate="copy"),
    "omega": Property("omega", 3, np.float64, replicate="copy"),
    "torque": Property("torque", 3, np.float64, ghost=False, replicate="copy"),
    "molecule": Property("molecule", 1, np.int64, replicate="copy"),
    "q": Property("q", 1, np.float64, replicate="copy"),
}

# The particle styles (LAMMPS's atom styles) pdps reads: the per-atom arrays each one adds to the core
# ones, and the columns of its lines in a data file's Atoms section (image flags may follow). The bond,
# angle and full styles read molecule ids and bonds (pdps_core/state/topology.py); their angles are skipped.
PARTICLE_STYLES = {
    "atomic": ((), ("id", "type", "x", "y", "z")),
    "sphere": (("radius", "rmass", "omega", "torque"), ("id", "type", "diameter", "density", "x", "y", "z")),
    "charge": (("q",), ("id", "type", "q", "x", "y", "z")),
    "molecular": (("molecule",), ("id", "molecule", "type", "x", "y", "z")),
    "bond": (("molecule",), ("id", "molecule", "type", "x", "y", "z")),
    "angle": (("molecule",), ("id", "molecule", "type", "x", "y", "z")),
    "full": (("molecule", "q"), ("id", "molecule", "type", "q", "x", "y", "z")),
}


POSITION_COLUMNS = ("id", "type", "x", "y", "z")


def substyles(style):
    """The particle styles a ``particle_style`` value stands for: itself, or for ``hybrid S1 S2 ...``
    (LAMMPS's atom_style hybrid) its sub-styles, LIGGGHTS's ``granular`` read as sphere. ValueError
    says what is wrong."""
    words = style.split()
    named = tuple("sphere" if w == "granular" else w for w in words[1:] if words[0] == "hybrid")
    if not words or (words[0] != "hybrid" and len(words) != 1):
        raise ValueError(f"a particle style is one word or hybrid S1 S2 ... (got {style!r})")
    if words[0] != "hybrid":
        name = "sphere" if words[0] == "granular" else words[0]
        if name not in PARTICLE_STYLES:
            raise ValueError(f"unknown particle style {words[0]} (known: {', '.join(PARTICLE_STYLES)}, hybrid)")
        return (name,)
    if not named:
        raise ValueError("hybrid needs one or more particle styles, e.g. hybrid sphere molecular")
    for name in named:
        if name not in PARTICLE_STYLES:
            raise ValueError(f"unknown particle style {name} in hybrid (known: {', '.join(PARTICLE_STYLES)})")
    if len(set(named)) < len(named):
        raise ValueError(f"a particle style appears twice in hybrid {' '.join(named)}")
    return named


def style_properties(style):
    """The per-atom arrays the style adds to the core ones (the union of its sub-styles')."""
    names = []
    for name in substyles(style):
        names += [p for p in PARTICLE_STYLES[name][0] if p not in names]
    return tuple(names)


def style_columns(style):
    """The columns of an Atoms line: the style's own, or for hybrid LAMMPS's order: id type x y z,
    then each sub-style's other columns in turn, a column two sub-styles share once."""
    subs = substyles(style)
    if style.split()[0] != "hybrid":
        return PARTICLE_STYLES[subs[0]][1]
    columns = list(POSITION_COLUMNS)
    for name in subs:
        columns += [c for c in PARTICLE_STYLES[name][1] if c not in columns]
    return tuple(columns)


@njit(cache=True)
def _gather_columns(values, index, rows, column):
    """rows[k, column:column + width] = values[index[k]]: one property of the particles ``index``
    into float64 rows (ids, types and group bits are exact in a double below 2^53)."""
    for k in range(len(index)):
        i = index[k]
        for d in range(values.shape[1]):
            rows[k, column + d] = values[i, d]


@njit(cache=True)
def _gather_blocks(values, index, shift, counts, column, width, out):
    """One property of the ghosts ``index`` into the flat buffer ``out``, laid out by destination:
    ``counts[r]`` ghosts for rank r, their rows of ``width`` values each stored property by
    property (this one a contiguous block ``column`` values into each row's share), plus ``shift``
    (positions of periodic images) if given. Vectors and scalars have loops of their own: a loop
    over a width known only at run time is several times slower."""
    w = values.shape[1]
    shifted = len(shift) > 0
    row = 0
    for r in range(len(counts)):
        block = out[row * width + counts[r] * column:]
        if w == 3 and shifted:
            for k in range(counts[r]):
                i = index[row + k]
                block[3 * k] = values[i, 0] + shift[row + k, 0]
                block[3 * k + 1] = values[i, 1] + shift[row + k, 1]
                block[3 * k + 2] = values[i, 2] + shift[row + k, 2]
        elif w == 3:
            for k in range(counts[r]):
                i = index[row + k]
                block[3 * k] = values[i, 0]
                block[3 * k + 1] = values[i, 1]
                block[3 * k + 2] = values[i, 2]
        elif w == 1:
            for k in range(counts[r]):
                block[k] = values[index[row + k], 0]
        else:
            for k in range(counts[r]):
                for d in range(w):
                    block[k * w + d] = values[index[row + k], d]
        row += counts[r]


@njit(cache=True)
def _scatter_blocks(buffer, counts, column, width, values, start):
    """The inverse of _gather_blocks: values[start + row] from the block of each source's share."""
    w = values.shape[1]
    row = 0
    for r in range(len(counts)):
        block = buffer[row * width + counts[r] * column:]
        first = start + row
        if w == 3:
            for k in range(counts[r]):
                values[first + k, 0] = block[3 * k]
                values[first + k, 1] = block[3 * k + 1]
                values[first + k, 2] = block[3 * k + 2]
        elif w == 1:
            for k in range(counts[r]):
                values[first + k, 0] = block[k]
        else:
            for k in range(counts[r]):
                for d in range(w):
                    values[first + k, d] = block[k * w + d]
        row += counts[r]


_NO_SHIFT = np.zeros((0, 3))


@njit(cache=True)
def _scatter_columns(rows, column, values, start):
    """values[start + k] = rows[k, column:column + width], each value cast to the property's type."""
    for k in range(rows.shape[0]):
        for d in range(values.shape[1]):
            values[start + k, d] = rows[k, column + d]


@njit(cache=True)
def _removal_moves(gone, nlocal, into, source):
    """Rows to move when the particles flagged in ``gone`` are removed as LAMMPS removes them (each
    gone particle's slot taken by the current last particle, which is looked at again): writes the
    (slot, row it takes) pairs and returns (how many moves, particles left). ``gone`` is modified."""
    n = nlocal
    moved = 0
    i = 0
    origin = source          # origin[k]: the original row now in slot k, for slots a move touched
    for k in range(nlocal):
        origin[k] = k
    while i < n:
        if gone[i]:
            last = n - 1
            gone[i] = gone[last]
            origin[i] = origin[last]
            n -= 1
        else:
            i += 1
    for k in range(n):
        if origin[k] != k:
            into[moved] = k
            origin[moved] = origin[k]
            moved += 1
    return moved, n


@njit(cache=True)
def _move_rows(values, into, source, moved):
    """values[into[k]] = values[source[k]] for the first ``moved`` moves (every source lies beyond
    every slot written before it, so moving in order is safe)."""
    for k in range(moved):
        for d in range(values.shape[1]):
            values[into[k], d] = values[source[k], d]


@njit(cache=True)
def _keep_in_place(values, index, nlocal, done):
    """values[k] = values[index[k]] for every k, in place; returns False (nothing written) unless
    ``index`` rises (a subset kept in order: each row comes from at or after its slot) or is a
    permutation of all ``nlocal`` rows, which moves one cycle at a time through a row of scratch.
    ``done``: nlocal flags, overwritten."""
    m = len(index)
    rising = True
    for k in range(1, m):
        if index[k] <= index[k - 1]:
            rising = False
            break
    if rising:
        for k in range(m):
            if index[k] != k:
                for d in range(values.shape[1]):
                    values[k, d] = values[index[k], d]
        return True
    if m != nlocal:
        return False
    done[:] = False
    for k in range(m):
        if index[k] < 0 or index[k] >= m or done[index[k]]:
            return False
        done[index[k]] = True
    done[:] = False
    row = np.empty(values.shape[1], dtype=values.dtype)
    for start in range(m):
        if done[start]:
            continue
        row[:] = values[start]
        k = start
        while True:
            done[k] = True
            j = index[k]
            if j == start:
                values[k] = row
                break
            values[k] = values[j]
            k = j
    return True


def _columns(array):
    """A per-atom array as (n, width): vectors as they are, scalars as a one-column view."""
    return array if array.ndim == 2 else array.reshape(-1, 1)


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
        self._moves = np.zeros((2, 0), dtype=np.int64)     # remove()'s buffers

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
        size = max(rows + rows // 8 + 16, int(1.25 * self._capacity()) + 16)
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
    def request(self, name, width=None, dtype=np.float64, default=0.0, ghost=True, replicate="refuse"):
        """Allocate a per-atom array (idempotent); known names have a fixed shape. ``ghost=False``
        for a value only owned particles need (one summed back from ghosts, say). ``replicate``:
        what the replicate command does with it (Property.replicate): "copy" for a value a copy of
        the particle shares (a temperature, a value a style computes afresh), "contacts" for contact
        partners, "refuse" (the default) for anything a copy must not take (a body id, a
        particle's position at some earlier time)."""
        if replicate not in REPLICATE_RULES:
            raise ValueError(f"replicate must be one of {', '.join(REPLICATE_RULES)} (got {replicate!r})")
        prop = KNOWN.get(name) or Property(name, width or 1, dtype, default, ghost, replicate)
        existing = self.properties.get(name)
        if existing is not None:
            if existing.width != prop.width or existing.dtype != prop.dtype:
                raise ScriptError(f"per-atom property {name} requested with two different shapes")
            if existing.replicate != prop.replicate:
                # a property read back from a restart file takes the rule of the style asking again
                self.properties[name] = replace(existing, replicate=prop.replicate)
            return self.arrays[name]
        self.properties[name] = prop
        self._store[name] = self._empty(prop, self._capacity())
        self.arrays[name] = self._store[name][:self.nlocal + self.nghost]
        return self.arrays[name]

    def widen(self, name, width):
        """Make a per-atom array ``width`` columns wide, its values kept and the new columns at the
        default (room for more bonds per particle). Every rank must widen alike: rows travel
        between ranks with one width."""
        prop = self.properties[name]
        if width <= prop.width:
            return self.arrays[name]
        wider = replace(prop, width=width)
        grown = self._empty(wider, self._capacity())
        grown[:, :prop.width] = self._store[name].reshape(len(grown), -1)
        self.properties[name], self._store[name] = wider, grown
        self.arrays[name] = grown[:self.nlocal + self.nghost]
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
        """Keep only the owned particles selected (boolean mask or index array), in that order.

        A subset kept in order and a reordering of all of them (the spatial sort) move rows in
        place: a copy of each array, as indexing makes, cost a transient the size of the largest
        (a contact history: 15 MB at 20,000 particles) and left that much resident after it."""
        self.clear_ghosts()
        index = np.asarray(selection)
        if index.dtype == np.bool_:
            index = np.flatnonzero(index)
        index = index.astype(np.int64, copy=False)
        done = np.empty(self.nlocal, dtype=np.bool_)
        for name in self.properties:
            rows = _columns(self._store[name])
            if not _keep_in_place(rows, index, self.nlocal, done):
                values = self._store[name][:self.nlocal][index]
                self._store[name][:len(index)] = values
        self.nlocal = len(index)
        self._views()

    def remove(self, gone):
        """Remove the owned particles flagged in ``gone`` (bool or uint8 per owned particle; it is
        modified) as LAMMPS does: the last particle takes each freed slot, so only the moved rows
        are copied and the order afterwards is LAMMPS's."""
        self.clear_ghosts()
        if self._moves.shape[1] < self.nlocal:
            self._moves = np.empty((2, self.nlocal + self.nlocal // 4 + 16), dtype=np.int64)
        into, source = self._moves[0], self._moves[1]
        moved, left = _removal_moves(gone.view(np.uint8), self.nlocal, into, source)
        for name in self.properties:
            _move_rows(_columns(self._store[name]), into, source, moved)
        self.nlocal = left
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
        for name, prop in self.properties.items():
            store = self._store[name]
            if prop.ghost:
                # mode clip: numpy's default (raise) copies through a buffer as large as the output
                np.take(store[:self.nlocal], source, axis=0, out=store[self.nlocal:self.nlocal + n], mode="clip")
            else:
                store[self.nlocal:self.nlocal + n] = 0
        self._store["x"][self.nlocal:self.nlocal + n] += shift
        self.nghost = n
        self._views()

    # ---- rows: per-atom values of a particle as one float64 row (migration, ghosts) --------------
    def row_width(self, ghost=False):
        """Values in a particle's row: every property, or (``ghost``) those ghosts carry."""
        return sum(p.width for p in self.properties.values() if p.ghost or not ghost)

    def pack(self, index):
        """Rows of every per-atom value of the particles ``index`` (migration), in property order
        (every rank requests properties in script order, so the layout agrees between ranks)."""
        rows = np.empty((len(index), self.row_width()))
        column = 0
        for name, prop in self.properties.items():
            _gather_columns(_columns(self.arrays[name]), index, rows, column)
            column += prop.width
        return rows

    def pack_ghosts(self, index, counts, out, shift):
        """The values ghosts carry of the particles ``index`` (``counts[r]`` of them for rank r, in
        rank order), positions displaced by ``shift``, into the flat float64 buffer ``out``: rank
        r's share is its ghosts' values property by property (each a contiguous block), so that
        set_ghost_blocks places them with contiguous reads."""
        width = self.row_width(ghost=True)
        column = 0
        for name, prop in self.properties.items():
            if prop.ghost:
                _gather_blocks(_columns(self.arrays[name]), index, shift if name == "x" else _NO_SHIFT,
                               counts, column, width, out)
                column += prop.width

    def set_ghost_blocks(self, values, counts):
        """Replace the ghosts by those received from each rank (``counts[r]`` from rank r) as
        pack_ghosts lays them out."""
        self.clear_ghosts()
        n, start = int(counts.sum()), self.nlocal
        self._reserve(start + n)
        width = self.row_width(ghost=True)
        column = 0
        for name, prop in self.properties.items():
            store = self._store[name]
            if not prop.ghost:
                store[start:start + n] = 0
                continue
            _scatter_blocks(values, counts, column, width, _columns(store), start)
            column += prop.width
        self.nghost = n
        self._views()

    def _place_rows(self, rows, start):
        column = 0
        for name, prop in self.properties.items():
            _scatter_columns(rows, column, _columns(self._store[name]), start)
            column += prop.width

    def append_owned(self, rows):
        """Particles arriving from another rank (full rows) become owned (ghosts are cleared first)."""
        self.clear_ghosts()
        n, start = len(rows), self.nlocal
        self._reserve(start + n)
        self._place_rows(rows, start)
        self.nlocal += n
        self._views()

    # ---- lookup ---------------------------------------------------------------------------------
    def index_of_tag(self, tag):
        hits = np.flatnonzero(self.arrays["tag"][: self.nlocal] == tag)
        return int(hits[0]) if len(hits) else -1

    def owned_rows(self, tags):
        """The owned row of each id in ``tags`` (an array), -1 for ids not owned here."""
        tags = np.asarray(tags, dtype=np.int64)
        n = self.nlocal
        if n == 0:
            return np.full(len(tags), -1, dtype=np.int64)
        owned = self.arrays["tag"][:n]
        order = np.argsort(owned, kind="stable")
        at = np.minimum(np.searchsorted(owned[order], tags), n - 1)
        rows = order[at]
        return np.where(owned[rows] == tags, rows, -1).astype(np.int64)
