"""The core commands: what each does, and the error each gives for bad input."""

import math
import textwrap

import numpy as np
import pytest

from pdps_core.state.lattice import USAGE
from pdps_core.errors import ScriptError
from pdps_core.simulation import Simulation
from pdps_core.state import observables as obs
from pdps_core.styles import registry


def box(ntypes=1, bounds="0 4 0 4 0 4", before=""):
    """Script text: settings, a block region ``box`` and the simulation box made from it."""
    return f"{before}\nregion box block {bounds}\ncreate_box {ntypes} box\n"


def run(sim, script):
    sim.command(textwrap.dedent(script))
    return sim


def fails(sim, script, command=None, message=None):
    """The ScriptError a script raises; checks its command and message when given."""
    with pytest.raises(ScriptError) as info:
        sim.command(textwrap.dedent(script))
    exc = info.value
    if command is not None:
        assert exc.command == command, str(exc)
    if message is not None:
        assert exc.message == message, str(exc)
    return exc


def thermo_rows(text):
    """The numbers of every thermo table in screen text, one list of rows per run."""
    tables, rows = [], None
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            rows = []
            tables.append(rows)
        elif words[:2] == ["Loop", "time"]:
            rows = None
        elif rows is not None and words:
            rows.append([float(w) for w in words])
    return tables


def min_image_distance(sim):
    x, length = sim.x, sim.box.length
    delta = x[:, None, :] - x[None, :, :]
    periodic = np.array(sim.box.periodic)
    delta = np.where(periodic, delta - length * np.round(delta / length), delta)
    r = np.sqrt((delta ** 2).sum(axis=-1))
    np.fill_diagonal(r, np.inf)
    return r.min()


# ---- initialization ------------------------------------------------------------------------------
class TestUnits:
    def test_lj_is_the_default(self, sim):
        assert sim.units.name == "lj"
        assert (sim.dt, sim.neighbor.skin, sim.units.boltz) == (0.005, 0.3, 1.0)

    def test_si_sets_its_time_step_skin_and_boltzmann_constant(self, sim):
        run(sim, "units si")
        assert (sim.units.name, sim.dt, sim.neighbor.skin) == ("si", 1e-8, 0.001)
        assert sim.units.boltz == 1.3806504e-23      # LAMMPS's value (its update.cpp)

    def test_temperature_in_si(self, sim):
        run(sim, "units si\nlattice sc 1e-9" + box(bounds="0 4e-9 0 4e-9 0 4e-9") +
            "mass 1 3e-26\ncreate_particle 1 box\nvelocity all create 300 5")
        assert sim.nlocal == 64
        assert obs.temperature(sim) == pytest.approx(300, rel=1e-12)

    def test_errors(self, sim):
        fails(sim, "units electron", "units", "units style must be one of lj, real, metal, si, cgs, micro, nano "
                                             "(got electron)")
        fails(sim, "units", "units", "expected 1 argument(s), got 0; usage: units lj|real|metal|si|cgs|micro|nano")
        fails(sim, box() + "units si", "units", "units must come before the simulation box is created")


class TestDimension:
    def test_default_is_3(self, sim):
        run(sim, box(bounds="0 4 0 4 2 3"))
        assert sim.dimension == 3
        assert sim.box.lo[2] == 2 and sim.box.hi[2] == 3

    def test_2d_box_is_thin_around_z_0(self, sim):
        run(sim, box(before="dimension 2", bounds="0 4 0 3 0 0"))
        assert sim.dimension == sim.box.dimension == 2
        assert (sim.box.lo[2], sim.box.hi[2]) == (-0.5, 0.5)
        assert sim.box.volume == 12          # area in 2-d

    def test_2d_particles_stay_in_the_plane(self, sim):
        run(sim, box(before="dimension 2", bounds="0 4 0 4 -1 1") +
            "mass 1 1\ncreate_particle 1 single 1 2 0.7\nvelocity all create 1.0 3")
        assert sim.x[0, 2] == 0.0
        assert np.all(sim.v[:, 2] == 0.0)

    def test_errors(self, sim):
        fails(sim, "dimension 4", "dimension", "dimension must be one of 2, 3 (got 4)")
        fails(sim, "dimension 2 3", "dimension", "expected 1 argument(s), got 2; usage: dimension 2|3")
        fails(sim, "dimension 2\nboundary p p f" + box(), "create_box",
              "a 2-d simulation needs a periodic z boundary (boundary x y p)")

    def test_after_the_box_is_an_error(self, sim):
        fails(sim, box() + "dimension 2", "dimension", "dimension must come before the simulation box is created")


class TestBoundary:
    def test_default_and_mixed(self, sim):
        run(sim, box(before="boundary p f p"))
        assert sim.box.periodic == (True, False, True)

    def test_errors(self, sim):
        fails(sim, "boundary p x p", "boundary", "boundary y must be one of p, f, s, m, ff, fs, fm, sf, ss, sm, mf, "
                                                "ms, mm (got x)")
        fails(sim, "boundary p p", "boundary", "expected 3 argument(s), got 2; usage: boundary x y z  (each p, f, s, "
                                               "m, or two of f, s, m)")
        fails(sim, box() + "boundary f f f", "boundary", "boundary must come before the simulation box is created")


class TestTimestep:
    def test_sets_dt_and_may_change_between_runs(self, sim):
        run(sim, "timestep 0.04")
        assert sim.dt == 0.04
        run(sim, box() + "mass 1 1\ncreate_particle 1 single 1 1 1\nrun 2\ntimestep 0.5\nrun 2")
        assert sim.time == pytest.approx(2 * 0.04 + 2 * 0.5)

    @pytest.mark.parametrize("value, message", [
        ("0", "timestep must be > 0 (got 0)"),
        ("-0.1", "timestep must be > 0 (got -0.1)"),
        ("fast", "timestep must be a number (got fast)"),
        ("nan", "timestep must be finite (got nan)"),
    ])
    def test_errors(self, sim, value, message):
        fails(sim, f"timestep {value}", "timestep", message)


class TestLattice:
    def test_spacing_per_axis(self, sim):
        run(sim, "lattice spacing x 0.5 y 0.5 z 1" + box(bounds="0 2 0 2 0 2") + "create_particle 1 box")
        assert sim.nlocal == 4 * 4 * 2
        x = sim.x
        assert set(np.round(x[:, 0], 12)) == {0, 0.5, 1, 1.5}
        assert set(np.round(x[:, 2], 12)) == {0, 1}

    def test_sc_scale_is_the_reduced_density_in_lj(self, sim):
        run(sim, "lattice sc 0.125" + box() + "create_particle 1 box")   # constant (1/0.125)^(1/3) = 2
        assert sim.nlocal == 8
        assert obs.count(sim) / sim.box.volume == pytest.approx(0.125)

    def test_fcc_density_and_nearest_neighbours(self, sim):
        run(sim, "lattice fcc 4.0" + box() + "create_particle 1 box")    # constant (4/4)^(1/3) = 1
        assert sim.nlocal == 4 * 4 ** 3
        assert sim.nlocal / sim.box.volume == pytest.approx(4.0)
        assert min_image_distance(sim) == pytest.approx(math.sqrt(0.5))

    def test_fcc_scale_is_the_lattice_constant_in_si(self, sim):
        run(sim, "units si\nlattice fcc 2.0" + box() + "create_particle 1 box")
        assert sim.nlocal == 4 * 2 ** 3
        assert min_image_distance(sim) == pytest.approx(2.0 / math.sqrt(2))

    def test_2d_sq(self, sim):
        run(sim, "dimension 2\nlattice sq 1.0" + box(bounds="0 4 0 3 -0.5 0.5") + "create_particle 1 box")
        assert sim.nlocal == 12
        assert np.all(sim.x[:, 2] == 0)

    @pytest.mark.parametrize("line, message", [
        ("lattice", "expected arguments; usage: " + USAGE),
        ("lattice hexagon 1", "lattice style must be one of spacing, none, custom, sc, bcc, fcc, hcp, diamond, "
                              "sq, sq2, hex (got hexagon)"),
        ("lattice hex 1", "lattice hex is a 2-d lattice; this is a 3-d simulation (sc, bcc, fcc, hcp, diamond "
                          "or custom)"),
        ("lattice spacing x 0.5 y", "expected pairs of axis and spacing; usage: " + USAGE),
        ("lattice fcc 1 orient x 1 1 0 orient y 1 0 0", "orient x and y must be orthogonal"),
        ("lattice fcc 1 origin 0.5 1 0", "origin fractions must be >= 0 and < 1 (got 0.5 1 0)"),
        ("lattice fcc 1 basis 0 0 0", "basis is for lattice custom (got lattice fcc)"),
        ("lattice custom 1 a1 1 0 0", "lattice custom needs at least one basis atom"),
        ("lattice spacing w 0.5", "lattice axis must be one of x, y, z (got w)"),
        ("lattice spacing x 0", "lattice spacing x must be > 0 (got 0)"),
        ("lattice fcc -1", "lattice scale must be > 0 (got -1)"),
        ("lattice fcc dense", "lattice scale must be a number (got dense)"),
    ])
    def test_errors(self, sim, line, message):
        fails(sim, line, "lattice", message)


