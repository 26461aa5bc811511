"""fix ave/euler on spheres placed in known cells: counts, volume fractions, masses, Favre-averaged
velocities, radii and the velocity-fluctuation stress by hand; the grid's rounding; nevery; a base
volume region; the errors of bad input."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import liggghts_material

# a unit box; one type of sphere, its largest radius 0.05 so the gran cutoff is 0.1: with
# cell_size_relative 2.5, cells of 0.25 (4 by 4 by 4)
SPHERES = [  # x, y, z, diameter, density, vx, vy, vz
    (0.1, 0.1, 0.1, 0.10, 1000.0, 1.0, 0.0, -0.5),
    (0.2, 0.15, 0.1, 0.06, 3000.0, -2.0, 0.5, 0.0),
    (0.6, 0.1, 0.9, 0.08, 2000.0, 0.0, 0.0, 0.3),
    (0.4875, 0.6, 0.4, 0.04, 1000.0, 1.0, 0.0, 0.0),
]


def scene(make_sim, fix, spheres=SPHERES, integrate=False):
    sim = make_sim()
    lines = ["atom_style granular", "atom_modify map array", "boundary f f f", "units si",
             "region box block 0 1 0 1 0 1 units box", "create_box 1 box",
             liggghts_material(5.e6, 0.45, 0.9, 0.3).rstrip(), "pair_style gran model hertz tangential history",
             "pair_coeff * *", "timestep 0.001"]
    for k, (x, y, z, d, rho, *_) in enumerate(spheres, start=1):
        lines += [f"create_atoms 1 single {x} {y} {z} units box", f"set atom {k} diameter {d} density {rho}"]
    if integrate:
        lines.append("fix integr all nve/sphere")
    lines.append(fix)
    sim.command("\n".join(lines))
    p = sim.particles
    for k, sphere in enumerate(spheres, start=1):
        p.v[p.index_of_tag(k)] = sphere[5:8]
    return sim


def mass(d, rho):
    return rho * math.pi / 6 * d ** 3


def test_counts_volume_fraction_mass_velocity_radius_and_stress_by_hand(make_sim):
    sim = scene(make_sim, "fix eu all ave/euler nevery 1 cell_size_relative 2.5 parallel no")
    sim.command("run 0")
    table = sim.fixes["eu"].array(sim)
    assert table.shape == (64, 17)
    edge = 0.25
    iz, iy, ix = np.unravel_index(np.arange(64), (4, 4, 4))
    np.testing.assert_allclose(table[:, :3], np.column_stack([ix, iy, iz]) * edge + edge / 2, rtol=1e-15)
    a, b, c, d = SPHERES
    volume = edge ** 3
    # cell 0 holds the first two
    ma, mb = mass(*a[3:5]), mass(*b[3:5])
    va, vb = np.array(a[5:]), np.array(b[5:])
    vav = (ma * va + mb * vb) / (ma + mb)
    row = table[0]
    assert row[15] == 2
    assert row[16] == pytest.approx(ma + mb, rel=1e-14)
    assert row[3] == pytest.approx(math.pi / 6 * (a[3] ** 3 + b[3] ** 3) / volume, rel=1e-14)
    np.testing.assert_allclose(row[4:7], vav, rtol=1e-14)
    assert row[14] == pytest.approx((a[3] + b[3]) / 4, rel=1e-14)
    dva, dvb = va - vav, vb - vav
    tensor = -(ma * np.outer(dva, dva) + mb * np.outer(dvb, dvb)) / volume
    np.testing.assert_allclose(row[8:14], [tensor[0, 0], tensor[1, 1], tensor[2, 2], tensor[0, 1], tensor[0, 2],
                                           tensor[1, 2]], rtol=1e-12, atol=1e-12)
    assert row[7] == pytest.approx(-np.trace(tensor) / 3, rel=1e-12)
    # the third in cell (2, 0, 3), the fourth in (1, 2, 1): one sphere each, no fluctuation
    for sphere, cell in ((c, 3 * 16 + 0 * 4 + 2), (d, 1 * 16 + 2 * 4 + 1)):
        row = table[cell]
        assert row[15] == 1
        assert row[16] == pytest.approx(mass(*sphere[3:5]), rel=1e-14)
        assert row[3] == pytest.approx(math.pi / 6 * sphere[3] ** 3 / volume, rel=1e-14)
        np.testing.assert_allclose(row[4:7], sphere[5:], rtol=1e-14, atol=1e-15)
        np.testing.assert_allclose(row[7:14], 0.0, atol=1e-12)
    empty = np.setdiff1d(np.arange(64), [0, 50, 25])
    np.testing.assert_array_equal(table[empty, 3:], 0.0)
    # f_eu[i][j] counts rows and columns from the dialect's first index
    base = sim.dialect.index_base
    assert sim.fix_value("eu", (base, base + 3)) == table[0, 3]


def test_the_grid_rounds_the_cell_count_down(make_sim):
    """2.2 times 0.1 is 0.22: int(1 / 0.22) = 4 cells of 0.25 per axis."""
    sim = scene(make_sim, "fix eu all ave/euler nevery 1 cell_size_relative 2.2 parallel yes")
    sim.command("run 0")
    assert sim.fixes["eu"].array(sim).shape == (64, 17)
    sim = scene(make_sim, "fix eu all ave/euler nevery 1 cell_size_relative 3.4 parallel yes")
    sim.command("run 0")
    table = sim.fixes["eu"].array(sim)
    assert table.shape == (8, 17)
    np.testing.assert_allclose(table[7, :3], [0.75, 0.75, 0.75])


def test_the_group_chooses_the_particles(make_sim):
    sim = scene(make_sim, "group first id 1\nfix eu first ave/euler nevery 1 cell_size_relative 2.5 parallel no")
    sim.command("run 0")
    table = sim.fixes["eu"].array(sim)
    assert table[:, 15].sum() == 1
    np.testing.assert_allclose(table[0, 4:7], SPHERES[0][5:], rtol=1e-15)


def test_values_are_those_of_the_last_multiple_of_nevery(make_sim):
    """The fourth sphere moves at 1 m/s from x = 0.4875: in cell ix = 1 up to step 12, ix = 2 after."""
    moving = 1 * 16 + 2 * 4
    for nevery, ix in ((10, 1), (5, 2)):
        sim = scene(make_sim, f"fix eu all ave/euler nevery {nevery} cell_size_relative 2.5 parallel no",
                    integrate=True)
        sim.command("run 15")
        table = sim.fixes["eu"].array(sim)
        assert table[moving + ix, 15] == 1 and table[moving + 3 - ix, 15] == 0


def test_a_base_volume_region_weights_the_cells(make_sim):
    """A region of the lower half: 50 points per cell drawn over the box, each in the region adding
    1/50 to its cell's weight (capped at 1); cells above z = 0.5 get none, so their volume
    fraction is 0, but for the one with a sphere, which gets 1/50 (LIGGGHTS's)."""
    sim = scene(make_sim, "region low block INF INF INF INF INF 0.5 units box\n"
                          "fix eu all ave/euler nevery 1 cell_size_relative 2.5 parallel no basevolume_region low")
    sim.command("run 0")
    fix = sim.fixes["eu"]
    from pdps_analyze_ave.ave_euler import park_miller_points
    points, _ = park_miller_points(15485863, 64 * 50, np.zeros(3), np.ones(3))
    points = points[points[:, 2] <= 0.5]
    cell = (np.floor(points[:, 2] / 0.25) * 16 + np.floor(points[:, 1] / 0.25) * 4
            + np.floor(points[:, 0] / 0.25)).astype(int)
    expected = np.minimum(np.bincount(cell, minlength=64) / 50, 1.0)
    expected[50] = 1 / 50
    np.testing.assert_allclose(fix.weight, expected, rtol=1e-15)
    assert 0.7 < fix.weight[:32].min() and fix.weight[:32].mean() > 0.9
    table = fix.array(sim)
    assert table[50, 3] == pytest.approx(math.pi / 6 * 0.08 ** 3 / 0.25 ** 3 * 50, rel=1e-12)
    assert table[0, 3] == pytest.approx(math.pi / 6 * (0.1 ** 3 + 0.06 ** 3) / 0.25 ** 3 / expected[0], rel=1e-14)


def test_the_park_miller_points_are_liggghts_generator():
    from pdps_analyze_ave.ave_euler import park_miller_points
    points, seed = park_miller_points(15485863, 2, np.zeros(3), np.ones(3))
    expected, state = [], 15485863
    for _ in range(6):
        state = state * 16807 % 2147483647
        expected.append(state / 2147483647)
    np.testing.assert_allclose(points.ravel(), expected, rtol=1e-15)
    assert seed == state


USAGE = "fix ID GROUP ave/euler nevery N cell_size_relative S parallel yes|no [basevolume_region R]"


@pytest.mark.parametrize("fix, message", [
    ("fix eu all ave/euler cell_size_relative 3 parallel no", f"fix: missing keyword nevery; usage: {USAGE}"),
    ("fix eu all ave/euler nevery 0 cell_size_relative 3 parallel no", "fix: nevery must be >= 1 (got 0)"),
    ("fix eu all ave/euler nevery 10 cell_size_relative 0.5 parallel no",
     "fix: cell_size_relative must be >= 1 (got 0.5)"),
    ("fix eu all ave/euler nevery 10 cell_size_relative 3 parallel maybe",
     "fix: parallel must be yes or no (got maybe)"),
    ("fix eu all ave/euler nevery 10 cell_size_relative 3 parallel no basevolume_region nowhere",
     "fix: region nowhere is not defined (defined: box)"),
])
def test_bad_input_is_one_line_naming_it(make_sim, fix, message):
    with pytest.raises(ScriptError) as error:
        scene(make_sim, fix)
    assert str(error.value) == f"<command>:22: {message}"


def test_no_pair_style_is_refused(make_sim):
    sim = make_sim()
    sim.command("atom_style granular\nunits si\nregion box block 0 1 0 1 0 1 units box\ncreate_box 1 box\n"
                "create_atoms 1 single 0.5 0.5 0.5 units box\n"
                "fix eu all ave/euler nevery 1 cell_size_relative 3 parallel no")
    with pytest.raises(ScriptError, match="needs a pair style"):
        sim.command("run 0")


def test_a_contact_adds_its_virial_to_the_stress(make_sim):
    """Two touching spheres at rest in one cell: sigma = -(x_a - x_b) (x) F_ab / V, F_ab the contact
    force on a (each particle's half of it summed)."""
    pair = [(0.1, 0.1, 0.1, 0.1, 1000.0, 0.0, 0.0, 0.0), (0.19, 0.12, 0.13, 0.1, 1000.0, 0.0, 0.0, 0.0)]
    sim = scene(make_sim, "fix eu all ave/euler nevery 1 cell_size_relative 2.5 parallel no", spheres=pair)
    sim.command("run 0")
    found = sim.pair.contacts(sim)
    assert len(found["i"]) == 1
    p = sim.particles
    i, j = int(found["i"][0]), int(found["j"][0])
    tensor = -np.outer(p.x[i] - p.x[j], found["force"][0]) / 0.25 ** 3
    row = sim.fixes["eu"].array(sim)[0]
    np.testing.assert_allclose(row[8:14], [tensor[0, 0], tensor[1, 1], tensor[2, 2], tensor[0, 1], tensor[0, 2],
                                           tensor[1, 2]], rtol=1e-12)
    assert row[7] > 0       # a compressed contact: positive pressure


def test_the_stress_of_the_bed_is_the_same_on_two_ranks(tmp_path):
    """The recorded bed (tests/data/liggghts.cases.json, ave_euler) with its cells' pressures and
    stresses printed as well (columns LIGGGHTS does not let thermo read), contacts among them: the
    same on 1 and 2 ranks, each contact's virial sent home from ghosts."""
    import json
    from pathlib import Path

    from pdps_core.testing import thermo_on_ranks
    table = json.loads((Path(__file__).parent / "data" / "liggghts.cases.json").read_text())
    script = table["cases"]["ave_euler"]["script"].replace(
        "v_s15\n", "v_s15 f_eu[5][8] f_eu[5][9] f_eu[2][8] f_eu[4][13] f_eu[1][8] f_eu[1][16] f_eu[1][17]\n")
    assert "f_eu[5][8]" in script
    one, two = thermo_on_ranks(script, tmp_path)
    np.testing.assert_allclose(two, one, rtol=1e-10, atol=1e-13)
    assert np.abs(one[:, -7:-2]).max() > 100.0      # contacts: stresses far above the kinetic part
