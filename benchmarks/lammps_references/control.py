"""Record what LAMMPS prints for a script of groups, variables, loops and run options, the reference
tests/test_control_lammps.py compares pdps with line for line.

    python benchmarks/lammps_references/control.py [LMP]

The script (SCRIPT) prints its results with ``print "@@ ..."``; LAMMPS's @@ lines go to
tests/data/lammps/control.txt.
"""

import sys
from pathlib import Path

from lammps_run import lammps_screen, marked_lines

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "lammps" / "control.txt"
SCRIPT = r"""units lj
atom_style atomic
lattice sc 1.0
region box block 0 5 0 5 0 5
create_box 3 box
create_atoms 1 box
mass * 1.0
group low id 1:40
group odd id 1:125:2
group mid id <> 30 60
group big id >= 100
group both intersect low odd
group either union low big
group rest subtract all low big
set group big type 2
set group mid type 3
group t2 type 2
group t23 type 2 3
group t13 type 1:3:2
variable xs atom x>2.5
group right variable xs
region corner block 0 2 0 2 0 2
group corner region corner
group corner id 125
print "@@ groups $(count(low)) $(count(odd)) $(count(mid)) $(count(big)) $(count(both)) $(count(either)) $(count(rest))"
print "@@ types $(count(t2)) $(count(t23)) $(count(t13)) $(count(right)) $(count(corner))"
print "@@ functions $(mass(all)) $(xcm(low,x):%.12f) $(xcm(big,z):%.12f) $(bound(mid,xmax)) $(bound(mid,zmin)) $(count(all,corner))"
variable n loop 3
variable sum equal 0
label loop
variable sum equal ${sum}+${n}*2
print "@@ loop ${n} ${sum}"
next n
jump SELF loop
variable s index a b c
label strings
print "@@ index ${s}"
next s
jump SELF strings
variable f format sum %08.3f
print "@@ format ${f} $(v_sum/7:%.5e) $(v_sum^2)"
if "${sum} > 10" then "print '@@ if big'" elif "${sum} > 5" "print '@@ if mid'" else "print '@@ if small'"
if "abc == abc" then "print '@@ string equal'"
velocity all set 0.1 0.2 0.3
fix 1 all nve
thermo 0
run 4 every 2 "print '@@ every $(step)'"
run 10 upto
print "@@ upto $(step)"
run 5 start 0 stop 40
print "@@ ramp $(ramp(0,40))"
variable v vector [1,4,9]
print "@@ vector $(v_v[2]) $(sum(v_v)) $(max(v_v)) $(ave(v_v))"
"""


def main(lmp):
    lines = marked_lines(lammps_screen(lmp, SCRIPT))
    OUT.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
