"""Compute chunk/atom and fix ave/chunk: which chunk a particle falls in (by hand, per style, units and
origin), profile averages against direct numpy sums over known configurations, the files and thermo
of two small scripts against LAMMPS 22 Jul 2025 (run on this machine 2026-12-07, its files recorded
here byte for byte), and the one-line errors."""

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import thermo_on_ranks

# ---- chunk ids by hand ----------------------------------------------------------------------------


@pytest.fixture
def planes(make_sim):
    """A periodic 4 x 4 x 10 box: 3 particles of type 1 on z = 0.5, 5 of type 2 on z = 2.5, 2 of type 1
    on z = 7.25 (LAMMPS dialect: units lattice is the default of chunk/atom there and here)."""
    sim = make_sim(dialect="lammps")
    lines = ["units lj", "region box block 0 4 0 4 0 10", "create_box 3 box", "mass 1 1.0", "mass 2 3.0",
             "mass 3 1.0"]
    for count, z, t in ((3, 0.5, 1), (5, 2.5, 2), (2, 7.25, 1)):
        lines += [f"create_atoms {t} single {0.5 + k * 0.7} {1.5 + 0.3 * k} {z}" for k in range(count)]
    sim.command("\n".join(lines))
    return sim


def ids(sim, name):
    return sim.computes[name].peratom(sim).tolist()


Z = [0.5] * 3 + [2.5] * 5 + [7.25] * 2


@pytest.mark.parametrize("line, nchunk, where", [
    # lower 1 box: slabs 0-1, 1-2, ..., the particle in floor(z) + 1
    ("bin/1d z lower 1 units box", 10, [1] * 3 + [3] * 5 + [8] * 2),
    # center 3 box: a boundary at 5, bins -1-2, 2-5, 5-8, 8-11
    ("bin/1d z center 3 units box", 4, [1] * 3 + [2] * 5 + [3] * 2),
    # upper 4 box: a boundary at 10, bins -2-2, 2-6, 6-10
    ("bin/1d z upper 4 units box", 3, [1] * 3 + [2] * 5 + [3] * 2),
    # a number as origin: 0.6 with width 2 gives -1.4-0.6, 0.6-2.6, ..., 8.6-10.6
    ("bin/1d z 0.6 2 units box", 6, [1] * 3 + [2] * 5 + [5] * 2),
    # reduced: z/10 in bins of 0.3 about 0.5: -0.1-0.2, 0.2-0.5, 0.5-0.8, 0.8-1.1
    ("bin/1d z center 0.3 units reduced", 4, [1] * 3 + [2] * 5 + [3] * 2),
    # lattice sc 0.064 (lj): spacing (1/0.064)^(1/3) = 2.5, width 2 is 5
    ("bin/1d z lower 2", 2, [1] * 8 + [2] * 2),
    ("type", 3, [1] * 3 + [2] * 5 + [1] * 2),
])
def test_which_chunk_each_particle_falls_in(planes, line, nchunk, where):
    planes.command(f"lattice sc 0.064\ncompute c all chunk/atom {line}")
    assert planes.computes["c"].scalar(planes) == nchunk
    assert ids(planes, "c") == where


