"""fix wall/gran/region with LAMMPS's classic laws on a block container that is deleted and made again
between runs, still, turning about z, about a tilted axis, and sliding (region move and rotate): the
thermo rows LAMMPS 22 Jul 2025 printed for this script on this machine (``lmp -in in.rot``), and the
lines refused."""

from pdps_core.testing import assert_prints_as_lammps, assert_refused

SETUP = """\
units           lj
atom_style      sphere
boundary        f f f
comm_modify     vel yes
region          box block -8 8 -8 8 -8 8 units box
create_box      1 box
"""

# 24 spheres thrown down into a container under gravity (pair_style hybrid with its one granular
# sub-style); then the container turns about z, turns about (1, 1, 1) through (0.5, 0, 0), slides in x
CONTAINER = SETUP + """\
region          fill block -4 4 -4 4 -4 4 units box
create_atoms    1 random 24 48213 fill overlap 1.2 units box
velocity        all set 0.3 -0.2 -3.0 units box
pair_style      hybrid gran/hooke/history 4000.0 NULL 100.0 NULL 0.5 1
pair_coeff      * * gran/hooke/history
region          container block -5 5 -5 5 -5 5 units box
fix             container all wall/gran/region hooke/history 4000.0 NULL 100.0 NULL 0.5 1 region container
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
fix             2 all nve/sphere
fix             3 all gravity 1.0 vector 0 0 -1
timestep        0.005
compute         rot all erotate/sphere
thermo          50
thermo_style    custom step atoms ke c_rot
run             300
region          container delete
variable        theta equal (step-300)*(4.0*PI/2000)
region          container block -5 5 -5 5 -5 5 units box rotate v_theta 0 0 0 0 0 1
run             300
region          container delete
variable        theta equal (step-600)*(4.0*PI/2000)
region          container block -5 5 -5 5 -5 5 units box rotate v_theta 0.5 0 0 1 1 1
run             300
region          container delete
variable        dx equal 0.5*sin((step-900)*0.02)
region          container block -5 5 -5 5 -5 5 units box move v_dx NULL NULL
run             100
"""

# step atoms ke c_rot, as LAMMPS printed them (the first row of each run repeats the last of the one before)
LAMMPS_CONTAINER = [
    (0, 24, 2.3902284, 0), (50, 24, 2.6834586, 0.00029051657), (100, 24, 2.7071271, 0.0011690275),
    (150, 24, 2.9454025, 0.0014574912), (200, 24, 3.1721397, 0.0017414262), (250, 24, 2.479176, 0.022904432),
    (300, 24, 1.7183865, 0.063710059),
    (300, 24, 1.7183865, 0.063710059), (350, 24, 1.1385538, 0.24197231), (400, 24, 0.91915541, 0.30375484),
    (450, 24, 0.51911949, 0.39815629), (500, 24, 0.58837092, 0.43333166), (550, 24, 0.63886692, 0.49628054),
    (600, 24, 0.66690889, 0.5501391),
    (600, 24, 0.66690889, 0.5501391), (650, 24, 4.6343214, 2.268375), (700, 24, 6.0005127, 3.0423427),
    (750, 24, 6.5168357, 2.9805437), (800, 24, 6.9527137, 2.9831156), (850, 24, 8.5921939, 3.7863402),
    (900, 24, 11.773641, 3.284707),
    (900, 24, 11.773641, 3.284707), (950, 24, 6.4975585, 2.8569004), (1000, 24, 4.3948327, 2.1232483),
]


def test_a_container_deleted_and_made_again_turning_and_sliding_prints_as_lammps(tmp_path):
    text = assert_prints_as_lammps(tmp_path, CONTAINER, LAMMPS_CONTAINER)
    # LAMMPS warns when the fix takes up the new region of its ID
    assert text.count("WARNING: Region properties for region container changed between runs, "
                      "resetting its motion") == 3


WALL = "fix w all wall/gran/region hooke/history 4000.0 NULL 100.0 NULL 0.5 1 region"


def test_bad_region_lines_are_refused_at_their_line(pdps_cli):
    cases = [
        ("region c block -5 5 -5 5 -5 5 rotate theta 0 0 0 0 0 1",
         "region: rotate takes an equal-style variable, v_NAME (got theta)"),
        ("region c block -5 5 -5 5 -5 5 move v_dx v_dy 0.5",
         "region: move takes an equal-style variable, v_NAME or NULL (got 0.5)"),
        ("region c block -5 5 -5 5 -5 5 rotate v_theta 0 0 0 0 0 0",
         "region: rotate needs an axis of length > 0 (got 0 0 0)"),
        ("region c union 2 box box rotate v_theta 0 0 0 0 0 1",
         "region: region union cannot move or rotate itself (as LAMMPS): give move or rotate to the regions it "
         "combines"),
        ("region c delete", "region: region c is not defined: nothing to delete"),
        ("region box delete now", "region: region ID delete takes nothing more (got now)"),
    ]
    for line, message in cases:
        assert_refused(pdps_cli(SETUP + line + "\n"), 7, message)


def test_bad_wall_lines_are_refused_at_their_line(pdps_cli):
    cases = [
        ("region ball sphere 0 0 0 3\n" + f"{WALL} ball",
         "fix: region ball (sphere) has no granular wall surface (LAMMPS's surface_interior and "
         "surface_exterior are not built for it)"),
        ("region c block -5 5 -5 5 -5 5\n" + WALL.replace("0.5 1", "0.5 2") + " c",
         "fix: dampflag must be <= 1 (got 2)"),
        ("region c block -5 5 -5 5 -5 5 rotate v_theta 0 0 0 0 0 1\n"
         "fix w all wall/dem lsd region c 0.85 3000 28.6527 571.43 15.82634 0.4 0.5",
         "fix: region c moves (move or rotate): fix wall/dem's walls stand still (fix wall/gran/region follows "
         "a moving region)"),
    ]
    for lines, message in cases:
        assert_refused(pdps_cli(SETUP + lines + "\n"), 8, message)


def test_a_deleted_region_or_its_missing_variable_stops_the_run_at_its_line(pdps_cli):
    body = SETUP + "region c block -5 5 -5 5 -5 5 units box\n" + f"{WALL} c\n" + "region c delete\nrun 1\n"
    assert_refused(pdps_cli(body), 10, "run: region c for fix wall/gran/region does not exist")
    body = (SETUP + "region c block -5 5 -5 5 -5 5 units box rotate v_theta 0 0 0 0 0 1\n" + f"{WALL} c\n"
            + "create_atoms 1 single 0 0 0 units box\nrun 1\n")
    assert_refused(pdps_cli(body), 10, "run: region c: variable theta is not defined")


def test_hybrid_with_its_one_granular_sub_style_names_it_in_pair_coeff(pdps_cli):
    body = SETUP + "pair_style hybrid gran/hooke 4000.0 NULL 100.0 NULL 0.5 1\npair_coeff * * gran/hooke/history\n"
    assert_refused(pdps_cli(body), 8, "pair_coeff: pair_coeff I J gran/hooke COEFFS: the only sub-style of this "
                                      "pair_style hybrid is gran/hooke (got gran/hooke/history)")
