"""fix indent: the force law F(r) = -K (r - R)^2 and its energy K |r - R|^3 / 3 on single particles
(against the formula and finite differences of the energy), f_ID and f_ID[1..3], side in, periodic
images, moving (variable) indenters, lattice units, minimize, the refusals, and LAMMPS's thermo on
two scripts of our own (recorded with LAMMPS 22 Jul 2025 on this machine, 12-07)."""


import numpy as np
import pytest

from pdps_core.api import observables
from pdps_core.testing import logged_thermo, make_box, script_error, thermo_on_ranks


def one_particle(position, fix, box="0 10 0 10 0 10", boundary="f f f", more=""):
    sim = make_box(f"""
        mass 1 1
        create_particle 1 single {position[0]} {position[1]} {position[2]}
        {more}
        fix ind all {fix}
        fix_modify ind energy yes
        run 0
    """, box=box, boundary=boundary)
    return sim, sim.fixes["ind"]


K = 7.0


@pytest.mark.parametrize("fix, position, centre, axis_mask", [
    (f"indent {K} sphere 5 5 5 2 units box", (5.3, 6.1, 4.2), (5, 5, 5), (1, 1, 1)),
    (f"indent {K} cylinder z 4 6 2.5 units box", (5.5, 4.5, 8.0), (4, 6, 0), (1, 1, 0)),
    (f"indent {K} cylinder x 4 6 2.5 units box", (1.0, 3.0, 4.5), (0, 4, 6), (0, 1, 1)),
])
def test_round_indenters_push_out_with_minus_k_overlap_squared(fix, position, centre, axis_mask):
    sim, ind = one_particle(position, fix)
    delta = (np.array(position) - np.array(centre)) * np.array(axis_mask)
    r = np.linalg.norm(delta)
    radius = 2.0 if "sphere" in fix else 2.5
    assert r < radius
    np.testing.assert_allclose(sim.f[0], K * (r - radius) ** 2 * delta / r, rtol=1e-14)
    assert ind.scalar(sim) == pytest.approx(K * (radius - r) ** 3 / 3, rel=1e-14)
    np.testing.assert_allclose(ind.vector(sim), -sim.f[0], rtol=1e-14)
    assert observables.potential_energy(sim) == pytest.approx(K * (radius - r) ** 3 / 3, rel=1e-14)


@pytest.mark.parametrize("fix", [f"indent {K} sphere 5 5 5 2 units box", f"indent {K} cylinder y 4 6 2.5 units box",
                                 f"indent {K} sphere 5 5 5 0.8 side in units box",
                                 f"indent {K} plane z 6 lo units box", f"indent {K} plane x 3.7 hi units box"])
def test_the_force_is_minus_the_gradient_of_the_energy(fix):
    position = np.array([4.1, 5.6, 5.4])
    sim, ind = one_particle(position, fix)
    force = sim.f[0].copy()
    assert np.linalg.norm(force) > 0.1
    h = 1e-6
    for axis in range(3):
        energies = []
        for step in (h, -h):
            moved = position.copy()
            moved[axis] += step
            other, fix_ = one_particle(moved, fix)
            energies.append(fix_.scalar(other))
        assert -(energies[0] - energies[1]) / (2 * h) == pytest.approx(force[axis], rel=1e-7, abs=1e-9)


def test_outside_the_overlap_there_is_no_force_and_no_energy():
    for fix, position in [("indent 5 sphere 5 5 5 2 units box", (5, 5, 7.5)),
                          ("indent 5 sphere 5 5 5 2 side in units box", (5, 5, 6.5)),
                          ("indent 5 plane z 4 lo units box", (5, 5, 4.5)),
                          ("indent 5 plane z 4 hi units box", (5, 5, 3.5))]:
        sim, ind = one_particle(position, fix)
        assert not sim.f[0].any() and ind.scalar(sim) == 0.0 and not ind.vector(sim).any()


def test_side_in_holds_particles_inside():
    # 0.5 beyond the radius 2, pushed back towards the centre
    sim, ind = one_particle((5, 5, 7.5), "indent 4 sphere 5 5 5 2 side in units box")
    np.testing.assert_allclose(sim.f[0], [0, 0, -4 * 0.25], rtol=1e-15)
    assert ind.scalar(sim) == pytest.approx(4 * 0.125 / 3, rel=1e-15)
    np.testing.assert_allclose(ind.vector(sim), [0, 0, 1.0], rtol=1e-15)


