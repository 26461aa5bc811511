"""Reading LAMMPS data files: the header, Masses, Atoms (atomic or sphere) and Velocities.

    Atoms # atomic:   id type x y z [ix iy iz]
    Atoms # sphere:   id type diameter density x y z [ix iy iz]
    Velocities:       id vx vy vz  (sphere: id vx vy vz wx wy wz; the angular part is ignored here)
"""

import re
from dataclasses import dataclass

import numpy as np

from ..errors import ScriptError

COLUMNS = {"atomic": 5, "sphere": 7}
SECTIONS = ("Masses", "Atoms", "Velocities")
IGNORED_COUNTS = ("bonds", "angles", "dihedrals", "impropers")


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


def read_data_file(path, particle_style):
    try:
        with open(path) as handle:
            lines = handle.read().splitlines()
    except OSError as exc:
        raise ScriptError(f"cannot read data file {path}: {exc.strerror}") from None
    name = path

    def fail(number, message):
        raise ScriptError(f"{name}:{number}: {message}")

    natoms, ntypes = None, None
    lo, hi = np.zeros(3), np.ones(3)
    masses, atoms, velocities = {}, [], {}
    section, i = None, 1          # line 1 is a title
    while i < len(lines):
        number = i + 1
        raw = lines[i]
        text = raw.split("#")[0].strip()
        i += 1
        if not text:
            continue
        words = text.split()
        head = words[0]
        if head[0].isalpha():
            # only section names start with a letter (LAMMPS's rule); Bonds, Pair Coeffs, ... are not read
            if head not in SECTIONS:
                fail(number, f"unsupported section {text} (sections read: {', '.join(SECTIONS)})")
            section = head
            hint = re.search(r"#\s*(\w+)", raw)
            if head == "Atoms" and hint and hint.group(1) != particle_style:
                fail(number, f"Atoms are '{hint.group(1)}' but particle_style is {particle_style}"
                             f" (set particle_style {hint.group(1)} before read_data)")
            continue
        if section is None:
            try:
                if text.endswith("atoms"):
                    natoms = int(words[0])
                elif text.endswith("atom types"):
                    ntypes = int(words[0])
                elif len(words) == 4 and words[2][1:] == "lo" and words[3][1:] == "hi":
                    d = "xyz".index(words[2][0])
                    lo[d], hi[d] = float(words[0]), float(words[1])
                elif any(text.endswith(k) for k in IGNORED_COUNTS) or text.endswith("types"):
                    if int(words[0]) != 0 and not text.endswith("atom types"):
                        fail(number, f"molecular data is not supported: {text}")
                elif len(words) == 6 and words[3:] == ["xy", "xz", "yz"]:
                    fail(number, "triclinic boxes are not supported")
                else:
                    fail(number, f"unrecognised header line: {text}")
            except ValueError:
                fail(number, f"cannot read header line: {text}")
            continue
        try:
            if section == "Masses":
                masses[int(words[0])] = (number, float(words[1]))
            elif section == "Atoms":
                width = COLUMNS[particle_style]
                if len(words) not in (width, width + 3):
                    fail(number, f"expected {width} or {width + 3} values per {particle_style} atom "
                                 f"(got {len(words)})")
                atoms.append((number, words))
            elif section == "Velocities":
                if len(words) < 4:
                    fail(number, f"expected id vx vy vz (got {len(words)} values)")
                velocities[int(words[0])] = (number, [float(w) for w in words[1:4]])
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
    n = len(atoms)
    tags = np.zeros(n, dtype=np.int64)
    types = np.zeros(n, dtype=np.int32)
    x = np.zeros((n, 3))
    images = np.zeros((n, 3), dtype=np.int32)
    diameter = np.ones(n)
    density = np.ones(n)
    seen = {}
    for k, (number, words) in enumerate(atoms):
        try:
            tags[k], types[k] = int(words[0]), int(words[1])
            if particle_style == "sphere":
                diameter[k], density[k] = float(words[2]), float(words[3])
                coords = words[4:7]
            else:
                coords = words[2:5]
            x[k] = [float(w) for w in coords]
            if len(words) == COLUMNS[particle_style] + 3:
                images[k] = [int(w) for w in words[-3:]]
        except ValueError:
            fail(number, f"cannot read Atoms line: {' '.join(words)}")
        if not np.isfinite(x[k]).all():
            fail(number, f"non-finite position: {' '.join(words)}")
        if not 1 <= types[k] <= ntypes:
            fail(number, f"atom type {types[k]} is out of range 1..{ntypes}")
        if diameter[k] <= 0 or density[k] <= 0:
            fail(number, f"diameter and density must be > 0: {' '.join(words)}")
        if tags[k] in seen:
            fail(number, f"atom id {tags[k]} appears twice in Atoms (first on line {seen[tags[k]]})")
        seen[tags[k]] = number
    v = None
    if velocities:
        v = np.zeros((n, 3))
        index = {int(t): k for k, t in enumerate(tags)}
        for tag, (number, value) in velocities.items():
            if tag not in index:
                fail(number, f"Velocities name atom {tag}, which is not in Atoms")
            v[index[tag]] = value
    return DataFile(lo, hi, ntypes, masses, tags, types, x, images, diameter, density, v)
