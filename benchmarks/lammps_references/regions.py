"""Record how many sites of a simple-cubic lattice LAMMPS's region styles select (group ... region),
the reference plugins/region_shapes/tests/test_lammps_regions.py compares pdps's region styles with.

    python benchmarks/lammps_references/regions.py [LMP]

The scene: ``lattice sc 1.0`` filling ``region box block 0 10 0 10 0 10`` (1,000 sites, lattice units
as LAMMPS defaults); each line of REGIONS defines a region (and, where it names others, uses the ones
above it) and a group of the sites in it. Counts go to plugins/region_shapes/tests/data/
lammps_regions.txt as ``region line<TAB>count``.
"""

import sys
from pathlib import Path

from lammps_run import lammps_screen, marked_lines

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "plugins" / "region_shapes" / "tests" / "data" / "lammps_regions.txt"
SETUP = ["units lj", "atom_style atomic", "lattice sc 1.0", "region box block 0 10 0 10 0 10", "create_box 1 box",
         "create_atoms 1 box", "mass 1 1"]
REGIONS = [
    "region s sphere 5 5 5 2", "region s2 sphere 4.5 5 5.5 3.2 units box", "region c cylinder z 5 5 2 2 8",
    "region cx cylinder x 4 6 3 INF INF", "region cy cylinder y 5 5 2.5 EDGE 3", "region k cone z 5 5 1 3 2 8",
    "region k2 cone x 5 5 3 0 1 9", "region p plane 0 0 5 0 0 1", "region p2 plane 3 3 3 1 1 1 side out",
    "region q prism 0 5 0 5 0 5 2 0 0", "region q2 prism 1 8 2 7 1 6 1 1.5 -1", "region u union 2 s p",
    "region i intersect 2 s p side out", "region o sphere 5 5 5 2 side out units box",
    "region b block 2 7 INF 4 EDGE 6 side out",
]


def main(lmp):
    lines = list(SETUP)
    for k, region in enumerate(REGIONS):
        name = region.split()[1]
        lines += [region, f"group g{name} region {name}", f'print "@@ {k} $(count(g{name}))"']
    counts = [line.split()[2] for line in marked_lines(lammps_screen(lmp, "\n".join(lines) + "\n"))]
    OUT.write_text("".join(f"{r}\t{c}\n" for r, c in zip(REGIONS, counts)))
    print(OUT.read_text())


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
