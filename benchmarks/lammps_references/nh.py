"""Record LAMMPS's thermo for short runs with fix nvt, npt, nph, deform, the LJ walls,
wall/harmonic and wall/reflect (fixed, lattice-scaled and variable), the reference plugins/fix_nh/tests/test_lammps_nh.py and
plugins/fix_wall/tests/test_wall_lj.py compare pdps with.

    python benchmarks/lammps_references/nh.py [LMP]

The scene is plugins/fix_nh/tests/data/fluid.data (200 particles of two types with Gaussian
velocities and a net momentum, a copy of pair_simple's), lj/cut 2.5, dt 0.002, 100 steps with each
case's integrator; thermo (step temp pe press vol lx ly lz, 15 digits) every 25 steps goes to
plugins/fix_nh/tests/data/nh.txt; thermo step etotal ecouple econserve f_1 of four of them to
data/ecouple.txt. The runs are deterministic (no random numbers), so pdps must give
these digits to round-off grown by the fluid's chaos over 100 steps. The walls' scenes (WALL_CASES,
thermo step temp pe press f_2 f_2[1] f_2[2]) use walls.data, written here from fluid.data, and go to
plugins/fix_wall/tests/data/wall_lj.txt.

OPTION_CASES are the keywords added later (ptemp, disc, flip, fix_modify temp and press; deform
volume, wiggle and variable), recorded alike into plugins/fix_nh/tests/data/nh_options.txt so that
the files above stay as they were; the cases named *_2d run a 2-d fluid (plane.data, 144 particles
on a square lattice with seeded Gaussian velocities, written here).
"""

import random
import sys
from pathlib import Path

from lammps_run import run_lammps, thermo_table, write_case_table

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "fix_nh" / "tests" / "data"
WALL_DATA = ROOT / "plugins" / "fix_wall" / "tests" / "data"
THERMO = "step temp pe press vol lx ly lz"
CASES = {
    "nvt": "fix 1 all nvt temp 1.0 1.0 0.1",
    "nvt_ramp": "fix 1 all nvt temp 1.0 2.0 0.05 tchain 5 tloop 3 drag 0.5",
    "nvt_group": "group light type 1\nfix 1 light nvt temp 1.5 1.5 0.1\nfix 2 all nve\nunfix 2\n"
                 "group heavy type 2\nfix 3 heavy nve",
    "npt_iso": "fix 1 all npt temp 1.0 1.0 0.1 iso 0.5 0.5 0.5",
    "npt_aniso": "fix 1 all npt temp 1.0 1.0 0.1 aniso 0.5 0.5 0.5",
    "npt_xyz": "fix 1 all npt temp 1.0 1.0 0.1 x 0.5 0.5 0.5 y 0.3 0.3 0.7 z 0.8 0.2 1.0 nreset 20",
    "npt_couple": "fix 1 all npt temp 1.2 0.8 0.2 aniso 0.5 1.0 0.5 couple xy tchain 4 pchain 2 tloop 2 ploop 3 drag 0.2",
    "nph_iso": "fix 1 all nph iso 0.5 0.5 0.5",
    "nph_aniso": "fix 1 all nph aniso 0.5 0.5 0.5 mtk no pchain 0",
    # a particle the box change does not carry (dilate GROUP, deform remap none) sits in whichever
    # periodic image it was last wrapped into, and x + L_old is not x + L_new: the trajectory depends
    # on when particles are wrapped (at LAMMPS's neighbor builds; at pdps's, which include every step
    # the box changed). Both wrap every step here, so both integrate the same scene
    "nph_dilate": "group light type 1\nneigh_modify every 1 delay 0 check no\n"
                  "fix 1 all nph iso 8.0 8.0 2.0 dilate light fixedpoint 1 2 3",
    "deform_erate": "fix 1 all nve\nfix 2 all deform 1 x erate 0.5 remap x units box",
    "deform_final": "neigh_modify every 1 delay 0 check no\nfix 1 all nve\n"
                    "fix 2 all deform 5 y final -0.5 7.5 z scale 0.95 remap none",
    "deform_delta": "fix 1 all nve\nfix 2 all deform 2 x delta -0.3 0.2 y trate -0.2",
    # LAMMPS changes a velocity when it wraps the particle, at its own neighbor list builds: every
    # step here, as pdps wraps on every step the box changes
    "deform_vremap": "neigh_modify every 1 delay 0 check no\nfix 1 all nve\n"
                     "fix 2 all deform 1 x vel 1.0 z trate 0.3 remap v",
    "deform_npt": "fix 1 all npt temp 1.0 1.0 0.1 x 0.5 0.5 0.5 y 0.5 0.5 0.5 couple xy\n"
                  "fix 2 all deform 1 z erate -0.3 units box",
}
# walls on the z faces: the fluid with z fixed, particles within 0.8 of a z face left out (walls.data)
WALL_CASES = {
    "lj93": "fix 1 all nve\nfix 2 all wall/lj93 zlo EDGE 1.0 1.0 2.5 zhi EDGE 1.5 0.8 2.0 units box\n"
            "fix_modify 2 energy yes virial yes",
    "lj126": "variable top equal 6.9-0.5*step*dt\nfix 1 all nve\n"
             "fix 2 all wall/lj126 zlo 0.1 1.0 1.0 2.5 zhi v_top 0.7 1.1 1.2345\nfix_modify 2 energy yes",
    "lj93_pbc": "fix 1 all nve\nfix 2 all wall/lj93 xhi 7.5 0.1 1.0 1.0 zhi EDGE 2.0 1.0 1.0 pbc yes units box\n"
                "fix_modify 2 virial yes",
    "harmonic": "fix 1 all nve\nfix 2 all wall/harmonic zlo EDGE 20.0 1.0 1.2 zhi 6.5 5.0 1.0 1.0 units box\n"
                "fix_modify 2 energy yes virial yes",
    # a fixed reflecting wall inside the fluid's lowest layer and one closing in from the top
    "reflect": "variable top equal 6.9-5.0*step*dt\nfix 1 all nve\n"
               "fix 2 all wall/reflect zlo 0.9 zhi v_top units box",
    "reflect_lattice": "lattice sc 0.5\nfix 1 all nve\nfix 2 all wall/reflect zlo EDGE zhi 4.9",
}
WALL_THERMO = "step temp pe press f_2 f_2[1] f_2[2]"
# the walls with no energy or force of their own print the fluid's
WALL_COLUMNS = {"reflect": "step temp pe press c_top c_low", "reflect_lattice": "step temp pe press c_top"}
WALL_COMPUTES = "compute top all reduce max z\ncompute low all reduce min z\n"
SETUP = ["units lj", "atom_style atomic", "read_data fluid.data", "pair_style lj/cut 2.5", "pair_coeff 1 1 1.0 1.0",
         "pair_coeff 2 2 0.5 1.2", "timestep 0.002"]


