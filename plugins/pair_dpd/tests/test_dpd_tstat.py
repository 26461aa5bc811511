"""pair dpd/tstat: with T = 0 (friction alone) under hybrid/overlay with lj/cut, LAMMPS's thermo step
for step; a DPD gas held at T by it, its mean temperature against LAMMPS's with honest errors; the
target ramped over the run as LAMMPS's; bad words one line."""

import io
import math

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import thermo_rows

FRICTION_ONLY = """\
units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 4 0 4 0 4
create_box 2 box
create_atoms 1 box
mass * 1.0
set type 1 type/fraction 2 0.5 12345
velocity all create 2.0 4928459 loop geom
comm_modify vel yes
pair_style hybrid/overlay lj/cut 2.5 dpd/tstat 0.0 0.0 2.5 34387
pair_coeff * * lj/cut 1.0 1.0
pair_coeff 1 1 dpd/tstat 4.5
pair_coeff 1 2 dpd/tstat 2.0 1.5
pair_coeff 2 2 dpd/tstat 1.0
neighbor 0.3 bin
fix 1 all nve
thermo_style custom step temp pe ke etotal press
thermo_modify format float %20.15g
thermo 20
timestep 0.005
run 100
"""
# LAMMPS 22 Jul 2025 on this machine, the script above
LAMMPS_FRICTION_ONLY = [
    (0, 2, -6.77336805325309, 2.98828125, -3.78508680325309, -4.56695665088527),
    (20, 0.595709409644363, -5.51825743418241, 0.89007362964441, -4.628183804538, 1.22550409044576),
    (40, 0.587341562703038, -5.89811514781352, 0.877570889585593, -5.02054425822792, -0.617807508383027),
    (60, 0.427180229847802, -5.968939984784, 0.638267335612438, -5.33067264917156, -1.09994892540895),
    (80, 0.388909927052481, -6.14210028066299, 0.581086121474899, -5.56101415918809, -2.06597452629544),
    (100, 0.312231285883376, -6.22551837137743, 0.466517448634342, -5.75900092274309, -2.49420729974264),
]


def test_friction_alone_gives_lammps_thermo_step_for_step():
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None, dialect="lammps")
    sim.command(FRICTION_ONLY)
    rows = thermo_rows(screen.getvalue())
    assert len(rows) == len(LAMMPS_FRICTION_ONLY)
    for row, reference in zip(rows, LAMMPS_FRICTION_ONLY):
        assert row == pytest.approx(reference, rel=1e-11, abs=1e-13)


GAS = """\
units lj
atom_style atomic
region box block 0 7 0 7 0 7
create_box 1 box
create_atoms 1 random 1029 4321 box
mass 1 1.0
velocity all create 0.5 4928459 loop geom
comm_modify vel yes
pair_style dpd/tstat 1.2 1.2 1.0 SEED
pair_coeff 1 1 4.5
neighbor 0.3 bin
fix 1 all nve
thermo_style custom step temp
thermo 10
timestep 0.02
run 6000
"""
# LAMMPS 22 Jul 2025, the gas above with seeds 34387 (6000 steps), 777 and 90210 (12000 steps): the
# mean thermo temperature after the first 1000 steps and its error from 20 block means each:
# 1.21715 +- 0.00276, 1.21810 +- 0.00145, 1.22217 +- 0.00157 (velocity Verlet runs ~1.5 % hot at
# dt = 0.02); weighted together 1.2196 +- 0.0010
LAMMPS_GAS_T, LAMMPS_GAS_ERROR = 1.2196, 0.0010


def test_a_gas_held_at_t_by_it_has_lammps_mean_temperature():
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None, dialect="lammps")
    sim.command(GAS.replace("SEED", "34387"))
    t = np.array(thermo_rows(screen.getvalue()))[100:, 1]
    blocks = t[: len(t) // 20 * 20].reshape(20, -1).mean(axis=1)
    error = blocks.std(ddof=1) / math.sqrt(len(blocks))
    assert abs(t.mean() - LAMMPS_GAS_T) < 3.0 * math.hypot(error, LAMMPS_GAS_ERROR)
    # and the target itself is far outside: the thermostat holds 1.2, not the starting 0.5
    assert abs(t.mean() - 1.2) < 0.05


def test_the_target_is_ramped_over_the_run():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(GAS.replace("SEED", "5").replace("1.2 1.2 1.0", "0.5 2.0 1.0").replace("run 6000", "run 0"))
    pair = sim.pair
    for step, first, last, target in ((0, 0, 100, 0.5), (50, 0, 100, 1.25), (100, 0, 100, 2.0), (30, 10, 30, 2.0)):
        sim.run_state.step, sim.run_state.ramp_bounds = step, (first, last)
        assert pair.law_state(sim)[2] == pytest.approx(math.sqrt(target / 0.02), rel=1e-14)


@pytest.mark.parametrize("line, message", [
    ("pair_style dpd/tstat -1 1 1 5", "t_start must be >= 0 (got -1)"),
    ("pair_style dpd/tstat 1 1 1 0", "seed must be >= 1 (got 0)"),
    ("pair_style dpd/tstat 1 1 1", "missing argument seed"),
])
def test_bad_words_are_one_line(line, message):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\nregion box block 0 3 0 3 0 3\ncreate_box 1 box")
    with pytest.raises(ScriptError) as info:
        sim.command(line)
    assert message in str(info.value) and "\n" not in str(info.value)
