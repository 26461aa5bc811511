"""fix wall/gran/region with LAMMPS's classic laws: a block container deleted and made again between
runs, still, turning about z, about a tilted axis and sliding (region move and rotate); a cylinder
cup with a turning paddle (intersect of a cylinder, side in, and a block, side out, LAMMPS's
granregion mixer in small); an L-shaped union of two blocks around a cylinder post (side out). The
thermo rows LAMMPS 22 Jul 2025 printed for these scripts on this machine (``lmp -in SCRIPT``), and
the lines refused."""

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


# 30 spheres dropped into a cylinder cup whose paddle turns once every 1000 steps (hertz/history)
MIXER = SETUP.replace("-8 8 -8 8 -8 8", "-8 8 -8 8 -2 14") + """\
region          fill cylinder z 0 0 4 3 10 units box
create_atoms    1 random 30 59210 fill overlap 1.1 units box
set             type 1 diameter 0.9
velocity        all set 0.5 -0.4 -2.0 units box
pair_style      gran/hertz/history 20000.0 NULL 50.0 NULL 0.5 1
pair_coeff      * *
variable        theta equal step*(2.0*PI/1000)
region          cup cylinder z 0 0 5 0 12 side in units box
region          paddle block -4.5 4.5 -0.6 0.6 0 1.5 side out units box rotate v_theta 0 0 0 0 0 1
region          mixer intersect 2 cup paddle
fix             mix all wall/gran/region hertz/history 20000.0 NULL 50.0 NULL 0.5 1 region mixer
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
fix             2 all nve/sphere
fix             3 all gravity 1.0 vector 0 0 -1
timestep        0.002
compute         rot all erotate/sphere
thermo          100
thermo_style    custom step atoms ke c_rot v_theta
run             1500
"""

# step atoms ke c_rot v_theta; the cup alone (no paddle) prints 2.1598449 at step 400, the paddle
# turning as a wall of its own 2.1947458: LAMMPS's intersect gives its contacts no wall velocity
LAMMPS_MIXER = [
    (0, 30, 1.1545353, 0, 0), (100, 30, 1.3744468, 0, 0.62831853), (200, 30, 1.6153022, 0, 1.2566371),
    (300, 30, 1.8771016, 0, 1.8849556), (400, 30, 2.123775, 0.018274274, 2.5132741),
    (500, 30, 2.2757635, 0.087898696, 3.1415927), (600, 30, 4.7456022, 0.12090441, 3.7699112),
    (700, 30, 5.725565, 1.2553801, 4.3982297), (800, 30, 14.353032, 2.022697, 5.0265482),
    (900, 30, 15.871332, 3.0124948, 5.6548668), (1000, 30, 19.061563, 2.7031757, 6.2831853),
    (1100, 30, 17.951853, 5.3734597, 6.9115038), (1200, 30, 15.541263, 4.9172263, 7.5398224),
    (1300, 30, 16.267101, 5.4896287, 8.1681409), (1400, 30, 22.448291, 5.228709, 8.7964594),
    (1500, 30, 22.762553, 6.8689356, 9.424778),
]

# 30 spheres in an L-shaped union of two blocks (their shared floor and faces dropped where the
# other block holds them), around a cylinder post along y (side out, hertz/history)
UNION = SETUP.replace("-8 8 -8 8 -8 8", "-8 8 -8 8 -2 14") + """\
region          fill block -4.5 -0.5 -2.5 2.5 1 9 units box
create_atoms    1 random 30 7731 fill overlap 1.1 units box
velocity        all set 1.0 -0.5 -2.0 units box
pair_style      gran/hooke/history 20000.0 NULL 50.0 NULL 0.5 1
pair_coeff      * *
region          left block -5 1 -3 3 0 12 units box
region          right block 0 5 -3.5 0.5 -1 12 units box
region          cup union 2 left right
region          post cylinder y 2.5 2 1.0 -3 3 side out units box
fix             cup all wall/gran/region hooke/history 20000.0 NULL 50.0 NULL 0.5 1 region cup
fix             post all wall/gran/region hertz/history 20000.0 NULL 50.0 NULL 0.5 1 region post
neighbor        0.3 bin
neigh_modify    delay 0 every 1 check yes
fix             2 all nve/sphere
fix             3 all gravity 1.0 vector 0 0 -1
timestep        0.001
compute         rot all erotate/sphere
thermo          100
thermo_style    custom step atoms ke c_rot
run             1500
"""

