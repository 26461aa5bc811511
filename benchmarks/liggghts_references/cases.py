"""Record LIGGGHTS 3.8.0's thermo for small deterministic scenes of pdps's own, one per style or
command of the LIGGGHTS manual, which tests/test_recorded_thermo.py makes pdps print again.

    python benchmarks/liggghts_references/cases.py [LIGGGHTS]

Every scene (LIGGGHTS syntax) starts from the same bed: 27 spheres on a simple-cubic lattice of
spacing 0.02 m in a closed box, two types (diameters 10 and 12 mm, densities 2500 and 1500 kg/m^3),
falling with velocities that grow with height and sideways ones that grow with x, onto a hertz
wall at z = 0, with pair gran hertz/history between them: the upper spheres catch the lower ones
and the bottom row meets the floor in the last third of the run, so contacts, walls and the
integrator all act while the scene is still far from chaos. Each case adds the lines of what it
checks and its thermo columns (every value at %20.15g); the table of each plugin is
plugins/NAME/tests/data/liggghts.cases.json (the core's commands': tests/data/liggghts.cases.json)
with LIGGGHTS's rows beside it (liggghts.txt), every case naming the manual items it checks.
"""

import json
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lammps_references"))
from lammps_run import write_case_table  # noqa: E402

from pdps_core.testing import liggghts_material  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
LIGGGHTS = str(ROOT.parent / "shared" / "bench" / "liggghts")
PROGRAM = "LIGGGHTS 3.8.0 (Debian's liggghts)"

MATERIAL = liggghts_material((5.e6, 1.e7), (0.45, 0.3), (0.9, 0.8, 0.8, 0.7), (0.3, 0.4, 0.4, 0.5))
HEAD = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box 2 box
neighbor 0.002 bin
neigh_modify delay 0
""" + MATERIAL + """\
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
"""
BED = """region bed block -0.03 0.03 -0.03 0.03 0.0 0.06 units box
lattice sc 0.02 origin 0.5 0.5 0.5
create_atoms 1 region bed
region top block INF INF INF INF 0.04 INF units box
group top region top
set group top type 2
set type 1 diameter 0.01 density 2500
set type 2 diameter 0.012 density 1500
velocity all ramp vz -0.2 -1.0 z 0.01 0.05 units box
velocity all ramp vx -0.05 0.05 x -0.02 0.02 sum yes units box
fix floor all wall/gran model hertz tangential history primitive type 1 zplane 0.0
"""
SUMS = """compute rke all erotate/sphere
compute sum all reduce sum x y z vx vy vz
"""
COLUMNS = "step atoms ke c_rke c_sum[1] c_sum[2] c_sum[3] c_sum[4] c_sum[5] c_sum[6]"
BOX_BOUNDS = "xlo xhi ylo yhi zlo zhi vol"


# what a script gives again after read_restart or read_data (LIGGGHTS keeps none of it)
AGAIN = """pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
fix floor all wall/gran model hertz tangential history primitive type 1 zplane 0.0
"""
# a Lennard-Jones-units fluid of point particles (the styles LIGGGHTS shares with LAMMPS)
ATOMIC = """units lj
atom_style atomic
atom_modify map array
boundary p p p
region box block 0 6 0 6 0 6
create_box 2 box
lattice sc 1.0
create_atoms 1 box
region half block 0 3 INF INF INF INF units box
group half region half
set group half type 2
mass 1 1.0
mass 2 2.0
velocity all ramp vx -0.5 0.5 y 0 6 units box
velocity all ramp vy -0.3 0.4 z 0 6 sum yes units box
displace_atoms half move 0.1 0.05 0.0 units box
neighbor 0.3 bin
"""
ATOMIC_RUN = """fix integr all nve
timestep 0.005
compute sum all reduce sum x y z vx vy vz
compute pe all pe
thermo_style custom step atoms ke c_pe c_sum[1] c_sum[2] c_sum[3] c_sum[4] c_sum[5] c_sum[6]
thermo_modify format float %20.15g norm no
thermo 100
run 1000
"""


def thermo(columns=""):
    return (f"thermo_style custom {COLUMNS} {columns}".rstrip() + "\n"
            "thermo_modify format float %20.15g\nthermo 300\n")


def floor_stl(z):
    """An ASCII STL: the square |x|, |y| <= 0.045 at height ``z``, of two triangles."""
    corners = [(-0.045, -0.045), (0.045, -0.045), (0.045, 0.045), (-0.045, 0.045)]
    facets = []
    for a, b, c in ((0, 1, 2), (0, 2, 3)):
        vertices = "".join(f"      vertex {corners[k][0]} {corners[k][1]} {z}\n" for k in (a, b, c))
        facets.append(f"  facet normal 0 0 1\n    outer loop\n{vertices}    endloop\n  endfacet\n")
    return "solid floor\n" + "".join(facets) + "endsolid floor\n"


def mesh_floor(stl="floor.stl"):
    """A mesh floor (the square of ``stl``) above the primitive one, which the spheres then never reach."""
    return (f"fix cad all mesh/surface file {stl} type 1\n"
            "fix meshfloor all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n")


MESH_FLOOR = mesh_floor()


def tilted_stl(z, slope_x, slope_y):
    """An ASCII STL: the square |x|, |y| <= 0.045 on the plane z + slope_x x + slope_y y, of two
    triangles (tilted so that no two spheres of the bed pass through it at one step)."""
    corners = [(-0.045, -0.045), (0.045, -0.045), (0.045, 0.045), (-0.045, 0.045)]
    facets = []
    for a, b, c in ((0, 1, 2), (0, 2, 3)):
        vertices = "".join(f"      vertex {corners[k][0]} {corners[k][1]} "
                           f"{z + slope_x * corners[k][0] + slope_y * corners[k][1]:.10g}\n" for k in (a, b, c))
        facets.append(f"  facet normal 0 0 1\n    outer loop\n{vertices}    endloop\n  endfacet\n")
    return "solid face\n" + "".join(facets) + "endsolid face\n"


FACE = {"face.stl": tilted_stl(0.024, 0.13, 0.047)}


def snapshots_dump():
    """A dump file of two snapshots for read_dump. Step 500: ids 1..24 of the bed (25..27 missing)
    and ids 40, 41 it lacks, near the bed's lattice, each with velocities, a radius and omegax, the
    columns in an order of their own. Step 800: 20 spheres of both types (ids 3..22) in a box of its
    own (z up to 0.12), scaled coordinates (some beyond the box in x and y), image flags, masses."""
    rows = []
    for k, tag in enumerate([*range(1, 25), 40, 41]):
        i, j, m = k % 3, (k // 3) % 3, k // 9
        x, y, z = -0.02 + 0.02 * i + 0.0013 * (k % 4), -0.02 + 0.02 * j - 0.0009 * (k % 5), 0.012 + 0.021 * m
        rows.append(f"{tag} {1 + (k % 2)} {-0.1 - 0.03 * k:.6f} {x:.7f} {0.003 * k:.6f} {y:.7f} "
                    f"{0.0045 + 0.00005 * k:.6f} {z:.7f} {-0.4 - 0.025 * k:.6f} {0.05 * (k % 7) - 0.1:.4f}")
    first = ("ITEM: TIMESTEP\n500\nITEM: NUMBER OF ATOMS\n26\nITEM: BOX BOUNDS ff ff ff\n-0.05 0.05\n"
             "-0.05 0.05\n0 0.1\nITEM: ATOMS id type vx x vy y radius z vz omegax\n" + "\n".join(rows) + "\n")
    rows = []
    for k in range(20):
        i, j, m = k % 4, (k // 4) % 3, k // 12
        xs, ys, zs = 0.2 + 0.2 * i + (0.5 if k % 6 == 0 else 0.0), 0.25 + 0.25 * j - (0.6 if k % 7 == 3 else 0.0), \
            0.1 + 0.18 * m + 0.01 * (k % 3)
        kind = 1 + (k % 2)
        radius = (0.005, 0.006)[kind - 1] * (1.0 + 0.01 * (k % 5))
        mass = (2500.0, 1500.0)[kind - 1] * 4.0 / 3.0 * 3.141592653589793 * radius ** 3
        rows.append(f"{k + 3} {kind} {xs:.6f} {ys:.6f} {zs:.6f} {0.02 * (k % 5) - 0.04:.4f} {-0.3 - 0.02 * k:.4f} "
                    f"{radius:.8f} {mass:.10g} {k % 3 - 1} {(k % 2) * 2 - 1} 0")
    second = ("ITEM: TIMESTEP\n800\nITEM: NUMBER OF ATOMS\n20\nITEM: BOX BOUNDS pp pp ff\n-0.05 0.05\n"
              "-0.05 0.05\n0 0.12\nITEM: ATOMS id type xs ys zs vx vz radius mass ix iy iz\n" + "\n".join(rows) + "\n")
    return first + second


SNAPSHOTS = {"snapshots.dump": snapshots_dump()}


def facets_stl(triangles, z, name):
    """An ASCII STL of the triangles (corners (x, y)) at height ``z``, normals up."""
    facets = []
    for corners in triangles:
        vertices = "".join(f"      vertex {x} {y} {z}\n" for x, y in corners)
        facets.append(f"  facet normal 0 0 1\n    outer loop\n{vertices}    endloop\n  endfacet\n")
    return f"solid {name}\n" + "".join(facets) + f"endsolid {name}\n"


SQUARE = ((-0.045, -0.045), (0.045, -0.045), (0.045, 0.045), (-0.045, 0.045))
# the floor of floor_stl with its first facet again after the others, one vertex 1e-9 higher
DUPLICATE_FLOOR = floor_stl(0.002).replace(
    "endsolid floor", "  facet normal 0 0 1\n    outer loop\n      vertex -0.045 -0.045 0.002000001\n"
    "      vertex 0.045 -0.045 0.002\n      vertex 0.045 0.045 0.002\n    endloop\n  endfacet\nendsolid floor")
# a fan of four triangles about (0.005, 0.003), the last split by a sliver of 0.7 degrees
FAN_CENTRE, SLIVER_TIP = (0.005, 0.003), (-0.044, 0.045)
SLIVER_FLOOR = facets_stl([(SQUARE[0], SQUARE[1], FAN_CENTRE), (SQUARE[1], SQUARE[2], FAN_CENTRE),
                           (SQUARE[2], SLIVER_TIP, FAN_CENTRE), (SLIVER_TIP, SQUARE[3], FAN_CENTRE)], 0.002, "sliver")
# a lid just wider than the bed, high above it: extruded 0.06 down it walls the bed in
LID = facets_stl([((-0.0362, -0.0362), (0.0362, -0.0362), (0.0362, 0.0362)),
                  ((-0.0362, -0.0362), (0.0362, 0.0362), (-0.0362, 0.0362))], 0.065, "lid")
MESH_FLOOR_WALL = "fix meshfloor all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"
HOT_FLOOR = (BED + SUMS + "fix cad all mesh/surface file floor.stl type 1 temperature 500.0{}\n" + MESH_FLOOR_WALL
             + "fix integr all nve/sphere\n"
             "fix k all property/global thermalConductivity peratomtype 5.0 20.0\n"
             "fix c all property/global thermalCapacity peratomtype 10.0 30.0\n"
             "fix ht all heat/gran/conduction initial_temperature 300.0 store_contact_data yes\n"
             "compute ts all reduce sum f_Temp f_heatFlux f_wallHeattransferCoeff\ncompute tm all reduce max f_Temp\n"
             + thermo("c_ts[1] c_ts[2] c_ts[3] c_tm") + "run 3000\n")


@dataclass
class Case:
    owner: str            # the plugin whose table holds it, or "core"
    checks: tuple         # the manual items it checks: "fix viscous", "compute reduce", "run"
    body: str             # the lines after the head
    ranks: bool = False
    files: dict = field(default_factory=dict)
    head: bool = True     # the granular head goes first
    outputs: tuple = ()   # files the run writes, recorded for pdps to write again
    status: int = 0       # LIGGGHTS's exit code (its quit exits with 1)


def bed(lines, columns="", steps=3000, integrate="fix integr all nve/sphere\n"):
    """The bed, ``lines``, the integrator, the sums and thermo with ``columns`` added, then run."""
    return BED + SUMS + lines + integrate + thermo(columns) + f"run {steps}\n"


def euler_snapshots(lines, references, steps=(1000, 1000, 1000)):
    """The bed with ``lines`` (a fix ave/euler) run in parts of ``steps``; after each part the
    ``references`` (f_ID[i][j]) are read into the variables s0, s1, ... (LIGGGHTS's thermo and
    variables cannot read the fix during a run: it sets no global_freq, and thermo divides by it),
    which thermo prints through the next part (0 before the first values) and a run 0 at the end."""
    names = " ".join(f"v_s{k}" for k in range(len(references)))
    text = (BED + SUMS + lines + "".join(f"variable s{k} equal 0.0\n" for k in range(len(references)))
            + "fix integr all nve/sphere\n" + thermo(names) + f"run {steps[0]}\n")
    for more in (*steps[1:], 0):
        text += "".join(f"variable t{k} equal {ref}\nvariable s{k} equal ${{t{k}}}\n"
                        for k, ref in enumerate(references))
        text += f"run {more}\n"
    return text


def cna_scene(lattice, cells, pair_cutoff, computes, counted, more=""):
    """A crystal of point particles (``lattice`` at reduced density 0.8442 filling ``cells``, half
    of it the group half) under pair soft, the ``computes`` (each a cna/atom named c...) summed by
    compute reduce, the particles of each class of compute ``counted`` counted, run 400 steps."""
    names = [line.split()[1] for line in computes.splitlines()]
    classes = "".join(f"variable n{k} atom c_{counted}=={k}\n" for k in range(6))
    return (f"units lj\natom_style atomic\natom_modify map array\nboundary p p p\nlattice {lattice} 0.8442\n"
            f"region box block {cells} units lattice\ncreate_box 1 box\ncreate_atoms 1 box\nmass 1 1.0\n"
            "region half block INF INF INF INF 0 1.5 units lattice\ngroup half region half\n"
            "velocity all ramp vx -0.6 0.6 y 0 3 units box\nvelocity all ramp vz -0.4 0.5 x 0 4 sum yes units box\n"
            f"neighbor 0.3 bin\npair_style soft {pair_cutoff}\npair_coeff * * 4.0\n{computes}{classes}"
            f"compute r all reduce sum {' '.join('c_' + n for n in names)}\n"
            f"compute n all reduce sum {' '.join(f'v_n{k}' for k in range(6))}\n"
            "fix integr all nve\ntimestep 0.005\ncompute pe all pe\n"
            f"thermo_style custom step atoms ke c_pe c_r[1] c_r[2] {more + ' ' if more else ''}"
            + " ".join(f"c_n[{k + 1}]" for k in range(6)) + "\n"
            "thermo_modify format float %20.15g norm no\nthermo 50\nrun 400\n")


def clumps(templates, pack_a, pack_b, steps=6000, more="", columns="", integrate="fix integr all multisphere\n"):
    """Two clumps of spheres (the ``templates``' lines: particletemplate/multisphere pts1, pts2 and
    their distributions pdd1, pdd2) inserted once by insert/pack, each at one point (a block of
    1e-15 m a side, all LIGGGHTS's insertion regions must have volume; their centres of mass land
    there to 1e-15), with ``pack_a`` and ``pack_b`` the insertion fixes' distribution, velocity and
    spin, in the template's orientation; moved by fix multisphere under gravity onto the hertz
    floor, where they meet each other about step 3600; ``more`` lines and thermo ``columns`` added."""
    return ("atom_modify sort 0 0.0\n"
            "fix floor all wall/gran model hertz tangential history primitive type 1 zplane 0.0\n"
            "fix grav all gravity 9.81 vector 0.0 0.0 -1.0\n" + templates
            + "region a block -0.01 -0.009999999999999 0.0 0.000000000000001 0.03 0.030000000000001 units box "
            "volume_limit 1e-50\n"
            "region b block 0.012 0.012000000000001 0.003 0.003000000000001 0.055 0.055000000000001 units box "
            "volume_limit 1e-50\n"
            f"fix insa all insert/pack seed 32452843 {pack_a} orientation template insert_every once "
            "overlapcheck yes region a particles_in_region 1\n"
            f"fix insb all insert/pack seed 32452867 {pack_b} orientation template insert_every once "
            "overlapcheck yes region b particles_in_region 1\n"
            + integrate +
            "compute rke all erotate/sphere\ncompute er all erotate\ncompute kem all ke/multisphere\n"
            "compute erm all erotate/multisphere\n" + SUMS.splitlines()[1] + "\n"
            "fix ts all check/timestep/gran 300 0.1 0.1\n" + more +
            "thermo_style custom step atoms ke c_rke c_er c_kem c_erm c_sum[1] c_sum[2] c_sum[3] c_sum[4] "
            f"c_sum[5] c_sum[6] f_ts[1] f_ts[2] {columns}".rstrip() + "\nthermo_modify format float %20.15g\nthermo 300\n"
            f"run {steps}\n")


def wall_region(region, law, fill="region fill sphere 0 0 0 3.7 units box", style="atomic", more="", steps=1000):
    """Point particles (or spheres, style sphere) of a simple-cubic lattice filling ``fill``, sheared
    and pushed by pair soft, held by fix wall/region on ``region`` (named wall) with ``law``
    (style epsilon sigma cutoff); ``more`` after the fix; thermo with the wall's energy and force."""
    return (f"units lj\natom_style {style}\natom_modify map array\nboundary f f f\n"
            "region box block -6 6 -6 6 -6 6 units box\ncreate_box 1 box\nlattice sc 1.0\n"
            f"{region}\n{fill}\ncreate_atoms 1 region fill\n"
            + ("set group all diameter 0.6 density 1.0\n" if style == "sphere" else "mass 1 1.0\n")
            + "velocity all ramp vx -0.5 0.5 y -4 4 units box\nvelocity all ramp vz -0.3 0.4 x -4 4 sum yes units box\n"
            "neighbor 0.3 bin\npair_style soft 1.0\npair_coeff * * 2.0\n"
            f"fix wall all wall/region ball {law}\n{more}"
            + ("fix integr all nve/sphere\n" if style == "sphere" else "fix integr all nve\n")
            + "timestep 0.005\ncompute sum all reduce sum x y z vx vy vz\ncompute pe all pe\n"
            "thermo_style custom step atoms ke c_pe f_wall f_wall[1] f_wall[2] f_wall[3] c_sum[1] c_sum[3] c_sum[4] "
            f"c_sum[6]\nthermo_modify format float %20.15g norm no\nthermo 100\nrun {steps}\n")


