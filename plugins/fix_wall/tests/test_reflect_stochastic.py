"""fix wall/reflect/stochastic: the velocities particles leave a wall with, per rule, against their
distributions (statistics of 20,000 collisions each, bounds of 5 standard errors or the
Kolmogorov-Smirnov bound at the 1e-4 level), the path after the collision, the refusals, and an
ideal gas between two walls against LAMMPS's means (recorded with LAMMPS 22 Jul 2025 on this machine,
12-07).

A collision scene: N particles at x = 0.5 moving to the wall xlo 0 with v = (-1, 0.25, -0.125); one
step of dt = 1 takes them to x = -0.5, half a step beyond the wall, so each is reflected once.
"""

import math

import numpy as np
import pytest

from pdps_core.testing import build, logged_thermo, script_error, thermo_on_ranks

N = 20000
V0 = np.array([-1.0, 0.25, -0.125])


def collide(tmp_path, wall, mass=2.0, units="lj", n=N, dt=1.0):
    rng = np.random.default_rng(7)
    x = np.column_stack([np.full(n, 0.5 * dt), rng.uniform(0, 10, n), rng.uniform(0, 10, n)])
    sim = build(tmp_path, x, v=np.tile(V0, (n, 1)), masses={1: mass}, lo=(-2, 0, 0), hi=(10, 10, 10),
                boundary="f p p", units=units, setup=f"""
        timestep {dt}
        fix 1 all nve
        fix 2 all wall/reflect/stochastic {wall}
        run 1
    """)
    order = np.argsort(sim.tag)
    return sim.x[order], sim.v[order]


def within(values, mean, std_of_one, sigmas=5.0):
    """The sample mean is within ``sigmas`` standard errors of ``mean``."""
    error = std_of_one / math.sqrt(len(values))
    return abs(values.mean() - mean) < sigmas * error


def ks_distance(values, cdf):
    ordered = np.sort(values)
    n = len(ordered)
    model = cdf(ordered)
    return max(np.max(np.arange(1, n + 1) / n - model), np.max(model - np.arange(n) / n))


KS_BOUND = 2.0 / math.sqrt(N)      # P(D > 2/sqrt(N)) ~ 6.7e-4


def rayleigh_cdf(sigma):
    return lambda v: 1.0 - np.exp(-v * v / (2 * sigma * sigma))


def normal_cdf(mean, sigma):
    erf = np.vectorize(math.erf)
    return lambda v: 0.5 * (1.0 + erf((v - mean) / (sigma * math.sqrt(2.0))))


def test_diffusive_walls_send_particles_back_with_the_maxwell_flux_distribution(tmp_path):
    """T = 1.5, m = 2: theta = kT/m = 0.75; the wall moves at vy = 0.4. Normal: Rayleigh(sqrt(theta)),
    mean sqrt(pi theta / 2), <v^2> = 2 theta; tangential: normal about the wall's velocity, variance theta."""
    x, v = collide(tmp_path, "diffusive 4321 xlo 0 1.5 0 0.4 0 units box")
    theta = 0.75
    sigma = math.sqrt(theta)
    assert (v[:, 0] > 0).all()
    assert within(v[:, 0], sigma * math.sqrt(math.pi / 2), sigma * math.sqrt(2 - math.pi / 2))
    assert ks_distance(v[:, 0], rayleigh_cdf(sigma)) < KS_BOUND
    assert within(v[:, 1], 0.4, sigma) and within(v[:, 2], 0.0, sigma)
    assert within((v[:, 1] - 0.4) ** 2, theta, math.sqrt(2) * theta)
    assert ks_distance(v[:, 1], normal_cdf(0.4, sigma)) < KS_BOUND
    assert ks_distance(v[:, 2], normal_cdf(0.0, sigma)) < KS_BOUND
    # the three components are independent: no correlation beyond 5 standard errors
    assert abs(np.corrcoef(v.T)[np.triu_indices(3, 1)]).max() < 5 / math.sqrt(N)


