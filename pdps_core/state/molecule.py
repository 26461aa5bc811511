r"""Molecule templates: the ``molecule`` command's file, read as LAMMPS reads its molecule file format
(LAMMPS's Molecule class), for styles that insert copies of it (fix pour ``mol``) and bodies made
of it (fix rigid/small ``mol``).

The file: a first line that is skipped, then header lines (``N atoms``, ``M mass``,
``Xc Yc Zc com``, ``Ixx Iyy Izz Ixy Ixz Iyz inertia``; ``0 bonds`` and the other topology counts may
be given as 0), then sections of one line per atom, ``I value(s)`` with every I from 1 to N once:
``Coords`` (x y z, distance), ``Types`` (a type, an offset to the inserting style's), ``Diameters``
(distance), ``Masses`` (mass), ``Molecules`` (one molecule id throughout). ``#`` starts a comment.
Bonds, angles, charges, fragments, special lists, SHAKE and body sections are refused by name.

What a template derives, as LAMMPS's Molecule does: the geometric centre (the mean of the
coordinates) and the displacements from it; ``molradius``, the largest distance of an atom's
surface from the centre, :math:`\max_i (|x_i - c| + r_i)` (radii 0 without Diameters); the total
mass, centre of mass and inertia tensor about it (spheres add :math:`\tfrac{2}{5} m r^2` to the
diagonal), each from the header where it gives them. The header's six inertia values are taken as
LAMMPS 22 Jul 2025 takes them, xx yy zz then yz xz xy (its manual names the last three Ixy Ixz Iyz;
measured: examples/rigid's molecule.data, whose Ixy and Iyz differ, moves as LAMMPS's only so). Masses come from Masses or, failing that, from
the types' masses when a style asks (``masses(type_mass)``), since ``mass`` may follow ``molecule``.
"""

from dataclasses import dataclass, field

import numpy as np

from ..errors import ScriptError

HEADER_WORDS = {"atoms": 1, "mass": 1, "com": 3, "inertia": 6, "bonds": 1, "angles": 1, "dihedrals": 1,
                "impropers": 1, "fragments": 1, "body": 2}
TOPOLOGY_COUNTS = ("bonds", "angles", "dihedrals", "impropers", "fragments")
SECTIONS = {"Coords": 3, "Types": 1, "Diameters": 1, "Masses": 1, "Molecules": 1}
REFUSED_SECTIONS = {
    **{name: "pdps's molecule templates carry no bonds" for name in
       ("Bonds", "Angles", "Dihedrals", "Impropers", "Special Bond Counts", "Special Bonds")},
    "Charges": "pdps's molecule templates carry no charges",
    "Fragments": "pdps's molecule templates have no fragments",
    **{name: "pdps has no fix shake" for name in ("Shake Flags", "Shake Atoms", "Shake Bond Types")},
    **{name: "pdps has no body particles" for name in ("Body Integers", "Body Doubles")},
}
VALUE_LIMIT = 1.0e100          # so that a template's sums (centre, reach, inertia) stay finite
SPHERE_INERTIA = 0.4        # of a solid sphere, m r^2 (LAMMPS uses it in 2-d too)


