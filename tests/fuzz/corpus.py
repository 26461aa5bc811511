"""The seeds the fuzz suite mutates: scripts, data files and restart files that run cleanly.

- Scripts: tests/fuzz/seeds/*.in, each run as ``in.fuzz`` with the files it names (an included
  script, a data file, an STL mesh). water.in, analysis.in and hopper.in are the examples of
  examples/ on smaller boxes and fewer steps (each seed runs in well under a second); dense_granular.in
  and mesh_plate.in are tests/data's; the ones whose first line reads ``# from tests/...`` are scripts
  of the test suite as they stand there; the others cover what those leave out (variables and
  include, lj/cut with langevin, walls, pair formula, mvv/dpd, dem/hertz with nve/limit, the granular
  fixes, read_data, restart output, 2-d).
- Data files: written with ``pdps_core.testing.write_data`` (atomic, with and without velocities,
  one and two types, 2-d) and by hand (sphere style, image flags; a molecule template, poured as rigid bodies), each read by a short script that
  runs them with a pair style, an integrator, thermo output and a dump.
- Restart files: written by running seed scripts with ``write_restart`` at the end (DPD with groups
  and fixes, granular contacts with their history, Lennard-Jones with langevin, mvv/dpd, the hopper
  with its mesh wall, 2-d, computes with state, and LAMMPS-dialect scenes: a melt, pair styles,
  molecules, commands between runs), each read by a short script, in the writer's dialect, that runs
  on; LIGGGHTS scenes too (pair gran and its walls with their contact history).
- Commands after a run: lammps_after_run.in and liggghts_after_run.in change pair coefficients, fixes,
  groups, velocities, gravity, the time step and the particles between runs.
"""

from pathlib import Path

import numpy as np

SEEDS = Path(__file__).with_name("seeds")
PROJECT = Path(__file__).resolve().parents[2]
SCRIPT = "in.fuzz"


class Seed:
    """A seed: its files (name -> bytes, the script included), the script to run and the file a data
    or restart case mutates. Not a dataclass: hypothesis would print every byte of it."""

    def __init__(self, name, files, script=SCRIPT, target=SCRIPT):
        self.name, self.files, self.script, self.target = name, files, script, target

    def __repr__(self):
        return f"Seed({self.name})"


class Context(dict):
    """What mutations draw words and lines from."""

    def __repr__(self):
        return f"Context({len(self.get('vocabulary', ()))} words, {len(self.get('lines', ()))} lines)"


def _support_files():
    files = {p.name: p.read_bytes() for p in sorted(SEEDS.iterdir()) if p.suffix != ".in"}
    files["hopper.stl"] = (PROJECT / "examples" / "hopper" / "hopper.stl").read_bytes()
    return files


def _with_support(text):
    """``{in.fuzz: text}`` and every support file the script names."""
    words = set(text.split())
    files = {SCRIPT: text}
    files.update({name: data for name, data in _support_files().items() if name.encode() in words})
    return files


def script_seeds():
    return [Seed(path.stem, _with_support(path.read_bytes())) for path in sorted(SEEDS.glob("*.in"))]


def script_context(seeds):
    """What mutations draw from: every word and every line of the seeds, and the command names."""
    from pdps_core.commands import COMMANDS
    import pdps_core.simulation  # noqa: F401  (fills the command table)
    # shell runs its words as a system command: mutated scripts must not (they could remove the
    # harness's files or wait on a terminal)
    words, lines = set(COMMANDS) - {"shell"}, set()
    for seed in seeds:
        for name, data in seed.files.items():
            if name.endswith(".stl"):
                continue
            for line in data.split(b"\n"):
                if line.strip() and not line.startswith(b"#"):
                    lines.add(line.strip())
                    words.update(w.decode() for w in line.split())
    words.discard("shell")
    return Context(vocabulary=sorted(w.encode() for w in words), lines=sorted(lines))


# ---- data files --------------------------------------------------------------------------------------
DATA = "data.fuzz"
OUTPUT = ("thermo 5\nthermo_style custom step temp pe ke press\n"
          "dump 1 all custom 5 dump.fuzz id type x y z vx vy vz\nrun 10\n")