def test_after_the_collision_the_particle_travels_on_for_the_time_it_spent_beyond_the_wall(tmp_path):
    """Crossing x = 0 at t = 0.5 of the step: back to the crossing point, then 0.5 of the new velocity."""
    rng = np.random.default_rng(7)
    y0 = rng.uniform(0, 10, N)
    x, v = collide(tmp_path, "diffusive 4321 xlo 0 1.5 0 0 0 units box")
    np.testing.assert_allclose(x[:, 0], 0.5 * v[:, 0], rtol=1e-14)
    crossing_y = y0 + 0.5 * V0[1]
    np.testing.assert_allclose(np.mod(x[:, 1] - crossing_y - 0.5 * v[:, 1] + 5, 10) - 5, 0, atol=1e-12)


def test_the_temperature_is_in_the_run_s_units(tmp_path):
    """metal: theta = k_B T / (m mvv2e) = 8.617333e-5 * 300 / (39.95 * 1.0364269e-4) (A/ps)^2."""
    x, v = collide(tmp_path, "diffusive 99 xlo 0 300 0 0 0 units box", mass=39.95, units="metal", dt=0.01)
    theta = 8.617333262e-5 * 300 / (39.95 * 1.0364269e-4)
    assert within(v[:, 0] ** 2, 2 * theta, 2 * theta)
    assert within(v[:, 2] ** 2, theta, math.sqrt(2) * theta)


def test_maxwell_walls_reflect_a_share_one_minus_alpha_specularly(tmp_path):
    """alpha = 0.3: 70 % leave specularly, v = (1, 0.25, -0.125) exactly; the rest diffusely."""
    x, v = collide(tmp_path, "maxwell 77 xlo 0 1.5 0 0 0 0.3 units box")
    specular = np.all(v == [1.0, 0.25, -0.125], axis=1)
    share = specular.mean()
    assert abs(share - 0.7) < 5 * math.sqrt(0.7 * 0.3 / N)
    np.testing.assert_array_equal(x[specular, 0], 0.5)
    diffuse = v[~specular]
    sigma = math.sqrt(0.75)
    assert ks_distance(diffuse[:, 0], rayleigh_cdf(sigma)) < 2.0 / math.sqrt(len(diffuse))
    assert ks_distance(diffuse[:, 1], normal_cdf(0.0, sigma)) < 2.0 / math.sqrt(len(diffuse))


@pytest.mark.parametrize("alpha, share", [(0.0, 1.0), (1.0, 0.0)])
def test_maxwell_limits(tmp_path, alpha, share):
    x, v = collide(tmp_path, f"maxwell 77 xlo 0 1.5 0 0 0 {alpha} units box", n=2000)
    assert np.all(v == [1.0, 0.25, -0.125], axis=1).mean() == share


def test_ccl_accommodates_each_direction_by_its_own_coefficient(tmp_path):
    """alpha = (0.4, 0.7, 0) (normal x, tangential y, z), wall velocity vy = 0.2, theta = 0.75:
    vy' normal with mean 0.2 + 0.3 (0.25 - 0.2), variance (2 - 0.7) 0.7 theta; vz kept (alpha 0);
    vx' > 0 with <vx'^2> = (1 - 0.4) vx^2 + 2 (0.4) theta."""
    x, v = collide(tmp_path, "ccl 5 xlo 0 1.5 0 0.2 0 0.4 0.7 0.0 units box")
    theta = 0.75
    assert (v[:, 0] > 0).all()
    np.testing.assert_array_equal(v[:, 2], -0.125)
    mean_y, sigma_y = 0.2 + 0.3 * 0.05, math.sqrt(1.3 * 0.7 * theta)
    assert ks_distance(v[:, 1], normal_cdf(mean_y, sigma_y)) < KS_BOUND
    assert within(v[:, 1], mean_y, sigma_y)
    second = 0.6 * 1.0 + 0.8 * theta
    # |vx'|^2 = A^2 + B^2 - 2 A B cos(phi), A^2 = 0.6 vx^2, B^2 exponential of mean 2 alpha theta
    a2, mean_b2 = 0.6, 0.8 * theta
    spread = math.sqrt(mean_b2 ** 2 + 2 * a2 * mean_b2)
    assert within(v[:, 0] ** 2, second, spread)


