"""Force fixes against their formulas: viscous decay, acc with a region, Stokes drag, buoyancy and
settling, LAMMPS's constant addforce, setforce with NULL, gravity directions; one-line errors."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import by_tag, sphere_mass


# ---- viscous ------------------------------------------------------------------------------------
def _viscous_decay(spheres, dt, gamma=0.5, t=1.0):
    sim = spheres(f"""
        create_particle 1 single 0 0 0 diameter 1.0 density 2.0
        create_particle 1 single 5 0 0 diameter 0.8 density 1.0
        timestep {dt!r}
        fix 1 all nve/sphere
        fix 2 all viscous {gamma}
    """)
    v0 = np.array([1.0, -2.0, 0.5])
    sim.v[:] = v0
    sim.command(f"run {round(t / dt)}")
    rate = gamma / np.array([sphere_mass(1.0, 2.0), sphere_mass(0.8, 1.0)])
    exact = v0 * np.exp(-rate * t)[:, None]
    return by_tag(sim, sim.v), exact, rate


def test_viscous_damping_decays_velocity_exponentially_to_first_order(spheres):
    t = 1.0
    coarse, exact, rate = _viscous_decay(spheres, 0.002, t=t)
    fine, _, _ = _viscous_decay(spheres, 0.001, t=t)
    error_coarse = np.abs(coarse / exact - 1.0)
    error_fine = np.abs(fine / exact - 1.0)
    # the force is taken from the half-step velocity: v_N / v(t) = 1 - (gamma/m)^2 t dt / 2 + ...
    expected = (rate ** 2 * t * 0.002 / 2.0)[:, None] * np.ones(3)
    np.testing.assert_allclose(error_coarse, expected, rtol=0.05)
    np.testing.assert_allclose(error_coarse / error_fine, 2.0, rtol=0.05)


# ---- acc ----------------------------------------------------------------------------------------
def test_acc_with_a_region_accelerates_only_particles_inside(spheres):
    sim = spheres("""
        region right block 0 INF -INF INF -INF INF
        create_particle 1 single -5 0 0 diameter 1.0 density 2.0
        create_particle 1 single 5 0 0 diameter 1.0 density 1.0
        create_particle 1 single 0.505 5 0 diameter 0.5 density 3.0
        timestep 0.01
        fix 1 all nve/sphere
        fix 2 all acc gravity z -2.0 region right
        run 0
    """)
    mass = np.array([sphere_mass(1.0, 2.0), sphere_mass(1.0, 1.0), sphere_mass(0.5, 3.0)])
    np.testing.assert_allclose(by_tag(sim, sim.f), [[0, 0, 0], [0, 0, -2.0 * mass[1]],
                                                    [0, 0, -2.0 * mass[2]]], rtol=1e-15)
    order = np.argsort(sim.tag)
    sim.v[order[2]] = [-1.0, 0.0, 0.0]      # leaves the region after its 50th step
    sim.command("run 100")
    x, v = by_tag(sim, sim.x), by_tag(sim, sim.v)
    np.testing.assert_array_equal(x[0], [-5.0, 0.0, 0.0])
    np.testing.assert_allclose(x[1], [5.0, 0.0, -1.0], rtol=0, atol=1e-12)     # z = -a t^2 / 2
    # kicked by the setup force and steps 1-50 (inside at x = 0.505 - 0.01 n), then coasting
    np.testing.assert_allclose(v[2], [-1.0, 0.0, -2.0 * 0.01 * 50.5], rtol=1e-12)


def test_acc_uses_the_type_mass_of_point_particles(make_plain):
    sim = make_plain()
    sim.command("fix 1 all acc gravity x 3.0\nrun 0")
    np.testing.assert_allclose(sim.f, [[6.0, 0.0, 0.0]] * 2, rtol=1e-15)


# ---- addforce -----------------------------------------------------------------------------------
def test_stokes_drag_opposes_velocity_with_six_pi_mu_r(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0
        create_particle 1 single 5 0 0 diameter 0.3
        fix 1 all addforce drag_stokes 0.3
    """)
    v = np.array([[1.0, -2.0, 0.5], [0.0, 3.0, 0.0]])
    sim.v[np.argsort(sim.tag)] = v
    sim.command("run 0")
    radius = np.array([0.5, 0.15])
    np.testing.assert_allclose(by_tag(sim, sim.f), -6.0 * math.pi * 0.3 * radius[:, None] * v,
                               rtol=1e-15)


@pytest.mark.parametrize("words", ["buoyancy z 0.789 9.81", "buoyancy z 7.74009"])
def test_buoyancy_is_rho_g_times_the_volume_along_its_axis(spheres, words):
    sim = spheres(f"""
        create_particle 1 single 0 0 0 diameter 1.0
        create_particle 1 single 5 0 0 diameter 0.4
        fix 1 all addforce {words}
        run 0
    """)
    volume = 4.0 / 3.0 * math.pi * np.array([0.5, 0.2]) ** 3
    np.testing.assert_allclose(by_tag(sim, sim.f), np.outer(7.74009 * volume, [0, 0, 1]), rtol=1e-15)


