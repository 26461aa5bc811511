"""fix rigid and rigid/nve against LAMMPS (22 Jul 2025) on bodies of Lennard-Jones particles, one of
them across the periodic x and y boundaries: temperature, total energy, pressure (the constraint
virial) and the bodies' temperature f_1 over 10^4 steps, recorded by
benchmarks/lammps_references/rigid.py into tests/data/rigid_lj.txt; the same thermo on 1 and 2 ranks."""

import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.testing import run_ranks, thermo_rows

DATA = Path(__file__).with_name("data")
SCRIPT = """units lj
atom_style molecular
read_data rigid_lj.data
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
neigh_modify exclude molecule/intra all
timestep 0.001
fix 1 all {style} molecule
thermo_style custom step temp epair ke etotal press f_1
thermo_modify format float %20.15g
thermo 100
run {steps}
"""


def reference(style):
    tables, name = {}, None
    for line in (DATA / "rigid_lj.txt").read_text().splitlines():
        if line.startswith("# "):
            name = line[2:]
            tables[name] = []
        else:
            tables[name].append([float(w) for w in line.split()])
    return np.array(tables[style])


@pytest.mark.parametrize("style", ["rigid", "rigid/nve"])
def test_thermo_matches_lammps_over_ten_thousand_steps(pdps_cli, tmp_path, style):
    shutil.copy(DATA / "rigid_lj.data", tmp_path)
    done = pdps_cli(SCRIPT.format(style=style, steps=10000), "-log", "none")
    assert done.returncode == 0, done.stderr
    ours = np.array(thermo_rows(done.stdout))
    lammps = reference(style)
    assert ours.shape == lammps.shape
    temp = np.abs(ours[:, 1] / lammps[:, 1] - 1).max()
    etotal = np.abs(ours[:, 4] / lammps[:, 4] - 1).max()
    press = np.abs(ours[:, 5] - lammps[:, 5]).max() / np.abs(lammps[:, 5]).max()
    print(f"{style}: largest relative difference from LAMMPS over 1e4 steps: temp {temp:.1e}, "
          f"etotal {etotal:.1e}, press {press:.1e} (of its largest value)")
    assert temp < 1e-5 and etotal < 1e-5       # 5 significant digits (achieved: 4e-12 and 8e-14)
    assert press < 1e-5
    assert ours[:, 6] == pytest.approx(lammps[:, 6], rel=1e-5)


@pytest.mark.parametrize("style", ["rigid", "rigid/nve"])
def test_same_thermo_on_one_and_two_ranks(tmp_path, style):
    shutil.copy(DATA / "rigid_lj.data", tmp_path)
    script = SCRIPT.format(style=style, steps=2000)
    one = np.array(thermo_rows(run_ranks(script, 1, tmp_path).stdout))
    two = np.array(thermo_rows(run_ranks(script, 2, tmp_path).stdout))
    assert one.shape == two.shape == (21, 7)
    assert two == pytest.approx(one, rel=1e-10, abs=1e-13)
