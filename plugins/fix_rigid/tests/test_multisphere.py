"""fix multisphere on its own terms: a free clump keeps its momentum, angular momentum and energy
and its spheres stay rigid; gravity pulls a clump by M g once; fflag and tflag hold what they name;
the energies are the bodies'; a clump that loses part of its spheres stops the run with a line.
(LIGGGHTS's numbers for the same fix: the recorded cases multisphere_given and multisphere_mc.)"""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

HEAD = """atom_style sphere
atom_modify map array sort 0 0.0
boundary {boundary}
newton off
communicate single vel yes
units si
region box block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box 1 box
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.9
fix m4 all property/global coefficientFriction peratomtypepair 1 0.3
pair_style gran model hertz tangential history
pair_coeff * *
timestep 1e-5
"""
# an L of three overlapping spheres, its mass and inertia given (the volume and centre by Monte Carlo)
TEMPLATE = ("fix pts all particletemplate/multisphere 15485863 atom_type 1 density constant 2500 nspheres 3 "
            "ntry 100000 spheres 0.0 0.0 0.0 0.005 0.008 0.0 0.0 0.004 0.0 0.007 0.002 0.0045 type 1 "
            "mass 0.0025 inertia_tensor 3.1e-8 -4e-9 1e-9 2.7e-8 -2e-9 4.0e-8 use_volume {flags}\n"
            "fix pdd all particledistribution/discrete 15485867 1 pts 1.0\n")
MASS = 0.0025
TENSOR = np.array([[3.1e-8, -4e-9, 1e-9], [-4e-9, 2.7e-8, -2e-9], [1e-9, -2e-9, 4.0e-8]])


def clump(more="", flags="", vel="0.2 -0.1 0.3", omega="20.0 -35.0 50.0", boundary="f f f", at="0.0 0.0 0.05"):
    """One clump inserted at ``at`` (its centre of mass) with velocity ``vel`` and spin ``omega``,
    in the template's orientation, moved by fix multisphere; ``more`` before the first run."""
    x, y, z = (float(w) for w in at.split())
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(HEAD.format(boundary=boundary) + TEMPLATE.format(flags=flags)
                + f"region at block {x} {x + 1e-15} {y} {y + 1e-15} {z} {z + 1e-15} units box volume_limit 1e-50\n"
                f"fix ins all insert/pack seed 32452843 distributiontemplate pdd vel constant {vel} "
                f"omega constant {omega} orientation template insert_every once overlapcheck yes region at "
                "particles_in_region 1\n"
                "fix integr all multisphere\ncompute kem all ke/multisphere\ncompute erm all erotate/multisphere\n"
                + more + "run 1\n")
    return sim


def spheres(sim):
    order = np.argsort(sim.particles.tag[:sim.particles.nlocal])
    return sim.particles.x[:sim.particles.nlocal][order].copy()


def space_angular_momentum(fix):
    return fix.angmom[0].copy()


