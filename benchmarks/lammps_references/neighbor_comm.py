"""Record what LAMMPS prints for neigh_modify exclude (type, group, none), newton off, comm_modify
cutoff and the neighbor list schedule, the reference tests/test_neighbor_comm_lammps.py compares pdps
with to the printed digits.

    python benchmarks/lammps_references/neighbor_comm.py [LMP]

One two-type LJ liquid (BASE: an fcc lattice with 40 % of type 2 by set type/fraction, velocity
create) run 100 NVE steps under each of CASES; thermo step temp pe press every 20 steps with 15 digits
into tests/data/lammps/neighbor_comm.txt, one block per case.
"""

import sys
from pathlib import Path

from pdps_core.testing import lj_fcc

sys.path.insert(0, str(Path(__file__).parent))
from lammps_run import run_lammps, thermo_lines, write_blocks  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "lammps" / "neighbor_comm.txt"
BASE = lj_fcc(4, 2) + """mass * 1.0
set type 1 type/fraction 2 0.4 2468
group ones type 1
group twos type 2
velocity all create 1.2 7531 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
pair_coeff 1 2 0.8 1.1
fix 1 all nve
"""
CASES = {
    "exclude_type": "neigh_modify exclude type 1 2",
    "exclude_group": "neigh_modify exclude group ones twos exclude type 2 2",
    "newton_comm": "newton off on\ncomm_modify cutoff 4.0\nneigh_modify every 2 delay 4 check no one 500",
    "exclude_none": "neigh_modify exclude type 1 1 exclude none",
}
THERMO = "thermo_style custom step temp pe press\nthermo_modify format float %20.15g\nthermo 20\nrun 100\n"


def script(case):
    return BASE + CASES[case] + "\n" + THERMO


def main(lmp):
    write_blocks(OUT, {case: thermo_lines(run_lammps(lmp, script(case), label=case)) for case in CASES})


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
