"""fix wall/gran: LAMMPS's recorded trajectories of spheres on planes and cylinders (data/wall_gran/,
recorded by benchmarks/lammps_references/gran.py), the law against its formulas, and bad input.

The reference scripts use LAMMPS's fix nve/sphere and fix addforce; here the kit's test/nve_sphere
and test/force stand in for them (the same integrator and the same constant force, without needing
another plugin)."""

import math
import textwrap
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import ConstantForce, Record, SphereVerlet, assert_refused, recorded_case, register_styles

DATA = Path(__file__).parent / "data" / "wall_gran"
STAND_INS = (("nve/sphere", "test/nve_sphere"), ("addforce", "test/force"))
M1 = 1.9098593171027440      # density of a sphere of diameter 1 and mass 1
HOOKE = "200000.0 NULL 50.0 NULL 0.5 1"

CASES = ["wall_zplane_hooke_history", "wall_zplane_hooke", "wall_xplane_hertz_limit_damping",
         "wall_yplane_dampflag0", "wall_zcylinder_inside", "wall_zcylinder_hertz_outside",
         "wall_zplane_wiggle", "wall_zplane_shear"]


@pytest.fixture(autouse=True)
def styles():
    register_styles(SphereVerlet, ConstantForce, Record)


def reference(name, folder=DATA):
    table = {}
    for line in (folder / f"{name}.ref").read_text().splitlines():
        if not line.startswith("#"):
            words = line.split()
            table.setdefault(int(words[0]), []).append([float(w) for w in words[1:]])
    return {step: np.array(rows) for step, rows in table.items()}


# fix wall/gran granular's cases (pair granular's models), recorded by benchmarks/lammps_references/granular.py
GRANULAR = Path(__file__).parent / "data" / "wall_granular"


@pytest.mark.parametrize("folder, name", [(DATA, name) for name in CASES]
                         + [(GRANULAR, path.stem) for path in sorted(GRANULAR.glob("*.ref"))])
def test_trajectories_equal_lammps(tmp_path, folder, name):
    """x, v, omega of every particle at every dumped step equal LAMMPS's to 1e-12 of their scale."""
    record = recorded_case(folder, name, tmp_path, STAND_INS)
    table = reference(name, folder)
    steps = sorted(s for s in table if s > 0)
    assert len(record.x) == steps[-1]
    for columns, key in ((slice(1, 4), "x"), (slice(4, 7), "v"), (slice(7, 10), "omega")):
        scale = max(np.abs(rows[:, columns]).max() for rows in table.values())
        for step in steps:
            np.testing.assert_allclose(getattr(record, key)[step - 1], table[step][:, columns], rtol=0,
                                       atol=1e-12 * scale, err_msg=f"{name}: {key} at step {step}")
    assert not np.allclose(record.v[-1], record.v[0])


def one_sphere(tmp_path, x, lines, boundary="p p f", box="0 10 0 10 0 10", diameter=1.0, density=M1):
    """One sphere at x read from a data file (LAMMPS's syntax, lj units), then ``lines``."""
    lo_hi = box.split()
    (tmp_path / "one.data").write_text("\n".join(
        ["one sphere", "", "1 atoms", "1 atom types", ""]
        + [f"{lo_hi[2 * d]} {lo_hi[2 * d + 1]} {a}lo {a}hi" for d, a in enumerate("xyz")]
        + ["", "Atoms # sphere", "", f"1 1 {diameter!r} {density!r} {x[0]!r} {x[1]!r} {x[2]!r}"]) + "\n")
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"units lj\natom_style sphere\nboundary {boundary}\nread_data {tmp_path / 'one.data'}\n"
                + textwrap.dedent(lines))
    return sim


def sphere_on_wall(tmp_path, wall, x, v=(0, 0, 0), omega=(0, 0, 0), boundary="p p f",
                   box="0 10 0 10 0 10", diameter=1.0, density=M1):
    sim = one_sphere(tmp_path, x, f"timestep 0.0001\nfix w all wall/gran {wall}\nrun 0",
                     boundary, box, diameter, density)
    sim.particles.v[0] = v
    sim.particles.omega[0] = omega
    sim.command("run 0")
    return sim.f[0].copy(), sim.particles.torque[0].copy()


