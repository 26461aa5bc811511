"""erotate/sphere, ke/atom and vacf against their formulas."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import build


def test_erotate_sphere_is_half_i_omega_squared():
    sim = Simulation(screen=False, log=None)
    sim.command("particle_style sphere\nregion box block 0 5 0 5 0 5\ncreate_box 1 box\n"
                "create_particle 1 single 1 1 1\ncreate_particle 1 single 3 3 3\ngroup one id 2\n"
                "compute r all erotate/sphere\ncompute r1 one erotate/sphere")
    p = sim.particles
    p.omega[:2] = [[1.0, -2.0, 0.5], [0.3, 0.0, 4.0]]
    p.radius[:2] = [0.5, 0.7]
    p.rmass[:2] = [1.2, 2.5]
    inertia = 0.4 * p.rmass[:2] * p.radius[:2] ** 2
    each = 0.5 * inertia * np.sum(p.omega[:2] ** 2, axis=1)
    second = int(np.flatnonzero(p.tag[:2] == 2)[0])
    assert sim.computes["r"].scalar(sim) == pytest.approx(each.sum(), rel=1e-14)
    assert sim.computes["r1"].scalar(sim) == pytest.approx(each[second], rel=1e-14)


def test_erotate_sphere_needs_spheres(tmp_path):
    with pytest.raises(ScriptError, match="compute erotate/sphere needs particle_style sphere"):
        build(tmp_path, [[1.0, 1.0, 1.0]], setup="compute r all erotate/sphere")


def test_vacf_starts_at_the_mean_square_velocity_and_follows_the_velocities(tmp_path):
    v = np.array([[1.0, 2.0, -1.0], [0.5, -0.5, 3.0], [-2.0, 1.0, 0.0]])
    sim = build(tmp_path, [[1.0, 1.0, 1.0], [4.0, 4.0, 4.0], [7.0, 7.0, 7.0]], v=v, masses={1: 2.0},
                setup="group two id 1 2\ncompute c all vacf\ncompute c2 two vacf\ncompute k all ke/atom")
    np.testing.assert_allclose(sim.computes["c"].vector(sim), [*(v * v).mean(axis=0), (v * v).sum() / 3], rtol=1e-14)
    sim.particles.v[: sim.nlocal] *= 2.0
    expected = 2.0 * np.array([*(v[:2] * v[:2]).mean(axis=0), (v[:2] * v[:2]).sum() / 2])
    np.testing.assert_allclose(sim.computes["c2"].vector(sim), expected, rtol=1e-12)
    ke = sim.computes["k"].peratom(sim)
    np.testing.assert_allclose(np.sort(ke), np.sort(0.5 * 2.0 * np.sum((2 * v) ** 2, axis=1)), rtol=1e-12)


def test_pe_keywords_split_pair_and_fix_energies(tmp_path):
    """A wall fix with fix_modify energy yes: compute pe is pair + wall, pe pair the pair's, pe fix the
    wall's, and the LAMMPS terms pdps does not have add 0."""
    x = [[0.3, 5.0, 5.0], [1.4, 5.0, 5.0], [5.0, 5.0, 5.0]]
    sim = build(tmp_path, x, boundary="f f f",
                setup="pair_style lj/cut 2.5\npair_coeff * * 1 1\n"
                      "fix w all wall/harmonic xlo EDGE 50.0 1.0 1.0 units box\nfix_modify w energy yes\n"
                      "compute all all pe\ncompute pair all pe pair\ncompute fix all pe fix\n"
                      "compute none all pe bond angle dihedral improper kspace\nrun 0")
    wall = 50.0 * 0.7 ** 2
    pair = 4.0 * (1.1 ** -12 - 1.1 ** -6)
    value = {name: sim.computes[name].scalar(sim) for name in ("all", "pair", "fix", "none")}
    assert value["fix"] == pytest.approx(wall, rel=1e-14)
    assert value["pair"] == pytest.approx(pair, rel=1e-13)
    assert value["all"] == pytest.approx(wall + pair, rel=1e-14)
    assert value["none"] == 0.0
