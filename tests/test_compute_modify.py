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


@pytest.mark.parametrize("line, message", [
    ("compute_modify thermo_temp dynamic no",
     "dynamic no is not supported: pdps counts a temperature's particles each time it is read (LAMMPS's dynamic yes)"),
    ("compute_modify thermo_temp extra/dof 0", "extra/dof 0 is not supported for thermo_temp: it removes the 3 "
     "degrees of freedom of the centre of mass (LAMMPS's default); define a compute temp and set it there"),
    ("compute_modify nothing dynamic yes", "compute nothing is not defined"),
    ("compute_modify t dynamic", "expected an ID and keyword/value pairs; usage: compute_modify ID [dynamic yes] "
     "[dynamic/dof yes] [extra/dof N]"),
])
def test_what_pdps_cannot_do_is_one_line(pdps_cli, line, message):
    assert_refused(pdps_cli(SETUP + line + "\n"), 9, f"compute_modify: {message}")
