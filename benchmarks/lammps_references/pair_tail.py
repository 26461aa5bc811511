"""Record LAMMPS's thermo for short NVE runs of lj/cut with ``pair_modify tail yes``, the reference
plugins/pair_lj/tests/test_lammps_tail.py compares pdps with.

    python benchmarks/lammps_references/pair_tail.py [LMP]

The scene is pair_styles.py's 200-particle two-type fluid (copied to plugins/pair_lj/tests/data/);
each case of CASES runs 100 steps of fix nve at dt 0.002; LAMMPS's thermo (step temp pe press evdwl etail,
15 digits) every 25 steps goes to plugins/pair_lj/tests/data/tail.txt; the energies a 60-iteration
minimize of the "tail" case reports (initial, next-to-last, final) to tail_minimize.txt.
"""

import sys
from pathlib import Path

from lammps_run import record_cases, run_lammps, write_case_table

ROOT = Path(__file__).resolve().parents[2]
SOURCE = ROOT / "plugins" / "pair_simple" / "tests" / "data" / "fluid.data"
DATA = ROOT / "plugins" / "pair_lj" / "tests" / "data"
CASES = {
    "tail": "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.2 2.0\npair_modify tail yes",
    "tail_arithmetic": "pair_style lj/cut 2.2\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.2\n"
                             "pair_coeff 1 2 0.8 1.05 2.6\npair_modify mix arithmetic tail yes",
}

# minimize reads pe with the tail (LAMMPS's compute pe): its summary energies and etol test include it
MINIMIZE = ("units lj\natom_style atomic\nread_data fluid.data\n" + CASES["tail"] + "\nthermo 10\n"
            "minimize 1e-6 1e-8 60 1000\n")


def script(case):
    return "\n".join(["units lj", "atom_style atomic", "read_data fluid.data", CASES[case], "fix 1 all nve",
                      "timestep 0.002", "thermo 25", "thermo_style custom step temp pe press evdwl etail",
                      "thermo_modify format float %.15g", "run 100", ""])


def write_tables():
    write_case_table(DATA / "tail.cases.json", __file__, "tail.txt", ["fluid.data"],
                     {case: script(case) for case in CASES}, ranks=("tail",), restart=("tail_arithmetic",))


def main(lmp):
    DATA.mkdir(parents=True, exist_ok=True)
    (DATA / "fluid.data").write_bytes(SOURCE.read_bytes())
    record_cases(lmp, {case: script(case) for case in CASES}, [SOURCE], DATA / "tail.txt")
    write_tables()
    lines = run_lammps(lmp, MINIMIZE, [SOURCE], "minimize").splitlines()
    energies = lines[next(k for k, line in enumerate(lines) if "Energy initial" in line) + 1]
    (DATA / "tail_minimize.txt").write_text(" ".join(energies.split()) + "\n")
    print(energies)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
