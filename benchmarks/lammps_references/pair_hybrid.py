"""Record LAMMPS's thermo for short NVE runs with pair_style hybrid and hybrid/overlay, the reference
plugins/pair_hybrid/tests/test_lammps_hybrid.py compares pdps with.

    python benchmarks/lammps_references/pair_hybrid.py [LMP]

The scene is pair_styles.py's 200-particle two-type fluid and pair_table.py's tables (both copied to
plugins/pair_hybrid/tests/data/); each case of CASES runs 100 steps of fix nve at dt 0.002; LAMMPS's thermo
(step temp pe press, 15 digits) every 25 steps goes to plugins/pair_hybrid/tests/data/hybrid.txt.
"""

import shutil
import sys
from pathlib import Path

from lammps_run import record_cases, write_case_table
from pair_styles import nve_script

ROOT = Path(__file__).resolve().parents[2]
SOURCES = [ROOT / "plugins" / "pair_simple" / "tests" / "data" / "fluid.data",
           ROOT / "plugins" / "pair_table" / "tests" / "data" / "pots.table"]
DATA = ROOT / "plugins" / "pair_hybrid" / "tests" / "data"
CASES = {
    "hybrid": "pair_style hybrid lj/cut 2.5 soft 1.5\npair_coeff 1 1 lj/cut 1.0 1.0\npair_coeff 2 2 soft 5.0\n"
              "pair_coeff 1 2 lj/cut 0.8 1.1 2.2",
    "hybrid_none_table": "pair_style hybrid lj/cut 2.5 table spline 600\npair_coeff 1 1 lj/cut 1.0 1.0\n"
                         "pair_coeff 2 2 table pots.table MORSE_FP\npair_coeff 1 2 none",
    "hybrid_mixed": "pair_style hybrid lj/cut 2.5\npair_coeff 1 1 lj/cut 1.0 1.0\n"
                    "pair_coeff 2 2 lj/cut 0.5 1.2 2.0\npair_modify mix arithmetic shift yes",
    "overlay": "pair_style hybrid/overlay lj/cut 2.5 yukawa 1.5 2.0\npair_coeff * * lj/cut 1.0 1.0\n"
               "pair_coeff 2 2 lj/cut 0.5 1.2\npair_coeff 1 1 yukawa 2.0\npair_coeff 2 2 yukawa 3.0 1.8",
    "overlay_tail": "pair_style hybrid/overlay lj/cut 2.5 soft 1.2\npair_coeff 1 1 lj/cut 1.0 1.0\n"
                    "pair_coeff 2 2 lj/cut 0.5 1.2\npair_coeff 1 2 lj/cut 0.7 1.1\npair_coeff 1 1 soft 2.0\n"
                    "pair_coeff 2 2 soft 3.0\npair_coeff 1 2 soft 2.5\npair_modify tail yes",
    "hybrid_dpd": "comm_modify vel yes\npair_style hybrid dpd 0.0 1.0 34387 lj/cut 2.5\n"
                  "pair_coeff 1 1 dpd 25.0 4.5\npair_coeff 2 2 lj/cut 1.0 1.0\npair_coeff 1 2 dpd 10.0 4.5 1.2",
    "overlay_dpd": "comm_modify vel yes\npair_style hybrid/overlay lj/cut 2.5 dpd 0.0 1.0 34387\n"
                   "pair_coeff * * lj/cut 1.0 1.0\npair_coeff * * dpd 0.0 4.5 1.0",
}


def write_tables():
    write_case_table(DATA / "hybrid.cases.json", __file__, "hybrid.txt", ["fluid.data", "pots.table"],
                     {case: nve_script(lines) for case, lines in CASES.items()},
                     ranks=("overlay",), restart=("hybrid", "overlay_dpd"))


def main(lmp):
    DATA.mkdir(parents=True, exist_ok=True)
    for source in SOURCES:
        shutil.copy(source, DATA / source.name)
    record_cases(lmp, {case: nve_script(lines) for case, lines in CASES.items()}, SOURCES, DATA / "hybrid.txt")
    write_tables()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