@dataclass
class MoleculeTemplate:
    """A molecule template: per-atom ``coords`` (n, 3), ``types`` (n,) int, ``radius`` (n,) or None
    (no Diameters), ``rmass`` (n,) or None (no Masses), the header's ``mass``, ``com``, ``inertia``
    (its six values in the file's order) or None, and what follows from them."""
    id: str
    title: str
    coords: np.ndarray
    types: np.ndarray
    radius: np.ndarray | None = None
    rmass: np.ndarray | None = None
    header_mass: float | None = None
    header_com: np.ndarray | None = None
    header_inertia: np.ndarray | None = None
    center: np.ndarray = field(init=False)
    dx: np.ndarray = field(init=False)
    molradius: float = field(init=False)

    def __post_init__(self):
        self.center = np.zeros(3)
        for row in self.coords:
            self.center += row
        self.center /= len(self.coords)
        self.dx = self.coords - self.center
        reach = np.sqrt((self.dx * self.dx).sum(axis=1))
        if self.radius is not None:
            reach = reach + self.radius
        self.molradius = float(reach.max())

    @property
    def natoms(self):
        return len(self.coords)

    @property
    def ntypes(self):
        """The largest type of the template (LAMMPS's ntypes)."""
        return int(self.types.max())

    def masses(self, type_mass):
        """Per-atom masses: Masses, else the mass per type (``type_mass[type_offset + t]`` taken by
        the caller: an array indexed by the template's types)."""
        if self.rmass is not None:
            return self.rmass
        values = np.asarray(type_mass, dtype=np.float64)[self.types]
        if not np.all(values > 0):
            raise ScriptError(f"molecule {self.id}: a type of its atoms has no mass (use the mass command, or give the "
                              "template a Masses section)")
        return values

    def mass_properties(self, type_mass):
        """(total mass, centre of mass (3,), inertia tensor about it as xx yy zz yz xz xy): the header's
        where it gives them (LAMMPS's compute_mass, compute_com, compute_inertia, summed atom by atom
        in their order, as LAMMPS sums)."""
        m = self.masses(type_mass)
        n = self.natoms
        total = self.header_mass
        if total is None:
            total = 0.0
            for i in range(n):
                total += m[i]
        if self.header_com is not None:
            com = self.header_com.copy()
        else:
            com = np.zeros(3)
            for i in range(n):
                com += self.coords[i] * m[i]
            com /= total
        if self.header_inertia is not None:
            return total, com, self.header_inertia.copy()
        d = self.coords - com
        tensor = np.zeros(6)
        for i in range(n):
            dx, dy, dz = d[i]
            tensor[0] += m[i] * (dy * dy + dz * dz)
            tensor[1] += m[i] * (dx * dx + dz * dz)
            tensor[2] += m[i] * (dx * dx + dy * dy)
            tensor[3] -= m[i] * dy * dz
            tensor[4] -= m[i] * dx * dz
            tensor[5] -= m[i] * dx * dy
        if self.radius is not None:
            for i in range(n):
                tensor[:3] += SPHERE_INERTIA * m[i] * self.radius[i] * self.radius[i]
        return total, com, tensor

    def summary(self):
        """LAMMPS's lines after reading a template."""
        types = self.ntypes
        lines = [f"Read molecule template {self.id}:", self.title, "  1 molecules", "  0 fragments", "  0 bodies",
                 f"  {self.natoms} atoms with max type {types}"]
        lines += [f"  0 {kind} with max type 0" for kind in ("bonds", "angles", "dihedrals", "impropers")]
        return "\n".join(lines)


def _number(word, what, where):
    try:
        value = float(word)
    except ValueError:
        raise ScriptError(f"{where}: {what} must be a number (got {word})") from None
    if not np.isfinite(value):
        raise ScriptError(f"{where}: {what} must be finite (got {word})")
    if abs(value) >= VALUE_LIMIT:
        raise ScriptError(f"{where}: {what} must lie within +-{VALUE_LIMIT:g} (got {word})")
    return value


def _whole(word, what, where, low):
    try:
        value = int(word)
    except ValueError:
        raise ScriptError(f"{where}: {what} must be a whole number (got {word})") from None
    if value < low:
        raise ScriptError(f"{where}: {what} must be >= {low} (got {value})")
    return value