DATA_SCRIPTS = {
    "dpd": "units lj\nboundary p p p\nread_data data.fuzz\npair_style dpd 1.0 1.0 5\n"
           "pair_coeff * * 25 4.5\nfix 1 all nve\ntimestep 0.02\n" + OUTPUT,
    "lj": "units lj\nboundary p p p\nread_data data.fuzz\npair_style lj/cut 2.0\n"
          "pair_coeff * * 1.0 1.0\nfix 1 all nve\ntimestep 0.002\n" + OUTPUT,
    # the data file's Pair Coeffs and PairIJ Coeffs set the coefficients (pair_style first, as LAMMPS)
    "lj_coeffs": "units lj\nboundary p p p\npair_style lj/cut 2.0\nread_data data.fuzz\nfix 1 all nve\n"
                 "timestep 0.002\n" + OUTPUT,
    "dpd2d": "units lj\ndimension 2\nboundary p p p\nread_data data.fuzz\n"
             "pair_style dpd 1.0 1.0 5\npair_coeff * * 25 4.5\nfix 1 all nve\ntimestep 0.02\n" + OUTPUT,
    "sphere": "particle_style sphere\nboundary p p f\nread_data data.fuzz\n"
              "pair_style dem/lsd 0.5 1.0\npair_coeff * * 1000 5 300 2 0.5\n"
              "region walls block INF INF INF INF 0 4\n"
              "fix w all wall/dem lsd region walls 0.5 1000 5 300 2 0.5 0.5\n"
              "fix g all gravity 1.0 vector 0 0 -1\nfix 1 all nve/sphere\ntimestep 0.001\n"
              "thermo 5\nthermo_style custom step atoms ke press\n"
              "dump 1 all custom 5 dump.fuzz id type x y z radius\nrun 10\n",
    "hybrid": "atom_style hybrid sphere molecular\nboundary p p f\nread_data data.fuzz\n"
              "pair_style gran/hooke/history 2000 NULL 50 NULL 0.5 1\npair_coeff * *\n"
              "fix w all wall/gran hooke/history 2000 NULL 50 NULL 0.5 1 zplane 0 4\n"
              "fix g all gravity 1.0 vector 0 0 -1\nfix 1 all rigid/small molecule\ntimestep 0.001\n"
              "thermo 5\nthermo_style custom step atoms pe\n"
              "dump 1 all custom 5 dump.fuzz id mol x y z radius omegax\nrun 10\nwrite_data out.data\n",
    # the data file is a molecule template (the molecule command), poured as rigid bodies
    "molecule": "atom_style sphere\nboundary p p f\ncomm_modify vel yes cutoff 3.0\n"
                "fix prop all property/atom mol ghost yes\nregion box block 0 8 0 8 0 12 units box\ncreate_box 2 box\n"
                "pair_style gran/hooke/history 4000 NULL 100 NULL 0.5 0\npair_coeff * *\n"
                "neigh_modify exclude molecule/intra all\nfix g all gravity 9.8 vector 0 0 -1 disable\n"
                "molecule m data.fuzz\nfix r all rigid/small molecule mol m gravity g\n"
                "region slab block 2 6 2 6 6 10 units box\nfix p all pour 4 0 4321 vol 0.3 20 region slab mol m rigid r\n"
                "fix w all wall/gran hooke/history 4000 NULL 100 NULL 0.5 0 zplane 0 NULL\ntimestep 0.001\n"
                "thermo 5\nthermo_style custom step atoms\ndump 1 all custom 5 dump.fuzz id mol x y z radius\nrun 10\n",
    "full": "atom_style full\nbond_style harmonic\nread_data data.fuzz\npair_style lj/cut 2.5\npair_coeff * * 1.0 1.0\n"
            "group first molecule 1\nneigh_modify exclude molecule/intra all exclude molecule/inter first\n"
            "fix 1 all nve\ntimestep 0.002\nthermo 5\nthermo_style custom step atoms pe ke press\n"
            "dump 1 all custom 5 dump.fuzz id mol type q x y z\nrun 10\n",
}
MOLECULE_FILE = """# an L of three spheres (the molecule command's file)

3 atoms
0 bonds

Coords

1 0.0 0.0 0.0
2 1.0 0.0 0.0
3 1.0 1.0 0.2

Types

1 1
2 2
3 1

Diameters

1 1.0
2 0.8
3 1.0

Masses

1 0.5
2 0.3
3 0.5
"""
MOLECULES = """three molecules, bonds and charges (atom_style full)

6 atoms
2 atom types
4 bonds
1 bond types
1 angles
1 angle types

0 5 xlo xhi
0 5 ylo yhi
0 5 zlo zhi

Masses

1 1.0
2 2.0

Atoms # full

1 1 1 0.5 1.0 1.0 1.0 0 0 0
2 1 2 -0.5 2.1 1.0 1.0 0 0 0
3 2 1 0.25 1.0 2.2 1.0 0 0 0
4 2 2 -0.25 2.1 2.2 1.0 0 0 0
5 3 1 0.0 3.2 3.3 4.4 0 0 -1
6 3 1 0.0 4.3 3.3 4.4 0 0 -1

Velocities

1 0.1 0.0 0.0
2 0.0 0.0 0.0
3 0.0 0.0 0.0
4 0.0 0.0 0.0
5 0.0 -0.2 0.3
6 0.0 0.0 0.0

Bond Coeffs

1 100.0 1.1

Bonds

1 1 1 2
2 1 3 4
3 1 5 6
4 1 1 3

Angles

1 1 2 1 3
"""
PAIR_COEFFS = """four particles whose coefficients the data file gives (LAMMPS's write_data writes them)

4 atoms
2 atom types

0 4 xlo xhi
0 4 ylo yhi
0 4 zlo zhi

Masses

1 1.0
2 2.0

Pair Coeffs # lj/cut

1 1.0 1.0
2 0.5 1.1

PairIJ Coeffs # lj/cut

1 2 0.8 1.05 1.8

Atoms # atomic

1 1 0.5 0.5 0.5 0 0 0
2 2 1.6 0.5 0.5 0 0 0
3 1 0.5 1.7 0.6 0 0 0
4 2 2.5 2.5 2.5 1 0 0

Velocities

1 0.1 0.0 0.0
2 0.0 0.0 0.0
3 0.0 0.0 0.0
4 -0.2 0.1 0.0
"""
# two clumps of spheres with spin (atom_style hybrid sphere molecular), as the rigid/small clumps test has them
CLUMPS = (PROJECT / "plugins" / "fix_rigid" / "tests" / "data" / "clumps.data").read_text()