def test_ccl_limits_are_specular_and_diffusive(tmp_path):
    x, v = collide(tmp_path, "ccl 5 xlo 0 1.5 0 0 0 0 0 0 units box", n=2000)
    np.testing.assert_allclose(v, np.tile([1.0, 0.25, -0.125], (2000, 1)), rtol=1e-15)
    x, v = collide(tmp_path, "ccl 5 xlo 0 1.5 0 0 0 1 1 1 units box")
    sigma = math.sqrt(0.75)
    assert ks_distance(v[:, 0], rayleigh_cdf(sigma)) < KS_BOUND
    assert ks_distance(v[:, 2], normal_cdf(0.0, sigma)) < KS_BOUND


def test_a_hi_wall_sends_particles_down_and_the_seed_decides(tmp_path):
    def run(seed):
        sim = build(tmp_path, [[9.5, 5, 5], [9.6, 3, 3]], v=[[1.0, 0, 0], [2.0, 0, 0]], boundary="f p p",
                    setup=f"timestep 1\nfix 1 all nve\nfix 2 all wall/reflect/stochastic diffusive {seed} "
                          "xhi 10 1 0 0 0 units box\nrun 1")
        return sim.v[np.argsort(sim.tag)].copy()
    first = run(11)
    assert (first[:, 0] < 0).all()
    np.testing.assert_array_equal(run(11), first)
    assert not np.array_equal(run(12), first)


def test_a_particle_beyond_the_wall_without_crossing_it_is_put_on_the_wall(tmp_path):
    """At rest at x = -1, behind the wall xlo 0: no time to go back, so it starts from the wall."""
    sim = build(tmp_path, [[-1.0, 5, 5]], v=[[0.0, 0, 0]], lo=(-2, 0, 0), boundary="f p p",
                setup="fix 1 all nve\nfix 2 all wall/reflect/stochastic diffusive 3 xlo 0 1 0 0 0 units box\nrun 1")
    assert sim.x[0, 0] == 0.0 and sim.v[0, 0] > 0 and np.isfinite(sim.v).all()


def test_lattice_units_scale_the_position():
    from pdps_core.api import Simulation
    sim = Simulation(screen=False, log=None)
    sim.command("boundary f p p\nlattice sc 0.125\nregion box block 0 10 0 10 0 10 units box\ncreate_box 1 box\n"
                "fix 2 all wall/reflect/stochastic diffusive 3 xlo 1 1 0 0 0 xhi EDGE 1 0 0 0")
    assert sim.fixes["2"].coords.tolist() == [2.0, 10.0]


SETUP = "boundary f p p\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\nmass 1 1"