# the keywords added later; *_2d cases run on plane.data (dimension 2)
LIGHT = "group light type 1\ngroup heavy type 2\ncompute light_t light temp\ncompute heavy_t heavy temp\n"
OPTION_CASES = {
    "nph_ptemp": "fix 1 all nph iso 0.5 0.5 0.5 ptemp 2.5",
    "nph_aniso_ptemp": "fix 1 all nph aniso 0.5 0.5 0.3 ptemp 0.4 pchain 2",
    "npt_flip": "fix 1 all npt temp 1.0 1.0 0.1 aniso 0.5 0.5 0.5 flip no",
    "nvt_disc": "fix 1 all nvt temp 1.0 1.0 0.1 disc",
    # the fix reads another temperature (the thermostat still scales all particles)
    "nvt_modify_temp": LIGHT + "fix 1 all nvt temp 1.0 1.0 0.1\nfix_modify 1 temp light_t",
    # ... and its pressure too
    "npt_modify_temp": LIGHT + "fix 1 all npt temp 1.0 1.0 0.1 iso 0.5 0.5 0.5\nfix_modify 1 temp light_t",
    "npt_modify_temp_aniso": LIGHT + "fix 1 all npt temp 1.0 1.0 0.1 aniso 0.5 0.5 0.5 couple xy\n"
                                     "fix_modify 1 temp light_t",
    # a pressure compute with its own temperature, another compute than the fix's
    "nph_modify_press": "compute my_t all temp\ncompute my_p all pressure my_t\nfix 1 all nph aniso 0.5 0.5 0.5\n"
                        "fix_modify 1 press my_p",
    "npt_modify_press": LIGHT + "compute light_p all pressure light_t\n"
                                "fix 1 all npt temp 1.0 1.0 0.1 iso 0.5 0.5 0.5\nfix_modify 1 press light_p",
    # temp then press: the pressure keeps heavy_t; press then temp: LAMMPS points heavy_p at light_t
    "npt_modify_temp_press": LIGHT + "compute heavy_p all pressure heavy_t\n"
                                     "fix 1 all npt temp 1.0 1.0 0.1 iso 0.5 0.5 0.5\n"
                                     "fix_modify 1 temp light_t press heavy_p",
    "npt_modify_press_temp": LIGHT + "compute heavy_p all pressure heavy_t\n"
                                     "fix 1 all npt temp 1.0 1.0 0.1 aniso 0.5 0.5 0.5\n"
                                     "fix_modify 1 press heavy_p\nfix_modify 1 temp light_t",
    "deform_volume": "fix 1 all nve\nfix 2 all deform 1 x erate 0.5 y volume remap x units box",
    "deform_volume_two": "fix 1 all nve\nfix 2 all deform 1 x volume y trate -0.4 z volume",
    "deform_volume_three": "fix 1 all nve\nfix 2 all deform 2 x erate 0.3 y scale 0.9 z volume units box",
    "deform_volume_vremap": "neigh_modify every 1 delay 0 check no\nfix 1 all nve\n"
                            "fix 2 all deform 1 x delta -0.4 0.3 y erate 0.3 z volume remap v units box",
    "deform_wiggle": "fix 1 all nve\nfix 2 all deform 1 x wiggle 0.8 0.15 y wiggle -0.5 0.4 units box",
    # units lattice: the amplitude in lattice spacings (1.077 for sc at reduced density 0.8)
    "deform_wiggle_vremap": "lattice sc 0.8\nneigh_modify every 1 delay 0 check no\nfix 1 all nve\n"
                            "fix 2 all deform 2 z wiggle 0.5 0.3 remap v",
    "deform_variable": "variable dl equal 2.0*(step*0.002)^2\nvariable rate equal 4.0*step*0.002\n"
                       "neigh_modify every 1 delay 0 check no\nfix 1 all nve\n"
                       "fix 2 all deform 1 x variable v_dl v_rate y volume remap v",
    "deform_nph_ptemp": "fix 1 all nph x 0.5 0.5 0.5 y 0.5 0.5 0.5 ptemp 1.5\n"
                        "fix 2 all deform 1 z wiggle 0.4 0.2 units box",
    "npt_disc_2d": "fix 1 all npt temp 1.0 1.0 0.1 iso 0.5 0.5 0.5 disc",
    "nph_ptemp_2d": "fix 1 all nph aniso 0.3 0.3 0.5 ptemp 1.5 disc",
    "deform_volume_2d": "fix 1 all nve\nfix 2 all deform 1 x erate 0.4 y volume units box",
}

