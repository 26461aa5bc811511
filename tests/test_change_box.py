"""change_box as LAMMPS does it: the script of benchmarks/lammps_references/box_commands.py, run by
pdps, prints after each operation the box and positions LAMMPS printed (tests/data/lammps/
change_box.txt: final and delta in lattice and box units, scale, volume of one and two axes, set and
remap of all and of a group, faces made periodic and shrink-wrapped, a box moved lengths away) and
writes LAMMPS's data file (image flags), on one rank and on two. Against formulas: a volume axis
keeps the volume, remap keeps fractional coordinates, the others stay put. A particle left outside
a fixed face is lost at the next run (an error, or gone with thermo_modify lost ignore); the forces
after a change are those of the same particles read into a fresh box of those bounds; a run after
it agrees on one and two ranks. Bad lines are one line each."""

import io
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import build, by_tag, fluid, forces_by_tag, run_ranks, script_error, thermo_on_ranks

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "lammps"
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from box_commands import OPERATIONS, change_box_script  # noqa: E402

LJ = "pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\nmass 1 1.0"
BOX = "units lj\natom_style atomic\natom_modify map array\nregion box block 0 4 0 5 0 6\ncreate_box 1 box\nmass 1 1\n"


def section(path, name):
    """The rows of a data file's section (Atoms, Velocities) as floats, by id."""
    lines = Path(path).read_text().split(f"\n{name}", 1)[1].splitlines()[2:]
    rows = [[float(v) for v in line.split()] for line in lines[:next((k for k, l in enumerate(lines) if not l.strip()),
                                                                      len(lines))]]
    table = np.array(rows)
    return table[np.argsort(table[:, 0])]