# a stream of 100 spheres every 2000 steps through a square face 0.15 m up, none touching another
# (overlapcheck, one velocity): which spheres its tracers mark is random, how many is not
STREAM_FACE = {"face.stl": floor_stl(0.15).replace("0.045", "0.04")}
STREAM = (HEAD.split("region box")[0].replace("atom_modify map array", "atom_modify map array sort 0 0.0")
          + "region box block -0.06 0.06 -0.06 0.06 0 0.2 units box\ncreate_box 1 box\nneighbor 0.001 bin\n"
          "neigh_modify delay 0\n" + liggghts_material(5.e6, 0.45, 0.3, 0.5)
          + "pair_style gran model hertz tangential history\npair_coeff * *\ntimestep 0.00001\n"
          "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2500 radius constant 0.002\n"
          "fix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0\n"
          "fix inface all mesh/surface file face.stl type 1\n"
          "fix ins all insert/stream seed 49979687 distributiontemplate pdd1 nparticles INF particlerate 5000 "
          "overlapcheck yes vel constant 0. 0. -1.0 insertion_face inface extrude_length 0.02\n")
def liquid(cohesion, content=0.01, tension=0.3, viscosity=0.01, max_ratio=1.1, more=""):
    """The material of a liquid bridge (LIGGGHTS's capillary cohesion models) and pair gran with
    ``cohesion``, replacing the head's dry pair style."""
    return (f"fix l1 all property/global surfaceLiquidContentInitial scalar {content}\n"
            f"fix l2 all property/global surfaceTension scalar {tension}\n"
            f"fix l3 all property/global fluidViscosity scalar {viscosity}\n"
            "fix l4 all property/global contactAngle peratomtype 30 40\n"
            "fix l5 all property/global minSeparationDistanceRatio scalar 1.01\n"
            f"fix l6 all property/global maxSeparationDistanceRatio scalar {max_ratio}\n" + more
            + f"pair_style gran model hertz tangential history {cohesion}\npair_coeff * *\n")


# the liquid's columns: its content summed, and its volume / (4/3 pi) (conserved); LIGGGHTS makes the
# content's fix property/atom at the first run, so the variables are 0 until a run 0 made it; then
# type 2 is made wetter (with equal contents washino's bridges give each sphere back what it lent)
LIQUID_COLUMNS = "v_lc v_lv"
LIQUID_SUMS = ("set type 2 property/atom surfaceLiquidContent 0.02\n"
               "compute lc all reduce sum f_surfaceLiquidContent\ncompute rad all property/atom radius\n"
               "variable vl atom f_surfaceLiquidContent*c_rad*c_rad*c_rad\ncompute lv all reduce sum v_vl\n"
               "variable lc equal c_lc\nvariable lv equal c_lv\n")


def wet_bed(cohesion, steps=4500, **material):
    """The bed with a liquid bridge of ``cohesion`` between its spheres (the floor stays dry)."""
    return (liquid(cohesion, **material) + BED + SUMS + "variable lc equal 0.0\nvariable lv equal 0.0\n"
            "fix integr all nve/sphere\n" + thermo(LIQUID_COLUMNS) + "run 0\n" + LIQUID_SUMS + f"run {steps}\n")


def wet_trio(cohesion, **material):
    """Three wet spheres near the x axis: 1 and 2 (types 1 and 2) touching and pulled apart, their
    bridge stretching until it breaks; 3 (type 1) coming at 1 from the side, sliding and spinning it
    up; thermo every 100 steps."""
    return (liquid(cohesion, **material) + "create_atoms 1 single 0.0 0.0 0.05 units box\n"
            "create_atoms 2 single 0.0109 0.0 0.05 units box\ncreate_atoms 1 single -0.0107 0.003 0.05 units box\n"
            "set type 1 diameter 0.01 density 2500\nset type 2 diameter 0.012 density 1500\n"
            "set atom 1 vx -0.03 vy 0.01\nset atom 2 vx 0.05 vz -0.02\nset atom 3 vx 0.08 vy -0.03\n"
            + SUMS + "variable lc equal 0.0\nvariable lv equal 0.0\nfix integr all nve/sphere\n"
            + thermo(LIQUID_COLUMNS).replace("thermo 300", "thermo 100") + "run 0\n" + LIQUID_SUMS + "run 4000\n")



def wet_pair_moved(cohesion):
    """Two wet spheres touching at rest, 50 steps, then moved beyond their bridge's rupture distance
    between runs and held there: the bridge breaks in the next run's setup force computation, whose
    liquid flux LIGGGHTS's transport equation drops (the contents stay)."""
    return (liquid(cohesion) + "create_atoms 1 single 0.0 0.0 0.05 units box\n"
            "create_atoms 2 single 0.0109 0.0 0.05 units box\n"
            "set type 1 diameter 0.01 density 2500\nset type 2 diameter 0.012 density 1500\n"
            + SUMS + "variable lc equal 0.0\nvariable lv equal 0.0\nfix integr all nve/sphere\n"
            + thermo(LIQUID_COLUMNS).replace("thermo 300", "thermo 10") + "run 0\n" + LIQUID_SUMS + "run 50\n"
            "set atom 2 x 0.0125\nvelocity all set 0.0 0.0 0.0 units box\nrun 50\n")


# three overlapping spheres; LIGGGHTS 3.8.0's Monte Carlo inertia tensor is wrong in its yz element
# (fix_template_multisphere.cpp), so where it is computed the body does not turn (tflag off)
TRIPLE = "nspheres 3 ntry 100000 spheres 0.0 0.0 0.0 0.005 0.008 0.0 0.0 0.004 0.0 0.007 0.002 0.0045"


