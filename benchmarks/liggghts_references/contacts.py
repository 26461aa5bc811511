"""Record LIGGGHTS 3.8.0's answers for each of its contact sub-models (pair gran model ..., fix
wall/gran model ...), which plugins/pair_gran/tests/test_gran_submodels.py compares pdps with.

    python benchmarks/liggghts_references/contacts.py [LIGGGHTS]

Deterministic scenes, every particle's start in the script (pdps's own scripts, LIGGGHTS syntax):

- ``pair``: two spheres of two materials, already overlapping, meeting off-centre with spin
  (6000 steps of 1 us), under the model words of each case;
- ``wall``: a sphere dropped with spin onto a primitive zplane under gravity, rolling along it
  (20000 steps of 2 us), the wall's model words those of each case.

LIGGGHTS runs each script with a dump of x, v and omega of every particle at the last step (%.16e)
added before ``run``; the table (the scripts without the dump, the final states) goes to
plugins/pair_gran/tests/data/liggghts_submodels.json.
"""

import json
import subprocess
import sys
import tempfile
from pathlib import Path

from pdps_core.testing import liggghts_material

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "plugins" / "pair_gran" / "tests" / "data" / "liggghts_submodels.json"
LIGGGHTS = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "liggghts")

HEAD = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 2 reg
neighbor 0.002 bin
neigh_modify delay 0
"""

# every property any case reads: LIGGGHTS reads only those its models ask for
MATERIAL = liggghts_material(
    (5.e6, 1.e7), (0.45, 0.3), (0.9, 0.8, 0.8, 0.7), (0.3, 0.4, 0.4, 0.5), characteristicVelocity=1.0,
    coefficientRollingFriction=[0.1, 0.15, 0.15, 0.2], coefficientRollingViscousDamping=[0.3, 0.2, 0.2, 0.1],
    cohesionEnergyDensity=[3.e4, 2.e4, 2.e4, 1.e4]) + """\
fix m9 all property/global kn peratomtypepair 2 2000 2500 2500 3000
fix m10 all property/global kt peratomtypepair 2 1500 1800 1800 2000
fix m11 all property/global gamman peratomtypepair 2 40 50 50 60
fix m12 all property/global gammat peratomtypepair 2 20 25 25 30
fix m13 all property/global gamman_abs peratomtypepair 2 0.02 0.03 0.03 0.04
fix m14 all property/global gammat_abs peratomtypepair 2 0.01 0.015 0.015 0.02
fix m15 all property/global rollingStiffness scalar 3.0
fix m16 all property/global coefficientMaxElasticStiffness peratomtypepair 2 2.0 2.5 2.5 3.0
fix m17 all property/global coefficientAdhesionStiffness peratomtypepair 2 0.5 0.4 0.4 0.3
fix m18 all property/global coefficientPlasticityDepth peratomtypepair 2 0.02 0.03 0.03 0.04
"""

PAIR = HEAD + MATERIAL + """\
pair_style gran model MODEL
pair_coeff * *
timestep 0.000001
create_atoms 1 single 0.0 0.0 0.0
create_atoms 2 single 0.0085 0.002 0.001
set atom 1 diameter 0.01 density 2500
set atom 2 diameter 0.008 density 1500
velocity all set 0 0 0
set atom 1 vx 0.4 vy 0.05 vz 0.0
set atom 2 vx -0.3 vy 0.0 vz 0.1
set atom 1 omegaz 30
set atom 2 omegax 10 omegay -20
fix integr all nve/sphere
DUMP
run 6000
"""

WALL = HEAD + MATERIAL + """\
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.000002
fix floor all wall/gran model MODEL primitive type 2 zplane -0.04
create_atoms 1 single 0.0 0.0 -0.0351
set atom 1 diameter 0.01 density 2500
velocity all set 0 0 0
set atom 1 vx 0.3 vy 0.1 vz -0.05
set atom 1 omegax 5 omegay -20 omegaz 40
fix g all gravity 9.81 vector 0 0 -1
fix integr all nve/sphere
DUMP
run 20000
"""

CASES = {
    "pair": ["hertz tangential history", "hooke tangential history", "hertz tangential history rolling_friction cdt",
             "hertz tangential history cohesion sjkr", "hooke tangential no_history", "hooke/stiffness tangential history",
             "hooke/stiffness tangential history absolute_damping on", "hertz/stiffness tangential history",
             "hooke/hysteresis tangential history", "hertz tangential history rolling_friction epsd",
             "hertz tangential history rolling_friction epsd2", "hertz tangential history rolling_friction epsd3",
             "hertz tangential history rolling_friction cdt torsionTorque on",
             "hertz tangential history rolling_friction epsd2 torsionTorque on",
             "hertz tangential history cohesion sjkr tangential_reduce on",
             "hertz tangential history cohesion sjkr2", "hertz tangential no_history limitForce on",
             "hertz tangential history tangential_damping off"],
    "wall": ["hertz tangential history", "hertz tangential history rolling_friction cdt",
             "hertz tangential history rolling_friction epsd", "hertz tangential history rolling_friction epsd2",
             "hertz tangential history rolling_friction epsd3", "hertz tangential history cohesion sjkr",
             "hooke tangential history rolling_friction epsd2"],
}


def final_state(liggghts, script, steps_line):
    """x v omega of every particle (by id) at the last step, as LIGGGHTS prints them."""
    with tempfile.TemporaryDirectory() as folder:
        dump = Path(folder) / "final.dump"
        every = steps_line.split()[1]
        line = (f"dump d all custom {every} {dump} id x y z vx vy vz omegax omegay omegaz\n"
                'dump_modify d format "%d' + " %.16e" * 9 + '"\n')
        (Path(folder) / "in.case").write_text(script.replace("DUMP\n", line))
        done = subprocess.run([liggghts, "-in", "in.case", "-log", "none", "-echo", "none"], cwd=folder,
                              capture_output=True, text=True)
        if done.returncode != 0 or "ERROR" in done.stdout:
            raise RuntimeError(f"LIGGGHTS failed: {done.stdout[-2000:]}{done.stderr[-2000:]}")
        rows = [line.split() for line in dump.read_text().splitlines()]
        last = max(i for i, row in enumerate(rows) if row == ["ITEM:", "TIMESTEP"])
        atoms = [row for row in rows[last + 9:] if row]
        return [[float(w) for w in row[1:]] for row in sorted(atoms, key=lambda r: int(r[0]))]


def main():
    table = {}
    for scene, template in (("pair", PAIR), ("wall", WALL)):
        steps = next(line for line in template.splitlines() if line.startswith("run "))
        for model in CASES[scene]:
            script = template.replace("MODEL", model)
            table[f"{scene}: {model}"] = {"script": script.replace("DUMP\n", ""),
                                          "state": final_state(LIGGGHTS, script, steps)}
            print(scene, model, table[f"{scene}: {model}"]["state"][0][3:6])
    OUT.write_text(json.dumps({"recorded with": "LIGGGHTS 3.8.0 (Debian's liggghts), "
                               "benchmarks/liggghts_references/contacts.py", "cases": table}, indent=1) + "\n")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