# ---- geometry ------------------------------------------------------------------------------------
class TestRegionAndCreateBox:
    def test_create_box_from_a_block(self, sim):
        run(sim, box(ntypes=3, bounds="-1 2 0 5 0.5 1.5"))
        assert list(sim.box.lo) == [-1, 0, 0.5] and list(sim.box.hi) == [2, 5, 1.5]
        assert sim.ntypes == 3
        assert np.isnan(sim.mass[1:]).all()

    def test_region_errors(self, sim):
        fails(sim, "region", "region", "expected: region ID STYLE args")
        fails(sim, "region r block 0 1 0 1 0 1\nregion r block 0 2 0 2 0 2", "region", "region r is already defined")
        exc = fails(sim, "region r2 blok 0 1 0 1 0 1", "region")
        assert exc.message == (f"unknown region style blok; did you mean block? "
                               f"(installed: {', '.join(registry.names('region'))})")
        fails(sim, "region r3 block 0 1 0 1 0", "region",
              "missing argument zhi; usage: region ID block xlo xhi ylo yhi zlo zhi [side in|out] "
              "[units box|lattice]")

    def test_create_box_errors(self, sim):
        fails(sim, "create_box 1 nowhere", "create_box", "region nowhere is not defined (defined: none)")
        fails(sim, "region box block 0 1 0 1 0 1\ncreate_box 0 box", "create_box", "ntypes must be >= 1 (got 0)")
        fails(sim, "create_box 1", "create_box",
              "expected 2 argument(s), got 1; usage: create_box NTYPES REGION-ID")
        fails(sim, "region flat block 0 1 0 1 0 0\ncreate_box 1 flat", "create_box",
              "box z bounds must have lo < hi (got 0 0)")
        run(sim, "create_box 1 box")
        fails(sim, "create_box 1 box", "create_box", "the simulation box already exists")


# ---- particles -----------------------------------------------------------------------------------
class TestCreateParticle:
    def test_single(self, sim):
        run(sim, box(ntypes=2) + "create_particle 2 single 1.5 2.5 3.5\ncreate_atoms 1 single 0 0 0")
        assert sim.x.tolist() == [[1.5, 2.5, 3.5], [0, 0, 0]]
        assert sim.type.tolist() == [2, 1]
        assert sim.tag.tolist() == [1, 2]

    def test_spacing_and_region_fill_the_region_only(self, sim):
        run(sim, "lattice sc 1" + box() + "region left block 0 2 0 4 0 4\ncreate_particle 1 spacing left")
        assert sim.nlocal == 2 * 4 * 4          # sites in [lo, hi): x = 0, 1
        assert set(sim.x[:, 0]) == {0, 1}
        run(sim, "region top block 0 4 0 4 3 4\ncreate_particle 1 region top")
        assert sim.nlocal == 32 + 16
        assert (sim.x[32:, 2] == 3).all()

    def test_box_fills_a_periodic_box_once(self, sim):
        run(sim, "lattice sc 1" + box() + "create_particle 1 box")
        assert sim.nlocal == 64
        assert min_image_distance(sim) == pytest.approx(1.0)

    def test_random_no_overlap_keeps_periodic_images_apart(self, sim):
        run(sim, box(bounds="0 5 0 5 0 5") + "create_particle 1 random_no_overlap 60 box 1.0 4821")
        assert sim.nlocal == 60
        assert sim.box.inside(sim.x).all()
        assert min_image_distance(sim) >= 1.0

    def test_random_no_overlap_is_reproducible_per_seed(self, make_sim):
        def positions(seed):
            s = make_sim()
            s.command(box() + f"create_particle 1 random_no_overlap 10 box 0.5 {seed}")
            return s.x.copy()
        assert np.array_equal(positions(17), positions(17))
        assert not np.array_equal(positions(17), positions(18))

    def test_random_no_overlap_in_a_region_avoids_existing_particles(self, sim):
        run(sim, box() + "region corner block 0 2 0 2 0 2\ncreate_particle 1 single 1 1 1\n"
                         "create_particle 1 random_no_overlap 5 corner 0.8 99")
        assert sim.nlocal == 6
        assert (sim.x[1:] <= 2).all()
        assert min_image_distance(sim) >= 0.8

    def test_random_no_overlap_in_2d(self, sim):
        run(sim, "dimension 2" + box(bounds="0 6 0 6 -0.5 0.5") + "create_particle 1 random_no_overlap 15 box 1 3")
        assert sim.nlocal == 15
        assert np.all(sim.x[:, 2] == 0)
        assert min_image_distance(sim) >= 1.0

    @pytest.mark.parametrize("bounds, boundary, n", [("0 2.5 0 2.5 0 2000", "p p p", 1500),
                                                     ("0 2.5 0 2.5 0 2000", "f f f", 1500),
                                                     ("0 3 0 3 0 1000", "p p p", 2000),
                                                     ("0 3 0 3 -1e9 1e9", "p p f", 2000)])
    def test_random_no_overlap_in_a_tall_box(self, sim, bounds, boundary, n):
        """Two cells across a periodic face, walls, 9000 cells hashed into 4096 buckets, and an absurd
        box of 2^20 cells along z: the spacing holds between every pair, brute force."""
        run(sim, f"boundary {boundary}" + box(bounds=bounds) + f"create_particle 1 random_no_overlap {n} box 1.0 5")
        assert sim.nlocal == n
        assert sim.box.inside(sim.x).all()
        assert min_image_distance(sim) >= 1.0

    @pytest.mark.parametrize("dimension, bounds, n", [(3, "0 1 0 1 0 1", 10), (2, "0 1 0 1 -0.5 0.5", 10),
                                                      (3, "0 4 0 4 0 4", 1000)])
    def test_too_full_a_region_is_an_error_not_a_hang(self, sim, dimension, bounds, n):
        exc = fails(sim, f"dimension {dimension}" + box(bounds=bounds) +
                    f"create_particle 1 random_no_overlap {n} box 1.0 7", "create_particle")
        assert exc.message.startswith(f"placed only ")
        assert exc.message.endswith("the region is too full")
        assert f" of {n} particles in region box without overlap" in exc.message
        assert sim.nlocal == 0                   # nothing is half-created

    def test_sphere_diameter_and_density(self, sim):
        run(sim, "particle_style sphere" + box() +
            "create_particle 1 single 1 1 1 diameter 2 density 3\ncreate_particle 1 single 3 3 3")
        assert sim.particles.radius.tolist() == [1.0, 0.5]
        assert sim.particles.rmass == pytest.approx([3 * 4 / 3 * math.pi, 4 / 3 * math.pi * 0.125])

    @pytest.mark.parametrize("line, message", [
        ("create_particle 3 single 1 1 1", "type must be <= 2 (got 3)"),
        ("create_particle 0 single 1 1 1", "type must be >= 1 (got 0)"),
        ("create_particle 1 single 1 1", "expected 3 argument(s), got 2; usage: create_particle TYPE single X Y Z"
                                         " | spacing REGION | region REGION | box | random_no_overlap N REGION "
                                         "MIN_DISTANCE SEED  [diameter D] [density RHO]"),
        ("create_particle 1 single 1 1 x", "z must be a number (got x)"),
        ("create_particle 1 single 5 1 1", "position 5 1 1 is outside the box"),
        ("create_particle 1 bogus 1", "create_particle style must be one of single, spacing, region, box, "
                                      "random_no_overlap, random (got bogus)"),
        ("create_particle 1 region nowhere", "region nowhere is not defined (defined: box)"),
        ("create_particle 1 box", "creating particles on a lattice needs a lattice command first"),
        ("create_particle 1 random_no_overlap 5 box 1", "expected 4 argument(s), got 3; usage: create_particle "
                                                        "TYPE single X Y Z | spacing REGION | region REGION | box "
                                                        "| random_no_overlap N REGION MIN_DISTANCE SEED  "
                                                        "[diameter D] [density RHO]"),
        ("create_particle 1 random_no_overlap 5 box -1 4", "minimum distance must be >= 0 (got -1)"),
        ("create_particle 1 random_no_overlap 5 box 1 0", "seed must be >= 1 (got 0)"),
        ("create_particle 1 single 1 1 1 diameter 2", "diameter needs particle_style sphere"),
    ])
    def test_errors(self, sim, line, message):
        fails(sim, box(ntypes=2) + line, "create_particle", message)

    def test_before_the_box(self, sim):
        fails(sim, "create_particle 1 single 0 0 0", "create_particle",
              "create_particle before the simulation box exists (use create_box or read_data first)")


