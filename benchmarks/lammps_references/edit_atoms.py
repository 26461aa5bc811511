"""Record what LAMMPS's set, delete_atoms, displace_atoms and write_data make of a lattice, the reference
tests/test_edit_atoms.py compares pdps with.

    python benchmarks/lammps_references/edit_atoms.py [LMP]

The script (SCRIPT below, run as it is by both programs) changes types at random (set type/fraction,
LAMMPS's Park-Miller numbers), deletes a sphere of particles and the overlaps a displacement makes,
moves, ramps and rotates particles across periodic faces, then writes the data file; LAMMPS's is
stored as tests/data/lammps/edit_atoms.data.
"""

import sys
from pathlib import Path

from pdps_core.testing import lj_fcc

from lammps_run import run_lammps

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "lammps" / "edit_atoms.data"
SCRIPT = lj_fcc(4, 2) + """mass * 1.0
set type 1 type/fraction 2 0.3 4567
region ball sphere 2 2 2 0.8
delete_atoms region ball compress yes
group two type 2
displace_atoms two move 0.15 0 0
displace_atoms all ramp x 0 0.5 z 0 4
displace_atoms all rotate 3 3 3 0 0 1 30 units box
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
delete_atoms overlap 0.6 all all
write_data out.data
"""


def main(lmp):
    print(run_lammps(lmp, SCRIPT, outputs={"out.data": OUT})[-1500:])


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
