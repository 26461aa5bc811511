"""pair_style granular (LAMMPS's composed contacts) against LAMMPS 22 Jul 2025's trajectories
(data/granular/NAME.ref, recorded by benchmarks/lammps_references/granular.py), formulas, analytic
limits and the errors of its pair_coeff lines."""

import math

import numpy as np
import pytest

from pathlib import Path

GRANULAR = Path(__file__).parent / "data" / "granular"
CASES = sorted(path.stem for path in GRANULAR.glob("*.ref"))


@pytest.mark.parametrize("name", CASES)
def test_trajectories_equal_lammps(granular_case, name):
    """x, v, omega of every particle at every dumped step equal LAMMPS's to 1e-10 of their scale
    over the whole contact, and a contact changed the motion."""
    record, table = granular_case(name, rtol=1e-10)
    assert not np.allclose(record.v[max(table) - 1], record.v[0])