@pytest.mark.parametrize("side, position, force", [("lo", (5, 5, 3.5), 5 * 0.25), ("hi", (5, 5, 4.5), -5 * 0.25)])
def test_a_plane_pushes_from_its_side(side, position, force):
    sim, ind = one_particle(position, f"indent 5 plane z 4 {side} units box")
    np.testing.assert_allclose(sim.f[0], [0, 0, force], rtol=1e-15)
    assert ind.scalar(sim) == pytest.approx(5 * 0.125 / 3, rel=1e-15)
    np.testing.assert_allclose(ind.vector(sim), [0, 0, -force], rtol=1e-15)


def test_a_sphere_across_a_periodic_face_pushes_the_nearest_image():
    """Centre (10.5, 5, 5) wraps to (0.5, 5, 5); the particle at x = 9.2 is 1.3 from it through the face."""
    sim, ind = one_particle((9.2, 5, 5), "indent 3 sphere 10.5 5 5 2 units box", boundary="p f f")
    np.testing.assert_allclose(sim.f[0], [-3 * 0.7 ** 2, 0, 0], rtol=1e-13)


def test_numbers_are_in_lattice_units_and_variables_as_they_are():
    """lattice spacing 2: the centre x 2 -> 4 and the radius 1 -> 2; v_zc (5) is not scaled."""
    sim, ind = one_particle((4, 5, 6.5), "indent 3 sphere 2 2.5 v_zc 1", more="variable zc equal 5",
                            box="0 10 0 10 0 10")
    assert sim.f[0, 2] == 0.0   # without a lattice command the spacing is 1: the sphere is far away
    sim = make_box("""
        lattice sc 0.125
        mass 1 1
        create_particle 1 single 4 5 6.5
        variable zc equal 5
        fix ind all indent 3 sphere 2 2.5 v_zc 1
        run 0
    """, boundary="f f f")
    np.testing.assert_allclose(sim.f[0], [0, 0, 3 * 0.5 ** 2], rtol=1e-14)


def test_a_moving_indenter_follows_its_variable_every_step():
    sim = make_box("""
        mass 1 1
        create_particle 1 single 5 5 5
        variable zc equal "7.5 - step"
        fix ind all indent 2 sphere 5 5 v_zc 2 units box
        run 0
    """, boundary="f f f")
    assert sim.fixes["ind"].scalar(sim) == 0.0
    sim.command("run 1")
    # the step's forces: centre at 6.5, the particle (still at 5 after one step of no integrator) 1.5 from it
    assert sim.fixes["ind"].scalar(sim) == pytest.approx(2 * 0.5 ** 3 / 3, rel=1e-14)
    assert sim.fixes["ind"].vector(sim)[2] == pytest.approx(2 * 0.25, rel=1e-14)


def test_a_particle_at_the_centre_feels_no_force_and_nothing_is_nan():
    sim, ind = one_particle((5, 5, 5), "indent 2 sphere 5 5 5 1 units box")
    assert not sim.f[0].any() and np.isfinite(ind.vector(sim)).all()
    assert ind.scalar(sim) == pytest.approx(2 / 3, rel=1e-15)


@pytest.mark.parametrize("line, message", [
    ("fix 1 all indent -1 sphere 1 2 3 4", "k must be >= 0 (got -1)"),
    ("fix 1 all indent 10 sphere 1 2 3 -4", "sphere radius must be >= 0 (got -4)"),
    ("fix 1 all indent 10 cylinder z 1 2 -1", "cylinder radius must be >= 0 (got -1)"),
    ("fix 1 all indent 10 cone z 1 2 1 2 0 5", "the cone indenter is not supported (sphere, cylinder and plane are)"),
    ("fix 1 all indent 10 box 1 2", "geometry must be one of sphere, cylinder, plane, cone (got box)"),
    ("fix 1 all indent 10 plane q 1 lo", "geometry must be one of 'x', 'y' or 'z' (got q)"),
    ("fix 1 all indent 10 plane z 1 mid", "geometry must be one of 'lo' or 'hi' (got mid)"),
    ("fix 1 all indent 10 sphere 1 2 3 4 side up", "side must be one of 'in' or 'out' (got up)"),
    ("fix 1 all indent 10 sphere 1 2 3 4 plane z 1 lo", "unknown keyword plane (known: side, units)"),
    ("fix 1 all indent 10 sphere 1 2 3 4 units metres", "units must be one of 'box' or 'lattice' (got metres)"),
])
def test_bad_indenters(line, message):
    assert script_error("region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1", line).message == message