DATA = """\
LAMMPS data file written by hand

3 atoms
2 atom types

0 10 xlo xhi
-1 1 ylo yhi
0 5 zlo zhi

Masses

1 1.5
2 3.0

Atoms # atomic

1 1 1.0 0.0 1.0
7 2 2.0 0.5 2.0 1 0 -1
3 1 3.0 -0.5 3.0

Velocities

3 0.3 0.0 0.0
1 0.1 0.2 0.3
7 0 0 -1
"""

HEADER = "title\n\n2 atoms\n2 atom types\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n\n"


class TestReadData:
    def test_atomic_with_masses_images_and_velocities(self, sim, tmp_path):
        (tmp_path / "in.data").write_text(DATA)
        run(sim, "read_data in.data")
        assert sim.box.lo.tolist() == [0, -1, 0] and sim.box.hi.tolist() == [10, 1, 5]
        assert sim.ntypes == 2
        assert sim.mass[1:].tolist() == [1.5, 3.0]
        assert sim.tag.tolist() == [1, 7, 3]
        assert sim.type.tolist() == [1, 2, 1]
        assert sim.x.tolist() == [[1, 0, 1], [2, 0.5, 2], [3, -0.5, 3]]
        assert sim.particles.image[:3].tolist() == [[0, 0, 0], [1, 0, -1], [0, 0, 0]]
        assert sim.v.tolist() == [[0.1, 0.2, 0.3], [0, 0, -1], [0.3, 0, 0]]

    def test_new_particles_get_tags_after_the_largest_read(self, sim, tmp_path):
        (tmp_path / "in.data").write_text(DATA)
        run(sim, "read_data in.data\ncreate_particle 1 single 5 0 2")
        assert sim.tag.tolist() == [1, 7, 3, 8]

    def test_sphere_with_diameter_density_and_images(self, sim, tmp_path):
        (tmp_path / "s.data").write_text(HEADER + "Atoms # sphere\n\n1 1 2.0 3.0 1 1 1\n2 2 1.0 1.0 5 5 5 0 2 0\n")
        run(sim, "particle_style sphere\nread_data s.data")
        assert sim.particles.radius[:2].tolist() == [1.0, 0.5]
        assert sim.particles.rmass[:2] == pytest.approx([3.0 * 4 / 3 * math.pi, 4 / 3 * math.pi / 8])
        assert sim.particles.image[:2].tolist() == [[0, 0, 0], [0, 2, 0]]
        assert sim.x.tolist() == [[1, 1, 1], [5, 5, 5]]

    def test_data_file_is_found_next_to_the_script(self, sim, tmp_path):
        (tmp_path / "case").mkdir()
        (tmp_path / "case" / "in.data").write_text(DATA)
        (tmp_path / "case" / "in.read").write_text("read_data in.data\n")
        sim.file(str(tmp_path / "case" / "in.read"))
        assert sim.nlocal == 3

    def test_read_particles_can_run(self, sim, tmp_path):
        (tmp_path / "in.data").write_text(DATA)
        run(sim, "read_data in.data\nfix 1 all nve\ntimestep 0.1\nrun 10")
        assert sim.x[1].tolist() == pytest.approx([2, 0.5, 1])
        assert sim.particles.image[1].tolist() == [1, 0, -1]

    @pytest.mark.parametrize("body, line, message", [
        ("Atoms\n\n1 1 1 1 1\n2 1 x 1 1\n", 12, "cannot read Atoms line: 2 1 x 1 1"),
        ("Atoms\n\n1 1 1 1 1\n2 1 1 1\n", 12, "expected 5 or 8 values per atomic atom (got 4)"),
        ("Atoms\n\n1 1 1 1 1 0 0\n2 1 1 1 1\n", 11, "expected 5 or 8 values per atomic atom (got 7)"),
        ("Atoms\n\n1 1 1 1 1 0 0 x\n2 1 1 1 1\n", 11, "cannot read Atoms line: 1 1 1 1 1 0 0 x"),
        ("Atoms\n\n1 1 1 1 1\n", 11, "header says 2 atoms but the Atoms section has 1"),
        ("Atoms\n\n1 1 1 1 1\n1 1 2 2 2\n", 12, "atom id 1 appears twice in Atoms (first on line 11)"),
        ("Atoms\n\n1 1 1 1 1\n2 3 2 2 2\n", 12, "atom type 3 is out of range 1..2"),
        ("Atoms\n\n1 1 1 1 1\n2 1 nan 2 2\n", 12, "position must be finite and within +-1e+150: 2 1 nan 2 2"),
        ("Masses\n\n1\n\nAtoms\n\n1 1 1 1 1\n2 1 2 2 2\n", 11, "cannot read Masses line: 1"),
        ("Masses\n\n3 1.0\n\nAtoms\n\n1 1 1 1 1\n2 1 2 2 2\n", 11, "Masses: type 3 is out of range 1..2"),
        ("Atoms\n\n1 1 1 1 1\n2 1 2 2 2\n\nVelocities\n\n1 0 0 0\n3 0 0 0\n", 17,
         "Velocities name atom 3, which is not in Atoms"),
        ("Atoms\n\n1 1 1 1 1\n2 1 2 2 2\n\nVelocities\n\n1 0 0\n", 16, "expected id vx vy vz (got 3 values)"),
        ("Atoms\n\n1 1 1 1 1\n2 1 2 2 2\n\nBonds\n\n1 1 1 2\n", 14,
         "section Bonds needs a particle_style with molecule ids (molecular, bond, angle or full), not atomic"),
        ("Atoms # sphere\n\n1 1 1 1 1 1 1\n2 1 1 1 2 2 2\n", 9,
         "Atoms are 'sphere' but particle_style is atomic (set particle_style sphere before read_data)"),
    ])
    def test_malformed_files(self, sim, tmp_path, body, line, message):
        path = tmp_path / "bad.data"
        path.write_text(HEADER + body)
        assert path.read_text().splitlines()[line - 1].strip()       # the line named is a real one
        exc = fails(sim, "read_data bad.data", "read_data")
        assert exc.message == f"{path}:{line}: {message}"
        assert sim.box is None and sim.nlocal == 0

    @pytest.mark.parametrize("text, line, message", [
        ("title\n\nfoo atoms\n", 3, "unsupported section foo atoms (sections read: Masses, Atoms, Velocities)"),
        ("title\n\n2 atoms\n1 atom types\n0 1 xlo xhi\n3 bonds\n", 6, "3 bonds need a particle_style with molecule ids (molecular, bond, angle or full), not atomic"),
        ("title\n\n2 atoms\n1 atom types\n0 1 0 0 0 xy xz yz\n", 5, "unrecognised header line: 0 1 0 0 0 xy xz yz"),
        ("title\n\n2 atoms\n", 1, "header must give the number of atoms and of atom types"),
        ("title\n\n2 atoms\n1 atom types\n0 1 0 xy xz yz\n", 5, "triclinic boxes are not supported"),
    ])
    def test_malformed_headers(self, sim, tmp_path, text, line, message):
        (tmp_path / "bad.data").write_text(text)
        exc = fails(sim, "read_data bad.data", "read_data")
        assert exc.message == f"{tmp_path / 'bad.data'}:{line}: {message}"

    def test_sphere_diameter_must_be_positive(self, sim, tmp_path):
        (tmp_path / "bad.data").write_text(HEADER + "Atoms # sphere\n\n1 1 1 1 1 1 1\n2 1 0 1 2 2 2\n")
        exc = fails(sim, "particle_style sphere\nread_data bad.data", "read_data")
        assert exc.message == f"{tmp_path / 'bad.data'}:12: diameter and density must be from 1e-50 to 1e+50: 2 1 0 1 2 2 2"

    def test_other_errors(self, sim, tmp_path):
        exc = fails(sim, "read_data missing.data", "read_data")
        assert exc.message.startswith("cannot read data file ")
        assert exc.message.endswith("missing.data: No such file or directory")
        fails(sim, "read_data", "read_data", "expected a file; usage: read_data FILE [fix ID NULL SECTION ...]")
        (tmp_path / "in.data").write_text(DATA)
        fails(sim, box() + "read_data in.data", "read_data", "read_data needs no box to exist yet (it creates it)")


