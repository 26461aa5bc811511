"""fix langevin: the ramp, the fluctuation-dissipation balance, and an LJ liquid held on a ramp."""

import numpy as np
import pytest

from pdps_core.api import observables
from pdps_core.testing import build, thermo_csv


def fcc(cells, density):
    a = (4.0 / density) ** (1.0 / 3.0)
    basis = np.array([[0, 0, 0], [0.5, 0.5, 0], [0.5, 0, 0.5], [0, 0.5, 0.5]])
    grid = np.mgrid[0:cells, 0:cells, 0:cells].reshape(3, -1).T
    return ((grid[:, None, :] + basis[None]) * a).reshape(-1, 3), cells * a


def sample_temperature(sim, samples, every):
    temps = []
    for _ in range(samples):
        sim.command(f"run {every}")
        temps.append(observables.temperature(sim))
    return np.array(temps)


def test_target_follows_the_ramp_from_the_first_to_the_last_step_of_each_run(tmp_path):
    sim = build(tmp_path, [[1.0, 1.0, 1.0]], setup="fix 1 all nve\nfix t all langevin 1.0 3.0 0.5 7\nrun 100")
    assert sim.fix_value("t") == 3.0
    sim.command("run 0")
    assert sim.fix_value("t") == 1.0      # a new run starts again at T_START, as LAMMPS's ramp
    sim.command("run 40")
    assert sim.fix_value("t") == 3.0


def test_ideal_gas_equilibrates_at_the_target(tmp_path):
    """Without pair forces each velocity component is an Ornstein-Uhlenbeck process whose stationary
    variance is kT/m: the kinetic temperature is T times 3N/(3N-3), the N_dof thermo divides by."""
    n = 400
    x = np.random.default_rng(3).uniform(0.0, 10.0, size=(n, 3))
    sim = build(tmp_path, x, setup="mass 1 2.0\ntimestep 0.01\nfix 1 all nve\n"
                                   "fix t all langevin 2.0 2.0 0.5 91\nrun 500")
    temps = sample_temperature(sim, 200, 50)     # 50 steps = 2 relaxation times of the kinetic energy
    expected = 2.0 * 3 * n / (3 * n - 3)
    error = temps.std(ddof=1) / np.sqrt(len(temps))
    assert abs(temps.mean() - expected) < 2.0 * error, (temps.mean(), expected, error)


def test_lj_liquid_stays_on_a_temperature_ramp(tmp_path):
    """An LJ liquid (density 0.8, 500 atoms) heated from T = 1.0 to 1.6 over 40 time units: block
    means of the kinetic temperature follow the ramp (its value at each thermo line, f_heat), the
    mean offset and the slope within two standard errors (the thermostat's lag, rate x damp/2 =
    0.0008, is far below them)."""
    x, length = fcc(5, 0.8)
    n = len(x)
    sim = build(tmp_path, x, hi=(length,) * 3, log=tmp_path / "log.ramp", setup="""
        pair_style lj/cut 2.5
        pair_coeff 1 1 1.0 1.0
        velocity all create 1.0 4928 dist gaussian
        timestep 0.005
        thermo 20
        thermo_style custom step temp f_heat
        fix 1 all nve
        fix heat all langevin 1.0 1.0 0.1 2207
        run 1000
        fix heat all langevin 1.0 1.6 0.1 2207
        run 8000
    """)
    sim.close()
    rows = thermo_csv(tmp_path / "log.ramp.csv")
    # the heating run's lines after its first (steps 1020 ... 9000)
    temp, target = rows["Temp"][-400:], rows["f_heat"][-400:]
    assert rows["Step"][-400] == 1020
    assert target[0] == pytest.approx(1.0 + 0.6 * 20 / 8000) and target[-1] == 1.6
    # blocks of 20 thermo lines = 2 time units, many relaxation times of the kinetic energy
    blocks = len(temp) // 20
    measured = temp[: blocks * 20].reshape(blocks, 20).mean(axis=1)
    expected = target[: blocks * 20].reshape(blocks, 20).mean(axis=1) * 3 * n / (3 * n - 3)
    offset = measured - expected
    error = offset.std(ddof=1) / np.sqrt(blocks)
    assert abs(offset.mean()) < 2.0 * error, (offset.mean(), error)
    slope, intercept = np.polyfit(expected, measured, 1)
    residual = measured - (slope * expected + intercept)
    slope_error = residual.std(ddof=2) / np.sqrt(((expected - expected.mean()) ** 2).sum())
    assert abs(slope - 1.0) < 2.0 * slope_error, (slope, slope_error)
    assert measured[-1] > measured[0] + 0.4        # it did heat up


def test_metal_units_thermostat_to_the_target():
    """In metal units (ftm2v != 1) the friction and noise are in force units: an ideal gas reaches T."""
    import numpy as np
    from pdps_core.api import Simulation
    sim = Simulation(screen=False, log=None)
    sim.command("units metal\nregion box block 0 30 0 30 0 30\ncreate_box 1 box\nmass 1 40.0\n"
                "create_particle 1 random 400 5 box\nfix 1 all nve\nfix 2 all langevin 300 300 0.1 77\n"
                "timestep 0.002\nrun 500")
    temps = []
    for _ in range(20):
        sim.command("run 50")
        temps.append(sim.variables.evaluate("temp"))
    mean, error = np.mean(temps), np.std(temps) / np.sqrt(len(temps))
    assert abs(mean - 300.0) < max(3 * error, 6.0), (mean, error)


def test_scale_multiplies_the_damping_time_per_type():
    """At T = 0 the thermostat is pure friction: F = -m v / (damp * ratio) (LAMMPS's scale: a ratio of
    4 makes the relaxation four times slower)."""
    import numpy as np
    from pdps_core.api import Simulation
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 10 0 10 0 10\ncreate_box 2 box\nmass 1 1.0\nmass 2 2.0\n"
                "create_particle 1 single 2 2 2\ncreate_particle 2 single 6 6 6\nvelocity all set 0.5 0 0\n"
                "fix 1 all langevin 0 0 0.4 9 scale 2 4.0\nrun 0")
    order = np.argsort(sim.tag)
    np.testing.assert_allclose(sim.f[order, 0], [-1.0 * 0.5 / 0.4, -2.0 * 0.5 / (0.4 * 4.0)], rtol=1e-14)


def test_zero_yes_adds_no_net_momentum():
    import numpy as np
    from pdps_core.api import Simulation
    from pdps_core.testing import total_momentum
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 10 0 10 0 10\ncreate_box 1 box\nmass 1 1.0\n"
                "create_particle 1 random 200 3 box\nfix 1 all nve\nfix 2 all langevin 1.0 1.0 0.5 17 zero yes\n"
                "run 200")
    assert np.abs(total_momentum(sim)).max() < 1e-10
    assert sim.variables.evaluate("temp") > 0.5


def test_langevin_keywords_pdps_refuses():
    import pytest as _pytest
    from pdps_core.api import ScriptError, Simulation
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 10 0 10 0 10\ncreate_box 1 box\nmass 1 1.0")
    with _pytest.raises(ScriptError, match="angmom thermostats the angular momentum of aspherical"):
        sim.command("fix 1 all langevin 1 1 1 5 angmom 3.333")
    sim.command("fix 1 all langevin 1 1 1 5 angmom no")