# step atoms ke c_rot; without the post LAMMPS prints 1.7955265 at step 1400, with the right block's
# floor at 0 (shared with the left's: a hole in both) 1.7603563 at step 1500
LAMMPS_UNION = [
    (0, 30, 1.3744468, 0), (100, 30, 1.4652548, 0.0037388244), (200, 30, 1.5771817, 0.0037388244),
    (300, 30, 1.6943446, 0.0037388244), (400, 30, 1.7780257, 0.0038692101), (500, 30, 1.823112, 0.020466306),
    (600, 30, 1.8480833, 0.023723331), (700, 30, 1.851373, 0.036526207), (800, 30, 1.9385086, 0.037213176),
    (900, 30, 1.9520683, 0.061439856), (1000, 30, 1.9142649, 0.089505806), (1100, 30, 1.8301493, 0.1181089),
    (1200, 30, 1.757195, 0.15053119), (1300, 30, 1.7235662, 0.15666425), (1400, 30, 1.7576356, 0.15905039),
    (1500, 30, 40.41776, 0.17815631),
]


# one sphere pressed by a tilted gravity onto the floor, then into the xlo and ylo walls of a box
# corner: it gains its faces in the order zlo, xlo, ylo, and LAMMPS's c2r hands contact xlo the ylo
# slot's spring, ylo the zlo's, zlo the xlo's (with each face's own spring pdps measured 0.012519041
# for c_k at step 5500)
CORNER = SETUP.replace("-8 8 -8 8 -8 8", "-1 11 -1 11 -1 11") + """\
create_atoms    1 single 0.8 1.5 0.499 units box
region          cup block 0 10 0 10 0 10 units box
fix             cup all wall/gran/region hooke/history 4000.0 NULL 10.0 NULL 0.5 1 region cup
fix             1 all nve/sphere
fix             2 all gravity 1.0 vector -1 -0.5 -1
timestep        0.001
compute         rot all erotate/sphere
compute         k all ke
variable        px equal xcm(all,x)
variable        py equal xcm(all,y)
variable        pz equal xcm(all,z)
thermo          500
thermo_style    custom step c_k c_rot v_px v_py v_pz
thermo_modify   format float %20.15g norm no
run             6000
"""

LAMMPS_CORNER = [
    (0, 0, 0, 0.8, 1.5, 0.499),
    (500, 0.0254282467154261, 0.0026420096557745, 0.724073776879228, 1.46203688843961, 0.500499641515624),
    (1000, 0.0884821063312269, 0.0176185124840873, 0.521833140442235, 1.36091657022112, 0.500314700746735),
    (1500, 0.036891470385556, 0.0079184186310992, 0.614374821841049, 1.21642851231145, 0.500324554553165),
    (2000, 0.0695414136859404, 0.0187870060016346, 0.572416579792898, 1.01183984838135, 0.499593664090821),
    (2500, 0.0739705619758093, 0.0335535509844393, 0.539042475466756, 0.764751856385798, 0.499933721395717),
    (3000, 0.0767813516914868, 0.0154621123824696, 0.509431425739483, 0.503215469790376, 0.502180151825868),
    (3500, 0.0105337714325841, 0.00397884987808542, 0.498819178049333, 0.672576200080238, 0.5047092233418),
    (4000, 0.000482201514535656, 0.000962113549633726, 0.504617884290658, 0.706196949163048, 0.500573706938492),
    (4500, 0.00312032928603737, 0.000738852969180524, 0.49950150919297, 0.672299250869405, 0.499885093389494),
    (5000, 0.00854747374161078, 0.00625394479562795, 0.499909895028309, 0.601258091619422, 0.499914838485518),
    (5500, 0.0125040173125895, 0.00562259550218769, 0.500487414742649, 0.501330476244001, 0.50049136746736),
    (6000, 0.00063363073111244, 0.000313876087943863, 0.499884876050121, 0.524544176909256, 0.499884253712796),
]