class TestMass:
    @pytest.mark.parametrize("lines, masses", [
        (["mass * 2.0"], [2, 2, 2, 2]),
        (["mass * 1", "mass 2* 3"], [1, 3, 3, 3]),
        (["mass * 1", "mass *2 3"], [3, 3, 1, 1]),
        (["mass * 1", "mass 2*3 5"], [1, 5, 5, 1]),
        (["mass 4 0.5", "mass 1*3 7"], [7, 7, 7, 0.5]),
    ])
    def test_ranges(self, sim, lines, masses):
        run(sim, box(ntypes=4) + "\n".join(lines))
        assert sim.mass[1:].tolist() == masses

    def test_mass_drives_the_dynamics(self, sim):
        run(sim, box(ntypes=2) + "mass 1 1\nmass 2 4\ncreate_particle 1 single 1 1 1\n"
                                 "create_particle 2 single 3 3 3\nvelocity all set 1 0 0")
        assert obs.kinetic_energy(sim) == pytest.approx(0.5 * 1 + 0.5 * 4)

    @pytest.mark.parametrize("line, message", [
        ("mass 1 0", "mass must be > 0 (got 0)"),
        ("mass 1 heavy", "mass must be a number (got heavy)"),
        ("mass 3 1", "type 3 is out of range 1..2"),
        ("mass 2*1 1", "type 2*1 is out of range 1..2"),
        ("mass x 1", "type must be an integer (got x)"),
        ("mass 1", "expected 2 argument(s), got 1; usage: mass TYPE VALUE"),
    ])
    def test_errors(self, sim, line, message):
        fails(sim, box(ntypes=2) + line, "mass", message)

    def test_before_the_box_and_missing_at_run(self, sim):
        fails(sim, "mass 1 1", "mass", "mass before the simulation box exists (use create_box or read_data first)")
        fails(sim, box(ntypes=2) + "mass 1 1\ncreate_particle 2 single 1 1 1\nrun 0", "run",
              "mass is not set for type 2 (use the mass command)")


class TestGroup:
    SETUP = "lattice sc 1" + box(ntypes=3) + "create_particle 1 box\n"

    def members(self, sim, name):
        return set(sim.tag[sim.groups.select(sim, name)].tolist())

    def test_all_always_exists(self, sim):
        run(sim, self.SETUP + "group all\ngroup all all")
        assert self.members(sim, "all") == set(range(1, 65))

    def test_region(self, sim):
        run(sim, self.SETUP + "region low block 0 1.5 0 4 0 4\ngroup low region low")
        low = self.members(sim, "low")
        assert len(low) == 32
        assert all(sim.x[sim.tag == t][0, 0] <= 1.5 for t in low)

    def test_region_with_inf_bounds(self, sim):
        run(sim, self.SETUP + "region low block INF 1.5 INF INF INF INF\ngroup low region low")
        assert len(self.members(sim, "low")) == 32

    def test_type_with_ranges(self, sim):
        run(sim, self.SETUP + "create_particle 2 single 0.5 0.5 0.5\ncreate_particle 3 single 1.5 0.5 0.5\n"
                              "group two type 2\ngroup many type 1 3\ngroup upper type 2*3\ngroup colon type 2:3")
        assert self.members(sim, "two") == {65}
        assert self.members(sim, "many") == set(range(1, 65)) | {66}
        assert self.members(sim, "upper") == self.members(sim, "colon") == {65, 66}

    def test_membership_is_evaluated_again_before_each_run(self, sim):
        run(sim, box() + "mass 1 1\nregion right block 2 4 0 4 0 4\ngroup right region right\n"
                         "create_particle 1 single 1 1 1\ncreate_particle 1 single 3 1 1")
        assert self.members(sim, "right") == {2}
        sim.x[0, 0] = 2.5
        run(sim, "run 0")
        assert self.members(sim, "right") == {1, 2}

    def test_delete_frees_the_name(self, sim):
        run(sim, self.SETUP + "group g type 1\ngroup g delete")
        assert "g" not in sim.groups
        assert not (sim.particles.mask[:sim.nlocal] & ~np.uint32(1)).any()

    def test_31_user_groups_and_no_more(self, sim):
        run(sim, self.SETUP + "\n".join(f"group g{i} type 1" for i in range(31)))
        assert len(sim.groups.names()) == 32
        fails(sim, "group one_too_many type 1", "group", "too many groups: at most 31 besides all (got one_too_many)")
        run(sim, "group g5 delete\ngroup h type 2")    # a deleted group's bit is free again
        assert "h" in sim.groups

    def test_lammps_groups_are_static_and_add_up(self, sim):
        from pdps_core.script.dialect import DIALECTS
        sim.script.dialect = DIALECTS["lammps"]
        run(sim, self.SETUP + "create_particle 2 single 0.5 0.5 0.5\ngroup g type 1\ngroup g type 2\n"
                 "group odd id 1:64:2\ngroup big id > 60\ngroup both intersect odd big\n"
                 "group rest subtract all g\ngroup mid id <> 10 12")
        assert self.members(sim, "g") == set(range(1, 66))
        assert self.members(sim, "odd") == set(range(1, 65, 2))
        assert self.members(sim, "both") == {61, 63}
        assert self.members(sim, "rest") == set()
        assert self.members(sim, "mid") == {10, 11, 12}
        run(sim, "create_particle 1 single 1.5 0.5 0.5")     # joins all only: static groups
        assert 66 not in self.members(sim, "g")

    def test_redefining_a_group_replaces_it(self, sim):
        run(sim, self.SETUP + "create_particle 2 single 0.5 0.5 0.5\ngroup g type 1\ngroup g type 2")
        assert self.members(sim, "g") == {65}

    @pytest.mark.parametrize("line, message", [
        ("group", "expected a group id; usage: group ID STYLE ARGS (all, region RID, type T..., id I..., molecule M..., variable NAME, subtract G..., union G..., intersect G..., empty, clear, delete)"),
        ("group g", "expected a group style; usage: group ID STYLE ARGS (all, region RID, type T..., id I..., molecule M..., variable NAME, subtract G..., union G..., intersect G..., empty, clear, delete)"),
        ("group g bogus", "group style must be one of all, region, type, id, variable, subtract, union, intersect, "
                          "empty, clear, delete, molecule, dynamic, static, include (got bogus)"),
        ("group g dynamic all", "group dynamic is not supported (supported: region, type, id, molecule, variable, "
                                "subtract, union, intersect, empty, clear, delete)"),
        ("group g id 5:2", "id range 5:2 must have A <= B and a stride >= 1"),
        ("group g union", "group union needs one or more groups"),
        ("group g region nowhere", "region nowhere is not defined (defined: box)"),
        ("group g type", "expected at least one type; usage: group ID STYLE ARGS (all, region RID, type T..., id I..., molecule M..., variable NAME, subtract G..., union G..., intersect G..., empty, clear, delete)"),
        ("group g type 4", "type 4 is out of range 1..3"),
        ("group g delete", "group g is not defined"),
        ("group all type 1", "group all is predefined and cannot be redefined"),
    ])
    def test_errors(self, sim, line, message):
        fails(sim, self.SETUP + line, "group", message)


