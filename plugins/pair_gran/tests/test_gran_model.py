"""pair_style gran model ... (LIGGGHTS): the material from fix property/global, the Hertz and Hooke
laws against their formulas and restitution coefficients, the script's dialect and the error lines."""

import math

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import assert_refused, liggghts_material, liggghts_one_particle

RHO = 2500.0
D = 0.01
MASS = RHO * math.pi / 6.0 * D ** 3


def material(e=0.5, mu=0.5, **more):
    return liggghts_material(5.e6, 0.45, e, mu, **more)


def two_spheres(pair, gap, speed, *, mat=None, dt=1e-6, extra="", style="gran", coeff=""):
    """Two spheres of diameter D on the x axis, centres 2 (D/2 + gap) apart, approaching at
    ``speed`` each (gap < 0: overlapping); SI units, LIGGGHTS's spelling."""
    sim = Simulation(screen=False, log=None)
    x = D / 2 + gap
    sim.command(f"""
atom_style granular
boundary f f f
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
{material() if mat is None else mat}
pair_style {style} {pair}
pair_coeff * * {coeff}
timestep {dt!r}
create_atoms 1 single {-x!r} 0 0 units box
create_atoms 1 single {x!r} 0 0 units box
set type 1 diameter {D!r} density {RHO!r}
velocity all set 0 0 0 units box
set atom 1 vx {speed!r}
set atom 2 vx {-speed!r}
{extra}""")
    return sim


def effective(youngs=5e6, poisson=0.45):
    y_star = youngs / (2 * (1 - poisson ** 2))
    g_star = youngs / (4 * (2 - poisson) * (1 + poisson))
    return y_star, g_star, D / 4, MASS / 2


@pytest.mark.parametrize("e", [0.5, 0.9])
def test_hertz_head_on_collision_rebounds_with_the_restitution_coefficient(e):
    """LIGGGHTS's Hertz damping (Tsuji's, -2 sqrt(5/6) beta sqrt(S_n m*)) makes the restitution
    independent of the speed and equal to e; ~650 steps a contact."""
    sim = two_spheres("model hertz tangential history", 1e-4, 1.0, mat=material(e),
                      extra="fix integr all nve/sphere")
    sim.command("run 3000")
    v = sim.v[np.argsort(sim.tag)]
    assert -v[0, 0] == pytest.approx(e, rel=2e-3)
    assert v[1, 0] == pytest.approx(-v[0, 0], rel=1e-12)


def test_hooke_head_on_collision_rebounds_with_the_restitution_coefficient():
    """Hooke: a linear spring with damping sqrt(4 m* kn / (1 + pi^2/ln^2 e)) rebounds with e at any
    speed; kn from the characteristic velocity."""
    mat = material(0.7, characteristicVelocity=2.0)
    sim = two_spheres("model hooke tangential history", 1e-4, 0.5, mat=mat, extra="fix integr all nve/sphere")
    sim.command("run 4000")
    v = sim.v[np.argsort(sim.tag)]
    assert -v[0, 0] / 0.5 == pytest.approx(0.7, rel=2e-3)


def setup_forces(sim):
    sim.command("run 0")
    order = np.argsort(sim.tag)
    return sim.f[order].copy(), sim.particles.torque[: sim.nlocal][order].copy()


@pytest.mark.parametrize("speed", [0.0, 0.3])
def test_hertz_normal_force_is_liggghts_formula(speed):
    """F_n = 4/3 Y* sqrt(R* delta) delta - gamma_n v_n, gamma_n = -2 sqrt(5/6) beta sqrt(2 Y*
    sqrt(R* delta) m*), Y* = Y / (2 (1 - nu^2)) for two equal spheres."""
    delta = 2e-5
    sim = two_spheres("model hertz tangential history", -delta / 2, speed)
    force, _ = setup_forces(sim)
    y_star, _, r_star, m_star = effective()
    root = math.sqrt(r_star * delta)
    beta = math.log(0.5) / math.sqrt(math.log(0.5) ** 2 + math.pi ** 2)
    gamma_n = -2 * math.sqrt(5 / 6) * beta * math.sqrt(2 * y_star * root * m_star)
    v_n = -2 * speed     # (v_1 - v_2) . n with n from 2 to 1 (-x)
    expected = 4 / 3 * y_star * root * delta - gamma_n * v_n
    assert force[0, 0] == pytest.approx(-expected, rel=1e-12)
    assert force[1, 0] == pytest.approx(expected, rel=1e-12)


