"""Every LAMMPS unit system with its constants: one argon scene written in real, metal, si, cgs, micro
and nano units (benchmarks/lammps_references/units.py) gives LAMMPS's thermo table
(tests/data/lammps/units.txt, 15 digits) over 100 NVE steps: boltz in the temperature, ftm2v in the
kick, mvv2e in the kinetic energy, nktv2p in the pressure, and the lattice, create_atoms and velocity
create of the same script."""

import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.testing import logged_thermo

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from lammps_run import read_blocks  # noqa: E402
from units import STYLES, script  # noqa: E402


LAMMPS = read_blocks(ROOT / "tests" / "data" / "lammps" / "units.txt")


@pytest.mark.parametrize("style", STYLES)
def test_argon_in_each_unit_system_prints_lammps_thermo(tmp_path, style):
    lammps = LAMMPS[style]
    mine = logged_thermo(tmp_path, script(style))
    assert mine.shape == lammps.shape == (11, 6)
    np.testing.assert_array_equal(mine[:, 0], lammps[:, 0])
    # steps 0 to 100: temp, pe, ke, etotal, press to the printed digits (they agree to 7e-15)
    np.testing.assert_allclose(mine[:, 1:], lammps[:, 1:], rtol=1e-13, atol=0)