def test_buoyancy_in_2d_uses_the_disc_area(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0
        fix 1 all addforce buoyancy y 2.0 -1.5
        run 0
    """, dimension=2)
    np.testing.assert_allclose(sim.f[0], [0.0, -3.0 * math.pi * 0.25, 0.0], rtol=1e-15)


def test_a_sphere_as_dense_as_the_fluid_floats(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 0.7 density 2.5
        fix 1 all gravity 9.81 vector 0 0 -1
        fix 2 all addforce buoyancy z 2.5 9.81
        run 0
    """)
    np.testing.assert_allclose(sim.f[0], 0.0, rtol=0, atol=1e-14)


def test_settling_sphere_reaches_stokes_terminal_velocity(spheres):
    """m dv/dt = (rho_p - rho_f) V g - 6 pi mu R v: v -> 2/9 (rho_p - rho_f) g R^2 / mu."""
    radius, rho_p, rho_f, g, mu = 0.5, 2.0, 1.0, 1.0, 0.1
    sim = spheres(f"""
        create_particle 1 single 0 0 0 diameter {2 * radius} density {rho_p}
        timestep 0.01
        fix 1 all nve/sphere
        fix 2 all gravity {g} vector 0 0 -1
        fix 3 all addforce buoyancy z {rho_f} {g} drag_stokes {mu}
        run 2500
    """, box="-5 5 -5 5 -20 20")
    relaxation = sphere_mass(2 * radius, rho_p) / (6 * math.pi * mu * radius)
    assert 2500 * 0.01 > 20 * relaxation
    terminal = 2.0 / 9.0 * (rho_p - rho_f) * g * radius ** 2 / mu
    np.testing.assert_allclose(sim.v[0], [0.0, 0.0, -terminal], rtol=1e-8)


def test_lammps_constant_addforce_respects_the_group(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0
        create_particle 2 single 5 0 0 diameter 1.0
        group one type 1
        fix 1 one addforce 1.0 0.0 -2.0
        run 0
    """, ntypes=2)
    np.testing.assert_array_equal(by_tag(sim, sim.f), [[1.0, 0.0, -2.0], [0.0, 0.0, 0.0]])


# ---- setforce -----------------------------------------------------------------------------------
def test_setforce_sets_given_components_and_leaves_null_ones(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0 density 2.0
        create_particle 2 single 5 0 0 diameter 1.0 density 2.0
        group one type 1
        timestep 0.01
        fix 1 all nve/sphere
        fix 2 all gravity 2.0 vector 1 1 -1
        fix 3 one setforce NULL 0.0 0.5
        run 0
    """, ntypes=2)
    mass = sphere_mass(1.0, 2.0)
    pull = mass * 2.0 / math.sqrt(3.0)
    np.testing.assert_allclose(by_tag(sim, sim.f), [[pull, 0.0, 0.5], [pull, pull, -pull]], rtol=1e-15)
    x0 = by_tag(sim, sim.x)
    sim.command("run 100")
    np.testing.assert_allclose(by_tag(sim, sim.x)[0] - x0[0], [pull / mass / 2, 0.0, 0.5 / mass / 2],
                               rtol=1e-12)


# ---- gravity ------------------------------------------------------------------------------------
@pytest.mark.parametrize("words, dimension, direction", [
    ("2.0 vector 3 0 4", 3, [0.6, 0.0, 0.8]),
    ("2.0 vector 0 0 -7", 3, [0.0, 0.0, -1.0]),
    ("2.0 chute 30", 3, [0.5, 0.0, -math.sqrt(3) / 2]),
    ("2.0 spherical 90 90", 3, [0.0, 1.0, 0.0]),
    ("2.0 spherical 0 180", 3, [0.0, 0.0, -1.0]),
    ("2.0 vector 1 1 5", 2, [math.sqrt(0.5), math.sqrt(0.5), 0.0]),
    ("2.0 chute 30", 2, [0.5, -math.sqrt(3) / 2, 0.0]),
    ("-2.0 spherical 0 0", 2, [0.0, -1.0, 0.0]),
])
def test_gravity_is_mass_times_g_along_the_normalised_direction(spheres, words, dimension, direction):
    sim = spheres(f"""
        create_particle 1 single 0 0 0 diameter 1.0 density 3.0
        fix 1 all gravity {words}
        run 0
    """, dimension=dimension)
    mass = sim.particles.rmass[0]
    np.testing.assert_allclose(sim.f[0], mass * 2.0 * np.array(direction), rtol=1e-12, atol=1e-15)


