"""compute msd (com yes, average yes), coord/atom (one type range gives one value per particle, as
LAMMPS), erotate/sphere and fix enforce2d as LAMMPS computes them: the scenes of
benchmarks/lammps_references/analysis_computes.py print LAMMPS's thermo (tests/data/lammps/
analysis_computes.txt, 15 digits) over 100 steps."""

import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.testing import logged_thermo

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from lammps_run import read_blocks  # noqa: E402
from analysis_computes import SCRIPTS  # noqa: E402


LAMMPS = read_blocks(ROOT / "tests" / "data" / "lammps" / "analysis_computes.txt")


@pytest.mark.parametrize("scene", SCRIPTS)
def test_scene_prints_lammps_thermo(tmp_path, scene):
    lammps = LAMMPS[scene]
    mine = logged_thermo(tmp_path, SCRIPTS[scene])
    assert mine.shape == lammps.shape and len(lammps) >= 6
    np.testing.assert_array_equal(mine[:, 0], lammps[:, 0])
    # the printed digits; a msd of 0 at step 0 is roundoff (1e-29) in both
    np.testing.assert_allclose(mine[:, 1:], lammps[:, 1:], rtol=1e-13, atol=1e-20)
    assert np.abs(lammps[1:, 1:]).min() > 0       # every column moves: the comparison has content