# the reservoirs' energy: thermo ecouple, econserve and the fix's scalar, for these cases
ECOUPLE_CASES = ("nvt_ramp", "npt_aniso", "npt_xyz", "nph_iso")
ECOUPLE_THERMO = "step etotal ecouple econserve f_1"


def script(case, thermo=THERMO):
    return "\n".join(SETUP + [CASES[case], "thermo 25", f"thermo_style custom {thermo}", "run 100"])


def option_script(case):
    """The script of an OPTION_CASES case: the fluid of fluid.data, or in 2-d of plane.data."""
    lines = SETUP + [OPTION_CASES[case], "thermo 25", f"thermo_style custom {THERMO}", "run 100"]
    if case.endswith("_2d"):
        lines = ["dimension 2"] + [line.replace("fluid.data", "plane.data") for line in lines]
    return "\n".join(lines)


def plane_data():
    """144 particles of two types on a 12 x 12 square lattice (spacing 1.15) in a periodic 2-d box,
    velocities Gaussian (seed 2025, unit variance, no z part): LAMMPS's data format."""
    n, spacing = 12, 1.15
    side = repr(n * spacing)
    draw = random.Random(2025)
    atoms, velocities = [], []
    for k in range(n * n):
        i, j = divmod(k, n)
        atoms.append(f"{k + 1} {1 + (i + j) % 2} {repr((i + 0.5) * spacing)} {repr((j + 0.5) * spacing)} 0.0")
        velocities.append(f"{k + 1} {repr(draw.gauss(0.0, 1.0))} {repr(draw.gauss(0.0, 1.0))} 0.0")
    return "\n".join(["written by benchmarks/lammps_references/nh.py", "", f"{n * n} atoms", "2 atom types", "",
                      f"0 {side} xlo xhi", f"0 {side} ylo yhi", "-0.5 0.5 zlo zhi", "", "Masses", "", "1 1",
                      "2 1.5", "", "Atoms # atomic", ""] + atoms + ["", "Velocities", ""] + velocities) + "\n"


