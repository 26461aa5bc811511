"""Record LAMMPS's thermo for short runs with the fixes of plugins/fix_simple and fix_granular's addforce,
setforce, aveforce, lineforce, planeforce, spring/self, drag, viscous and gravity, fix nve/noforce and fix move, the reference
plugins/fix_simple/tests/test_lammps_fixes.py compares pdps with.

    python benchmarks/lammps_references/fixes.py [LMP]

The scene is plugins/fix_simple/tests/data/fluid.data (a copy of pair_simple's: 200 particles of two
types with Gaussian velocities and a net momentum), lj/cut 2.5, fix nve, dt 0.002, 100 steps with
each case's fix; thermo (step temp pe press, 15 digits) every 25 steps, and fix print's lines, go to
plugins/fix_simple/tests/data/fixes.txt.
"""

import sys
from pathlib import Path

from lammps_run import run_lammps, thermo_lines, write_case_table

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "fix_simple" / "tests" / "data"
# the heavy particles moved by fix move, the light ones integrated
MOVED = "group heavy type 2\ngroup light type 1\nunfix 1\nfix 1 light nve\n"
CASES = {
    "rescale": "fix 2 all temp/rescale 10 1.0 2.0 0.05 0.5",
    "berendsen": "fix 2 all temp/berendsen 1.5 1.0 0.1",
    "momentum": "fix 2 all momentum 20 linear 1 1 0 angular rescale",
    "momentum_linear": "group heavy type 2\nfix 2 heavy momentum 10 linear 1 1 1",
    "print": 'fix 2 all print 25 "PRINTED $(step) $(temp:%.12f) $(pe:%.12f)"',
    "addforce": "variable fx equal 0.3*cos(0.05*step)\nfix 2 all addforce v_fx -0.2 0.1",
    "setforce": "group heavy type 2\nfix 2 heavy setforce 0.0 NULL 0.5",
    "viscous": "fix 2 all viscous 0.8 scale 2 2.5",
    "gravity": "fix 2 all gravity 1.5 vector 1 -2 0.5",
    "aveforce": "group heavy type 2\nvariable fz equal 0.2*sin(0.1*step)\nfix 2 heavy aveforce NULL 0.0 v_fz",
    "aveforce_region": "region low block INF INF INF INF INF 3 units box\nfix 2 all aveforce 0.1 NULL NULL region low",
    "lineforce": "fix 2 all lineforce 1 1 0",
    "planeforce": "fix 2 all planeforce 0 0 1",
    "spring_self": "fix 2 all spring/self 20.0\nfix_modify 2 energy yes",
    "spring_self_xy": "group heavy type 2\nfix 2 heavy spring/self 50.0 xy\nfix_modify 2 energy yes",
    "drag": "group heavy type 2\nfix 2 heavy drag 1.0 NULL 3.0 0.8 0.5",
    "nve_noforce": "group heavy type 2\ngroup light type 1\nunfix 1\nfix 1 light nve\nfix 2 heavy nve/noforce",
    "move_linear": MOVED + "lattice fcc 0.8442\nfix 2 heavy move linear 0.5 NULL -0.2",
    "move_wiggle": MOVED + "fix 2 heavy move wiggle 0.3 NULL 0.1 1.0 units box",
    "move_rotate": MOVED + "fix 2 heavy move rotate 0.5 0.5 0.5 1 0 0 30.0",
    "move_rotate_lattice": MOVED + "lattice sc 1.1\nfix 2 heavy move rotate 3.4 3.4 3.4 0 1 1 20.0",
    "move_variable": MOVED + "variable dx equal 0.1*sin(10*time)\nvariable vx equal cos(10*time)\n"
                             "fix 2 heavy move variable v_dx NULL NULL v_vx NULL NULL",
    "move_variable_atom": MOVED + "variable dy atom 0.05*x*sin(5*time)\nvariable vz atom 0.02*y\n"
                                  "fix 2 heavy move variable NULL v_dy NULL NULL NULL v_vz",
}
SETUP = ["units lj", "atom_style atomic", "read_data fluid.data", "pair_style lj/cut 2.5", "pair_coeff 1 1 1.0 1.0",
         "pair_coeff 2 2 0.5 1.2", "fix 1 all nve", "timestep 0.002"]


def script(case):
    return "\n".join(SETUP + [CASES[case], "thermo 25", "thermo_style custom step temp pe press",
                              "thermo_modify format float %.15g", "run 100", ""])


def write_tables():
    write_case_table(DATA / "fixes.cases.json", __file__, "fixes.txt", ["fluid.data"],
                     {case: script(case) for case in CASES}, ranks=("momentum",),
                     restart=("rescale", "berendsen", "viscous", "spring_self"))


def main(lmp):
    rows = []
    for case in CASES:
        log = run_lammps(lmp, script(case), [DATA / "fluid.data"], case)
        # fix print's lines, from the whole log: the first step's comes before the thermo header
        printed = [line.split()[1:] for line in log.splitlines() if line.startswith("PRINTED")]
        for words in thermo_lines(log):
            if words[0] == "PRINTED":
                continue
            while printed and int(printed[0][0]) <= int(words[0]):
                rows.append(f"{case}\tprint\t" + "\t".join(printed.pop(0)))
            rows.append(f"{case}\t" + "\t".join(words))
    (DATA / "fixes.txt").write_text("\n".join(rows) + "\n")
    write_tables()
    print("\n".join(rows))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
