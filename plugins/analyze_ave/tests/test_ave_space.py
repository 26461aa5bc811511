"""ave/space on particles placed on known planes: exact counts per bin, number and mass densities over
the bin volume (area in 2-d), time averages of particles crossing a bin boundary at a known step."""

import numpy as np
import pytest

from pdps_core.api import ScriptError


@pytest.fixture
def planes(make_sim):
    """A 4 x 4 x 10 box: 3 particles of type 1 on z = 0.5, 5 of type 2 on z = 2.5, 2 of type 1 on
    z = 7.25, all at rest (no pair style, no integrator)."""
    sim = make_sim()
    lines = ["units lj", "region box block 0 4 0 4 0 10", "create_box 2 box", "mass 1 1.0", "mass 2 3.0",
             "group heavy type 2"]
    for count, z, t in ((3, 0.5, 1), (5, 2.5, 2), (2, 7.25, 1)):
        lines += [f"create_particle {t} single {0.5 + k * 0.7} {1.5 + 0.3 * k} {z}" for k in range(count)]
    sim.command("\n".join(lines))
    return sim


def read(path):
    with open(path) as handle:
        return handle.read()


def test_number_density_of_planes_in_unit_slabs(planes):
    planes.command("analyze 1 all ave/space 1 1 1 z lower 1 density/number file rho.txt\nrun 0")
    table = planes.analyzes["1"].array(planes)
    counts = [3, 0, 5, 0, 0, 0, 0, 2, 0, 0]
    np.testing.assert_array_equal(table[:, 0], np.arange(10) + 0.5)
    np.testing.assert_array_equal(table[:, 1], counts)
    np.testing.assert_array_equal(table[:, 2], np.array(counts) / 16.0)
    assert read("rho.txt") == ("# Spatial-averaged data for analyze 1 and group all\n"
                               "# Timestep Number-of-bins\n# Bin Coord Ncount density/number\n0 10\n"
                               + "".join(f"  {b + 1} {b + 0.5:g} {c} {c / 16:g}\n" for b, c in enumerate(counts)))


def test_bins_start_at_the_origin_and_edge_bins_count_their_part_in_the_box(planes):
    """center 3 in 0..10: bins -1..2, 2..5, 5..8, 8..11 (LAMMPS); the edge bins hold 2 of their 3."""
    planes.command("analyze 1 all ave/space 1 1 1 z center 3 density/number\nrun 0")
    table = planes.analyzes["1"].array(planes)
    np.testing.assert_array_equal(table[:, 0], [0.5, 3.5, 6.5, 9.5])
    np.testing.assert_array_equal(table[:, 1], [3, 5, 2, 0])
    np.testing.assert_allclose(table[:, 2], [3 / 32, 5 / 48, 2 / 48, 0], rtol=1e-15)


def test_mass_density_weighs_each_type_and_a_group_counts_only_its_own(planes):
    planes.command("analyze 1 all ave/space 1 1 1 z lower 5 density/mass density/number\n"
                   "analyze 2 heavy ave/space 1 1 1 z lower 5 density/mass\nrun 0")
    table = planes.analyzes["1"].array(planes)
    np.testing.assert_allclose(table[:, 2], [(3 * 1.0 + 5 * 3.0) / 80, 2 * 1.0 / 80], rtol=1e-15)
    np.testing.assert_allclose(table[:, 3], [8 / 80, 2 / 80], rtol=1e-15)
    heavy = planes.analyzes["2"].array(planes)
    np.testing.assert_array_equal(heavy[:, 1], [5, 0])
    np.testing.assert_allclose(heavy[:, 2], [5 * 3.0 / 80, 0], rtol=1e-15)


def test_time_average_of_a_particle_crossing_into_the_next_bin(make_sim):
    """z = 0.5 + 0.25 n: samples at steps 1..4 see it at 0.75 (bin 0), then 1.0, 1.25, 1.5 (bin 1)."""
    sim = make_sim()
    sim.command("units lj\nregion box block 0 2 0 2 0 4\ncreate_box 1 box\nmass 1 2.0\n"
                "create_particle 1 single 1 1 0.5\nvelocity all set 0.5 0.0 0.5\ntimestep 0.5\nfix 1 all nve\n"
                "analyze 1 all ave/space 1 4 4 z lower 1 density/number density/mass vx vz file z.txt\nrun 4")
    table = sim.analyzes["1"].array(sim)
    np.testing.assert_array_equal(table[:, 1], [0.25, 0.75, 0, 0])
    np.testing.assert_array_equal(table[:, 2], [0.25 / 4, 0.75 / 4, 0, 0])
    np.testing.assert_array_equal(table[:, 3], [0.5 / 4, 1.5 / 4, 0, 0])
    np.testing.assert_array_equal(table[:, 4], [0.5, 0.5, 0, 0])          # vx: in visited bins only
    np.testing.assert_array_equal(table[:, 5], [0.5, 0.5, 0, 0])
    assert read("z.txt").splitlines()[2:5] == ["# Bin Coord Ncount density/number density/mass vx vz",
                                               "4 4", "  1 0.5 0.25 0.0625 0.125 0.5 0.5"]


