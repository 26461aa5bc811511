"""Record what LAMMPS prints for fix rigid/small, rigid/nve/small and rigid/nvt/small (temp 0.5 0.4 1.0) on
many small bodies of Lennard-Jones particles, the reference plugins/fix_rigid/tests/test_rigid_small_lammps.py
compares pdps with.

    python benchmarks/lammps_references/rigid_small.py [LMP]

The scene (written here, deterministic, no random start in either program): 27 bodies of 3 to 5
Lennard-Jones particles (molecule ids, atom_style molecular), randomly oriented on a 3x3x3 grid in a
periodic box of 12 sigma, no two particles of different bodies closer than 1.05, one body straddling
the x and y boundaries (image flags in the data file), with random particle velocities of spread 1
(made rigid by each program's body setup: the bodies drift a few sigma over the run, across the
periodic boundaries and, on 2 ranks, the sub-domain boundary) and interactions within a body
excluded (neigh_modify exclude molecule/intra all). Thermo (15 digits) every 100 steps over 10^4
steps of dt = 0.001 for each style, into plugins/fix_rigid/tests/data/rigid_small_lj.txt; the data
file is plugins/fix_rigid/tests/data/rigid_small_lj.data. Two more scenes, ``free`` and ``plane``: a dimer
(a linear body) and a triangle pushed across the periodic x boundary by fix addforce, in 3d and in 2d,
2000 steps of each style; ``infile``: the free scene with the bodies' values from
plugins/fix_rigid/tests/data/rigid_small_bodies.txt. BAROSTATS: rigid/npt/small and rigid/nph/small on
the 27 LJ bodies (iso; aniso with a ramped target and pchain; x and z coupled with a dilate
group; fix rigid/nph on some bodies, whose box change carries rigid/small's others; fix_modify temp
and press naming computes of group high, also for fix rigid/nph), neighbor lists built every step
(BAROSTAT_SCRIPT says why): temperature, pressure, volume, box lengths, f_1, ecouple and econserve every
100 steps; ``plane rigid/nph/small``: the 2-d plane scene under rigid/nph/small iso, 2000 steps.
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from lammps_run import run_lammps, thermo_lines, write_blocks  # noqa: E402
from rigid import lj_bodies, write_bodies  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "fix_rigid" / "tests" / "data"
STYLES = {"rigid/small": "", "rigid/nve/small": "", "rigid/nvt/small": " temp 0.5 0.4 1.0"}
SCRIPT = lj_bodies("rigid_small_lj.data") + """timestep 0.001
fix 1 all {style} molecule{extra}
thermo_style custom step temp epair ke etotal press {columns}
thermo_modify format float %20.15g
thermo 100
run {steps}
"""
# f_1: the bodies' temperature (rigid/small), LAMMPS's energy of rigid/nh/small (rigid/nve/small; rigid/nvt/small,
# extensive, with the chains' energy)
COLUMNS = {"rigid/small": "f_1", "rigid/nve/small": "f_1", "rigid/nvt/small": "f_1 ecouple econserve"}
BAROSTATS = {
    "rigid/npt/small iso": ("all rigid/npt/small molecule temp 0.5 0.5 1.0 iso 0.05 0.05 2.0", 5000),
    "rigid/nph/small aniso": ("all rigid/nph/small molecule aniso 0.05 0.08 2.0 pchain 4", 5000),
    "rigid/npt/small xz": ("all rigid/npt/small molecule temp 0.5 0.4 1.0 x 0.05 0.05 2.0 z 0.05 0.05 2.0 couple xz "
                           "dilate low", 3000),
    # another fix's box change carries rigid/small's bodies: rigid/small on molecules 14-27 and fix rigid/nph on
    # the others (LAMMPS wants rigid fixes before a box-changing one); f_1 rigid/small's bodies' temperature
    "rigid/nph carries rigid/small": ("high rigid/small molecule\nfix 2 low rigid/nph molecule iso 0.05 0.05 2.0",
                                      3000),
    # fix_modify temp|press: the barostat's pressure (and rigid/nph's barostat temperature) from the named computes
    "rigid/nph/small temp": ("all rigid/nph/small molecule aniso 0.05 0.05 2.0\ncompute t2 high temp\n"
                             "fix_modify 1 temp t2", 3000),
    "rigid/npt/small press": ("all rigid/npt/small molecule temp 0.5 0.5 1.0 iso 0.05 0.05 2.0\ncompute t2 high temp\n"
                              "compute p2 all pressure t2\nfix_modify 1 press p2", 3000),
    "rigid/nph temp": ("all rigid/nph molecule iso 0.05 0.05 2.0\ncompute t2 high temp\nfix_modify 1 temp t2", 3000),
}
# LAMMPS puts a body's centre back into the box (its image flags) only when neighbor lists are built, and
# the virial of its scaled bodies depends on that image (fix rigid's recorder, rigid.py); with check no it
# does so every step, as pdps does whenever the box changes; pdps runs the script without that line
BAROSTAT_SCRIPT = lj_bodies("rigid_small_lj.data") + """neigh_modify every 1 delay 0 check no
group low molecule <= 13
group high molecule > 13
timestep 0.001
fix 1 {fix}
thermo_style custom step temp epair ke etotal press vol lx ly lz f_1 ecouple econserve
thermo_modify format float %20.15g
thermo 100
run {steps}
"""
LENGTH = 12.0
GRID = 3
# a dimer (a linear body: 5 degrees of freedom in 3d) and a triangle pushed across the periodic x boundary
# by fix addforce,
# no pair style (comm_modify cutoff: LAMMPS wants ghosts that span a body all the same), 2000 steps;
# the same in 2d (fix enforce2d; LAMMPS's f_ID counts 6 per body there too)
FREE = """units lj
{dimension}atom_style molecular
region box block 0 20 0 20 {zbox}
create_box 1 box
mass 1 1.0
create_atoms 1 single 5 5 {z[0]}
create_atoms 1 single 6 5 {z[0]}
create_atoms 1 single 18.5 10 {z[1]}
create_atoms 1 single 19.5 10 {z[1]}
create_atoms 1 single 18.8 11 {z[2]}
set atom 1*2 mol 1
set atom 3*5 mol 2
velocity all set 0.1 0.2 {vz[0]}
group g id 2 4
velocity g set 0.5 -0.3 {vz[1]}
group h id 5
velocity h set -0.5 -0.3 {vz[2]}
comm_modify cutoff 3.0
fix 1 all {{style}} molecule{{extra}}
fix 2 all addforce 0.1 -0.05 {vz[3]}
{enforce}thermo_style custom step temp ke press f_1
thermo_modify format float %20.15g
thermo 200
run 2000
"""
PLANE = FREE.format(dimension="dimension 2\n", zbox="-0.5 0.5", z=(0, 0, 0), vz=(0, 0, 0, 0),
                    enforce="fix 3 all enforce2d\n")
FREE = FREE.format(dimension="", zbox="0 20", z=(5, 10, 10.4), vz=(0.3, 0.2, 0.9, 0.02), enforce="")
# the plane scene under rigid/nph/small iso (x and y): 2-d bodies and the barostat, LAMMPS run with check no
# (BAROSTAT_SCRIPT says why; pdps runs it without)
PLANE_NPH = PLANE.format(style="rigid/nph/small", extra=" iso 0.01 0.01 1.0").replace(
    "thermo_style custom step temp ke press f_1", "thermo_style custom step temp ke press vol f_1 ecouple")
EVERY_STEP = "comm_modify cutoff 3.0\n"
# the free scene with the bodies' values from a file (infile): the dimer's centre of mass given outside the
# box with the image flag that brings it back, the triangle a heavier body with its own inertia tensor,
# velocity and angular momentum
INFILE = FREE.replace("molecule{extra}", "molecule{extra} infile rigid_small_bodies.txt")
BODIES = """# ID masstotal xcm ycm zcm ixx iyy izz ixy ixz iyz vxcm vycm vzcm lx ly lz ixcm iycm izcm
2
1 2.0 -14.5 5 5 0 0.5 0.5 0 0 0 -0.05 0.4 -0.05 0 -0.15 0.1 1 0 0
2 6.0 18.9 10.3 10.1 1.0 2.0 3.0 0.1 -0.2 0.05 0.3 -0.1 0.2 0.1 -0.2 0.5 0 0 0
"""


def centres():
    spacing = LENGTH / GRID
    points = [np.array([i, j, k]) * spacing + 0.5 * spacing for i in range(GRID) for j in range(GRID)
              for k in range(GRID)]
    points[0] = np.array([0.2, 11.9, 2.0])       # across the x and y boundaries
    return points


def body(rng, count):
    """``count`` points within 1.3 of their centroid, no two closer than 0.95, randomly turned (the
    draw of rigid.py's bodies; kept here so this scene does not change with that recorder)."""
    while True:
        points = rng.uniform(-1.0, 1.0, size=(count, 3))
        distances = np.linalg.norm(points[:, None] - points[None], axis=2)[np.triu_indices(count, 1)]
        if distances.min() > 0.95 and np.linalg.norm(points - points.mean(axis=0), axis=1).max() < 1.3:
            return points - points.mean(axis=0)


def periodic_gap(a, b):
    """Smallest distance between the points of a and b under the periodic box."""
    d = a[:, None] - b[None]
    d -= LENGTH * np.round(d / LENGTH)
    return np.linalg.norm(d, axis=2).min()


def write_data(path):
    rng = np.random.default_rng(20261124)
    placed = []
    for mol, centre in enumerate(centres(), start=1):
        while True:
            points = body(rng, 3 + mol % 3) + centre
            if all(periodic_gap(points, other) > 1.05 for other in placed):
                break
        placed.append(points)
    rows = []
    tag = 0
    for mol, points in enumerate(placed, start=1):
        for point in points:
            tag += 1
            image = np.floor(point / LENGTH).astype(int)
            rows.append((tag, mol, point - image * LENGTH, image, rng.normal(0.0, 1.0, size=3)))
    write_bodies(path, f"fix rigid/small reference scene: {len(placed)} LJ bodies "
                 "(benchmarks/lammps_references/rigid_small.py)", rows, LENGTH)


def script(style, steps=10000):
    return SCRIPT.format(style=style, extra=STYLES[style], columns=COLUMNS[style], steps=steps)


def main():
    lmp = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp")
    DATA.mkdir(parents=True, exist_ok=True)
    data = DATA / "rigid_small_lj.data"
    write_data(data)
    (DATA / "rigid_small_bodies.txt").write_text(BODIES)
    tables = {style: thermo_lines(run_lammps(lmp, script(style), [data], label=style)) for style in STYLES}
    for name, (fix, steps) in BAROSTATS.items():
        tables[name] = thermo_lines(run_lammps(lmp, BAROSTAT_SCRIPT.format(fix=fix, steps=steps), [data], label=name))
    tables["plane rigid/nph/small"] = thermo_lines(run_lammps(
        lmp, PLANE_NPH.replace(EVERY_STEP, EVERY_STEP + "neigh_modify every 1 delay 0 check no\n"), label="plane nph"))
    for style in STYLES:
        extra = STYLES[style]
        tables[f"free {style}"] = thermo_lines(run_lammps(lmp, FREE.format(style=style, extra=extra), label=style))
        tables[f"plane {style}"] = thermo_lines(run_lammps(lmp, PLANE.format(style=style, extra=extra), label=style))
        tables[f"infile {style}"] = thermo_lines(run_lammps(lmp, INFILE.format(style=style, extra=extra),
                                                            [DATA / "rigid_small_bodies.txt"], label=style))
    write_blocks(DATA / "rigid_small_lj.txt", tables)


if __name__ == "__main__":
    main()