CASES = {
    "capillary_easo": Case("pair_gran", ("gran cohesion easo/capillary/viscous", "pair_style gran"),
                           wet_bed("cohesion easo/capillary/viscous"), ranks=True),
    "capillary_easo_reduce": Case("pair_gran", ("gran cohesion easo/capillary/viscous",),
                                  wet_bed("cohesion easo/capillary/viscous rolling_friction epsd2 tangential_reduce on",
                                          tension=0.5, max_ratio=1.05,
                                          more="fix m5 all property/global coefficientRollingFriction "
                                               "peratomtypepair 2 0.1 0.2 0.2 0.3\n")),
    "capillary_easo_trio": Case("pair_gran", ("gran cohesion easo/capillary/viscous",),
                                wet_trio("cohesion easo/capillary/viscous", viscosity=0.05, content=0.0123456789)),
    "capillary_easo_moved": Case("pair_gran", ("gran cohesion easo/capillary/viscous",),
                                 wet_pair_moved("cohesion easo/capillary/viscous")),
    "capillary_washino": Case("pair_gran", ("gran cohesion washino/capillary/viscous", "pair_style gran"),
                              wet_bed("cohesion washino/capillary/viscous")),
    "capillary_washino_limited": Case(
        "pair_gran", ("gran cohesion washino/capillary/viscous",),
        wet_bed("cohesion washino/capillary/viscous limitLiquidContent on modifyLbVolume on tangential_reduce on",
                more="fix l7 all property/global maxLiquidContent peratomtype 0.008 0.02\n"
                     "fix l8 all property/global lbVolumeFraction scalar 0.1\n")),
    "capillary_washino_trio": Case("pair_gran", ("gran cohesion washino/capillary/viscous",),
                                   wet_trio("cohesion washino/capillary/viscous", viscosity=0.05)),
    "bed": Case("fix_granular", ("fix", "compute", "fix nve/sphere", "fix wall/gran", "gran model hertz",
                                 "gran tangential history", "compute erotate/sphere", "compute reduce", "velocity",
                                 "lattice", "create_atoms",
                                 "set", "group", "region", "create_box", "thermo_style", "run", "timestep"),
                bed(""), ranks=True),
    "gravity_viscous": Case("fix_granular", ("fix gravity", "fix viscous"),
                            bed("fix grav all gravity 9.81 vector 0.0 0.0 -1.0\nfix visc all viscous 0.0001\n")),
    "addforce": Case("fix_granular", ("fix addforce", "variable"),
                     bed("variable fx equal 0.002*sin(step*0.003)\nfix push top addforce v_fx 0.0 0.0005\n",
                         "f_push[1] f_push[2] f_push[3]")),
    "setforce": Case("fix_granular", ("fix setforce",),
                     bed("fix hold top setforce 0.0 NULL NULL\n", "f_hold[1] f_hold[2] f_hold[3]")),
    "aveforce": Case("fix_granular", ("fix aveforce",),
                     bed("fix av top aveforce NULL NULL -0.01\n", "f_av[1] f_av[2] f_av[3]")),
    "lineforce": Case("fix_granular", ("fix lineforce",), bed("fix line all lineforce 1.0 1.0 0.0\n")),
    "planeforce": Case("fix_granular", ("fix planeforce",), bed("fix plane all planeforce 0.0 1.0 1.0\n")),
    "freeze": Case("fix_granular", ("fix freeze",),
                   bed("region low block INF INF INF INF INF 0.02 units box\ngroup low region low\n"
                       "fix fr low freeze\n", "f_fr[1] f_fr[2] f_fr[3]")),
    "nve_limit": Case("fix_granular", ("fix nve/limit",), bed("", integrate="fix integr all nve/limit absolute 0.000005\n")),
    "spring_self": Case("fix_granular", ("fix spring/self",), bed("fix tether all spring/self 20.0\n", "f_tether")),
    "spring_self_xy": Case("fix_granular", ("fix spring/self",), bed("fix tether all spring/self 20.0 xy\n", "f_tether")),
    # the top row's centre tethered in x and z (y left out) near a sphere of radius 5 mm about a point
    # above it, its energy in pe; then the top row coupled to the other spheres' centre
    "spring_tether": Case("compute_basic", ("fix spring",),
                          bed("fix teth top spring tether 5.0 0.01 NULL 0.08 0.005\nfix_modify teth energy yes\n"
                              "compute pe all pe\n",
                              "c_pe f_teth f_teth[1] f_teth[2] f_teth[3] f_teth[4]"), ranks=True),
    "spring_couple": Case("compute_basic", ("fix spring",),
                          bed("group rest subtract all top\n"
                              "fix cpl top spring couple rest 4.0 0.006 NULL -0.02 0.002\n",
                              "f_cpl f_cpl[1] f_cpl[2] f_cpl[3] f_cpl[4]"), ranks=True),
    "drag": Case("fix_granular", ("fix drag",),
                 bed("fix pull top drag 0.0 0.0 0.0 0.002 0.001\n", "f_pull[1] f_pull[2] f_pull[3]")),
    "store_force": Case("fix_granular", ("fix store/force",),
                        bed("fix sf all store/force\ncompute sf all reduce sum f_sf[1] f_sf[2] f_sf[3]\n",
                            "c_sf[1] c_sf[2] c_sf[3]")),
    "check_timestep": Case("fix_granular", ("fix check/timestep/gran",),
                           bed("fix ts all check/timestep/gran 300 0.1 0.1\n", "f_ts[1] f_ts[2] f_ts[3]")),
    "nve": Case("fix_nve", ("fix nve",), bed("", integrate="fix integr all nve\n")),
    "nve_noforce": Case("fix_nve", ("fix nve/noforce",),
                        bed("", integrate="fix integr top nve/sphere\nfix fly all nve/noforce\n")),
    "momentum": Case("fix_simple", ("fix momentum",), bed("fix mom all momentum 200 linear 1 1 0 angular\n")),
    "ke_computes": Case("compute_basic", ("compute ke", "compute com", "compute gyration", "compute msd",
                                          "compute displace/atom", "compute property/atom"),
                        bed("compute k all ke\ncompute c all com\ncompute g top gyration\ncompute m all msd\n"
                            "compute d all displace/atom\n"
                            "compute p all property/atom vx omegax radius mass\n"
                            "compute ds all reduce sum c_d[1] c_d[2] c_d[3] c_d[4] c_p[1] c_p[2] c_p[3] c_p[4]\n",
                            "c_k c_c[1] c_c[2] c_c[3] c_g c_m[1] c_m[3] c_m[4] "
                            "c_ds[1] c_ds[2] c_ds[3] c_ds[4] c_ds[5] c_ds[6] c_ds[7] c_ds[8]")),
    "reduce_region": Case("compute_basic", ("compute reduce/region",),
                          bed("region half block 0.0 INF INF INF INF INF units box\n"
                              "compute rr all reduce/region half sum x vz\ncompute mx all reduce/region half max vz\n"
                              "compute rx all reduce/region half max vz x z replace 2 1 replace 3 1\n"
                              "compute rn all reduce min vx y replace 2 1\n",
                              "c_rr[1] c_rr[2] c_mx c_rx[1] c_rx[2] c_rx[3] c_rn[1] c_rn[2]")),
    "energy_computes": Case("compute_energy", ("compute erotate", "compute erotate/sphere/atom", "compute ke/atom",
                                               "compute pe"),
                            bed("compute er all erotate\ncompute era all erotate/sphere/atom\ncompute ka all ke/atom\n"
                                "compute pe all pe\ncompute es all reduce sum c_era c_ka\n",
                                "c_er c_es[1] c_es[2] c_pe")),
    "pressure": Case("compute_thermo", ("compute pressure",),
                     bed("compute tt all temp\ncompute pp all pressure tt\ncompute pv all pressure tt virial\n",
                         "c_tt c_pp c_pv c_pp[1] c_pp[3] c_pp[4]")),
    "coord": Case("compute_coord", ("compute coord/atom",),
                  bed("compute co all coord/atom 0.0125\ncompute cs all reduce sum c_co\n", "c_cs")),
    # not contact/atom/gran: LIGGGHTS 3.8.0's counts 16 pairs at step 2400 that neither it nor
    # pair/gran/local finds touching (its history flags of pairs about to touch)
    "contacts": Case("compute_gran_local", ("compute contact/atom", "compute pair/gran/local"),
                     bed("compute ca all contact/atom\n"
                         "compute pl all pair/gran/local force delta\n"
                         "compute cs all reduce sum c_ca\ncompute ps all reduce sum c_pl[1] c_pl[2] c_pl[3] c_pl[4]\n"
                         "compute pm all reduce max c_pl[4]\n",
                         "c_cs c_ps[1] c_ps[2] c_ps[3] c_ps[4] c_pm")),
    "coord_mix": Case("compute_coord", ("compute coord/atom",),
                      bed("compute co all coord/atom 0.0125 mix yes\ncompute ct all coord/atom 0.0125 1 2\n"
                          "compute cs all reduce sum c_co c_ct[1] c_ct[2]\n", "c_cs[1] c_cs[2] c_cs[3]")),
    "wall_local": Case("compute_gran_local", ("compute wall/gran/local",),
                       bed(MESH_FLOOR + "compute wl all wall/gran/local force\n"
                           "compute ws all reduce sum c_wl[1] c_wl[2] c_wl[3]\n", "c_ws[1] c_ws[2] c_ws[3]"),
                       files={"floor.stl": floor_stl(0.002)}),
    "ave_time": Case("analyze_ave", ("fix ave/time",),
                     bed("variable z equal c_sum[3]\n"
                         "fix at all ave/time 10 30 300 c_rke v_z ave running\n"
                         "fix aw all ave/time 10 30 300 c_rke v_z ave window 3\n",
                         "f_at[1] f_at[2] f_aw[1] f_aw[2]")),
    "ave_atom": Case("analyze_ave", ("fix ave/atom",),
                     bed("fix aa all ave/atom 10 30 300 vz x\ncompute as all reduce sum f_aa[1] f_aa[2]\n",
                         "c_as[1] c_as[2]")),
    "move": Case("fix_nve", ("fix move",),
                 bed("group bottom subtract all top\nfix mv top move linear 0.05 NULL -0.5\n",
                     integrate="fix integr bottom nve/sphere\n")),
    "move_wiggle": Case("fix_nve", ("fix move",),
                        bed("group bottom subtract all top\n"
                            "fix mv top move wiggle 0.0 0.004 -0.01 0.02 units box\n",
                            integrate="fix integr bottom nve/sphere\n")),
    "move_rotate": Case("fix_nve", ("fix move",),
                        bed("group bottom subtract all top\n"
                            "fix mv top move rotate 0.0 0.0 0.05 0 1 0 0.1 units box\n",
                            integrate="fix integr bottom nve/sphere\n")),
    "move_mesh": Case("fix_wall", ("fix move/mesh", "fix mesh/surface"),
                      bed(mesh_floor("lift.stl") + "fix lift all move/mesh mesh cad linear 0.0 0.0 0.2\n"),
                      files={"lift.stl": floor_stl(0.002137)}),
    "move_mesh_wiggle": Case("fix_wall", ("fix move/mesh",),
                             bed(mesh_floor("lift.stl") + "fix shake all move/mesh mesh cad wiggle amplitude 0.0 0.0 "
                                 "0.002 period 0.005\n"),
                             files={"lift.stl": floor_stl(0.002137)}),
    "mesh_planar": Case("fix_wall", ("fix mesh/surface/planar",),
                        bed("fix cad all mesh/surface/planar file floor.stl type 1\n"
                            "fix meshfloor all wall/gran model hertz tangential history mesh n_meshes 1 meshes cad\n"),
                        files={"floor.stl": floor_stl(0.002)}),
    "mesh_extrude": Case("fix_wall", ("fix mesh/surface", "fix mesh/surface/planar"),
                         BED + SUMS + "fix lid all mesh/surface/planar file lid.stl type 1 extrude_planar 0.06\n"
                         "fix integr all nve/sphere\n" + thermo() + "run 0\nfix cad all mesh/surface fix lid type 1\n"
                         + MESH_FLOOR_WALL + "run 3000\n",
                         files={"lid.stl": LID}),
    "mesh_heal": Case("fix_wall", ("fix mesh/surface",),
                      bed("fix cad all mesh/surface file dup.stl type 1 precision 1e-5 heal auto_remove_duplicates\n"
                          + MESH_FLOOR_WALL), files={"dup.stl": DUPLICATE_FLOOR}),
    # LIGGGHTS writes line 2 (the first facet, a duplicate) into the list, twice; pdps once
    "mesh_exclusion_write": Case("fix_wall", ("fix mesh/surface",),
                                 bed("fix cad all mesh/surface file dup.stl type 1 precision 1e-5 "
                                     "element_exclusion_list write written.txt\n" + MESH_FLOOR_WALL),
                                 files={"dup.stl": DUPLICATE_FLOOR}),
    "mesh_exclusion_read": Case("fix_wall", ("fix mesh/surface",),
                                bed("fix cad all mesh/surface file dup.stl type 1 element_exclusion_list read "
                                    "excluded.txt\n" + MESH_FLOOR_WALL),
                                files={"dup.stl": DUPLICATE_FLOOR, "excluded.txt": "2\n"}),
    "mesh_tolerant": Case("fix_wall", ("fix mesh/surface",),
                          bed("fix cad all mesh/surface file sliver.stl type 1 curvature 5 curvature_tolerant yes\n"
                              + MESH_FLOOR_WALL), files={"sliver.stl": SLIVER_FLOOR}),
    "mesh_temperature": Case("fix_wall", ("fix mesh/surface", "fix heat/gran/conduction"), HOT_FLOOR.format(""),
                             files={"floor.stl": floor_stl(0.002)}),
    "wall_local_heat": Case("fix_wall", ("compute wall/gran/local",),
                            HOT_FLOOR.format("").replace(
                                "compute tm all reduce max f_Temp\n",
                                "compute tm all reduce max f_Temp\ncompute wl all wall/gran/local delta heatFlux\n"
                                "compute ws all reduce sum c_wl[1] c_wl[2]\n").replace(
                                "c_ts[1] c_ts[2] c_ts[3] c_tm", "c_ts[1] c_ts[2] c_tm c_ws[1] c_ws[2]"),
                            files={"floor.stl": floor_stl(0.002)}),
    # LIGGGHTS 3.8.0 sums no heat flux into a mesh: mass_temperature changes nothing
    "mesh_mass_temperature": Case("fix_wall", ("fix mesh/surface",), HOT_FLOOR.format(" mass_temperature 0.01"),
                                  files={"floor.stl": floor_stl(0.002)}),
    "deform": Case("fix_nh", ("fix deform",),
                   bed("fix squeeze all deform 1 x final -0.04 0.04 y final -0.045 0.045 remap x units box\n")),
    "adapt_diameter": Case("fix_simple", ("fix adapt",),
                           bed("variable d equal 0.01+0.004*step/3000\nfix grow all adapt 1 atom diameter v_d\n")),
    "ave_spatial": Case("analyze_ave", ("fix ave/spatial",),
                        bed("fix prof all ave/spatial 10 30 300 z lower 0.02 vz vx density/mass units box\n",
                            "f_prof[1][1] f_prof[1][2] f_prof[1][3] f_prof[1][4] f_prof[1][5] f_prof[2][4] "
                            "f_prof[3][3] f_prof[3][5]")),
    "regions": Case("core", ("region", "compute reduce/region"),
                    bed("region s sphere 0.0 0.0 0.03 0.02 units box\n"
                        "region c cylinder z 0.01 0.0 0.015 INF INF units box\n"
                        "region k cone z 0.0 0.0 0.01 0.03 0.0 0.06 units box\n"
                        "region pl plane 0.0 0.0 0.02 0.0 0.3 1.0 units box\n"
                        "region pr prism -0.03 0.02 -0.03 0.03 0.0 0.05 0.01 0.0 0.0 units box\n"
                        "region u union 2 s c\nregion i intersect 2 k pl\n"
                        "region o block -0.02 0.02 -0.02 0.02 0.0 0.04 side out units box\n"
                        "compute rs all reduce/region s sum vz\ncompute rc all reduce/region c sum vz\n"
                        "compute rk all reduce/region k sum vz\ncompute rp all reduce/region pl sum vz\n"
                        "compute rr all reduce/region pr sum vz\ncompute ru all reduce/region u sum vz\n"
                        "compute ri all reduce/region i sum vz\ncompute ro all reduce/region o sum vz\n",
                        "c_rs c_rc c_rk c_rp c_rr c_ru c_ri c_ro")),
    "displace_delete": Case("core", ("displace_atoms", "delete_atoms"),
                            bed("displace_atoms top move 0.003 -0.002 0.004 units box\n"
                                "region corner block 0.0 INF 0.0 INF INF INF units box\n"
                                "delete_atoms region corner\n")),
    # the top row squeezed in x about the middle (set after a stretch, then remap of a group); then
    # the box made periodic in x and y, narrowed in x, widened in y with z keeping the volume, all
    # remapped, and lowered in z without (its default units: box, LIGGGHTS 3.8.0's)
    "change_box": Case("core", ("change_box",),
                       BED + SUMS + "fix integr all nve/sphere\n" + thermo(BOX_BOUNDS) + "run 1500\n"
                       "change_box top x scale 1.25 set x scale 0.8 remap\n"
                       "change_box all boundary p p f x final -0.045 0.045 y scale 1.1 z volume remap "
                       "z delta 0.0 -0.01\nrun 1500\n", ranks=True),
    # the box lowered under the falling top row, which leaves it (LIGGGHTS ignores lost particles)
    "change_box_lost": Case("core", ("change_box",),
                            BED + SUMS + "fix integr all nve/sphere\n" + thermo(BOX_BOUNDS) + "run 600\n"
                            "change_box all z final 0.0 0.04 units box\nrun 900\n", ranks=True),
    # the bed (molecules 1 and 3) beside a copy of itself 0.08 away, everything shifted by -0.03 in x; the
    # ids weighted by x summed, the molecules listed and the first counted (copies keep their molecule;
    # LIGGGHTS 3.8.0 prints no number for the count of the second after replicate)
    "replicate": Case("core", ("replicate",),
                      HEAD.replace("atom_style granular", "atom_style hybrid granular molecular") + BED
                      + "set group all mol 1\nset group top mol 3\n"
                      "replicate 2 1 1 offset 0.08 0.0 0.0 shift -0.03 0.0 0.0\n" + SUMS
                      + "variable idx atom id*x\ncompute ids all reduce sum v_idx\n"
                      "compute pm all property/molecule mol count\nfix integr all nve/sphere\n"
                      + thermo("c_ids c_pm[1][1] c_pm[1][2] c_pm[2][1] " + BOX_BOUNDS) + "run 3000\n",
                      head=False, ranks=True),
    # LJ-units point particles in a periodic box, four copies side by side (offset the box's
    # lengths in x, more than it in y) and shifted, then run
    "replicate_atomic": Case("core", ("replicate",),
                             ATOMIC.replace("region box block 0 6 0 6 0 6", "region box block 0 4 0 4 0 3")
                             .replace("region half block 0 3", "region half block 0 2")
                             + "replicate 2 2 1 offset 4.0 4.5 0.0 shift 0.3 -0.2 0.0\n"
                             "variable idx atom id*x+0.5*id*y\ncompute ids all reduce sum v_idx\n"
                             "pair_style soft 1.2\npair_coeff * * 3.0\n"
                             + ATOMIC_RUN.replace("c_sum[6]", "c_sum[6] c_ids " + BOX_BOUNDS), head=False,
                             ranks=True),
    # the bed overwritten by the snapshot of step 500 (velocities, radii, omegax; its masses kept),
    # the 22 particles of the 48 the snapshot lacks trimmed; the step is 500 after
    "read_dump": Case("core", ("read_dump",),
                      BED + SUMS + "read_dump snapshots.dump 500 x y z vx vy vz radius omegax box no trim yes\n"
                      "fix integr all nve/sphere\n" + thermo(BOX_BOUNDS) + "run 2000\n", files=SNAPSHOTS,
                      ranks=True),
    # everything purged and the step-800 snapshot added (new ids, their types, masses and image flags
    # read; vy 0) in its box, periodic in x and y: the scaled positions outside it wrapped in
    "read_dump_add": Case("core", ("read_dump",),
                          HEAD.replace("boundary f f f", "boundary p p f") + BED + SUMS
                          + "read_dump snapshots.dump 800 x y z vx vz radius mass ix iy iz purge yes replace no "
                          "add yes\ncompute im all property/atom ix iy\ncompute ims all reduce sum c_im[1] c_im[2]\n"
                          "variable idx atom id*x\ncompute ids all reduce sum v_idx\n"
                          "fix integr all nve/sphere\n" + thermo("c_ims[1] c_ims[2] c_ids " + BOX_BOUNDS)
                          + "run 2000\n", head=False, files=SNAPSHOTS, ranks=True),
    "runs": Case("core", ("reset_timestep", "unfix", "uncompute", "run"),
                 BED + SUMS + "fix integr all nve/sphere\nfix grav all gravity 9.81 vector 0.0 0.0 -1.0\n"
                 + thermo() + "run 1200\nunfix grav\nreset_timestep 5000\nrun 900\n"
                 "compute extra all ke\nuncompute extra\nrun 900\n"),
    "variables": Case("core", ("variable", "if", "label", "jump", "next", "print"),
                      BED + SUMS + "fix integr all nve/sphere\n"
                      "variable zc equal c_sum[3]/atoms\nvariable big equal (ke>0.01)*2+(ke<=0.01)\n"
                      + thermo("v_zc v_big") +
                      "variable k loop 3\nlabel again\n"
                      "if \"${k} == 2\" then \"fix grav all gravity 9.81 vector 0.0 0.0 -1.0\" "
                      "else \"print 'no gravity in run ${k}'\"\n"
                      "run 1000\nif \"${k} == 2\" then \"unfix grav\"\nnext k\njump SELF again\n"),
    "thermo_settings": Case("core", ("thermo", "thermo_modify", "neighbor", "neigh_modify", "atom_modify",
                                     "communicate", "newton", "run_style", "compute_modify",
                                     "fix_modify", "echo", "units", "boundary", "timestep"),
                            BED + SUMS + "fix integr all nve/sphere\nneighbor 0.003 bin\n"
                            "neigh_modify every 1 delay 0 check yes\nrun_style verlet\n"
                            "echo none\ncompute tmp all temp\ncompute_modify tmp extra 0\n"
                            "fix_modify integr energy no\n"
                            + thermo("c_tmp") + "thermo_modify lost ignore norm no\nthermo 200\nrun 3000\n"),
    "rigid_single": Case("fix_rigid", ("fix rigid",),
                         bed("group bottom subtract all top\nfix body top rigid single\n",
                             integrate="fix integr bottom nve/sphere\n")),
    "rigid_groups": Case("fix_rigid", ("fix rigid",),
                         bed("region left block INF 0.0 INF INF 0.04 INF units box\ngroup left region left\n"
                             "group right subtract top left\ngroup bottom subtract all top\n"
                             "fix bodies top rigid group 2 left right\n",
                             integrate="fix integr bottom nve/sphere\n")),
    "heat_conduction": Case("fix_heat", ("fix heat/gran/conduction", "fix property/atom", "fix property/global"),
                            BED + SUMS + "fix integr all nve/sphere\n"
                            "fix k all property/global thermalConductivity peratomtype 5.0 20.0\n"
                            "fix c all property/global thermalCapacity peratomtype 10.0 30.0\n"
                            "fix ht all heat/gran/conduction initial_temperature 300.0\n"
                            "fix mark all property/atom mark scalar yes no no 1.5\n"
                            "compute ts all reduce sum f_Temp f_heatFlux f_mark\ncompute tm all reduce max f_Temp\n"
                            + thermo("c_ts[1] c_ts[2] c_ts[3] c_tm") +
                            # LIGGGHTS sets a property/atom only after a run 0 (before it, it aborts)
                            "run 0\nset group top property/atom Temp 400.0\nset type 2 property/atom mark 2.0\n"
                            "run 3000\n"),
    # a vector per-atom property's columns count from 1 (f_directionalHeatFlux[3]), a scalar's [0] is the
    # scalar (f_Temp[0])
    "heat_flux_columns": Case("fix_heat", ("fix heat/gran/conduction", "fix property/atom"),
                              BED + SUMS + "fix integr all nve/sphere\n"
                              "fix k all property/global thermalConductivity peratomtype 5.0 20.0\n"
                              "fix c all property/global thermalCapacity peratomtype 10.0 30.0\n"
                              "fix ht all heat/gran/conduction initial_temperature 300.0\n"
                              "compute hf all reduce sum f_Temp[0] f_directionalHeatFlux[1] "
                              "f_directionalHeatFlux[2] f_directionalHeatFlux[3]\n"
                              + thermo("c_hf[1] c_hf[2] c_hf[3] c_hf[4]") +
                              "run 0\nset group top property/atom Temp 400.0\nrun 3000\n"),
    "heat_contact_data": Case("fix_heat", ("fix heat/gran/conduction",),
                              BED + SUMS + "fix integr all nve/sphere\n"
                              "fix k all property/global thermalConductivity peratomtype 5.0 20.0\n"
                              "fix c all property/global thermalCapacity peratomtype 10.0 30.0\n"
                              "fix ht all heat/gran/conduction initial_temperature 300.0 "
                              "store_contact_data yes\n"
                              "compute cd all reduce sum f_contactAreaConduction f_nContactsConduction "
                              "f_wallHeattransferCoeff f_wallTemp f_Temp\n"
                              "compute ca all reduce max f_contactAreaConduction\n"
                              + thermo("c_cd[1] c_cd[2] c_cd[3] c_cd[4] c_cd[5] c_ca") + "thermo 50\n"
                              "run 0\nset group top property/atom Temp 400.0\nrun 3000\n"),
    "pair_none": Case("core", ("pair_style none", "pair_style"),
                      bed("pair_style none\natom_modify sort 0 0.0\n")),
    # a rigid layer that lands on the floor: LIGGGHTS's wall/gran takes the body's mass as pair gran does
    "rigid_on_floor": Case("fix_rigid", ("fix rigid", "fix wall/gran"),
                           bed("region low block INF INF INF INF INF 0.02 units box\ngroup low region low\n"
                               "group rest subtract all low\nfix body low rigid single\n",
                               integrate="fix integr rest nve/sphere\n")),
    # a clump whose mass and inertia are given (its volume and centre by Monte Carlo), spinning, and
    # another of the same template; they land on the floor and on each other
    "multisphere_given": Case("fix_rigid", ("fix multisphere", "fix particletemplate/multisphere",
                                            "compute ke/multisphere", "compute erotate/multisphere"), clumps(
        f"fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 {TRIPLE} "
        "type 1 mass 0.0025 inertia_tensor 3.1e-8 -4e-9 1e-9 2.7e-8 -2e-9 4.0e-8 use_volume\n"
        "fix pdd1 all particledistribution/discrete 15485867 1 pts1 1.0\n",
        "distributiontemplate pdd1 vel constant 0.2 0.0 -0.5 omega constant 0.0 5.0 3.0",
        "distributiontemplate pdd1 vel constant -0.3 0.05 -0.8"), ranks=True),
    # the Monte Carlo template (mass, centre, inertia) with its torque off, and a clump of four
    # spheres of the second type whose mass and inertia are given with use_density (no Monte Carlo:
    # the template's origin is its centre of mass), free in x and z only, spinning
    "multisphere_mc": Case("fix_rigid", ("fix multisphere", "fix particletemplate/multisphere",
                                         "compute ke/multisphere", "compute erotate/multisphere"), clumps(
        f"fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 {TRIPLE} "
        "type 1 tflag off off off\n"
        "fix pdd1 all particledistribution/discrete 15485867 1 pts1 1.0\n"
        "fix pts2 all particletemplate/multisphere 15485917 atom_type 2 density constant 1500 nspheres 4 ntry 200000 "
        "spheres 0.0 0.0 0.0 0.006 0.0 0.0 0.009 0.005 0.0 0.0 -0.009 0.005 0.007 0.0 0.0 0.004 type 2 mass 0.004 "
        "inertia_tensor 5.0e-8 0.0 1.0e-9 6.0e-8 0.0 4.5e-8 use_density fflag on off on\n"
        "fix pdd2 all particledistribution/discrete 15485927 1 pts2 1.0\n",
        "distributiontemplate pdd1 vel constant 0.2 0.0 -0.5",
        "distributiontemplate pdd2 vel constant -0.3 0.05 -0.8 omega constant 2.0 -4.0 1.0")),
    # the bodies' properties: the second body's one by one (the first's inertia frame is LIGGGHTS's
    # wrong Monte Carlo tensor's), sums over both of the single-valued ones (compute rigid is the
    # same compute)
    "multisphere_properties": Case("fix_rigid", ("compute multisphere", "compute multisphere/single", "compute rigid"),
                                   clumps(
        f"fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 {TRIPLE} "
        "type 1 tflag off off off\n"
        "fix pdd1 all particledistribution/discrete 15485867 1 pts1 1.0\n"
        "fix pts2 all particletemplate/multisphere 15485917 atom_type 2 density constant 1500 nspheres 4 ntry 200000 "
        "spheres 0.0 0.0 0.0 0.006 0.0 0.0 0.009 0.005 0.0 0.0 -0.009 0.005 0.007 0.0 0.0 0.004 type 2 mass 0.004 "
        "inertia_tensor 5.0e-8 0.0 1.0e-9 6.0e-8 0.0 4.5e-8 use_density fflag on off on\n"
        "fix pdd2 all particledistribution/discrete 15485927 1 pts2 1.0\n",
        "distributiontemplate pdd1 vel constant 0.2 0.0 -0.5",
        "distributiontemplate pdd2 vel constant -0.3 0.05 -0.8 omega constant 2.0 -4.0 1.0",
        more="compute m all multisphere property masstotal\ncompute d all multisphere property density\n"
             "compute n all rigid property nrigid\ncompute t all multisphere property atomtype\n"
             "compute c all multisphere property clumptype\ncompute i all multisphere property id_multisphere\n"
             "compute vz all multisphere property vcm\n"
             "compute sums all reduce sum c_m c_d c_n c_t c_c c_i c_vz[3]\n"
             "compute x2 all multisphere/single id 2 property xcm\ncompute v2 all multisphere/single id 2 property vcm\n"
             "compute f2 all multisphere/single id 2 property fcm\ncompute q2 all multisphere/single id 2 property torque\n"
             "compute l2 all multisphere/single id 2 property angmom\ncompute w2 all multisphere/single id 2 property omega\n"
             "compute u2 all multisphere/single id 2 property quat\ncompute i2 all multisphere/single id 2 property inertia\n"
             "compute e2 all multisphere/single id 2 property ez_space\ncompute m1 all multisphere/single id 1 property masstotal\n",
        columns="c_sums[1] c_sums[2] c_sums[3] c_sums[4] c_sums[5] c_sums[6] c_sums[7] c_x2[1] c_x2[3] c_v2[1] c_v2[3] "
                "c_f2[1] c_f2[3] c_q2[1] c_q2[2] c_q2[3] c_l2[1] c_l2[2] c_w2[1] c_w2[3] c_u2[1] c_u2[2] c_u2[3] c_u2[4] "
                "c_i2[1] c_i2[2] c_i2[3] c_e2[1] c_e2[3] c_m1"), ranks=True),
    # LAMMPS's fix wall/region: the inside of a sphere, of a block (several faces at a corner), the
    # outside of a sphere (side out) with the wall's energy in pe, and the colloid law on spheres
    "wall_region_lj93": Case("fix_wall", ("fix wall/region",), wall_region(
        "region ball sphere 0 0 0 4.6 units box", "lj93 1.0 1.0 2.5"), head=False, ranks=True),
    "wall_region_lj126_block": Case("fix_wall", ("fix wall/region",), wall_region(
        "region ball block -4.3 4.4 -4.5 4.2 -4.6 4.5 units box", "lj126 1.5 0.8 1.6",
        fill="region fill block -3.5 3.5 -3.5 3.5 -3.5 3.5 units box"), head=False),
    "wall_region_harmonic_out": Case("fix_wall", ("fix wall/region", "fix_modify"), wall_region(
        "region ball sphere 0.3 -0.2 0.1 1.6 side out units box", "harmonic 2.0 1.0 1.0",
        fill="region fill block -4.5 4.5 -4.5 4.5 -4.5 4.5 units box\n"
             "region notfill sphere 0.3 -0.2 0.1 2.2 side out units box\nregion fill_out intersect 2 fill notfill",
        more="fix_modify wall energy yes\n").replace("create_atoms 1 region fill\n", "create_atoms 1 region fill_out\n"),
        head=False),
    # LAMMPS's colloid law in wall/region attracts a sphere near the surface (LIGGGHTS 3.8.0 and LAMMPS
    # 22 Jul 2025 print the same rows and both stop at step 301: a sphere reaches the surface)
    "wall_region_colloid": Case("fix_wall", ("fix wall/region",), wall_region(
        "region ball sphere 0 0 0 4.8 units box", "colloid 2.0 1.0 1.5", style="sphere", steps=300), head=False),
    # packets of 30 every 4000 steps from step 3000 (a packet waits for the spheres crossing after
    # it), and 250 from step 2202 once (over three insertions); their counts in thermo
    "tracer_stream": Case("fix_property", ("fix property/atom/tracer/stream",), STREAM
        + "fix tr all property/atom/tracer/stream mark_step 3000 n_tracer 30 insert_stream ins every 4000\n"
          "fix trb all property/atom/tracer/stream mark_step 2202 n_tracer 250 insert_stream ins every once\n"
          "compute m all reduce sum f_tr f_trb\nfix integr all nve/sphere\n"
          "thermo_style custom step atoms f_tr f_trb c_m[1] c_m[2]\nthermo_modify format float %20.15g\n"
          "thermo 500\nrun 14000\n", head=False, files=STREAM_FACE, ranks=True),
    # LIGGGHTS's aliases of pair gran (its manual: for pair hybrid with a law per phase, which pdps's
    # pair hybrid does not take granular styles for): the bed under each name, without tangential
    # history (with it LIGGGHTS 3.8.0 crashes in FixContactHistory::init under either name, 12-03)
    "bubble": Case("pair_gran", ("pair_style bubble",),
                   HEAD.replace("pair_style gran model hertz tangential history",
                                "pair_style bubble model hertz tangential no_history") + bed(""), head=False),
    "gran_bubble": Case("pair_gran", ("pair_style bubble",),
                        HEAD.replace("pair_style gran model hertz tangential history",
                                     "pair_style gran_bubble model hooke tangential no_history")
                        + "fix m5 all property/global characteristicVelocity scalar 1.5\n" + bed(""), head=False),
    # residence times in the whole simulation and in two regions looked at every 20 steps (their bitmap
    # summed too), and over the top row alone; the global means divide by all particles, as LIGGGHTS's
    "regiontracer_time": Case("fix_property", ("fix property/atom/regiontracer/time",),
                              bed("region low block INF INF INF INF INF 0.025 units box\n"
                                  "region left block INF 0.0 INF INF INF INF units box\n"
                                  "fix rt all property/atom/regiontracer/time add_region low add_region left "
                                  "check_region_every 20\nfix rt0 top property/atom/regiontracer/time\n"
                                  "compute s all reduce sum f_rt[1] f_rt[2] f_rt[3] f_rt[4] f_rt0\n",
                                  "f_rt[1] f_rt[2] f_rt[3] f_rt0[1] c_s[1] c_s[2] c_s[3] c_s[4] c_s[5]"), ranks=True),
    # loose spheres beside the clumps, in fix multisphere's group: two of them collide head-on (the
    # body exclusion must leave them, which belong to no body, in the lists), integrated by nve/sphere
    "multisphere_loose": Case("fix_rigid", ("fix multisphere",), clumps(
        "create_atoms 1 single 0.0 -0.03 0.02 units box\ncreate_atoms 1 single 0.0 -0.012 0.021 units box\n"
        "group loose id 1 2\nset group loose diameter 0.008 density 2500\n"
        "velocity loose set 0.0 0.4 0.0 units box\nset atom 2 vy -0.4\n"
        f"fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 {TRIPLE} "
        "type 1 mass 0.0025 inertia_tensor 3.1e-8 -4e-9 1e-9 2.7e-8 -2e-9 4.0e-8 use_volume\n"
        "fix pdd1 all particledistribution/discrete 15485867 1 pts1 1.0\n",
        "distributiontemplate pdd1 vel constant 0.2 0.0 -0.5 omega constant 0.0 5.0 3.0",
        "distributiontemplate pdd1 vel constant -0.3 0.05 -0.8", more="fix move_loose loose nve/sphere\n"),
        ranks=True),
    # bodies of three spheres apart from each other that break when a sphere's centre comes below
    # 12 mm (a tracer's marker as the trigger: LIGGGHTS 3.8.0 checks a v_ trigger against the fix of
    # the variable's index, and stops); nve/sphere moves the released spheres. Without gravity: LIGGGHTS
    # 3.8.0 gives the released spheres and the broken body no weight for the step after the break
    # (measured with thermo every step: their velocities stand still that step), pdps gives it. The
    # run ends before the broken body's centre reaches the floor, which LIGGGHTS drops it about
    "multisphere_break": Case("fix_rigid", ("fix multisphere/break",), clumps(
        "region low block INF INF INF INF INF 0.012 units box\n"
        "fix low all property/atom/tracer region_mark low mark_step 0 marker_style heaviside check_mark_every 1\n"
        "fix pts1 all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 nspheres 3 ntry 100000 "
        "spheres 0.0 0.0 0.0 0.004 0.009 0.0 0.0 0.004 0.0 0.0085 0.001 0.004 type 1 mass 0.002 "
        "inertia_tensor 3.1e-8 -4e-9 1e-9 2.7e-8 -2e-9 4.0e-8 use_volume\n"
        "fix pdd1 all particledistribution/discrete 15485867 1 pts1 1.0\n",
        "distributiontemplate pdd1 vel constant 0.2 0.0 -0.5 omega constant 0.0 5.0 3.0",
        "distributiontemplate pdd1 vel constant -0.3 0.05 -0.8",
        integrate="fix move all nve/sphere\nfix integr all multisphere/break trigger_name f_low trigger_threshold 0.5 "
                  "trigger_timeStep 100\n", steps=5700).replace("fix grav all gravity 9.81 vector 0.0 0.0 -1.0\n", ""),
        ranks=True),
    # settings without an effect here: box tilt (orthogonal box), dielectric (no Coulombic style in
    # either program), and partition (one partition: yes 1 runs its command, no 1 does not)
    "settings": Case("core", ("box", "dielectric", "partition"),
                     HEAD.replace("region box block", "box tilt large\nregion box block", 1)
                     + "dielectric 2.0\n" + bed("partition no 1 fix push all addforce 0.0 0.0 5.0\n"
                                                 "partition yes * fix drag all viscous 0.0002\n"
                                                 "partition no 2* fix grav all gravity 9.81 vector 0.0 0.0 -1.0\n"),
                     head=False),
    # charged spheres in a field: a constant x part on the top row, an equal-style z part that
    # oscillates and an atom-style y part that grows with x on all (charges of both signs)
    "efield": Case("fix_granular", ("fix efield",),
                   HEAD.replace("atom_style granular", "atom_style hybrid granular charge")
                   + bed("set group all charge -1.0e-6\nset group top charge 2.0e-6\n"
                         "variable ez equal -800.0*(1.0+0.5*sin(step*0.002))\nvariable ey atom 3.0e4*x\n"
                         "fix push top efield 1500.0 0.0 0.0\nfix field all efield 0.0 v_ey v_ez\n"), head=False),
    # contact/atom/gran counts the pairs that touch (within its skin) or keep a contact history
    # (until the lists are next built), and so differs from contact/atom after contacts open
    "contacts_gran": Case("compute_gran_local", ("compute contact/atom/gran",),
                          bed("compute cg all contact/atom/gran\ncompute cs all contact/atom/gran skin 0.001\n"
                              "compute ca all contact/atom\ncompute sums all reduce sum c_cg c_cs c_ca\n",
                              "c_sums[1] c_sums[2] c_sums[3]"), ranks=True),
    "restart": Case("core", ("write_restart", "read_restart", "clear"),
                    BED + SUMS + "fix integr all nve/sphere\n" + thermo() + "run 1500\n"
                    "write_restart bed.restart\nclear\natom_modify map array\nnewton off\n"
                    "communicate single vel yes\nread_restart bed.restart\nneighbor 0.002 bin\n"
                    "neigh_modify delay 0\n" + MATERIAL + AGAIN + SUMS + "fix integr all nve/sphere\n"
                    + thermo() + "run 1500\n"),
    "data_file": Case("core", ("write_data", "read_data", "include", "atom_style", "boundary", "units"),
                      BED + SUMS + "fix integr all nve/sphere\n" + thermo() + "run 1500\n"
                      "write_data bed.data\nclear\ninclude settings.in\nread_data bed.data\n"
                      "neighbor 0.002 bin\nneigh_modify delay 0\n" + MATERIAL + AGAIN
                      + "group top type 2\n" + SUMS + "fix integr all nve/sphere\n" + thermo() + "run 1500\n",
                      files={"settings.in": "atom_style granular\natom_modify map array\nboundary f f f\n"
                                            "newton off\ncommunicate single vel yes\nunits si\n"}),
    "atomic_soft": Case("pair_simple", ("pair_style soft", "pair_coeff", "mass", "atom_style", "dimension"),
                        ATOMIC + "pair_style soft 1.2\npair_coeff * * 3.0\n" + ATOMIC_RUN, head=False),
    "atomic_hybrid": Case("pair_hybrid", ("pair_style hybrid",),
                          ATOMIC + "pair_style hybrid soft 1.2 soft 1.0\npair_coeff 1 1 soft 1 3.0\n"
                          "pair_coeff 2 2 soft 2 2.0\npair_coeff 1 2 soft 1 1.0\n" + ATOMIC_RUN, head=False),
    "atomic_overlay": Case("pair_hybrid", ("pair_style hybrid/overlay",),
                           ATOMIC + "pair_style hybrid/overlay soft 1.2 soft 1.0\npair_coeff * * soft 1 3.0\n"
                           "pair_coeff 1 1 soft 2 2.0\n" + ATOMIC_RUN, head=False),
    "enforce2d": Case("fix_simple", ("fix enforce2d", "dimension"),
                      ATOMIC.replace("units lj\n", "units lj\ndimension 2\n").replace("boundary p p p", "boundary p p p")
                      .replace("region box block 0 6 0 6 0 6", "region box block 0 6 0 6 -0.5 0.5")
                      .replace("lattice sc 1.0", "lattice sq 1.0") + "pair_style soft 1.2\npair_coeff * * 3.0\n"
                      + ATOMIC_RUN.replace("fix integr all nve\n", "fix integr all nve\nfix flat all enforce2d\n"),
                      head=False),
    "dumps": Case("dump_text", ("dump", "dump_modify", "undump", "write_dump"),
                  bed("dump d all custom 500 bed.dump id type x y z vx vy vz radius mass\n"
                      "dump_modify d sort id\n"
                      "dump t top custom 1000 top.dump id x z omegax omegay omegaz fx fz\n"
                      "dump_modify t sort id\n", steps=1500)
                  + "undump t\nwrite_dump all custom last.dump id x y z vx vy vz modify sort id\nrun 1500\n",
                  outputs=("bed.dump", "top.dump", "last.dump")),
    "restart_every": Case("core", ("restart", "processors"),
                          HEAD.replace("create_box 2 box", "processors * * *\ncreate_box 2 box") + BED + SUMS
                          + "fix integr all nve/sphere\n" + thermo() + "restart 1500 bed.restart\nrun 1500\n"
                          "clear\natom_modify map array\nnewton off\ncommunicate single vel yes\n"
                          "read_restart bed.restart.1500\nneighbor 0.002 bin\nneigh_modify delay 0\n" + MATERIAL
                          + AGAIN + SUMS + "fix integr all nve/sphere\n" + thermo() + "run 1500\n", head=False),
    # the working directory changes, files are made, moved and removed, the environment feeds a
    # variable, and quit ends the script before its last run
    "shell_quit": Case("core", ("shell", "quit"),
                       BED + SUMS + "fix integr all nve/sphere\n" + thermo() + "run 900\n"
                       "shell mkdir out scratch\nshell putenv STEPS=600 LABEL=bed\n"
                       "variable steps getenv STEPS\nvariable label getenv LABEL\nrun ${steps}\n"
                       "shell cd out\nwrite_dump all custom ${label}.dump id x y z modify sort id\n"
                       "shell cd ..\nshell mv out/bed.dump moved.dump\nshell rmdir out scratch\n"
                       "shell touch gone.txt\nshell rm gone.txt\nrun 900\nquit\nrun 900\n",
                       outputs=("moved.dump",), status=1),
    # spheres falling through a tilted face: counted as they pass, once or every time, with LIGGGHTS's
    # rates between thermo lines, a file of those counted, a property summed, the counted deleted
    "massflow": Case("fix_wall", ("fix massflow/mesh",),
                     bed("fix face all mesh/surface file face.stl type 1\n"
                         "fix flow all massflow/mesh mesh face vec_side 0 0 -1 file flow.txt writeTime\n",
                         "f_flow[1] f_flow[2] f_flow[3] f_flow[4] f_flow[5] f_flow[6]"),
                     files=FACE, outputs=("flow.txt",)),
    "massflow_delete": Case("fix_wall", ("fix massflow/mesh",),
                            bed("fix face all mesh/surface file face.stl type 1\n"
                                "fix mark all property/atom mark scalar yes no no 1.5\n"
                                "fix flow top massflow/mesh mesh face count once vec_side 0.1 0.2 -1 "
                                "sum_property mark delete_atoms yes screen no append gone.txt\n",
                                "f_flow[1] f_flow[2] f_flow[3] f_flow[4] f_flow[5] f_flow[6] f_flow[7]"),
                            files=FACE, outputs=("gone.txt",)),
    "massflow_outlet": Case("fix_wall", ("fix massflow/mesh",),
                            bed("fix face all mesh/surface file face.stl type 1\n"
                                "fix down all massflow/mesh mesh face count once point_at_outlet 0.0 0.0 -0.5\n"
                                "fix up all massflow/mesh mesh face count once point_at_outlet 0.0 0.0 0.5 "
                                "inside_out\n",
                                "f_down[1] f_down[2] f_up[1] f_up[2] f_up[3]"),
                            files=FACE, ranks=True),
    # a sieve of holes smaller than every sphere (passage probability 0): the spheres bounce off the
    # face on its spring-dashpot; one of holes far larger (probability > 1): all pass, counted as
    # massflow/mesh counts them
    "sieve_held": Case("fix_wall", ("fix massflow/mesh/sieve",),
                       bed("fix face all mesh/surface file face.stl type 1\n"
                           "fix sieve all massflow/mesh/sieve mesh face count once vec_side 0 0 -1 sieveSize 0.005 "
                           "sieveSpacing 0.006 sieveStiffness 2000 sieveDamping 0.3\n",
                           "f_sieve[1] f_sieve[2]"),
                       files=FACE),
    "sieve_pass": Case("fix_wall", ("fix massflow/mesh/sieve",),
                       bed("fix face all mesh/surface file face.stl type 1\n"
                           "fix sieve all massflow/mesh/sieve mesh face count once vec_side 0 0 -1 sieveSize 0.05 "
                           "sieveSpacing 0.01 sieveStiffness 2000\n",
                           "f_sieve[1] f_sieve[2] f_sieve[3] f_sieve[4]"),
                       files=FACE),
    # the floor's force on each sphere, kept as the per-atom vector force_ID (store_force), summed;
    # store_force_contact and store_force_contact_stress keep what no output of LIGGGHTS-PUBLIC reads
    "wall_store_force": Case("fix_wall", ("fix wall/gran",),
                             bed("unfix floor\nfix floor all wall/gran model hertz tangential history primitive "
                                 "type 1 zplane 0.0 store_force yes store_force_contact yes "
                                 "store_force_contact_stress yes\n"
                                 "compute wf all reduce sum f_force_floor[1] f_force_floor[2] f_force_floor[3]\n"
                                 "compute wz all reduce max f_force_floor[3]\n"
                                 "fix grav all gravity 9.81 vector 0.0 0.0 -1.0\n",
                                 "c_wf[1] c_wf[2] c_wf[3] c_wz", steps=4500)),
    # what a template makes is deterministic where its distributions are constant: the number, type,
    # radius and mass of what insert/pack puts in (the places are random: no positions printed)
    "template_sphere": Case("fix_insert", ("fix particletemplate/sphere", "fix particledistribution/discrete"),
                            "atom_modify sort 0 0.0\n"
                            "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 1800 "
                            "radius constant 0.004 volume_limit 1e-14 relative no\n"
                            "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2600 "
                            "radius constant 0.005 relative no\n"
                            "fix pdd1 all particledistribution/discrete 32452843 1 pts1 1.0\n"
                            "fix pdd2 all particledistribution/discrete 32452867 1 pts2 1.0\n"
                            "region low block -0.04 0.04 -0.04 0.04 0.01 0.045 units box\n"
                            "region high block -0.04 0.04 -0.04 0.04 0.05 0.09 units box\n"
                            "fix ins1 all insert/pack seed 49979687 distributiontemplate pdd1 insert_every once "
                            "overlapcheck yes all_in yes particles_in_region 30 region low\n"
                            "fix ins2 all insert/pack seed 49979693 distributiontemplate pdd2 insert_every once "
                            "overlapcheck yes all_in yes particles_in_region 20 region high\n"
                            "fix integr all nve/sphere\ncompute pa all property/atom mass type radius\n"
                            "compute m all reduce sum c_pa[1] c_pa[2] c_pa[3]\ncompute rr all reduce max c_pa[3]\n"
                            "thermo_style custom step atoms c_m[1] c_m[2] c_m[3] c_rr\n"
                            "thermo_modify format float %20.15g\nthermo 1\nrun 2\n"),
    # the numbers of each template are fixed where they come out whole: 10 and 30 of 40 by number; by
    # mass, two templates of equal mass, 20 and 20
    "distribution_numberbased": Case("fix_insert", ("fix particledistribution/discrete/numberbased",),
                            "atom_modify sort 0 0.0\n"
                            "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2600 "
                            "radius constant 0.004\n"
                            "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 2600 radius constant 0.005\n"
                            "fix pdd all particledistribution/discrete/numberbased 32452843 2 pts1 0.25 pts2 0.75\n"
                            "region ins block -0.04 0.04 -0.04 0.04 0.01 0.09 units box\n"
                            "fix ins all insert/pack seed 49979687 distributiontemplate pdd insert_every once "
                            "overlapcheck yes all_in yes particles_in_region 40 region ins\n"
                            "fix integr all nve/sphere\ncompute pa all property/atom mass type radius\n"
                            "compute m all reduce sum c_pa[1] c_pa[2] c_pa[3]\n"
                            "thermo_style custom step atoms c_m[1] c_m[2] c_m[3]\n"
                            "thermo_modify format float %20.15g\nthermo 1\nrun 2\n"),
    "distribution_massbased": Case("fix_insert", ("fix particledistribution/discrete/massbased",),
                            "atom_modify sort 0 0.0\n"
                            "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2600 "
                            "radius constant 0.004\n"
                            "fix pts2 all particletemplate/sphere 15485867 atom_type 2 density constant 1331.2 radius constant 0.005\n"
                            "fix pdd all particledistribution/discrete/massbased 32452843 2 pts1 0.5 pts2 0.5\n"
                            "region ins block -0.04 0.04 -0.04 0.04 0.01 0.09 units box\n"
                            "fix ins all insert/pack seed 49979687 distributiontemplate pdd insert_every once "
                            "overlapcheck yes all_in yes particles_in_region 40 region ins\n"
                            "fix integr all nve/sphere\ncompute pa all property/atom mass type radius\n"
                            "compute m all reduce sum c_pa[1] c_pa[2] c_pa[3]\n"
                            "thermo_style custom step atoms c_m[1] c_m[2] c_m[3]\n"
                            "thermo_modify format float %20.15g\nthermo 1\nrun 2\n"),
    # insert/rate/region's counts come out whole: 20 a time every 100 steps (particlerate x insert_every x
    # dt), 60 in all, each moving at the velocity given (their places are random: not printed)
    "insert_rate_region": Case("fix_insert", ("fix insert/rate/region",),
                               "atom_modify sort 0 0.0\n"
                               "fix pts1 all particletemplate/sphere 15485863 atom_type 1 density constant 2600 "
                               "radius constant 0.003\n"
                               "fix pdd all particledistribution/discrete 32452843 1 pts1 1.0\n"
                               "region ins block -0.04 0.04 -0.04 0.04 0.02 0.09 units box\n"
                               "fix ins all insert/rate/region seed 49979687 distributiontemplate pdd nparticles 60 "
                               "particlerate 20000 insert_every 100 overlapcheck yes all_in yes vel constant 0.1 0.0 -0.5 "
                               "region ins\n"
                               "fix integr all nve/sphere\ncompute pa all property/atom mass\n"
                               "compute m all reduce sum c_pa vx vz\n"
                               "thermo_style custom step atoms c_m[1] c_m[2] c_m[3]\n"
                               "thermo_modify format float %20.15g\nthermo 50\nrun 400\n"),
    # the tutorials' dump custom/vtk, with a per-atom property and a compute: the particles' points and
    # arrays, and LIGGGHTS's bounding-box companion file
    "custom_vtk": Case("dump_mesh", ("dump custom/vtk",),
                       bed("compute ke all ke/atom\nfix tag all property/atom tag2 scalar yes no no 2.5\n"
                           "dump d all custom/vtk 1500 bed_*.vtk id type x y z vx vy vz fx fy fz omegax omegay "
                           "omegaz radius mass c_ke f_tag\n"),
                       outputs=("bed_3000.vtk", "bed_boundingBox_3000.vtk")),
    # the time step follows the fastest sphere (Xmax 15 um a step, bounded to [2e-6, 3e-5]; unbounded,
    # the top group's, Xmax in lattice spacings): thermo's time adds each step's own size
    "dt_reset": Case("fix_simple", ("fix dt/reset",),
                     BED + SUMS + "fix integr all nve/sphere\nfix grav all gravity 9.81 vector 0.0 0.0 -1.0\n"
                     "fix adapt all dt/reset 50 2e-6 3e-5 1.5e-5\n" + thermo("dt time f_adapt") + "run 3000\n"),
    "dt_reset_unbounded": Case("fix_simple", ("fix dt/reset",),
                               BED + SUMS + "fix integr all nve/sphere\nfix grav all gravity 9.81 vector 0.0 0.0 -1.0\n"
                               "fix adapt top dt/reset 100 NULL NULL 0.001 units lattice\n"
                               + thermo("dt time f_adapt") + "run 2000\n"),
    # the pairs within the pair cutoff and within the neighbor list's (cutoff + skin), of the group and
    # of all: which of a pair is atom1 follows each program's list, so what is compared is symmetric (the
    # sums of both IDs and both types, the number of pairs)
    "property_local": Case("compute_gran_local", ("compute property/local",),
                           ATOMIC + "pair_style soft 1.2\npair_coeff * * 3.0\n"
                           "compute pl all property/local patom1 patom2 ptype1 ptype2\n"
                           "compute nl half property/local natom1 natom2 ntype1 ntype2\n"
                           "compute ps all reduce sum c_pl[1] c_pl[2] c_pl[3] c_pl[4]\n"
                           "compute pa all reduce ave c_pl[1] c_pl[2]\n"
                           "compute ns all reduce sum c_nl[1] c_nl[2] c_nl[3] c_nl[4]\n"
                           "compute na all reduce ave c_nl[1] c_nl[2]\n"
                           "variable pids equal c_ps[1]+c_ps[2]\nvariable ptypes equal c_ps[3]+c_ps[4]\n"
                           "variable npairs equal (c_ps[1]+c_ps[2])/(c_pa[1]+c_pa[2])\n"
                           "variable nids equal c_ns[1]+c_ns[2]\n"
                           "variable ntypes equal c_ns[3]+c_ns[4]\n"
                           "variable nnear equal (c_ns[1]+c_ns[2])/(c_na[1]+c_na[2])\n"
                           + ATOMIC_RUN.replace("c_sum[6]\n", "c_sum[6] v_pids v_ptypes v_npairs v_nids "
                                                "v_ntypes v_nnear\n"), head=False, ranks=True),
    "log": Case("core", ("log",), BED + SUMS + "fix integr all nve/sphere\n" + thermo()
                + "run 900\nlog other.log\nrun 900\nlog log.case append\nrun 1200\n"),
    "print": Case("fix_simple", ("fix print",),
                  bed("variable k equal ke\nvariable z equal c_sum[3]\n"
                      "fix pr all print 250 \"${k} ${z}\" file printed.txt screen no title \"# ke z\"\n"),
                  outputs=("printed.txt",)),
    "atomic_computes": Case("compute_energy", ("compute pe/atom", "compute stress/atom", "compute group/group"),
                            ATOMIC + "pair_style soft 1.2\npair_coeff * * 3.0\ngroup other subtract all half\n"
                            "compute pa all pe/atom\ncompute sa all stress/atom\ncompute sv all stress/atom virial\n"
                            "compute gg half group/group other\n"
                            "compute ps all reduce sum c_pa c_sa[1] c_sa[2] c_sa[4] c_sv[3] c_sv[6]\n"
                            + ATOMIC_RUN.replace("thermo_style custom step atoms ke c_pe",
                                                 "thermo_style custom step atoms ke c_pe c_ps[1] c_ps[2] c_ps[3] "
                                                 "c_ps[4] c_ps[5] c_ps[6] c_gg c_gg[1] c_gg[2] c_gg[3]"), head=False),
    "rdf": Case("compute_rdf", ("compute rdf",),
                ATOMIC + "pair_style soft 1.2\npair_coeff * * 3.0\ncompute g all rdf 20 1 1 1 2\n"
                "fix gr all ave/time 100 1 100 c_g file rdf.txt mode vector\n" + ATOMIC_RUN,
                head=False, outputs=("rdf.txt",)),
    "buoyancy": Case("fix_granular", ("fix buoyancy",),
                     bed("fix grav all gravity 9.81 vector 0.0 0.0 -1.0\n"
                         "fix float all buoyancy density 1800 level 0.031 dim z\n", "f_float[1] f_float[2] f_float[3]")),
    "buoyancy_region": Case("fix_granular", ("fix buoyancy",),
                            bed("fix grav all gravity 9.81 vector 0.0 0.0 -1.0\n"
                                "region pool block 0.0 INF INF INF INF INF units box\n"
                                "fix float all buoyancy density 3000 dim z level 0.05 region pool\n", "f_float[3]")),
    # LIGGGHTS 3.8.0's slice of several inputs, or of an array's columns, gives wrong elements
    # (uninitialised ones among them): one vector at a time is compared
    "slice": Case("compute_basic", ("compute slice",),
                  bed("compute v all slice 4 6 1 c_sum\ncompute odd all slice 1 5 2 c_sum\n"
                      "fix push all addforce 0.001 -0.002 0.0\ncompute tq all reduce sum fx fy fz\n"
                      "compute f all slice 1 3 1 c_tq\n", "c_v[1] c_v[2] c_odd[1] c_odd[2] c_f[1] c_f[2]")),
    "store_state": Case("compute_basic", ("fix store/state",),
                        bed("compute rke_atom all erotate/sphere/atom\n"
                            "fix start all store/state 0 x z vz c_rke_atom\n"
                            "fix every top store/state 600 xu zu vx com yes\n"
                            "variable dz atom z-f_start[2]\ncompute ds all reduce sum v_dz f_start[3] f_start[4]\n"
                            "compute es top reduce max f_every[1] f_every[2] f_every[3]\n",
                            "c_ds[1] c_ds[2] c_ds[3] c_es[1] c_es[2] c_es[3]")),
    "spring_rg": Case("compute_basic", ("fix spring/rg",),
                      ATOMIC + "pair_style soft 1.2\npair_coeff * * 3.0\nfix pull half spring/rg 2.0 1.0\n"
                      "fix keep all spring/rg 0.5 NULL\ncompute g half gyration\n"
                      + ATOMIC_RUN.replace("thermo_style custom step atoms ke c_pe", "thermo_style custom step atoms ke c_pe c_g"),
                      head=False),
    "ave_histo": Case("analyze_ave", ("fix ave/histo",),
                      bed("fix hz all ave/histo 10 30 300 0.0 0.06 6 z mode vector file z.histo\n"
                          "fix hv all ave/histo 10 3 300 -0.9 0.0 5 vz vx mode vector beyond extra ave running\n"
                          "compute ka all ke/atom\n"
                          "fix hk top ave/histo 100 1 300 0.0 0.001 4 c_ka mode vector beyond end ave window 2 "
                          "file k.histo\n"
                          "fix hs all ave/histo 300 1 300 0.0 0.05 5 c_rke c_sum[3] mode scalar\n",
                          "f_hz[1] f_hz[2] f_hz[3] f_hz[4] f_hz[2][2] f_hz[3][3] f_hv[1] f_hv[2] f_hv[3] "
                          "f_hv[1][2] f_hv[7][2] f_hk[1] f_hk[4][2] f_hs[1] f_hs[2]"),
                      outputs=("z.histo", "k.histo")),
    "check_timestep_vmax": Case("fix_granular", ("fix check/timestep/gran",),
                                bed("fix ts all check/timestep/gran 300 0.1 0.1 vmax 3.0 warn no\n",
                                    "f_ts[1] f_ts[2] f_ts[3]")),
    "ave_spatial_options": Case("analyze_ave", ("fix ave/spatial",),
                                bed("fix ps all ave/spatial 10 30 300 z lower 0.02 vz density/mass norm sample "
                                    "ave running overwrite units box file sample.profile title1 \"# profile\" "
                                    "write_ts no\n"
                                    "fix pw all ave/spatial 10 3 300 x lower 0.02 vx vz ave window 3 "
                                    "units box file window.profile title2 \"# step bins\" title3 \"# columns\" "
                                    "std 1 40 spread.txt\n",
                                    "f_ps[1][2] f_ps[1][3] f_ps[2][3] f_ps[3][4] f_pw[1][2] f_pw[2][3] f_pw[3][4]"),
                                outputs=("sample.profile", "window.profile", "spread.txt")),
    "ave_spatial_refs": Case("analyze_ave", ("fix ave/spatial",),
                             bed("compute ka all ke/atom\ncompute ra all erotate/sphere/atom\n"
                                 "variable h atom z*vz\n"
                                 "fix pr all ave/spatial 10 30 300 z lower 0.02 c_ka c_ra v_h units box\n",
                                 "f_pr[1][3] f_pr[1][4] f_pr[1][5] f_pr[2][3] f_pr[3][5]")),
    "addforce_energy": Case("fix_granular", ("fix addforce",),
                            bed("variable fx equal 0.002*sin(step*0.003)\nvariable e atom -0.0005*z\n"
                                "fix push top addforce v_fx 0.0 0.0005 energy v_e\n"
                                "fix pull all addforce 0.0 -0.0002 0.0001\nfix_modify pull energy yes\n"
                                "compute pe all pe\n", "f_push f_push[1] f_pull f_pull[2] c_pe")),
    "cluster": Case("compute_coord", ("compute cluster/atom",),
                    bed("compute cl all cluster/atom 0.0108\ncompute tc top cluster/atom 0.0119\n"
                        "compute cs all reduce sum c_cl c_tc\ncompute cm all reduce max c_cl c_tc\n",
                        "c_cs[1] c_cs[2] c_cm[1] c_cm[2]")),
    "ave_correlate": Case("analyze_ave", ("fix ave/correlate",),
                          bed("variable z equal c_sum[3]\n"
                              "fix ca all ave/correlate 50 4 300 c_sum[6] c_rke v_z file auto.correlate\n"
                              "fix cu all ave/correlate 20 10 300 c_sum[6] v_z type upper ave running prefactor 2.0 "
                              "file upper.correlate\n"
                              "fix cf all ave/correlate 100 3 300 c_sum[6] c_sum[3] type full start 600\n"
                              "fix cl all ave/correlate 100 3 300 c_sum[6] c_sum[3] c_rke type auto/lower\n",
                              "f_ca[1][2] f_ca[1][3] f_ca[2][3] f_ca[4][5] f_cu[1][3] f_cu[10][3] f_cu[5][2] "
                              "f_cf[2][4] f_cf[3][6] f_cl[1][5] f_cl[2][8]"),
                          outputs=("auto.correlate", "upper.correlate")),
    # cells of 0.1/3 (2.7 times the largest cutoff 0.012, rounded down to 3 per axis): the spheres on
    # x, y = -0.03 -0.01 0.01 0.03 and z = 0.01 0.03 0.05 sit in cells 0 1 1 2 (x, y) and 0 0 1 (z), off
    # every cell face; the upper ones fall into the lower cells in the run
    "ave_euler": Case("analyze_ave", ("fix ave/euler",),
                      euler_snapshots("fix eu all ave/euler nevery 100 cell_size_relative 2.7 parallel no\n",
                                      ("f_eu[5][4]", "f_eu[5][5]", "f_eu[5][6]", "f_eu[5][7]", "f_eu[4][4]",
                                       "f_eu[4][5]", "f_eu[4][7]", "f_eu[1][4]", "f_eu[1][6]", "f_eu[14][1]",
                                       "f_eu[14][2]", "f_eu[14][3]", "f_eu[14][4]", "f_eu[14][7]", "f_eu[27][3]",
                                       "f_eu[27][4]")), ranks=True),
    # the upper spheres only, volume fractions over the part of each cell in a cylinder (LIGGGHTS's
    # Monte Carlo weights, its Park-Miller generator); averaged every 150 steps (the last at 2850
    # before the snapshot at 3000 is taken: run 0 averages again)
    "ave_euler_region": Case("analyze_ave", ("fix ave/euler",),
                             euler_snapshots("region base cylinder z 0.0 0.0 0.04 INF INF units box\n"
                                             "fix er top ave/euler nevery 150 cell_size_relative 2.7 parallel yes "
                                             "basevolume_region base\n",
                                             ("f_er[1][4]", "f_er[2][4]", "f_er[4][4]", "f_er[5][4]", "f_er[5][7]",
                                              "f_er[11][4]", "f_er[13][4]", "f_er[14][4]", "f_er[14][5]",
                                              "f_er[14][7]", "f_er[17][4]"), steps=(1000, 1000, 1050)), ranks=True),
    "centro": Case("compute_coord", ("compute centro/atom",),
                   ATOMIC + "pair_style soft 1.2\npair_coeff * * 3.0\ncompute cs all centro/atom 6\n"
                   "compute c4 half centro/atom 6\ncompute sum all reduce sum x y z vx vy vz\n"
                   "compute cr all reduce sum c_cs c_c4\ncompute cm all reduce max c_cs\n"
                   + ATOMIC_RUN.replace("compute sum all reduce sum x y z vx vy vz\n", "")
                   .replace("thermo_style custom step atoms ke c_pe", "thermo_style custom step atoms ke c_pe c_cr[1] "
                            "c_cr[2] c_cm"), head=False),
    # compute cna/atom: LJ-units crystals of point particles under pair soft, set moving by velocity
    # ramps (their periodic jumps melt the crystal near the box faces), counted by class
    "cna_fcc": Case("compute_coord", ("compute cna/atom",), cna_scene(
        "fcc", "0 4 0 4 0 4", 2.5, "compute c all cna/atom 1.3\ncompute ch half cna/atom 1.3\n", "c"), head=False,
        ranks=True),
    "cna_bcc": Case("compute_coord", ("compute cna/atom",), cna_scene(
        "bcc", "0 4 0 4 0 4", 2.5, "compute c all cna/atom 1.6\ncompute ch half cna/atom 1.0\n"
        "compute cb all cna/atom 2.0\ncompute cz all cna/atom 0\n", "c", more="c_r[3] c_r[4]"), head=False),
    "cna_hcp": Case("compute_coord", ("compute cna/atom",), cna_scene(
        "hcp", "0 6 0 3 0 3", 2.5, "compute c all cna/atom 1.3\ncompute ch half cna/atom 1.5\n", "c"), head=False,
        ranks=True),
    "molecules": Case("compute_basic", ("compute com/molecule", "compute gyration/molecule", "compute msd/molecule",
                                        "compute inertia/molecule", "compute atom/molecule",
                                        "compute property/molecule"),
                      HEAD.replace("atom_style granular", "atom_style hybrid granular molecular")
                      + bed("region left block INF 0.0 INF INF INF INF units box\ngroup left region left\n"
                            "set group all mol 1\nset group left mol 3\nset group top mol 5\n"
                            "compute cm all com/molecule\ncompute rg all gyration/molecule\n"
                            "compute rt left gyration/molecule tensor\ncompute md all msd/molecule\n"
                            "compute in all inertia/molecule\ncompute ka all ke/atom\n"
                            "compute rke_atom all erotate/sphere/atom\ncompute am all atom/molecule c_ka c_rke_atom\n"
                            "compute pm top property/molecule mol count\n",
                            "c_cm[1][1] c_cm[2][3] c_cm[3][2] c_rg[1] c_rg[3] c_rt[1][1] c_rt[2][4] c_md[1][3] "
                            "c_md[3][4] c_in[1][1] c_in[2][4] c_in[3][6] c_am[1][1] c_am[3][2] c_pm[1][1] c_pm[1][2]"),
                      head=False),
    "tracer": Case("fix_property", ("fix property/atom/tracer", "compute nparticles/tracer/region"),
                   bed("region mark block INF INF INF INF 0.025 INF units box\n"
                       "region low block 0.0 INF INF INF INF 0.022 units box\n"
                       "fix tr all property/atom/tracer region_mark mark mark_step 600 check_mark_every 20\n"
                       "fix th all property/atom/tracer region_mark low mark_step 0 marker_style heaviside\n"
                       "compute nt all nparticles/tracer/region region_count low tracer tr\n"
                       "compute nh all nparticles/tracer/region region_count low tracer th reset_marker no\n"
                       "compute ms all reduce sum f_tr f_th\n",
                       "f_tr f_th c_nt[1] c_nt[2] c_nt[3] c_nt[4] c_nh[2] c_nh[4] c_ms[1] c_ms[2]")),
}


