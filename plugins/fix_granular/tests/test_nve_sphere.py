"""fix nve/sphere: exact free fall and exact spin-up under constant force and torque (velocity Verlet
is exact for constant forces), sphere and disc inertia, groups, one-line errors."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import by_tag


def test_free_fall_follows_the_parabola_exactly(spheres):
    g = 9.81
    sim = spheres("""
        create_particle 1 single 0 0 10 diameter 1.0 density 2.0
        create_particle 1 single 5 5 12 diameter 0.4 density 7.0
        timestep 0.01
        fix 1 all nve/sphere
        fix 2 all gravity 9.81 vector 0 0 -1
    """)
    v0 = np.array([[0.3, -0.2, 1.5], [-1.0, 0.0, 0.0]])
    sim.v[np.argsort(sim.tag)] = v0
    x0 = by_tag(sim, sim.x)
    for k in range(1, 4):
        sim.command("run 50")
        t = 0.5 * k
        expected = x0 + v0 * t - 0.5 * g * t * t * np.array([0.0, 0.0, 1.0])
        np.testing.assert_allclose(by_tag(sim, sim.x), expected, rtol=0, atol=1e-12)
        np.testing.assert_allclose(by_tag(sim, sim.v), v0 - g * t * np.array([0.0, 0.0, 1.0]),
                                   rtol=0, atol=1e-12)


def test_constant_torque_spins_a_sphere_as_torque_time_over_inertia(spheres):
    torque = np.array([0.2, -0.1, 0.7])
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0 density 2.0
        create_particle 1 single 3 0 0 diameter 0.5 density 1.0
        timestep 0.005
        fix 1 all nve/sphere
        fix 2 all test/granular/torque 0.2 -0.1 0.7
    """)
    x0 = by_tag(sim, sim.x)
    radius = np.array([0.5, 0.25])
    mass = np.array([2.0, 1.0]) * 4.0 / 3.0 * math.pi * radius ** 3
    inertia = 0.4 * mass * radius ** 2
    for k in range(1, 3):
        sim.command("run 80")
        t = 0.4 * k
        omega = by_tag(sim, sim.particles.omega[: sim.nlocal])
        np.testing.assert_allclose(omega, torque * t / inertia[:, None], rtol=1e-12)
    # a torque turns the spheres but does not move them
    np.testing.assert_array_equal(by_tag(sim, sim.x), x0)


def test_disc_keyword_uses_half_m_r_squared_in_2d(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 2.0 density 3.0
        timestep 0.01
        fix 1 all nve/sphere disc
        fix 2 all test/granular/torque 0 0 0.7
        run 100
    """, dimension=2)
    mass = 3.0 * math.pi * 1.0 ** 2          # 2-d particles: mass = density * area
    assert sim.particles.rmass[0] == pytest.approx(mass, rel=1e-15)
    np.testing.assert_allclose(sim.particles.omega[0], [0.0, 0.0, 0.7 * 1.0 / (0.5 * mass)], rtol=1e-12)


def test_only_the_group_is_integrated(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0
        create_particle 2 single 5 0 0 diameter 1.0
        group mobile type 1
        timestep 0.01
        fix 1 mobile nve/sphere
        fix 2 all gravity 2.0 vector 0 0 -1
        fix 3 all test/granular/torque 0 0 1
        run 100
    """, ntypes=2)
    x, omega = by_tag(sim, sim.x), by_tag(sim, sim.particles.omega[: sim.nlocal])
    np.testing.assert_allclose(x[0], [0.0, 0.0, -1.0], rtol=0, atol=1e-12)
    assert omega[0, 2] > 0
    np.testing.assert_array_equal(x[1], [5.0, 0.0, 0.0])
    np.testing.assert_array_equal(omega[1], [0.0, 0.0, 0.0])


@pytest.mark.parametrize("fix, message", [
    ("nve/sphere sphere", "inertia must be one of 'disc' (got sphere)"),
    ("nve/sphere update dipole",
     "update dipole needs each particle's dipole moment (atom attribute mu), which pdps's atom styles do not "
     "keep (nor LIGGGHTS 3.8.0's)"),
    ("nve/sphere update spin", "update must be one of 'dipole' or 'dipole/dlm' (got spin)"),
    ("nve/sphere disc", "fix nve/sphere disc needs a 2-d simulation (dimension 2)"),
])
def test_bad_arguments_are_one_line_errors(spheres, fix, message):
    sim = spheres("create_particle 1 single 0 0 0")
    with pytest.raises(ScriptError) as error:
        sim.command(f"fix 1 all {fix}")
    assert error.value.message == message
    assert str(error.value) == f"<command>:1: fix: {message}"


def test_point_particles_are_refused(make_plain):
    sim = make_plain()
    with pytest.raises(ScriptError) as error:
        sim.command("fix 1 all nve/sphere")
    assert error.value.message == ("fix nve/sphere needs finite-size particles (per-particle radius "
                                   "and mass): use particle_style sphere before creating the box")


def test_a_particle_without_radius_stops_the_run(spheres):
    sim = spheres("create_particle 1 single 0 0 0\nfix 1 all nve/sphere")
    sim.particles.radius[0] = 0.0
    with pytest.raises(ScriptError) as error:
        sim.command("run 1")
    assert error.value.message == "fix nve/sphere needs finite-size particles: particle 1 has radius 0"
