"""Record LAMMPS's answers for the classic granular styles (pair gran/hooke, gran/hooke/history,
gran/hertz/history; fix wall/gran), which the tests of plugins/pair_gran, plugins/fix_wall
(test_wall_gran.py) and tests/lammps_scripts/test_gran_box.py compare pdps with.

    python benchmarks/lammps_references/gran.py [LMP]

- Deterministic cases (CASES below): two or three spheres colliding, pressed together or on a wall,
  every particle's start (position, velocity, spin) in the data file. For each, NAME.in (the script
  both programs run), NAME.data and NAME.ref (LAMMPS's positions, velocities and spins of every
  particle every EVERY steps, printed with 17 significant digits) go to the plugin's tests/data
  folder. LAMMPS runs the script with one dump command added before ``run``.
- in.gran_box (tests/lammps_scripts/gran_box/in.gran_box, a copy of the benchmark kit's): the thermo
  table of the unmodified script at nsteps = NSTEPS (seed 99 of velocity create), and the final ke of
  SEEDS runs with other seeds (mean and standard deviation of one run), for comparisons that do not
  depend on velocity create's random numbers.

Data files of the cases are written here (full precision); gran_box's by
pdps_core.testing.bench_data, byte for byte what the kit's make_data.py writes.
"""

import re
import statistics
import sys
import tempfile
from pathlib import Path

from pdps_core.testing import bench_data

sys.path.insert(0, str(Path(__file__).parent))
from lammps_run import run_lammps_file, thermo_table  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
PAIR_DATA = ROOT / "plugins" / "pair_gran" / "tests" / "data"
WALL_DATA = ROOT / "plugins" / "fix_wall" / "tests" / "data" / "wall_gran"
GRAN_BOX = ROOT / "tests" / "lammps_scripts" / "gran_box"
NSTEPS = 2000
SEEDS = 12
UNIT_MASS = 1.9098593171027440      # density of a sphere of diameter 1 and mass 1

