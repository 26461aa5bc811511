"""Record what LAMMPS does with granular clumps under fix rigid/small and rigid/nve/small: the reference
plugins/fix_rigid/tests/test_rigid_small_clumps.py compares pdps with.

    python benchmarks/lammps_references/rigid_small_clumps.py [LMP]

The scene: two clumps of overlapping spheres (atom_style hybrid sphere molecular, one body per molecule:
a resting dimer and a spinning, falling triangle of two sizes, its spin given in the data file's
Velocities) under gravity between wall/gran planes, touching through pair gran/hooke/history.
LAMMPS's contacts take each clump's mass for their effective mass (mass_rigid), and its spheres of one
body touch one another too (internal contacts slow a spinning clump): the same run in pdps must do both.
Thermo without a temperature: LAMMPS stops on clumps of spheres when anything asks its compute temp
("degrees of freedom < 0"), and so does pdps. Positions, velocities and angular velocities of every
sphere every 500 steps over 3000 steps of
dt = 0.001, into plugins/fix_rigid/tests/data/rigid_small_clumps.txt (one block per style).
"""

import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from lammps_run import run_lammps_file  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "plugins" / "fix_rigid" / "tests" / "data" / "rigid_small_clumps.txt"
STYLES = ("rigid/small", "rigid/nve/small")
# the data file (spins in its Velocities); the fuzz suite's clumps seed reads it too
DATA = (ROOT / "plugins" / "fix_rigid" / "tests" / "data" / "clumps.data").read_text()
SCRIPT = """atom_style hybrid sphere molecular
boundary p p f
comm_modify vel yes
read_data clumps.data
pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1
pair_coeff * *
fix w all wall/gran hooke/history 2000 NULL 50 NULL 0.5 1 zplane 0 4
fix g all gravity 1.0 vector 0 0 -1
fix 1 all {style} molecule
timestep 0.001
thermo_style custom step atoms pe
thermo 500
dump 1 all custom 500 clumps.dump id x y z vx vy vz omegax omegay omegaz
dump_modify 1 sort id format float %.17g
run 3000
"""


def frames(text):
    """Rows (step id x y z vx vy vz omegax omegay omegaz) of every frame of a dump."""
    rows = []
    for frame in text.split("ITEM: TIMESTEP")[1:]:
        lines = frame.strip().splitlines()
        rows += [f"{lines[0].strip()} {line}" for line in lines[8:]]
    return rows


def main():
    lmp = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp")
    blocks = []
    for style in STYLES:
        with tempfile.TemporaryDirectory() as folder:
            (Path(folder) / "clumps.data").write_text(DATA)
            (Path(folder) / "in.case").write_text(SCRIPT.format(style=style))
            run_lammps_file(lmp, folder, "in.case", label=style)
            blocks.append(f"# {style}\n" + "\n".join(frames((Path(folder) / "clumps.dump").read_text())))
    OUT.write_text("\n".join(blocks) + "\n")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
