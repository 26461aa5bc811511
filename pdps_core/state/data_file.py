"""Reading LAMMPS data files: the header, Masses, Atoms and Velocities.

    Atoms # atomic:     id type x y z [ix iy iz]
    Atoms # sphere:     id type diameter density x y z [ix iy iz]
    Atoms # charge:     id type q x y z [ix iy iz]
    Atoms # molecular:  id molecule type x y z [ix iy iz]   (bond and angle alike)
    Atoms # full:       id molecule type q x y z [ix iy iz]
    Atoms # hybrid:     id type x y z, then each sub-style's other columns [ix iy iz]
                        (hybrid sphere molecular: id type x y z diameter density molecule)
    Velocities:         id vx vy vz  (sphere, hybrid with sphere: id vx vy vz wx wy wz, the angular
                        velocity; id vx vy vz alone leaves it 0)
    Pair Coeffs:        I coefficients...      (as pair_coeff I I ..., needs a pair_style first)
    PairIJ Coeffs:      I J coefficients...    (as pair_coeff I J ...)

    Bonds:              id type atom1 atom2    (each stored on atom1, as LAMMPS with newton_bond on)
    Bond Coeffs:        N coefficients...      (as bond_coeff N ..., needs a bond_style first)

For the styles with molecule ids, the header's bonds, bond types and extra bond per atom are read;
its angle, dihedral and improper counts and types and the sections that list them are read past:
pdps has no angle styles. ``DataFile.skipped`` says how many of each were, so that read_data can warn.
"""

import re
from dataclasses import dataclass, field

import numpy as np

from ..errors import ScriptError
from . import limits
from .particles import style_columns, substyles
from ..script.lexer import read_text

SECTIONS = ("Masses", "Atoms", "Velocities")
# pair coefficients, applied by read_data as pair_coeff lines (I I ... or I J ...)
PAIR_SECTIONS = ("Pair Coeffs", "PairIJ Coeffs")
TOPOLOGY = ("bonds", "angles", "dihedrals", "impropers")
# sections of the topology pdps reads past (with a molecular style)
SKIPPED_SECTIONS = ("Angles", "Dihedrals", "Impropers", "Angle Coeffs", "Dihedral Coeffs", "Improper Coeffs")
BOND_SECTIONS = ("Bonds", "Bond Coeffs")


@dataclass
class DataFile:
    lo: np.ndarray
    hi: np.ndarray
    ntypes: int
    masses: dict
    tags: np.ndarray
    types: np.ndarray
    x: np.ndarray
    images: np.ndarray
    diameter: np.ndarray
    density: np.ndarray
    velocities: np.ndarray | None
    per_atom: dict = field(default_factory=dict)       # molecule, q: what the style's columns add
    skipped: dict = field(default_factory=dict)        # "bonds": 12, ...: topology read past
    pair_coeffs: list = field(default_factory=list)    # (line number, [I, J, coefficient words...])
    angular_velocities: np.ndarray = None               # spheres' wx wy wz from Velocities
    nbondtypes: int = 0
    extra_bonds: int = 0                                # extra bond per atom: room for bonds made later
    bonds: np.ndarray = None                            # (nbonds, 3) int64: type, atom1, atom2
    bond_coeffs: list = field(default_factory=list)     # (line number, [N, coefficient words...])
    fix_sections: dict = field(default_factory=dict)    # read_data fix ID NULL SECTION: {SECTION: [(line, words)]}