def read_molecule_file(ident, path, label=None):
    """The template in the molecule file at ``path`` (its name in messages: ``label``)."""
    label = label or str(path)
    try:
        with open(path, encoding="utf-8", errors="replace") as handle:
            raw = handle.read().splitlines()
    except OSError as error:
        raise ScriptError(f"molecule {ident}: cannot read {label} ({error.strerror or error})") from None
    if not raw:
        raise ScriptError(f"{label}: empty molecule file")
    lines = [(number, line.split("#", 1)[0].split()) for number, line in enumerate(raw, start=1)]
    title = raw[0].rstrip()
    header, index = {}, 1
    while index < len(lines):
        number, words = lines[index]
        if not words:
            index += 1
            continue
        keyword = next((w for w in HEADER_WORDS if len(words) == HEADER_WORDS[w] + 1 and words[-1] == w), None)
        if keyword is None:
            break
        where = f"{label}:{number}"
        if keyword in header:
            raise ScriptError(f"{where}: header line '{keyword}' given twice")
        if keyword == "body":
            raise ScriptError(f"{where}: body: pdps has no body particles")
        if keyword in ("atoms", *TOPOLOGY_COUNTS):
            value = _whole(words[0], f"the number of {keyword}", where, 0)
            if keyword != "atoms" and value:
                raise ScriptError(f"{where}: {value} {keyword}: pdps's molecule templates carry no "
                                  f"{'fragments' if keyword == 'fragments' else 'bonds'}")
            header[keyword] = value
        else:
            header[keyword] = np.array([_number(w, keyword, where) for w in words[:-1]])
        index += 1
    natoms = header.get("atoms", 0)
    if natoms < 1:
        raise ScriptError(f"{label}: the header must give 'N atoms' with N >= 1")
    if natoms > len(lines):
        raise ScriptError(f"{label}: the header gives {natoms} atoms, more than the file's {len(lines)} lines can list")
    if "mass" in header and not header["mass"][0] > 0:
        raise ScriptError(f"{label}: mass must be > 0 (got {header['mass'][0]:g})")
    if "inertia" in header and not np.all(header["inertia"][:3] >= 0):
        raise ScriptError(f"{label}: the inertia's Ixx Iyy Izz must be >= 0 (got "
                          f"{' '.join(f'{v:g}' for v in header['inertia'][:3])})")
    sections = {}
    while index < len(lines):
        number, words = lines[index]
        if not words:
            index += 1
            continue
        name = " ".join(words)
        where = f"{label}:{number}"
        if name in REFUSED_SECTIONS:
            raise ScriptError(f"{where}: section {name}: {REFUSED_SECTIONS[name]}")
        if name not in SECTIONS:
            raise ScriptError(f"{where}: unknown section or header line '{raw[number - 1].strip()}' (sections: "
                              f"{', '.join(SECTIONS)})")
        if name in sections:
            raise ScriptError(f"{where}: section {name} given twice")
        width = SECTIONS[name]
        values = np.full((natoms, width), np.nan)
        seen = np.zeros(natoms, dtype=bool)
        numbers = np.zeros(natoms, dtype=np.int64)
        index += 1
        count = 0
        while count < natoms:
            if index >= len(lines):
                raise ScriptError(f"{label}: section {name} ends after {count} of {natoms} atoms")
            number, words = lines[index]
            index += 1
            if not words:
                continue
            where = f"{label}:{number}"
            if len(words) != width + 1:
                raise ScriptError(f"{where}: section {name} takes ID and {width} value(s) per line (got "
                                  f"{' '.join(words)})")
            atom = _whole(words[0], "the atom index", where, 1)
            if atom > natoms:
                raise ScriptError(f"{where}: atom index {atom} in section {name} is beyond the {natoms} atoms")
            if seen[atom - 1]:
                raise ScriptError(f"{where}: atom {atom} given twice in section {name}")
            seen[atom - 1] = True
            numbers[atom - 1] = number
            values[atom - 1] = [_number(w, name, where) for w in words[1:]]
            count += 1
        sections[name] = (values, numbers)
    if "Coords" not in sections:
        raise ScriptError(f"{label}: no Coords section (a template needs its atoms' coordinates)")
    if "Types" not in sections:
        raise ScriptError(f"{label}: no Types section (a template needs its atoms' types)")
    types, numbers = sections["Types"]
    bad = (types[:, 0] != np.round(types[:, 0])) | (types[:, 0] < 1)
    if bad.any():
        raise ScriptError(f"{label}:{numbers[bad][0]}: Types: each type must be a whole number >= 1")
    radius = rmass = None
    if "Diameters" in sections:
        diameters, numbers = sections["Diameters"]
        bad = diameters[:, 0] < 0
        if bad.any():
            raise ScriptError(f"{label}:{numbers[bad][0]}: Diameters: each diameter must be >= 0")
        radius = 0.5 * diameters[:, 0]
    if "Masses" in sections:
        masses, numbers = sections["Masses"]
        bad = ~(masses[:, 0] > 0)
        if bad.any():
            raise ScriptError(f"{label}:{numbers[bad][0]}: Masses: each mass must be > 0")
        rmass = masses[:, 0].copy()
    if "Molecules" in sections:
        ids, numbers = sections["Molecules"]
        if len(np.unique(ids)) > 1:
            raise ScriptError(f"{label}:{numbers[-1]}: Molecules: the template holds {len(np.unique(ids))} molecules; pdps's "
                              "templates are one molecule each")
    coords = sections["Coords"][0]
    return MoleculeTemplate(ident, title, coords, types[:, 0].astype(np.int64), radius, rmass,
                            float(header["mass"][0]) if "mass" in header else None, header.get("com"),
                            header.get("inertia"))
