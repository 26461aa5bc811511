"""Record where LIGGGHTS 3.8.0's insertion fixes put their particles, over many seeds, which
plugins/fix_insert/tests/test_liggghts_placement.py compares pdps with.

    python benchmarks/liggghts_references/insertion.py [LIGGGHTS]

Two scenes of pdps's own (LIGGGHTS syntax), each run for one step per seed set (SEEDS primes > 10^7
for the templates, the distribution and the insertion), with a dump of every particle's id, radius
and position at step 1 added:

- ``stream``: fix insert/stream through a square face of two triangles (an ASCII STL written with
  the script) 0.145 below the box's top, extrude_length 0.15, spheres of radius 0.006 and 0.01 (half
  the mass each), overlapcheck yes; per radius the count and the height above the face less the
  radius (LIGGGHTS's depth u L + r; the larger spheres also keep their radius from the box's top);
- ``pack``: fix insert/pack filling a block region that is the whole box (periodic in x and y), all_in
  no, to a volume fraction of 0.2; the count and each centre's distance to the nearest face of the
  box less its radius (LIGGGHTS's check_dist_from_subdomain_border, by default yes).

The scripts (without the dump), the STL and every seed set's numbers go to
plugins/fix_insert/tests/data/liggghts_placement.json.
"""

import json
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "plugins" / "fix_insert" / "tests" / "data" / "liggghts_placement.json"
LIGGGHTS = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "liggghts")
RUNS = 20

FACE_Z = 0.3
STL = f"""solid face
facet normal 0 0 1
  outer loop
    vertex -0.1 -0.1 {FACE_Z}
    vertex 0.1 -0.1 {FACE_Z}
    vertex 0.1 0.1 {FACE_Z}
  endloop
endfacet
facet normal 0 0 1
  outer loop
    vertex -0.1 -0.1 {FACE_Z}
    vertex 0.1 0.1 {FACE_Z}
    vertex -0.1 0.1 {FACE_Z}
  endloop
endfacet
endsolid face
"""

HEAD = """atom_style granular
atom_modify map array
newton off
communicate single vel yes
units si
"""
MATERIAL = """fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m4 all property/global coefficientFriction peratomtypepair 1 0.05
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.00001
"""
TEMPLATES = """fix pts1 all particletemplate/sphere {s1} atom_type 1 density constant 2500 radius constant 0.006
fix pts2 all particletemplate/sphere {s2} atom_type 1 density constant 2500 radius constant 0.01
fix pdd all particledistribution/discrete {s3} 2 pts1 0.5 pts2 0.5
"""

SCENES = {
    "stream": HEAD + """boundary f f f
region reg block -0.2 0.2 -0.2 0.2 -0.1 0.455 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
""" + MATERIAL + TEMPLATES + """fix face all mesh/surface file face.stl type 1
fix ins all insert/stream seed {s4} distributiontemplate pdd nparticles 100000 particlerate 6000 &
    vel constant 0. -0.5 -2. overlapcheck yes insertion_face face extrude_length 0.15
fix integr all nve/sphere
""",
    "pack": HEAD + """boundary p p f
region reg block 0 0.1 0 0.1 0 0.1 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
""" + MATERIAL + TEMPLATES + """fix ins all insert/pack seed {s4} distributiontemplate pdd insert_every once &
    overlapcheck yes volumefraction_region 0.2 region reg
fix integr all nve/sphere
""",
}
RUN = "run 1\n"
DUMP = "dump d all custom 1 placed.txt id radius x y z\n"


def is_prime(n):
    return n > 1 and all(n % k for k in range(2, int(n ** 0.5) + 1))


def seed_sets(runs, start=10_000_000):
    primes, n = [], start
    while len(primes) < 4 * runs:
        n += 1
        if is_prime(n):
            primes.append(n)
    return [dict(zip(("s1", "s2", "s3", "s4"), primes[4 * k:4 * k + 4])) for k in range(runs)]


def placed(dump_text):
    """(radius, x) of the particles in a dump's last snapshot."""
    lines = dump_text.splitlines()
    start = max(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
    rows = np.array([line.split() for line in lines[start:]], dtype=float)
    return rows[:, 1], rows[:, 2:5]


def stream_numbers(radius, x):
    """Per radius (small, large): count, mean, min and max of the height above the face less the radius."""
    out = []
    for r in (0.006, 0.01):
        mine = np.isclose(radius, r)
        lift = x[mine, 2] - FACE_Z - radius[mine]
        out.append([int(mine.sum()), float(lift.mean()), float(lift.min()), float(lift.max())])
    return out


def pack_numbers(radius, x, lo=(0.0, 0.0, 0.0), hi=(0.1, 0.1, 0.1)):
    """Count, and the smallest and the mean distance of a centre to a face of the box less its radius."""
    room = np.minimum(x - np.array(lo), np.array(hi) - x).min(axis=1) - radius
    return [len(radius), float(room.min()), float(room.mean())]


NUMBERS = {"stream": stream_numbers, "pack": pack_numbers}


def main():
    table = {"liggghts": LIGGGHTS, "stl": STL, "scripts": {}, "seeds": seed_sets(RUNS), "runs": {}}
    for name, script in SCENES.items():
        table["scripts"][name] = script + RUN
        table["runs"][name] = []
        for seeds in table["seeds"]:
            with tempfile.TemporaryDirectory() as folder:
                Path(folder, "face.stl").write_text(STL)
                Path(folder, "in.scene").write_text(script.format(**seeds) + DUMP + RUN)
                subprocess.run([LIGGGHTS, "-in", "in.scene", "-log", "log.liggghts"], cwd=folder, check=True,
                               capture_output=True)
                radius, x = placed(Path(folder, "placed.txt").read_text())
                table["runs"][name].append(NUMBERS[name](radius, x))
        print(name, np.mean([np.ravel(row) for row in table["runs"][name]], axis=0).round(5))
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(json.dumps(table, indent=1) + "\n")


if __name__ == "__main__":
    main()
