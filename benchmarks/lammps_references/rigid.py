"""Record what LAMMPS prints for fix rigid, rigid/nve and rigid/nvt (temp 0.5 0.4 1.0) on bodies of Lennard-Jones particles, the
reference plugins/fix_rigid/tests/test_rigid_lammps.py compares pdps with.

    python benchmarks/lammps_references/rigid.py [LMP]

The scene (written here, deterministic, no random start in either program): 8 bodies of 3 to 5
Lennard-Jones particles (molecule ids, atom_style molecular), randomly oriented on a 2x2x2 grid in a
periodic box of 12 sigma, one of them straddling the x and y boundaries (image flags in the data
file), with random particle velocities (made rigid by each program's body setup) and interactions
within a body excluded (neigh_modify exclude molecule/intra all). Thermo (15 digits) every 100 steps
over 10^4 steps of dt = 0.001 for each style, into plugins/fix_rigid/tests/data/rigid_lj.txt; the data
file is plugins/fix_rigid/tests/data/rigid_lj.data. The same for rigid and rigid/nve with ``langevin 0.0
0.0 2.0 428984``: the Langevin drag on the bodies' translation and rotation without noise, the one
deterministic run of that keyword (its noise is LAMMPS's Marsaglia generator's, pdps's a counter-based one).
And rigid/npt and rigid/nph (BAROSTATS: iso, aniso with a ramped target and other chain settings, x and z
coupled with a dilate group) on these bodies, 5000 or 10^4 steps: temperature, pressure, volume, box
lengths, f_1, ecouple and econserve. ``custom``: bodystyle custom v_b, four bodies of two molecules each
(b = ceil(mol/2)), 5000 steps. ``mixed``: four bodies under rigid/npt (dilate all) among the other
molecules' particles, free under fix nvt, 5000 steps. ``plane nph``: the 2-d bodies under rigid/nph iso (x and y), with the
bodies' array f_1[i][j] in thermo (not normalised by the particle count where f_1 is). ``infile gravity``:
the infile clumps pulled by fix rigid's gravity keyword (their file masses), fix gravity on the free spheres.

A second scene, ``clumps``: two clumps of overlapping finite-size spheres (atom_style sphere, bodystyle
group: their own 2/5 m R^2 in the inertia, 6 degrees of freedom each in the count) and three free
spheres under fix nve, all falling under fix gravity along a slanted vector, 5000 steps. A third,
``plane``: a 2-d box (fix enforce2d) with a triangle, a dimer and a dimer of particles near the two x
faces (image flags 0: the body spans the box, as LAMMPS reads it) pushed by fix addforce, one with its torque off (torque 2 off off on keeps z, as 2d needs),
beside a free particle, 3000 steps. A fourth, ``infile``: the clumps with masses, inertia tensors,
velocities and angular momenta from plugins/fix_rigid/tests/data/rigid_bodies.txt. A fifth,
``collide``: three clumps of 2 to 4 spheres and two free spheres falling onto a wall/gran floor and
onto each other through gran/hooke/history, 3000 steps: contacts of a clump take the body's mass for
their effective mass (LAMMPS's mass_rigid in pair gran/* and fix wall/gran).
"""

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from lammps_run import run_lammps, thermo_lines, write_blocks  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "fix_rigid" / "tests" / "data"


def lj_bodies(data):
    """The opening of the rigid-body scenes: Lennard-Jones particles in molecules read from ``data``,
    no pair forces within a molecule (each is a body)."""
    return (f"units lj\natom_style molecular\nread_data {data}\npair_style lj/cut 2.5\npair_coeff * * 1.0 1.0\n"
            "neigh_modify exclude molecule/intra all\n")


