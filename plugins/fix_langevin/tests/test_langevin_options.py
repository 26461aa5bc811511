"""fix langevin's omega, tally and gjf keywords: the friction laws against LAMMPS's numbers, the
bookkeeping of tally against the kinetic energy it must balance, GJF's exact configurational
sampling at a large time step, and the statistics of each keyword against LAMMPS's
(data/langevin_options.txt, recorded by benchmarks/lammps_references/langevin_options.py from the
scripts in data/, which this test runs through pdps's LAMMPS dialect as they are)."""

import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation, observables
from pdps_core.testing import run_ranks, thermo_csv, thermo_rows

DATA = Path(__file__).parent / "data"
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from langevin_options import EXACT, EXACT_CASES, FRICTION, block_mean, script  # noqa: E402

REFERENCE, THERMO = {}, {}
for _line in (DATA / "langevin_options.txt").read_text().splitlines():
    _case, _quantity, *_values = _line.split("\t")
    if _quantity == "thermo":
        THERMO.setdefault(_case, []).append([float(v) for v in _values])
    else:
        REFERENCE[(_case, _quantity)] = [float(v) for v in _values]


def lammps(text, log=None):
    sim = Simulation(screen=False, log=log, dialect="lammps")
    sim.command(text)
    return sim


def production(tmp_path, name, seed, options=""):
    """The thermo columns of the scene's production run, from its first line (which repeats the
    equilibration's last), as the recorder reads LAMMPS's."""
    log = tmp_path / f"log.{name}"
    sim = lammps(script(name, seed, options), log=log)
    sim.close()
    columns = thermo_csv(f"{log}.csv")
    first = int(np.flatnonzero(np.diff(columns["Step"]) == 0)[-1]) + 1
    return {name: values[first:] for name, values in columns.items()}


def agree(mine, reference, what):
    """Two means with standard errors agree within two combined standard errors."""
    (m, sm, _), (r, sr) = mine, reference[:2]
    bound = 2.0 * np.hypot(sm, sr)
    assert abs(m - r) < bound, f"{what}: pdps {m:.5f} +- {sm:.5f}, LAMMPS {r:.5f} +- {sr:.5f}"


# ---- omega -------------------------------------------------------------------------------------
def test_friction_and_rotational_friction_are_lammps_at_zero_temperature():
    """At T = 0 the thermostat is friction only: F = -m v / (DAMP ratio) and T = -(10/3) I omega /
    (DAMP ratio) with I = 0.4 m R^2, ``scale 2 4.0`` multiplying type 2's damping time; LAMMPS's
    forces and torques after run 0, to 15 digits."""
    sim = lammps(FRICTION.split("run 0")[0] + "run 0")
    order = np.argsort(sim.tag)
    p = sim.particles
    mine = [p.f[order[0], 0], p.f[order[1], 0], p.torque[order[0], 2], p.torque[order[1], 2]]
    np.testing.assert_allclose(mine, REFERENCE[("friction", "values")], rtol=1e-13)
    # and the formulas: type 1 (m 1, R 0.5), type 2 (m 2, R 1, ratio 4)
    np.testing.assert_allclose(mine, [-1.0 * 0.5 / 0.4, -2.0 * 0.5 / (0.4 * 4.0),
                                      -10 / 3 * 0.4 * 1.0 * 0.25 * 3.0 / 0.4,
                                      -10 / 3 * 0.4 * 2.0 * 1.0 * 3.0 / (0.4 * 4.0)], rtol=1e-14)


def test_spheres_rotate_and_move_at_the_target_as_in_lammps(tmp_path):
    """300 free spheres, T = 1.2, damp 0.5, dt 0.01, 20,000 steps after 1000 of equilibration: the
    translational temperature (N_dof = 3N - 3) and the rotational one, 2 E_rot / (3 N k_B) from
    compute erotate/sphere, each within two standard errors (20 block averages of 10 time units, 20
    damping times) of the target and of LAMMPS's means over as many steps. Measured: translational
    1.2082 +- 0.0024 (target 1.2040; LAMMPS 1.2049 +- 0.0021), rotational 1.2005 +- 0.0013 (target
    1.2; LAMMPS 1.1978 +- 0.0021)."""
    rows = {name: values[1:] for name, values in production(tmp_path, "in.spheres", 911).items()}
    translational = block_mean(rows["Temp"])
    rotational = block_mean(rows["c_rot"] * 2.0 / (3.0 * 300))
    agree(translational, (1.2 * 900 / 897, 0.0), "translational temperature vs the target")
    agree(rotational, (1.2, 0.0), "rotational temperature vs the target")
    agree(translational, REFERENCE[("omega", "temp")], "translational temperature vs LAMMPS")
    agree(rotational, REFERENCE[("omega", "rotational_temp")], "rotational temperature vs LAMMPS")


