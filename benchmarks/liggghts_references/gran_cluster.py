"""Record LIGGGHTS 3.8.0's end state of a small cohesive cluster falling in the tutorials' box, which
plugins/pair_gran/tests/test_gran_cluster.py compares pdps with.

    python benchmarks/liggghts_references/gran_cluster.py [LIGGGHTS]

The scene (SCRIPT) is the cohesion tutorial's material, contact laws and walls (pair gran model hertz
tangential history cohesion sjkr; floor, lid and cylinder as primitive walls) with 36 spheres set on
a simple cubic lattice near the cylinder wall, each with its own velocity from a formula, run for
STEPS steps. Its spheres touch, part and touch again between list builds, and roll on the floor and
the wall. The script goes to plugins/pair_gran/tests/data/liggghts_cohesive_cluster.in, LIGGGHTS's
id x y z vx vy vz omegax omegay omegaz of every sphere at the end (17 significant digits) to
liggghts_cohesive_cluster.ref beside it.
"""

import subprocess
import sys
import tempfile
from pathlib import Path

DATA = Path(__file__).resolve().parents[2] / "plugins" / "pair_gran" / "tests" / "data"
NAME = "liggghts_cohesive_cluster"
STEPS = 1500
SCRIPT = f"""\
atom_style granular
atom_modify map array
boundary m m m
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 0. 0.15 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m4 all property/global coefficientFriction peratomtypepair 1 0.05
fix m5 all property/global cohesionEnergyDensity peratomtypepair 1 300000
pair_style gran model hertz tangential history cohesion sjkr
pair_coeff * *
timestep 0.00001
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix zwalls1 all wall/gran model hertz tangential history primitive type 1 zplane 0.0
fix zwalls2 all wall/gran model hertz tangential history primitive type 1 zplane 0.15
fix cylwalls all wall/gran model hertz tangential history primitive type 1 zcylinder 0.05 0. 0.
lattice sc 0.0031
region lat block 0.0376 0.0494 -0.006 0.006 0.0016 0.0128 units box
create_atoms 1 region lat
set group all diameter 0.003 density 2500
variable vx atom 0.3*sin(1000*y+2000*z)
variable vy atom 0.3*cos(1500*x-900*z)
variable vz atom -0.2+0.2*sin(700*x+1100*y)
velocity all set v_vx v_vy v_vz
fix integr all nve/sphere
run {STEPS}
"""
DUMP = (f"dump d all custom {STEPS} end.*.txt id x y z vx vy vz omegax omegay omegaz\n"
        'dump_modify d sort id format "%d' + " %.17g" * 9 + '"\n')


def main():
    liggghts = sys.argv[1] if len(sys.argv) > 1 else "liggghts"
    lines = SCRIPT.splitlines(keepends=True)
    with tempfile.TemporaryDirectory() as folder:
        (Path(folder) / "in.case").write_text("".join(lines[:-1]) + DUMP + lines[-1])
        done = subprocess.run([liggghts, "-in", "in.case", "-log", "none", "-echo", "none"], cwd=folder,
                              capture_output=True, text=True)
        if done.returncode != 0:
            sys.exit(f"LIGGGHTS failed:\n{done.stdout[-2000:]}")
        rows = (Path(folder) / f"end.{STEPS}.txt").read_text().splitlines()[9:]
    (DATA / f"{NAME}.in").write_text(f"# {NAME} (benchmarks/liggghts_references/gran_cluster.py)\n" + SCRIPT)
    (DATA / f"{NAME}.ref").write_text(f"# LIGGGHTS 3.8.0 at step {STEPS}: id x y z vx vy vz omegax omegay omegaz\n"
                                      + "\n".join(row.strip() for row in rows) + "\n")
    print(f"wrote {DATA / NAME}.in and .ref ({len(rows)} spheres)")


if __name__ == "__main__":
    main()