@pytest.mark.parametrize("line, message", [
    ("fix 1 all indent 10 sphere v_nope 2 3 1\nrun 0", "fix 1 indent: variable nope is not defined"),
    ("variable a atom x\nfix 1 all indent 10 plane z v_a lo\nrun 0",
     "fix 1 indent: variable a is not equal-style (got atom)"),
    ("variable r equal 1-step\nfix 1 all indent 10 sphere 1 1 1 v_r\nrun 2",
     "fix 1 indent: the sphere radius must be >= 0 (got -1 at step 2)"),
])
def test_bad_variables_stop_the_run_with_one_line(line, message):
    setup = "region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1\ncreate_particle 1 single 1 1 1\nfix 0 all nve"
    assert script_error(setup, line).message == message


SLAB = """units lj
atom_style atomic
boundary p p f
lattice fcc 0.8442
region box block 0 {n} 0 {n} -1 {top}
create_box 1 box
region slab block 0 {n} 0 {n} 0 3
create_atoms 1 region slab
mass 1 1.0
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
"""

RUNS = SLAB.format(n=4, top=6) + """velocity all create 0.5 87287 loop geom
neighbor 0.3 bin
neigh_modify every 1 delay 0 check yes
fix 1 all nve
variable zc equal "7.6 - 0.004*step"
fix ind all indent 20.0 sphere 0.25 3.9 v_zc 2.0
fix_modify ind energy yes
thermo_style custom step temp pe etotal f_ind f_ind[1] f_ind[2] f_ind[3]
thermo_modify format float %.15g norm no
thermo 25
run 100
unfix ind
fix cyl all indent 5.0 cylinder z 3.3 3.4 3.3 side in units box
fix_modify cyl energy yes
thermo_style custom step temp pe etotal f_cyl f_cyl[1] f_cyl[2] f_cyl[3]
thermo_modify format float %.15g norm no
run 100
unfix cyl
variable p equal "-0.4 + 0.006*(step-200)"
fix pl all indent 30.0 plane z v_p lo
thermo_style custom step temp pe etotal f_pl f_pl[1] f_pl[2] f_pl[3]
thermo_modify format float %.15g norm no
run 100
"""

# LAMMPS 22 Jul 2025 (lmp -in, one rank): step temp pe etotal f_ID f_ID[1] f_ID[2] f_ID[3]; a sphere
# moving down across the periodic x face (energy in pe), a cylinder holding the slab inside (energy
# in pe), a plane rising from below (energy not in pe)
LAMMPS_RUNS = """
0 0.5 -1348.36347030918 -1181.11347030918 8.20158724824379 0.0268061011005429 0.0552570659089198 38.6665723782607
25 0.227960611734437 -1254.55490557295 -1178.30208094778 7.09355924922736 -0.587584125926364 -0.671031763788321 35.4671228034796
50 0.377711984388294 -1304.10183536092 -1177.75717658303 5.64148060538427 0.207772500995036 0.835596732718827 30.4184266689411
75 0.483717433039436 -1339.61465906678 -1177.81117771509 5.0870008564114 0.706696543868811 2.51220896315804 29.7414756425944
100 0.553429132617974 -1362.28961775265 -1177.16757289194 5.98847152695436 -0.54479365654909 2.12960290028905 32.9261803459235
100 0.553429132617974 -1339.6268452782 -1154.50480041749 28.6512440014056 -23.7946489367899 13.1275805029099 0
125 0.527857317303016 -1331.92678490146 -1155.3585122636 27.3159271740674 -20.9343086540822 15.6345565645659 0
150 0.531664872745259 -1333.29486927142 -1155.45296933813 25.8708424428553 -29.5072399236213 23.3527238985368 0
175 0.518820752926964 -1328.83228996788 -1155.28674811381 26.1460437401422 -20.2351148704854 18.0531206863293 0
200 0.556320792116933 -1340.30092776109 -1154.21162279798 24.065736525185 -13.485523514191 27.3760750505249 0
200 0.556320792116933 -1364.36666428627 -1178.27735932316 0 0 0 0
225 0.506183524364708 -1345.90964868308 -1176.59125978308 0 0 0 0
250 0.430489181032419 -1318.07212438232 -1174.07349332698 1.29039684458478e-05 0 0 -0.00447964578399757
275 0.368466840071423 -1295.73881925051 -1172.48666124662 0.885155718809028 0 0 -12.4560455777736
300 0.340106234804241 -1286.44880545526 -1172.68326991324 7.08676386089508 0 0 -61.5499874224384
"""

