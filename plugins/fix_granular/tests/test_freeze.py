"""fix freeze: frozen spheres at rest stay exactly in place under force and torque, the rest move; the
force the group carried is reported; a frozen sphere that moves goes on at its velocity (as LAMMPS's
and LIGGGHTS's, which zero forces only), with a warning; a force fix defined after freeze is warned
about."""

import math

import numpy as np

from pdps_core.testing import by_tag


def test_frozen_spheres_stay_put_under_gravity_and_torque(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0 density 2.0
        create_particle 2 single 3 0 0 diameter 1.0 density 2.0
        group floor type 1
        timestep 0.01
        fix 1 all nve/sphere
        fix 2 all gravity 9.81 vector 0 0 -1
        fix 3 all test/granular/torque 0 0 1
        fix 4 floor freeze
    """, ntypes=2)
    moving = sim.particles.type[: sim.nlocal] == 2
    sim.v[moving] = [1.0, 1.0, 1.0]
    sim.particles.omega[: sim.nlocal][moving] = [0.0, 0.0, 2.0]
    x0 = by_tag(sim, sim.x)
    sim.command("run 100")
    x, v, omega = by_tag(sim, sim.x), by_tag(sim, sim.v), by_tag(sim, sim.particles.omega[:2])
    np.testing.assert_array_equal(x[0], x0[0])
    np.testing.assert_array_equal(v[0], 0.0)
    np.testing.assert_array_equal(omega[0], 0.0)
    # the free sphere flies and spins on
    t, mass = 1.0, 2.0 * math.pi / 6.0
    np.testing.assert_allclose(x[1], x0[1] + [t, t, t - 0.5 * 9.81 * t * t], rtol=0, atol=1e-12)
    np.testing.assert_allclose(omega[1], [0.0, 0.0, 2.0 + t / (0.4 * mass * 0.25)], rtol=1e-12)
    # the load the frozen sphere carried before it was zeroed
    np.testing.assert_allclose(sim.fixes["4"].total_force, [0.0, 0.0, -9.81 * mass], rtol=1e-12)
    assert sim.warnings == []


def test_a_frozen_sphere_that_moves_goes_on_at_its_velocity(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0 density 2.0
        group floor type 1
        timestep 0.01
        fix 1 all nve/sphere
        fix 2 all gravity 9.81 vector 0 0 -1
        fix 3 floor freeze
    """)
    sim.v[:] = [1.0, 0.0, -2.0]
    sim.particles.omega[: sim.nlocal] = [0.0, 3.0, 0.0]
    sim.command("run 100")
    np.testing.assert_allclose(sim.x[0], [1.0, 0.0, -2.0], rtol=1e-12)
    np.testing.assert_array_equal(sim.particles.omega[0], [0.0, 3.0, 0.0])
    assert sim.warnings == ["fix 3 (freeze) zeroes forces and torques only, as LAMMPS and LIGGGHTS: "
                            "particles of group floor that move or spin go on doing so (velocity floor "
                            "set 0 0 0 holds them in place)"]


def test_a_force_fix_defined_after_freeze_is_warned_about(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0
        create_particle 2 single 3 0 0 diameter 1.0
        group floor type 1
        group top type 2
        timestep 0.01
        fix 1 all nve/sphere
        fix 2 floor freeze
        fix 3 top gravity 1.0 vector 0 0 -1
        fix 4 all gravity 1.0 vector 0 0 -1
        run 10
        run 10
    """, ntypes=2)
    # fix 3 acts on other particles; fix 4 undoes the freeze (as in LAMMPS), said once; by the
    # second run the frozen sphere falls
    assert sim.warnings == ["fix 4 (gravity) is defined after fix 2 (freeze) and changes forces on its "
                            "particles after they were zeroed: frozen particles may move (define "
                            "freeze last)",
                            "fix 2 (freeze) zeroes forces and torques only, as LAMMPS and LIGGGHTS: "
                            "particles of group floor that move or spin go on doing so (velocity floor "
                            "set 0 0 0 holds them in place)"]
    assert by_tag(sim, sim.x)[0, 2] < 0.0