def thermo_rows(log):
    """Every row of every thermo table of a log (the repeated first row of each later run included),
    split into words; lines a fix or a warning printed inside a table are left out."""
    rows, inside = [], False
    for line in log.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            inside = True
        elif line.startswith("Loop time"):
            inside = False
        elif inside and words and words[0].isdigit():
            try:
                [float(w) for w in words]
            except ValueError:
                continue
            rows.append(words)
    return rows


def run_liggghts(script, files, label, outputs=(), status=0):
    """LIGGGHTS's log of ``script`` (None when it fails: an exit code other than ``status``, or an
    error in its log), with the texts of the ``outputs`` it wrote in ``written``."""
    written.clear()
    with tempfile.TemporaryDirectory() as folder:
        for name, text in files.items():
            (Path(folder) / name).write_text(text)
        (Path(folder) / "in.case").write_text(script)
        done = subprocess.run([LIGGGHTS, "-in", "in.case", "-log", "log.case", "-echo", "none"],
                              cwd=folder, capture_output=True, text=True, errors="replace")
        log = (Path(folder) / "log.case").read_text(errors="replace") if (Path(folder) / "log.case").exists() else ""
        for name in outputs:
            if (Path(folder) / name).exists():
                written[name] = (Path(folder) / name).read_text()
    if done.returncode != status or "ERROR" in log:
        error = next((line for line in log.splitlines() if line.startswith("ERROR")), done.stderr[-300:])
        print(f"LIGGGHTS failed ({label}): {error}")
        return None
    return log


