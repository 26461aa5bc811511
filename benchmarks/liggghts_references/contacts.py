"""Record LIGGGHTS 3.8.0's answers for each of its contact sub-models (pair gran model ..., fix
wall/gran model ...), which plugins/pair_gran/tests/test_gran_submodels.py compares pdps with.

    python benchmarks/liggghts_references/contacts.py [LIGGGHTS]

Deterministic scenes, every particle's start in the script (pdps's own scripts, LIGGGHTS syntax):

- ``pair``: two spheres of two materials, already overlapping, meeting off-centre with spin
  (6000 steps of 1 us), under the model words of each case;
- ``wall``: a sphere dropped with spin onto a primitive zplane under gravity, rolling along it
  (20000 steps of 2 us), the wall's model words those of each case;
- ``mesh``: the same sphere, dropped with spin onto a fix mesh/surface wall (an ASCII STL written
  with the script: a square of two triangles, flat or tilted by atan(1/8) = 7.1 degrees about y),
  bouncing, then rolling across the triangles' shared diagonal (40000 steps of 2 us, the state
  every 10000; one case also as 40 runs of 1000 steps); the STL has coordinates of few binary digits, so that no reader rounds them;
- ``conduction``: two spheres of two materials, overlapping and held still (no integrator, no
  gravity), at 400 and 300 K under fix heat/gran with each contact_area (900 steps, lambda dt = 2e-3
  of the exponential rate; LIGGGHTS takes ``set ... property/atom Temp`` only after a ``run 0``).

LIGGGHTS runs each script with a dump of x, v and omega of every particle at the last step (%.16e)
added before ``run``; the table (the scripts without the dump, the final states, the STL of a mesh
case) goes to plugins/pair_gran/tests/data/liggghts_submodels.json. The conduction scene's dump is of
both temperatures every 100 steps; its table goes to plugins/fix_heat/tests/data/liggghts_conduction.json.
"""

import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

from pdps_core.testing import liggghts_material

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "plugins" / "pair_gran" / "tests" / "data" / "liggghts_submodels.json"
OUT_HEAT = ROOT / "plugins" / "fix_heat" / "tests" / "data" / "liggghts_conduction.json"
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

MESH = HEAD + MATERIAL + """\
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.000002
fix plane all mesh/surface file plane.stl type 2
fix floor all wall/gran model MODEL mesh n_meshes 1 meshes plane
create_atoms 1 single X0 Y0 Z0
set atom 1 diameter 0.01 density 2500
velocity all set 0 0 0
set atom 1 vx -0.3 vy 0.1 vz -0.02
set atom 1 omegax 5 omegay -20
fix g all gravity 9.81 vector 0 0 -1
fix integr all nve/sphere
DUMP
run 40000
"""

# the square |x|, |y| <= 5/128 m about z = -0.04 + slope x, split along its diagonal y = x; the
# sphere starts below the diagonal touching the plane (1 um of overlap), moving to -x: its bounces
# end within some 10000 steps, it rolls over the diagonal near step 25000
HALF, SLOPES, START = 0.0390625, {"flat": 0.0, "tilted": 0.125}, (0.015, -0.003)


def plane_stl(slope):
    """The ASCII STL of the square, both triangles facing up."""
    corners = [(x, y, -0.04 + slope * x) for x, y in ((-HALF, -HALF), (HALF, -HALF), (HALF, HALF), (-HALF, HALF))]
    normal = (-slope / (1 + slope * slope) ** 0.5, 0.0, 1 / (1 + slope * slope) ** 0.5)
    lines = ["solid plane"]
    for triangle in ((0, 1, 2), (0, 2, 3)):
        lines += ["facet normal {!r} {!r} {!r}".format(*normal), "outer loop"]
        lines += ["vertex {!r} {!r} {!r}".format(*corners[k]) for k in triangle]
        lines += ["endloop", "endfacet"]
    return "\n".join(lines + ["endsolid plane"]) + "\n"


def mesh_script(slope, model):
    norm = (1 + slope * slope) ** 0.5
    x0, y0 = START
    z0 = -0.04 + slope * x0 + 0.004999 / norm
    x0 -= 0.004999 * slope / norm
    return MESH.replace("MODEL", model).replace("X0", repr(x0)).replace("Y0", repr(y0)).replace("Z0", repr(z0))


CONDUCTION = HEAD + liggghts_material(
    (5.e6, 5.e6), (0.45, 0.45), [0.5] * 4, [0.5] * 4, thermalConductivity=(5.0, 2.0),
    thermalCapacity=(10.0, 30.0)) + """\
pair_style gran model hertz tangential history
pair_coeff * *
timestep DT
create_atoms 1 single 0.0 0.0 0.0
create_atoms 2 single 0.0088 0.0 0.0
set atom 1 diameter 0.01 density 2500
set atom 2 diameter 0.008 density 2500
fix heat all heat/gran initial_temperature 300.0 AREA
run 0
set atom 1 property/atom Temp 400.0
DUMP
run 900
"""


# fix heat/gran's contact areas: the circle where the spheres meet (its default), the larger
# sphere's cross-section (LIGGGHTS's source; its manual says the smaller), a constant
CONDUCTION_AREAS = {"overlap": "", "projection": "contact_area projection", "constant": "contact_area constant 1e-6"}


