"""Record LAMMPS's computes pe, pe/atom, stress/atom, ke/atom and vacf on a short NVE run, the
reference plugins/compute_energy/tests/test_lammps_computes.py compares pdps with.

    python benchmarks/lammps_references/computes.py [LMP]

The scene is pair_styles.py's 200-particle two-type fluid (copied to
plugins/compute_energy/tests/data/fluid.data) with lj/cut 2.5 (mixed 1 2 pair), 100 steps of fix nve at
dt 0.002. LAMMPS's thermo (15 digits) every 25 steps goes to computes_thermo.txt; its per-particle
values at steps 0 and 100 (dump custom, 17 digits, sorted by id) to computes_step0.dump and
computes_step100.dump, all in plugins/compute_energy/tests/data.
"""

import shutil
import sys
from pathlib import Path

from lammps_run import run_lammps, thermo_lines, write_case_table

ROOT = Path(__file__).resolve().parents[2]
SOURCE = ROOT / "plugins" / "pair_simple" / "tests" / "data" / "fluid.data"
DATA = ROOT / "plugins" / "compute_energy" / "tests" / "data"
SETUP = """units lj
atom_style atomic
read_data fluid.data
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0
pair_coeff 2 2 0.5 1.2 2.0
group heavy type 2
compute pe all pe
compute pep all pe pair
compute pea all pe/atom
compute peh heavy pe/atom pair
compute s all stress/atom NULL
compute sv all stress/atom NULL virial
compute sk heavy stress/atom NULL ke
compute ka all ke/atom
compute vacf all vacf
compute vh heavy vacf
compute sums all reduce sum c_pea c_s[1] c_s[2] c_s[3] c_sv[1] c_sv[2] c_sv[3] c_ka
fix 1 all nve
timestep 0.002
thermo 25
"""
THERMO = ("thermo_style custom step temp pe press c_pe c_pep c_vacf[1] c_vacf[2] c_vacf[3] c_vacf[4] c_vh[4] "
          "c_sums[1] c_sums[2] c_sums[3] c_sums[4] c_sums[5] c_sums[6] c_sums[7] c_sums[8]")
COLUMNS = "id c_pea c_peh c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6] c_sv[1] c_sv[4] c_sk[1] c_sk[6] c_ka"


def script():
    return SETUP + THERMO + "\nthermo_modify format float %.15g\n" + \
        f"dump d all custom 100 step*.dump {COLUMNS}\ndump_modify d sort id format float %.17g\nrun 100\n"


def write_tables():
    write_case_table(DATA / "computes.cases.json", __file__, "computes_thermo.txt", ["fluid.data"],
                     {"computes": script()}, ranks=("computes",))


def main(lmp):
    DATA.mkdir(parents=True, exist_ok=True)
    shutil.copy(SOURCE, DATA / "fluid.data")
    log = run_lammps(lmp, script(), [SOURCE], outputs={f"step{step}.dump": DATA / f"computes_step{step}.dump"
                                                       for step in (0, 100)})
    rows = ["computes\t" + "\t".join(words) for words in thermo_lines(log)]
    (DATA / "computes_thermo.txt").write_text("\n".join(rows) + "\n")
    write_tables()
    print("\n".join(rows))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