written = {}


def script_of(case):
    return (HEAD if case.head else "") + case.body


def folder_of(owner):
    return ROOT / ("tests" if owner == "core" else f"plugins/{owner}/tests") / "data"


def main(only=()):
    failed = []
    owners = sorted({c.owner for c in CASES.values()})
    for owner in owners:
        cases = {name: c for name, c in CASES.items() if c.owner == owner}
        folder = folder_of(owner)
        rows_path = folder / "liggghts.txt"
        old = {}
        table_path = folder / "liggghts.cases.json"
        recorded = {}
        if only and table_path.exists():
            recorded = {n: e.get("outputs", {}) for n, e in json.loads(table_path.read_text())["cases"].items()}
        if only and rows_path.exists():
            for line in rows_path.read_text().splitlines():
                old.setdefault(line.split("\t")[0], []).append(line)
        rows = []
        for name, c in cases.items():
            if only and name not in only and name in old:
                rows += old[name]
                continue
            log = run_liggghts(script_of(c), c.files, name, c.outputs, c.status)
            if set(written) != set(c.outputs):
                print(f"LIGGGHTS wrote none of {sorted(set(c.outputs) - set(written))} ({name})")
                log = None
            recorded[name] = dict(written)
            if log is None:
                failed.append(name)
                continue
            found = [f"{name}\t" + "\t".join(words) for words in thermo_rows(log)]
            if not found:
                sys.exit(f"{name}: no thermo in LIGGGHTS's log")
            rows += found
            print(f"{owner}:{name}: {len(found)} rows")
        files = sorted({n for c in cases.values() for n in c.files})
        folder.mkdir(parents=True, exist_ok=True)
        for c in cases.values():
            for n, text in c.files.items():
                (folder / n).write_text(text)
        rows_path.write_text("\n".join(rows) + "\n")
        write_case_table(folder / "liggghts.cases.json", __file__, "liggghts.txt", files,
                         {name: script_of(c) for name, c in cases.items()}, rtol=1e-8, atol=1e-13,
                         ranks=[n for n, c in cases.items() if c.ranks], dialect="liggghts", program=PROGRAM,
                         checks={name: c.checks for name, c in cases.items()},
                         outputs={name: recorded.get(name, {}) for name, c in cases.items() if c.outputs})
    if failed:
        sys.exit(f"LIGGGHTS ran none of {', '.join(failed)}: mend them or take them out")


if __name__ == "__main__":
    args = [a for a in sys.argv[1:] if not a.startswith("--only=")]
    LIGGGHTS = args[0] if args else LIGGGHTS
    main(tuple(a[len("--only="):] for a in sys.argv[1:] if a.startswith("--only=")))
