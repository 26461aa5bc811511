"""Computes temp, pressure and centroid against values worked out independently in the test:

    T = sum m v^2 / (d N - d),   P = (N_dof T + sum_pairs r_ij . F_ij) / (d V),
    centroid = mean of unwrapped positions x + image * L.
"""

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import make_box


def make(setup, boundary="p p p", box="0 10 0 10 0 10", ntypes=1, dimension=3):
    return make_box(setup, box=box, boundary=boundary, ntypes=ntypes, dimension=dimension)


def masses_of(sim, table):
    return np.array([table[int(t)] for t in sim.type])


# ---- temp ---------------------------------------------------------------------------------------
def _mixed_system(dimension=3):
    rng = np.random.default_rng(5)
    sim = make("""
        mass 1 1.0
        mass 2 3.0
        lattice spacing x 2 y 2 z 2
        create_particle 1 box
    """, ntypes=2, dimension=dimension)
    sim.type[1::3] = 2
    sim.command("group heavy type 2\ngroup light type 1")
    v = rng.normal(size=sim.v.shape) + [0.3, -0.1, 0.2]
    if dimension == 2:
        v[:, 2] = 0.0
    sim.v[:] = v
    return sim


@pytest.mark.parametrize("dimension", [3, 2])
def test_temp_of_hand_set_velocities(dimension):
    sim = _mixed_system(dimension)
    sim.command("compute t all temp\ncompute th heavy temp\ncompute tl light temp")
    m = masses_of(sim, {1: 1.0, 2: 3.0})
    mv2 = m * (sim.v ** 2).sum(axis=1)
    d = dimension
    heavy = sim.type == 2
    assert 2 < heavy.sum() < len(heavy) - 2
    assert sim.compute_value("t") == pytest.approx(mv2.sum() / (d * len(m) - d), rel=1e-13)
    assert sim.compute_value("th") == pytest.approx(mv2[heavy].sum() / (d * heavy.sum() - d), rel=1e-13)
    assert sim.compute_value("tl") == pytest.approx(mv2[~heavy].sum() / (d * (~heavy).sum() - d),
                                                    rel=1e-13)


def test_temp_follows_the_velocities_and_counts_only_its_group():
    sim = _mixed_system()
    sim.command("compute th heavy temp")
    before = sim.compute_value("th")
    sim.v[sim.type == 1] *= 10.0
    assert sim.compute_value("th") == before
    sim.v[sim.type == 2] *= 2.0
    assert sim.compute_value("th") == pytest.approx(4.0 * before, rel=1e-13)


def test_temp_of_a_single_particle_or_empty_group_is_zero():
    """No degrees of freedom left after removing the centre of mass: T = 0, not a division by 0."""
    sim = make("mass 1 1\ncreate_particle 1 single 1 1 1\nregion far block 5 6 5 6 5 6\n"
               "group none region far\ncompute t all temp\ncompute t0 none temp")
    sim.v[:] = [1.0, 2.0, 3.0]
    assert sim.compute_value("t") == 0.0
    assert sim.compute_value("t0") == 0.0


# ---- pressure -----------------------------------------------------------------------------------
def _two_body(x, v, box="0 20 0 20 0 20", dimension=3, extra=""):
    sim = make(f"""
        mass 1 1.5
        create_particle 1 single {x[0][0]} {x[0][1]} {x[0][2]}
        create_particle 1 single {x[1][0]} {x[1][1]} {x[1][2]}
        pair_style dpd 0.0 1.0 7
        pair_coeff 1 1 25.0 0.0
        compute t all temp
        compute p all pressure
        {extra}
    """, box=box, dimension=dimension)
    sim.v[:] = v
    sim.command("run 0")
    return sim


def _expected_pressure(delta, v, mass, volume, dimension=3, a=25.0, rc=1.0):
    r = np.linalg.norm(delta)
    force = a * (1.0 - r / rc) * delta / r          # on i from j, delta = x_i - x_j
    kinetic = mass * (np.asarray(v) ** 2).sum()      # N_dof T = 2 KE
    return (kinetic + delta @ force) / (dimension * volume)


@pytest.mark.parametrize("x, delta", [
    ([[10.0, 10.0, 10.0], [10.4, 10.3, 9.9]], [-0.4, -0.3, 0.1]),
    ([[0.1, 5.0, 5.0], [19.7, 5.2, 5.0]], [0.4, -0.2, 0.0]),       # across the x face
    ([[0.1, 19.9, 0.2], [19.8, 0.3, 19.9]], [0.3, -0.4, 0.3]),     # across a corner
])
def test_pressure_is_kinetic_plus_pair_virial(x, delta):
    v = np.array([[0.5, -1.0, 0.25], [-0.2, 0.4, 1.0]])
    sim = _two_body(x, v)
    expected = _expected_pressure(np.array(delta), v, 1.5, 20.0 ** 3)
    assert sim.compute_value("p") == pytest.approx(expected, rel=1e-10)
    # the virial alone is repulsive (positive) here
    assert expected > 1.5 * (v ** 2).sum() / (3 * 20.0 ** 3)


