"""compute ke/rigid and erotate/rigid: the bodies' translational and rotational kinetic energies, against
LAMMPS (22 Jul 2025) on 27 LJ bodies under fix rigid, rigid/small and rigid/nvt/small (recorded by
benchmarks/lammps_references/rigid_energies.py), and against the particles' own kinetic energy, which
for bodies of point particles is exactly their sum; on 2 ranks as on 1."""

import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.testing import thermo_on_ranks, thermo_rows

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from lammps_run import read_blocks  # noqa: E402
from rigid_energies import SCRIPT, STYLES  # noqa: E402

DATA = Path(__file__).with_name("data")


@pytest.mark.parametrize("name", list(STYLES))
def test_body_energies_match_lammps_and_add_up_to_the_particles(pdps_cli, tmp_path, name):
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    done = pdps_cli(SCRIPT.format(fix=STYLES[name]), "-log", "none")
    assert done.returncode == 0, done.stderr
    ours = np.array(thermo_rows(done.stdout))
    lammps = read_blocks(DATA / "rigid_energies.txt")[name]
    assert ours.shape == lammps.shape == (5, 4)
    # within the round-off the 27 bodies' collisions grow over 2000 steps (fix rigid's thermo: 1e-11)
    assert ours[:, 1:3] == pytest.approx(lammps[:, 1:3], rel=1e-9)
    # point particles moving rigidly: their kinetic energy is the bodies' translation plus rotation
    assert ours[:, 1] + ours[:, 2] == pytest.approx(ours[:, 3], rel=1e-12)


def test_two_ranks_sum_the_bodies_each_rank_owns(tmp_path):
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    text = SCRIPT.format(fix=STYLES["rigid/small"])
    one, two = thermo_on_ranks(text, tmp_path)
    assert two == pytest.approx(one, rel=1e-10)


@pytest.mark.parametrize("line, message", [
    ("compute r all erotate/rigid 9", "compute r (erotate/rigid): fix 9 is not defined"),
    ("compute r all ke/rigid 2", "compute r (ke/rigid): fix 2 (nve) is not a fix of rigid bodies (rigid, "
                                 "rigid/small or their variants)"),
])
def test_a_missing_or_wrong_fix_is_one_line(pdps_cli, tmp_path, line, message):
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    script = SCRIPT.format(fix="rigid/small molecule").replace(
        "compute trans all ke/rigid 1\ncompute rot all erotate/rigid 1\n", f"fix 2 all nve\n{line}\n").replace(
        "c_trans c_rot", "c_r")
    done = pdps_cli(script, "-log", "none")
    assert done.returncode == 1
    assert message in done.stderr.strip().splitlines()[-1]
