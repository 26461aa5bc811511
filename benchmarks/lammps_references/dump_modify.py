"""Record the text dumps LAMMPS writes with dump_modify, the reference tests/test_dump_modify_lammps.py
compares pdps's dumps with, line by line.

    python benchmarks/lammps_references/dump_modify.py [LMP]

The script (SCRIPT, run as it is by both programs) runs 80 deterministic NVE steps of an LJ crystal
(LAMMPS's numbers for set type/fraction and velocity loop geom; neighbor lists built every step, so
LAMMPS's positions are in the box whenever it dumps, as pdps's) with custom dumps: ``sort id`` and
``format float``; ``every`` (replacing the dump's interval) and ``first yes`` with ``format line``;
``sort -N`` (descending by a column) with ``format N`` and ``format int``; in the second run a dump
that appends to the third one's file (``append yes``, ``sort N``) and one defined between the runs
with ``first yes`` (a frame at the step it is defined on, off its interval). The four files LAMMPS
writes go to tests/data/lammps/dump_modify/.
"""

import sys
from pathlib import Path

from pdps_core.testing import lj_fcc

from lammps_run import run_lammps

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "lammps" / "dump_modify"
FILES = ("dump.sorted", "dump.every", "dump.desc", "dump.late")
SCRIPT = lj_fcc(3, 2) + """mass * 1.0
set type 1 type/fraction 2 0.3 12345
velocity all create 1.0 87287 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
neighbor 0.3 bin
neigh_modify every 1 delay 0 check no
fix 1 all nve
dump sorted all custom 10 dump.sorted id type x y z vx vy vz ix iy iz
dump_modify sorted sort id format float %12.6f
dump every all custom 25 dump.every id type xs ys zs
dump_modify every sort id every 20 first yes format line "%d %d %10.4f %10.4f %10.4f"
dump desc all custom 10 dump.desc id type vx
dump_modify desc sort -3 format 3 %15.8e format int %5d
thermo 10
run 50
undump desc
dump again all custom 15 dump.desc id type vz
dump_modify again append yes sort 3 format float %.5f
dump late all custom 20 dump.late id type x
dump_modify late first yes sort id format float %8.3f
run 30
"""


def main(lmp):
    OUT.mkdir(parents=True, exist_ok=True)
    run_lammps(lmp, SCRIPT, outputs={name: OUT / name for name in FILES})


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