def test_pressure_with_named_temperature_compute_of_group_all():
    v = np.array([[0.5, -1.0, 0.25], [-0.2, 0.4, 1.0]])
    x = [[10.0, 10.0, 10.0], [10.5, 10.0, 10.0]]
    sim = _two_body(x, v, extra="compute p2 all pressure t")
    assert sim.compute_value("p2") == pytest.approx(sim.compute_value("p"), rel=1e-14)
    assert sim.compute_value("p2") == pytest.approx(
        _expected_pressure(np.array([-0.5, 0, 0]), v, 1.5, 20.0 ** 3), rel=1e-10)


def test_pressure_in_two_dimensions_uses_area():
    v = np.array([[0.5, -1.0, 0.0], [-0.2, 0.4, 0.0]])
    x = [[5.0, 5.0, 0.0], [5.3, 5.4, 0.0]]
    sim = _two_body(x, v, box="0 10 0 8 -0.5 0.5", dimension=2)
    expected = _expected_pressure(np.array([-0.3, -0.4, 0.0]), v, 1.5, 80.0, dimension=2)
    assert sim.compute_value("p") == pytest.approx(expected, rel=1e-10)


def test_pressure_without_pair_style_is_ideal_gas():
    sim = make("mass 1 2.0\ncreate_particle 1 single 1 1 1\ncreate_particle 1 single 3 3 3\n"
               "compute p all pressure")
    sim.v[:] = [[1.0, 0.0, 0.0], [0.0, -2.0, 1.0]]
    sim.command("run 0")
    assert sim.compute_value("p") == pytest.approx(2.0 * (1 + 4 + 1) / (3 * 1000.0), rel=1e-13)


def test_pressure_needs_group_all():
    sim = make("mass 1 1\ncreate_particle 1 single 1 1 1\ngroup some type 1")
    with pytest.raises(ScriptError, match="compute pressure needs group all \\(got some\\)"):
        sim.command("compute p some pressure")
    assert "p" not in sim.computes


def test_pressure_with_unknown_temperature_compute_is_an_error():
    sim = make("mass 1 1\ncreate_particle 1 single 1 1 1")
    with pytest.raises(ScriptError, match="compute nope is not defined"):
        sim.command("compute p all pressure nope")


# ---- centroid -----------------------------------------------------------------------------------
def test_centroid_is_unwrapped_across_periodic_faces():
    """Three particles drift through the +x face: the centroid moves on smoothly past the box."""
    sim = make("""
        mass 1 1.0
        create_particle 1 single 9.5 5.0 5.0
        create_particle 1 single 9.7 5.5 5.0
        create_particle 1 single 9.9 6.0 5.0
        compute c all centroid
        timestep 0.01
        fix 1 all nve
    """)
    sim.v[:] = [1.0, 0.0, 0.0]
    start = np.array([9.7, 5.5, 5.0])
    np.testing.assert_allclose([sim.compute_value("c", (i,)) for i in range(3)], start, rtol=1e-14)
    sim.command("run 100")
    assert np.all(sim.x[:, 0] < 1.0)       # all wrapped to the low side
    centroid = [sim.compute_value("c", (i,)) for i in range(3)]
    np.testing.assert_allclose(centroid, start + [1.0, 0.0, 0.0], rtol=1e-12)


def test_centroid_uses_image_flags_and_its_group(tmp_path, make_sim):
    path = tmp_path / "data.img"
    path.write_text("""image flags

3 atoms
2 atom types
0 4 xlo xhi
0 5 ylo yhi
0 6 zlo zhi

Masses

1 1.0
2 1.0

Atoms # atomic

1 1 1.0 1.0 1.0 0 0 0
2 1 3.0 2.0 1.0 1 -1 0
3 2 2.0 2.0 2.0 0 0 2
""")
    sim = make_sim()
    sim.command(f"read_data {path}\ngroup one type 1\ncompute c all centroid\ncompute c1 one centroid")
    unwrapped = np.array([[1.0, 1.0, 1.0], [7.0, -3.0, 1.0], [2.0, 2.0, 14.0]])
    for ident, rows in (("c", [0, 1, 2]), ("c1", [0, 1])):
        got = [sim.compute_value(ident, (i,)) for i in range(3)]
        np.testing.assert_allclose(got, unwrapped[rows].mean(axis=0), rtol=1e-14)
