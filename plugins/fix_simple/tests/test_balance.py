"""comm_style, comm_modify mode multi, the balance command and fix balance: LAMMPS's load balancing
is read and changes no number (pdps keeps its regular processor grid); fix balance flags a changing
box as LAMMPS's does, so thermo one prints Volume. BALANCE_LAMMPS is what LAMMPS 22 Jul 2025
printed on this machine for BALANCE on one rank."""

import pytest

from pdps_core.testing import assert_prints_as_lammps, script_error

BALANCE = """units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.5 87287 loop geom
neighbor 0.3 multi
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
comm_style tiled
comm_modify mode multi group all vel yes
balance 1.1 rcb
fix 1 all nve
fix 10 all balance 50 0.9 rcb
thermo 50
run 200
unfix 10
balance 1.1 shift xyz 20 1.1
fix 10 all balance 100 1.1 shift xyz 20 1.01
run 100
"""
# Step Temp E_pair E_mol TotEng Press Volume (the second run's first row repeats step 200)
BALANCE_LAMMPS = [
    [0, 1.5, -6.7733681, 0, -4.5321571, -4.9739638, 303.24568],
    [50, 0.73570063, -5.6383249, 0, -4.5390847, 0.73267385, 303.24568],
    [100, 0.75591871, -5.6697485, 0, -4.5402997, 0.55560942, 303.24568],
    [150, 0.81591063, -5.762633, 0, -4.5435478, 0.18402571, 303.24568],
    [200, 0.75459308, -5.6701197, 0, -4.5426516, 0.52830868, 303.24568],
    [200, 0.75459308, -5.6701197, 0, -4.5426516, 0.52830868, 303.24568],
    [250, 0.76043251, -5.6779327, 0, -4.5417396, 0.59622749, 303.24568],
    [300, 0.77604704, -5.7003636, 0, -4.5408402, 0.51701681, 303.24568],
]


def test_balanced_run_prints_lammps_thermo(tmp_path):
    text = assert_prints_as_lammps(tmp_path, BALANCE, BALANCE_LAMMPS)
    assert text.count("Volume") == 2


SETUP = "dialect lammps\n" + BALANCE.split("comm_style")[0]


@pytest.mark.parametrize("line, message", [
    ("comm_style cubes", "<command>:1: comm_style: comm_style must be one of brick, tiled (got cubes)"),
    ("neighbor 0.3 bin\ncomm_modify mode multi",
     "<command>:2: comm_modify: mode multi needs multi neighbor lists (neighbor SKIN multi first), as LAMMPS's"),
    ("comm_modify group mobile", "<command>:1: comm_modify: comm_modify group mobile: pdps sends the ghosts of "
                                 "every particle (group all)"),
    ("balance 1.1 rcb out boxes.txt", "<command>:1: balance: out: pdps keeps a regular processor grid, so it has no "
                                      "balanced sub-domains to write"),
    ("balance 1.1 cubes", "<command>:1: balance: balance style must be one of x, y, z, shift, rcb (got cubes)"),
    ("fix 10 all balance 50 0.9 cubes", "<command>:1: fix: balance style must be shift or rcb (got cubes)"),
    ("fix 10 all balance 50 0.9 shift xyz", "<command>:1: fix: balance shift needs DIMSTR NITER STOPTHRESH"),
])
def test_bad_balancing_is_refused(line, message):
    assert str(script_error(SETUP, line)) == message


OUTPUTS = """units lj
dimension 2
atom_style atomic
boundary f f p
lattice hex 0.85
region box block 0 20 0 10 -0.5 0.5
create_box 1 box
region circle sphere 6 4 0.0 4
create_atoms 1 region circle
mass 1 1.0
velocity all create 0.5 87287 loop geom
velocity all set 5 2 0 sum yes
pair_style lj/cut 2.5
pair_coeff 1 1 10.0 1.0 2.5
fix 1 all nve
fix 2 all wall/lj93 xlo 0.0 1 1 2.5 xhi 20 1 1 2.5
fix 3 all wall/lj93 ylo 0.0 1 1 2.5 yhi 10 1 1 2.5
comm_style tiled
fix 10 all balance 50 0.9 rcb
thermo_style custom step temp epair press f_10[1] f_10[2] f_10[3] f_10 atoms
thermo 100
run 300
"""
# LAMMPS 22 Jul 2025 on one rank: the most particles a rank holds, iterations, imbalance before and after
OUTPUTS_LAMMPS = [
    [0, 26.072625, -26.08571, -0.51470668, 58, 0, 1, 1, 58],
    [100, 26.037246, -26.051425, 0.5803223, 58, 0, 1, 1, 58],
    [200, 25.966618, -25.981426, 0.42574508, 58, 0, 1, 1, 58],
    [300, 26.011219, -26.022754, 0.72222753, 58, 0, 1, 1, 58],
]


def test_fix_balance_outputs_are_lammps_on_one_rank(tmp_path):
    assert_prints_as_lammps(tmp_path, OUTPUTS, OUTPUTS_LAMMPS)
