"""pair_style hybrid and hybrid/overlay give LAMMPS's thermo, step for step, on a 200-particle
two-type fluid (data/hybrid.txt, recorded with LAMMPS by benchmarks/lammps_references/pair_hybrid.py);
a hybrid of one style is that style; overlaid styles add; bad assignments get one line.

The thermo against LAMMPS's (with 2 ranks and restarts for the cases marked so) is checked by
tests/test_recorded_thermo.py from data/hybrid.cases.json; this file holds the rest."""

from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, observables
from pdps_core.testing import forces_by_tag, two_type_cluster

DATA = Path(__file__).parent / "data"


def _state(tmp_path, setup):
    sim = two_type_cluster(tmp_path, setup + "\nrun 0")
    return forces_by_tag(sim), observables.potential_energy(sim), observables.virial_trace(sim)


def test_overlay_adds_the_sub_styles(tmp_path):
    both = _state(tmp_path, "pair_style hybrid/overlay lj/cut 2.5 soft 1.5\npair_coeff * * lj/cut 1 1\n"
                            "pair_coeff * * soft 3.0")
    lj = _state(tmp_path, "pair_style lj/cut 2.5\npair_coeff * * 1 1")
    soft = _state(tmp_path, "pair_style soft 1.5\npair_coeff * * 3.0")
    for total, a, b in zip(both, lj, soft):
        np.testing.assert_allclose(total, np.asarray(a) + np.asarray(b), rtol=1e-13, atol=1e-13)


def test_hybrid_moves_a_pair_to_its_last_style(tmp_path):
    moved = _state(tmp_path, "pair_style hybrid lj/cut 2.5 soft 1.5\npair_coeff * * lj/cut 1 1\n"
                             "pair_coeff * * soft 3.0\npair_coeff 1 1 lj/cut 1 1")
    lj = _state(tmp_path, "pair_style lj/cut 2.5\npair_coeff 1 1 1 1\npair_coeff 1 2 0 1\npair_coeff 2 2 0 1")
    soft = _state(tmp_path, "pair_style soft 1.5\npair_coeff 1 1 0.0\npair_coeff 1 2 3.0\npair_coeff 2 2 3.0")
    for total, a, b in zip(moved, lj, soft):
        np.testing.assert_allclose(total, np.asarray(a) + np.asarray(b), rtol=1e-13, atol=1e-13)


def test_none_removes_a_pair(tmp_path):
    forces, energy, _ = _state(tmp_path, "pair_style hybrid lj/cut 2.5\npair_coeff * * lj/cut 1 1\n"
                                         "pair_coeff 1 2 none\npair_coeff 2 2 none")
    only_11 = _state(tmp_path, "pair_style lj/cut 2.5\npair_coeff 1 1 1 1\npair_coeff 1 2 0 1\npair_coeff 2 2 0 1")
    np.testing.assert_allclose(forces, only_11[0], rtol=1e-13, atol=1e-13)
    assert energy == pytest.approx(only_11[1], rel=1e-13)


BAD = {
    "not a sub-style": ("pair_style hybrid lj/cut 2.5\npair_coeff * * soft 3.0",
                        "soft is not a sub-style of this pair_style hybrid (it has: lj/cut)"),
    "unused": ("pair_style hybrid lj/cut 2.5 soft 1.5\npair_coeff * * lj/cut 1 1\nrun 0",
               "pair hybrid sub-style soft is not used (no pair_coeff assigns a type pair to it)"),
    "unmixable": ("pair_style hybrid/overlay lj/cut 2.5 soft 1.5\npair_coeff 1 1 lj/cut 1 1\npair_coeff 1 1 soft 1\n"
                  "pair_coeff 2 2 lj/cut 1 1\npair_coeff 2 2 soft 1\nrun 0",
                  "pair coefficients are not set for types 1 2: only a pair whose types each have the same one "
                  "sub-style is mixed (give pair_coeff 1 2 STYLE ... or none)"),
    "no style": ("pair_style hybrid 2.5", "substyles must start with the name of a pair style (got 2.5)"),
    "twice, unnamed": ("pair_style hybrid lj/cut 2.5 lj/cut 3.0\npair_coeff 1 1 lj/cut 1.0 1.0",
                       "pair style lj/cut appears 2 times in pair_style hybrid: name which with a number from 1 to "
                       "2 after it (got 1.0 1.0)"),
    "own loop beside another": ("pair_style hybrid gran/hooke 200000 NULL 50 NULL 0.5 0 lj/cut 2.5",
                                "pair style gran/hooke cannot be a sub-style of hybrid: it is not a force law over a "
                                "half list"),
    "own loop, overlaid": ("pair_style hybrid/overlay gran/hooke 200000 NULL 50 NULL 0.5 0",
                           "pair style gran/hooke cannot be a sub-style of hybrid/overlay: it is not a force law "
                           "over a half list"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_hybrids_get_one_line(tmp_path, case):
    script, message = BAD[case]
    with pytest.raises(ScriptError) as caught:
        two_type_cluster(tmp_path, script)
    assert message in str(caught.value) and "\n" not in str(caught.value)


def test_a_style_twice_is_two_styles_of_their_own_settings(tmp_path):
    """lj/cut at 2.5 on 1-1 and lj/cut at 1.5 on 2-2 and 1-2 (each instance its own cutoff) is lj/cut
    2.5 with those cutoffs per pair."""
    twice = _state(tmp_path, "pair_style hybrid lj/cut 2.5 lj/cut 1.5\npair_coeff 1 1 lj/cut 1 1.0 1.0\n"
                             "pair_coeff 2 2 lj/cut 2 0.5 1.1\npair_coeff 1 2 lj/cut 2 0.7 1.05")
    once = _state(tmp_path, "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.5 1.1 1.5\n"
                            "pair_coeff 1 2 0.7 1.05 1.5")
    np.testing.assert_allclose(twice[0], once[0], rtol=1e-13, atol=1e-13)
    assert twice[1] == pytest.approx(once[1], rel=1e-13)


def test_per_particle_energies_of_the_sub_styles_add_up(tmp_path):
    sim = two_type_cluster(tmp_path, "pair_style hybrid/overlay lj/cut 2.5 soft 1.5\npair_coeff * * lj/cut 1 1\n"
                                     "pair_coeff 1 2 soft 3.0\ncompute e all pe/atom\n"
                                     "compute s all stress/atom NULL virial\nrun 0")
    assert np.sum(sim.computes["e"].peratom(sim)) == pytest.approx(observables.potential_energy(sim), rel=1e-13)
    assert np.sum(sim.computes["s"].peratom(sim)[:, :3]) == pytest.approx(-observables.virial_trace(sim), rel=1e-13)