def test_hooke_stiffness_from_the_characteristic_velocity():
    """kn = 16/15 sqrt(R*) Y* (15 m* V^2 / (16 sqrt(R*) Y*))^(1/5)."""
    delta, velocity = 2e-5, 2.0
    mat = material(characteristicVelocity=velocity)
    sim = two_spheres("model hooke tangential history", -delta / 2, 0.0, mat=mat)
    force, _ = setup_forces(sim)
    y_star, _, r_star, m_star = effective()
    kn = 16 / 15 * math.sqrt(r_star) * y_star * (15 * m_star * velocity ** 2 / (16 * math.sqrt(r_star) * y_star)) ** 0.2
    assert force[1, 0] == pytest.approx(kn * delta, rel=1e-12)


def test_no_history_friction_is_viscous_up_to_coulomb():
    """tangential no_history: F_t = -min(mu |F_n|, gamma_t |v_t|) v_t/|v_t|; a fast slide sits on
    Coulomb's limit."""
    delta = 2e-5
    sim = two_spheres("model hertz tangential no_history", -delta / 2, 0.0,
                      extra="set atom 1 vy 1.0")
    force, torque = setup_forces(sim)
    assert abs(force[0, 1]) == pytest.approx(0.5 * abs(force[0, 0]), rel=1e-12)
    assert force[0, 1] < 0
    # the torque of the tangential force at the contact point, R - delta/2 along +x from sphere 1
    assert torque[0, 2] == pytest.approx((D / 2 - delta / 2) * force[0, 1], rel=1e-12)


