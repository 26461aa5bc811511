"""Pair styles dpd/ext and dpd/ext/tstat: with T = 0 (friction along and across the line of
centres, no noise) a run is deterministic and gives LAMMPS's thermo to every printed digit
(FRICTION_LAMMPS, TSTAT_LAMMPS: LAMMPS 22 Jul 2025 on this machine); with noise the fluid holds
its temperature and pressure as LAMMPS's does (11 LAMMPS runs of NOISY, mean and spread recorded),
and the pair forces conserve momentum to round-off."""

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import assert_prints_as_lammps, script_error, thermo_rows

FRICTION = """units lj
atom_style atomic
comm_modify vel yes
lattice fcc 3.0
region box block 0 3 0 3 0 3
create_box 2 box
create_atoms 1 box
region half block 0 1.5 INF INF INF INF
set region half type 2
displace_atoms all random 0.1 0.1 0.1 4928459
mass 1 1.0
mass 2 2.0
velocity all create 1.5 68768932
pair_style dpd/ext 0.0 1.0 3854262
pair_coeff 1 1 25.0 4.5 4.53 0.5 0.53 1.2
pair_coeff 1 2 25.1 4.51 4.54 0.51 0.54 1.21
pair_coeff 2 2 25.2 4.52 4.55 0.52 0.55 1.22
timestep 0.01
thermo_style custom step temp pe press pxy
thermo 20
fix 1 all nve
run 100
"""
FRICTION_LAMMPS = [
    [0, 1.5, 12.281822, 52.965731, 0.056304922],
    [20, 0.065247609, 12.144454, 48.679279, -0.085732247],
    [40, 0.028023001, 11.985088, 48.745457, -0.0085951195],
    [60, 0.013439921, 11.919274, 48.891583, -0.032229625],
    [80, 0.011182457, 11.864834, 49.002151, -0.059379728],
    [100, 0.00838855, 11.821287, 49.088692, -0.11168988],
]
TSTAT = """units lj
atom_style atomic
comm_modify vel yes
lattice fcc 0.8442
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 3.0 68768932
pair_style hybrid/overlay lj/cut 2.5 dpd/ext/tstat 0.0 0.0 1.5 385262
pair_coeff 1 1 lj/cut 1.0 1.0
pair_coeff 1 1 dpd/ext/tstat 2.0 1.0 0.5 0.3
timestep 0.005
thermo_style custom step temp pe press pxy
thermo 20
fix 1 all nve
run 100
"""
TSTAT_LAMMPS = [
    [0, 3, -6.7733681, -3.7126102, -0.22041778],
    [20, 0.76899692, -5.4836339, 1.5851656, -0.24575084],
    [40, 0.50223511, -5.9080783, -0.61017484, 0.081911183],
    [60, 0.3088073, -6.1191902, -1.7293103, -0.024820862],
    [80, 0.22371719, -6.3330559, -2.8701258, -0.065188411],
    [100, 0.14420638, -6.4438057, -3.603284, -0.022475738],
]


@pytest.mark.parametrize("script, lammps", [(FRICTION, FRICTION_LAMMPS), (TSTAT, TSTAT_LAMMPS)],
                         ids=["dpd_ext", "dpd_ext_tstat_overlay"])
def test_friction_alone_gives_lammps_thermo(tmp_path, script, lammps):
    assert_prints_as_lammps(tmp_path, script, lammps)


NOISY = """units lj
atom_style atomic
comm_modify vel yes
region box block 0 5 0 5 0 5
create_box 2 box
create_atoms 1 random 200 132456 box overlap 0.3
create_atoms 2 random 175 132457 box overlap 0.3
mass 1 1.0
mass 2 2.0
velocity all create 1.0 68768932
pair_style dpd/ext 1.0 1.0 ${seed}
pair_coeff 1 1 25.0 4.5 4.53 0.5 0.53 1.2
pair_coeff 1 2 25.1 4.51 4.54 0.51 0.54 1.21
pair_coeff 2 2 25.2 4.52 4.55 0.52 0.55 1.22
timestep 0.01
fix 1 all nve
run 500
reset_timestep 0
variable t equal temp
variable p equal press
fix a all ave/time 10 400 4000 v_t v_p
thermo_style custom step temp press f_a[1] f_a[2]
thermo 4000
run 4000
"""
# LAMMPS over 11 seeds: the 4000-step means of T and P, their mean and standard deviation
LAMMPS_T, LAMMPS_T_SD = 1.0010356, 0.0023992
LAMMPS_P, LAMMPS_P_SD = 50.766933, 0.12661


def test_the_noise_holds_lammps_temperature_and_pressure(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command("variable seed equal 3854262\n" + NOISY)
    sim.close()
    temperature, pressure = thermo_rows((tmp_path / "log.case").read_text())[-1][3:5]
    # one pdps run against the mean of 11 LAMMPS runs: the spread of one run and of their mean
    assert abs(temperature - LAMMPS_T) < 3.5 * LAMMPS_T_SD * np.sqrt(1 + 1 / 11)
    assert abs(pressure - LAMMPS_P) < 3.5 * LAMMPS_P_SD * np.sqrt(1 + 1 / 11)


def test_pair_forces_conserve_momentum():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(NOISY.split("run 500")[0].replace("${seed}", "4928459") + "run 50")
    p = sim.particles
    assert np.abs(p.f[:p.nlocal]).max() > 1.0
    np.testing.assert_allclose(p.f[:p.nlocal].sum(axis=0), 0.0, atol=1e-10)


SETUP = "dialect lammps\n" + FRICTION.split("pair_style")[0]


@pytest.mark.parametrize("line, message", [
    ("pair_style dpd/ext 1.0 1.0 0", "<command>:1: pair_style: seed must be >= 1 (got 0)"),
    ("pair_style dpd/ext 1.0 1.0 5\npair_coeff 1 1 25 4.5 4.5 0.5 0.5\npair_coeff 2 2 25 4.5 4.5 0.5 0.5\nrun 0",
     "<command>:4: run: pair coefficients are not set for types 1 2 (pair style dpd/ext does not mix: give "
     "pair_coeff for every type pair, as LAMMPS's)"),
    ("pair_style dpd/ext 1.0 1.0 5\npair_coeff 1 1 25 -4.5 4.5 0.5 0.5",
     "<command>:2: pair_coeff: gamma must be >= 0 (got -4.5)"),
])
def test_bad_dpd_ext_is_refused(line, message):
    assert str(script_error(SETUP, line)) == message