VELOCITY_USAGE = ("velocity GROUP create T SEED | set VX VY VZ | scale T | ramp vx|vy|vz VLO VHI x|y|z CLO CHI | "
                  "zero linear|angular, then [dist uniform|gaussian] [sum yes|no] [mom yes|no] [rot yes|no] "
                  "[temp COMPUTE-ID] [loop all|local|geom] [units box|lattice]")


class TestVelocity:
    def setup_sim(self, sim, dimension=3):
        run(sim, f"dimension {dimension}\nlattice {'sc' if dimension == 3 else 'sq'} 1" + box(ntypes=2, bounds="0 6 0 6 0 6") +
            "mass 1 1\nmass 2 3\ncreate_particle 1 box\nregion half block 0 2.5 0 6 0 6\n"
            "create_particle 2 region half")
        return sim

    @staticmethod
    def momentum(sim, chosen=slice(None)):
        return (obs.masses(sim)[chosen][:, None] * sim.v[chosen]).sum(axis=0)

    @pytest.mark.parametrize("dist", ["uniform", "gaussian", "dist gaussian", "dist uniform"])
    def test_create_zero_momentum_exact_temperature(self, sim, dist):
        self.setup_sim(sim)
        run(sim, f"velocity all create 2.5 87287 {dist}")
        scale = np.abs(obs.masses(sim)[:, None] * sim.v).sum()
        assert np.abs(self.momentum(sim)).max() < 1e-13 * scale
        assert obs.temperature(sim) == pytest.approx(2.5, rel=1e-12)

    def test_uniform_and_gaussian_distributions_differ(self, make_sim):
        def extreme(dist):
            s = self.setup_sim(make_sim())
            s.command(f"velocity all create 1.0 5 {dist}")
            v = s.v[s.type == 1]
            return np.abs(v).max() / np.sqrt((v ** 2).mean())
        assert extreme("uniform") < 2.0       # a uniform distribution has max/rms = sqrt(3)
        assert extreme("gaussian") > 2.5      # ~3.2 expected among ~650 normal draws

    def test_same_seed_same_velocities(self, make_sim):
        def velocities(seed):
            s = self.setup_sim(make_sim())
            s.command(f"velocity all create 1.0 {seed} gaussian")
            return s.v.copy()
        assert np.array_equal(velocities(11), velocities(11))
        assert not np.allclose(velocities(11), velocities(12))

    def test_create_for_a_group_leaves_the_others(self, sim):
        self.setup_sim(sim)
        run(sim, "velocity all set 0.5 0 0\ngroup heavy type 2\nvelocity heavy create 4.0 3 gaussian")
        heavy = sim.type == 2
        assert np.all(sim.v[~heavy] == [0.5, 0, 0])
        assert obs.temperature(sim, "heavy") == pytest.approx(4.0, rel=1e-12)
        assert np.abs(self.momentum(sim, heavy)).max() < 1e-12

    def test_mom_no_keeps_the_momentum_but_sets_the_temperature(self, sim):
        self.setup_sim(sim)
        run(sim, "velocity all create 1.5 3 gaussian mom no")
        assert np.abs(self.momentum(sim)).max() > 1e-3
        assert obs.temperature(sim) == pytest.approx(1.5, rel=1e-12)

    def test_2d(self, sim):
        self.setup_sim(sim, dimension=2)
        run(sim, "velocity all create 1.5 3")
        assert np.all(sim.v[:, 2] == 0)
        assert obs.temperature(sim) == pytest.approx(1.5, rel=1e-12)
        assert np.abs(self.momentum(sim)).max() < 1e-12

    def test_zero_temperature(self, sim):
        self.setup_sim(sim)
        run(sim, "velocity all create 0 3")
        assert np.all(sim.v == 0)

    def test_set_with_null(self, sim):
        self.setup_sim(sim)
        run(sim, "velocity all set 1 2 3\ngroup heavy type 2\nvelocity heavy set NULL -5 NULL")
        heavy = sim.type == 2
        assert np.all(sim.v[heavy] == [1, -5, 3])
        assert np.all(sim.v[~heavy] == [1, 2, 3])

    @pytest.mark.parametrize("line, message", [
        ("velocity hot create 1 1", "group hot is not defined (defined: all)"),
        ("velocity all create -1 1", "temperature must be >= 0 (got -1)"),
        ("velocity all create 1 0", "seed must be >= 1 (got 0)"),
        ("velocity all create 1 2.5", "seed must be an integer (got 2.5)"),
        ("velocity all create warm 1", "temperature must be a number (got warm)"),
        ("velocity all create 1 1 poisson", f"unknown velocity keyword poisson; usage: {VELOCITY_USAGE}"),
        ("velocity all create 1 1 mom maybe", "mom must be one of yes, no (got maybe)"),
        ("velocity all create 1", f"expected a temperature and a seed; usage: {VELOCITY_USAGE}"),
        ("velocity all set 1 2", f"expected VX VY VZ; usage: {VELOCITY_USAGE}"),
        ("velocity all set 1 2 fast", "vz must be a number (got fast)"),
        ("velocity all spin 1", "velocity style must be one of create, set, scale, ramp, zero (got spin)"),
    ])
    def test_errors(self, sim, line, message):
        self.setup_sim(sim)
        v_before = sim.v.copy()
        fails(sim, line, "velocity", message)
        assert np.array_equal(sim.v, v_before)

    def test_before_the_box(self, sim):
        fails(sim, "velocity all set 0 0 0", "velocity",
              "velocity before the simulation box exists (use create_box or read_data first)")


class TestParticleStyle:
    def test_atomic_is_the_default_and_has_no_rotation(self, sim):
        assert sim.particle_style == "atomic"
        run(sim, "particle_style atomic" + box())
        assert not any(sim.particles.has(n) for n in ("radius", "rmass", "omega", "torque"))

    def test_sphere_allocates_radius_mass_omega_torque(self, sim):
        run(sim, "particle_style sphere" + box() + "create_particle 1 single 1 1 1")
        assert sim.particle_style == "sphere"
        assert all(sim.particles.has(n) for n in ("radius", "rmass", "omega", "torque"))
        assert sim.particles.omega.shape == (1, 3)

    def test_atom_style_spelling(self, sim):
        run(sim, "atom_style sphere")
        assert sim.particle_style == "sphere"

    def test_errors(self, sim):
        fails(sim, "particle_style ellipsoid", "particle_style",
              "particle style must be one of atomic, sphere, charge, molecular, bond, angle, full, hybrid (got ellipsoid)")
        fails(sim, box() + "particle_style sphere", "particle_style",
              "particle_style must come before the simulation box is created")


