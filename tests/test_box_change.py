"""A box that changes during a run (sim.change_box): the group's particles keep their fractional
coordinates, the others stay put, and forces after the change (periodic images at the new lengths,
on one rank or two) are those of the same particles read into the new box; the box saves as it is;
impossible bounds are one line."""

import numpy as np
import pytest

from pdps_core.api import SimulationError
from pdps_core.testing import build, by_tag, fluid, forces_by_tag, run_ranks, thermo_rows

LJ = "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\nmass 1 1.0"


def scene(tmp_path):
    return fluid(120, 0.7, min_distance=0.85)


def test_remapped_particles_keep_fractional_coordinates_and_forces_match_a_fresh_box(tmp_path):
    x, length = scene(tmp_path)
    sim = build(tmp_path, x, setup=LJ + "\nrun 0", hi=(length,) * 3)
    lo, hi = np.array([-0.3, 0.2, 0.0]), np.array([1.06 * length, 0.97 * length + 0.2, length])
    sim.change_box(lo, hi, remap="all")
    expected = lo + (x - 0.0) / length * (hi - lo)
    np.testing.assert_allclose(by_tag(sim, sim.x), expected, rtol=1e-13, atol=1e-13)
    sim.command("run 0")
    fresh = build(tmp_path, expected, setup=LJ + "\nrun 0", lo=lo, hi=hi, name="fresh.data")
    np.testing.assert_allclose(forces_by_tag(sim), forces_by_tag(fresh), rtol=1e-10, atol=1e-10)
    assert sim.box.volume == pytest.approx(float(np.prod(hi - lo)), rel=1e-14)


def test_a_box_changing_inside_a_run_keeps_the_images_right(tmp_path):
    """fix deform shrinks x every step without remapping and the run's last forces (computed before
    the last step's change, in the box of step 39) equal a fresh evaluation of the same positions in
    that box: every image at that step's length."""
    x, length = scene(tmp_path)
    v = np.random.default_rng(3).normal(0, 0.5, x.shape)
    sim = build(tmp_path, x, v=v, setup=LJ + "\nfix 1 all nve\nfix 2 all deform 1 x erate -0.2 remap none "
                "units box\nrun 40", hi=(length,) * 3)
    assert sim.box.length[0] == pytest.approx(length * (1 - 0.2 * 40 * sim.dt), rel=1e-12)
    shift = 0.5 * 0.2 * (39 * sim.dt) * length
    lo, hi = [shift, 0, 0], [length - shift, length, length]
    fresh = build(tmp_path, by_tag(sim, sim.x), setup=LJ + "\nrun 0", lo=lo, hi=hi, name="fresh.data")
    np.testing.assert_allclose(forces_by_tag(sim), forces_by_tag(fresh), rtol=1e-9, atol=1e-9)


def test_particles_outside_the_group_stay_put(tmp_path):
    x, length = scene(tmp_path)
    sim = build(tmp_path, x, setup=LJ + "\ngroup low id 1:60\nrun 0", hi=(length,) * 3)
    sim.change_box([0, 0, 0], [length * 1.1, length, length], remap="low")
    moved = by_tag(sim, sim.x)
    np.testing.assert_allclose(moved[60:], x[60:], rtol=0, atol=0)
    np.testing.assert_allclose(moved[:60, 0], x[:60, 0] * 1.1, rtol=1e-13)


@pytest.mark.parametrize("lo, hi", [([0, 0, 0], [5, 5, -1]), ([0, 0, 0], [5, np.inf, 5]), ([0, 0, np.nan], [5, 5, 5])])
def test_impossible_bounds_are_one_line(tmp_path, lo, hi):
    x, length = scene(tmp_path)
    sim = build(tmp_path, x, setup=LJ, hi=(length,) * 3)
    with pytest.raises(SimulationError) as caught:
        sim.change_box(lo, hi)
    assert "every side must stay finite and longer than 0" in str(caught.value)
    assert "\n" not in str(caught.value)


def test_two_ranks_follow_the_changing_box(tmp_path):
    """fix deform (remap x) with migration between 2 sub-domains gives the 1-rank thermo."""
    x, length = scene(tmp_path)
    v = np.random.default_rng(5).normal(0, 0.7, x.shape)
    build(tmp_path, x, v=v, hi=(length,) * 3, name="box.data")
    script = (f"units lj\nread_data box.data\n{LJ}\nfix 1 all nve\nfix 2 all deform 1 x erate 0.3 y erate -0.2 "
              "units box\nthermo 20\nthermo_style custom step temp pe press vol\nthermo_modify format float %.15g\n"
              "run 100\n")
    serial = thermo_rows(run_ranks(script, 1, tmp_path).stdout)
    parallel = thermo_rows(run_ranks(script.replace("run 100", "processors 2 1 1\nrun 100"), 2, tmp_path).stdout)
    assert len(serial) == 6
    np.testing.assert_allclose(parallel, serial, rtol=1e-9, atol=1e-10)
