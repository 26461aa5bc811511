"""Record what LAMMPS's change_box and replicate make of a few particles, the references
tests/test_change_box.py and tests/test_replicate.py compare pdps with.

    python benchmarks/lammps_references/box_commands.py [LMP]

CHANGE_BOX (run as it is by both programs): three particles in a box periodic in x and y, fixed in z,
under each line of OPERATIONS in turn (final and delta in lattice spacings and in box units, scale,
volume with one and two axes, set and remap of all and of a group, faces made periodic and
shrink-wrapped, a box moved several lengths from its particles); after each line the box's bounds
and the particles' positions are printed (tests/data/lammps/change_box.txt, one line per operation),
and at the end the data file is written (tests/data/lammps/change_box.data: image flags).
REPLICATE: a small lattice of molecular particles with image flags, molecule ids, two types and
velocities, replicated 2 x 3 x 1 in a box fixed in z; its data file is
tests/data/lammps/replicate.data.
"""

import sys
from pathlib import Path

from lammps_run import lammps_screen, marked_lines, run_lammps

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "lammps"
CHANGE_BOX_SETUP = """units lj
atom_style atomic
atom_modify map array
boundary p p f
lattice sc 2.0
region box block 0 4 0 4 0 4 units box
create_box 1 box
create_atoms 1 single 1 1 3.5 units box
create_atoms 1 single 3.9 1 1.5 units box
create_atoms 1 single 2 3.5 0.5 units box
mass 1 1
group low id 2 3
"""
OPERATIONS = [
    "change_box all x scale 1.5 remap",
    "change_box all x final 0 2 remap",
    "change_box low x final 0 2 y delta -0.5 0.5 remap units box",
    "change_box all x scale 1.1 z volume remap",
    "change_box all x scale 1.1 z volume y scale 1.1 z volume",
    "change_box all boundary p p p x delta 1 1 set remap",
    "change_box all y scale 0.5 set z scale 0.8 y volume remap",
    "change_box all boundary p s f remap",
    "change_box all y final -10 -6 boundary p p f",
]
PRINTED = ("xlo xhi ylo yhi zlo zhi " + " ".join(f"x[{i}] y[{i}] z[{i}]" for i in (1, 2, 3))).split()


def change_box_script():
    lines = [CHANGE_BOX_SETUP]
    for k, operation in enumerate(OPERATIONS):
        lines.append(f"{operation}\nprint \"@@ {k} {' '.join(f'$({name})' for name in PRINTED)}\"\n")
    return "".join(lines) + "write_data change_box.data\n"


REPLICATE = """units lj
atom_style molecular
atom_modify map array
boundary p p f
lattice sc 1.0
region box block 0 3 0 2 0 2
create_box 2 box
create_atoms 1 box
mass * 1.0
displace_atoms all random 0.1 0.1 0.0 4321 units box
set atom 1*5 mol 2
set atom 6*8 mol 7
set atom 3 image 1 0 0
set atom 4 image -2 1 0
set atom 9 type 2
velocity all create 1.0 8765 loop geom
replicate 2 3 1
write_data replicate.data
"""


def main(lmp):
    screen = lammps_screen(lmp, change_box_script().replace("write_data change_box.data\n", ""))
    (DATA / "change_box.txt").write_text("".join(line[3:] + "\n" for line in marked_lines(screen)))
    run_lammps(lmp, change_box_script(), outputs={"change_box.data": DATA / "change_box.data"})
    run_lammps(lmp, REPLICATE, outputs={"replicate.data": DATA / "replicate.data"})
    print((DATA / "change_box.txt").read_text())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