def wall_script(case):
    return "\n".join(["units lj", "atom_style atomic", "boundary p p f", "read_data walls.data",
                      "pair_style lj/cut 2.5", "pair_coeff 1 1 1.0 1.0", "pair_coeff 2 2 0.5 1.2",
                      "timestep 0.002", WALL_CASES[case], WALL_COMPUTES + "thermo 25",
                      f"thermo_style custom {WALL_COLUMNS.get(case, WALL_THERMO)}", "run 100"])


def wall_data():
    """fluid.data with the particles within 0.8 of a z face left out (their ids kept)."""
    lines = (DATA / "fluid.data").read_text().splitlines()
    lz = float(next(line for line in lines if line.endswith("zlo zhi")).split()[1])
    kept, section, out = set(), None, []
    for line in lines:
        words = line.split()
        if words[:1] in (["Atoms"], ["Velocities"], ["Masses"]):
            section = words[0]
        elif section == "Atoms" and len(words) >= 5:
            if not 0.8 <= float(words[4]) <= lz - 0.8:
                continue
            kept.add(words[0])
        elif section == "Velocities" and len(words) >= 4 and words[0] not in kept:
            continue
        out.append(line)
    text = "\n".join(out) + "\n"
    return text.replace("200 atoms", f"{len(kept)} atoms")


def as_run(text):
    """The script as LAMMPS runs it: thermo printed to 15 digits."""
    return text.replace("run 100", "thermo_modify format float %.15g\nrun 100") + "\n"


def thermo_lines(lmp, text, files, label):
    """LAMMPS's first five thermo lines of ``text`` (15 digits, tab-separated), run with ``files``."""
    return ["\t".join(words) for words in thermo_table(run_lammps(lmp, as_run(text), files, label))[1][:5]]


def write_tables():
    tolerance = {"rtol": 1e-8, "atol": 1e-10}
    write_case_table(DATA / "nh.cases.json", __file__, "nh.txt", ["fluid.data"],
                     {case: as_run(script(case)) for case in CASES}, ranks=("npt_aniso",),
                     restart=("nvt", "npt_aniso", "nph_iso"), **tolerance)
    write_case_table(DATA / "ecouple.cases.json", __file__, "ecouple.txt", ["fluid.data"],
                     {case: as_run(script(case, ECOUPLE_THERMO)) for case in ECOUPLE_CASES}, **tolerance)
    write_case_table(WALL_DATA / "wall_lj.cases.json", __file__, "wall_lj.txt", ["walls.data"],
                     {case: as_run(wall_script(case)) for case in WALL_CASES}, ranks=("lj93",),
                     restart=("harmonic",), **tolerance)
    write_case_table(DATA / "nh_options.cases.json", __file__, "nh_options.txt", ["fluid.data", "plane.data"],
                     {case: as_run(option_script(case)) for case in OPTION_CASES},
                     ranks=("npt_modify_temp_press", "deform_variable"), **tolerance)


def main(lmp):
    fluid = DATA / "fluid.data"
    rows = [f"{case}\t{line}" for case in CASES for line in thermo_lines(lmp, script(case), [fluid], case)]
    (DATA / "nh.txt").write_text("\n".join(rows) + "\n")
    coupled = [f"{case}\t{line}" for case in ECOUPLE_CASES
               for line in thermo_lines(lmp, script(case, ECOUPLE_THERMO), [fluid], case)]
    (DATA / "ecouple.txt").write_text("\n".join(coupled) + "\n")
    rows += coupled
    (WALL_DATA / "walls.data").write_text(wall_data())
    wall_rows = [f"{case}\t{line}" for case in WALL_CASES
                 for line in thermo_lines(lmp, wall_script(case), [WALL_DATA / "walls.data"], case)]
    (WALL_DATA / "wall_lj.txt").write_text("\n".join(wall_rows) + "\n")
    (DATA / "plane.data").write_text(plane_data())
    option_rows = [f"{case}\t{line}" for case in OPTION_CASES
                   for line in thermo_lines(lmp, option_script(case), [fluid, DATA / "plane.data"], case)]
    (DATA / "nh_options.txt").write_text("\n".join(option_rows) + "\n")
    write_tables()
    print("\n".join(rows + wall_rows + option_rows))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
