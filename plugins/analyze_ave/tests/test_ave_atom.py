"""Fix ave/atom against LAMMPS 22 Jul 2025 (recorded on this machine, 2026-12-02): the 200-particle
LJ fluid (data/fluid.data, a copy of pair_simple's), two averages of different schedules over
positions, velocities, forces, a per-atom compute and an atom-style variable, read through compute
reduce at the steps both averages are current; and the values it refuses."""

import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError

SCENE = """
units lj
atom_style atomic
atom_modify map array
read_data fluid.data
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0
pair_coeff 2 2 0.5 1.2
fix 1 all nve
timestep 0.002
group heavy type 2
compute k all ke/atom
variable vx2 atom vx*vx
fix a heavy ave/atom 2 5 20 vx fz y c_k v_vx2
fix b all ave/atom 1 1 30 x
compute s all reduce sum f_a[1] f_a[2] f_a[3] f_a[4] f_a[5] f_b
thermo 60
thermo_style custom step c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6]
thermo_modify norm no
"""
# thermo (%.15g) at the steps both averages are current (LAMMPS refuses reading them at others)
LAMMPS = {
    0: [0, 0, 0, 0, 0, 694.014801376487],
    60: [-14.0895863057849, 128.193985289418, 244.866660224986, 370.371044438322, 173.32642021317,
         702.652924530196],
    120: [8.92334374377067, 2.90291816092036, 239.69632932497, 311.199149769792, 138.914148795991,
          696.852979138554],
}


def test_averages_as_lammps(make_sim, tmp_path):
    shutil.copy(Path(__file__).parent / "data" / "fluid.data", tmp_path)
    sim = make_sim(dialect="lammps")
    sim.command(SCENE)
    for step, want in LAMMPS.items():
        sim.command(f"run {step - sim.step}")
        np.testing.assert_allclose(sim.computes["s"].vector(sim), want, rtol=1e-10, atol=1e-9)
    # particles outside the group read 0
    light = sim.particles.type[:sim.particles.nlocal] == 1
    assert not sim.fixes["a"].peratom(sim)[light].any()


@pytest.mark.parametrize("line, message", [
    ("fix a all ave/atom 1 1 10 xu", "fix a ave/atom: unknown value xu (x y z vx vy vz fx fy fz, c_ID, c_ID[k], "
                                     "f_ID, f_ID[k] or v_NAME)"),
    ("fix a all ave/atom 3 1 10 x", "nfreq must be a multiple of nevery (got nevery 3, nfreq 10)"),
    ("fix a all ave/atom 1 1 10 c_none", "fix a ave/atom value c_none: compute none is not defined"),
])
def test_refused(make_sim, tmp_path, line, message):
    shutil.copy(Path(__file__).parent / "data" / "fluid.data", tmp_path)
    sim = make_sim(dialect="lammps")
    sim.command(SCENE.split("group heavy")[0])
    with pytest.raises(ScriptError) as error:
        sim.command(line)
    assert message in str(error.value)
