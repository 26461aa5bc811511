"""neigh_modify exclude type/group/none, newton off, comm_modify cutoff and neigh_modify every/delay/
check/one as LAMMPS: a two-type LJ liquid under each (benchmarks/lammps_references/neighbor_comm.py)
prints LAMMPS's thermo (tests/data/lammps/neighbor_comm.txt, 15 digits) over 100 steps."""

import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.testing import logged_thermo

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from lammps_run import read_blocks  # noqa: E402
from neighbor_comm import CASES, script  # noqa: E402


LAMMPS = read_blocks(ROOT / "tests" / "data" / "lammps" / "neighbor_comm.txt")


@pytest.mark.parametrize("case", CASES)
def test_case_prints_lammps_thermo(tmp_path, case):
    mine = logged_thermo(tmp_path, script(case))
    lammps = LAMMPS[case]
    assert mine.shape == lammps.shape == (6, 4)
    np.testing.assert_array_equal(mine[:, 0], lammps[:, 0])
    np.testing.assert_allclose(mine[:, 1:], lammps[:, 1:], rtol=1e-11, atol=0)


def test_the_cases_differ_from_each_other():
    """Each exclusion changes the run (one that excluded nothing would pass the test above)."""
    finals = {case: tuple(table[-1, 1:]) for case, table in LAMMPS.items()}
    assert len({finals[c] for c in ("exclude_type", "exclude_group", "exclude_none")}) == 3
