"""Fix vector: the rows it stores and what slope(), trap() make of them, against LAMMPS 22 Jul 2025
on this machine (FIX_VECTOR_LAMMPS: its thermo over two runs of FIX_VECTOR; at step 0 the slope of
one stored value is LAMMPS's 1e20, over 4 x 10 dt)."""

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import script_error, thermo_rows

FIX_VECTOR = """units lj
dimension 2
atom_style atomic
lattice sq2 0.6
region box block 0 8 0 8 -0.1 0.1
create_box 1 box
create_atoms 1 box
pair_style lj/cut 2.5
pair_coeff * * 1 1
mass * 1.0
velocity all create 1.0 97287
fix 1 all nve
fix 3 all enforce2d
compute msd all msd com yes
compute vacf all vacf
fix 9 all vector 10 c_msd[4]
fix 5 all vector 5 c_vacf[4] c_msd[4]
variable fitslope equal slope(f_9)/4/(10*dt)
variable total equal trap(f_9)
thermo_style custom step temp c_msd[4] v_fitslope v_total
thermo 50
run 200
run 100
"""
FIX_VECTOR_LAMMPS = [
    [0, 1, 9.3677232e-31, 5e+20, 0],
    [50, 0.93067869, 0.076630145, 0.078916139, 0.1553302],
    [100, 0.87142974, 0.20911774, 0.10893233, 0.8667613],
    [150, 0.96164253, 0.34401858, 0.11972937, 2.2348339],
    [200, 1.0527391, 0.48665449, 0.12745176, 4.3150949],
    [200, 1.0527391, 0.48665449, 0.12745176, 4.3150949],
    [250, 0.94631506, 0.64348437, 0.13362361, 7.1447627],
    [300, 1.0180555, 0.75820331, 0.13505598, 10.652866],
]


def test_fix_vector_gives_lammps_slope_and_trap(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command(FIX_VECTOR)
    rows = thermo_rows((tmp_path / "log.case").read_text())
    assert len(rows) == len(FIX_VECTOR_LAMMPS)
    for got, want in zip(rows, FIX_VECTOR_LAMMPS):
        assert got == pytest.approx(want, rel=2e-8, abs=1e-20), want[0]
    # rows at 0, 10, ..., 300 once each (the second run's setup at step 200 adds none); the
    # two-value fix's array has a row every 5 steps, its second column the msd of the same steps
    assert len(sim.fixes["9"].vector(sim)) == 31
    table = sim.fixes["5"].array(sim)
    assert table.shape == (61, 2)
    assert np.array_equal(table[::2, 1], sim.fixes["9"].vector(sim))
    assert sim.fix_value("5", (3, 2)) == table[2, 1]
    sim.close()


SETUP = "dialect lammps\n" + FIX_VECTOR.split("fix 9")[0]


@pytest.mark.parametrize("line, message", [
    ("fix 9 all vector 0 c_msd[4]", "<command>:1: fix: every must be >= 1 (got 0)"),
    ("fix 9 all vector 10 msd", "<command>:1: fix: value msd: expected c_ID, c_ID[i], f_ID, f_ID[i] or v_NAME"),
    ("fix 9 all vector 10 c_nothere\nrun 10", "<command>:2: run: compute nothere is not defined"),
    ("fix 9 all vector 10 c_vacf[4] c_msd[4]\nvariable s equal slope(f_9)\nthermo_style custom step v_s\nrun 10",
     "<command>:4: run: fix 9 vector stores several values, an array: read f_9[i][j]"),
])
def test_bad_vectors_are_refused(line, message):
    assert str(script_error(SETUP, line)) == message


# trap() and sum() of one column of a global array (fix ave/correlate's), f_ID[i] with i from 1 as in
# LAMMPS's VISCOSITY/in.gk.2d: LAMMPS 22 Jul 2025's thermo for ARRAY_COLUMN, recorded here
ARRAY_COLUMN = """units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
fix 1 all nve
variable pxy equal pxy
variable pxz equal pxz
fix SS all ave/correlate 1 10 50 v_pxy v_pxz type auto ave running
variable t3 equal trap(f_SS[3])
variable t4 equal trap(f_SS[4])
variable s2 equal sum(f_SS[2])
thermo_style custom step temp press v_t3 v_t4 v_s2
thermo 50
run 200
"""
ARRAY_COLUMN_LAMMPS = [
    [0, 1.5, -4.9739638, 0.0020464704, 0.00034919745, 1],
    [50, 0.73570063, 0.73267385, 0.32740632, 0.12719806, 465],
    [100, 0.75591871, 0.55560942, 0.3572215, 0.71486064, 965],
    [150, 0.81591063, 0.18402571, 0.32777378, 1.2009902, 1465],
    [200, 0.75459308, 0.52830868, 0.27473244, 1.0071481, 1965],
]


def test_special_functions_read_a_column_of_an_array_as_lammps(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command(ARRAY_COLUMN)
    sim.close()
    rows = thermo_rows((tmp_path / "log.case").read_text())
    assert len(rows) == len(ARRAY_COLUMN_LAMMPS)
    for got, want in zip(rows, ARRAY_COLUMN_LAMMPS):
        assert got == pytest.approx(want, rel=2e-8, abs=1e-20), want[0]
