"""fix nve/limit: a huge overlap separates at exactly XMAX per step without NaN, spins left alone
(as LAMMPS and LIGGGHTS), radius_ratio, identical to nve when the cap never acts, point particles,
the cap's warning and report, one-line errors."""

import math

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import by_tag


def test_hugely_overlapping_spheres_separate_at_xmax_per_step(spheres):
    xmax, dt, stiffness = 0.01, 0.001, 1e9
    sim = spheres(f"""
        create_particle 1 single -0.025 0 0 diameter 1.0 density 1.0
        create_particle 1 single 0.025 0 0 diameter 1.0 density 1.0
        timestep {dt}
        fix 1 all nve/limit {xmax}
        fix 2 all test/granular/overlap {stiffness}
        fix 3 all test/record
    """)
    mass = math.pi / 6.0
    # without the cap the first step alone would throw each sphere ~900 diameters
    assert 0.5 * stiffness * 0.95 / mass * dt * dt > 1e4 * xmax
    x0 = by_tag(sim, sim.x)
    sim.command("run 80")
    path = np.concatenate([x0[None], np.array(sim.fixes["3"].x)])
    assert np.isfinite(path).all() and np.isfinite(sim.v).all()
    step = np.linalg.norm(np.diff(path, axis=0), axis=2)
    assert step.max() <= xmax * (1 + 1e-12)
    np.testing.assert_allclose(step, xmax, rtol=1e-12)     # capped while overlapping, then at speed
    gap = path[:, 1, 0] - path[:, 0, 0]
    # each moves xmax per step: the centres are 0.05 + 0.02 n apart, touching no more after step 48
    assert gap[47] < 1.0 < gap[48]
    assert gap[-1] == pytest.approx(0.05 + 0.02 * 80, rel=1e-12)
    # both velocities capped after each half-kick of steps 1-47, after the first one of step 48
    assert sim.fixes["1"].count == 4 * 47 + 2
    assert sim.warnings == ["fix 1 (nve/limit): the displacement limit 0.01 acted on 4 update(s) at "
                            "step 1; energy is not conserved while it acts"]
    assert ("fix 1 (nve/limit): the displacement limit 0.01 acted 190 time(s) on steps 1 to 48"
            in sim.output.screen.getvalue())


def test_spins_are_left_alone(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0
        timestep 0.001
        fix 1 all nve/limit 0.01
        fix 2 all test/granular/torque 0 1e9 0
        run 5
    """)
    np.testing.assert_array_equal(sim.particles.omega[0], [0.0, 0.0, 0.0])
    np.testing.assert_array_equal(sim.x[0], [0.0, 0.0, 0.0])
    assert sim.fixes["1"].count == 0


def test_radius_ratio_caps_each_particle_at_a_multiple_of_its_radius(spheres):
    sim = spheres("""
        create_particle 1 single 0 0 0 diameter 1.0
        create_particle 1 single 0 5 0 diameter 0.2
        timestep 0.001
        fix 1 all nve/limit radius_ratio 0.1
        fix 2 all test/force 1e9 0 0
    """)
    x0 = by_tag(sim, sim.x)
    sim.command("run 10")
    moved = by_tag(sim, sim.x) - x0
    np.testing.assert_allclose(moved[:, 0], 10 * 0.1 * np.array([0.5, 0.1]), rtol=1e-12)
    np.testing.assert_array_equal(moved[:, 1:], 0.0)


def _spinning_fall(spheres, integrator):
    sim = spheres(f"""
        create_particle 1 single 0 0 10 diameter 1.0 density 2.0
        create_particle 1 single 4 0 10 diameter 0.6 density 3.0
        timestep 0.01
        fix 1 all {integrator}
        fix 2 all gravity 9.81 vector 0 0 -1
        fix 3 all test/granular/torque 0.1 0 0.3
    """)
    sim.v[:] = [0.5, 0.0, 1.0]
    sim.command("run 100")
    return sim


def test_without_caps_it_is_nve_to_the_last_bit(spheres):
    limited = _spinning_fall(spheres, "nve/limit 1.0")
    plain = _spinning_fall(spheres, "nve")
    assert limited.fixes["1"].count == 0 and limited.warnings == []
    np.testing.assert_array_equal(limited.x, plain.x)
    np.testing.assert_array_equal(limited.v, plain.v)
    np.testing.assert_array_equal(limited.particles.omega, plain.particles.omega)


def test_point_particles_are_capped_without_rotation(make_plain):
    sim = make_plain()
    sim.command("fix 1 all nve/limit 0.02\nfix 2 all test/force 0 -1e8 0")
    x0 = by_tag(sim, sim.x)
    sim.command("run 20")
    np.testing.assert_allclose(by_tag(sim, sim.x) - x0, [[0.0, -0.4, 0.0]] * 2, rtol=1e-12, atol=1e-15)
    assert not sim.particles.has("omega")


@pytest.mark.parametrize("args, message", [
    ("", "missing argument xmax; usage: fix ID GROUP nve/limit [absolute|radius_ratio] XMAX"),
    ("-1", "xmax must be > 0 (got -1)"),
    ("radius_ratio abc", "xmax must be a finite number (got abc)"),
])
def test_bad_arguments_are_one_line_errors(spheres, args, message):
    sim = spheres("create_particle 1 single 0 0 0")
    with pytest.raises(ScriptError) as error:
        sim.command(f"fix 1 all nve/limit {args}")
    assert error.value.message == message


def test_radius_ratio_needs_spheres(make_plain):
    with pytest.raises(ScriptError) as error:
        make_plain().command("fix 1 all nve/limit radius_ratio 0.1")
    assert error.value.message.startswith("fix nve/limit radius_ratio needs finite-size particles")