def test_a_sphere_on_a_plane_feels_hookes_law_and_mass_scaled_damping(tmp_path):
    """Resting on zplane 0 with overlap 0.01, moving down at 0.5 and sideways, spinning: F_n = kn
    delta - m gamma_n v_n along +z; F_t = -m gamma_t v_tr (the spring is zero at setup);
    torque -R n x F_t."""
    v, omega = np.array([0.3, 0.0, -0.5]), np.array([0.0, 2.0, 0.0])
    f, torque = sphere_on_wall(tmp_path, f"hooke/history {HOOKE} zplane 0.0 NULL", (5, 5, 0.49), v, omega)
    n = np.array([0.0, 0.0, 1.0])
    vtr = v - (v @ n) * n - np.cross(0.5 * omega, n)
    ft = -1.0 * 25.0 * vtr
    assert f == pytest.approx((200000.0 * 0.01 - 50.0 * (-0.5)) * n + ft, rel=1e-12)
    assert torque == pytest.approx(-0.5 * np.cross(n, ft), rel=1e-12)


def test_hertz_on_a_plane_scales_by_the_root_of_overlap_times_radius(tmp_path):
    f, _ = sphere_on_wall(tmp_path, "hertz/history 2000000.0 NULL 400.0 NULL 0.5 1 zplane 0.0 NULL",
                          (5, 5, 0.49), (0, 0, -0.5))
    assert f == pytest.approx([0, 0, math.sqrt(0.01 * 0.5) * (2.0e6 * 0.01 + 400.0 * 0.5)], rel=1e-12)


@pytest.mark.parametrize("x, expected", [(0.45, 1.0), (9.55, -1.0), (4.0, 0.0)])
def test_only_the_nearer_plane_pushes(tmp_path, x, expected):
    f, _ = sphere_on_wall(tmp_path, f"hooke {HOOKE} xplane 0.0 10.0", (x, 5, 5), boundary="f p p")
    assert f == pytest.approx([expected * 200000.0 * 0.05, 0, 0], rel=1e-12, abs=1e-12)


def test_a_cylinder_wall_uses_lammps_effective_radius_inside_and_outside(tmp_path):
    """R* = R R_w / (R + R_w) with R_w = -2 R_c inside, +2 R_c outside (LAMMPS)."""
    box, boundary = "-8 8 -8 8 0 10", "f f p"
    wall = "hertz/history 2000000.0 NULL 0.0 NULL 0.5 1 zcylinder 4.0"
    inside, _ = sphere_on_wall(tmp_path, wall, (3.51, 0, 5), box=box, boundary=boundary)
    outside, _ = sphere_on_wall(tmp_path, wall, (0, 4.49, 5), box=box, boundary=boundary)
    for force, r_wall, n in ((inside, -8.0, [-1, 0, 0]), (outside, 8.0, [0, 1, 0])):
        r_eff = 0.5 * r_wall / (0.5 + r_wall)
        assert force == pytest.approx(2.0e6 * math.sqrt(0.01 * r_eff) * 0.01 * np.array(n), rel=1e-12,
                                      abs=1e-9)


def test_a_turning_cylinder_drags_a_sphere_at_its_own_contact_point(tmp_path):
    """shear x on zcylinder: the surface moves at vshear (y, -x, 0)/|(x, y)|; a sphere at rest at
    (0, 3.51) inside R_c = 4 feels the damping m gamma_t vshear along -x (hooke: below mu F_n)."""
    f, _ = sphere_on_wall(tmp_path, f"hooke {HOOKE} zcylinder 4.0 shear x 0.2", (0, 3.51, 5),
                          box="-8 8 -8 8 0 10", boundary="f f p")
    wall_velocity = 0.2 * np.array([3.51, 0.0, 0.0]) / 3.51
    assert f == pytest.approx(200000.0 * 0.01 * np.array([0, -1, 0]) + 25.0 * wall_velocity, rel=1e-12)


