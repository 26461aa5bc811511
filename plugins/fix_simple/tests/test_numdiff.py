"""Fix numdiff: finite-difference forces of the system's energy, against the forces the pair style
computes (they agree to the difference's error), and LAMMPS's own numbers: LAMMPS 22 Jul 2025
printed NUMDIFF_LAMMPS on this machine for NUMDIFF, the largest finite-difference force component
(c_fmax) alongside the thermo; the dynamics are left as they were."""

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import script_error, thermo_rows

NUMDIFF = """units metal
atom_style atomic
atom_modify map yes
lattice fcc 5.358
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
mass 1 39.903
velocity all create 10 2357 mom yes dist gaussian
pair_style lj/cubic
pair_coeff * * 0.0102701 3.42
neighbor 1 bin
timestep 0.001
fix numdiff all numdiff 50 0.0001
fix nve all nve
variable fnx atom f_numdiff[1]
compute fmax all reduce max v_fnx
thermo_style custom step temp pe press c_fmax
thermo 50
run 200
"""
NUMDIFF_LAMMPS = [
    [0, 10, -7.0259569, 28.564278, 4.4408921e-12],
    [50, 8.5192918, -7.0054772, 68.585553, 0.014661035],
    [100, 5.0688629, -6.957754, 160.9668, 0.026861604],
    [150, 2.1269443, -6.917064, 238.6596, 0.033834409],
    [200, 1.7089493, -6.911283, 248.98142, 0.033846954],
]


def test_numdiff_prints_lammps_numbers_and_leaves_the_run_alone(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command(NUMDIFF)
    sim.close()
    rows = thermo_rows((tmp_path / "log.case").read_text())
    assert len(rows) == len(NUMDIFF_LAMMPS)
    for got, want in zip(rows, NUMDIFF_LAMMPS):
        # step 0's largest component is round-off of a perfect lattice's zero force
        assert got[:4] == pytest.approx(want[:4], rel=2e-8, abs=1e-12), want[0]
        assert got[4] == pytest.approx(want[4], rel=2e-8, abs=1e-11), want[0]


def test_finite_difference_forces_are_the_pair_forces():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(NUMDIFF.replace("run 200", "run 50"))
    p = sim.particles
    numeric = p.arrays["numdiff_numdiff"][:p.nlocal]
    assert np.abs(p.f[:p.nlocal]).max() > 0.01
    # central difference error ~ delta^2 |f''|: 1e-8 of these forces
    np.testing.assert_allclose(numeric, p.f[:p.nlocal], rtol=0, atol=1e-8)


def test_bad_numdiff_is_refused():
    setup = "dialect lammps\n" + NUMDIFF.split("fix numdiff")[0]
    assert str(script_error(setup, "fix nd all numdiff 50 0")) == (
        "<command>:1: fix: delta must be > 0 (got 0)")
