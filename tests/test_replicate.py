"""replicate as LAMMPS does it: the script of benchmarks/lammps_references/box_commands.py (molecular
particles with image flags, two types, velocities, replicated 2 x 3 x 1), run by pdps on one rank and
on two, writes LAMMPS's data file (tests/data/lammps/replicate.data): ids, molecule ids, types,
positions, image flags and velocities exact. Against formulas: an fcc crystal replicated has the
energy per particle and pressure of the larger crystal made at once; LIGGGHTS's offset form places
copies at the shifted position plus the offsets with ids counting z fastest; copies take radii,
masses, spins and a fix property/atom's values. What copies must not take (rigid bodies, open
contacts, a particle's earlier position) is refused at the line; bad lines are one line each."""

import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import by_tag, lj_fcc, run_ranks, script_error

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "lammps"
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
sys.path.insert(0, str(ROOT / "benchmarks" / "liggghts_references"))
from box_commands import REPLICATE  # noqa: E402
from cases import BED, HEAD, SUMS  # noqa: E402

USAGE = "replicate NX NY NZ [bbox] | replicate NX NY NZ offset OX OY OZ [shift SX SY SZ]"
BOX = "units lj\natom_style atomic\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\ncreate_atoms 1 single 1 1 1\nmass 1 1\n"


def section(path, name):
    """The rows of a data file's section (Atoms, Velocities) as floats, by id."""
    lines = Path(path).read_text().split(f"\n{name}", 1)[1].splitlines()[2:]
    end = next((k for k, line in enumerate(lines) if not line.strip()), len(lines))
    table = np.array([[float(v) for v in line.split()] for line in lines[:end]])
    return table[np.argsort(table[:, 0])]


def test_the_replicated_particles_are_lammps_ones(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "in.rep").write_text(REPLICATE)
    Simulation(screen=False, log=None).file(str(tmp_path / "in.rep"))
    for name in ("Atoms", "Velocities"):
        mine, lammps = section("replicate.data", name), section(DATA / "replicate.data", name)
        assert len(mine) == len(lammps) == 72
        np.testing.assert_array_equal(mine, lammps, err_msg=name)


def test_two_ranks_make_the_same_particles(tmp_path):
    run_ranks(REPLICATE, 2, tmp_path, name="in.rep")
    np.testing.assert_array_equal(section(tmp_path / "replicate.data", "Atoms"), section(DATA / "replicate.data", "Atoms"))
    # velocity create scales by sums over ranks: the last digit may differ
    np.testing.assert_allclose(section(tmp_path / "replicate.data", "Velocities"),
                               section(DATA / "replicate.data", "Velocities"), rtol=0, atol=1e-15)


def test_a_replicated_crystal_is_the_larger_crystal():
    """An fcc crystal of 3 cells a side replicated 2 x 2 x 2 is the crystal of 6 cells: 8 times the
    particles in 8 times the volume, the same energy per particle and pressure, ids 1..864."""
    thermo = "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\nrun 0\n"
    small = Simulation(screen=False, log=None, dialect="lammps")
    small.command(lj_fcc(3) + "mass 1 1.0\nreplicate 2 2 2\n" + thermo)
    large = Simulation(screen=False, log=None, dialect="lammps")
    large.command(lj_fcc(6) + "mass 1 1.0\n" + thermo)
    assert small.nlocal == large.nlocal == 864
    np.testing.assert_array_equal(np.sort(small.tag), np.arange(1, 865))
    np.testing.assert_allclose(small.box.hi, large.box.hi, rtol=1e-15)
    for key in ("pe", "press", "vol"):
        assert small.variables.evaluate(key) == pytest.approx(large.variables.evaluate(key), rel=1e-12)


def test_ids_add_multiples_of_the_largest_id():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\natom_style atomic\nregion box block 0 3 0 3 0 3\ncreate_box 1 box\nmass 1 1\n"
                "create_atoms 1 single 0.5 0.5 0.5\ncreate_atoms 1 single 1.5 0.5 0.5\n"
                "create_atoms 1 single 2.5 0.5 0.5\ngroup two id 2\ndelete_atoms group two compress no\n"
                "replicate 1 2 1")
    np.testing.assert_array_equal(np.sort(sim.tag), [1, 3, 4, 6])
    np.testing.assert_allclose(by_tag(sim, sim.x)[:, 1], [0.5, 0.5, 3.5, 3.5], rtol=0)


def test_liggghts_copies_lie_at_the_offsets_from_the_shifted_particles():
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command("units lj\natom_style atomic\nboundary p p p\nregion box block 0 2 0 2 0 2\ncreate_box 1 box\n"
                "create_atoms 1 single 0.5 0.5 0.5\ncreate_atoms 1 single 1.5 0.5 1.5\nmass 1 1\n"
                "set atom 2 image 1 0 -1\nreplicate 1 2 2 offset 0 3 2.5 shift 0.1 0 -0.2")
    np.testing.assert_allclose(sim.box.lo, [0.1, 0, -0.2], rtol=1e-15)
    np.testing.assert_allclose(sim.box.hi, [2.1, 4, 3.8], rtol=1e-15)
    x, image = by_tag(sim, sim.x), by_tag(sim, sim.particles.image[:sim.nlocal])
    originals = np.array([[0.6, 0.5, 0.3], [1.6, 0.5, 1.3]])
    # copy (i, j, k) adds ((i NY + j) NZ + k) x 2 to the ids: (0,0,1) ids 3 4, (0,1,0) 5 6, (0,1,1) 7 8
    for multiple, (j, k) in enumerate([(0, 0), (0, 1), (1, 0), (1, 1)]):
        np.testing.assert_allclose(x[2 * multiple:2 * multiple + 2], originals + [0, 3 * j, 2.5 * k], rtol=1e-15)
        np.testing.assert_array_equal(image[2 * multiple + 1], [1, 0, -1])


