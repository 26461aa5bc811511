"""compute_modify (LAMMPS, used by LIGGGHTS scripts): dynamic yes accepted for thermo's temperature
and a temp compute (pdps recounts a group each time), extra/dof of a temp compute, what pdps cannot
do refused by line."""

import pytest

from pdps_core.api import Simulation, observables
from pdps_core.testing import assert_refused

SETUP = """\
units lj
atom_style atomic
region r block 0 5 0 5 0 5
create_box 1 r
create_atoms 1 single 1 1 1
create_atoms 1 single 2 2 2
mass 1 1.0
compute t all temp
"""


def test_dynamic_yes_counts_particles_inserted_during_a_run():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SETUP + "compute_modify thermo_temp dynamic yes\ncompute_modify t dynamic/dof yes extra/dof 3\n"
                "velocity all set 1 0 0\nrun 0")
    # two particles moving together: 6 - 3 dof, KE 1
    assert observables.temperature(sim) == pytest.approx(2 * 1.0 / 3, rel=1e-15)
    sim.command("create_atoms 1 single 3 3 3\nrun 0")
    assert observables.degrees_of_freedom(sim) == 6


def test_extra_dof_sets_what_a_temp_compute_takes_off():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SETUP + "compute_modify t extra/dof 0\nvelocity all set 1 0 0\nrun 0")
    # two particles of mass 1 at unit speed: KE 1 over all 6 degrees of freedom
    assert sim.compute_value("t") == pytest.approx(2 * 1.0 / 6, rel=1e-15)
    assert observables.temperature(sim) == pytest.approx(2 * 1.0 / 3, rel=1e-15)


LJ_CRYSTAL = """\
units lj
lattice fcc 0.8442
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
fix 1 all nve
compute_modify thermo_temp extra/dof 0
thermo_style custom step temp ke press etotal
thermo 10
run 20
"""
# LAMMPS 22 Jul 2025 on this machine, the script above (%20.15g): temp, ke, press, etotal at 0, 10, 20
LAMMPS_EXTRA_DOF_0 = [
    (1.48611111111111, 2.22916666666667, -4.98074227008559, -4.54420138658623),
    (1.16477332394566, 1.74715998591849, -2.45684768334709, -4.54494549805407),
    (0.657891869979291, 0.986837804968936, 1.18404584704705, -4.54924919233268),
]


def test_extra_dof_of_thermo_temp_gives_lammps_thermo():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(LJ_CRYSTAL.replace("run 20", "run 0"))
    assert sim.output.thermo.values()[1:] == pytest.approx(LAMMPS_EXTRA_DOF_0[0], rel=1e-13)
    # 108 particles at 1.5 over 321 degrees of freedom (velocity create's), read over 324
    assert sim.output.thermo.values()[1] == pytest.approx(1.5 * 321 / 324, rel=1e-14)
    for k, steps in enumerate((10, 10)):
        sim.command(f"run {steps}")
        assert sim.output.thermo.values()[1:] == pytest.approx(LAMMPS_EXTRA_DOF_0[k + 1], rel=1e-9)


@pytest.mark.parametrize("line, message", [
    ("compute_modify thermo_temp dynamic no",
     "dynamic no is not supported: pdps counts a temperature's particles each time it is read (LAMMPS's dynamic yes)"),
    ("compute_modify thermo_press extra/dof 0", "extra/dof 0 is not supported for thermo_press: it takes no "
     "degrees of freedom off"),
    ("compute_modify nothing dynamic yes", "compute nothing is not defined"),
    ("compute_modify t dynamic", "expected an ID and keyword/value pairs; usage: compute_modify ID [dynamic yes] "
     "[dynamic/dof yes] [extra/dof N]"),
])
def test_what_pdps_cannot_do_is_one_line(pdps_cli, line, message):
    assert_refused(pdps_cli(SETUP + line + "\n"), 9, f"compute_modify: {message}")