def test_a_sphere_in_a_corner_keeps_its_springs_as_lammps_hands_them_out(tmp_path):
    assert_prints_as_lammps(tmp_path, CORNER, LAMMPS_CORNER, rel=1e-12, abs=1e-15)


def test_a_cylinder_cup_with_a_turning_paddle_prints_as_lammps(tmp_path):
    assert_prints_as_lammps(tmp_path, MIXER, LAMMPS_MIXER)


def test_an_l_shaped_union_around_a_post_prints_as_lammps(tmp_path):
    assert_prints_as_lammps(tmp_path, UNION, LAMMPS_UNION)


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
        ("region c cylinder z 0 0 2 0 5 side in units box open 2",
         "region: open faces are not built (LAMMPS's open keyword: a region's face left out of its surface and its "
         "test of points) (got open 2)"),
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
        ("region c block -5 5 -5 5 -5 5\nregion u union 2 box c side out\n" + f"{WALL} u",
         "fix: region u (union) with side out is not built as a granular wall"),
        ("region c block -5 5 -5 5 -5 5 units box move v_dx NULL NULL\n"
         "fix p all pour 10 1 4767 region c diam one 1.0",
         "fix: region c moves (move or rotate): fix pour region cannot be dynamic (as LAMMPS)"),
        ("region c block -5 5 -5 5 -5 5 rotate v_theta 0 0 0 0 0 1\n"
         "fix w all wall/dem lsd region c 0.85 3000 28.6527 571.43 15.82634 0.4 0.5",
         "fix: region c moves (move or rotate): fix wall/dem's walls stand still (fix wall/gran/region follows "
         "a moving region)"),
    ]
    for lines, message in cases:
        assert_refused(pdps_cli(SETUP + lines + "\n"), 7 + lines.count("\n"), message)


def test_a_deleted_region_or_its_missing_variable_stops_the_run_at_its_line(pdps_cli):
    body = SETUP + "region c block -5 5 -5 5 -5 5 units box\n" + f"{WALL} c\n" + "region c delete\nrun 1\n"
    assert_refused(pdps_cli(body), 10, "run: region c for fix wall/gran/region does not exist")
    body = (SETUP + "region c block -5 5 -5 5 -5 5 units box rotate v_theta 0 0 0 0 0 1\n" + f"{WALL} c\n"
            + "create_atoms 1 single 0 0 0 units box\nrun 1\n")
    assert_refused(pdps_cli(body), 10, "run: region c: variable theta is not defined")
    # a union holds its regions as they were made: one deleted under it stops the run
    body = (SETUP + "region a block -5 5 -5 5 -5 5 units box\nregion b block 4 6 -1 1 -1 1 units box\n"
            "region u union 2 a b\n" + f"{WALL} u\n" + "region a delete\nregion a block -4 4 -4 4 -4 4 units box\n"
            "run 1\n")
    assert_refused(pdps_cli(body), 13, "run: region a was deleted (region a delete) but a style or region made "
                                       "with it still uses it: define that again after the new region a")


def test_hybrid_with_its_one_granular_sub_style_names_it_in_pair_coeff(pdps_cli):
    body = SETUP + "pair_style hybrid gran/hooke 4000.0 NULL 100.0 NULL 0.5 1\npair_coeff * * gran/hooke/history\n"
    assert_refused(pdps_cli(body), 8, "pair_coeff: pair_coeff I J gran/hooke COEFFS: the only sub-style of this "
                                      "pair_style hybrid is gran/hooke (got gran/hooke/history)")