# Each case: the folder it goes to, the box, boundaries, particles (type, diameter, density, x, v,
# omega), the script lines between read_data and run, the run length and the output interval.
HOOKE = "200000.0 NULL 50.0 NULL 0.5 1"
CASES = {
    # ---- pair styles: periodic boxes, no walls ----
    "hooke_history_head_on": dict(
        folder=PAIR_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p p",
        particles=[(1, 1.0, UNIT_MASS, (4.49, 5.0, 5.0), (1.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
                   (1, 1.0, UNIT_MASS, (5.51, 5.0, 5.0), (-1.0, 0.0, 0.0), (0.0, 0.0, 0.0))],
        lines=[f"pair_style gran/hooke/history {HOOKE}", "pair_coeff * *", "fix 1 all nve/sphere"],
        steps=300, every=15),
    "hooke_history_oblique": dict(
        folder=PAIR_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p p",
        particles=[(1, 1.0, 2.0, (4.5, 5.0, 5.0), (1.0, 0.3, 0.0), (0.0, 0.0, 5.0)),
                   (1, 1.4, 1.0, (5.7, 5.25, 5.0), (-0.5, 0.0, 0.2), (1.0, -2.0, 0.0))],
        lines=[f"pair_style gran/hooke/history {HOOKE}", "pair_coeff * *", "fix 1 all nve/sphere"],
        steps=600, every=30),
    "hooke_oblique": dict(
        folder=PAIR_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p p",
        particles=[(1, 1.0, 2.0, (4.5, 5.0, 5.0), (1.0, 0.3, 0.0), (0.0, 0.0, 5.0)),
                   (1, 1.4, 1.0, (5.7, 5.25, 5.0), (-0.5, 0.0, 0.2), (1.0, -2.0, 0.0))],
        lines=["pair_style gran/hooke 200000.0 NULL 50.0 NULL 0.2 1", "pair_coeff * *",
               "fix 1 all nve/sphere"],
        steps=600, every=30),
    "hooke_history_dampflag0": dict(
        folder=PAIR_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p p",
        particles=[(1, 1.0, 2.0, (4.5, 5.0, 5.0), (1.0, 0.3, 0.0), (0.0, 0.0, 5.0)),
                   (2, 1.4, 1.0, (5.7, 5.25, 5.0), (-0.5, 0.0, 0.2), (1.0, -2.0, 0.0))],
        lines=["pair_style gran/hooke/history 200000.0 50000.0 80.0 20.0 0.3 0", "pair_coeff * *",
               "fix 1 all nve/sphere"],
        steps=600, every=30),
    "hertz_history_limit_damping": dict(
        folder=PAIR_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p p",
        particles=[(1, 1.0, 2.0, (4.5, 5.0, 5.0), (1.0, 0.3, 0.0), (0.0, 0.0, 5.0)),
                   (1, 1.4, 1.0, (5.7, 5.25, 5.0), (-0.5, 0.0, 0.2), (1.0, -2.0, 0.0))],
        lines=["pair_style gran/hertz/history 2000000.0 NULL 400.0 NULL 0.5 1 limit_damping",
               "pair_coeff * *", "fix 1 all nve/sphere"],
        steps=600, every=30),
    "hooke_history_stick_on_frozen": dict(
        folder=PAIR_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p p",
        particles=[(1, 1.0, UNIT_MASS, (5.0, 5.0, 5.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
                   (1, 1.0, UNIT_MASS, (5.0, 5.0, 5.99999), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))],
        lines=[f"pair_style gran/hooke/history {HOOKE}", "pair_coeff * *", "group base id 1",
               "group top id 2", "fix 1 all nve/sphere", "fix 2 top addforce 0.2 0.0 -1.0",
               "fix 3 base freeze"],
        steps=3000, every=150),
    "hertz_history_slide_on_frozen": dict(
        folder=PAIR_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p p",
        particles=[(1, 1.2, 1.0, (5.0, 5.0, 5.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
                   (1, 0.8, 3.0, (5.0, 5.0, 5.9999), (0.3, 0.0, 0.0), (0.0, 1.0, 0.0))],
        lines=["pair_style gran/hertz/history 2000000.0 NULL 400.0 NULL 0.5 1", "pair_coeff * *",
               "group base id 1", "group top id 2", "fix 1 all nve/sphere",
               "fix 2 top addforce 0.8 0.3 -1.0", "fix 3 base freeze"],
        steps=3000, every=150),
    "hooke_history_three_spheres": dict(
        folder=PAIR_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p p",
        particles=[(1, 1.0, UNIT_MASS, (3.9, 5.0, 5.0), (2.0, 0.0, 0.1), (0.0, 0.0, 0.0)),
                   (1, 1.0, 1.5, (4.95, 5.05, 5.0), (0.0, 0.0, 0.0), (0.0, 0.0, -3.0)),
                   (1, 1.2, 1.0, (5.9, 5.6, 5.02), (0.0, -0.2, 0.0), (2.0, 0.0, 0.0))],
        lines=["pair_style gran/hooke/history 200000.0 NULL 50.0 NULL 0.8 1", "pair_coeff * *",
               "fix 1 all nve/sphere"],
        steps=800, every=40),
    # ---- walls: no pair style ----
    "wall_zplane_hooke_history": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p f",
        particles=[(1, 1.0, UNIT_MASS, (3.0, 5.0, 0.52), (2.0, 0.0, -0.5), (0.0, 3.0, 0.0)),
                   (1, 1.4, 0.8, (7.0, 5.0, 0.75), (0.0, -1.0, -0.2), (1.0, 0.0, 0.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 0.0 0.0 -1.0",
               f"fix 3 all wall/gran hooke/history {HOOKE} zplane 0.0 NULL"],
        steps=3000, every=150),
    "wall_zplane_hooke": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p f",
        particles=[(1, 1.0, UNIT_MASS, (3.0, 5.0, 0.52), (2.0, 0.0, -0.5), (0.0, 3.0, 0.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 0.0 0.0 -1.0",
               "fix 3 all wall/gran hooke 200000.0 NULL 50.0 NULL 0.5 1 zplane 0.0 NULL"],
        steps=3000, every=150),
    "wall_xplane_hertz_limit_damping": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="f p p",
        particles=[(1, 1.0, UNIT_MASS, (7.45, 5.0, 5.0), (1.5, 0.4, 0.2), (1.0, 2.0, 3.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 1.0 0.0 0.0",
               "fix 3 all wall/gran hertz/history 2000000.0 NULL 400.0 NULL 0.4 1 limit_damping "
               "xplane NULL 8.0"],
        steps=2000, every=100),
    "wall_yplane_dampflag0": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p f p",
        particles=[(1, 1.0, UNIT_MASS, (5.0, 1.55, 5.0), (0.7, -1.0, 0.0), (0.0, 0.0, 2.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 0.0 -1.0 0.0",
               "fix 3 all wall/gran hooke/history 200000.0 100000.0 80.0 20.0 0.3 0 yplane 1.0 9.0"],
        steps=2000, every=100),
    "wall_zcylinder_inside": dict(
        folder=WALL_DATA, box=(-5, 5, -5, 5, 0, 10), boundary="f f p",
        particles=[(1, 1.0, UNIT_MASS, (3.45, 0.0, 5.0), (1.0, 0.5, 0.3), (0.0, 0.0, 2.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 1.0 0.2 0.0",
               f"fix 3 all wall/gran hooke/history {HOOKE} zcylinder 4.0"],
        steps=2000, every=100),
    "wall_zcylinder_hertz_outside": dict(
        folder=WALL_DATA, box=(-8, 8, -8, 8, 0, 10), boundary="f f p",
        particles=[(1, 1.0, UNIT_MASS, (0.0, 4.55, 5.0), (0.3, -1.0, 0.0), (0.5, 0.0, 1.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 0.0 -1.0 0.0",
               "fix 3 all wall/gran hertz/history 2000000.0 NULL 400.0 NULL 0.5 1 zcylinder 4.0"],
        steps=2000, every=100),
    "wall_zplane_wiggle": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p f",
        particles=[(1, 1.0, UNIT_MASS, (5.0, 5.0, 0.499), (0.2, 0.0, 0.0), (0.0, 0.0, 0.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 0.0 0.0 -1.0",
               f"fix 3 all wall/gran hooke/history {HOOKE} zplane 0.0 NULL wiggle z 0.01 0.05"],
        steps=2000, every=100),
    "wall_zplane_shear": dict(
        folder=WALL_DATA, box=(0, 10, 0, 10, 0, 10), boundary="p p f",
        particles=[(1, 1.0, UNIT_MASS, (5.0, 5.0, 0.499), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))],
        lines=["fix 1 all nve/sphere", "fix 2 all addforce 0.0 0.0 -1.0",
               "fix 3 all wall/gran hooke/history 200000.0 NULL 50.0 NULL 0.3 1 zplane 0.0 10.0 shear x 0.5"],
        steps=2000, every=100),
}


def write_case(name, case):
    """NAME.data and NAME.in in the case's folder; returns the script text."""
    folder = case["folder"]
    folder.mkdir(parents=True, exist_ok=True)
    lo_hi = case["box"]
    parts = case["particles"]
    ntypes = max(p[0] for p in parts)
    lines = [f"pdps gran reference case {name}", "", f"{len(parts)} atoms", f"{ntypes} atom types", ""]
    lines += [f"{lo_hi[2 * d]} {lo_hi[2 * d + 1]} {a}lo {a}hi" for d, a in enumerate("xyz")]
    lines += ["", "Atoms # sphere", ""]
    for tag, (kind, diameter, density, x, _, _) in enumerate(parts, 1):
        lines.append(f"{tag} {kind} {diameter!r} {density!r} {x[0]!r} {x[1]!r} {x[2]!r}")
    lines += ["", "Velocities", ""]
    for tag, (_, _, _, _, v, w) in enumerate(parts, 1):
        lines.append(f"{tag} {v[0]!r} {v[1]!r} {v[2]!r} {w[0]!r} {w[1]!r} {w[2]!r}")
    (folder / f"{name}.data").write_text("\n".join(lines) + "\n")
    script = "\n".join([f"# reference case {name} (benchmarks/lammps_references/gran.py)",
                        "units lj", "atom_style sphere", f"boundary {case['boundary']}", "comm_modify vel yes",
                        f"read_data {name}.data", *case["lines"], "timestep 0.0001",
                        f"run {case['steps']}"]) + "\n"
    (folder / f"{name}.in").write_text(script)
    return script


def record_case(lmp, name, case):
    script = write_case(name, case)
    every = case["every"]
    dump = (f"dump d all custom {every} {name}.dump id x y z vx vy vz omegax omegay omegaz\n"
            f"dump_modify d sort id format float %.17g\n")
    run_line = f"run {case['steps']}"
    with tempfile.TemporaryDirectory() as folder:
        (Path(folder) / f"{name}.data").write_text((case["folder"] / f"{name}.data").read_text())
        (Path(folder) / f"{name}.in").write_text(script.replace(run_line, dump + run_line))
        run_lammps_file(lmp, folder, f"{name}.in")
        rows = read_dump((Path(folder) / f"{name}.dump").read_text())
    text = [f"# {name}: LAMMPS's state every {every} steps (step id x y z vx vy vz omegax omegay omegaz)"]
    text += [" ".join(row) for row in rows]
    (case["folder"] / f"{name}.ref").write_text("\n".join(text) + "\n")
    print(f"{name}: {len(rows)} rows")


def read_dump(text):
    rows, lines, k = [], text.splitlines(), 0
    while k < len(lines):
        if lines[k].startswith("ITEM: TIMESTEP"):
            step = lines[k + 1].strip()
            count = int(lines[k + 3])
            start = next(m for m in range(k, len(lines)) if lines[m].startswith("ITEM: ATOMS")) + 1
            rows += [[step] + lines[m].split() for m in range(start, start + count)]
            k = start + count
        else:
            k += 1
    return rows


def gran_box(lmp):
    source = (GRAN_BOX / "in.gran_box").read_text()
    variables = (("scenes", "."), ("nsteps", NSTEPS), ("navg", NSTEPS // 2))
    finals = []
    with tempfile.TemporaryDirectory() as folder:
        bench_data("gran_box", Path(folder) / "gran_box.data")
        (Path(folder) / "in.gran_box").write_text(source)
        header, rows = thermo_table(run_lammps_file(lmp, folder, "in.gran_box", variables))
        for k in range(SEEDS):
            text = re.sub(r"^(velocity all create \S+) (\d+)", lambda m: f"{m[1]} {int(m[2]) + 104729 * (k + 1)}",
                          source, flags=re.M)
            (Path(folder) / "in.seeded").write_text(text)
            _, seeded = thermo_table(run_lammps_file(lmp, folder, "in.seeded", variables))
            finals.append(float(dict(zip(header, seeded[-1]))["KinEng"]))
    lines = [f"# in.gran_box in LAMMPS, nsteps {NSTEPS}: the thermo table of the script as it is (seed 99)",
             " ".join(header)] + [" ".join(row) for row in rows]
    lines += [f"# final KinEng over {SEEDS} runs with other velocity seeds: mean sd_of_one_run",
              f"seeds {statistics.mean(finals):.10g} {statistics.stdev(finals):.6g}"]
    (GRAN_BOX / "reference.txt").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    command = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp")
    for case_name, definition in CASES.items():
        record_case(command, case_name, definition)
    gran_box(command)
