"""Record LAMMPS's thermo for short NVE runs with pair_style table, the reference
plugins/pair_table/tests/test_lammps_table.py compares pdps with.

    python benchmarks/lammps_references/pair_table.py [LMP]

The scene is pair_styles.py's: 200 particles of two types (masses 1 and 1.5) at number density 0.6,
no two closer than 0.95, Gaussian velocities (seed 11), written to plugins/pair_table/tests/data/fluid.data.
The tables (plugins/pair_table/tests/data/pots.table) tabulate Lennard-Jones and Morse potentials in
every form a table file takes: R spacing, RSQ spacing, r given line by line with FPRIME end slopes. Each case
of CASES runs 100 steps of fix nve at dt 0.002; LAMMPS's thermo (step temp pe press, 15 digits) every
25 steps goes to plugins/pair_table/tests/data/pair_table.txt.
"""

import math
import sys
from pathlib import Path

import numpy as np

from lammps_run import record_cases, write_case_table
from pair_styles import nve_script, write_fluid

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "pair_table" / "tests" / "data"
CASES = {
    "linear_r": "pair_style table linear 1000\npair_coeff * * pots.table LJ_R",
    "spline_r": "pair_style table spline 400\npair_coeff * * pots.table LJ_R",
    "lookup_r": "pair_style table lookup 2000\npair_coeff * * pots.table LJ_R",
    "linear_rsq_match": "pair_style table linear 1200\npair_coeff * * pots.table LJ_RSQ",
    "spline_rsq": "pair_style table spline 1200\npair_coeff * * pots.table LJ_RSQ",
    "two_types_spline": "pair_style table spline 600\npair_coeff 1 1 pots.table LJ_R 2.2\n"
                        "pair_coeff 2 2 pots.table MORSE_FP\npair_coeff 1 2 pots.table LJ_RSQ 2.4",
    "two_types_linear": "pair_style table linear 700\npair_coeff 1 1 pots.table LJ_R 2.2\n"
                        "pair_coeff 2 2 pots.table MORSE_FP\npair_coeff 1 2 pots.table MORSE_FP 2.0",
}


def lj(r):
    s6 = r ** -6
    return 4.0 * (s6 * s6 - s6), 24.0 * (2.0 * s6 * s6 - s6) / r


def morse(r, d0=0.8, alpha=3.0, r0=1.1):
    x = math.exp(-alpha * (r - r0))
    return d0 * (x * x - 2.0 * x), 2.0 * alpha * d0 * (x * x - x)


def section(keyword, params, rs, law):
    lines = [f"{keyword}", params, ""]
    for k, r in enumerate(rs, 1):
        e, f = law(r)
        lines.append(f"{k} {r!r} {e!r} {f!r}")
    return "\n".join(lines) + "\n\n"


def tables():
    n = 500
    r_lin = [0.7 + (2.5 - 0.7) * i / (n - 1) for i in range(n)]
    m = 1200
    r_sq = [math.sqrt(0.7 ** 2 + (2.5 ** 2 - 0.7 ** 2) * i / (m - 1)) for i in range(m)]
    r_free = [float(r) for r in np.round(np.concatenate([np.linspace(0.6, 1.4, 300), np.linspace(1.41, 2.6, 150)]), 6)]
    text = "# pdps pair_table reference tables: Lennard-Jones (eps 1, sigma 1) and Morse (0.8, 3, 1.1)\n\n"
    text += section("LJ_R", f"N {n} R 0.7 2.5", r_lin, lj)
    text += section("LJ_RSQ", f"N {m} RSQ 0.7 2.5", r_sq, lj)
    text += section("MORSE_FP", f"N {len(r_free)} FPRIME -150.0 0.0", r_free, morse)
    (DATA / "pots.table").write_text(text)


def write_tables():
    write_case_table(DATA / "pair_table.cases.json", __file__, "pair_table.txt", ["fluid.data", "pots.table"],
                     {case: nve_script(lines) for case, lines in CASES.items()}, restart=("linear_r",))


def main(lmp):
    DATA.mkdir(parents=True, exist_ok=True)
    write_fluid(DATA / "fluid.data")
    tables()
    record_cases(lmp, {case: nve_script(lines) for case, lines in CASES.items()},
                 [DATA / "fluid.data", DATA / "pots.table"], DATA / "pair_table.txt")
    write_tables()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
