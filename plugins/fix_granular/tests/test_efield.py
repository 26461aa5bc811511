"""fix efield: F = q E qe2f on each charged particle of the group (in the region), per component a
number, an equal-style or an atom-style variable; what it needs, one line each. (LIGGGHTS 3.8.0's
thermo with it: the recorded case efield, data/liggghts.cases.json.)"""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

SETUP = """units {units}
atom_style charge
boundary f f f
region box block 0 10 0 10 0 10
create_box 1 box
mass 1 1.0
create_atoms 1 single 2 5 5 units box
create_atoms 1 single 7 5 5 units box
set atom 1 charge 0.5
set atom 2 charge -2.0
"""


def forces(units, fix):
    sim = Simulation(screen=False, log=None)
    sim.command(SETUP.format(units=units) + fix + "\nrun 0")
    order = np.argsort(sim.particles.tag[:2])
    return sim.particles.f[:2][order]


def test_the_force_is_q_e_in_each_unit_system():
    np.testing.assert_allclose(forces("lj", "fix e all efield 1.0 -2.0 0.5"), [[0.5, -1.0, 0.25], [-2.0, 4.0, -1.0]])
    # real units: kcal/mol-Angstrom from e V/Angstrom, LAMMPS's qe2f
    np.testing.assert_allclose(forces("real", "fix e all efield 1.0 0.0 0.0")[:, 0], [0.5 * 23.060549, -2.0 * 23.060549])


def test_variables_and_region():
    f = forces("lj", "variable ez equal 3.0\nvariable ey atom 0.1*x\nregion right block 5 INF INF INF INF INF\n"
                     "fix e all efield 0.0 v_ey v_ez region right")
    np.testing.assert_allclose(f, [[0.0, 0.0, 0.0], [0.0, -2.0 * 0.7, -2.0 * 3.0]])


@pytest.mark.parametrize("fix, message", [
    ("fix e all efield 1.0 0.0", "missing argument ez; usage: fix ID GROUP efield EX EY EZ [region RID] [energy v_E]"),
    ("fix e all efield 1.0 0.0 v_none\nrun 0", "fix e (efield): variable none is not defined"),
    ("fix e all efield 1.0 0.0 0.0 region nowhere", "region nowhere is not defined (defined: box)"),
])
def test_what_it_needs_is_one_line(fix, message):
    sim = Simulation(screen=False, log=None)
    sim.command(SETUP.format(units="lj"))
    with pytest.raises(ScriptError) as error:
        sim.command(fix)
    assert str(error.value).split(": ", 2)[2] == message


def test_it_needs_charges():
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 1 0 1 0 1\ncreate_box 1 box")
    with pytest.raises(ScriptError) as error:
        sim.command("fix e all efield 1 0 0")
    assert str(error.value) == ("<command>:1: fix: fix e efield needs charges (atom_style charge or full; LAMMPS's "
                                "'requires atom attribute q')")