def test_per_type_pair_tables_reach_the_law():
    """Two types, friction per type pair: a sliding contact of types 1 and 2 is limited by
    mu_12, not mu_11 or mu_22."""
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
atom_style granular
units si
boundary f f f
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 2 reg
{liggghts_material((5.e6, 5.e6), (0.45, 0.45), [0.5] * 4, (0.1, 0.3, 0.3, 0.7))}
pair_style gran model hertz tangential no_history
pair_coeff * *
create_atoms 1 single -0.00499 0 0 units box
create_atoms 2 single 0.00499 0 0 units box
set group all diameter {D} density {RHO}
set atom 1 vy 1.0
""")
    force, _ = setup_forces(sim)
    assert abs(force[0, 1]) == pytest.approx(0.3 * abs(force[0, 0]), rel=1e-12)


SETUP = liggghts_one_particle(2)
FULL = """\
fix m1 all property/global youngsModulus peratomtype 5.e6 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 0.5 0.5
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
"""


@pytest.mark.parametrize("lines, message", [
    (FULL.replace("fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5\n", ""),
     "run: pair gran needs coefficientFriction: fix ID all property/global coefficientFriction "
     "peratomtypepair 2 V11 ... V22"),
    (FULL.replace("peratomtype 5.e6 5.e6", "peratomtype 5.e6"),
     "run: youngsModulus (fix m1) has 1 value(s) for 2 particle type(s)"),
    (FULL.replace("coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5", "coefficientFriction peratomtypepair 1 0.5"),
     "run: coefficientFriction (fix m4) is a 1 x 1 table for 2 particle type(s)"),
    (FULL.replace("0.45 0.45", "0.45 0.7"), "run: poissonsRatio (fix m2) must be in (-1, 0.5] (got 0.7)"),
    (FULL, "run: pair gran needs characteristicVelocity: fix ID all property/global characteristicVelocity "
     "scalar VALUE"),
    (FULL + "fix m5 all property/global characteristicVelocity peratomtype 2 2\n",
     "run: characteristicVelocity (fix m5) must be given as scalar (got peratomtype)"),
])
def test_bad_material_stops_the_run_with_one_line(pdps_cli, lines, message):
    """Missing properties and wrong counts are found at the run that needs them (hooke reads the
    characteristic velocity, hertz does not)."""
    style = "hooke" if "characteristicVelocity" in message else "hertz"
    script = SETUP + lines + f"pair_style gran model {style} tangential history\npair_coeff * *\nrun 0\n"
    assert_refused(pdps_cli(script), script.count(chr(10)), message)


@pytest.mark.parametrize("line, message", [
    ("pair_style gran model hertz", "pair_style: missing keyword tangential; usage: pair_style gran model "
     "hertz|hooke|hertz/stiffness|hooke/stiffness|hooke/hysteresis tangential history|no_history [rolling_friction "
     "off|cdt|epsd|epsd2|epsd3] [cohesion off|sjkr|sjkr2|easo/capillary/viscous|washino/capillary/viscous] "
     "[surface default] [tangential_damping|limitForce|absolute_damping|tangential_reduce|torsionTorque|"
     "limitLiquidContent|modifyLbVolume on|off] [max_contacts N]"),
    ("pair_style gran model hertz tangential history torsionTorque on",
     "pair_style: torsionTorque is not a setting of the chosen models (normal hertz tangential history)"),
    ("pair_style gran model hertz tangential history rolling_friction xyz",
     "pair_style: rolling_friction must be one of 'off', 'cdt', 'epsd', 'epsd2' or 'epsd3' (got xyz)"),
    ("pair_style gran model hertz tangential history cohesion sjkr limitForce maybe",
     "pair_style: limitForce must be one of 'on' or 'off' (got maybe)"),
])
def test_bad_pair_style_lines(pdps_cli, line, message):
    assert_refused(pdps_cli(SETUP + line + "\n"), 6, message)


def test_a_liggghts_script_says_so_on_its_first_line(pdps_cli):
    done = pdps_cli("units si\nboundary f f f\natom_style granular\nregion reg block -1 1 -1 1 -1 1 units box\n"
                    "create_box 1 reg\n")
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[0] == "read as LIGGGHTS: atom_style granular on line 3"
    done = pdps_cli("units si\natom_style sphere\nregion reg block -1 1 -1 1 -1 1 units box\ncreate_box 1 reg\n"
                    + FULL.replace("5.e6 5.e6", "5.e6").splitlines()[0] + "\n")
    assert done.stdout.splitlines()[0] == "read as LIGGGHTS: fix property/global on line 5"


def test_cohesion_sjkr_pulls_with_k_times_the_intersection_area():
    """sjkr: F_n = hertz - k pi a^2, a the radius of the circle where the spheres intersect."""
    delta, k = 2e-5, 3.0e4
    mat = material(cohesionEnergyDensity=k)
    sim = two_spheres("model hertz tangential history cohesion sjkr", -delta / 2, 0.0, mat=mat)
    force, _ = setup_forces(sim)
    y_star, _, r_star, _ = effective()
    r = D - delta
    a2 = (D / 2) ** 2 - (r / 2) ** 2
    assert force[1, 0] == pytest.approx(4 / 3 * y_star * math.sqrt(r_star * delta) * delta - k * math.pi * a2,
                                        rel=1e-12)


@pytest.mark.parametrize("spin", [40.0, -40.0])
def test_cdt_rolling_torque_opposes_the_relative_spin(spin):
    """Spheres spinning oppositely about z (their contact points move together: no sliding) feel
    the cdt torque mu_r k_n delta R* against omega_1 - omega_2: -M on 1, +M on 2."""
    delta, mu_r = 2e-5, 0.2
    mat = material(coefficientRollingFriction=mu_r)
    sim = two_spheres("model hertz tangential history rolling_friction cdt", -delta / 2, 0.0, mat=mat)
    p = sim.particles
    p.omega[p.index_of_tag(1)] = (0.0, 0.0, spin)
    p.omega[p.index_of_tag(2)] = (0.0, 0.0, -spin)
    _, torque = setup_forces(sim)
    y_star, _, r_star, _ = effective()
    moment = mu_r * 4 / 3 * y_star * math.sqrt(r_star * delta) * delta * r_star
    assert torque[0] == pytest.approx([0.0, 0.0, -math.copysign(moment, spin)], rel=1e-12, abs=1e-20)
    assert torque[1] == pytest.approx([0.0, 0.0, math.copysign(moment, spin)], rel=1e-12, abs=1e-20)


def test_a_liggghts_header_runs_as_liggghts_means_it(pdps_cli):
    """The lines LIGGGHTS's own examples start with: atom_modify map array, boundary m m m,
    newton off, communicate single vel yes, thermo_modify lost ignore norm no, compute_modify
    thermo_temp dynamic yes, run N upto. A sphere falls out through the m floor: the box follows
    it instead of losing it; run 300 upto after run 100 stops at step 300."""
    done = pdps_cli("""\