def test_the_spring_grows_in_contact_and_is_zeroed_when_the_sphere_leaves(tmp_path):
    """A sphere sliding on the floor while lifting off: its spring holds v_t dt per step (stuck
    below the Coulomb limit at first), and is gone once it no longer touches (its contact slot
    freed: an empty slot)."""
    sim = one_sphere(tmp_path, (5, 5, 0.499), f"""
        timestep 0.0001
        fix 1 all test/nve_sphere
        fix w all wall/gran hooke/history {HOOKE} zplane 0.0 NULL
        """)
    sim.particles.v[0] = (0.01, 0.0, 2.0)
    sim.command("run 1")
    partner, spring = sim.fixes["w"].history.partner, sim.fixes["w"].history.values
    assert partner[0, 0] == 0
    assert spring[0, :3] == pytest.approx([0.01 * 0.0001, 0.0, 0.0], rel=1e-2)
    sim.command("run 20")
    assert sim.x[0, 2] > 0.5
    assert (sim.fixes["w"].history.partner[0] < 0).all()


@pytest.mark.parametrize("neighbor", ["neigh_modify delay 0 every 1 check yes", "neigh_modify every 40 check no"])
def test_a_sphere_arriving_from_far_between_rebuilds_bounces_as_if_always_watched(tmp_path, neighbor):
    """Only particles within radius + skin of the wall at a rebuild are visited: a sphere thrown
    from 10 radii away (0.005 per step, the skin 0.3 crossed in 60 steps) is still caught by the
    floor, and bounces with the restitution of a contact followed at every step: Hooke's
    e = exp(-pi zeta / sqrt(1 - zeta^2)) with m* gamma_n = 50, k = 2e5 (LAMMPS's damping)."""
    sim = one_sphere(tmp_path, (5, 5, 5.0), f"""
        {neighbor}
        timestep 0.0001
        fix 1 all test/nve_sphere
        fix w all wall/gran hooke 200000.0 NULL 50.0 NULL 0.5 0 zplane 0.0 NULL
        """)
    sim.particles.v[0] = (0.0, 0.0, -50.0)
    sim.command("run 1000")
    zeta = 50.0 / (2.0 * math.sqrt(200000.0))
    restitution = math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta * zeta))
    assert sim.v[0, 2] > 0.0 and sim.x[0, 2] > 0.5
    assert sim.v[0, 2] == pytest.approx(50.0 * restitution, rel=2e-2)


@pytest.mark.parametrize("words, message", [
    ("hooke/histroy 1 NULL 1 NULL 0.5 1 zplane 0 NULL",
     "style must be one of 'hooke', 'hooke/history' or 'hertz/history' (got hooke/histroy)"),
    ("hooke -1 NULL 1 NULL 0.5 1 zplane 0 NULL", "Kn must be >= 0 (got -1)"),
    ("hooke 1 NULL 1 NULL 0.5 2 zplane 0 NULL", "dampflag must be <= 1 (got 2)"),
    ("hooke 1 NULL 1 NULL 20000 1 zplane 0 NULL", "xmu must be <= 10000 (got 20000)"),
    ("hooke 1 NULL 1 NULL 0.5 1 zplane 0", "wallstyle zplane takes 2 value(s): number number (got 0)"),
    ("hooke 1 NULL 1 NULL 0.5 1 plane 0 1", "wallstyle must be one of xplane, yplane, zplane, zcylinder (got plane)"),
    ("hooke 1 NULL 1 NULL 0.5 1 xplane 0 NULL", "xplane needs a box not periodic in x (boundary f or s there)"),
    ("hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL shear z 1", "shear z would move a zplane wall along its own "
     "normal; shear along a direction in the plane"),
    ("hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL wiggle z 0.1 0", "wiggle period must be > 0 (got 0)"),
    ("hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL wiggle z 0.1 1 shear x 1", "a wall can wiggle or shear, not both"),
    ("hooke 1 NULL 1 NULL 0.5 1 zplane 0 NULL push 1", "unknown keyword push (known: wiggle, shear)"),
])
def test_bad_arguments_get_one_line(pdps_cli, words, message):
    done = pdps_cli(f"""\
        units lj
        atom_style sphere
        boundary p p f
        region box block 0 10 0 10 0 10
        create_box 1 box
        fix w all wall/gran {words}
        """)
    assert_refused(done, 6, f"fix: {message}")
