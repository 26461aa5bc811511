"""Record what LAMMPS prints for compute msd (com, average), coord/atom (type ranges, through compute
reduce), erotate/sphere and fix enforce2d, the reference tests/test_analysis_computes_lammps.py
compares pdps with to the printed digits.

    python benchmarks/lammps_references/analysis_computes.py [LMP]

Three deterministic scenes (SCRIPTS, run as they are by both programs): a two-type LJ liquid with
four msd computes (plain, com yes on a drifting group, average yes, both); a 2-d LJ liquid under fix
enforce2d with coord/atom and msd com yes; spheres on a compressed lattice with gran/hooke (tangential
damping on, so they spin) read by erotate/sphere and a coord/atom of one type range. 100 steps each,
thermo every 10 or 20 steps with 15 digits, into tests/data/lammps/analysis_computes.txt.
"""

import sys
from pathlib import Path

from pdps_core.testing import lj_fcc

sys.path.insert(0, str(Path(__file__).parent))
from lammps_run import run_lammps, thermo_lines, write_blocks  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "lammps" / "analysis_computes.txt"
SCRIPTS = {
    "msd": lj_fcc(4, 2) + """mass 1 1.0
mass 2 3.0
set type 1 type/fraction 2 0.3 4567
group heavy type 2
velocity all create 1.44 87287 loop geom
velocity heavy set 0.5 0.2 0.0 sum yes
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
fix 1 all nve
compute m all msd
compute mc heavy msd com yes
compute ma all msd average yes
compute mca heavy msd com yes average yes
thermo_style custom step temp c_m[1] c_m[4] c_mc[2] c_mc[4] c_ma[3] c_ma[4] c_mca[4]
thermo_modify format float %20.15g
thermo 10
run 100
""",
    "enforce2d": """units lj
dimension 2
atom_style atomic
lattice sq2 0.8
region box block 0 6 0 6 -0.5 0.5
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.0 4321 loop geom
pair_style lj/cut 2.4
pair_coeff 1 1 1.0 1.0
fix 1 all nve
fix 2 all enforce2d
compute c all coord/atom cutoff 1.3
compute cs all reduce sum c_c
compute m all msd com yes
thermo_style custom step temp pe press c_cs c_m[4]
thermo_modify format float %20.15g
thermo 20
run 100
""",
    "spheres": """units lj
atom_style sphere
lattice sc 0.97
region box block 0 5 0 5 0 5
create_box 2 box
create_atoms 1 box
set type 1 type/fraction 2 0.5 9876
set type 2 density 2.0
velocity all create 1.0 5511 loop geom
comm_modify vel yes
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
fix 1 all nve/sphere
compute rot all erotate/sphere
compute c2 all coord/atom cutoff 1.0 2
compute cs all reduce sum c_c2
timestep 0.001
thermo_style custom step ke c_rot c_cs press
thermo_modify format float %20.15g
thermo 20
run 100
""",
}


def main(lmp):
    write_blocks(OUT, {name: thermo_lines(run_lammps(lmp, text, label=name)) for name, text in SCRIPTS.items()})


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