STYLES = {"rigid": "", "rigid/nve": "", "rigid/nvt": " temp 0.5 0.4 1.0"}
# rigid/npt and rigid/nph on the same bodies: name -> (style and keywords, steps)
BAROSTATS = {
    "rigid/npt iso": ("rigid/npt molecule temp 0.5 0.5 1.0 iso 0.05 0.05 2.0", 10000),
    "rigid/npt aniso": ("rigid/npt molecule temp 0.5 0.4 1.0 aniso 0.05 0.08 2.0 tparam 5 2 5 pchain 4", 5000),
    "rigid/nph iso": ("rigid/nph molecule iso 0.05 0.05 2.0", 10000),
    "rigid/nph xz": ("rigid/nph molecule x 0.05 0.05 2.0 z 0.05 0.05 2.0 couple xz dilate low", 5000),
}
# LAMMPS's fix rigid puts a body's centre back into the box (its image flags) only when neighbor lists are
# built, and the virial of its thermostatted constraint forces depends on that image; pdps builds them
# every step the box changes: LAMMPS does so too with check no, and pdps runs the script without that line
BAROSTAT_SCRIPT = lj_bodies("rigid_lj.data") + """neigh_modify every 1 delay 0 check no
group low molecule <= 4
timestep 0.001
fix 1 all {fix}
thermo_style custom step temp epair ke etotal press vol lx ly lz f_1 ecouple econserve
thermo_modify format float %20.15g
thermo 100
run {steps}
"""
# the bodies of molecules 1-4 under rigid/npt (dilate all) among free particles under fix nvt (the page's
# first way to barostat a mixture)
MIXED = lj_bodies("rigid_lj.data") + """neigh_modify every 1 delay 0 check no
group low molecule <= 4
group high subtract all low
timestep 0.001
fix 1 low rigid/npt molecule temp 0.5 0.5 1.0 iso 0.05 0.05 2.0 dilate all
fix 2 high nvt temp 0.5 0.5 0.5
thermo_style custom step temp epair ke etotal press vol f_1 ecouple econserve
thermo_modify format float %20.15g
thermo 500
run 5000
"""
# bodystyle custom: bodies of two molecules each, from an atom-style variable
CUSTOM = lj_bodies("rigid_lj.data") + """variable b atom ceil(mol/2)
timestep 0.001
fix 1 all rigid custom v_b
thermo_style custom step temp epair etotal press f_1 f_1[3][1]
thermo_modify format float %20.15g
thermo 500
run 5000
"""
# the langevin keyword with T = 0: its drag alone, deterministic (no noise to draw), LAMMPS's to round-off
DRAG = " langevin 0.0 0.0 2.0 428984"
SCRIPT = lj_bodies("rigid_lj.data") + """timestep 0.001
fix 1 all {style} molecule{extra}
thermo_style custom step temp epair ke etotal press f_1 ecouple econserve
thermo_modify format float %20.15g
thermo 100
run {steps}
"""
LENGTH = 12.0
CLUMPS = """units lj
atom_style sphere
region box block -10 10 -10 10 -10 10
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 0.8 0 0
create_atoms 1 single 0.3 0.6 0.1
create_atoms 1 single 4 4 4
create_atoms 1 single 4.9 4 4
create_atoms 1 single -5 -5 -5
create_atoms 1 single -5 5 -5
create_atoms 1 single 5 -5 -5
set atom 1 diameter 1.0
set atom 2 diameter 0.8
set atom 3 diameter 1.2
set atom 4 diameter 1.0
set atom 5 diameter 0.6
set atom 6*8 diameter 1.0
set atom * density 1.5
group free id 6:8
group a id 1:3
group b id 4:5
velocity all set 0.1 0.2 0.3
group g id 2 5
velocity g set 0.5 -0.3 0.2
group h id 3
velocity h set -0.5 -0.3 0.9
fix 1 all rigid/nve group 2 a b
fix 3 free nve
fix 2 all gravity 1.0 vector 0.3 -0.5 -1
thermo_style custom step temp ke press f_1 f_1[2][1] f_1[1][6]
thermo_modify format float %20.15g
thermo 500
run 5000
"""
INFILE = CLUMPS.replace("fix 1 all rigid/nve group 2 a b", "fix 1 all rigid/nve group 2 a b infile rigid_bodies.txt")
PLANE = """units lj
dimension 2
atom_style atomic
boundary p p p
region box block -10 10 -10 10 -0.5 0.5
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 1 0 0
create_atoms 1 single 0.3 0.8 0
create_atoms 1 single 3 3 0
create_atoms 1 single 3.9 3.1 0
create_atoms 1 single 9.5 2 0
create_atoms 1 single -9.5 2.4 0
create_atoms 1 single -5 -5 0
mass 1 1.0
group a id 1:3
group b id 4:5
group c id 6:7
group free id 8
velocity all set 0.1 0.2 0
group g id 2 5 6
velocity g set 0.5 -0.3 0
group h id 3
velocity h set -0.5 -0.3 0
fix 1 all rigid group 3 a b c torque 2 off off on
fix 3 free nve
fix 4 all addforce 0.1 -0.05 0
fix 5 all enforce2d
thermo_style custom step temp ke press f_1 f_1[3][1] f_1[1][12]
thermo_modify format float %20.15g
thermo 500
run 3000
"""
COLLIDE = """units lj
atom_style sphere
boundary p p f
comm_modify vel yes
region box block 0 6 0 6 0 12
create_box 1 box
create_atoms 1 single 3.0 3.0 1.0
create_atoms 1 single 3.7 3.1 1.0
create_atoms 1 single 2.8 3.2 2.3
create_atoms 1 single 3.4 2.7 2.5
create_atoms 1 single 3.2 3.5 2.9
create_atoms 1 single 3.3 3.0 4.0
create_atoms 1 single 3.9 3.2 4.3
create_atoms 1 single 3.5 3.6 4.6
create_atoms 1 single 3.1 3.4 4.9
create_atoms 1 single 2.0 2.2 3.6
create_atoms 1 single 4.4 4.0 5.8
set atom 1*2 diameter 1.0
set atom 3*5 diameter 0.8
set atom 6*9 diameter 0.7
set atom 10*11 diameter 0.9
set atom * density 1.2
group a id 1:2
group b id 3:5
group c id 6:9
group free id 10:11
velocity a set 0.2 -0.1 -0.5
velocity b set -0.1 0.2 -1.0
velocity c set 0.1 0.0 -1.5
velocity free set 0.4 0.3 -0.8
neigh_modify exclude group a a
neigh_modify exclude group b b
neigh_modify exclude group c c
pair_style gran/hooke/history 20000.0 NULL 30.0 NULL 0.5 1
pair_coeff * *
timestep 0.0002
fix 1 all rigid/nve group 3 a b c
fix 2 free nve/sphere
fix 3 all gravity 5.0 vector 0 0 -1
fix 4 all wall/gran hooke/history 20000.0 NULL 30.0 NULL 0.5 1 zplane 0.0 NULL
thermo_style custom step f_1 f_1[1][3] f_1[2][3] f_1[3][3] f_1[1][4] f_1[2][5] f_1[3][6] f_1[1][10] f_1[2][11] f_1[3][12]
thermo_modify format float %20.15g
thermo 100
run 3000
"""
# the infile clumps pulled by the gravity keyword (their file masses), fix gravity on the free spheres only
INFILE_GRAVITY = (INFILE.replace("infile rigid_bodies.txt", "infile rigid_bodies.txt gravity 2")
                  .replace("fix 2 all gravity", "fix 2 free gravity"))