@pytest.mark.parametrize("case", list(EXACT_CASES))
def test_friction_alone_gives_lammps_thermo(tmp_path, case):
    """At T = 0 nothing is random: a 256-atom LJ crystal melting while friction (damp 0.5) drains it,
    with tally yes, gjf vhalf|vfull with tally (GJF's scaled forces, its velocities, LAMMPS's tally of
    them, which starts a gjf run at dt P_0 rather than 0) and gjf with zero yes: temp, pe, etotal and
    f_t every 25 of 100 steps as LAMMPS prints them, to 1e-9."""
    log = tmp_path / "log.exact"
    lammps(EXACT.replace("OPTIONS", EXACT_CASES[case]), log=log).close()
    columns = thermo_csv(f"{log}.csv")
    mine = np.column_stack([columns[name] for name in ("Step", "Temp", "PotEng", "TotEng", "f_t")])
    np.testing.assert_allclose(mine, np.array(THERMO[case]), rtol=1e-9, atol=1e-9)


def test_gjf_on_two_ranks_gives_lammps_thermo(tmp_path):
    """The same with gjf vfull and tally on 2 ranks (particles that cross between the sub-domains
    take GJF's velocities and noises with them): LAMMPS's serial thermo."""
    text = EXACT.replace("OPTIONS", EXACT_CASES["exact_vfull"]).replace("run 100", "processors 2 1 1\nrun 100")
    done = run_ranks(text, 2, tmp_path)
    np.testing.assert_allclose(thermo_rows(done.stdout), np.array(THERMO["exact_vfull"]), rtol=1e-9, atol=1e-9)


def test_omega_needs_finite_size_particles():
    sim = lammps("units lj\natom_style atomic\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\nmass 1 1.0")
    with pytest.raises(ScriptError) as caught:
        sim.command("fix 1 all langevin 1 1 1 5 omega yes")
    assert str(caught.value).endswith("omega yes needs finite-size particles (per-particle radius, mass, omega "
                                      "and torque): use particle_style sphere before creating the box")


# ---- tally -------------------------------------------------------------------------------------
def test_tally_balances_the_kinetic_energy_of_an_ideal_gas_to_the_step():
    """Without other forces velocity Verlet changes each particle's kinetic energy by
    dt/4 (F_n + F_n+1).(v_n + v_n+1) a step, and LAMMPS's tally counts dt/2 (F_n.v_n + F_n+1.v_n+1):
    the difference telescopes, so ke(N) - ke(0) + f_t(N) = -dt^2/8 sum_i (|F_i(N)|^2 - |F_i(0)|^2)/m_i
    exactly, after any number of steps (here 400, the gas heated from T = 0.5 to 2 while f_t falls
    by 635)."""
    sim = lammps("units lj\natom_style atomic\nregion box block 0 10 0 10 0 10\ncreate_box 2 box\n"
                 "create_atoms 1 random 150 42 box\ncreate_atoms 2 random 150 43 box\nmass 1 1.0\nmass 2 3.0\n"
                 "velocity all create 0.5 77\ntimestep 0.01\nthermo_modify norm no\n"
                 "fix t all langevin 2.0 2.0 0.2 913 tally yes zero yes scale 2 2.0\nfix 1 all nve\nrun 0")
    masses = observables.masses(sim)
    ke0 = observables.kinetic_energy(sim)
    f0 = {int(t): (row @ row) / m for t, row, m in zip(sim.tag, sim.f, masses)}
    assert sim.fix_value("t") == 0.0
    sim.command("run 400")
    f_n = {int(t): (row @ row) / m for t, row, m in zip(sim.tag, sim.f, observables.masses(sim))}
    boundary = -0.01 ** 2 / 8 * sum(f_n[t] - f0[t] for t in f0)
    exchanged = sim.fix_value("t")
    assert exchanged < -600.0
    assert observables.kinetic_energy(sim) - ke0 + exchanged == pytest.approx(boundary, abs=1e-9)
    assert sim.variables.evaluate("ecouple") == exchanged