def test_a_disabled_gravity_pulls_nothing_and_keeps_its_acceleration(spheres):
    """LAMMPS's disable: the fix only holds g for the styles that read it (fix rigid/small's gravity
    keyword, fix pour's schedule)."""
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0 density 3.0
        fix 1 all gravity 2.0 vector 0 0 -1 disable
        run 0
    """)
    assert sim.f[0].tolist() == [0.0, 0.0, 0.0]
    assert sim.fixes["1"].extract("gvec") == (0.0, 0.0, -2.0)


# ---- errors -------------------------------------------------------------------------------------
@pytest.mark.parametrize("fix, message", [
    ("viscous", "missing argument gamma; usage: fix ID GROUP viscous GAMMA [scale TYPE RATIO]..."),
    ("viscous -1", "gamma must be >= 0 (got -1)"),
    ("acc", "missing keyword gravity; usage: fix ID GROUP acc gravity DIM VALUE [region RID]"),
    ("acc gravity w 1", "gravity must be one of 'x', 'y' or 'z' (got w)"),
    ("acc gravity z 1 region nowhere", "region nowhere is not defined (defined: box)"),
    ("addforce", "nothing to add: give FX FY FZ, drag_stokes MU or buoyancy DIM RHO G"),
    ("addforce 1 2", "a constant force needs three components FX FY FZ (got 1 2)"),
    ("addforce buoyancy z", "buoyancy z takes number number or number (got nothing)"),
    ("addforce buoyancy z 1 2 3", "unknown keyword 3 (known: drag_stokes, buoyancy, region, energy)"),
    ("addforce drag_stokes -1", "drag_stokes must be >= 0 (got -1)"),
    ("setforce 1 abc 0", "fy: must be a finite number or NULL (got abc)"),
    ("setforce 1 2", "missing argument fz; usage: fix ID GROUP setforce FX FY FZ [region RID]"),
    ("gravity 1 vector 0 0 0", "gravity vector 0 0 0 has no direction"),
    ("gravity 1 vector 1 2", "direction vector takes 3 value(s): number number number (got 1 2)"),
    ("gravity 1 chute", "direction chute takes 1 value(s): number (got nothing)"),
    ("gravity 1 sideways 1", "direction must be one of vector, chute, spherical (got sideways)"),
])
def test_bad_arguments_are_one_line_errors(spheres, fix, message):
    sim = spheres("create_particle 1 single 0 0 0")
    with pytest.raises(ScriptError) as error:
        sim.command(f"fix 1 all {fix}")
    assert error.value.message == message
    assert "\n" not in str(error.value)


@pytest.mark.parametrize("fix, message", [
    ("acc gravity z 1", "fix acc gravity along z in a 2-d simulation would move particles out of the plane"),
    ("addforce buoyancy z 1 1", "fix addforce buoyancy along z in a 2-d simulation would move particles "
     "out of the plane"),
    ("gravity 1 vector 0 0 1", "gravity vector 0 0 1 has no direction in the xy plane (z is ignored in 2-d)"),
])
def test_out_of_plane_forces_in_2d_are_refused(spheres, fix, message):
    sim = spheres("create_particle 1 single 0 0 0", dimension=2)
    with pytest.raises(ScriptError) as error:
        sim.command(f"fix 1 all {fix}")
    assert error.value.message == message


@pytest.mark.parametrize("fix", ["addforce drag_stokes 1", "addforce buoyancy z 1 1"])
def test_drag_and_buoyancy_need_radii(make_plain, fix):
    with pytest.raises(ScriptError) as error:
        make_plain().command(f"fix 1 all {fix}")
    assert error.value.message.endswith("needs finite-size particles (per-particle radius and mass): "
                                        "use particle_style sphere before creating the box")


# LAMMPS 22 Jul 2025 on this machine (2026-12-02): the scene below, write_dump id f_s[1] f_s[2] f_s[3]
# fx fy fz (%.17g)
STORE_FORCE_SCENE = """
units lj
atom_style atomic
atom_modify map array
region b block 0 5 0 5 0 5
create_box 1 b
create_atoms 1 single 1 1 1
create_atoms 1 single 2.2 1 1
create_atoms 1 single 3 3 3
mass * 1.0
group two id 1 2
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
fix n all nve
fix before all addforce 0.5 0 0
fix s two store/force
fix after all addforce 0 0.25 0
run 0
"""
LAMMPS_STORE_FORCE = [[2.7116933422230796, 0, 0, 2.7116933422230796, 0.25, 0],
                      [-1.7116933422230796, 0, 0, -1.7116933422230796, 0.25, 0],
                      [0, 0, 0, 0.5, 0.25, 0]]


def test_store_force_keeps_the_force_of_its_turn_as_lammps(make_sim):
    """The pair's and the earlier addforce's, not the later one's; 0 outside the group."""
    sim = make_sim(dialect="lammps")
    sim.command(STORE_FORCE_SCENE)
    order = np.argsort(sim.tag)
    got = np.column_stack([sim.fixes["s"].peratom(sim), sim.f])[order]
    np.testing.assert_allclose(got, LAMMPS_STORE_FORCE, rtol=1e-15, atol=0)