SPHERES = """spheres in a box with a fixed floor

6 atoms
1 atom types

0 3 xlo xhi
0 3 ylo yhi
0 4 zlo zhi

Atoms # sphere

1 1 1.0 1.9 0.5 0.5 0.6 0 0 0
2 1 1.0 1.9 1.6 0.5 0.6 0 0 0
3 1 0.8 2.2 0.5 1.6 0.6 1 0 0
4 1 0.8 2.2 1.6 1.6 0.6 0 -1 0
5 1 1.0 1.9 1.0 1.0 1.7 0 0 0
6 1 0.9 1.9 2.5 2.5 2.0 0 0 0

Velocities

1 0.1 0 0 0 0 0
2 0 0.1 0 0 0 0.5
3 0 0 -0.1 0 0 0
4 0.2 0 0 0 0 0
5 0 0 0 0.1 0 0
6 -0.1 0.1 0 0 0 0
"""


def data_seeds(folder):
    """The data-file seeds, written into ``folder`` (write_data writes files)."""
    from pdps_core.testing import write_data
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(2024)
    grid = np.array([[i, j, k] for i in range(3) for j in range(3) for k in range(3)], float) + 0.5
    made = {
        "grid27": ("dpd", dict(lo=(0, 0, 0), hi=(3, 3, 3), x=grid,
                               velocities=rng.normal(0, 1, (27, 3)))),
        "two_types": ("lj", dict(lo=(0, 0, 0), hi=(4.5, 4.5, 4.5), x=1.5 * grid[::2],
                                 types=[1, 2] * 7, masses={1: 1.0, 2: 2.5})),
        "flat2d": ("dpd2d", dict(lo=(0, 0, -0.5), hi=(3, 3, 0.5),
                                 x=np.c_[grid[::3, :2], np.zeros(9)],
                                 velocities=np.c_[rng.normal(0, 1, (9, 2)), np.zeros(9)])),
    }
    seeds = []
    for name, (style, kwargs) in made.items():
        path = write_data(folder / f"{name}.data", kwargs.pop("lo"), kwargs.pop("hi"),
                          kwargs.pop("x"), **kwargs)
        seeds.append(Seed(name, {SCRIPT: DATA_SCRIPTS[style].encode(), DATA: path.read_bytes()},
                          target=DATA))
    seeds.append(Seed("spheres", {SCRIPT: DATA_SCRIPTS["sphere"].encode(), DATA: SPHERES.encode()},
                      target=DATA))
    seeds.append(Seed("molecules", {SCRIPT: DATA_SCRIPTS["full"].encode(), DATA: MOLECULES.encode()},
                      target=DATA))
    seeds.append(Seed("clumps", {SCRIPT: DATA_SCRIPTS["hybrid"].encode(), DATA: CLUMPS.encode()},
                      target=DATA))
    seeds.append(Seed("molecule_file", {SCRIPT: DATA_SCRIPTS["molecule"].encode(), DATA: MOLECULE_FILE.encode()},
                      target=DATA))
    seeds.append(Seed("pair_coeffs", {SCRIPT: DATA_SCRIPTS["lj_coeffs"].encode(), DATA: PAIR_COEFFS.encode()},
                      target=DATA))
    lammps = (SEEDS / "particles.data").read_bytes()           # image flags, comments, two types
    seeds.append(Seed("particles", {SCRIPT: DATA_SCRIPTS["lj"].encode(), DATA: lammps}, target=DATA))
    return seeds