# the 2-d bodies under rigid/nph (iso: x and y coupled), the bodies' array in thermo
PLANE_NPH = (PLANE.replace("fix 1 all rigid group 3 a b c torque 2 off off on",
                           "fix 1 all rigid/nph group 3 a b c iso 0.05 0.05 1.0\nneigh_modify every 1 delay 0 check no")
             .replace("thermo_style custom step temp ke press f_1 f_1[3][1] f_1[1][12]",
                      "thermo_style custom step temp ke press vol f_1 f_1[3][1] f_1[2][5] ecouple"))


def body(rng, count):
    """``count`` points within 1.3 of their centroid, no two closer than 0.95, randomly turned."""
    while True:
        points = rng.uniform(-1.0, 1.0, size=(count, 3))
        distances = np.linalg.norm(points[:, None] - points[None], axis=2)[np.triu_indices(count, 1)]
        if distances.min() > 0.95 and np.linalg.norm(points - points.mean(axis=0), axis=1).max() < 1.3:
            return points - points.mean(axis=0)


def write_data(path):
    rng = np.random.default_rng(20261123)
    rows = []
    tag = 0
    centres = [np.array([i, j, k]) * 6.0 + 3.0 for i in range(2) for j in range(2) for k in range(2)]
    centres[0] = np.array([0.3, 11.8, 3.0])          # across the x and y boundaries
    for mol, centre in enumerate(centres, start=1):
        for point in body(rng, 3 + mol % 3) + centre:
            tag += 1
            image = np.floor(point / LENGTH).astype(int)
            wrapped = point - image * LENGTH
            rows.append((tag, mol, wrapped, image, rng.normal(0.0, 0.5, size=3)))
    write_bodies(path, "fix rigid reference scene: 8 LJ bodies (benchmarks/lammps_references/rigid.py)", rows, LENGTH)