MINIMIZE = SLAB.format(n=3, top=5) + """region base block INF INF INF INF INF 0.6
group base region base
fix hold base setforce 0 0 0
fix ind all indent 20.0 sphere 1.5 1.5 3.4 1.4
fix_modify ind energy yes
thermo_style custom step pe f_ind f_ind[1] f_ind[2] f_ind[3]
thermo_modify format float %.15g norm no
thermo 10
minimize 0.0 1.0e-8 200 10000
fix ind all indent 20.0 cylinder y 1.6 3.5 1.2 units lattice
fix_modify ind energy yes
minimize 0.0 1.0e-8 200 10000
"""

# LAMMPS 22 Jul 2025: step pe f_ID f_ID[1] f_ID[2] f_ID[3]; cg under a sphere pressed into a slab
# held at its base (linesearch alpha is zero after 30 iterations, 98 evaluations), then a cylinder
# along y in its place (force tolerance after 79 iterations, 158 evaluations)
LAMMPS_MINIMIZE = """
0 -695.166144858321 67.9017000177174 8.88178419700125e-15 8.88178419700125e-15 130.601378348923
10 -780.66514716225 14.8185129271214 1.15463194561016e-14 1.15463194561016e-14 50.4004741614359
20 -832.161209805071 6.19663491914315 7.32747196252603e-15 -4.44089209850063e-16 27.7509179456965
30 -833.691225097705 4.86810595320859 -1.55431223447522e-15 5.32907051820075e-15 23.5818917849099
30 -836.888664282788 1.67066676812508 -0.277502451546395 0 13.3216209859911
40 -838.2097109703 1.65004188857589 -0.233678007244796 0 14.1982303761248
50 -838.228249811905 1.63884723009719 -0.253715558720546 0 14.1291446833644
60 -838.228301567796 1.63973007812673 -0.253527106197219 0 14.1345844069767
70 -838.228301691605 1.63977943250708 -0.253525512838778 0 14.1348779364356
80 -838.228301692047 1.63977898862339 -0.253526076535881 0 14.134875938928
90 -838.228301692051 1.63977903671344 -0.25352589584676 0 14.1348763237042
100 -838.22830169205 1.63977902730753 -0.253525892447611 0 14.1348762725733
109 -838.22830169205 1.63977902776009 -0.253525892928716 0 14.1348762743582
"""


def recorded(text):
    return np.array([[float(v) for v in line.split()] for line in text.strip().splitlines()])


def test_lammps_thermo_of_a_sphere_a_cylinder_and_a_plane_pressing_a_slab(tmp_path):
    mine, lammps = logged_thermo(tmp_path, RUNS), recorded(LAMMPS_RUNS)
    assert mine.shape == lammps.shape
    np.testing.assert_array_equal(mine[:, 0], lammps[:, 0])
    # the force components that cancel by symmetry are round-off (1e-14) in both programs
    np.testing.assert_allclose(mine, lammps, rtol=1e-10, atol=1e-10)


def test_lammps_minimizes_under_an_indenter_as_pdps(tmp_path):
    mine, lammps = logged_thermo(tmp_path, MINIMIZE), recorded(LAMMPS_MINIMIZE)
    assert mine.shape == lammps.shape
    np.testing.assert_array_equal(mine[:, 0], lammps[:, 0])
    np.testing.assert_allclose(mine, lammps, rtol=1e-10, atol=1e-12)


def test_f_id_is_per_particle_where_lj_thermo_normalises(tmp_path):
    """The first run's set-up with LAMMPS's default thermo_modify norm yes in lj units: LAMMPS prints
    f_ID and f_ID[1..3] divided by the 224 particles, as pe."""
    script = RUNS.split("run 100")[0].replace(" norm no", "") + "run 0\n"
    mine = logged_thermo(tmp_path, script)
    lammps = [0, 0.5, -6.01947977816597, -5.27282799245168, 0.0366142287868026, 0.000119670094198852,
              0.000246683329950535, 0.172618626688664]
    np.testing.assert_allclose(mine[0], lammps, rtol=1e-12)


def test_the_same_run_on_1_and_2_ranks(tmp_path):
    """The sphere across the periodic x face and the cylinder (first 200 steps of the LAMMPS scene):
    thermo and f_ID on 2 ranks as on 1, to round-off."""
    one, two = thermo_on_ranks(RUNS.split("unfix cyl")[0], tmp_path)
    assert one[:, 0].tolist() == [0, 25, 50, 75, 100, 100, 125, 150, 175, 200]
    np.testing.assert_allclose(two, one, rtol=1e-9, atol=1e-10)
