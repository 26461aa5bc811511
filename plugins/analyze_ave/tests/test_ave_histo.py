"""Fix ave/histo (LIGGGHTS 3.8.0's numbers, thermo and files: plugins/analyze_ave/tests/data/
liggghts.cases.json, case ave_histo): a histogram worked out here by hand, and the values it
refuses, each a one-line error."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

SCENE = """
units lj
atom_style atomic
region box block 0 10 0 10 0 10
create_box 1 box
mass 1 1.0
create_atoms 1 single 1.0 1 1
create_atoms 1 single 2.5 1 1
create_atoms 1 single 2.6 1 1
create_atoms 1 single 9.5 1 1
create_atoms 1 single 4.0 1 1
"""


def test_counts_shares_and_what_falls_outside():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SCENE + "fix h all ave/histo 1 1 1 0.0 4.0 4 x mode vector\n"
                        "fix e all ave/histo 1 1 1 0.0 4.0 4 x mode vector beyond extra\nrun 0")
    # x = 1.0, 2.5, 2.6, 4.0 in [0, 4] (4.0 in the last bin), 9.5 missing
    np.testing.assert_array_equal(sim.fixes["h"].vector(sim), [4, 1, 1.0, 9.5])
    np.testing.assert_array_equal(sim.fixes["h"].array(sim), [[0.5, 0, 0], [1.5, 1, 0.25], [2.5, 2, 0.5],
                                                            [3.5, 1, 0.25]])
    # extra: bins at lo and hi hold what falls outside, and everything counts
    np.testing.assert_array_equal(sim.fixes["e"].array(sim)[:, 1], [0, 0, 1, 2, 1, 1])
    assert sim.fixes["e"].vector(sim)[0] == 5


@pytest.mark.parametrize("line, message", [
    ("fix h all ave/histo 1 1 1 4.0 0.0 4 x mode vector", "lo must be below hi (got 4 0)"),
    ("fix h all ave/histo 1 1 1 0.0 4.0 4 x", "per-atom and local values are histogrammed in mode vector"),
    ("fix h all ave/histo 1 1 1 0.0 4.0 4 speed mode vector", "value must be x, y, z, vx, vy, vz, fx, fy, fz"),
    ("fix h all ave/histo 1 1 1 0.0 4.0 4 c_none mode vector", "compute none is not defined (value c_none)"),
    ("fix h all ave/histo 1 1 1 0.0 4.0 4 x mode vector ave window 0", "ave window M needs M >= 1 (got 0)"),
])
def test_refused_values_are_one_line(line, message):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SCENE)
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert message in error.value.message
