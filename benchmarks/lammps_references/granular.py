"""Record LAMMPS's answers for its composed granular contacts (pair_style granular; fix wall/gran
granular), which plugins/pair_gran/tests/test_granular.py compares pdps with.

    python benchmarks/lammps_references/granular.py [LMP]

Besides, a bed of 288 spheres (pdps_core.testing.sphere_bed) settling on walls under gravity with
several laws (BED_CASES): LAMMPS's thermo (step ke c_rke, 15 digits, every 250 of 1,500 steps) goes
to plugins/pair_gran/tests/data/granular_bed.txt with the table granular.cases.json, which
tests/test_recorded_thermo.py runs. Its scripts say ``newton off`` and ``atom_modify sort 0 0.0``:
LAMMPS then keeps which sphere holds each contact, as its negated rolling and twist history needs
for its numbers not to depend on its atom order (docs/lammps.md).

Each case (CASES below) is two or three spheres colliding, pressed together or pulled apart, every
particle's start in the data file; NAME.in, NAME.data and NAME.ref (LAMMPS's positions, velocities
and spins every EVERY steps, 17 digits) go to plugins/pair_gran/tests/data/granular, written as
gran.py writes its cases (``write_case``, ``record_case``).
"""

import sys
from pathlib import Path

from pdps_core.testing import sphere_bed

sys.path.insert(0, str(Path(__file__).parent))
from gran import ROOT, UNIT_MASS, record_case  # noqa: E402
from lammps_run import record_cases, write_case_table  # noqa: E402

