"""Record LAMMPS's thermo for short NVE runs with the pair styles of plugins/pair_simple and lj/cut's
mixing rules, the reference plugins/pair_simple/tests/test_lammps_pair_styles.py compares pdps with.

    python benchmarks/lammps_references/pair_styles.py [LMP]

The scene (written by pdps_core.testing.write_data to plugins/pair_simple/tests/data/fluid.data):
200 particles of two types and masses 1 and 1.5 at number density 0.6, no two closer than 0.95, with
Gaussian velocities (seed 11). Each case of CASES runs 100 steps of fix nve at dt 0.002 in both
programs; LAMMPS's thermo lines (step temp pe press, 15 digits) every 25 steps go to
plugins/pair_simple/tests/data/pair_styles.txt.
"""

import sys
from pathlib import Path

import numpy as np

from pdps_core.testing import fluid, write_data

from lammps_run import record_cases, write_case_table

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "pair_simple" / "tests" / "data"
CASES = {
    "soft": "pair_style soft 1.5\npair_coeff 1 1 3.0\npair_coeff 2 2 5.0 1.3",
    "morse": "pair_style morse 2.5\npair_coeff 1 1 1.0 4.0 1.1\npair_coeff 2 2 0.7 3.5 1.2\n"
             "pair_coeff 1 2 0.85 3.8 1.15 2.2\npair_modify shift yes",
    "yukawa": "pair_style yukawa 1.5 2.8\npair_coeff 1 1 10.0\npair_coeff 2 2 6.0 2.5\npair_modify shift yes",
    "zero": "pair_style zero 2.5\npair_coeff * *",
    "lj_sixthpower": "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.2 2.0\n"
                     "pair_modify mix sixthpower",
    "lj_arithmetic_shift": "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.2\n"
                           "pair_modify mix arithmetic shift yes",
}


def write_fluid(path):
    """The two-type fluid's data file (also pair_table.py's scene)."""
    x, length = fluid(200, 0.6, seed=11, min_distance=0.95)
    types = np.where(np.arange(200) % 3 == 0, 2, 1)
    v = np.random.default_rng(11).normal(size=(200, 3))
    write_data(path, (0, 0, 0), (length,) * 3, x, types=types, velocities=v, masses={1: 1.0, 2: 1.5})


def nve_script(pair_lines):
    """The fluid under ``pair_lines``: 100 NVE steps at dt 0.002, thermo every 25 (also pair_table.py's
    and pair_hybrid.py's runs, and the tests' scripts)."""
    return "\n".join(["units lj", "atom_style atomic", "read_data fluid.data", pair_lines, "fix 1 all nve",
                      "timestep 0.002", "thermo 25", "thermo_style custom step temp pe press",
                      "thermo_modify format float %.15g", "run 100", ""])


def write_tables():
    write_case_table(DATA / "pair_styles.cases.json", __file__, "pair_styles.txt", ["fluid.data"],
                     {case: nve_script(lines) for case, lines in CASES.items()},
                     ranks=("morse",), restart=("yukawa", "lj_arithmetic_shift"))


def main(lmp):
    DATA.mkdir(parents=True, exist_ok=True)
    write_fluid(DATA / "fluid.data")
    record_cases(lmp, {case: nve_script(lines) for case, lines in CASES.items()}, [DATA / "fluid.data"],
                 DATA / "pair_styles.txt")
    write_tables()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