def read_data_file(path, particle_style, fix_sections=()):
    """The data file's contents; ``fix_sections``: names of sections a fix reads (read_data's fix
    keyword), kept as (line number, words) for it."""
    lines = read_text(path, "data file").splitlines()
    name = path

    def fail(number, message):
        raise ScriptError(f"{name}:{number}: {message}")

    natoms, ntypes = None, None
    lo, hi = np.zeros(3), np.ones(3)
    masses, atoms, velocities, skipped, pair_coeffs, kept = {}, [], {}, {}, [], {}
    nbonds, nbondtypes, extra_bonds, bond_lines, bond_coeffs = 0, 0, 0, [], []
    columns = style_columns(particle_style)
    spheres = "sphere" in substyles(particle_style)
    molecular = "molecule" in columns
    section, i = None, 1          # line 1 is a title
    velocities_at, velocity_rows = None, 0
    while i < len(lines):
        number = i + 1
        raw = lines[i]
        text = raw.split("#")[0].strip()
        i += 1
        if not text:
            continue
        words = text.split()
        text = " ".join(words)          # tabs and repeated spaces separate words alike
        head = words[0]
        if head[0].isalpha():
            # only section names start with a letter (LAMMPS's rule)
            two = " ".join(words[:2])
            if two in PAIR_SECTIONS:
                section = two
                continue
            if head == "Bonds" or two == "Bond Coeffs":
                if not molecular:
                    fail(number, f"section {text} needs a particle_style with molecule ids (molecular, bond, "
                                 f"angle or full), not {particle_style}")
                section = "Bonds" if head == "Bonds" else two
                continue
            if text in fix_sections:
                section = text
                kept.setdefault(text, [])
                continue
            if head in SKIPPED_SECTIONS or two in SKIPPED_SECTIONS:
                if not molecular:
                    fail(number, f"section {text} needs a particle_style with molecule ids (molecular, bond, "
                                 f"angle or full), not {particle_style}")
                section = "skipped"
                continue
            if head not in SECTIONS:
                fail(number, f"unsupported section {text} (sections read: {', '.join(SECTIONS)})")
            section = head
            if head == "Velocities":
                velocities_at = number
            hint = re.search(r"#\s*(\w+)", raw)
            if head == "Atoms" and hint and hint.group(1) != particle_style.split()[0]:
                fail(number, f"Atoms are '{hint.group(1)}' but particle_style is {particle_style}"
                             f" (set particle_style {hint.group(1)} before read_data)")
            continue
        if section == "skipped":
            continue
        if section in kept:
            kept[section].append((number, words))
            continue
        # Python's int() and float() take other scripts' digits (U+FF11) and 1_000; a data file's
        # numbers are ASCII, as LAMMPS reads them ("Expected floating point parameter")
        odd = next((w for w in words if not w.isascii() or "_" in w), None)
        if odd is not None:
            fail(number, f"{odd} is not a number written in ASCII digits: {text}")
        if section is None:
            try:
                if text.endswith("atoms"):
                    natoms = int(words[0])
                    if not 0 <= natoms <= limits.MAX_TAG:
                        fail(number, f"number of atoms must be from 0 to {limits.MAX_TAG} (got {words[0]})")
                elif text.endswith("atom types"):
                    ntypes = int(words[0])
                    if not 1 <= ntypes <= limits.MAX_TYPES:
                        fail(number, f"number of atom types must be from 1 to {limits.MAX_TYPES} (got {words[0]})")
                elif len(words) == 4 and words[2][1:] == "lo" and words[3][1:] == "hi":
                    d = "xyz".index(words[2][0])
                    lo[d], hi[d] = float(words[0]), float(words[1])
                elif molecular and len(words) > 2 and words[1] == "extra" and text.endswith("per atom"):
                    amount = int(words[0])
                    if not 0 <= amount <= 64:
                        fail(number, f"extra per atom must be from 0 to 64 (got {words[0]})")
                    if text == f"{words[0]} extra bond per atom":
                        extra_bonds = amount
                elif text.endswith(("bonds", "bond types")) and molecular:
                    amount = int(words[0])
                    if not 0 <= amount <= (limits.MAX_TAG if text.endswith("bonds") else limits.MAX_TYPES):
                        fail(number, f"a count must be >= 0 and in range: {text}")
                    if text.endswith("bonds"):
                        nbonds = amount
                    else:
                        nbondtypes = amount
                elif any(text.endswith(k) for k in TOPOLOGY) or text.endswith("types"):
                    amount = int(words[0])
                    if amount != 0 and not molecular:
                        fail(number, f"{text} need a particle_style with molecule ids (molecular, bond, "
                                     f"angle or full), not {particle_style}")
                    if amount < 0:
                        fail(number, f"a count must be >= 0: {text}")
                    if text.endswith(TOPOLOGY) and amount:
                        skipped[words[-1]] = amount
                elif len(words) == 6 and words[3:] == ["xy", "xz", "yz"]:
                    fail(number, "triclinic boxes are not supported")
                else:
                    fail(number, f"unrecognised header line: {text}")
            except ValueError:
                fail(number, f"cannot read header line: {text}")
            continue
        try:
            if section == "Masses":
                mass = float(words[1])
                if not (np.isfinite(mass) and mass > 0):
                    fail(number, f"mass must be a finite number > 0 (got {words[1]})")
                masses[int(words[0])] = (number, mass)
            elif section == "Atoms":
                width = len(columns)
                if len(words) not in (width, width + 3):
                    fail(number, f"expected {width} or {width + 3} values per {particle_style} atom "
                                 f"(got {len(words)})")
                atoms.append(number)        # its words are split again below, one line at a time
            elif section == "Bonds":
                if len(words) != 4:
                    fail(number, f"expected id type atom1 atom2 in Bonds (got {text})")
                values = [int(w) for w in words]
                # a bond turned off (delete_bonds) is written with its type negative
                if not 1 <= abs(values[1]) <= nbondtypes:
                    fail(number, f"bond type {words[1]} is out of range 1..{nbondtypes}")
                if values[2] == values[3]:
                    fail(number, f"a bond joins two particles, not atom {words[2]} to itself")
                bond_lines.append((number, values))
            elif section == "Bond Coeffs":
                if not words[0].isdigit() or not 1 <= int(words[0]) <= nbondtypes:
                    fail(number, f"bond type {words[0]} is out of range 1..{nbondtypes} in Bond Coeffs")
                bond_coeffs.append((number, words))
            elif section in PAIR_SECTIONS:
                width = 1 if section == "Pair Coeffs" else 2
                if len(words) < width or not all(w.isdigit() for w in words[:width]):
                    fail(number, f"expected {'I' if width == 1 else 'I J'} and coefficients in {section} "
                                 f"(got {text})")
                pair_coeffs.append((number, words[:1] * 2 + words[1:] if width == 1 else words))
            elif section == "Velocities":
                velocity_rows += 1
                if len(words) < 4:
                    fail(number, f"expected id vx vy vz (got {len(words)} values)")
                tag = int(words[0])
                # spheres' lines go on with their angular velocity, as LAMMPS writes them
                value = [float(w) for w in words[1:7 if spheres and len(words) >= 7 else 4]]
                value += [0.0] * (6 - len(value))
                if not np.isfinite(value).all():
                    fail(number, f"non-finite velocity: {text}")
                if tag in velocities:
                    fail(number, f"Velocities: atom {tag} appears twice (first on line {velocities[tag][0]})")
                velocities[tag] = (number, value)
        except (ValueError, IndexError):
            fail(number, f"cannot read {section} line: {text}")
    if natoms is None or ntypes is None:
        fail(1, "header must give the number of atoms and of atom types")
    for t, (number, _) in masses.items():
        if not 1 <= t <= ntypes:
            fail(number, f"Masses: type {t} is out of range 1..{ntypes}")
    masses = {t: value for t, (_, value) in masses.items()}
    if len(atoms) != natoms:
        fail(len(lines), f"header says {natoms} atoms but the Atoms section has {len(atoms)}")
    if velocities_at is not None and velocity_rows != natoms:
        # LAMMPS reads one Velocities row per atom of the header, and refuses a section with fewer
        fail(velocities_at, f"header says {natoms} atoms but the Velocities section has {velocity_rows}")
    n = len(atoms)
    tags = np.zeros(n, dtype=np.int64)
    types = np.zeros(n, dtype=np.int32)
    x = np.zeros((n, 3))
    images = np.zeros((n, 3), dtype=np.int32)
    diameter = np.ones(n)
    density = np.ones(n)
    molecule = np.zeros(n, dtype=np.int64)
    charge = np.zeros(n)
    seen = {}
    at = {name: k for k, name in enumerate(columns)}
    for k, number in enumerate(atoms):
        words = lines[number - 1].split("#")[0].split()
        try:
            tag, kind = int(words[at["id"]]), int(words[at["type"]])
            if "diameter" in at:
                diameter[k], density[k] = float(words[at["diameter"]]), float(words[at["density"]])
            if "molecule" in at:
                mol = int(words[at["molecule"]])
                if not 0 <= mol <= limits.MAX_TAG:
                    fail(number, f"molecule id must be from 0 to {limits.MAX_TAG} (got {words[at['molecule']]})")
                molecule[k] = mol
            if "q" in at:
                charge[k] = float(words[at["q"]])
            x[k] = [float(words[at[axis]]) for axis in "xyz"]
            image = [int(w) for w in words[-3:]] if len(words) == len(columns) + 3 else [0, 0, 0]
        except ValueError:
            fail(number, f"cannot read Atoms line: {' '.join(words)}")
        if not np.isfinite(charge[k]):
            fail(number, f"charge must be finite (got {words[at['q']]})")
        if not 1 <= tag <= limits.MAX_TAG:
            fail(number, f"atom id must be from 1 to {limits.MAX_TAG} (got {words[0]})")
        if not 1 <= kind <= ntypes:
            fail(number, f"atom type {words[at['type']]} is out of range 1..{ntypes}")
        if any(abs(m) > limits.MAX_IMAGE for m in image):
            fail(number, f"image flags must fit in 32 bits (got {' '.join(words[-3:])})")
        tags[k], types[k], images[k] = tag, kind, image
        if not np.isfinite(x[k]).all() or np.abs(x[k]).max() > limits.MAX_COORDINATE:
            fail(number, f"position must be finite and within +-{limits.MAX_COORDINATE:g}: {' '.join(words)}")
        if not (limits.MIN_SIZE <= diameter[k] <= limits.MAX_SIZE and limits.MIN_SIZE <= density[k] <= limits.MAX_SIZE):
            fail(number, f"diameter and density must be from {limits.MIN_SIZE:g} to {limits.MAX_SIZE:g}: {' '.join(words)}")
        if tags[k] in seen:
            fail(number, f"atom id {tags[k]} appears twice in Atoms (first on line {seen[tags[k]]})")
        seen[tags[k]] = number
    v = omega = None
    if velocities:
        v, omega = np.zeros((n, 3)), np.zeros((n, 3))
        index = {int(t): k for k, t in enumerate(tags)}
        for tag, (number, value) in velocities.items():
            if tag not in index:
                fail(number, f"Velocities name atom {tag}, which is not in Atoms")
            v[index[tag]], omega[index[tag]] = value[:3], value[3:]
        if not spheres:
            omega = None
    try:
        limits.check_box(lo, hi, "box")
    except ScriptError as exc:
        fail(1, str(exc))
    length = hi - lo
    for d, axis in enumerate("xyz"):
        # positions a periodic box wraps must leave image flags that fit in 32 bits
        turns = np.floor((x[:, d] - lo[d]) / length[d]) + images[:, d]
        if n and np.abs(turns).max() > limits.MAX_IMAGE:
            k = int(np.argmax(np.abs(turns)))
            fail(atoms[k], f"{axis} = {x[k, d]:g} is {abs(turns[k]):.3g} box lengths away: its image "
                              "flag would not fit in 32 bits")
    per_atom = {name: values for name, values in (("molecule", molecule), ("q", charge)) if name in at}
    for number, words in pair_coeffs:
        if not all(1 <= int(w) <= ntypes for w in words[:2]):
            fail(number, f"pair coefficients for types {words[0]} {words[1]} out of range 1..{ntypes}")
    if len(bond_lines) != nbonds:
        fail(len(lines), f"header says {nbonds} bonds but the Bonds section has {len(bond_lines)}")
    bonds = np.zeros((len(bond_lines), 3), dtype=np.int64)
    for k, (number, values) in enumerate(bond_lines):
        for atom in values[2:]:
            if atom not in seen:
                fail(number, f"Bonds name atom {atom}, which is not in Atoms")
        bonds[k] = values[1:]
    return DataFile(lo, hi, ntypes, masses, tags, types, x, images, diameter, density, v, per_atom, skipped,
                    pair_coeffs, omega, nbondtypes, extra_bonds, bonds if nbonds or nbondtypes or extra_bonds else None,
                    bond_coeffs, kept)