atom_style granular
atom_modify map array
boundary m m m
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
""" + material() + """\
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.001
create_atoms 1 single 0 0 0.01 units box
set type 1 diameter 0.01 density 2500
fix integr all nve/sphere
fix g all gravity 9.81 vector 0 0 -1
compute_modify thermo_temp dynamic yes
thermo_style custom step atoms zlo
thermo_modify lost ignore norm no
thermo 100
run 100
run 300 upto
""")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert lines[0] == "read as LIGGGHTS: atom_style granular on line 1"
    rows = [line.split() for line in lines if line.split()[:1] in (["100"], ["200"], ["300"])]
    steps = [int(r[0]) for r in rows]
    assert steps[-1] == 300 and steps.count(300) == 1
    # fallen 0.44 m by t = 0.3 s: the lower face went with it, the sphere is still there
    assert float(rows[-1][1]) == 1
    assert float(rows[-1][2]) < -0.4


@pytest.mark.parametrize("limit", ["off", "on"])
def test_limit_force_keeps_a_separating_contact_from_pulling(limit):
    """Spheres 1e-7 into each other, separating at 2 m/s: the damping outweighs the spring, so
    F_n = kn delta - gamma_n v_n < 0 (a pull) unless limitForce on sets it to 0."""
    delta = 1e-7
    sim = two_spheres(f"model hertz tangential history limitForce {limit}", -delta / 2, -1.0)
    force, _ = setup_forces(sim)
    y_star, _, r_star, m_star = effective()
    root = math.sqrt(r_star * delta)
    beta = math.log(0.5) / math.sqrt(math.log(0.5) ** 2 + math.pi ** 2)
    gamma_n = -2 * math.sqrt(5 / 6) * beta * math.sqrt(2 * y_star * root * m_star)
    pull = 4 / 3 * y_star * root * delta - gamma_n * 2.0
    assert pull < 0
    assert force[1, 0] == (0.0 if limit == "on" else pytest.approx(pull, rel=1e-12))


def test_tangential_damping_off_leaves_only_the_spring():
    """With no spring yet (run 0 does not grow it) a sliding contact feels the tangential damping
    -gamma_t v_t alone, and nothing with tangential_damping off."""
    delta = 2e-5
    forces = {}
    for damping in ("on", "off"):
        sim = two_spheres(f"model hertz tangential history tangential_damping {damping}", -delta / 2, 0.0,
                          extra="set atom 1 vy 0.001")
        forces[damping], _ = setup_forces(sim)
    _, g_star, r_star, m_star = effective()
    beta = math.log(0.5) / math.sqrt(math.log(0.5) ** 2 + math.pi ** 2)
    gamma_t = -2 * math.sqrt(5 / 6) * beta * math.sqrt(8 * g_star * math.sqrt(r_star * delta) * m_star)
    assert forces["on"][0, 1] == pytest.approx(-gamma_t * 0.001, rel=1e-12)
    assert forces["off"][0, 1] == 0.0


def test_timestep_limits_give_liggghts_rayleigh_and_hertz_times():
    """Rayleigh time pi R sqrt(rho/G) / (0.1631 nu + 0.8766), G = Y / 2(1 + nu); LIGGGHTS's Hertz
    estimate of a sphere hitting its copy at twice the largest speed, 2.87 (m^2 / (R* Y*^2 v))^(1/5)
    with m the full mass (LIGGGHTS's fix check/timestep/gran); the contact time with m* = m/2."""
    sim = two_spheres("model hertz tangential history", 1e-4, 1.0)
    sim.command("run 0")
    limits = sim.pair.timestep_limits(sim)
    shear = 5e6 / (2 * 1.45)
    rayleigh = math.pi * (D / 2) * math.sqrt(RHO / shear) / (0.1631 * 0.45 + 0.8766)
    assert limits["rayleigh"] == pytest.approx(rayleigh, rel=1e-12)
    y_star, _, r_star, m_star = effective()
    hertz = 2.87 * ((2 * m_star) ** 2 / (r_star * y_star ** 2 * 2.0)) ** 0.2
    assert limits["hertz"] == pytest.approx(hertz, rel=1e-12)
    contact = 2.868 * (m_star ** 2 / (r_star * y_star ** 2 * 2.0)) ** 0.2
    assert limits["contact"] == pytest.approx(contact, rel=1e-12)


def test_head_on_hertz_collision_is_dem_hertzs():
    """LIGGGHTS's normal Hertz law is pdps's dem/hertz one (the same stiffness and Tsuji damping):
    a head-on collision, with no tangential motion, gives the same velocities after every step to
    1e-12; so docs/accuracy-dem.md's dem/hertz rows (restitution against dt/t_c) hold for it."""
    records = []
    for style, pair, coeff in (("gran", "model hertz tangential history", ""),
                               ("dem/hertz", "", "5.e6 0.45 0.5 0.5")):
        sim = two_spheres(pair, 1e-4, 1.0, extra="fix integr all nve/sphere", style=style, coeff=coeff)
        velocities = []
        for _ in range(30):
            sim.command("run 100")
            velocities.append(sim.v[np.argsort(sim.tag)][:, 0].copy())
        records.append(np.array(velocities))
    np.testing.assert_allclose(records[0], records[1], rtol=1e-12, atol=1e-15)
    assert records[0][-1, 0] == pytest.approx(-0.5, rel=2e-3)


def test_contacts_stored_under_other_models_do_not_carry_over(pdps_cli):
    """A restart written with rolling friction epsd2 keeps 6 values a contact (spring and rolling
    torque); read back under hertz with history alone (3) the run stops at its line, saying why,
    rather than reading the springs askew."""
    mat = material(coefficientRollingFriction=0.1)
    written = pdps_cli("atom_style granular\nunits si\nregion reg block -1 1 -1 1 -1 1 units box\ncreate_box 1 reg\n"
                       + mat + "pair_style gran model hertz tangential history rolling_friction epsd2\npair_coeff * *\n"
                       "create_atoms 1 single -0.00499 0 0 units box\ncreate_atoms 1 single 0.00499 0 0 units box\n"
                       "set type 1 diameter 0.01 density 2500\nfix integr all nve/sphere\nrun 10\n"
                       "write_restart gran.restart\n")
    assert written.returncode == 0, written.stderr
    script = ("read_restart gran.restart\n" + mat
              + "pair_style gran model hertz tangential history\npair_coeff * *\nfix integr all nve/sphere\nrun 0\n")
    assert_refused(pdps_cli(script), script.count("\n"),
                   "run: the contacts stored keep 6 value(s) each, pair gran's 3: they were written under other "
                   "models (a restart file of other model words, or of a pdps before 11-28) and cannot carry over")


@pytest.mark.parametrize("alias", ["bubble", "gran_bubble"])
def test_bubble_and_gran_bubble_are_gran(alias):
    """LIGGGHTS's aliases give gran's trajectory, tangential history included (which LIGGGHTS 3.8.0
    itself crashes on under these names: the recorded cases bubble and gran_bubble run without it)."""
    runs = []
    for style in ("gran", alias):
        sim = two_spheres("model hertz tangential history", -1e-5, 0.3, style=style,
                          extra="set atom 1 vy 0.05 omegaz 3.0\nfix integr all nve/sphere\nrun 400")
        runs.append((sim.x[:2].copy(), sim.v[:2].copy(), sim.particles.omega[:2].copy()))
    for mine, theirs in zip(*runs):
        np.testing.assert_array_equal(mine, theirs)
    assert np.abs(runs[0][2]).max() > 0
