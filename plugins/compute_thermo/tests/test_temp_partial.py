"""Compute temp/partial and a thermostat given it (fix_modify ID temp CID on fix temp/rescale): the
components it leaves out are kept out of the temperature, its degrees of freedom and the rescaling,
as LAMMPS's. LAMMPS 22 Jul 2025 printed TEMP_PARTIAL_LAMMPS on this machine for TEMP_PARTIAL: a 2d
LJ crystal with a shear ramp in vx that only vy's temperature, rescaled to 0.2, must leave alone."""

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import script_error, thermo_rows

TEMP_PARTIAL = """dimension 2
units lj
atom_style atomic
lattice hex 0.9
region box block 0 12 0 8 -0.5 0.5
create_box 2 box
create_atoms 1 box
mass * 1.0
region top block INF INF 6 INF INF INF
set region top type 2
group mobile type 1
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
compute new mobile temp/partial 0 1 0
velocity all create 0.5 482748
velocity mobile ramp vx 0.0 1.0 y 0 8 sum yes
fix 1 all nve
fix 2 all enforce2d
fix 3 mobile temp/rescale 20 0.2 0.2 0.01 1.0
fix_modify 3 temp new
thermo_style custom step temp c_new ke pe etotal press
thermo_modify temp new
thermo 20
run 200
"""
# step temp c_new ke pe etotal press
TEMP_PARTIAL_LAMMPS = [
    [0, 0.461308, 0.461308, 0.17178918, -3.2864505, -3.1146613, -1.442934],
    [20, 0.2, 0.2, 0.074479167, -2.9320651, -2.8575859, 1.3631233],
    [40, 0.2, 0.2, 0.074479167, -2.9895983, -2.9151191, 0.8700263],
    [60, 0.2, 0.2, 0.074479167, -3.0160928, -2.9416136, 0.67370218],
    [80, 0.2, 0.2, 0.074479167, -3.0220033, -2.9475242, 0.63131253],
    [100, 0.2085665, 0.2085665, 0.077669296, -3.0306863, -2.953017, 0.57306657],
    [120, 0.2, 0.2, 0.074479167, -3.0523268, -2.9778477, 0.38370018],
    [140, 0.2, 0.2, 0.074479167, -3.0362167, -2.9617376, 0.50130633],
    [160, 0.2, 0.2, 0.074479167, -3.0508221, -2.9763429, 0.40603441],
    [180, 0.2, 0.2, 0.074479167, -3.0358106, -2.9613314, 0.5206376],
    [200, 0.2, 0.2, 0.074479167, -3.042064, -2.9675848, 0.47569572],
]


def test_temp_rescale_with_a_partial_temperature_prints_lammps_thermo(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command(TEMP_PARTIAL)
    sim.close()
    rows = thermo_rows((tmp_path / "log.case").read_text())
    assert len(rows) == len(TEMP_PARTIAL_LAMMPS)
    for got, want in zip(rows, TEMP_PARTIAL_LAMMPS):
        assert got == pytest.approx(want, rel=2e-8, abs=1e-12), want[0]


# fix temp/berendsen 0.2 0.2 0.5 instead of temp/rescale, the rest as TEMP_PARTIAL: LAMMPS's thermo
BERENDSEN_LAMMPS = [
    [0, 0.461308, 0.461308, 0.17178918, -3.2864505, -3.1146613, -1.442934],
    [20, 0.13260636, 0.13260636, 0.049382057, -2.9364484, -2.8870663, 1.3061072],
    [40, 0.21427063, 0.21427063, 0.07979349, -3.0123891, -2.9325956, 0.69335239],
    [60, 0.24310809, 0.24310809, 0.09053244, -3.0275691, -2.9370367, 0.5988406],
    [80, 0.26023334, 0.26023334, 0.096909812, -3.017284, -2.9203742, 0.68681114],
    [100, 0.23052869, 0.23052869, 0.085847924, -3.0164666, -2.9306187, 0.68442955],
    [120, 0.26586265, 0.26586265, 0.099006142, -3.0370787, -2.9380725, 0.52483273],
    [140, 0.23984446, 0.23984446, 0.089317077, -3.0179024, -2.9285853, 0.65025774],
    [160, 0.24362544, 0.24362544, 0.0907251, -3.0275691, -2.936844, 0.60528137],
    [180, 0.24118207, 0.24118207, 0.089815198, -3.0257633, -2.9359481, 0.62362299],
    [200, 0.23153094, 0.23153094, 0.086221156, -3.0165826, -2.9303614, 0.68251917],
]


def test_temp_berendsen_with_a_partial_temperature_prints_lammps_thermo(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command(TEMP_PARTIAL.replace("fix 3 mobile temp/rescale 20 0.2 0.2 0.01 1.0",
                                     "fix 3 mobile temp/berendsen 0.2 0.2 0.5"))
    sim.close()
    rows = thermo_rows((tmp_path / "log.case").read_text())
    assert len(rows) == len(BERENDSEN_LAMMPS)
    for got, want in zip(rows, BERENDSEN_LAMMPS):
        assert got == pytest.approx(want, rel=2e-8, abs=1e-12), want[0]


def test_partial_temperature_counts_only_its_components():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(TEMP_PARTIAL.replace("run 200", "run 0"))
    p = sim.particles
    n = p.nlocal
    mobile = sim.groups.select(sim, "mobile")
    vy = p.v[:n][mobile, 1]
    # 2d: 2 N - 2 for the group, one component of two: (2 N - 2) / 2
    dof = (2 * mobile.sum() - 2) / 2
    assert sim.compute_value("new") == pytest.approx(float(np.sum(vy * vy)) / dof, rel=1e-12)
    assert sim.computes["new"].dof(sim) == dof


@pytest.mark.parametrize("line, message", [
    ("compute bad mobile temp/partial 0 2 0", "<command>:1: compute: yflag must be <= 1 (got 2)"),
    ("compute bad mobile temp/partial 0 0 1",
     "<command>:1: compute: zflag 1 in a 2d simulation, which has no z velocity"),
    ("fix_modify 3 temp nothere", "<command>:1: fix_modify: compute nothere is not defined (temperature of fix 3)"),
    ("compute pe all pe\nfix_modify 3 temp pe",
     "<command>:2: fix_modify: compute pe (pe) is not a temp compute, so it gives no temperature"),
])
def test_bad_partial_temperatures_are_refused(line, message):
    setup = "dialect lammps\n" + TEMP_PARTIAL.split("thermo_style")[0].replace("fix_modify 3 temp new\n", "")
    assert str(script_error(setup, line)) == message


def test_a_temperature_of_another_group_is_warned_of(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command(TEMP_PARTIAL.replace("fix_modify 3 temp new", "compute whole all temp/partial 0 1 0\nfix_modify 3 temp whole")
                .replace("run 200", "run 0"))
    sim.close()
    assert ("WARNING: fix 3 temp/rescale: temperature compute whole is of group all, not the fix's mobile "
            "(LAMMPS's fix_modify warns so too)") in (tmp_path / "log.case").read_text()