# ---- restart files -----------------------------------------------------------------------------------
RESTART = "r.restart"
RESTART_SCRIPT = ("read_restart r.restart\nthermo 5\nthermo_style custom step temp pe ke press\n"
                  "dump 1 all custom 5 dump.fuzz id type x y z vx vy vz\nrun 10\n"
                  "write_restart again.restart\n")
RESTART_FROM = ("restart_groups", "dense_granular", "lj_langevin", "mvv_dpd", "hopper", "plane_2d",
                "granular_computes")
# LAMMPS-dialect writers, their files read back by a LAMMPS-dialect script (index bases, region units)
# (not lammps_melt: its fix ave/time reads c_k, and read_restart restores fixes before computes)
LAMMPS_RESTART_FROM = ("lammps_styles", "lammps_molecules", "lammps_hybrid", "lammps_after_run")
# LIGGGHTS writers: pair gran with contact history, walls, and commands between runs
LIGGGHTS_RESTART_FROM = ("liggghts_gran", "liggghts_contacts", "liggghts_walls", "liggghts_after_run")
READ_BACK = {name: "dialect lammps\n" for name in LAMMPS_RESTART_FROM}
READ_BACK.update({name: "dialect liggghts\n" for name in LIGGGHTS_RESTART_FROM})


def restart_writers():
    """The seed scripts that write the restart seeds, as Seeds to run (each ends in write_restart)."""
    scripts = {seed.name: seed for seed in script_seeds()}
    writers = []
    for name in RESTART_FROM + LAMMPS_RESTART_FROM + LIGGGHTS_RESTART_FROM:
        seed = scripts[name]
        files = dict(seed.files)
        files[SCRIPT] = files[SCRIPT] + f"\nwrite_restart {RESTART}\n".encode()
        writers.append(Seed(name, files))
    return writers


def restart_seeds(written):
    """Restart-file seeds from ``{writer name: (its files, restart bytes)}``."""
    seeds = []
    for name, (files, restart) in written.items():
        support = {n: d for n, d in files.items() if n != SCRIPT}
        script = READ_BACK.get(name, "") + RESTART_SCRIPT
        seeds.append(Seed(name, {**support, SCRIPT: script.encode(), RESTART: restart}, target=RESTART))
    return seeds
