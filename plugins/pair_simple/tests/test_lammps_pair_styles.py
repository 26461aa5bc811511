"""Pair styles soft, morse, yukawa, zero and lj/cut's mixing rules give LAMMPS's thermo, step for step,
on a 200-particle two-type fluid (data/pair_styles.txt, recorded with LAMMPS by
benchmarks/lammps_references/pair_styles.py), and their forces are minus the gradient of their energy.

The thermo against LAMMPS's (with 2 ranks and restarts for the cases marked so) is checked by
tests/test_recorded_thermo.py from data/pair_styles.cases.json; this file holds the rest."""

import math
import sys
from pathlib import Path

import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import assert_force_is_minus_gradient, build, forces_by_tag, two_type_cluster

DATA = Path(__file__).parent / "data"
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from pair_styles import CASES  # noqa: E402


@pytest.mark.parametrize("case", ["soft", "morse", "yukawa"])
def test_forces_are_minus_the_gradient(tmp_path, case):
    sim = two_type_cluster(tmp_path, CASES[case].replace("pair_modify shift yes", ""))
    assert_force_is_minus_gradient(sim, rel=1e-6, abs=1e-7, largest=0.1)


def test_soft_pushes_coincident_particles_apart_without_blowing_up(tmp_path):
    sim = build(tmp_path, [[5.0, 5.0, 5.0], [5.2, 5.0, 5.0]], setup="pair_style soft 1.0\npair_coeff * * 2.0\nrun 0")
    f = forces_by_tag(sim)
    assert f[1, 0] == pytest.approx(2.0 * math.pi * math.sin(0.2 * math.pi) / 1.0, rel=1e-13)
    assert sim.pe == pytest.approx(2.0 * (1 + math.cos(0.2 * math.pi)), rel=1e-13)


def test_morse_does_not_mix():
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 5 0 5 0 5\ncreate_box 2 box\nmass * 1\ncreate_particle 1 single 1 1 1\n"
                "pair_style morse 2.5\npair_coeff 1 1 1 4 1.1\npair_coeff 2 2 1 4 1.1")
    with pytest.raises(ScriptError, match="pair coefficients are not set for types 1 2"):
        sim.command("run 0")