DATA = ROOT / "plugins" / "pair_gran" / "tests" / "data" / "granular"
WALL_DATA = ROOT / "plugins" / "fix_wall" / "tests" / "data" / "wall_granular"
BOX = dict(folder=DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p p")
# an oblique collision with spin about every axis: sliding, rolling and twisting all act
OBLIQUE = [(1, 1.0, 2.0, (4.5, 5.0, 5.0), (1.0, 0.3, 0.0), (3.0, 1.0, 5.0)),
           (1, 1.4, 1.0, (5.7, 5.25, 5.0), (-0.5, 0.0, 0.2), (1.0, -2.0, 4.0))]
HEAD_ON = [(1, 1.0, UNIT_MASS, (4.49, 5.0, 5.0), (1.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
           (1, 1.0, UNIT_MASS, (5.51, 5.0, 5.0), (-1.0, 0.0, 0.0), (0.0, 0.0, 0.0))]
MATERIAL = "1.0e5 {damp} 0.3"


def pair_case(coeff, particles=OBLIQUE, steps=1500, every=50, extra=()):
    return dict(BOX, particles=particles, lines=["pair_style granular", f"pair_coeff * * {coeff}", *extra,
                                                 "fix 1 all nve/sphere"], steps=steps, every=every)


CASES = {
    "hooke_mass_velocity_linear_history": pair_case(
        "hooke 200000.0 50.0 damping mass_velocity tangential linear_history 57142.9 0.5 0.5"),
    "hooke_velocity_linear_nohistory": pair_case(
        "hooke 200000.0 20.0 damping velocity tangential linear_nohistory 0.5 0.3"),
    "hooke_coeff_restitution_head_on": pair_case(
        "hooke 200000.0 0.6 damping coeff_restitution tangential linear_history 57142.9 1.0 0.5", HEAD_ON, 300, 15),
    "hertz_viscoelastic_mindlin": pair_case(
        "hertz 200000.0 500.0 tangential mindlin 150000.0 1.0 0.4"),
    "hertz_limit_damping": pair_case(
        "hertz 200000.0 4000.0 tangential linear_history 57142.9 0.5 0.5 limit_damping"),
    "material_coeff_restitution_mindlin_null": pair_case(
        f"hertz/material {MATERIAL.format(damp=0.5)} damping coeff_restitution tangential mindlin NULL 1.0 0.5"),
    "material_tsuji_mindlin_force": pair_case(
        f"hertz/material {MATERIAL.format(damp=0.7)} damping tsuji tangential mindlin/force NULL 0.5 0.3"),
    "material_velocity_mindlin_rescale": pair_case(
        f"hertz/material {MATERIAL.format(damp=10.0)} damping velocity tangential mindlin_rescale NULL 1.0 0.4"),
    "material_mass_velocity_mindlin_rescale_force": pair_case(
        f"hertz/material {MATERIAL.format(damp=30.0)} damping mass_velocity tangential mindlin_rescale/force "
        "NULL 1.0 0.4"),
    "material_rolling_twisting_sds": pair_case(
        f"hertz/material {MATERIAL.format(damp=0.5)} damping coeff_restitution tangential mindlin NULL 1.0 0.5 "
        "rolling sds 500.0 2.0 0.1 twisting sds 50.0 0.5 0.05"),
    "material_twisting_marshall": pair_case(
        f"hertz/material {MATERIAL.format(damp=500.0)} tangential mindlin NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 "
        "twisting marshall"),
    "dmt_rolling_twisting": pair_case(
        "dmt 1.0e5 500.0 0.3 5.0 tangential mindlin NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 twisting marshall"),
    "jkr_oblique": pair_case(
        "jkr 1.0e5 500.0 0.3 5.0 tangential mindlin NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 twisting sds 50.0 0.5 "
        "0.05"),
    # two unit spheres just touching, pulled apart by opposite forces above JKR's pull-off force
    # 3 pi gamma R* = 23.6 (gamma 10): the neck stretches beyond touching, then breaks
    "jkr_pull_off": dict(
        BOX, particles=[(1, 1.0, UNIT_MASS, (4.5, 5.0, 5.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
                        (1, 1.0, UNIT_MASS, (5.4995, 5.0, 5.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))],
        lines=["pair_style granular", "pair_coeff * * jkr 1.0e5 200.0 0.3 10.0 tangential linear_history 1000.0 "
               "0.5 0.5", "group left id 1", "group right id 2", "fix 1 all nve/sphere",
               "fix 2 left addforce -25.0 0.0 0.0", "fix 3 right addforce 25.0 0.0 0.0"],
        steps=3000, every=100),
    # types 1 and 2 of different materials, pair_coeff 1 1 and 2 2 only: 1 2 mixed as LAMMPS mixes
    "material_two_types_mixed": dict(
        BOX, particles=[(1, 1.0, UNIT_MASS, (3.9, 5.0, 5.0), (2.0, 0.0, 0.1), (0.0, 1.0, 0.0)),
                        (2, 1.0, 1.5, (4.95, 5.05, 5.0), (0.0, 0.0, 0.0), (0.0, 0.0, -3.0)),
                        (2, 1.2, 1.0, (5.9, 5.6, 5.02), (0.0, -0.2, 0.0), (2.0, 0.0, 0.0))],
        lines=["pair_style granular",
               "pair_coeff 1 1 hertz/material 1.0e5 0.5 0.3 damping coeff_restitution tangential mindlin NULL 1.0 0.5 "
               "rolling sds 500.0 2.0 0.1",
               "pair_coeff 2 2 hertz/material 3.0e5 0.8 0.2 damping coeff_restitution tangential mindlin NULL 0.5 0.3 "
               "rolling sds 800.0 1.0 0.2",
               "fix 1 all nve/sphere"], steps=2000, every=50),
    # ---- walls (fix wall/gran granular): no pair style ----
    "wall_zplane_settle_law": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p f",
        particles=[(1, 1.0, UNIT_MASS, (3.0, 5.0, 0.52), (2.0, 0.0, -0.5), (0.0, 3.0, 1.0)),
                   (1, 1.4, 0.8, (7.0, 5.0, 0.75), (0.0, -1.0, -0.2), (1.0, 0.0, 2.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 0.0 0.0 -1.0",
               f"fix 3 all wall/gran granular hertz/material 1.0e5 0.5 0.3 tangential mindlin NULL 1.0 0.5 rolling "
               f"sds 500.0 2.0 0.1 damping coeff_restitution zplane 0.0 NULL"],
        steps=3000, every=150),
    "wall_xplanes_hooke_twisting": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="f p p",
        particles=[(1, 1.0, UNIT_MASS, (7.45, 5.0, 5.0), (1.5, 0.4, 0.2), (3.0, 2.0, 3.0)),
                   (1, 1.0, UNIT_MASS, (2.6, 5.0, 5.0), (-1.0, 0.0, 0.3), (-2.0, 0.0, 1.0))],
        lines=["fix 1 all nve/sphere",
               "fix 3 all wall/gran granular hooke 200000.0 50.0 damping mass_velocity tangential linear_history "
               "57142.9 0.5 0.4 twisting sds 50.0 0.5 0.05 limit_damping xplane 2.0 8.0"],
        steps=2000, every=100),
    "wall_zcylinder_dmt_marshall": dict(
        folder=WALL_DATA, box=(-5, 5, -5, 5, 0, 10), boundary="f f p",
        particles=[(1, 1.0, UNIT_MASS, (3.45, 0.0, 5.0), (1.0, 0.5, 0.3), (0.0, 1.0, 2.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 1.0 0.2 0.0",
               "fix 3 all wall/gran granular dmt 1.0e5 500.0 0.3 5.0 tangential mindlin_rescale NULL 1.0 0.5 "
               "rolling sds 500.0 2.0 0.1 twisting marshall zcylinder 4.0"],
        steps=2000, every=100),
    "wall_yplane_shear_tsuji": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p f p",
        particles=[(1, 1.0, UNIT_MASS, (5.0, 1.499, 5.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 0.0 -1.0 0.0",
               "fix 3 all wall/gran granular hertz/material 1.0e5 0.7 0.3 damping tsuji tangential mindlin/force "
               "NULL 1.0 0.4 yplane 1.0 9.0 shear x 0.5"],
        steps=2000, every=100),
    # ---- region walls (fix wall/gran/region granular) ----
    "region_block_corner": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="f f f",
        particles=[(1, 1.0, UNIT_MASS, (1.6, 5.0, 1.02), (-1.0, 0.6, -0.3), (0.0, 3.0, 1.0)),
                   (1, 1.2, 0.8, (8.3, 8.2, 1.1), (0.8, 0.9, -0.2), (1.0, -2.0, 2.0))],
        lines=["region cup block 1.0 9.0 1.0 9.0 0.5 9.0 units box", "fix 1 all nve/sphere",
               "fix 2 all addforce 0.0 0.0 -1.0",
               "fix 3 all wall/gran/region granular hertz/material 1.0e5 0.5 0.3 damping coeff_restitution "
               "tangential mindlin NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 twisting marshall region cup"],
        steps=3000, every=150),
    "region_block_obstacle_hooke": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="f f f",
        particles=[(1, 1.0, UNIT_MASS, (3.45, 5.2, 6.3), (1.0, 0.0, -0.6), (0.0, 0.0, 2.0))],
        lines=["region rock block 4.0 6.0 4.0 6.0 4.0 6.0 side out units box", "fix 1 all nve/sphere",
               "fix 3 all wall/gran/region granular hooke 200000.0 50.0 damping mass_velocity tangential "
               "linear_history 57142.9 0.5 0.4 region rock"],
        steps=3000, every=150),
}


BED_DATA = ROOT / "plugins" / "pair_gran" / "tests" / "data"
BED_LAWS = {
    "bed_jkr": ("jkr 1.0e5 500.0 0.3 1.0 tangential mindlin NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 twisting marshall",
                "pair_coeff * * {law}"),
    "bed_two_types": ("", "pair_coeff 1 1 hertz/material 1.0e5 0.5 0.3 damping coeff_restitution tangential mindlin "
                      "NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 twisting sds 50.0 0.5 0.05\n"
                      "pair_coeff 2 2 hertz/material 3.0e5 0.8 0.2 damping coeff_restitution tangential mindlin "
                      "NULL 0.5 0.3 rolling sds 800.0 1.0 0.2 twisting sds 30.0 0.3 0.1"),
    "bed_hooke_region": ("hooke 200000.0 50.0 damping mass_velocity tangential linear_history 57142.9 0.5 0.5 "
                         "limit_damping", "pair_coeff * * {law}"),
}
WALLS = {
    "bed_jkr": "fix w all wall/gran granular hertz/material 1.0e5 0.5 0.3 damping coeff_restitution tangential "
               "mindlin NULL 1.0 0.5 zplane 0.0 NULL",
    "bed_two_types": "fix w all wall/gran granular hertz/material 1.0e5 0.5 0.3 damping coeff_restitution tangential "
                     "mindlin_rescale NULL 1.0 0.5 rolling sds 500.0 2.0 0.1 zplane 0.0 NULL",
    "bed_hooke_region": "region cup block 0.0 15.6 0.0 7.8 0.0 20.0 units box\n"
                        "fix w all wall/gran/region granular hooke 200000.0 50.0 damping mass_velocity tangential "
                        "linear_history 57142.9 0.5 0.5 region cup",
}


def bed_script(case):
    law, coeff = BED_LAWS[case]
    return "\n".join(["units lj", "atom_style sphere", "boundary p p f", "newton off", "atom_modify sort 0 0.0",
                      "comm_modify vel yes", "read_data bed.data", "group low id 1:144", "set group low type 2", "pair_style granular",
                      coeff.format(law=law), "timestep 0.0001", "fix 1 all nve/sphere",
                      "fix 2 all gravity 10.0 vector 0 0 -1", WALLS[case], "compute rke all erotate/sphere",
                      "thermo_style custom step ke c_rke", "thermo_modify format float %.15g", "thermo 250",
                      "run 1500", ""])


def bed_cases(lmp):
    sphere_bed(BED_DATA / "bed.data", (12, 6, 4), (0.7, 0.7, 0.7), (0, 0, 0), (15.6, 7.8, 12), ntypes=2, seed=11)
    scripts = {case: bed_script(case) for case in BED_LAWS}
    record_cases(lmp, scripts, [BED_DATA / "bed.data"], BED_DATA / "granular_bed.txt")
    write_case_table(BED_DATA / "granular.cases.json", __file__, "granular_bed.txt", ["bed.data"], scripts,
                     rtol=1e-10, ranks=("bed_jkr",), restart=("bed_two_types",))


if __name__ == "__main__":
    command = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp")
    chosen = sys.argv[2:] or list(CASES) + ["beds"]
    for case_name in chosen:
        if case_name == "beds":
            bed_cases(command)
        else:
            record_case(command, case_name, CASES[case_name])