def test_bins_in_two_and_three_axes_count_the_first_axis_slowest(planes):
    """x lower 2, z lower 5 (box units): x bins 0-2, 2-4, z bins 0-5, 5-10; chunk = 2 ix + iz + 1."""
    planes.command("compute c all chunk/atom bin/2d x lower 2 z lower 5 units box\n"
                   "compute d all chunk/atom bin/3d z lower 5 y lower 2 x lower 4 units box")
    x = [0.5 + k * 0.7 for k in range(3)] + [0.5 + k * 0.7 for k in range(5)] + [0.5, 1.2]
    y = [1.5 + 0.3 * k for k in range(3)] + [1.5 + 0.3 * k for k in range(5)] + [1.5, 1.8]
    want = [2 * int(xi // 2) + int(zi // 5) + 1 for xi, zi in zip(x, Z)]
    assert ids(planes, "c") == want
    assert planes.computes["c"].scalar(planes) == 4
    # z slowest, then y, then x (one bin): 2 * iz + iy + 1
    assert ids(planes, "d") == [2 * int(zi // 5) + int(yi // 2) + 1 for yi, zi in zip(y, Z)]


def test_a_group_leaves_the_others_in_no_chunk_and_compress_renumbers(planes):
    planes.command("group heavy type 2\n"
                   "compute c heavy chunk/atom bin/1d z lower 1 units box\n"
                   "compute k all chunk/atom bin/1d z lower 1 units box compress yes\n"
                   "compute t all chunk/atom type compress yes")
    assert ids(planes, "c") == [0] * 3 + [3] * 5 + [0] * 2
    # populated slabs 1, 3, 8 become chunks 1, 2, 3
    assert ids(planes, "k") == [1] * 3 + [2] * 5 + [3] * 2
    assert planes.computes["k"].scalar(planes) == 3
    assert planes.computes["k"].original_ids.tolist() == [1, 3, 8]
    # per-atom values other styles read: an atom-style variable and compute reduce
    planes.command("variable twice atom 2*c_k\ncompute top all reduce max v_twice")
    assert planes.computes["top"].scalar(planes) == 6
    # type 3 has no particle: types 1, 2 stay 1, 2
    assert planes.computes["t"].scalar(planes) == 2


def test_molecules_are_chunks_and_molecule_zero_is_in_none(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command("units lj\natom_style molecular\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\nmass 1 1\n"
                + "".join(f"create_atoms 1 single {0.5 + k} 1 1\n" for k in range(4))
                + "set atom 1 mol 3\nset atom 2 mol 1\nset atom 3 mol 3\n"
                "compute m all chunk/atom molecule\ncompute n all chunk/atom molecule compress yes discard no")
    assert sim.computes["m"].scalar(sim) == 3
    assert ids(sim, "m") == [3, 1, 3, 0]
    # compressed: the numbers held, molecule 0 among them (LAMMPS's hash), are 0, 1, 3: chunks 1, 2, 3
    assert ids(sim, "n") == [3, 2, 3, 1]
    assert sim.computes["n"].original_ids.tolist() == [0, 1, 3]


MOLECULES = """units lj
atom_style molecular
lattice sc 0.5
region box block 0 3 0 3 0 3
create_box 2 box
create_atoms 1 box
mass * 1.0
set atom 1*9 mol 2
set atom 10*18 mol 5
set atom 19*20 mol 7
set atom 21*27 type 2
velocity all create 1.0 999 loop geom
fix 1 all nve
compute m all chunk/atom molecule
compute mc all chunk/atom molecule compress yes discard no
fix a all ave/chunk 1 2 4 m vx temp mass file prof.m
fix b all ave/chunk 2 1 4 mc vy density/number file prof.mc
thermo_style custom step c_m c_mc f_a[5][3] f_b[2][1] f_b[4][3]
thermo 4
run 8
"""
# LAMMPS's files of MOLECULES (compress yes: molecule 0 is chunk 1, OrigID 0)
MOLECULE_FILE = ('# Chunk-averaged data for fix a and group all\n'
    '# Timestep Number-of-chunks Total-count\n'
    '# Chunk Ncount vx temp mass\n'
    '4 7 20\n'
    '  1 0 0 0 0\n'
    '  2 9 -0.0911578 0.945139 1\n'
    '  3 0 0 0 0\n'
    '  4 0 0 0 0\n'
    '  5 9 -0.0759723 1.08121 1\n'
    '  6 0 0 0 0\n'
    '  7 2 0.478591 0.661574 1\n'
    '8 7 20\n'
    '  1 0 0 0 0\n'
    '  2 9 -0.0911578 0.945139 1\n'
    '  3 0 0 0 0\n'
    '  4 0 0 0 0\n'
    '  5 9 -0.0759723 1.08121 1\n'
    '  6 0 0 0 0\n'
    '  7 2 0.478591 0.661574 1\n')
COMPRESSED_MOLECULES = ('# Chunk-averaged data for fix b and group all\n'
    '# Timestep Number-of-chunks Total-count\n'
    '# Chunk OrigID Ncount vy density/number\n'
    '0 4 27\n'
    '  1 0 7 0.489452 0.12963\n'
    '  2 2 9 -0.470968 0.166667\n'
    '  3 5 9 0.10885 0.166667\n'
    '  4 7 2 -0.08355 0.037037\n'
    '4 4 27\n'
    '  1 0 7 0.489452 0.12963\n'
    '  2 2 9 -0.470968 0.166667\n'
    '  3 5 9 0.10885 0.166667\n'
    '  4 7 2 -0.08355 0.037037\n'
    '8 4 27\n'
    '  1 0 7 0.489452 0.12963\n'
    '  2 2 9 -0.470968 0.166667\n'
    '  3 5 9 0.10885 0.166667\n'
    '  4 7 2 -0.08355 0.037037\n')


def test_molecule_chunks_as_lammps(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command(MOLECULES)
    assert read("prof.m") == MOLECULE_FILE
    assert read("prof.mc") == COMPRESSED_MOLECULES
    # a row past the last chunk reads 0 (LAMMPS's thermo of f_b[9][2]: 0), a column past the last is an error
    sim.command("variable past equal f_b[9][2]")
    assert sim.variables.value("past") == 0
    with pytest.raises(ScriptError, match=r"f_b\[2\]\[9\] is out of range"):
        sim.command("variable wide equal f_b[2][9]\nprint ${wide}")


# ---- averages against numpy -----------------------------------------------------------------------

def test_profile_averages_are_the_sums_over_each_chunk(make_sim):
    """Particles at rest in slabs, a known velocity each: one sample's vx, mass, temp and densities."""
    sim = make_sim(dialect="lammps")
    rng = np.random.default_rng(7)
    z = rng.uniform(0, 6, 40)
    v = rng.normal(size=(40, 3))
    t = rng.integers(1, 3, 40)
    sim.command("units lj\nregion box block 0 3 0 2 0 6\ncreate_box 2 box\nmass 1 1.0\nmass 2 2.0\n"
                + "".join(f"create_atoms {ti} single 1 1 {float(zi)!r}\n" for ti, zi in zip(t, z)))
    p = sim.particles
    order = np.argsort(p.tag[:p.nlocal])
    p.v[:p.nlocal][order] = v
    sim.command("compute s all chunk/atom bin/1d z lower 2 units box\n"
                "fix a all ave/chunk 1 1 1 s vx mass temp density/number density/mass\n"
                "fix b all ave/chunk 1 1 1 s vx temp norm none adof 2 cdof 1\n"
                "fix c all ave/chunk 1 1 1 s temp adof 0\nrun 0")
    slab = (z // 2).astype(int)
    m = np.where(t == 2, 2.0, 1.0)
    table = sim.fixes["a"].array(sim)
    tableb = sim.fixes["b"].array(sim)
    # no degrees of freedom: 0, not inf
    np.testing.assert_array_equal(sim.fixes["c"].array(sim)[:, 2], [0, 0, 0])
    np.testing.assert_array_equal(table[:, 0], [1, 3, 5])
    for k in range(3):
        here = slab == k
        n = here.sum()
        np.testing.assert_allclose(table[k, 1:], [n, v[here, 0].mean(), m[here].mean(),
                                                  (m[here] * (v[here] ** 2).sum(1)).sum() / (3 * n),
                                                  n / 12.0, m[here].sum() / 12.0], rtol=1e-13)
        # norm none: vx summed; temp over cdof + adof N degrees of freedom (none left: 0)
        np.testing.assert_allclose(tableb[k, 2:], [v[here, 0].sum(),
                                                   (m[here] * (v[here] ** 2).sum(1)).sum() / (1 + 2 * n)],
                                   rtol=1e-13)


# ---- against LAMMPS ---------------------------------------------------------------------------------

FLUID = """
units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 4 0 4 0 6
create_box 2 box
create_atoms 1 box
mass 1 1.0
mass 2 2.5
set group all type/fraction 2 0.3 4321
velocity all create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0 2.5
neighbor 0.3 bin
fix 1 all nve
compute layers all chunk/atom bin/1d z center 0.3 units reduced
compute types all chunk/atom type
variable ke atom 0.5*mass*(vx*vx+vy*vy+vz*vz)
fix 2 all ave/chunk 2 5 10 layers vx density/number density/mass temp mass v_ke file prof.all
fix 3 all ave/chunk 2 5 10 layers vx density/mass temp norm sample file prof.sample
compute layers2 all chunk/atom bin/1d z center 0.3 units reduced
fix 4 all ave/chunk 2 5 10 layers2 vx density/number temp mass norm none ave running overwrite file prof.none
fix 5 all ave/chunk 5 1 10 types vz temp mass ave window 2 file prof.types
compute lat all chunk/atom bin/1d x lower 1.3 compress yes
fix 6 all ave/chunk 10 1 10 lat density/number vy format %12.6f file prof.lat
thermo_style custom step temp pe c_layers f_2[2][3] f_5[2][4]
thermo 10
run 30
"""
# LAMMPS's files of FLUID: whole (types, lat, none) and the last output (all, sample)
TYPES = ('# Chunk-averaged data for fix 5 and group all\n'
    '# Timestep Number-of-chunks Total-count\n'
    '# Chunk Ncount vz temp mass\n'
    '0 2 384\n'
    '  1 260 -0.0458087 1.47782 1\n'
    '  2 124 0.0384202 1.5344 2.5\n'
    '10 2 768\n'
    '  1 260 -0.045001 1.32864 1\n'
    '  2 124 0.0377428 1.47436 2.5\n'
    '20 2 768\n'
    '  1 260 -0.0428794 0.891746 1\n'
    '  2 124 0.0359633 1.20635 2.5\n'
    '30 2 768\n'
    '  1 260 -0.0393407 0.669862 1\n'
    '  2 124 0.0329954 0.907429 2.5\n')
COMPRESSED = ('# Chunk-averaged data for fix 6 and group all\n'
    '# Timestep Number-of-chunks Total-count\n'
    '# Chunk OrigID Coord1 Ncount density/number vy\n'
    '0 3 384\n'
    '  1 1 1.09174 144    0.974077   -0.063666\n'
    '  2 2 3.27521 144    0.974077    0.134412\n'
    '  3 3 5.45869 96    0.649385   -0.120705\n'
    '10 4 384\n'
    '  1 1 1.09174 121    0.818495    0.054189\n'
    '  2 2 3.27521 144    0.974077    0.130555\n'
    '  3 3 5.45869 96    0.649385   -0.118504\n'
    '  4 4 7.64216 23    0.155582   -0.685618\n'
    '20 4 384\n'
    '  1 1 1.09174 122    0.825260    0.011105\n'
    '  2 2 3.27521 142    0.960548    0.117250\n'
    '  3 3 5.45869 98    0.662913   -0.111044\n'
    '  4 4 7.64216 22    0.148817   -0.489326\n'
    '30 4 384\n'
    '  1 1 1.09174 122    0.825260    0.001097\n'
    '  2 2 3.27521 140    0.947019    0.081744\n'
    '  3 3 5.45869 103    0.696736   -0.107767\n'
    '  4 4 7.64216 19    0.128524   -0.218021\n')
RUNNING = ('# Chunk-averaged data for fix 4 and group all\n'
    '# Timestep Number-of-chunks Total-count\n'
    '# Chunk Coord1 Ncount vx density/number temp mass\n'
    '30 4 1152\n'
    '  1 0.05 78.5333 -1.92797 0.575502 1.02183 108.533\n'
    '  2 0.35 113.667 7.56844 0.832964 1.03711 173.067\n'
    '  3 0.65 110.333 5.08204 0.808536 0.997906 161.933\n'
    '  4 0.95 81.4667 -5.10185 0.596998 0.981813 126.467\n')
ALL_LAST = ('30 4 384\n'
    '  1 0.05 77.8 -0.0124515 0.570128 0.789972 0.728933 1.3856 1.0934\n'
    '  2 0.35 113 0.0654038 0.828078 1.25457 0.779008 1.51504 1.16851\n'
    '  3 0.65 111 0.00583617 0.813422 1.20035 0.715952 1.47568 1.07393\n'
    '  4 0.95 82.2 0.00844411 0.602372 0.932138 0.724982 1.54745 1.08747\n')
SAMPLE_LAST = ('30 4 384\n'
    '  1 0.05 77.8 -0.0124347 0.789972 0.729062\n'
    '  2 0.35 113 0.0654088 1.25457 0.779135\n'
    '  3 0.65 111 0.00587198 1.20035 0.71594\n'
    '  4 0.95 82.2 0.00829361 0.932137 0.724785\n')


def read(path):
    with open(path) as handle:
        return handle.read()


def test_files_as_lammps(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command(FLUID)
    assert read("prof.types") == TYPES
    assert read("prof.lat") == COMPRESSED
    assert read("prof.none") == RUNNING
    assert read("prof.all").startswith("# Chunk-averaged data for fix 2 and group all\n"
                                       "# Timestep Number-of-chunks Total-count\n"
                                       "# Chunk Coord1 Ncount vx density/number density/mass temp mass v_ke\n")
    assert read("prof.all").endswith(ALL_LAST)
    assert read("prof.sample").endswith(SAMPLE_LAST)
    # f_2[2][3]: row 2, column 3 (vx) of the last output, LAMMPS's thermo
    assert f"{sim.fixes['2'].array(sim)[1, 2]:.8g}" == "0.06540381"


WALLS = """
units lj
atom_style atomic
boundary p f p
lattice sc 0.7
region box block 0 5 0 5 0 4
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 2.0 4928 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0 2.5
fix 1 all nve
fix w all wall/reflect ylo EDGE yhi EDGE
compute c2 all chunk/atom bin/2d y center 1.5 x lower 2.0 units box discard yes
compute c3 all chunk/atom bin/3d x lower 0.5 y upper 0.5 z 0.25 0.5 units lattice
fix 2 all ave/chunk 5 2 10 c2 vx vy fy temp adof 2 cdof 1 file prof.2d
fix 3 all ave/chunk 10 1 20 c3 density/number file prof.3d
"""
# LAMMPS's thermo of c_c2 c_c3 f_2[3][1] f_2[3][2] f_2[3][3] f_2[5][7] at steps 0, 10, .. 40 (%.8g)
WALLS_THERMO = {0: [12, 900, 0, 0, 0, 0], 10: [12, 900, 0.5656197, 5, 14, 2.451567],
                20: [12, 900, 0.5656197, 5, 14, 1.8885231], 30: [12, 900, 0.5656197, 5, 13, 1.9893654],
                40: [12, 900, 0.5656197, 5, 13, 2.1827276]}


def test_two_and_three_dimensional_bins_as_lammps(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command(WALLS)
    for step, want in WALLS_THERMO.items():
        sim.command(f"run {step - sim.step}")
        table = sim.fixes["2"].array(sim)
        got = [sim.computes["c2"].scalar(sim), sim.computes["c3"].scalar(sim), *table[2, :3], table[4, 6]]
        assert [float(f"{g:.8g}") for g in got] == want
    head = read("prof.2d").splitlines()[:5]
    assert head == ["# Chunk-averaged data for fix 2 and group all", "# Timestep Number-of-chunks Total-count",
                    "# Chunk Coord1 Coord2 Ncount vx vy fy temp", "10 12 100",
                    "  1 0.56562 1 10 0.646931 0.956508 -1.31273 2.55064"]


# ---- errors -------------------------------------------------------------------------------------------

@pytest.mark.parametrize("line, message", [
    ("compute q all chunk/atom bin/sphere 0 0 0 1 2 3",
     "compute: style must be one of bin/1d, bin/2d, bin/3d, type, molecule (got bin/sphere)"),
    ("compute q all chunk/atom type region r",
     "compute: keyword region of compute chunk/atom: not in pdps (LAMMPS's compute chunk/atom has it)"),
    ("compute q all chunk/atom bin/1d z lower 1 region r",
     "compute: keyword region of compute chunk/atom: not in pdps (LAMMPS's compute chunk/atom has it)"),
    ("compute q all chunk/atom bin/2d z lower 1 units box",
     "compute: style bin/2d takes 2 DIM ORIGIN DELTA triple(s) (got 1)"),
    ("compute q all chunk/atom type discard mixed", "compute: discard mixed needs a bin style (got type)"),
    ("compute q all chunk/atom bin/1d z lower 0", "compute: bins z: delta must be > 0 (got 0)"),
    ("compute q all chunk/atom bin/2d z lower 1 z lower 2", "compute: compute q chunk/atom: axis z is binned twice"),
    ("compute q all chunk/atom molecule",
     "compute: compute q chunk/atom molecule needs molecule ids (particle_style molecular, bond, angle or full)"),
    ("fix a all ave/chunk 1 1 1 nothere vx", "fix: fix a ave/chunk: compute nothere is not defined"),
    ("fix a all ave/chunk 1 1 1 k vx", "fix: fix a ave/chunk: compute k is ke, not chunk/atom"),
    ("fix a all ave/chunk 1 1 1 c vx bias k",
     "fix: bias is not in pdps: it has no velocity-bias temperature computes"),
    ("fix a all ave/chunk 1 1 1 c vx file a.txt append b.txt", "fix: file and append name one file: give one"),
    ("fix a all ave/chunk 1 1 1 c press",
     "fix: values must be vx, vy, vz, fx, fy, fz, mass, density/number, density/mass, temp, c_ID, c_ID[k], "
     "f_ID, f_ID[k] or v_NAME (got press)"),
    ("fix a all ave/chunk 1 1 1 c vx overwrite", "fix: overwrite needs ave running (LAMMPS)"),
    ("fix b all ave/chunk 2 5 10 c vx\nfix a all ave/chunk 1 1 10 c vx ave running",
     "fix: fix a ave/chunk: compute c is held by fix b over other windows (LAMMPS: \"Two fix commands using same "
     "compute chunk/atom command in incompatible ways\"); give each its own compute chunk/atom"),
    ("fix a all ave/chunk 2 1 5 c vx", "fix: nfreq must be a multiple of nevery (got nevery 2, nfreq 5)"),
    ("fix a all ave/chunk 1 1 1 c vx format %d%d",
     "fix: format must be a C format of one number, %e %f or %g (got %d%d)"),
    ("fix a all ave/chunk 1 1 1 c vx format %s", "fix: format must be a C format of one number, %e %f or %g (got %s)"),
])
def test_bad_input_is_one_line(planes, line, message):
    planes.command("compute c all chunk/atom bin/1d z lower 1 units box\ncompute k all ke")
    with pytest.raises(ScriptError) as error:
        planes.command(line)
    assert str(error.value) == f"<command>:{line.count(chr(10)) + 1}: {message}"


def test_profiles_on_two_ranks_are_those_of_one(tmp_path):
    script = WALLS + ("thermo_style custom step c_c2 f_2[3][2] f_2[3][3] f_2[5][7] f_2[12][4] f_3[450][4]\n"
                      "thermo 10\nrun 40\n")
    one, two = thermo_on_ranks(script, tmp_path)
    assert one.shape == (5, 7) and np.all(one[1:, 2:6] != 0)
    np.testing.assert_allclose(two, one, rtol=1e-12, atol=1e-12)


def test_reduced_bins_follow_the_box_and_their_volume_with_it(planes):
    """units reduced, nchunk once: after the box doubles along z the same two halves hold the
    particles (z/20 now) and the densities divide by the new half volume."""
    planes.command("compute h all chunk/atom bin/1d z lower 0.5 units reduced\n"
                   "fix d all ave/chunk 1 1 1 h density/number\nrun 0")
    np.testing.assert_allclose(planes.fixes["d"].array(planes)[:, 2], [8 / 80, 2 / 80], rtol=1e-15)
    planes.command("change_box all z final 0 20\nrun 1")
    np.testing.assert_allclose(planes.fixes["d"].array(planes)[:, 2], [10 / 160, 0], rtol=1e-15)


def test_too_many_bins_is_one_line(planes):
    with pytest.raises(ScriptError) as error:
        planes.command("compute q all chunk/atom bin/3d x lower 1e-3 y lower 1e-3 z lower 1e-3 units box\n"
                       "fix a all ave/chunk 1 1 1 q vx\nrun 0")
    assert "compute q chunk/atom: bins of 4000 by 4000 by 10000" in str(error.value)


def test_a_fix_of_single_samples_leaves_another_fixs_hold(make_sim):
    """ave running holds compressed chunks for good; a one-sample fix on the same compute must not let
    them change under it: the particle at z 0.5 moves 2 in 10 steps, through the empty slab 1-2 into
    the other's, 2-3 (laid anew, one chunk)."""
    sim = make_sim(dialect="lammps")
    sim.command("units lj\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\nmass 1 1\n"
                "create_atoms 1 single 1 1 0.5\ncreate_atoms 1 single 1 1 2.5\ngroup a id 1\nvelocity a set 0 0 40\n"
                "fix 1 all nve\ncompute c all chunk/atom bin/1d z lower 1 units box compress yes\n"
                "fix r all ave/chunk 1 1 1 c vz ave running\nfix o all ave/chunk 1 1 1 c vz\nrun 10")
    assert sim.computes["c"].scalar(sim) == 2
    assert sim.fixes["r"].array(sim).shape == sim.fixes["o"].array(sim).shape == (2, 4)
    # unfix lets them go: the next window lays them anew; another fix may hold them its own way
    sim.command("unfix r\nrun 1\nfix w all ave/chunk 1 2 2 c vz")
    assert sim.computes["c"].scalar(sim) == 1
