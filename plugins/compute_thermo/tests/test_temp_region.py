"""Compute temp/region and a thermostat given it: only the particles inside the region (now) count
and are rescaled, with d N - d degrees of freedom, as LAMMPS's. Over two runs, the second one with
thermo_modify temp: its rows also need the particles wrapped into the box at the run's setup, as
LAMMPS wraps them (the region test reads positions). LAMMPS 22 Jul 2025 printed TEMP_REGION_LAMMPS on
this machine for TEMP_REGION."""

import pytest

from pdps_core.api import Simulation
from pdps_core.testing import script_error, thermo_rows

TEMP_REGION = """units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 5 0 5 0 5
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.2 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
region hot block INF INF INF INF 0 2.5
compute Thot all temp/region hot
fix 1 all nve
fix 2 all temp/rescale 10 2.0 2.0 0.0 1.0
fix_modify 2 temp Thot
thermo_style custom step temp c_Thot pe etotal press
thermo 50
run 300
thermo_modify temp Thot
run 100
"""
# step temp c_Thot pe etotal press (the second run: thermo's temperature is Thot's)
TEMP_REGION_LAMMPS = [
    [0, 1.2, 1.2324688, -6.7733681, -4.9769681, -5.2243034],
    [50, 1.4406167, 2, -5.1016637, -2.9450605, 4.0420215],
    [100, 1.5986187, 2, -4.8723613, -2.4792291, 5.5422662],
    [150, 1.6902852, 2, -4.743517, -2.2131601, 6.4945094],
    [200, 1.7144872, 2, -4.6541865, -2.0875991, 6.3487038],
    [250, 1.7072856, 2, -4.666623, -2.1108166, 6.2657481],
    [300, 1.7703692, 2, -4.6365282, -1.9862855, 6.5693088],
    [300, 2, 2, -4.6365282, -3.1845282, 5.8949378],
    [350, 2, 2, -4.6397036, -3.2117036, 5.8880476],
    [400, 2, 2, -4.5582244, -3.1062244, 6.2562912],
]


def test_temp_rescale_in_a_region_prints_lammps_thermo(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command(TEMP_REGION)
    sim.close()
    rows = thermo_rows((tmp_path / "log.case").read_text())
    assert len(rows) == len(TEMP_REGION_LAMMPS)
    for got, want in zip(rows, TEMP_REGION_LAMMPS):
        assert got == pytest.approx(want, rel=2e-8, abs=1e-12), want[0]


def test_an_undefined_region_is_refused():
    setup = "dialect lammps\n" + TEMP_REGION.split("region hot")[0]
    assert str(script_error(setup, "compute T all temp/region nowhere")) == \
        "<command>:1: compute: compute temp/region: region nowhere is not defined"