# ---- interactions --------------------------------------------------------------------------------
class TestNeighbor:
    def test_skin_and_style(self, sim):
        run(sim, "neighbor 0.5 multi")
        assert (sim.neighbor.skin, sim.neighbor.style) == (0.5, "multi")
        run(sim, "neighbor 0.2 bin")
        assert (sim.neighbor.skin, sim.neighbor.style) == (0.2, "single")

    @pytest.mark.parametrize("name", ["neigh_modify", "neighbor_modify"])
    def test_modify(self, sim, name):
        run(sim, f"{name} every 2 delay 4 check no")
        n = sim.neighbor
        assert (n.every, n.delay, n.check) == (2, 4, False)
        run(sim, f"{name} check yes")
        assert (n.every, n.delay, n.check) == (2, 4, True)

    @pytest.mark.parametrize("line, command, message", [
        ("neighbor -1", "neighbor", "skin must be >= 0 (got -1)"),
        ("neighbor 0.3 nsq", "neighbor", "neighbor style must be one of single, multi, bin (got nsq)"),
        ("neighbor auto nsq", "neighbor", "neighbor style must be one of single, multi, bin (got nsq)"),
        ("neighbor outo", "neighbor", "skin must be a number (got outo)"),
        ("neighbor", "neighbor", "expected 1 to 2 argument(s), got 0; usage: neighbor SKIN|auto [single|multi|bin]"),
        ("neigh_modify every 0", "neigh_modify", "every must be >= 1 (got 0)"),
        ("neigh_modify delay -1", "neigh_modify", "delay must be >= 0 (got -1)"),
        ("neigh_modify every", "neigh_modify",
         "expected keyword/value pairs; usage: neigh_modify [every N] [delay N] [check yes|no] [once yes|no] [one N] [exclude type I J | group G1 G2 | "
                                        "molecule/intra G | molecule/inter G | none]"),
        ("neighbor_modify check maybe", "neighbor_modify", "check must be one of yes, no (got maybe)"),
        ("neigh_modify often 2", "neigh_modify", "neigh_modify keyword must be one of every, delay, check, once, one, exclude (got often)"),
    ])
    def test_errors(self, sim, line, command, message):
        fails(sim, line, command, message)


class TestPairCoeff:
    SETUP = box(ntypes=4) + "pair_style dpd 1.0 1.0 1234\n"

    def coeffs(self, sim):
        return {k: (c.a, c.gamma, c.cutoff) for k, c in sim.pair.coeffs.items()}

    def test_all_pairs(self, sim):
        run(sim, self.SETUP + "pair_coeff * * 25 4.5")
        assert self.coeffs(sim) == {(i, j): (25, 4.5, None) for i in range(1, 5) for j in range(i, 5)}

    @pytest.mark.parametrize("i, j, pairs", [
        ("2", "3", {(2, 3)}),
        ("3", "2", {(2, 3)}),                                  # swapped to I <= J
        ("2*", "3", {(2, 3), (3, 3)}),                         # only I <= J: not (4, 3)
        ("*", "2", {(1, 2), (2, 2)}),
        ("*2", "4", {(1, 4), (2, 4)}),
        ("2", "*", {(2, 2), (2, 3), (2, 4)}),
        ("2*3", "2*4", {(2, 2), (2, 3), (2, 4), (3, 3), (3, 4)}),
        ("*", "*", {(i, j) for i in range(1, 5) for j in range(i, 5)}),
    ])
    def test_ranges_set_the_pairs_with_i_le_j(self, sim, i, j, pairs):
        run(sim, self.SETUP + "pair_coeff * * 1 1\n" + f"pair_coeff {i} {j} 7 2 0.8")
        changed = {k for k, c in self.coeffs(sim).items() if c == (7, 2, 0.8)}
        assert changed == pairs

    def test_later_coefficients_override(self, sim):
        run(sim, self.SETUP + "pair_coeff * * 25 4.5\npair_coeff 1 1 10 1")
        assert self.coeffs(sim)[(1, 1)] == (10, 1, None)
        assert self.coeffs(sim)[(1, 2)] == (25, 4.5, None)

    def test_pair_style_again_keeps_coefficients(self, sim):
        run(sim, self.SETUP + "pair_coeff * * 25 4.5\npair_style dpd 2.0 1.0 99")
        assert self.coeffs(sim)[(1, 1)] == (25, 4.5, None)
        assert sim.pair.args.temperature == 2.0

    @pytest.mark.parametrize("line, message", [
        ("pair_coeff 5 1 25 4.5", "I 5 is out of range 1..4"),
        ("pair_coeff 1 0 25 4.5", "J 0 is out of range 1..4"),
        ("pair_coeff 3*2 1 25 4.5", "I 3*2 is out of range 1..4"),
        ("pair_coeff 3* *2 25 4.5", "pair_coeff 3* *2 names no type pair with I <= J"),
        ("pair_coeff a 1 25 4.5", "I must be an integer (got a)"),
        ("pair_coeff 1 1 25", "missing argument gamma; usage: a gamma [rc]"),
        ("pair_coeff 1 1 abc 4.5", "a must be a finite number (got abc)"),
        ("pair_coeff 1 1 25 4.5 1 1", "too many arguments: unexpected '1'; usage: a gamma [rc]"),
        ("pair_coeff 1", "expected I J and coefficients; usage: pair_coeff I J a gamma [rc]"),
    ])
    def test_errors(self, sim, line, message):
        fails(sim, self.SETUP + line, "pair_coeff", message)
        assert sim.pair.coeffs == {}

    def test_order_errors(self, sim):
        fails(sim, box() + "pair_coeff 1 1 1 1", "pair_coeff", "pair_coeff before pair_style")

    def test_pair_style_errors(self, sim):
        fails(sim, "pair_style dpd 1 1", "pair_style", "missing argument seed; usage: pair_style dpd T rc seed "
                                                          "[noise gaussian|uniform]")
        exc = fails(sim, "pair_style dpdd 1 1 1", "pair_style")
        assert exc.message == (f"unknown pair style dpdd; did you mean dpd? "
                               f"(installed: {', '.join(registry.names('pair'))})")

    def test_missing_type_pair_is_an_error_at_run(self, sim):
        exc = fails(sim, box(ntypes=2) + "mass * 1\ncreate_particle 1 single 1 1 1\npair_style dpd 1 1 1\n"
                                         "pair_coeff 1 1 25 4.5\nrun 0", "run")
        assert exc.message.startswith("pair coefficients are not set for types 1 2 (give pair_coeff")


# ---- run setup -----------------------------------------------------------------------------------
class TestProcessors:
    def test_one_rank(self, sim):
        run(sim, "processors 1 1 1")
        assert sim.system.processors == (1, 1, 1)
        run(sim, "processors * * 1")
        assert sim.system.processors == (None, None, 1)

    @pytest.mark.parametrize("line, message", [
        ("processors 2 1 1", "processor grid 2 x 1 x 1 = 2 does not match the 1 rank(s) of this run"),
        ("processors 2 * 1", "processor grid 2 * 1 cannot divide 1 rank(s)"),
        ("processors 0 1 1", "processors nx must be >= 1 (got 0)"),
        ("processors 1 1", "expected 3 argument(s), got 2; usage: processors nx ny nz"),
    ])
    def test_errors(self, sim, line, message):
        fails(sim, line, "processors", message)