def test_copies_take_the_particles_values():
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command("units si\natom_style granular\nboundary p p p\nregion box block 0 1 0 1 0 1 units box\n"
                "create_box 1 box\ncreate_atoms 1 single 0.5 0.5 0.5 units box\nset atom 1 diameter 0.2 density 900\n"
                "set atom 1 omegax 3.0\nvelocity all set 1 2 3 units box\n"
                "fix t all property/atom temperature scalar yes no no 300.0\nset atom 1 property/atom temperature 350.0\n"
                "replicate 2 2 1 offset 1 1 0")
    p = sim.particles
    assert p.nlocal == 4
    np.testing.assert_array_equal(p.radius[:4], 0.1)
    np.testing.assert_allclose(p.rmass[:4], 900 * 4 / 3 * np.pi * 0.1 ** 3, rtol=1e-15)
    np.testing.assert_array_equal(p.omega[:4], [[3.0, 0, 0]] * 4)
    np.testing.assert_array_equal(sim.v, [[1.0, 2.0, 3.0]] * 4)
    np.testing.assert_array_equal(p.arrays["temperature"][:4], 350.0)


def test_open_contacts_are_refused():
    """After 2700 steps of the bed 16 spheres touch the floor: their copies would claim partners that
    are not theirs."""
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(HEAD + BED + SUMS + "fix integr all nve/sphere\nrun 2700")
    with pytest.raises(ScriptError) as caught:
        sim.command("replicate 2 1 1 offset 0.08 0 0")
    assert caught.value.message == ("replicate cannot copy contacts (wall_floor_partner: 16 open): a copy's "
                                    "partners are other copies; replicate before the first run")


@pytest.mark.parametrize("setup, name", [
    ("fix 1 all rigid single", "rigid_body_1"),
    ("fix 1 all spring/self 2.0\nrun 0", "spring_self_origin_1"),
])
def test_what_copies_must_not_share_is_refused(setup, name):
    message = script_error(lj_fcc(2) + "mass 1 1.0\n" + setup, "replicate 2 1 1").message
    assert message == (f"replicate cannot copy the per-particle values {name} a style keeps (a rigid body's "
                       "members, a particle's earlier position: copies must not share them); replicate before "
                       "defining the styles that keep them, or before the run that made them")


@pytest.mark.parametrize("line, message", [
    ("replicate 0 1 1", "nx must be >= 1 (got 0)"),
    ("replicate 2 2", f"missing argument nz; usage: {USAGE}"),
    ("replicate 2.5 1 1", "nx must be an integer (got 2.5)"),
    ("replicate 2 2 2 twice", "option must be one of 'bbox' or 'bondlist' (got twice)"),
    ("replicate 2 2 2 bondlist", "replicate bondlist re-links bonds across the copies, and pdps has no bonds: "
     "replicate NX NY NZ"),
    ("replicate 2 2 2 shift 1 1 1", f"shift goes with offset (LIGGGHTS's replicate); usage: {USAGE}"),
    ("replicate 2 2 2 bbox offset 1 1 1", f"bbox is LAMMPS's replicate's, offset LIGGGHTS's: give one; usage: {USAGE}"),
    ("replicate 2 2 2 offset 1 1", "keyword offset needs 3 value(s) (got 2)"),
    ("replicate 2 1 1 offset 1 nan 1", "offset must be a finite number (got nan)"),
    ("replicate 3000 3000 3000", "replicate 3000 3000 3000 would make 26999999999 particles (at most 20000000 at once)"),
])
def test_bad_lines_are_one_line(pdps_cli, line, message):
    done = pdps_cli(BOX + line + "\n", "-log", "none")
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [f"ERROR: in.test:7: replicate: {message}"]


def test_a_particle_outside_a_fixed_face_is_refused():
    setup = ("boundary p p f\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\ncreate_atoms 1 single 1 1 1\n"
             "mass 1 1\nset atom 1 z 4.5")
    assert script_error(setup, "replicate 2 1 1").message == (
        "particle 1 lies outside the box's non-periodic z faces (z = 4.5 outside [0, 4]): replicate copies "
        "particles in the box (LAMMPS's refuses so too)")


def test_a_2d_simulation_is_not_replicated_in_z():
    setup = "dimension 2\nregion box block 0 4 0 4 -0.5 0.5\ncreate_box 1 box"
    assert script_error(setup, "replicate 1 1 2").message == "a 2-d simulation cannot be replicated in z (nz = 2)"


def test_a_non_periodic_axis_replicated_is_warned():
    sim = Simulation(screen=False, log=None)
    sim.command("boundary p f p\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\ncreate_particle 1 single 1 1 1\n"
                "replicate 1 2 1")
    assert sim.warnings == ["Replicating in a non-periodic dimension"]
    assert sim.nlocal == 2 and sim.box.hi[1] == 8.0