def test_a_free_clump_keeps_momentum_angular_momentum_energy_and_shape():
    sim = clump()
    fix = sim.fixes["integr"]
    x0, v0, l0 = fix.xcm[0].copy(), fix.vcm[0].copy(), space_angular_momentum(fix)
    e0 = sim.computes["erm"].scalar(sim)
    gaps0 = np.linalg.norm(spheres(sim)[:, None] - spheres(sim)[None], axis=2)
    sim.command("run 2000")       # 20 ms: the L turns about 1 rad a ms
    np.testing.assert_allclose(fix.vcm[0], v0, rtol=1e-14)
    np.testing.assert_allclose(fix.xcm[0], x0 + v0 * 2000e-5, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(space_angular_momentum(fix), l0, rtol=1e-12, atol=1e-22)
    # Richardson's quaternion update keeps the energy of torque-free rotation to O(dt^2) a period
    assert sim.computes["erm"].scalar(sim) == pytest.approx(e0, rel=1e-6)
    gaps = np.linalg.norm(spheres(sim)[:, None] - spheres(sim)[None], axis=2)
    np.testing.assert_allclose(gaps, gaps0, atol=1e-13)
    # the spheres move with the body: v_i = V + omega x (r_i - X)
    p = sim.particles
    arm = p.x[:3] - fix.xcm[0]
    np.testing.assert_allclose(p.v[:3], fix.vcm[0] + np.cross(fix.omega[0], arm), rtol=1e-10, atol=1e-14)


def test_the_energies_are_the_body_s():
    sim = clump(more="compute k all ke\ncompute r all erotate\ncompute rs all erotate/sphere\n")
    fix = sim.fixes["integr"]
    omega = fix.omega[0]
    rotation = np.array([fix.ex[0], fix.ey[0], fix.ez[0]]).T       # body frame to space
    inertia_space = rotation @ np.diag(fix.inertia[0]) @ rotation.T
    # the template's orientation: the body's inertia in space is the tensor given
    np.testing.assert_allclose(inertia_space, TENSOR, rtol=1e-10, atol=1e-20)
    kem = 0.5 * MASS * float(fix.vcm[0] @ fix.vcm[0])
    erm = 0.5 * float(omega @ TENSOR @ omega)
    assert sim.computes["kem"].scalar(sim) == pytest.approx(kem, rel=1e-12)
    assert sim.computes["erm"].scalar(sim) == pytest.approx(erm, rel=1e-10)
    assert sim.computes["k"].scalar(sim) == pytest.approx(kem, rel=1e-12)
    assert sim.computes["r"].scalar(sim) == pytest.approx(erm, rel=1e-10)
    assert sim.computes["rs"].scalar(sim) == 0.0


def test_gravity_pulls_a_clump_by_m_g_once():
    sim = clump(more="fix grav all gravity 9.81 vector 0.0 0.0 -1.0\n", omega="0.0 0.0 0.0")
    fix = sim.fixes["integr"]
    v0 = fix.vcm[0].copy()
    sim.command("run 1000")
    np.testing.assert_allclose(fix.vcm[0], v0 + np.array([0.0, 0.0, -9.81]) * 1000e-5, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(fix.omega[0], 0.0, atol=1e-12)


def test_fflag_and_tflag_hold_what_they_name():
    sim = clump(more="fix grav all gravity 9.81 vector 0.3 0.0 -1.0\n", flags="fflag off on on tflag on off on")
    fix = sim.fixes["integr"]
    v0, l0 = fix.vcm[0].copy(), fix.angmom[0].copy()
    sim.command("run 500")
    assert fix.vcm[0][0] == v0[0]                       # no force along x: vx stays
    assert fix.vcm[0][2] < v0[2]
    assert fix.angmom[0][1] == l0[1]                    # no torque about y: L_y stays


def test_a_clump_that_loses_spheres_stops_the_run():
    # the clump flies out through a fixed face, sphere by sphere
    sim = clump(more="thermo_modify lost ignore\n", vel="3.0 0.0 0.0", omega="0.0 0.0 0.0", at="0.03 0.0 0.05")
    with pytest.raises(ScriptError) as error:
        sim.command("run 2000")
    assert "fix integr: multisphere body 1 lost 1 of its 3 spheres at step" in str(error.value)
    assert "LIGGGHTS removes the whole body, pdps cannot yet" in str(error.value)


def test_a_clump_that_leaves_through_a_periodic_face_comes_back_whole():
    sim = clump(vel="3.0 0.0 0.0", omega="0.0 0.0 0.0", boundary="p f f", at="0.03 0.0 0.05")
    gaps0 = np.linalg.norm(spheres(sim)[:, None] - spheres(sim)[None], axis=2)
    sim.command("run 1000")
    fix = sim.fixes["integr"]
    assert -0.05 <= fix.xcm[0][0] < 0.05
    # the spheres are the body's, as the box wraps them: the unwrapped gaps stay
    p = sim.particles
    unwrapped = p.x[:3] + p.image[:3] * np.asarray(sim.box.length)
    order = np.argsort(p.tag[:3])
    np.testing.assert_allclose(np.linalg.norm(unwrapped[order][:, None] - unwrapped[order][None], axis=2), gaps0,
                               atol=1e-12)


def test_compute_multisphere_gives_every_body_s_property():
    sim = clump(more="compute x all multisphere property xcm\ncompute m all rigid property masstotal\n"
                     "compute i all multisphere property id\ncompute t all multisphere property type\n"
                     "compute one all multisphere/single id 1 property vcm\n"
                     "compute two all multisphere/single id 2 property masstotal\n")
    fix = sim.fixes["integr"]
    np.testing.assert_array_equal(sim.computes["x"].local(sim), fix.xcm)
    np.testing.assert_array_equal(sim.computes["m"].local(sim), [MASS])
    np.testing.assert_array_equal(sim.computes["i"].local(sim), [1.0])
    np.testing.assert_array_equal(sim.computes["t"].local(sim), [1.0])
    np.testing.assert_array_equal(sim.computes["one"].vector(sim), fix.vcm[0])
    assert sim.computes["two"].scalar(sim) == 0.0          # no body 2 yet


@pytest.mark.parametrize("line, message", [
    ("compute c top multisphere property xcm",
     "compute c (multisphere): the group must be all (as LIGGGHTS: bodies belong to no group; got top)"),
    ("compute c all multisphere property colour",
     "property must be one of xcm, vcm, fcm, torque, angmom, omega, quat, inertia, ex_space, ey_space, ez_space, "
     "masstotal, density, atomtype, clumptype, nrigid, id_multisphere, id, type (got colour)"),
    ("compute c all rigid property r_bound",
     "property r_bound: pdps's fix multisphere does not keep it per body (it has: xcm, vcm, fcm, torque, angmom, "
     "omega, quat, inertia, ex_space, ey_space, ez_space, masstotal, density, atomtype, clumptype, nrigid, "
     "id_multisphere)"),
    ("compute c all multisphere/single id 0 property xcm", "id must be >= 1 (got 0)"),
    ("compute c all multisphere/single property xcm",
     "missing keyword id; usage: compute ID all multisphere/single id N property NAME"),
])
def test_bad_compute_multisphere_lines(line, message):
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(HEAD.format(boundary="f f f") + "group top region box\n")
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert str(error.value) == f"<command>:1: compute: {message}"


def test_a_vector_property_read_as_a_scalar_is_named():
    with pytest.raises(ScriptError) as error:
        clump(more="compute one all multisphere/single id 1 property vcm\nthermo_style custom step c_one\n")
    assert "compute one (multisphere/single): property vcm has 3 values: read c_one[i]" in str(error.value)


def test_compute_multisphere_without_the_fix_is_refused_at_the_run():
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(HEAD.format(boundary="f f f") + "compute x all multisphere property xcm\n")
    with pytest.raises(ScriptError) as error:
        sim.command("run 1")
    assert str(error.value) == "<command>:1: run: compute x (multisphere): fix multisphere does not exist"


def test_two_fixes_gravity_are_refused_with_fix_multisphere():
    with pytest.raises(ScriptError) as error:
        clump(more="fix g1 all gravity 9.81 vector 0.0 0.0 -1.0\nfix g2 all gravity 1.0 vector 1.0 0.0 0.0\n")
    assert "fix integr multisphere takes one fix gravity (as LIGGGHTS); fixes g1 and g2 are two" in str(error.value)


def breaking_clump(trigger_lines, fix_args):
    x, y, z = 0.0, 0.0, 0.05
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(HEAD.format(boundary="f f f") + TEMPLATE.format(flags="")
                + f"region at block {x} {x + 1e-15} {y} {y + 1e-15} {z} {z + 1e-15} units box volume_limit 1e-50\n"
                "fix ins all insert/pack seed 32452843 distributiontemplate pdd vel constant 0.0 0.0 -1.0 "
                "omega constant 0.0 0.0 30.0 orientation template insert_every once overlapcheck yes region at "
                "particles_in_region 1\n" + trigger_lines
                + f"fix move all nve/sphere\nfix integr all multisphere/break {fix_args}\n"
                "compute kem all ke/multisphere\ncompute one all multisphere/single id 1 property vcm\nrun 1\n")
    return sim


def test_a_body_breaks_when_a_sphere_s_trigger_reaches_the_threshold():
    sim = breaking_clump("region low block INF INF INF INF INF 0.03 units box\n"
                         "fix low all property/atom/tracer region_mark low mark_step 0 marker_style heaviside "
                         "check_mark_every 1\n", "trigger_name f_low trigger_threshold 0.5")
    fix = sim.fixes["integr"]
    p = sim.particles
    sim.command("run 1000")                  # the clump falls 1 cm: still whole
    assert fix.nrigid[0] == 3
    assert (p.rmass[:3] == MASS).all()
    sim.command("run 1300")                  # its lowest sphere is below 3 cm by now
    assert fix.nrigid[0] == 0
    order = np.argsort(p.tag[:3])
    radius, density = p.radius[:3][order], p.arrays["density"][:3][order]
    # each released sphere weighs its own volume at the body's density
    np.testing.assert_allclose(p.rmass[:3][order], 4.0 / 3.0 * np.pi * radius ** 3 * density, rtol=1e-14)
    assert (p.arrays["molecule"][:3] == 0).all()
    # the spheres fly on as released (no force acts: their spin and velocities stay)
    v = p.v[:3].copy()
    sim.command("run 10")
    np.testing.assert_allclose(p.v[:3], v, rtol=0, atol=1e-15)
    # the broken body has lost its id: its single compute reads zeros, as LIGGGHTS's
    np.testing.assert_array_equal(sim.computes["one"].vector(sim), [0.0, 0.0, 0.0])


def test_no_body_breaks_before_trigger_timestep():
    sim = breaking_clump("variable one atom 1.0\n", "trigger_name v_one trigger_threshold 0.5 trigger_timeStep 50")
    sim.command("run 49")
    assert sim.step == 50
    assert sim.fixes["integr"].nrigid[0] == 3       # at step 50, not after it
    sim.command("run 1")
    assert sim.fixes["integr"].nrigid[0] == 0       # at the end of step 51


@pytest.mark.parametrize("fix_args, message", [
    ("trigger_threshold 1", "No setting made for 'trigger_name'. You must make this setting! (as LIGGGHTS)"),
    ("trigger_name c_x", "trigger_name must be f_NAME, f_NAME[k] or v_NAME (got c_x)"),
    ("trigger_name f_a trigger_fixName a", "give trigger_name or the deprecated trigger_fixName, not both (as LIGGGHTS)"),
])
def test_bad_multisphere_break_lines(fix_args, message):
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(HEAD.format(boundary="f f f"))
    with pytest.raises(ScriptError) as error:
        sim.command(f"fix integr all multisphere/break {fix_args}")
    assert str(error.value) == f"<command>:1: fix: {message}"