def conduction_rate(area_words):
    """lambda = h (1/m1c1 + 1/m2c2), h = 4 k1k2/(k1+k2) sqrt(A)."""
    r, r1, r2 = 0.0088, 0.005, 0.004
    area = {"": -math.pi / 4 * (r - r1 - r2) * (r + r1 - r2) * (r - r1 + r2) * (r + r1 + r2) / (r * r),
            "contact_area projection": math.pi * max(r1, r2) ** 2, "contact_area constant 1e-6": 1e-6}[area_words]
    h = 4 * 5.0 * 2.0 / (5.0 + 2.0) * math.sqrt(area)
    m1, m2 = (2500 * math.pi / 6 * d ** 3 for d in (0.01, 0.008))
    return h * (1 / (m1 * 10.0) + 1 / (m2 * 30.0))


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
MESH_CASES = [("flat", "hertz tangential history"), ("flat", "hertz tangential history rolling_friction cdt"),
              ("tilted", "hertz tangential history"), ("tilted", "hertz tangential history rolling_friction epsd2")]
SPLIT_CASE = "hertz tangential history rolling_friction cdt"


STATE, MESH_EVERY = "x y z vx vy vz omegax omegay omegaz", 10000


def dumped(liggghts, script, every, columns, files=None):
    """Each dump snapshot of ``columns`` of every particle (by id), as LIGGGHTS prints them, every
    ``every`` steps; ``files`` (name: text) are written beside the script."""
    with tempfile.TemporaryDirectory() as folder:
        dump = Path(folder) / "case.dump"
        line = (f"dump d all custom {every} {dump} id {columns}\n"
                'dump_modify d format "%d' + " %.16e" * len(columns.split()) + '"\n')
        (Path(folder) / "in.case").write_text(script.replace("DUMP\n", line))
        for name, text in (files or {}).items():
            (Path(folder) / name).write_text(text)
        done = subprocess.run([liggghts, "-in", "in.case", "-log", "none", "-echo", "none"], cwd=folder,
                              capture_output=True, text=True)
        if done.returncode != 0 or "ERROR" in done.stdout:
            raise RuntimeError(f"LIGGGHTS failed: {done.stdout[-2000:]}{done.stderr[-2000:]}")
        rows = [line.split() for line in dump.read_text().splitlines()]
        starts = [i for i, row in enumerate(rows) if row == ["ITEM:", "TIMESTEP"]] + [len(rows)]
        snapshots = []
        for start, end in zip(starts, starts[1:]):
            atoms = [row for row in rows[start + 9:end] if row]
            snapshots.append([[float(w) for w in row[1:]] for row in sorted(atoms, key=lambda r: int(r[0]))])
        return snapshots


def final_state(liggghts, script, files=None):
    """x v omega of every particle (by id) at the last step."""
    steps = next(line for line in script.splitlines() if line.startswith("run ")).split()[1]
    return dumped(liggghts, script, steps, STATE, files)[-1]


def main():
    table = {}
    for scene, template in (("pair", PAIR), ("wall", WALL)):
        for model in CASES[scene]:
            script = template.replace("MODEL", model)
            table[f"{scene}: {model}"] = {"script": script.replace("DUMP\n", ""),
                                          "state": final_state(LIGGGHTS, script)}
            print(scene, model, table[f"{scene}: {model}"]["state"][0][3:6])
    for tilt, model in MESH_CASES:
        script, stl = mesh_script(SLOPES[tilt], model), plane_stl(SLOPES[tilt])
        key = f"mesh {tilt}: {model}"
        states = dumped(LIGGGHTS, script, MESH_EVERY, STATE, {"plane.stl": stl})
        table[key] = {"script": script.replace("DUMP\n", ""), "files": {"plane.stl": stl}, "state": states[-1],
                      "every": MESH_EVERY, "states": states}
        print(key, table[key]["state"][0][:6])
    # one case again as 40 runs of 1000 steps: each run's setup forces move the springs, so its end is
    # not the whole run's (5e-6 of scale apart), and pdps must part from the whole run as LIGGGHTS does
    split = mesh_script(SLOPES["flat"], SPLIT_CASE).replace("run 40000\n", "run 1000\n" * 40)
    stl = plane_stl(SLOPES["flat"])
    table[f"mesh flat, 40 runs: {SPLIT_CASE}"] = {"script": split.replace("DUMP\n", ""), "files": {"plane.stl": stl},
                                                  "state": final_state(LIGGGHTS, split, {"plane.stl": stl})}
    OUT.write_text(json.dumps({"recorded with": "LIGGGHTS 3.8.0 (Debian's liggghts), "
                               "benchmarks/liggghts_references/contacts.py", "cases": table}, indent=1) + "\n")
    print(f"wrote {OUT}")
    heat = {}
    for name, words in CONDUCTION_AREAS.items():
        script = CONDUCTION.replace("DT", repr(2e-3 / conduction_rate(words))).replace(" AREA", f" {words}".rstrip())
        temperatures = [[row[0] for row in snapshot] for snapshot in dumped(LIGGGHTS, script, 100, "f_Temp")]
        heat[name] = {"script": script.replace("DUMP\n", ""), "every": 100, "temperatures": temperatures}
    OUT_HEAT.parent.mkdir(exist_ok=True)
    OUT_HEAT.write_text(json.dumps({"recorded with": "LIGGGHTS 3.8.0 (Debian's liggghts), "
                                    "benchmarks/liggghts_references/contacts.py", "cases": heat}, indent=1) + "\n")
    print(f"wrote {OUT_HEAT}", {name: case["temperatures"][-1] for name, case in heat.items()})


if __name__ == "__main__":
    main()
