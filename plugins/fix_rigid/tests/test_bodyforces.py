"""fix_modify ID bodyforces early|late on fix rigid: early, the bodies' forces are summed at the fix's
turn in post_force, so fix addforce defined after it does not push the bodies; late (the default),
it does. LAMMPS 22 Jul 2025 printed BODYFORCES_LAMMPS on this machine for BODYFORCES, both ways."""

import pytest

from pdps_core.api import Simulation
from pdps_core.testing import script_error, thermo_rows

BODYFORCES = """units lj
atom_style atomic
region box block -6 6 -6 6 -6 6
create_box 1 box
create_atoms 1 single 0 0 0
create_atoms 1 single 1 0 0
create_atoms 1 single 0 1 0
create_atoms 1 single 2.2 0.3 0.1
create_atoms 1 single 3.1 0.5 0.2
create_atoms 1 single 2.4 1.3 -0.3
mass 1 1.0
group a id 1:3
group b id 4:6
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
neigh_modify exclude group a a exclude group b b
velocity all create 1.0 4928 loop geom
fix 1 all rigid group 2 a b
fix_modify 1 bodyforces ${when}
fix 2 a addforce 0.5 0.2 0.0
variable xa equal xcm(a,x)
variable vb equal vcm(b,x)
thermo_style custom step temp pe etotal v_xa v_vb
thermo 50
run 200
"""
# step temp pe etotal xcm(a,x) vcm(b,x)
BODYFORCES_LAMMPS = {
    "early": [[0, 0.64194967, -0.16441515, 0.3170471, 0.33333333, 0.20616439],
              [50, 0.60081764, -0.13084945, 0.31976378, 0.31013182, -0.015612649],
              [100, 0.56980806, -0.10759135, 0.31976469, 0.33720645, -0.19293608],
              [150, 0.57921735, -0.11464786, 0.31976515, 0.40423592, -0.34284542],
              [200, 0.66223843, -0.18235567, 0.31432315, 0.5115688, -0.53006344]],
    "late": [[0, 0.64194967, -0.16441515, 0.3170471, 0.33333333, 0.20616439],
             [50, 0.61945988, -0.13770836, 0.32688656, 0.3255473, -0.017567485],
             [100, 0.65284109, -0.13270107, 0.35692975, 0.40143184, -0.21298585],
             [150, 0.80218965, -0.19603914, 0.4056031, 0.5570597, -0.41974653],
             [200, 0.84354809, -0.15597131, 0.47668976, 0.79948361, -0.41911986]],
}


@pytest.mark.parametrize("when", list(BODYFORCES_LAMMPS))
def test_bodyforces_early_leaves_out_later_fixes_forces_as_lammps(tmp_path, when):
    sim = Simulation(screen=False, log=str(tmp_path / "log.case"), dialect="lammps")
    sim.command(BODYFORCES.replace("${when}", when))
    sim.close()
    rows = thermo_rows((tmp_path / "log.case").read_text())
    assert len(rows) == 5
    for got, want in zip(rows, BODYFORCES_LAMMPS[when]):
        assert got == pytest.approx(want, rel=2e-8, abs=1e-12), (when, want[0])


def test_bodyforces_takes_early_or_late():
    setup = "dialect lammps\n" + BODYFORCES.split("fix_modify")[0]
    assert str(script_error(setup, "fix_modify 1 bodyforces soon")) == \
        "<command>:1: fix_modify: bodyforces must be early or late (got soon)"