class TestIntegrate:
    @pytest.mark.parametrize("line", ["integrate v_verlet", "integrate verlet", "run_style verlet"])
    def test_velocity_verlet(self, make_sim, line):
        """A Lennard-Jones dimer from rest at r0 = 1.5 (masses 2): the first step is velocity Verlet's
        by hand from the analytic force, and over two vibrations the energy stays within a bound that
        falls as dt^2 (second order)."""
        r0, dt, m = 1.5, 0.002, 2.0

        def force(r):                 # -dU/dr of U = 4 (r^-12 - r^-6), along the bond
            return 24.0 * (2.0 * r ** -13 - r ** -7)

        def dimer(step):
            sim = make_sim()
            run(sim, f"""{line}
                {box(bounds="0 10 0 10 0 10")}mass 1 {m}
                create_particle 1 single 4 5 5
                create_particle 1 single {4 + r0} 5 5
                pair_style lj/cut 3.0
                pair_coeff * * 1.0 1.0
                fix 1 all nve
                timestep {step}
                run 0""")
            return sim

        def drift(sim, step):
            energy0 = obs.potential_energy(sim)
            worst = 0.0
            for _ in range(round(4.0 / step) // 40):         # 4 time units: two vibrations
                run(sim, "run 40")
                worst = max(worst, abs(obs.potential_energy(sim) + obs.kinetic_energy(sim) - energy0))
            return worst / abs(energy0)

        sim = dimer(dt)
        assert obs.potential_energy(sim) == pytest.approx(4.0 * (r0 ** -12 - r0 ** -6), rel=1e-14)
        run(sim, "run 1")
        # x1 = x0 + dt^2 F(x0) / 2m on each particle; v1 = dt (F(x0) + F(x1)) / 2m
        dx = 0.5 * dt * dt * force(r0) / m
        r1 = r0 + 2.0 * dx
        order = np.argsort(sim.tag)
        assert sim.x[order, 0] == pytest.approx([4.0 - dx, 4.0 + r0 + dx], rel=1e-14)
        v1 = 0.5 * dt * (force(r0) + force(r1)) / m
        assert sim.v[order, 0] == pytest.approx([-v1, v1], rel=1e-12)
        fine, coarse = drift(dimer(dt), dt), drift(dimer(2 * dt), 2 * dt)
        assert 0.0 < fine < 3e-4                           # measured 1.5e-4
        assert 3.0 < coarse / fine < 5.0                    # twice the step, four times the error
        assert np.abs(sim.v.sum(axis=0)).max() < 1e-13     # momentum stays zero

    def test_errors(self, sim):
        fails(sim, "integrate respa", "integrate", "integrate style must be one of v_verlet (got respa)")
        fails(sim, "integrate", "integrate", "expected 1 argument(s), got 0; usage: integrate v_verlet")


class TestFix:
    SETUP = box() + "mass 1 1\ncreate_particle 1 single 1 1 1\nvelocity all set 1 0 0\ntimestep 0.1\n"

    def test_fix_moves_and_unfix_stops(self, sim):
        run(sim, self.SETUP + "fix 1 all nve\nrun 5")
        assert sim.x[0, 0] == pytest.approx(1.5)
        run(sim, "unfix 1\nrun 5")
        assert sim.x[0, 0] == pytest.approx(1.5)
        assert sim.fixes == {}

    def test_fix_on_a_group_only(self, sim):
        run(sim, self.SETUP + "create_particle 1 single 3 1 1\nvelocity all set 1 0 0\n"
                              "region r block 2 4 0 4 0 4\ngroup moving region r\nfix 1 moving nve\nrun 5")
        assert sim.x[:, 0].tolist() == pytest.approx([1.0, 3.5])

    def test_redefining_a_fix_keeps_its_place(self, sim):
        run(sim, self.SETUP + "fix a all nve\nfix b all nve\nfix a all nve")
        assert list(sim.fixes) == ["a", "b"]

    @pytest.mark.parametrize("line, command, message", [
        ("fix 1 nope nve", "fix", "group nope is not defined (defined: all)"),
        ("fix 1 all", "fix", "expected: fix ID GROUP STYLE args"),
        ("fix 1 all nve extra", "fix", "too many arguments: unexpected 'extra'; usage: fix ID GROUP nve"),
        ("unfix 1", "unfix", "fix 1 is not defined"),
        ("unfix", "unfix", "expected 1 argument(s), got 0; usage: unfix ID"),
    ])
    def test_errors(self, sim, line, command, message):
        fails(sim, self.SETUP + line, command, message)

    def test_unknown_style_suggests_a_close_one(self, sim):
        exc = fails(sim, self.SETUP + "fix 1 all nvee", "fix")
        assert exc.message == f"unknown fix style nvee; did you mean nve? (installed: {', '.join(registry.names('fix'))})"

    def test_before_the_box(self, sim):
        fails(sim, "fix 1 all nve", "fix", "fix before the simulation box exists (use create_box or read_data first)")


class TestCompute:
    SETUP = box() + "mass 1 1\ncreate_particle 1 single 1 1 1\ncreate_particle 1 single 3 2 1\n"

    def test_compute_and_uncompute(self, sim):
        run(sim, self.SETUP + "compute c all centroid\ncompute t all temp\nvelocity all set 1 0 0")
        assert sim.compute_value("c", (0,)) == 2.0
        assert sim.compute_value("t") == pytest.approx(obs.temperature(sim))
        run(sim, "uncompute c\ncompute c all temp")      # the id is free again
        assert sim.compute_value("c") == sim.compute_value("t")

    @pytest.mark.parametrize("line, command, message", [
        ("compute t all temp\ncompute t all temp", "compute", "compute t is already defined"),
        ("compute t nope temp", "compute", "group nope is not defined (defined: all)"),
        ("compute t all", "compute", "expected: compute ID GROUP STYLE args"),
        ("uncompute 3", "uncompute", "compute 3 is not defined"),
    ])
    def test_errors(self, sim, line, command, message):
        fails(sim, self.SETUP + line, command, message)

    def test_write_dump_writes_one_frame_as_lammps(self, pdps_cli, tmp_path):
        """LAMMPS's write_dump with modify keywords: one frame now, the dump gone after (a second
        write_dump of the same name works); the ATOMS lines as LAMMPS 22 Jul 2025 wrote them for this
        script (2026-12-02)."""
        lammps = ["1 4.5000000000000089 -1.4999999999999796 0.74999999999998401 4.8023431780746364",
                  "2 -6.0000000000000053 -1.4999999999999791 0.74999999999998401 6.2299678971885548",
                  "3 0 0 0 0"]
        done = pdps_cli("""
            units lj
            atom_style atomic
            atom_modify map array
            region b block 0 4 0 4 0 4
            create_box 2 b
            create_atoms 1 single 0.5 0.5 0.5
            create_atoms 1 single 3.5 2 1
            create_atoms 2 single 2 3.9 2
            mass * 1.0
            velocity all set 1.5 -0.5 0.25
            set atom 2 vx -2.0
            group one type 1
            compute d one displace/atom
            pair_style zero 1.0
            pair_coeff * *
            fix n all nve
            timestep 0.01
            run 300
            write_dump all custom dd.dump id c_d[1] c_d[2] c_d[3] c_d[4] modify sort id format float %.17g
            write_dump one atom one.dump
        """, "-log", "none")
        assert done.returncode == 0, done.stderr
        lines = (tmp_path / "dd.dump").read_text().splitlines()
        assert lines[:2] == ["ITEM: TIMESTEP", "300"] and lines[-3:] == lammps
        assert (tmp_path / "one.dump").read_text().splitlines()[3] == "2"

    def test_unknown_style(self, sim):
        exc = fails(sim, self.SETUP + "compute t all tmp", "compute")
        assert exc.message == (f"unknown compute style tmp; did you mean temp? "
                               f"(installed: {', '.join(registry.names('compute'))})")

    def test_reading_a_removed_compute(self, sim):
        run(sim, self.SETUP + "compute c all centroid\nthermo_style custom step c_c[0]\nuncompute c")
        fails(sim, "run 0", "run", "thermo_style: compute c is not defined (thermo keyword c_c[0])")


class TestDump:
    SETUP = box() + "mass 1 1\ncreate_particle 1 single 1 1 1\nvelocity all set 1 0 0\n" \
                    "timestep 0.1\nfix 1 all nve\n"

    @staticmethod
    def frames(path):
        lines = path.read_text().splitlines()
        return [int(lines[i + 1]) for i, line in enumerate(lines) if line == "ITEM: TIMESTEP"]

    def test_every_n_steps_until_undump(self, sim, tmp_path):
        run(sim, self.SETUP + "dump d all atom 2 out.atom\nrun 5")
        assert self.frames(tmp_path / "out.atom") == [0, 2, 4]
        run(sim, "undump d\nrun 4")
        assert self.frames(tmp_path / "out.atom") == [0, 2, 4]
        assert sim.output.dumps == {}

    def test_custom_columns(self, sim, tmp_path):
        run(sim, self.SETUP + "dump d all custom 5 out.txt id x vx\nrun 5")
        lines = (tmp_path / "out.txt").read_text().splitlines()
        assert lines[8] == "ITEM: ATOMS id x vx"
        assert [float(w) for w in lines[-1].split()] == pytest.approx([1, 1.5, 1])

    @pytest.mark.parametrize("line, command, message", [
        ("dump d all atom 0 out.atom", "dump", "N must be >= 1 (got 0)"),
        ("dump d all atom x out.atom", "dump", "N must be an integer (got x)"),
        ("dump d all atom 1", "dump", "expected: dump ID GROUP STYLE N FILE [columns...]"),
        ("dump d all atom 1 a.atom\ndump d all atom 1 b.atom", "dump", "dump d is already defined"),
        ("dump d nope atom 1 a.atom", "dump", "group nope is not defined (defined: all)"),
        ("undump d", "undump", "dump d is not defined"),
    ])
    def test_errors(self, sim, line, command, message):
        fails(sim, self.SETUP + line, command, message)

    def test_unknown_style(self, sim):
        exc = fails(sim, self.SETUP + "dump d all no/such 1 a.mpg", "dump")
        assert exc.message == f"unknown dump style no/such (installed: {', '.join(registry.names('dump'))})"
        exc = fails(sim, "dump d all dcd 1 a.dcd", "dump")
        assert exc.message == ("dump style dcd is a LAMMPS style pdps does not have; instead: dump custom or "
                               "dump xdmf (docs/lammps.md)")
        exc = fails(sim, "dump d all xyz 1 a.xyz", "dump")
        assert exc.message == ("dump style xyz is a LAMMPS style pdps does not have; instead: dump custom with "
                               "id type x y z (docs/lammps.md)")


# ---- output and running --------------------------------------------------------------------------
class TestThermo:
    SETUP = box() + "mass 1 1\ncreate_particle 1 single 1 1 1\ncreate_particle 1 single 3 1 1\n" \
                    "velocity all set 1 0 0\ntimestep 0.1\nfix 1 all nve\n"

    def steps(self, sim):
        return [[int(row[0]) for row in table] for table in thermo_rows(sim.output.screen.getvalue())]

    def test_every_n_plus_first_and_last(self, sim):
        run(sim, self.SETUP + "thermo 3\nrun 7")
        assert self.steps(sim) == [[0, 3, 6, 7]]

    def test_thermo_0_writes_first_and_last(self, sim):
        run(sim, self.SETUP + "run 5")
        assert self.steps(sim) == [[0, 5]]

    def test_thermo_1_writes_n_plus_1_lines(self, sim):
        # the PDPS manual: 10 steps with thermo 1 write 11 lines
        run(sim, self.SETUP + "thermo 1\nrun 10")
        assert self.steps(sim) == [list(range(11))]

    def test_default_columns(self, sim):
        run(sim, self.SETUP + "run 0")
        header = [line for line in sim.output.screen.getvalue().splitlines() if line.split()[:1] == ["Step"]]
        assert header[0].split() == ["Step", "Temp", "PotEng", "KinEng", "TotEng", "Press"]

    @pytest.mark.parametrize("style", ["thermo_style custom step c_cen[0] c_t v_twice atoms",
                                       "thermo_style step c_cen[0] c_t v_twice atoms"])
    def test_custom_columns_with_computes_and_variables(self, sim, style):
        run(sim, self.SETUP + "compute cen all centroid\ncompute t all temp\nvariable twice equal 2*step\n"
                              f"{style}\nthermo 2\nrun 4")
        header = [line.split() for line in sim.output.screen.getvalue().splitlines() if line.split()[:1] == ["Step"]]
        assert header == [["Step", "c_cen[0]", "c_t", "v_twice", "Atoms"]]
        rows = thermo_rows(sim.output.screen.getvalue())[0]
        assert [row[0] for row in rows] == [0, 2, 4]
        assert [row[1] for row in rows] == pytest.approx([2.0, 2.2, 2.4])
        assert [row[2] for row in rows] == pytest.approx([2 / 3] * 3)   # sum m v^2 / (3N - 3)
        assert [row[3] for row in rows] == [0, 4, 8]
        assert [row[4] for row in rows] == [2, 2, 2]

    @pytest.mark.parametrize("line, command, message", [
        ("thermo -1", "thermo", "N must be >= 0 (got -1)"),
        ("thermo often", "thermo", "N must be an integer (got often)"),
        ("thermo_style custom step qqq", "thermo_style",
         "unknown thermo keyword qqq (keywords: step, temp, press, pe, ke, etotal and the rest of LAMMPS's "
         "thermo_style list; c_ID, f_ID, v_NAME)"),
        ("thermo_style custom step tempp", "thermo_style",
         "unknown thermo keyword tempp (did you mean temp? keywords: step, temp, press, pe, ke, etotal and the "
         "rest of LAMMPS's thermo_style list; c_ID, f_ID, v_NAME)"),
        ("thermo_style custom", "thermo_style", "thermo_style needs at least one keyword"),
        ("thermo_style custom step c_7\nrun 0", "run", "thermo_style: compute 7 is not defined (thermo keyword c_7)"),
        ("thermo_style custom step v_nope\nrun 0", "run",
         "thermo_style: variable nope is not defined (thermo keyword v_nope)"),
        ("compute cen all centroid\nthermo_style custom c_cen[3]\nrun 0", "run",
         "c_cen[3] is out of range (compute cen has shape (3,); indices count from 0)"),
    ])
    def test_errors(self, sim, line, command, message):
        fails(sim, self.SETUP + line, command, message)


class TestResetTimestepAndRun:
    SETUP = box() + "mass 1 1\ncreate_particle 1 single 1 1 1\nvelocity all set 1 0 0\ntimestep 0.1\n" \
                    "fix 1 all nve\n"

    def test_reset_timestep_then_run(self, sim, tmp_path):
        run(sim, self.SETUP + "reset_timestep 100\ndump d all atom 5 out.atom\nrun 10")
        assert sim.step == 110
        assert TestDump.frames(tmp_path / "out.atom") == [100, 105, 110]
        run(sim, "reset_timestep 0")
        assert sim.step == 0

    def test_runs_continue_from_where_the_last_stopped(self, sim):
        run(sim, self.SETUP + "run 3\nrun 2")
        assert sim.step == 5
        assert sim.x[0, 0] == pytest.approx(1.5)

    def test_run_0_sets_up_without_moving(self, sim):
        run(sim, self.SETUP + "run 0")
        assert sim.step == 0
        assert sim.x[0].tolist() == [1, 1, 1]
        assert sim.run_state.energy_step == sim.run_state.virial_step == 0
        assert [[row[0] for row in table] for table in thermo_rows(sim.output.screen.getvalue())] == [[0]]

    def test_run_0_with_no_particles(self, sim):
        run(sim, box() + "run 0")
        assert sim.step == 0

    @pytest.mark.parametrize("line, command, message", [
        ("reset_timestep -1", "reset_timestep", "timestep must be >= 0 (got -1)"),
        ("reset_timestep", "reset_timestep", "expected 1 argument(s), got 0; usage: reset_timestep N"),
        ("run -1", "run", "N must be >= 0 (got -1)"),
        ("run 1.5", "run", "N must be an integer (got 1.5)"),
        ("run", "run", "expected a number of steps; usage: run N [upto] [start S] [stop E] [pre yes|no] "
                       "[post yes|no] [every M COMMAND...]"),
    ])
    def test_errors(self, sim, line, command, message):
        fails(sim, self.SETUP + line, command, message)

    def test_run_before_the_box(self, sim):
        fails(sim, "run 0", "run", "run before the simulation box exists (use create_box or read_data first)")


def test_atom_modify_first_names_a_group_and_needs_sorting_off():
    """LAMMPS keeps the group's particles first in storage (for speed) and refuses it with sorting
    on; pdps takes it where LAMMPS does and changes nothing."""
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("atom_modify map array sort 0 0\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\ngroup some type 1\n"
                "atom_modify first some")
    with pytest.raises(ScriptError, match=r"group nobody is not defined"):
        sim.command("atom_modify first nobody")
    other = Simulation(screen=False, log=None, dialect="lammps")
    other.command("region b block 0 4 0 4 0 4\ncreate_box 1 b\ngroup some type 1")
    with pytest.raises(ScriptError) as caught:
        other.command("atom_modify first some")
    assert str(caught.value) == ("<command>:1: atom_modify: first some needs sorting off (sort 0 0 first; LAMMPS: "
                                 "Atom_modify sort and first options cannot be used together)")
