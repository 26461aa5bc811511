"""Record what LAMMPS makes of molecule ids: an LJ liquid of four-particle molecules, with the pairs
inside every molecule, and between the molecules of one group, left out of the neighbor list; the
reference tests/test_molecules.py compares pdps with.

    python benchmarks/lammps_references/molecules.py [LMP]

The script (SCRIPT, run as it is by both programs) numbers molecules with ``set mol`` from an
atom-style variable, selects with ``group molecule``, deletes whole molecules (``delete_atoms ... mol
yes``), excludes ``molecule/intra`` and ``molecule/inter`` pairs and runs 100 deterministic NVE
steps. LAMMPS's thermo table goes to tests/data/lammps/molecules.txt and its data file to
tests/data/lammps/molecules.data.
"""

import sys
from pathlib import Path

from pdps_core.testing import lj_fcc

from lammps_run import run_lammps

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "lammps"
SCRIPT = lj_fcc(4, 2, atom_style="molecular") + """mass * 1.0
variable m atom floor((id-1)/4)+1
set group all mol v_m
group low molecule <= 20
set group low type 2
region ball sphere 2 2 2 0.6
delete_atoms region ball mol yes compress no
velocity all create 1.44 87287 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
neigh_modify exclude molecule/intra all exclude molecule/inter low
fix 1 all nve
variable m100 equal mol[100]
thermo_style custom step atoms temp epair etotal press v_m100
thermo_modify format float %20.15g
thermo 10
run 100
write_data out.data nocoeff
"""


def main(lmp):
    lines = run_lammps(lmp, SCRIPT, outputs={"out.data": OUT / "molecules.data"}).splitlines()
    start = next(k for k, line in enumerate(lines) if line.split()[:1] == ["Step"])
    end = next(k for k in range(start, len(lines)) if lines[k].startswith("Loop time"))
    (OUT / "molecules.txt").write_text("\n".join(lines[start:end]) + "\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