def heating(tmp_path, tstart):
    log = tmp_path / "log.heating"
    sim = lammps(script("in.heating", 101, steps=2000, tstart=tstart), log=log)
    sim.close()
    columns = thermo_csv(f"{log}.csv")
    first = int(np.flatnonzero(np.diff(columns["Step"]) == 0)[-1]) + 1
    return {name: values[first:] for name, values in columns.items()}


def within_lammps_spread(value, reference, what):
    """One pdps run against the mean of LAMMPS's runs over ``seeds`` seeds: within two standard
    deviations of a run about that mean (the spread of one run plus the error of the mean)."""
    mean, error, seeds = reference
    bound = 2.0 * error * np.sqrt(seeds + 1)
    assert abs(value - mean) < bound, f"{what}: pdps {value:.4g}, LAMMPS {mean:.4g} +- {error:.2g} ({seeds:g} seeds)"


def test_econserve_stays_flat_while_a_liquid_is_heated(tmp_path):
    """500 LJ atoms (shifted potential) at T = 1.0 heated to 1.6 at once (dt 0.005, damp 0.1, 2000
    steps) with tally yes: the bath gives the liquid 707 energy units (f_t falls from 0 to -707;
    LAMMPS: -731 +- 9 over 16 seeds, 36 a run) while econserve = pe + ke + f_t ends within 0.83 of
    where it started (LAMMPS: +1.6 +- 0.5, 2.0 a run): flat to 0.1 % of the energy exchanged."""
    rows = heating(tmp_path, 1.6)
    exchanged = rows["f_t"][-1] - rows["f_t"][0]
    change = rows["Econserve"][-1] - rows["Econserve"][0]
    assert exchanged < -600.0
    assert abs(change) < 0.002 * abs(exchanged)
    within_lammps_spread(exchanged, REFERENCE[("tally", "f_t_change_step")], "f_t over the heating")
    within_lammps_spread(change, REFERENCE[("tally", "econserve_change_step")], "econserve over the heating")


def test_the_bath_gives_energy_at_lammps_rate_on_a_ramp(tmp_path):
    """The same liquid heated on a ramp from 1.0 to 1.6 over 2000 steps: f_t falls at -72.2 energy
    units per time unit (the slope of a line through its 101 values; LAMMPS: -70.8 +- 0.7 over 16
    seeds, 3.0 a run). On a ramp econserve does not end where it started, by the tally's own
    bookkeeping: it differs from what velocity Verlet conserves by dt^2/8 sum |F_i|^2 / m_i (see the
    ideal-gas test above), whose noise part, 3 N k_B T dt / (4 DAMP), grows with the target: by 11.25
    from 1.0 to 1.6, so econserve falls by about that. Measured over 16 seeds: pdps -11.3 +- 0.3,
    LAMMPS -9.7 +- 0.2. The difference is the start of the run: pdps's setup draws the noise of the
    step it continues (the same key), which that step's last half-kick already put into the
    velocities, so the friction and the noise in |F_0|^2 are correlated (econserve's fall grows by
    3 N k_B T dt^2 / (4 DAMP^2), 0.94 here), where LAMMPS draws afresh; with a fresh draw at setup
    pdps gives -9.9 +- 0.5. pdps keeps its draw, so that a run split in two (or restarted) goes on as
    one run would."""
    rows = heating(tmp_path, 1.0)
    slope = np.polyfit(rows["Step"] * 0.005, rows["f_t"], 1)[0]
    assert slope < -50.0
    within_lammps_spread(slope, REFERENCE[("tally", "f_t_slope")], "the rate f_t falls on the ramp")


def test_tally_restarts_with_each_run_as_lammps():
    """LAMMPS's f_ID reads 0 at the start of every run (its tally starts from the run's setup)."""
    sim = lammps("units lj\natom_style atomic\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\n"
                 "create_atoms 1 random 100 42 box\nmass 1 1.0\ntimestep 0.01\n"
                 "fix t all langevin 2.0 2.0 0.2 913 tally yes\nfix 1 all nve\nrun 100")
    assert sim.fix_value("t") < -10.0
    sim.command("run 0")
    assert sim.fix_value("t") == 0.0


