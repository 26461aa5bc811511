"""Record LAMMPS's minimisation of an overlapping Lennard-Jones start, the reference
tests/test_minimize.py compares pdps's ``minimize`` with.

    python benchmarks/lammps_references/minimize.py [LMP]

The start: an fcc crystal at reduced density 0.8442 (4 x 4 x 4 cells, 256 atoms) with every atom
displaced uniformly by up to 0.2 sigma per axis (seed 2024), so close pairs overlap (energy above
zero where the crystal's is -6.77 per atom); lj/cut 2.5. (With 0.3 sigma LAMMPS's own first steps
throw atoms out of the box.) It is written by pdps_core.testing.write_data to tests/data/lammps/
min_start.data; both programs read that file. For min_style cg, sd and fire (LAMMPS's defaults
otherwise) the energies per atom LAMMPS reports (initial and final), its iterations and stopping
criterion go to tests/data/lammps/minimize.txt.
"""

import sys
from pathlib import Path

import numpy as np

from pdps_core.testing import write_data

from lammps_run import run_lammps

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "tests" / "data" / "lammps"
MINIMIZE = "minimize 1.0e-8 1.0e-8 5000 50000"
STYLES = ("cg", "sd", "fire")


def start():
    a = (4 / 0.8442) ** (1 / 3)
    basis = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    cells = np.mgrid[0:4, 0:4, 0:4].reshape(3, -1).T
    x = ((cells[:, None, :] + basis[None]) * a).reshape(-1, 3)
    x += np.random.default_rng(2024).uniform(-0.2, 0.2, size=x.shape)
    x %= 4 * a
    write_data(DATA / "min_start.data", (0, 0, 0), (4 * a,) * 3, x)


def script(style):
    return "\n".join(["units lj", "atom_style atomic", "read_data min_start.data", "mass 1 1.0",
                      "pair_style lj/cut 2.5", "pair_coeff 1 1 1.0 1.0 2.5", "neighbor 0.3 bin",
                      "neigh_modify every 1 delay 0 check yes", f"min_style {style}", "thermo 0",
                      MINIMIZE, ""])


def main(lmp):
    DATA.mkdir(parents=True, exist_ok=True)
    start()
    rows = [f"# {MINIMIZE}; style initial final iterations evaluations criterion"]
    for style in STYLES:
        lines = run_lammps(lmp, script(style), [DATA / "min_start.data"], style).splitlines()
        k = next(i for i, line in enumerate(lines) if "Energy initial, next-to-last, final" in line)
        initial, _, final = lines[k + 1].split()
        criterion = next(line.split("=", 1)[1].strip() for line in lines if "Stopping criterion" in line)
        iterations, evaluations = next(line.split("=", 1)[1].split() for line in lines
                                       if "Iterations, force evaluations" in line)
        rows.append(f"{style}\t{initial}\t{final}\t{iterations}\t{evaluations}\t{criterion}")
    (DATA / "minimize.txt").write_text("\n".join(rows) + "\n")
    print("\n".join(rows))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
