"""fix property/global: each of LIGGGHTS's forms read, and bad lines refused with one line."""

import pytest

from pdps_core.api import Simulation
from pdps_core.testing import assert_refused, liggghts_one_particle

SETUP = liggghts_one_particle(2)


@pytest.mark.parametrize("line, kind, values", [
    ("fix a all property/global youngsModulus peratomtype 1e6 2e6", "per_type", [1e6, 2e6]),
    ("fix a all property/global youngsModulus atomtype 1e6 2e6", "per_type", [1e6, 2e6]),
    ("fix a all property/global youngsModulus vector 1e6 2e6", "per_type", [1e6, 2e6]),
    ("fix a all property/global characteristicVelocity scalar 2.", "scalar", [2.0]),
    ("fix a all property/global coefficientFriction peratomtypepair 2 0.1 0.2 0.2 0.3", "per_type_pair",
     [0.1, 0.2, 0.2, 0.3]),
    ("fix a all property/global coefficientFriction atomtypepair 2 0.1 0.2 0.2 0.3", "per_type_pair",
     [0.1, 0.2, 0.2, 0.3]),
    ("fix a all property/global table matrix 3 1 2 3 4 5 6", "matrix", [1, 2, 3, 4, 5, 6]),
])
def test_each_property_global_form_is_read(line, kind, values):
    sim = Simulation(screen=False, log=None)
    sim.command(SETUP + line)
    fix = sim.fixes["a"]
    assert fix.style == kind
    assert list(fix.values) == values
    assert fix.columns == (3 if kind == "matrix" else 2 if kind == "per_type_pair" else 1)



def test_the_later_of_two_fixes_of_one_name_holds():
    from pdps_granular_contact.material import read_property
    sim = Simulation(screen=False, log=None)
    sim.command(SETUP + "fix a all property/global youngsModulus peratomtype 1e6 2e6\n"
                "fix b all property/global youngsModulus peratomtype 6e6 7e6\n")
    assert list(read_property(sim, "youngsModulus", 2, "test")) == [0.0, 6e6, 7e6]


def test_scalar_with_two_values_is_refused(pdps_cli):
    assert_refused(pdps_cli(SETUP + "fix m2 all property/global poissonsRatio scalar 0.45 0.45\n"), 6,
                   "fix: poissonsRatio scalar takes one value (got 2)")


@pytest.mark.parametrize("line, message", [
    ("fix a all property/global coefficientFriction peratomtypepair 2 0.1 0.2 0.3 0.4",
     "fix: coefficientFriction peratomtypepair: the table must be symmetric (value 1,2 is 0.2, value 2,1 is 0.3)"),
    ("fix a all property/global coefficientFriction peratomtypepair 2 0.1 0.2 0.2",
     "fix: coefficientFriction peratomtypepair 2: expected 2 x 2 = 4 values (got 3)"),
    ("fix a all property/global coefficientFriction peratomtypepair two 0.1",
     "fix: values: the number of columns must be an integer (got two)"),
    ("fix a all property/global table matrix 4 1 2 3", "fix: table matrix: 3 values do not fill rows of 4 columns"),
    ("fix a all property/global youngsModulus peratomtype", "fix: youngsModulus peratomtype: expected at least "
     "one value; usage: " + "fix ID GROUP property/global NAME scalar V | vector|atomtype|peratomtype V1 V2 ... | "
     "matrix|atomtypepair|peratomtypepair N V11 ... VNN"),
    ("fix a all property/global youngsModulus peratomtype 5e6 abc",
     "fix: values must be a finite number (got abc)"),
    ("fix a all property/global youngsModulus peratomtype 5e6 inf",
     "fix: values must be a finite number (got inf)"),
    ("fix a all property/global youngsModulus perparticle 5e6",
     "fix: values must be one of scalar, vector, atomtype, peratomtype, matrix, atomtypepair, peratomtypepair "
     "(got perparticle)"),
])
def test_bad_lines(pdps_cli, line, message):
    assert_refused(pdps_cli(SETUP + line + "\n"), 6, message)


def test_property_atom_values_follow_set_and_dumps(tmp_path):
    """LIGGGHTS's property/atom: a default for every particle, set property/atom, f_NAME[k] in a
    LIGGGHTS dump (a scalar's [0] is its value, a vector's columns count from 1, as LIGGGHTS 3.8.0:
    fix_heat's heat_flux_columns case)."""
    path = tmp_path / "p.dump"
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(SETUP + "create_atoms 1 single 0.5 0.5 0.5 units box\n"
                "fix age all property/atom age scalar yes no no 7.0\n"
                "fix u all property/atom uf vector yes no no 1. 2. 3.\n"
                "set atom 2 property/atom age 9.5\n"
                f"dump d all custom 1 {path} id f_age[0] f_uf[1] f_uf[3]\nrun 0")
    rows = sorted(line.split() for line in path.read_text().splitlines()[-2:])
    assert rows == [["1", "7", "1", "3"], ["2", "9.5", "1", "3"]]


@pytest.mark.parametrize("line, message", [
    ("fix a all property/atom age scalar yes no no 1 2", "fix: age scalar takes one default value (got 2)"),
    ("fix a all property/atom age scalar yes no no", "fix: age scalar: expected the default value(s); usage: "
     "fix ID GROUP property/atom NAME scalar|vector yes|no yes|no yes|no V1 [V2 ...]"),
    ("fix a all property/atom radius scalar yes no no 1", "fix: radius is a core per-atom array, not a property a "
     "fix can make"),
    ("fix a all property/atom age scalar maybe no no 1", "fix: restart must be one of 'yes' or 'no' (got maybe)"),
])
def test_bad_property_atom_lines(pdps_cli, line, message):
    assert_refused(pdps_cli(SETUP + line + "\n"), 6, message)
