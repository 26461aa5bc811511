"""The ``lattice`` command: PDPS's spacings, and LAMMPS's lattices with their scaling.

    lattice spacing x DX y DY z DZ                      (PDPS: an orthogonal grid of the spacings)
    lattice none SCALE
    lattice sc|bcc|fcc|hcp|diamond|sq|sq2|hex|custom SCALE [keyword values]...
        origin X Y Z     fractions of the unit cell (0 <= X < 1) by which every site is shifted
        orient x|y|z I J K   the box axis along lattice direction [I J K] (orthogonal, integers)
        spacing DX DY DZ     the lattice spacings (units lattice) given instead of derived
        a1|a2|a3 X Y Z       unit-cell vectors (custom)
        basis X Y Z          a basis atom, in fractions of the unit cell (custom; repeatable)

LAMMPS's rules (its lattice page): in ``lj`` units SCALE is the reduced density rho*, and the lattice
constant is a = (n_basis / (rho* V_cell))^(1/d) with V_cell the unit cell's volume (area in 2-d) for
a = 1; in other units SCALE is the lattice constant. A site is ``R (A (ijk + b)) a + origin * spacing``
with A the unit-cell vectors as columns and R the rows ``orient`` gives, normalised. The spacings
(what ``units lattice`` multiplies by) are the box extents of the transformed unit cell, unless given.
sc/bcc/fcc/hcp/diamond are 3-d lattices, sq/sq2/hex 2-d ones, as LAMMPS requires.
"""

from typing import NamedTuple

import numpy as np

from ..errors import ScriptError
from ..commands.words import choice, integer, number

ROOT3 = np.sqrt(3.0)
STYLES = {
    "sc": (3, np.eye(3), [[0, 0, 0]]),
    "bcc": (3, np.eye(3), [[0, 0, 0], [0.5, 0.5, 0.5]]),
    "fcc": (3, np.eye(3), [[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]]),
    "hcp": (3, np.diag([1.0, ROOT3, np.sqrt(8.0 / 3.0)]),
            [[0, 0, 0], [0.5, 0.5, 0], [0.5, 5.0 / 6.0, 0.5], [0, 1.0 / 3.0, 0.5]]),
    "diamond": (3, np.eye(3), [[0, 0, 0], [0, 0.5, 0.5], [0.5, 0, 0.5], [0.5, 0.5, 0],
                               [0.25, 0.25, 0.25], [0.25, 0.75, 0.75], [0.75, 0.25, 0.75], [0.75, 0.75, 0.25]]),
    "sq": (2, np.eye(3), [[0, 0, 0]]),
    "sq2": (2, np.eye(3), [[0, 0, 0], [0.5, 0.5, 0]]),
    "hex": (2, np.diag([1.0, ROOT3, 1.0]), [[0, 0, 0], [0.5, 0.5, 0]]),
}
USAGE = ("lattice spacing x DX y DY z DZ | lattice none SCALE | lattice sc|bcc|fcc|hcp|diamond|sq|sq2|hex|custom "
         "SCALE [origin X Y Z] [orient x|y|z I J K] [spacing DX DY DZ] [a1|a2|a3 X Y Z] [basis X Y Z]")


class Lattice(NamedTuple):
    """``spacing`` (3,): what units lattice multiplies by; ``basis`` (n, 3): sites of a unit cell in
    its fractions; ``cell`` (3, 3): box-space vectors of the unit cell as columns (scaled, rotated);
    ``offset`` (3,): origin * spacing; ``style``; ``primitive`` (3, 3) the unscaled a1, a2, a3 as
    columns, ``scale`` and ``rotation`` (3, 3) the orient rows normalised, of which ``cell`` is made
    (None where only the cell is known: a restart's lattice)."""
    spacing: np.ndarray
    basis: np.ndarray
    cell: np.ndarray
    offset: np.ndarray
    style: str
    primitive: np.ndarray | None = None
    scale: float = 1.0
    rotation: np.ndarray | None = None

    def sites(self, cells):
        """Box positions of every basis site of the integer cells (m, 3) -> (m * n_basis, 3): with
        LAMMPS's arithmetic (its Lattice::lattice2box, one rounding after another: a1, a2, a3 times
        the fractions, times the scale, rotated, plus the origin), so that a site on a region's
        surface falls on the side it falls in LAMMPS (a hex lattice's y differs in its last bit
        with the cell premultiplied)."""
        f = (cells[:, None, :] + self.basis[None, :, :]).reshape(-1, 3)
        if self.primitive is None:
            return f @ self.cell.T + self.offset
        return lattice_to_box(f, self.primitive, self.scale, self.rotation, self.offset)

    def fractions(self, x):
        """Cell coordinates (ijk + b) of box positions x (m, 3)."""
        return (x - self.offset) @ np.linalg.inv(self.cell).T


def lattice_to_box(f, primitive, scale, rotation, offset):
    """Box positions of lattice coordinates f (m, 3), LAMMPS's Lattice::lattice2box term by term."""
    p, r = primitive, rotation
    unrotated = [(p[a, 0] * f[:, 0] + p[a, 1] * f[:, 1] + p[a, 2] * f[:, 2]) * scale for a in range(3)]
    out = np.empty_like(f)
    for a in range(3):
        out[:, a] = r[a, 0] * unrotated[0] + r[a, 1] * unrotated[1] + r[a, 2] * unrotated[2] + offset[a]
    return out


