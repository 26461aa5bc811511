"""Record LAMMPS's thermo for bonds made and broken during a run (fix bond/create, fix bond/break),
the references plugins/bond_basic/tests compares pdps with.

    python benchmarks/lammps_references/bond_topology.py [LMP]

Two scenes, in plugins/bond_basic/tests/data: bonds.py's chains.data (20 chains of 8 beads, harmonic
bonds of rest length 1 and 0.95, stretched bonds break) and monomers.data, written here: 200 free
particles of types 1 and 2 (masses 1, 1.5; a third type 3 of mass 1.2 for the types bond/create
gives), Gaussian velocities (seed 5), room for 4 bonds each. Each case runs 200 steps of fix nve at
dt 0.002 under pair_style soft; thermo (step temp pe ebond press, the fix's vector, bonds; 15
digits) every 20 steps goes to bond_topology.txt. The cases with iparam/jparam also dump the
particles' types at the end (the types bond/create gave), word for word.
"""

import sys
from pathlib import Path

import numpy as np

from lammps_run import record_cases, run_lammps, write_case_table

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "bond_basic" / "tests" / "data"
TYPES_DUMP = "dump t all custom 200 types.txt id type\ndump_modify t sort id"
BREAK = {
    "break": ("chains", "fix b all bond/break 5 1 1.02", "f_b[1] f_b[2]"),
    "break_group": ("chains", "group few id <= 80\nfix b few bond/break 1 2 1.0", "f_b[1] f_b[2]"),
}
CREATE = {
    "create": ("monomers", "special_bonds lj 0 1 1\nfix c all bond/create 5 1 2 1.2 1 iparam 2 3 jparam 3 2\n"
               + TYPES_DUMP, "f_c[1] f_c[2]"),
    "create_special_0": ("monomers", "fix c all bond/create 5 1 2 1.2 1 iparam 2 3 jparam 3 2", "f_c[1] f_c[2]"),
    "create_same_type": ("monomers", "special_bonds lj 0 1 1\nfix c all bond/create 2 1 1 1.1 1 iparam 3 3 "
                         "jparam 3 3\n" + TYPES_DUMP, "f_c[1] f_c[2]"),
    "create_special_1": ("monomers", "special_bonds lj 1 1 1\nfix c all bond/create 10 2 1 1.3 1 iparam 2 2 jparam 2 1",
                         "f_c[1] f_c[2]"),
    "create_and_break": ("monomers", "special_bonds lj 0 1 1\nfix c all bond/create 4 1 2 1.0 1\n"
                         "fix b all bond/break 4 1 1.15", "f_c[2] f_b[2]"),
}


def write_monomers(path):
    rng = np.random.default_rng(5)
    n, side = 200, 10.0
    x = rng.uniform(0, side, (n, 3))
    v = rng.normal(scale=0.7, size=(n, 3))
    lines = ["monomers", "", f"{n} atoms", "3 atom types", "0 bonds", "1 bond types", "4 extra bond per atom",
             "12 extra special per atom", "", f"0 {side} xlo xhi", f"0 {side} ylo yhi", f"0 {side} zlo zhi", "",
             "Masses", "", "1 1.0", "2 1.5", "3 1.2", "", "Atoms # bond", "",
             *[f"{i + 1} {i + 1} {1 + i % 2} {x[i, 0]:.10f} {x[i, 1]:.10f} {x[i, 2]:.10f}" for i in range(n)],
             "", "Velocities", "", *[f"{i + 1} {v[i, 0]:.10f} {v[i, 1]:.10f} {v[i, 2]:.10f}" for i in range(n)]]
    Path(path).write_text("\n".join(lines) + "\n")


def script(scene, lines, columns):
    pair = "pair_style soft 2.5\npair_coeff * * 5.0" if scene == "chains" else "pair_style soft 1.5\npair_coeff * * 2.0"
    bonds = ("bond_style harmonic\nbond_coeff 1 100.0 1.0\nbond_coeff 2 80.0 0.95" if scene == "chains"
             else "bond_style harmonic\nbond_coeff 1 50.0 1.0")
    return "\n".join(["units lj", "atom_style bond", f"read_data {scene}.data", pair, bonds, "fix 1 all nve",
                      lines, "timestep 0.002", "thermo 20",
                      f"thermo_style custom step temp pe ebond press {columns} bonds",
                      "thermo_modify format float %.15g", "run 200", ""])


def main(lmp):
    DATA.mkdir(parents=True, exist_ok=True)
    write_monomers(DATA / "monomers.data")
    files = [DATA / "chains.data", DATA / "monomers.data"]
    scripts = {case: script(*entry) for case, entry in {**BREAK, **CREATE}.items()}
    record_cases(lmp, scripts, files, DATA / "bond_topology.txt")
    outputs = {}
    for case, text in scripts.items():
        if "types.txt" in text:
            kept = DATA / f"_{case}_types.txt"
            run_lammps(lmp, text, files, case, outputs={"types.txt": kept})
            outputs[case] = {"types.txt": kept.read_text()}
            kept.unlink()
    write_case_table(DATA / "bond_topology.cases.json", __file__, "bond_topology.txt",
                     ["chains.data", "monomers.data"], scripts,
                     ranks=("break", "create", "create_special_0", "create_and_break"), outputs=outputs)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
