"""Physics of fix nve (velocity Verlet): exact ballistic and constant-force motion, group masks,
per-type and per-particle masses, and energy conservation with second-order drift."""

import math

import numpy as np
import pytest

from pdps_core.api import Fix, observables
from pdps_core.testing import ConstantForce, by_tag, make_box, register_styles, unwrapped


class EnergyRecord(Fix):
    """Test fix: total energy KE + PE after every step (PE is current on thermo steps)."""
    name = "test_nve_energy_record"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.energy = []

    def end_of_step(self, sim):
        self.energy.append(observables.kinetic_energy(sim) + observables.potential_energy(sim))


register_styles(ConstantForce, EnergyRecord)


def make(setup, boundary="p p p", box="0 10 0 10 0 10", ntypes=1):
    return make_box(setup, box=box, boundary=boundary, ntypes=ntypes)


def _ballistic(start, velocity, steps, dt=0.01):
    sim = make(f"""
        mass 1 1.0
        create_particle 1 single {start[0][0]} {start[0][1]} {start[0][2]}
        create_particle 1 single {start[1][0]} {start[1][1]} {start[1][2]}
        timestep {dt}
        fix 1 all nve
    """)
    v0 = np.array(velocity, dtype=float)
    x0 = by_tag(sim, sim.x)
    sim.v[np.argsort(sim.tag)] = v0
    sim.command(f"run {steps}")
    np.testing.assert_allclose(by_tag(sim, sim.v), v0, rtol=0, atol=0)
    return sim, x0 + v0 * steps * dt


def test_free_particles_move_ballistically_through_periodic_faces():
    sim, expected = _ballistic([[1.0, 2.0, 3.0], [9.5, 0.55, 5.0]],
                               [[1.5, -0.75, 0.25], [3.0, -2.0, 0.0]], 400)
    np.testing.assert_allclose(unwrapped(sim), expected, rtol=1e-12, atol=1e-12)
    # both particles crossed faces and were wrapped back into the box
    assert np.all(sim.x >= sim.box.lo) and np.all(sim.x < sim.box.hi)
    assert np.abs(sim.particles.image[:2]).sum() > 0


def test_particle_landing_just_below_the_low_face_keeps_its_unwrapped_position():
    # y = 0.5 - 25 * 0.02 lands a round-off below 0: wrapped y + 10 rounds to exactly 10 = hi
    sim, expected = _ballistic([[1.0, 2.0, 3.0], [9.5, 0.5, 5.0]],
                               [[1.5, -0.75, 0.25], [3.0, -2.0, 0.0]], 400)
    np.testing.assert_allclose(unwrapped(sim), expected, rtol=1e-12, atol=1e-12)


@pytest.mark.parametrize("mass, force, dt, steps", [(1.0, (0.5, -1.0, 2.0), 0.01, 100),
                                                     (2.5, (3.0, 0.0, -0.7), 0.037, 37)])
