"""Record LAMMPS's thermo keywords on a short Lennard-Jones run, the reference tests/test_thermo_lammps.py
compares pdps's with.

    python benchmarks/lammps_references/thermo.py [LMP]

The scene is plugins/pair_simple/tests/data/fluid.data (200 particles, two types, masses 1 and 1.5),
lj/cut 2.5, fix nve, dt 0.002; KEYWORDS printed with 15 digits at steps 0, 20, 40 in lj units (energies
per particle) and again with thermo_modify norm no, then in metal units (epsilons in eV, the same
lengths in Angstrom), then in lj units between wall/lj93 walls whose energy joins pe through
fix_modify energy yes (epair and evdwl stay the pair's). Rows go to
tests/data/lammps/thermo.txt as ``case<TAB>values...``.
"""

import sys
from pathlib import Path

from lammps_run import run_lammps, thermo_lines

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "pair_simple" / "tests" / "data" / "fluid.data"
OUT = ROOT / "tests" / "data" / "lammps" / "thermo.txt"
KEYWORDS = ("step elapsed elaplong dt time atoms temp press pe ke etotal enthalpy evdwl ecoul epair ebond "
            "elong vol density lx ly lz xlo xhi ylo yhi zlo zhi fmax fnorm pxx pyy pzz pxy pxz pyz")
# lj_fix_energy: a wall/lj93 fix whose energy joins pe (fix_modify energy yes) but not epair or evdwl
CASES = {"lj": "", "lj_norm_no": "thermo_modify norm no", "metal": None,
         "lj_fix_energy": "fix 2 all wall/lj93 zlo -0.5 1.0 1.0 2.5 zhi 7.43 1.0 1.0 2.5 units box\n"
                          "fix_modify 2 energy yes"}


def script(case):
    units = "metal" if case == "metal" else "lj"
    epsilon = (0.0103, 0.005) if case == "metal" else (1.0, 0.5)
    lines = [f"units {units}", "atom_style atomic", "read_data fluid.data", "pair_style lj/cut 2.5",
             f"pair_coeff 1 1 {epsilon[0]} 1.0", f"pair_coeff 2 2 {epsilon[1]} 1.2"]
    lines += ["fix 1 all nve", "timestep 0.002" if case != "metal" else "timestep 0.001",
              "thermo 20", f"thermo_style custom {KEYWORDS}", "thermo_modify format float %.15g"]
    if case == "lj_fix_energy":
        # walls need a z that is not periodic; they stand half a sigma outside the box's faces
        lines.insert(1, "boundary p p f")
        lines.append(CASES[case])
    elif CASES.get(case):
        lines.append(CASES[case])
    lines.append("run 40")
    return "\n".join(lines) + "\n"


def main(lmp):
    rows = []
    for case in CASES:
        log = run_lammps(lmp, script(case), [DATA], case)
        rows += [f"{case}\t" + "\t".join(words) for words in thermo_lines(log)]
    OUT.write_text("\n".join(rows) + "\n")
    print("\n".join(rows))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