def parse_lattice(words, units, dimension):
    """A Lattice (or None for ``lattice none``'s absence of sites) from the command's words."""
    if not words:
        raise ScriptError(f"expected arguments; usage: {USAGE}")
    style = choice(words[0], "lattice style", ("spacing", "none", "custom", *STYLES))
    if style == "spacing":
        return _pdps_spacing(words[1:])
    if len(words) < 2:
        raise ScriptError(f"lattice {style} needs a scale; usage: {USAGE}")
    scale = number(words[1], "lattice scale", low=0.0, strict_low=True)
    if style == "none":
        if len(words) != 2:
            raise ScriptError("lattice none takes only a scale")
        spacing = np.full(3, scale)
        return Lattice(spacing, np.zeros((0, 3)), np.diag(spacing), np.zeros(3), "none")
    if style == "custom":
        need, vectors, basis = 3, np.eye(3), []
    else:
        need, vectors, basis = STYLES[style]
        vectors, basis = vectors.copy(), [list(b) for b in basis]
        if need != dimension:
            raise ScriptError(f"lattice {style} is a {need}-d lattice; this is a {dimension}-d simulation "
                              f"({'sq, sq2, hex or custom' if dimension == 2 else 'sc, bcc, fcc, hcp, diamond or custom'})")
    origin, orient, spacing = np.zeros(3), np.eye(3, dtype=np.int64), None
    k = 2
    while k < len(words):
        key = words[k]
        if key == "origin":
            origin = _numbers(words, k, 3, "origin")
            if np.any((origin < 0) | (origin >= 1)):
                raise ScriptError(f"origin fractions must be >= 0 and < 1 (got {' '.join(words[k + 1:k + 4])})")
            k += 4
        elif key == "orient":
            if len(words) < k + 5:
                raise ScriptError("orient takes x|y|z I J K")
            axis = "xyz".index(choice(words[k + 1], "orient axis", ("x", "y", "z")))
            orient[axis] = [integer(w, "orient component") for w in words[k + 2:k + 5]]
            k += 5
        elif key == "spacing":
            spacing = _numbers(words, k, 3, "spacing")
            if np.any(spacing <= 0):
                raise ScriptError("spacing values must be > 0")
            k += 4
        elif key in ("a1", "a2", "a3"):
            if style != "custom":
                raise ScriptError(f"{key} is for lattice custom (got lattice {style})")
            vectors[:, int(key[1]) - 1] = _numbers(words, k, 3, key)
            k += 4
        elif key == "basis":
            if style != "custom":
                raise ScriptError(f"basis is for lattice custom (got lattice {style})")
            fraction = _numbers(words, k, 3, "basis")
            if np.any((fraction < 0) | (fraction >= 1)):
                raise ScriptError(f"basis fractions must be >= 0 and < 1 (got {' '.join(words[k + 1:k + 4])})")
            basis.append(list(fraction))
            k += 4
        elif key in ("triclinic/general",):
            raise ScriptError(f"lattice keyword {key} is not supported")
        else:
            raise ScriptError(f"unknown lattice keyword {key}; usage: {USAGE}")
    if not basis:
        raise ScriptError("lattice custom needs at least one basis atom")
    basis = np.array(basis, dtype=np.float64)
    if dimension == 2:
        if np.any(basis[:, 2] != 0) or np.any(vectors[2, :2] != 0) or np.any(vectors[:2, 2] != 0):
            raise ScriptError("a 2-d lattice has its basis and a1, a2 in the xy plane and a3 along z")
        if np.any(orient[2] != [0, 0, 1]) or np.any(orient[:2, 2] != 0):
            raise ScriptError("a 2-d lattice keeps z along [0 0 1]")
    rotation = _rotation(orient)
    if abs(np.linalg.det(vectors)) < 1e-12:
        raise ScriptError("a1, a2 and a3 must not lie in one plane")
    if units == "lj":
        # LAMMPS's: the cell volume a1 . (a2 x a3) in 2d too, and n / volume / rho* in that order
        size = abs(float(vectors[:, 0] @ np.cross(vectors[:, 1], vectors[:, 2])))
        constant = (len(basis) / size / scale) ** (1.0 / dimension)
    else:
        constant = scale
    cell = rotation @ vectors * constant
    if spacing is None:
        corners = np.array([[i, j, k] for i in (0, 1) for j in (0, 1) for k in (0, 1)], dtype=np.float64)
        extent = lattice_to_box(corners, vectors, constant, rotation, np.zeros(3))
        spacing = extent.max(axis=0) - extent.min(axis=0)
    return Lattice(np.asarray(spacing, dtype=np.float64), basis, cell, origin * spacing, style, vectors.copy(),
                   constant, rotation)


def _pdps_spacing(words):
    if not words or len(words) % 2:
        raise ScriptError(f"expected pairs of axis and spacing; usage: {USAGE}")
    spacing = np.ones(3)
    for axis, value in zip(words[::2], words[1::2]):
        choice(axis, "lattice axis", ("x", "y", "z"))
        spacing["xyz".index(axis)] = number(value, f"lattice spacing {axis}", low=0.0, strict_low=True)
    return Lattice(spacing, np.zeros((1, 3)), np.diag(spacing), np.zeros(3), "spacing")


def _numbers(words, k, n, what):
    values = words[k + 1:k + 1 + n]
    if len(values) != n:
        raise ScriptError(f"{what} takes {n} numbers (got {' '.join(values) or 'none'})")
    return np.array([number(w, what) for w in values])


def _rotation(orient):
    rows = orient.astype(np.float64)
    lengths = np.linalg.norm(rows, axis=1)
    if np.any(lengths == 0):
        raise ScriptError("orient vectors must not be zero")
    for a, b in ((0, 1), (0, 2), (1, 2)):
        if rows[a] @ rows[b] != 0:
            raise ScriptError(f"orient {'xyz'[a]} and {'xyz'[b]} must be orthogonal")
    if np.linalg.det(rows) <= 0:
        raise ScriptError("orient x, y, z must form a right-handed system")
    return rows / lengths[:, None]
