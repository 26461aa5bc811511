"""Record what LAMMPS's create_atoms random and displace_atoms random make, the reference
tests/test_random_atoms.py compares pdps with (ids, types, positions and image flags of the data file
each script writes, and the lines LAMMPS prints about them).

    python benchmarks/lammps_references/random_atoms.py [LMP]

Each script of SCRIPTS, run as it is by both programs, ends with ``write_data out.data``. The
scenes: three seeds in a sphere region and one in the whole box (region NULL); a block region and
the whole box with ``overlap`` (the second command's particles kept off the first's); more
particles than fit, so that ``maxtry`` runs out and LAMMPS warns ``Only inserted M particles out of
N``; a 2-d disk cut by a fixed face, then the whole box, with an overlap across the periodic one, then
displaced at random along x (across the periodic face; y is fixed);
regions with INF sides (a block, a cylinder, their union and intersection: tries narrowed to their
finite sides) and an outside one (tried in the whole box);
and displace_atoms random on an fcc lattice, in lattice units and in box units, far enough to cross
periodic faces.
For each NAME, LAMMPS's data file goes to tests/data/lammps/random_atoms/NAME.data and its
``Created ...`` and ``WARNING: Only inserted ...`` lines (without the source location) to
NAME.messages.
"""

import re
import sys
from pathlib import Path

from pdps_core.testing import lj_fcc

from lammps_run import run_lammps

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "lammps" / "random_atoms"

SCRIPTS = {
    "sphere_seeds": """units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 5 0 5 0 5
create_box 3 box
region ball sphere 2.5 2.5 2.5 2.0
create_atoms 1 random 300 1 ball
create_atoms 2 random 300 12345 ball
create_atoms 3 random 300 987654321 ball
create_atoms 1 random 50 4242 NULL
mass * 1.0
write_data out.data
""",
    "block_overlap": """units lj
atom_style atomic
region box block 0 10 0 10 0 10 units box
create_box 2 box
region slab block 1 9 2 8 0 10 units box
create_atoms 1 random 150 5555 slab overlap 0.9 units box
create_atoms 2 random 100 6666 NULL overlap 0.9
mass * 1.0
write_data out.data
""",
    "maxtry": """units lj
atom_style atomic
region box block 0 5 0 5 0 5 units box
create_box 1 box
create_atoms 1 random 500 31415 NULL overlap 1.0 maxtry 50 units box
create_atoms 1 random 20 2718 NULL overlap 1.0
mass * 1.0
write_data out.data
""",
    "disk_2d": """units lj
dimension 2
atom_style atomic
boundary p f p
lattice sq 0.8
region box block 0 10 0 10 -0.5 0.5
create_box 1 box
region disk cylinder z 3 8 4 -0.5 0.5
create_atoms 1 random 120 2024 disk overlap 0.8
create_atoms 1 random 40 77 NULL overlap 0.8
mass * 1.0
displace_atoms all random 0.3 0 0 555
write_data out.data
""",
    "unbounded": """units lj
atom_style atomic
region box block 0 10 0 8 0 6 units box
create_box 2 box
region slab block INF INF 2 5 INF INF units box
create_atoms 1 random 100 1111 slab
region rod cylinder z 5 4 1.5 INF INF units box
region both union 2 slab rod
create_atoms 2 random 100 2222 both overlap 0.4 units box
region corner intersect 2 slab rod
create_atoms 1 random 30 3333 corner
region hole sphere 5 4 3 3 side out units box
create_atoms 2 random 30 4444 hole
mass * 1.0
write_data out.data
""",
    "displace": lj_fcc(4, 2) + """mass * 1.0
displace_atoms all random 0.3 0.3 0.3 98765
region half block 0 2 INF INF INF INF
group half region half
set group half type 2
displace_atoms half random 2.5 0.2 4.0 4321 units box
displace_atoms all random 0.05 0.05 0.05 2147483647 units box
write_data out.data
""",
}


def messages(log):
    """The lines LAMMPS prints about created particles and the tries that ran out."""
    kept = []
    for line in log.splitlines():
        if re.match(r"Created \d+ atoms", line) or line.startswith("WARNING: Only inserted"):
            kept.append(re.sub(r" \(src/[^)]*\)$", "", line.rstrip()))
    return kept


def main(lmp):
    OUT.mkdir(parents=True, exist_ok=True)
    for name, script in SCRIPTS.items():
        log = run_lammps(lmp, script, label=name, outputs={"out.data": OUT / f"{name}.data"})
        (OUT / f"{name}.messages").write_text("\n".join(messages(log)) + "\n")
        print(name, *messages(log), sep="\n  ")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
