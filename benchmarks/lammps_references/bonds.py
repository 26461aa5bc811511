"""Record LAMMPS's thermo for bonded chains (bond_style harmonic, hybrid and none, special_bonds,
delete_bonds) and its compute bond/local rows, the references plugins/bond_basic/tests compares pdps
with.

    python benchmarks/lammps_references/bonds.py [LMP]

The scene (written here to plugins/bond_basic/tests/data/chains.data): 20 chains of 8 beads of two
types (masses 1, 1.5) in a periodic box of side 16, bonds of two types alternating along each chain,
many across the box's faces, Gaussian velocities (seed 3). Each case runs 200 steps of fix nve at dt
0.002 under pair_style soft (finite, so that the chains may overlap); thermo (step temp pe ebond
press, 15 digits) every 50 steps goes to bonds.txt; the bond/local case's dump local to
bond_local.txt.
"""

import sys
from pathlib import Path

import numpy as np

from lammps_run import record_cases, run_lammps, write_case_table

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "bond_basic" / "tests" / "data"
HARMONIC = "bond_style harmonic\nbond_coeff 1 100.0 1.0\nbond_coeff 2 80.0 0.95"
CASES = {
    "harmonic": HARMONIC,
    "harmonic_star": "bond_style harmonic\nbond_coeff * 100.0 1.0",
    "hybrid": "bond_style hybrid harmonic\nbond_coeff 1 harmonic 100.0 1.0\nbond_coeff 2 harmonic 80.0 0.95\n"
              "special_bonds lj/coul 0.0 1.0 1.0",
    "special_fene": HARMONIC + "\nspecial_bonds fene",
    "none": "bond_style none",
    "delete_bonds": "bond_style harmonic\nbond_coeff * 100.0 1.0\ndelete_bonds all bond 2 remove\n"
                    "delete_bonds all atom 1 any\ndelete_bonds all bond 1 undo\ndelete_bonds all stats\n"
                    "group few id <= 40\ndelete_bonds few multi remove special",
    "delete_keep_special": HARMONIC + "\ngroup few id <= 60\ndelete_bonds few multi",
}
LOCAL = (HARMONIC + "\ndelete_bonds all bond 2\ncompute b all bond/local dist engpot force dx fx\n"
         "dump d all local 100 bonds.txt index c_b[1] c_b[2] c_b[3] c_b[4] c_b[5]\n"
         "dump_modify d format float %.15g")


def write_chains(path):
    rng = np.random.default_rng(3)
    side, atoms, bonds = 16.0, [], []
    tag = 0
    for chain in range(20):
        start = rng.uniform(0, side, 3)
        direction = rng.normal(size=3)
        direction /= np.linalg.norm(direction)
        for k in range(8):
            tag += 1
            x = (start + k * 0.97 * direction + rng.normal(scale=0.05, size=3)) % side
            atoms.append(f"{tag} {chain + 1} {1 + k % 2} {x[0]:.10f} {x[1]:.10f} {x[2]:.10f}")
            if k:
                bonds.append(f"{len(bonds) + 1} {1 + k % 2} {tag - 1} {tag}")
    v = rng.normal(scale=0.5, size=(tag, 3))
    lines = ["chains of 8 beads", "", f"{tag} atoms", "2 atom types", f"{len(bonds)} bonds", "2 bond types",
             "1 extra bond per atom", "", f"0 {side} xlo xhi", f"0 {side} ylo yhi", f"0 {side} zlo zhi", "",
             "Masses", "", "1 1.0", "2 1.5", "", "Atoms # bond", "", *atoms, "", "Velocities", "",
             *[f"{i + 1} {v[i, 0]:.10f} {v[i, 1]:.10f} {v[i, 2]:.10f}" for i in range(tag)], "", "Bonds", "", *bonds]
    Path(path).write_text("\n".join(lines) + "\n")


def script(bond_lines, run=200):
    return "\n".join(["units lj", "atom_style bond", "read_data chains.data", "pair_style soft 2.5",
                      "pair_coeff * * 5.0", bond_lines, "fix 1 all nve", "timestep 0.002", "thermo 50",
                      "thermo_style custom step temp pe ebond press", "thermo_modify format float %.15g",
                      f"run {run}", ""])


def main(lmp):
    DATA.mkdir(parents=True, exist_ok=True)
    write_chains(DATA / "chains.data")
    scripts = {case: script(lines) for case, lines in CASES.items()}
    record_cases(lmp, scripts, [DATA / "chains.data"], DATA / "bonds.txt")
    write_case_table(DATA / "bonds.cases.json", __file__, "bonds.txt", ["chains.data"], scripts,
                     ranks=("harmonic", "delete_bonds", "hybrid"))
    run_lammps(lmp, script(LOCAL), [DATA / "chains.data"], "bond_local", outputs={"bonds.txt": DATA / "bond_local.txt"})


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