@pytest.mark.parametrize("line, message", [
    ("fix 1 all wall/reflect/stochastic maxwell 5 ylo EDGE 300 0 0 0",
     "wall ylo: maxwell takes one accommodation coefficient after the wall velocity (got none)"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 xlo EDGE 300 0 0 0 0.3",
     "wall xlo: diffusive takes no accommodation coefficient after the wall velocity (got 0.3)"),
    ("fix 1 all wall/reflect/stochastic ccl 5 xlo EDGE 300 0 0 0 0.3",
     "wall xlo: ccl takes three accommodation coefficients (x y z) after the wall velocity (got 0.3)"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 xlo EDGE 300 0 0", "missing argument wall xlo: vz"),
    ("fix 1 all wall/reflect/stochastic diffusive 0 xlo EDGE 300 0 0 0", "seed must be >= 1 (got 0)"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 xlo EDGE 300 1 0 0",
     "wall xlo: the wall velocity must be tangential (got vx 1)"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 xlo v_a 300 0 0 0",
     "wall xlo: coord must be a finite number or EDGE (got v_a)"),
    ("fix 1 all wall/reflect/stochastic maxwell 5 xlo EDGE 300 0 0 0 1.2",
     "wall xlo: accommodation coefficients must be from 0 to 1 (got 1.2)"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 xlo EDGE 0 0 0 0",
     "wall xlo: temperature must be > 0 for diffusive reflection (got 0)"),
    ("fix 1 all wall/reflect/stochastic ccl 5 xlo EDGE -1 0 0 0 1 1 1", "wall xlo: temperature must be >= 0 (got -1)"),
    ("fix 1 all wall/reflect/stochastic specular 5 xlo EDGE 1 0 0 0",
     "rule must be one of 'diffusive', 'maxwell' or 'ccl' (got specular)"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 xlo EDGE 1 0 0 0 units foo",
     "units must be one of 'box' or 'lattice' (got foo)"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 xlo EDGE 1 0 0 0 xlo 3 1 0 0 0", "wall xlo is given twice"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 wlo 1 1 0 0 0",
     "wall must start with one of xlo, xhi, ylo, yhi, zlo, zhi (got wlo)"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 ylo EDGE 1 0 0 0",
     "wall ylo stands on the periodic y axis: make it fixed (boundary f)"),
    ("fix 1 all wall/reflect/stochastic diffusive 5 xlo 6 1 0 0 0 xhi 4 1 0 0 0 units box",
     "xlo must be below xhi (got 6 4)"),
])
def test_bad_walls(line, message):
    assert script_error(SETUP, line).message == message


def test_a_2d_run_has_no_z_walls():
    setup = "dimension 2\nboundary f f p\nregion box block 0 10 0 10 -0.5 0.5\ncreate_box 1 box"
    assert script_error(setup, "fix 1 all wall/reflect/stochastic diffusive 5 zlo EDGE 1 0 0 0").message == \
        "wall zlo in a 2-d simulation"


GAS = """units lj
atom_style atomic
boundary f p p
lattice sc 16
region box block 0 5 0 5 0 5 units box
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.0 5511 loop geom
timestep 0.01
fix 1 all nve
compute vy all reduce ave vy
thermo_style custom step temp c_vy
thermo 100
fix 2 all wall/reflect/stochastic ccl {seed} xlo EDGE 1.0 0 0.3 0 0.6 0.8 0.8 xhi EDGE 2.0 0 -0.2 0 0.9 0.4 0.4
run 23000
unfix 2
fix 3 all wall/reflect/stochastic maxwell {seed} xlo EDGE 1.0 0 0.5 0 0.3 xhi EDGE 3.0 0 0 0 0.7
run 23000
unfix 3
fix 4 all wall/reflect/stochastic diffusive {seed} xlo EDGE 0.5 0 0 0.4 xhi EDGE 2.5 0 0 0
run 23000
"""

# LAMMPS 22 Jul 2025, this script with 8 seeds (8231 1177 90210 4242 555 31337 2718 16180): per
# rule, temp and c_vy averaged over the last 20,000 steps of its 23,000 (thermo every 100), the
# mean of the 8 runs and the standard deviation of one run's average
LAMMPS_GAS = {"ccl": ((1.42768, 0.00579), (0.17041, 0.00757)),
              "maxwell": ((2.27908, 0.02345), (0.17456, 0.00957)),
              "diffusive": ((1.16542, 0.00426), (0.00119, 0.00816))}


def test_an_ideal_gas_between_two_walls_of_each_rule_reaches_lammps_s_state(tmp_path):
    """2,000 particles without a pair style between walls at different temperatures and wall
    velocities: the gas's stationary temperature and mean vy, pdps's run (seed 8231) within 4
    standard deviations of LAMMPS's mean (the deviation of one run, and that of the 8-run mean)."""
    rows = logged_thermo(tmp_path, GAS.format(seed=8231))
    for k, rule in enumerate(("ccl", "maxwell", "diffusive")):
        start = 23000 * k
        chosen = rows[(rows[:, 0] > start + 3000) & (rows[:, 0] <= start + 23000)]
        _, first = np.unique(chosen[:, 0], return_index=True)
        chosen = chosen[first]
        assert len(chosen) == 200
        for column, (mean, std) in zip((1, 2), LAMMPS_GAS[rule]):
            assert abs(chosen[:, column].mean() - mean) < 4 * std * math.sqrt(1 + 1 / 8), (rule, column)


def test_the_same_run_on_1_and_2_ranks(tmp_path):
    """The random numbers follow particle ids, not ranks: the gas's first 1,500 steps of each rule
    on 2 ranks as on 1, to round-off."""
    script = GAS.format(seed=8231).replace("run 23000", "run 1500").replace("thermo 100", "thermo 500")
    script = script.replace("thermo_style custom step temp c_vy",
                            "thermo_style custom step temp c_vy\nthermo_modify format float %.15g")
    one, two = thermo_on_ranks(script, tmp_path)
    assert one[:, 0].tolist() == [0, 500, 1000, 1500, 1500, 2000, 2500, 3000, 3000, 3500, 4000, 4500]
    np.testing.assert_allclose(two, one, rtol=1e-9, atol=1e-12)
