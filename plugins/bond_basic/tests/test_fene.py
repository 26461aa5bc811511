"""Bond style fene: the Kremer-Grest spring and WCA core against its formula and the gradient of its
energy, LAMMPS's thermo for chains (FENE_LAMMPS, printed by LAMMPS 22 Jul 2025 on this machine for
FENE), and LAMMPS's treatment of a bond stretched beyond the spring's range (warned of and held at
1 - (r/R0)^2 = 0.1; beyond 2 R0 the run stops)."""

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation, SimulationError
from pdps_core.testing import assert_prints_as_lammps, assert_force_is_minus_gradient

DATA = Path(__file__).parent / "data"

PAIR = """two beads, one bond

2 atoms
1 atom types
1 bonds
1 bond types

0 10 xlo xhi
0 10 ylo yhi
0 10 zlo zhi

Masses

1 1.0

Atoms # bond

1 1 1 5.0 5.0 5.0
2 1 1 {x2} 5.2 4.9

Bonds

1 1 1 2
"""


def pair(tmp_path, x2, lines="run 0"):
    (tmp_path / "pair.data").write_text(PAIR.format(x2=x2))
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"atom_style bond\nread_data {tmp_path / 'pair.data'}\npair_style zero 4.0\npair_coeff * *\n"
                "bond_style fene\nbond_coeff 1 30.0 1.5 1.2 0.9\nthermo_modify norm no\n" + lines)
    return sim


def fene_energy(r, k=30.0, r0=1.5, epsilon=1.2, sigma=0.9):
    e = -0.5 * k * r0 * r0 * math.log(max(1.0 - (r / r0) ** 2, 0.1))
    if r < 2 ** (1 / 6) * sigma:
        e += 4 * epsilon * ((sigma / r) ** 12 - (sigma / r) ** 6) + epsilon
    return e


@pytest.mark.parametrize("x2", [5.85, 6.1], ids=["core and spring", "spring alone"])
def test_fene_energy_and_forces_are_its_formula(tmp_path, x2):
    sim = pair(tmp_path, x2)
    r = math.dist((5.0, 5.0, 5.0), (x2, 5.2, 4.9))
    assert sim.variables.evaluate("ebond") == pytest.approx(fene_energy(r), rel=1e-13)
    assert_force_is_minus_gradient(sim, rel=1e-6, abs=1e-7, largest=1.0)


def test_a_stretched_bond_is_warned_of_and_held_as_lammps(tmp_path):
    x2 = 6.45                                   # r = 1.47 > sqrt(0.9) 1.5 = 1.42
    sim = pair(tmp_path, x2)
    r = math.dist((5.0, 5.0, 5.0), (x2, 5.2, 4.9))
    assert sim.variables.evaluate("ebond") == pytest.approx(-0.5 * 30 * 1.5 ** 2 * math.log(0.1), rel=1e-13)
    f1 = sim.f[list(sim.tag).index(1)]
    separation = np.array([5.0 - x2, -0.2, 0.1])
    np.testing.assert_allclose(f1, -30.0 / 0.1 * separation, rtol=1e-13)
    assert sim.warnings[-1] == ("bond style fene: 1 bonds longer than sqrt(0.9) R0 (their springs are taken at "
                                "that length, as LAMMPS's) at step 0")
    assert r > math.sqrt(0.9) * 1.5


def test_a_bond_beyond_twice_its_range_stops_the_run(tmp_path):
    with pytest.raises(SimulationError) as stopped:
        pair(tmp_path, 8.2)
    assert str(stopped.value) == ("<command>:8: run: bond style fene: the bond of particles 1 and 2 is 3.2078 long at step 0, beyond "
                                  "2 R0, where the FENE spring is undefined (LAMMPS's Bad FENE bond)")


FENE = """units lj
atom_style bond
read_data {data}
pair_style soft 1.122462048309373
comm_modify cutoff 2.5
pair_coeff * * 5.0
bond_style fene
bond_coeff 1 30.0 1.5 1.0 1.0
bond_coeff 2 25.0 1.6 1.0 0.95
special_bonds fene
velocity all create 1.0 87287 loop geom
fix 1 all nve
timestep 0.005
thermo_style custom step temp pe ebond epair etotal press
thermo 50
run 300
"""
FENE_LAMMPS = [
    [0, 1, 17.884735, 17.751328, 0.13340701, 19.37536, 0.20392335],
    [50, 1.9068618, 16.486668, 16.428919, 0.057748898, 19.329084, -0.091798197],
    [100, 1.8054589, 16.640452, 16.629027, 0.011424756, 19.331714, -0.073363579],
    [150, 1.8539919, 16.566582, 16.557682, 0.0088998005, 19.330188, 0.04010764],
    [200, 1.6929512, 16.811135, 16.773862, 0.037272675, 19.33469, 0.011760599],
    [250, 1.7481962, 16.725547, 16.634761, 0.090786852, 19.331452, -0.044379019],
    [300, 1.8674437, 16.547347, 16.487416, 0.059931316, 19.331005, 0.0033217847],
]


def test_fene_chains_print_lammps_thermo(tmp_path):
    shutil.copy(DATA / "chains.data", tmp_path)
    assert_prints_as_lammps(tmp_path, FENE.format(data=tmp_path / "chains.data"), FENE_LAMMPS)