def test_two_dimensional_bins_divide_by_area(make_sim):
    sim = make_sim()
    sim.command("units lj\ndimension 2\nregion box block 0 6 0 3 -0.5 0.5\ncreate_box 1 box\nmass 1 1\n"
                "create_particle 1 single 0.2 0.5 0\ncreate_particle 1 single 0.4 2.5 0\n"
                "create_particle 1 single 4.1 1.5 0\n"
                "analyze 1 all ave/space 1 1 1 x lower 2 density/number\n"
                "analyze 2 all ave/space 1 1 1 x lower 2 y lower 1.5 density/number file xy.txt\nrun 0")
    np.testing.assert_array_equal(sim.analyzes["1"].array(sim)[:, 2], [2 / 6, 0, 1 / 6])
    table = sim.analyzes["2"].array(sim)
    # bins ordered with x slowest (LAMMPS): (x, y) = (1, 0.75) (1, 2.25) (3, 0.75) ...
    np.testing.assert_array_equal(table[:, :2], [[1, 0.75], [1, 2.25], [3, 0.75], [3, 2.25], [5, 0.75], [5, 2.25]])
    np.testing.assert_array_equal(table[:, 3], np.array([1, 1, 0, 0, 0, 1]) / 3.0)
    assert read("xy.txt").splitlines()[2] == "# Bin Coord1 Coord2 Ncount density/number"
    with pytest.raises(ScriptError, match="cannot bin along z in a 2-d simulation"):
        sim.command("analyze 3 all ave/space 1 1 1 z lower 1 density/number")


def test_fix_ave_spatial_bins_in_lattice_spacings_by_default(planes):
    planes.command("lattice spacing x 2 y 2 z 2.5\n"
                   "fix 1 all ave/spatial 1 1 1 z lower 2 density/number file lat.txt\n"
                   "fix 2 all ave/spatial 1 1 1 z lower 5 density/number units box\nrun 0")
    np.testing.assert_array_equal(planes.fixes["1"].array(planes)[:, 1], [8, 2])
    np.testing.assert_array_equal(planes.fixes["2"].array(planes)[:, 1], [8, 2])
    assert read("lat.txt").startswith("# Spatial-averaged data for fix 1 and group all\n")


@pytest.mark.parametrize("command, message", [
    ("analyze 1 all ave/space 2 1 5 z lower 1 density/number",
     "analyze: nfreq must be a multiple of nevery (got nevery 2, nfreq 5)"),
    ("analyze 1 all ave/space 1 6 5 z lower 1 density/number",
     "analyze: nrepeat * nevery must not exceed nfreq (got 6 * 1 = 6 > 5)"),
    ("analyze 1 all ave/space 0 1 5 z lower 1 density/number", "analyze: nevery must be > 0 (got 0)"),
    ("analyze 1 all ave/space 1 1 5 density/number",
     "analyze: missing argument bins (got density/number); usage: analyze ID GROUP ave/space NEVERY NREPEAT NFREQ "
     "DIM ORIGIN DELTA [DIM ORIGIN DELTA]... value... [file NAME] [units box|lattice]"),
    ("analyze 1 all ave/space 1 1 5 z middle 1 density/number",
     "analyze: bins z: origin must be lower|center|upper or a finite number (got middle)"),
    ("analyze 1 all ave/space 1 1 5 z lower 0 density/number",
     "analyze: bins z: delta must be > 0 (got 0)"),
    ("analyze 1 all ave/space 1 1 5 z lower 1 z upper 1 density/number", "analyze: axis z is binned twice"),
    ("analyze 1 all ave/space 1 1 5 z lower 1 file x.txt",
     "analyze: missing argument values; usage: analyze ID GROUP ave/space NEVERY NREPEAT NFREQ "
     "DIM ORIGIN DELTA [DIM ORIGIN DELTA]... value... [file NAME] [units box|lattice]"),
    ("analyze 1 all ave/space 1 1 5 z lower 1 density/number temp",
     "analyze: values must be density/number, density/mass, vx, vy, vz, fx, fy, fz, c_ID, c_ID[k], f_ID, f_ID[k] "
     "or v_NAME (got temp)"),
    ("fix 1 all ave/spatial 1 1 5 z lower 1 density/number units reduced",
     "fix: units must be one of 'box' or 'lattice' (got reduced)"),
])
def test_bad_input_is_one_line(planes, command, message):
    with pytest.raises(ScriptError) as error:
        planes.command(command)
    assert str(error.value) == f"<command>:1: {message}"
