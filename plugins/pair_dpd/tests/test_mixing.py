"""Several types: per-pair coefficients, and mixing rules for pairs not given."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

BASE = """
region box block 0 6 0 6 0 6
create_box 3 box
mass * 1
create_particle 1 single 1.0 1.0 1.0
create_particle 2 single 1.5 1.0 1.0
create_particle 3 single 4.0 4.0 4.0
velocity all set 0 0 0
pair_style dpd 0.0 1.0 7
pair_coeff 1 1 16.0 4.0 1.0
pair_coeff 2 2 36.0 9.0 0.8
pair_coeff 3 3 25.0 4.5
"""


def force_between_1_and_2(extra):
    sim = Simulation(screen=False, log=None)
    sim.command(BASE + extra + "run 0")
    return sim, sim.f[0, 0]


def test_unset_cross_pair_is_an_error_without_a_mixing_rule():
    with pytest.raises(ScriptError, match=r"pair coefficients are not set for types 1 2 .*pair_modify mix"):
        force_between_1_and_2("")


@pytest.mark.parametrize("rule,combine", [
    ("geometric", lambda p, q: math.sqrt(p * q)),
    ("arithmetic", lambda p, q: 0.5 * (p + q)),
])
def test_mixing_rule_combines_like_pairs(rule, combine):
    sim, fx = force_between_1_and_2(f"pair_modify mix {rule}\n")
    a, rc = combine(16.0, 36.0), combine(1.0, 0.8)
    r = 0.5
    assert fx == pytest.approx(-a * (1 - r / rc))       # particle 1 is pushed towards -x
    assert sim.pair.cut[1, 2] == pytest.approx(rc)
    assert sim.pair.gamma[1, 2] == pytest.approx(combine(4.0, 9.0))


def test_explicit_cross_pair_wins_over_the_rule_and_later_changes_remix():
    sim, fx = force_between_1_and_2("pair_modify mix arithmetic\npair_coeff 1 2 10.0 1.0 1.0\n")
    assert fx == pytest.approx(-10.0 * 0.5)
    sim = Simulation(screen=False, log=None)
    sim.command(BASE + "pair_modify mix arithmetic\nrun 0\npair_coeff 1 1 20.0 4.0 1.0\nrun 0")
    assert sim.pair.a[1, 2] == pytest.approx(0.5 * (20.0 + 36.0))


def test_per_type_cutoffs_are_used_in_the_neighbor_list():
    sim = Simulation(screen=False, log=None)
    sim.command(BASE + "pair_modify mix geometric\nrun 0")
    cut = sim.pair_list.cutoff
    assert cut[2, 2] == pytest.approx(0.8) and cut[1, 1] == pytest.approx(1.0)
    assert cut[1, 2] == pytest.approx(math.sqrt(0.8))
    assert np.isfinite(sim.f).all()