def test_each_operation_gives_the_box_and_positions_lammps_prints(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    screen = io.StringIO()
    (tmp_path / "in.box").write_text(change_box_script())
    Simulation(screen=screen, log=None).file(str(tmp_path / "in.box"))
    mine = [line[3:].split() for line in screen.getvalue().splitlines() if line.startswith("@@ ")]
    lammps = [line.split() for line in (DATA / "change_box.txt").read_text().splitlines()]
    assert len(mine) == len(lammps) == len(OPERATIONS)
    for operation, a, b in zip(OPERATIONS, mine, lammps):
        np.testing.assert_allclose(np.array(a, float), np.array(b, float), rtol=1e-15, atol=1e-15,
                                   err_msg=operation)
    np.testing.assert_array_equal(section("change_box.data", "Atoms"), section(DATA / "change_box.data", "Atoms"))


def test_two_ranks_write_lammps_data_file(tmp_path):
    run_ranks(change_box_script(), 2, tmp_path, name="in.box")
    np.testing.assert_array_equal(section(tmp_path / "change_box.data", "Atoms"),
                                  section(DATA / "change_box.data", "Atoms"))


def test_volume_axes_keep_the_volume_about_their_midpoints():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(BOX + "change_box all x scale 1.2 y volume z volume")
    np.testing.assert_allclose(sim.box.length, [4.8, 5 / np.sqrt(1.2), 6 / np.sqrt(1.2)], rtol=1e-15)
    np.testing.assert_allclose(0.5 * (sim.box.lo + sim.box.hi), [2.0, 2.5, 3.0], rtol=1e-15)
    sim.command("change_box all z final 1 4 x volume units box")
    assert sim.box.volume == pytest.approx(4.8 * 5 * 6 / 1.2, rel=1e-14)
    np.testing.assert_allclose([sim.box.lo[2], sim.box.hi[2]], [1.0, 4.0], rtol=0)


def test_remap_carries_the_group_and_leaves_the_others(tmp_path):
    x, length = fluid(60, 0.5, min_distance=0.8)
    sim = build(tmp_path, x, setup="group low id 1:30", hi=(length,) * 3)
    sim.command("change_box low x final -1 8 y delta 0.5 -0.25 remap z scale 2 set remap units box")
    moved = by_tag(sim, sim.x)
    # the others stay, wrapped into the new box along y; the group's z too: the second remap starts
    # from the box set after z scale
    others = x[30:].copy()
    others[:, 1] = 0.5 + np.mod(others[:, 1] - 0.5, length - 0.75)
    np.testing.assert_allclose(moved[30:], others, rtol=0, atol=1e-14)
    expected = x[:30].copy()
    expected[:, 0] = -1 + 9 * x[:30, 0] / length
    expected[:, 1] = 0.5 + (length - 0.75) * x[:30, 1] / length
    np.testing.assert_allclose(moved[:30], expected, rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(sim.box.lo, [-1, 0.5, -0.5 * length], rtol=1e-15)


def test_a_particle_left_outside_a_fixed_face_is_lost_at_the_next_run(pdps_cli):
    script = ("units lj\natom_style atomic\nboundary p p f\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\n"
              "create_atoms 1 single 1 1 3.5\ncreate_atoms 1 single 1 1 1.5\nmass 1 1\n"
              "change_box all z final 0 3\n{lost}run 0\nprint \"@@ $(atoms)\"\n")
    done = pdps_cli(script.format(lost=""), "-log", "none")
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [
        "ERROR: in.test:10: run: particle 1 lost through the fixed z boundary at step 0: z = 3.5 outside [0, 3] "
        "(1 particle(s) outside)"]
    done = pdps_cli(script.format(lost="thermo_modify lost ignore\n"), "-log", "none")
    assert done.returncode == 0
    assert "@@ 1" in done.stdout.splitlines()


def test_a_face_made_periodic_wraps_and_one_made_fixed_forgets_its_images():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\natom_style atomic\nboundary p f p\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\n"
                "create_atoms 1 single 3.5 3.5 1 units box\nmass 1 1\nset atom 1 image 2 0 -1\n"
                "change_box all y final 0 3 boundary f p p units box")
    np.testing.assert_allclose(sim.x[0], [3.5, 0.5, 1.0], rtol=1e-15)
    np.testing.assert_array_equal(sim.particles.image[0], [0, 1, -1])


def test_forces_after_the_change_are_those_of_a_fresh_box(tmp_path):
    x, length = fluid(120, 0.7, min_distance=0.85)
    sim = build(tmp_path, x, setup=LJ + "\nrun 0", hi=(length,) * 3, boundary="p p f")
    sim.command("change_box all boundary p f p x scale 1.05 y delta -0.1 0.2 remap z scale 0.98 units box\nrun 0")
    lo, hi = sim.box.lo.copy(), sim.box.hi.copy()
    fresh = build(tmp_path, by_tag(sim, sim.x), setup=LJ + "\nrun 0", lo=lo, hi=hi, boundary="p f p",
                  name="fresh.data")
    np.testing.assert_allclose(forces_by_tag(sim), forces_by_tag(fresh), rtol=1e-10, atol=1e-10)


def test_a_run_after_it_agrees_on_one_and_two_ranks(tmp_path):
    script = """
        units lj
        atom_style atomic
        lattice fcc 0.8442
        region box block 0 4 0 4 0 4
        create_box 1 box
        create_atoms 1 box
        mass 1 1.0
        velocity all create 1.2 4928 loop geom
        pair_style lj/cut 2.5
        pair_coeff 1 1 1.0 1.0
        fix 1 all nve
        thermo_style custom step pe ke press vol
        thermo_modify format float %20.15g
        thermo 25
        run 50
        change_box all x scale 1.08 y volume remap boundary p p s
        run 50
        change_box all z final 0.2 5 boundary p p p x delta 0.3 0.3
        run 50
    """
    one, two = thermo_on_ranks(script, tmp_path)
    np.testing.assert_allclose(two, one, rtol=1e-10, atol=1e-10)
    spacing = (4 / 0.8442) ** (1 / 3)
    # 1.08 L by L / 1.08 by 4.8 spacings (z final 0.2 5 in lattice units), L = 4 spacings; z, still
    # shrink-wrapped when it is set, has its faces moved out by 1e-4 of that length each (LAMMPS's)
    assert one[-1][4] == pytest.approx(4 * 4 * 4.8 * spacing ** 3 * (1 + 2e-4), rel=1e-13)


@pytest.mark.parametrize("line, message", [
    ("change_box all", "expected at least one operation; usage: change_box GROUP-ID x|y|z final LO HI|delta DLO "
     "DHI|scale F|volume, boundary BX BY BZ, set, remap ... [units lattice|box]"),
    ("change_box all x", "x needs a style: final, delta, scale or volume"),
    ("change_box all x final 1", "x final needs LO HI (got 1)"),
    ("change_box all x final 1 units box", "x final needs LO HI (got 1 units)"),
    ("change_box all x shrink 1", "x style must be one of final, delta, scale, volume (got shrink)"),
    ("change_box all y volume", "y volume must follow an x, y or z change of another axis (with at most one "
     "other volume)"),
    ("change_box all x scale 2 x volume", "x volume must follow an x, y or z change of another axis (with at "
     "most one other volume)"),
    ("change_box all x scale 2 y volume z volume x volume", "x volume must follow an x, y or z change of another "
     "axis (with at most one other volume)"),
    ("change_box all xy final 1", "xy: pdps boxes are orthogonal (no tilt); change_box takes x, y, z, boundary, "
     "set and remap"),
    ("change_box all ortho", "ortho: pdps boxes are orthogonal (no tilt); change_box takes x, y, z, boundary, "
     "set and remap"),
    ("change_box all x final 3 1 units box", "x final 3 1: the box's x bounds must have lo < hi (got 3 1)"),
    ("change_box all x scale 0", "x scale FACTOR must be > 0 (got 0)"),
    ("change_box all x final 0 nan", "x final HI must be finite (got nan)"),
    ("change_box all boundary p q p", "boundary y must be one of p, f, s, m, ff, fs, fm, sf, ss, sm, mf, ms, mm "
     "(got q)"),
    ("change_box all boundary p p", "boundary needs BX BY BZ (got p p)"),
    ("change_box all remap units pizza", "units must be one of box, lattice (got pizza)"),
    ("change_box all remap units", "after the operations only units lattice|box may follow; usage: change_box "
     "GROUP-ID x|y|z final LO HI|delta DLO DHI|scale F|volume, boundary BX BY BZ, set, remap ... [units "
     "lattice|box]"),
    ("change_box all remap x", "x needs a style: final, delta, scale or volume"),
    ("change_box all squash", "unknown operation squash; usage: change_box GROUP-ID x|y|z final LO HI|delta DLO "
     "DHI|scale F|volume, boundary BX BY BZ, set, remap ... [units lattice|box]"),
    ("change_box nobody remap", "group nobody is not defined (defined: all)"),
])
def test_bad_lines_are_one_line(pdps_cli, line, message):
    done = pdps_cli(BOX + line + "\n", "-log", "none")
    assert done.returncode == 1
    assert done.stderr.strip().splitlines() == [f"ERROR: in.test:7: change_box: {message}"]


def test_a_2d_box_keeps_z():
    setup = "dimension 2\nregion box block 0 4 0 4 -0.5 0.5\ncreate_box 1 box"
    assert script_error(setup, "change_box all z scale 2").message == "a 2-d simulation's box cannot change in z"
    assert script_error(setup, "change_box all boundary p p f").message == (
        "a 2-d simulation needs a periodic z boundary (got boundary z f)")


def test_before_a_box_it_is_refused():
    assert script_error("units lj", "change_box all x scale 2").message == (
        "change_box before the simulation box exists (use create_box or read_data first)")


def test_units_default_by_dialect():
    """FINAL and DELTA are lattice spacings in the LAMMPS dialect, box units in LIGGGHTS's (its
    change_box.cpp; the recorded change_box case of tests/data/liggghts.cases.json measures it)."""
    for dialect, hi in (("lammps", 2 * 0.5), ("liggghts", 2.0)):
        sim = Simulation(screen=False, log=None, dialect=dialect)
        sim.command("units lj\natom_style atomic\nlattice sc 8.0\nregion box block 0 4 0 4 0 4 units box\n"
                    "create_box 1 box\nchange_box all x final 0 2")
        assert sim.box.hi[0] == pytest.approx(hi, rel=1e-14)