# ---- gjf ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("case, options", [("gjf_no", ""), ("gjf_vhalf", "gjf vhalf"), ("gjf_vfull", "gjf vfull")])
def test_harmonic_well_at_a_large_step(tmp_path, case, options):
    """200 particles in a harmonic well along x (omega = 1) at dt = 1 (omega dt = 1), damp 1, T = 1,
    20,000 steps: GJF samples positions from Boltzmann's distribution at any stable step, so the mean
    wall energy per particle is kT/2 = 0.5 (measured 0.4989 +- 0.0014; with three other seeds 0.4973,
    0.5002, 0.4994, each +- 0.001; LAMMPS 0.4990 +- 0.0012), where the standard Langevin step gives
    0.9991 +- 0.0017, twice kT/2 (LAMMPS 1.0007 +- 0.0019). The 2GJ half-step velocity (vhalf) holds
    the kinetic temperature at T: 1.0047 +- 0.0015 for 1.0050 (N_dof = 3N - 3; LAMMPS 1.0071 +-
    0.0011); GJF's on-site velocity (vfull) reads low, 0.9211 +- 0.0011 (LAMMPS 0.9215 +- 0.0012);
    the standard step 1.0032 +- 0.0009 (LAMMPS 1.0059 +- 0.0010). Each mean agrees with LAMMPS's
    (as many steps, another seed) within two combined standard errors (20 blocks of 1000 time
    units)."""
    rows = {name: values[1:] for name, values in production(tmp_path, "in.harmonic", 11, options).items()}
    energy = block_mean(rows["f_w"] / 200)
    temp = block_mean(rows["Temp"])
    agree(energy, REFERENCE[(case, "wall_energy_per_particle")], "wall energy per particle")
    agree(temp, REFERENCE[(case, "temp")], "temperature")
    target_temp = 600 / 597
    if case == "gjf_no":
        assert energy[0] > 0.5 + 100 * energy[1]
    else:
        agree(energy, (0.5, 0.0), "wall energy per particle vs kT/2")
    if case == "gjf_vhalf":
        agree(temp, (target_temp, 0.0), "vhalf temperature vs T")
    if case == "gjf_vfull":
        assert temp[0] < target_temp - 50 * temp[1]


def test_gjf_ideal_gas_reaches_the_target():
    """Free particles (no forces) with gjf vhalf: the reported velocities' temperature is T."""
    sim = lammps("units lj\natom_style atomic\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\n"
                 "create_atoms 1 random 400 42 box\nmass 1 2.0\ntimestep 0.05\n"
                 "fix t all langevin 1.5 1.5 0.5 913 gjf vhalf\nfix 1 all nve\nrun 200")
    temps = []
    for _ in range(100):
        sim.command("run 20")
        temps.append(sim.variables.evaluate("temp"))
    mean, error = np.mean(temps), np.std(temps, ddof=1) / np.sqrt(len(temps))
    expected = 1.5 * 1200 / 1197
    assert abs(mean - expected) < 2.0 * error, (mean, expected, error)


GAS = "units lj\natom_style atomic\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\ncreate_atoms 1 random 10 4 box\nmass 1 1.0\n"


@pytest.mark.parametrize("lines, message", [
    ("fix 1 all nve\nfix t all langevin 1 1 0.5 5 gjf vhalf",
     "fix t langevin gjf must be defined before fix 1 (nve), whose steps it wraps"),
    ("fix t all langevin 1 1 0.5 5 gjf vfull",
     "fix t langevin gjf needs an integrator (fix nve, nve/sphere, nve/limit...) to move the particles; "
     "define it after this fix"),
    ("fix t all langevin 1 1 0.5 5 gjf vhalf\nfix 1 all nve\ntimestep 1.0",
     "fix t langevin gjf: DAMP must not be dt/2 (got 0.5 with timestep 1), which makes GJF's a = 0"),
])
def test_gjf_refuses_what_lammps_refuses(lines, message):
    sim = lammps(GAS + lines)
    with pytest.raises(ScriptError) as caught:
        sim.command("run 1")
    assert str(caught.value).endswith(message)


@pytest.mark.parametrize("words, message", [
    ("gjf yes", "gjf must be one of 'no', 'vfull' or 'vhalf' (got yes)"),
    ("angmom 3.333", "angmom thermostats the angular momentum of aspherical (ellipsoid) particles, which pdps "
                     "does not have (use omega yes for spheres)"),
    ("tally maybe", "tally must be yes or no (got maybe)"),
])
def test_bad_keywords(words, message):
    sim = lammps(GAS)
    with pytest.raises(ScriptError) as caught:
        sim.command(f"fix 1 all langevin 1 1 1 5 {words}")
    assert str(caught.value).endswith(message)