def test_constant_force_gives_exact_parabola(mass, force, dt, steps):
    """Velocity Verlet is exact for a constant force: x = x0 + v0 t + F t^2 / 2m, v = v0 + F t / m."""
    sim = make(f"""
        mass 1 {mass}
        create_particle 1 single 5.0 5.0 5.0
        timestep {dt}
        fix 1 all nve
        fix 2 all {ConstantForce.name} {force[0]} {force[1]} {force[2]}
    """, boundary="f f f", box="-100 100 -100 100 -100 100")
    v0 = np.array([0.3, 0.2, -0.4])
    sim.v[:] = v0
    x0 = sim.x[0].copy()
    for k in range(1, 4):
        sim.command(f"run {steps}")
        t = k * steps * dt
        a = np.array(force) / mass
        np.testing.assert_allclose(sim.x[0], x0 + v0 * t + 0.5 * a * t * t, rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(sim.v[0], v0 + a * t, rtol=1e-12, atol=1e-12)


def test_per_particle_mass_is_used_when_present():
    """particle_style sphere: a = F / rmass with rmass = density * 4/3 pi r^3, not the type mass."""
    sim = make_box(f"""
        create_particle 1 single 0 0 0 diameter 2.0 density 3.0
        create_particle 1 single 10 0 0 diameter 1.0 density 1.0
        timestep 0.01
        fix 1 all nve
        fix 2 all {ConstantForce.name} 1.0 0.0 0.0
        run 100
    """, box="-50 50 -50 50 -50 50", boundary="f f f", particle_style="sphere")
    rmass = np.array([3.0 * 4.0 / 3.0 * math.pi, 4.0 / 3.0 * math.pi / 8.0])
    np.testing.assert_allclose(by_tag(sim, sim.v)[:, 0], 1.0 / rmass, rtol=1e-12)
    np.testing.assert_allclose(unwrapped(sim)[:, 0], [0.0, 10.0] + 0.5 / rmass, rtol=1e-12)


def test_only_the_fix_group_moves():
    sim = make("""
        mass * 1.0
        create_particle 1 single 2 2 2
        create_particle 2 single 5 5 5
        create_particle 1 single 8 8 8
        group mobile type 1
        timestep 0.01
        fix 1 mobile nve
    """, ntypes=2)
    sim.command(f"fix 2 all {ConstantForce.name} 1.0 2.0 3.0")
    sim.v[np.argsort(sim.tag)] = [[1.0, 0.0, 0.0], [0.5, 0.5, 0.5], [0.0, -1.0, 0.0]]
    x0, v0 = by_tag(sim, sim.x), by_tag(sim, sim.v)
    sim.command("run 50")
    frozen = by_tag(sim, sim.type) == 2
    # the type-2 particle feels the force and has a velocity, but is not integrated
    np.testing.assert_array_equal(by_tag(sim, sim.x)[frozen], x0[frozen])
    np.testing.assert_array_equal(by_tag(sim, sim.v)[frozen], v0[frozen])
    t = 0.5
    expected = x0[~frozen] + v0[~frozen] * t + 0.5 * np.array([1.0, 2.0, 3.0]) * t * t
    np.testing.assert_allclose(unwrapped(sim)[~frozen], expected, rtol=1e-12)


def test_no_fix_no_motion():
    sim = make("mass 1 1\ncreate_particle 1 single 2 2 2")
    sim.v[:] = [1.0, 1.0, 1.0]
    sim.command("run 10")
    np.testing.assert_array_equal(sim.x, [[2.0, 2.0, 2.0]])


def _energy_error(dt, total_time=1.0):
    """max |E(t) - E(0)| / |E(0)| of a purely conservative DPD system (T=0, gamma=0) over a fixed
    physical time."""
    rng = np.random.default_rng(1)
    sim = make_box("""
        lattice spacing x 0.6 y 0.6 z 0.6
        mass 1 1.0
        create_particle 1 box
        pair_style dpd 0.0 1.0 1
        pair_coeff 1 1 25.0 0.0
    """, box="0 3 0 3 0 3")
    sim.x[:] += rng.uniform(-0.15, 0.15, size=sim.x.shape)
    sim.v[:] = rng.normal(scale=1.0, size=sim.v.shape)
    steps = int(round(total_time / dt))
    sim.command(f"timestep {dt!r}\nthermo 1\nthermo_style custom step pe\nrun 0")
    e0 = observables.kinetic_energy(sim) + observables.potential_energy(sim)
    sim.command(f"fix 1 all nve\nfix 2 all {EnergyRecord.name}\nrun {steps}")
    energy = np.array(sim.fixes["2"].energy)
    assert len(energy) == steps
    return np.abs(energy - e0).max() / abs(e0), sim


def test_energy_is_conserved_with_second_order_error():
    coarse, sim = _energy_error(0.01)
    fine, _ = _energy_error(0.005)
    assert sim.nlocal == 125
    assert coarse < 5e-4
    # global error of velocity Verlet is O(dt^2): halving dt divides the error by ~4
    assert 2.5 < coarse / fine < 6.0
