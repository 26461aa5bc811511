"""Record how many of many spheres LIGGGHTS 3.8.0's fix massflow/mesh/sieve lets through, for
plugins/fix_wall/tests/test_massflow_sieve.py, which compares pdps's count of the same scene with it
and both with the passage probability (each a binomial count, so within their error bars, not
digit for digit: the two programs draw different random numbers).

    python benchmarks/liggghts_references/sieve_statistics.py [LIGGGHTS]

The scene: 20 x 20 x 4 spheres of diameter 2 mm on a simple-cubic lattice (spacing 5 mm), all moving
down at 1 m/s, no pair style (they never meet), onto a flat square sieve of two triangles at z = 0
with holes of 3 mm at 1.5 mm spacing (probability pi/4 (3 - 2)^2 / 1.5^2 = 0.349): those drawn to
pass cross it and are counted (count once), the others bounce back up and leave. The script, the
number of spheres and LIGGGHTS's count after 2000 steps go into
plugins/fix_wall/tests/data/liggghts_sieve_statistics.json.
"""

import json
import re
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from cases import LIGGGHTS, PROGRAM, ROOT  # noqa: E402

DATA = ROOT / "plugins" / "fix_wall" / "tests" / "data" / "liggghts_sieve_statistics.json"
HALF = 0.048
STL = "solid sieve\n" + "".join(
    "  facet normal 0 0 1\n    outer loop\n" + "".join(f"      vertex {x} {y} 0.0\n" for x, y in corners)
    + "    endloop\n  endfacet\n"
    for corners in (((-HALF, -HALF), (HALF, -HALF), (HALF, HALF)), ((-HALF, -HALF), (HALF, HALF), (-HALF, HALF)))
) + "endsolid sieve\n"
SCRIPT = """atom_style granular
atom_modify map array sort 0 0
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 -0.05 0.02 units box
create_box 1 box
neighbor 0.001 bin
neigh_modify delay 0
region bed block -0.0475 0.0475 -0.0475 0.0475 0.0025 0.0175 units box
lattice sc 0.005 origin 0.5 0.5 0.5
create_atoms 1 region bed
set type 1 diameter 0.002 density 2500
velocity all set 0.0 0.0 -1.0 units box
timestep 1e-5
fix sievemesh all mesh/surface file sieve.stl type 1
fix sieve all massflow/mesh/sieve mesh sievemesh count once vec_side 0 0 -1 sieveSize 0.003 sieveSpacing 0.0015 sieveStiffness 100
fix integr all nve/sphere
thermo_style custom step atoms f_sieve[2]
thermo_modify format float %20.15g
thermo 1000
run 2000
"""


def main(liggghts=LIGGGHTS):
    with tempfile.TemporaryDirectory() as tmp:
        (Path(tmp) / "sieve.stl").write_text(STL)
        (Path(tmp) / "in.sieve").write_text(SCRIPT)
        done = subprocess.run([liggghts, "-in", "in.sieve", "-log", "none", "-echo", "none"], cwd=tmp, check=True,
                              capture_output=True, text=True)
    rows = [line.split() for line in done.stdout.splitlines() if re.match(r"\s+2000\s", line)]
    atoms, passed = int(rows[-1][1]), float(rows[-1][2])
    DATA.write_text(json.dumps({"program": PROGRAM, "script": SCRIPT, "sieve.stl": STL, "spheres": atoms,
                                "passed": passed}, indent=1) + "\n")
    print(f"wrote {DATA}: {passed:g} of {atoms} passed")


if __name__ == "__main__":
    main(*sys.argv[1:])