def write_bodies(path, title, rows, length):
    """A molecular data file in a cubic box of side ``length``, one type of mass 1: rows of (tag,
    molecule, wrapped position, image, velocity), at full precision."""
    lines = [title, "", f"{len(rows)} atoms", "1 atom types", "",
             f"0 {length} xlo xhi", f"0 {length} ylo yhi", f"0 {length} zlo zhi", "", "Masses", "", "1 1.0", "",
             "Atoms # molecular", ""]
    lines += [f"{t} {m} 1 {x[0]:.17g} {x[1]:.17g} {x[2]:.17g} {i[0]} {i[1]} {i[2]}" for t, m, x, i, _ in rows]
    lines += ["", "Velocities", ""]
    lines += [f"{t} {v[0]:.17g} {v[1]:.17g} {v[2]:.17g}" for t, _, _, _, v in rows]
    path.write_text("\n".join(lines) + "\n")


def main():
    lmp = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp")
    DATA.mkdir(parents=True, exist_ok=True)
    data = DATA / "rigid_lj.data"
    write_data(data)
    tables = {style: thermo_lines(run_lammps(lmp, SCRIPT.format(style=style, extra=extra, steps=10000), [data], label=style))
              for style, extra in STYLES.items()}
    for style in ("rigid", "rigid/nve"):
        tables[f"{style} drag"] = thermo_lines(run_lammps(lmp, SCRIPT.format(style=style, extra=DRAG, steps=10000), [data],
                                                          label=f"{style} drag"))
    for name, (fix, steps) in BAROSTATS.items():
        tables[name] = thermo_lines(run_lammps(lmp, BAROSTAT_SCRIPT.format(fix=fix, steps=steps), [data], label=name))
    tables["custom"] = thermo_lines(run_lammps(lmp, CUSTOM, [data], label="custom"))
    tables["mixed"] = thermo_lines(run_lammps(lmp, MIXED, [data], label="mixed"))
    # LAMMPS warns at every neighbor list build of this scene without a pair style (communication cutoff 0)
    tables["infile gravity"] = thermo_lines(run_lammps(lmp, INFILE_GRAVITY, [DATA / "rigid_bodies.txt"],
                                                       label="infile gravity"))
    tables["plane nph"] = [row for row in thermo_lines(run_lammps(lmp, PLANE_NPH, label="plane nph"))
                           if row[0] != "WARNING:"]
    tables["clumps"] = thermo_lines(run_lammps(lmp, CLUMPS, label="clumps"))
    tables["plane"] = thermo_lines(run_lammps(lmp, PLANE, label="plane"))
    tables["infile"] = thermo_lines(run_lammps(lmp, INFILE, [DATA / "rigid_bodies.txt"], label="infile"))
    tables["collide"] = thermo_lines(run_lammps(lmp, COLLIDE, label="collide"))
    write_blocks(DATA / "rigid_lj.txt", tables)


if __name__ == "__main__":
    main()
