"""Physics of pair style dpd, checked against the formula of Groot & Warren (1997):

    F_ij = (a w - gamma w^2 (r_hat . v_ij) + sigma w xi / sqrt(dt)) r_hat,
    w = 1 - r/rc,  sigma^2 = 2 kT gamma,  E = 1/2 a rc w^2,

with xi = pair_gaussian(seed, step, tag_i, tag_j) from the counter-based Philox generator.
Every expected value here is computed independently in the test (numpy, O(N^2) over periodic images).
"""

import itertools
import math

import numpy as np
import pytest

from pdps_core import testing
from pdps_core.api import Fix, ScriptError, observables, pair_gaussian, pair_uniform, philox4x32
from pdps_core.testing import by_tag, energy_gradient, forces_by_tag, make_box, register_styles

SEED = 4872155
DT = 0.04


# ---- helpers ------------------------------------------------------------------------------------
def build(tmp_path, x, *, v=None, types=None, tags=None, lo=(0.0, 0.0, 0.0), hi=(10.0, 10.0, 10.0),
          boundary="f f f", T=1.0, rc=1.0, coeffs=("* * 25.0 0.0",), dt=DT, units="lj",
          name="data.dpd", skin=None, masses=None, noise=""):
    """A Simulation holding the given particles with pair style dpd; nothing run yet."""
    setup = [] if skin is None else [f"neighbor {skin}"]
    setup += [f"timestep {dt!r}", f"pair_style dpd {T!r} {rc!r} {SEED} {noise}"]
    setup += [f"pair_coeff {line}" for line in coeffs]
    return testing.build(tmp_path, x, setup="\n".join(setup), types=types, tags=tags, v=v,
                         masses=masses, lo=lo, hi=hi, boundary=boundary, units=units, name=name)


def reference(x, v, tags, types, coeff, *, T, seed=SEED, step=0, dt=DT, lo=None, length=None,
              periodic=(False, False, False), boltz=1.0):
    """Forces, energy and virial tensor sum_pairs r_ij F_ij^T from the DPD formula, summed over every
    periodic image within the cutoff (boxes longer than every cutoff: no self-images)."""
    n = len(x)
    forces = np.zeros((n, 3))
    energy = 0.0
    virial = np.zeros((3, 3))
    length = np.zeros(3) if length is None else np.asarray(length, float)
    images = [(-1, 0, 1) if p else (0,) for p in periodic]
    for i in range(n):
        for j in range(i + 1, n):
            a, gamma, rc = coeff[(min(types[i], types[j]), max(types[i], types[j]))]
            sigma = math.sqrt(2.0 * boltz * T * gamma)
            xi = pair_gaussian(seed, step, int(tags[i]), int(tags[j]))
            for image in itertools.product(*images):
                delta = x[i] - (x[j] + np.array(image) * length)
                r = float(np.linalg.norm(delta))
                if r >= rc or r < 1e-10:
                    continue
                w = 1.0 - r / rc
                e = delta / r
                force = (a * w - gamma * w * w * float(e @ (v[i] - v[j]))
                         + sigma * w * xi / math.sqrt(dt)) * e
                forces[i] += force
                forces[j] -= force
                energy += 0.5 * a * rc * w * w
                virial += np.outer(delta, force)
    return forces, energy, virial


def unit(vector):
    vector = np.asarray(vector, float)
    return vector / np.linalg.norm(vector)


# ---- two particles: each part of the force on its own ----------------------------------------
@pytest.mark.parametrize("r", [0.05, 0.3, 0.5, 0.77, 0.999])
@pytest.mark.parametrize("gamma, T", [(0.0, 1.0), (4.5, 0.0)])
def test_conservative_force_and_energy_two_particles(tmp_path, r, gamma, T):
    """With no noise (gamma=0 or T=0) and v=0: F = a w r_hat on i, -F on j; E = a rc w^2 / 2."""
    a, rc = 25.0, 1.0
    direction = unit([0.3, -0.5, 0.8])
    x = np.array([[5.0, 5.0, 5.0], [5.0, 5.0, 5.0] - r * direction])
    sim = build(tmp_path, x, T=T, rc=rc, coeffs=(f"1 1 {a} {gamma}",))
    sim.command("run 0")
    w = 1.0 - r / rc
    expected = a * w * direction
    np.testing.assert_allclose(forces_by_tag(sim)[0], expected, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(forces_by_tag(sim)[1], -expected, rtol=1e-12, atol=1e-12)
    assert sim.pe == pytest.approx(0.5 * a * rc * w * w, rel=1e-12)
    # virial sum_i r_i . f_i = r_ij . F_ij = a w r
    assert sum(sim.virial[:3]) == pytest.approx(a * w * r, rel=1e-10)


def test_repulsion_pushes_apart_and_attraction_pulls_together(tmp_path):
    x = [[5.0, 5.0, 5.0], [5.5, 5.0, 5.0]]
    repulsive = build(tmp_path, x, coeffs=("1 1 25.0 0.0",), name="rep")
    repulsive.command("run 0")
    assert repulsive.f[0, 0] < 0 < repulsive.f[1, 0]
    attractive = build(tmp_path, x, coeffs=("1 1 -10.0 0.0",), name="att")
    attractive.command("run 0")
    assert attractive.f[0, 0] > 0 > attractive.f[1, 0]


def test_per_pair_cutoff_sets_range_and_weight(tmp_path):
    """pair_coeff's own rc replaces the global one in w = 1 - r/rc, the energy and the range."""
    x = [[5.0, 5.0, 5.0], [6.2, 5.0, 5.0]]
    sim = build(tmp_path, x, rc=1.0, coeffs=("1 1 20.0 0.0 1.5",))
    sim.command("run 0")
    w = 1.0 - 1.2 / 1.5
    np.testing.assert_allclose(forces_by_tag(sim)[0], [-20.0 * w, 0, 0], rtol=1e-12)
    assert sim.pe == pytest.approx(0.5 * 20.0 * 1.5 * w * w, rel=1e-12)


@pytest.mark.parametrize("approach", [+1.0, -1.0])
def test_dissipative_force_with_known_velocities(tmp_path, approach):
    """a=0, T=0: F_i = -gamma w^2 (r_hat . v_ij) r_hat; it opposes the relative radial motion and
    ignores the tangential one. Energy counts the conservative part only (zero here)."""
    gamma, rc, r = 4.5, 1.0, 0.6
    e = unit([1.0, 2.0, -0.5])
    tangent = unit(np.cross(e, [0.0, 0.0, 1.0]))
    x = np.array([[5.0, 5.0, 5.0] + r * e, [5.0, 5.0, 5.0]])
    # i moves toward j (approach=+1) or away (-1) along r_hat, plus a tangential part
    v = np.array([-approach * 0.7 * e + 2.0 * tangent, 0.3 * e - 1.1 * tangent])
    sim = build(tmp_path, x, v=v, T=0.0, rc=rc, coeffs=(f"1 1 0.0 {gamma}",))
    sim.command("run 0")
    w = 1.0 - r / rc
    radial = float(e @ (v[0] - v[1]))
    expected = -gamma * w * w * radial * e
    np.testing.assert_allclose(forces_by_tag(sim)[0], expected, rtol=1e-12, atol=1e-14)
    np.testing.assert_allclose(forces_by_tag(sim)[1], -expected, rtol=1e-12, atol=1e-14)
    # friction: the force on i is along -r_hat when i approaches j (radial < 0 -> push apart)
    assert np.sign(forces_by_tag(sim)[0] @ e) == np.sign(-radial)
    assert sim.pe == 0.0


def test_tangential_velocity_alone_gives_no_force(tmp_path):
    e = unit([0.0, 1.0, 1.0])
    x = np.array([[5.0, 5.0, 5.0] + 0.4 * e, [5.0, 5.0, 5.0]])
    v = np.array([[3.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    sim = build(tmp_path, x, v=v, T=0.0, coeffs=("1 1 0.0 4.5",))
    sim.command("run 0")
    np.testing.assert_allclose(forces_by_tag(sim), 0.0, atol=1e-14)


@pytest.mark.parametrize("units, T, gamma, dt, rc, step", [
    ("lj", 1.0, 4.5, 0.04, 1.0, 0),
    ("lj", 2.5, 1.0, 0.01, 1.0, 17),
    ("si", 300.0, 2.0e-12, 1.0e-9, 1.0e-6, 3),
])
def test_random_force_is_sigma_w_xi_over_sqrt_dt(tmp_path, units, T, gamma, dt, rc, step):
    """a=0, gamma>0, v=0: F_i = sigma w xi / sqrt(dt) r_hat with sigma^2 = 2 k_B T gamma and
    xi = pair_gaussian(seed, step, tag_i, tag_j), the same for (i, j) and (j, i)."""
    boltz = {"lj": 1.0, "si": 1.3806504e-23}[units]
    r = 0.35 * rc
    e = unit([-0.2, 0.9, 0.4])
    centre = np.full(3, 5.0 * rc)
    x = np.array([centre + r * e, centre])
    lo, hi = (0.0,) * 3, (10.0 * rc,) * 3
    sim = build(tmp_path, x, T=T, rc=rc, coeffs=(f"1 1 0.0 {gamma!r}",), dt=dt, units=units,
                lo=lo, hi=hi, skin=0.3 * rc)
    sim.command(f"reset_timestep {step}\nrun 0")
    assert sim.step == step
    xi = pair_gaussian(SEED, step, 1, 2)
    assert xi == pair_gaussian(SEED, step, 2, 1)
    sigma = math.sqrt(2.0 * boltz * T * gamma)
    w = 1.0 - r / rc
    expected = sigma * w * xi / math.sqrt(dt) * e
    np.testing.assert_allclose(forces_by_tag(sim)[0], expected, rtol=1e-10)
    np.testing.assert_allclose(forces_by_tag(sim)[1], -expected, rtol=1e-10)
    assert sim.pe == 0.0


@pytest.mark.parametrize("step", [0, 5, 123])
def test_uniform_noise_is_sigma_w_xi_over_sqrt_dt_with_xi_uniform_of_unit_variance(tmp_path, step):
    """noise uniform: as above with xi = sqrt(3) (2 u - 1), u = pair_uniform(seed, step, i, j)."""
    r, T, gamma = 0.6, 1.0, 4.5
    e = unit([0.3, -0.5, 0.8])
    x = np.array([np.full(3, 5.0) + r * e, np.full(3, 5.0)])
    sim = build(tmp_path, x, T=T, coeffs=(f"1 1 0.0 {gamma!r}",), noise="noise uniform")
    sim.command(f"reset_timestep {step}\nrun 0")
    xi = math.sqrt(3.0) * (2.0 * pair_uniform(SEED, step, 1, 2) - 1.0)
    expected = math.sqrt(2.0 * T * gamma) * (1.0 - r) * xi / math.sqrt(DT) * e
    np.testing.assert_allclose(forces_by_tag(sim)[0], expected, rtol=1e-10)
    np.testing.assert_allclose(forces_by_tag(sim)[1], -expected, rtol=1e-10)


def test_random_force_does_not_depend_on_which_particle_comes_first(tmp_path):
    """The same pair stored as (tag 1, tag 2) or (tag 2, tag 1) gets the same noise."""
    x = np.array([[5.0, 5.0, 5.0], [5.3, 5.2, 4.9]])
    forward = build(tmp_path, x, T=1.0, coeffs=("1 1 0.0 4.5",), name="fwd")
    backward = build(tmp_path, x[::-1], tags=[2, 1], T=1.0, coeffs=("1 1 0.0 4.5",), name="bwd")
    for sim in (forward, backward):
        sim.command("reset_timestep 5\nrun 0")
    assert list(backward.tag) == [2, 1]
    np.testing.assert_allclose(by_tag(backward, backward.f), by_tag(forward, forward.f), rtol=1e-13)
    assert np.abs(forward.f).max() > 0.1


def test_noise_changes_from_step_to_step_and_with_the_seed(tmp_path):
    x = np.array([[5.0, 5.0, 5.0], [5.3, 5.2, 4.9]])
    seen = []
    for step in (0, 1, 2):
        sim = build(tmp_path, x, T=1.0, coeffs=("1 1 0.0 4.5",), name=f"s{step}")
        sim.command(f"reset_timestep {step}\nrun 0")
        seen.append(forces_by_tag(sim)[0])
    assert not np.allclose(seen[0], seen[1]) and not np.allclose(seen[1], seen[2])
    assert pair_gaussian(SEED, 3, 1, 2) != pair_gaussian(SEED + 1, 3, 1, 2)


def test_full_force_two_particles_all_parts_together(tmp_path):
    a, gamma, T, rc = 18.0, 3.0, 1.7, 1.2
    x = np.array([[5.0, 5.0, 5.0], [5.4, 4.7, 5.3]])
    v = np.array([[0.4, -1.0, 0.2], [-0.3, 0.5, 0.9]])
    sim = build(tmp_path, x, v=v, T=T, rc=rc, coeffs=(f"1 1 {a} {gamma}",))
    sim.command("reset_timestep 11\nrun 0")
    f, energy, virial = reference(x, v, [1, 2], [1, 1], {(1, 1): (a, gamma, rc)}, T=T, step=11)
    np.testing.assert_allclose(forces_by_tag(sim), f, rtol=1e-12, atol=1e-12)
    assert sim.pe == pytest.approx(energy, rel=1e-12)
    np.testing.assert_allclose(sim.virial[:3], np.diag(virial), rtol=1e-9, atol=1e-9)


# ---- conservative force = -grad E --------------------------------------------------------------
def test_conservative_force_is_minus_gradient_of_energy(tmp_path):
    """Central differences of the total pair energy of three particles (two types, a per-pair
    cutoff) reproduce every force component."""
    coeffs = ("1 1 25.0 0.0", "2 2 15.0 0.0", "1 2 40.0 0.0 1.3")
    x = np.array([[5.0, 5.0, 5.0], [5.55, 5.2, 4.9], [4.6, 5.7, 5.35]])
    sim = build(tmp_path, x, types=[1, 1, 2], T=1.0, rc=1.0, coeffs=coeffs)
    analytic, numeric = energy_gradient(sim, h=1e-6)
    assert np.abs(analytic).max() > 1.0
    assert numeric == pytest.approx(analytic, rel=1e-6, abs=1e-6)


# ---- Newton's third law, periodic images --------------------------------------------------------
def test_pair_across_periodic_face_matches_minimum_image(tmp_path):
    """A pair straddling the x face: the partner is a ghost; the force uses the minimum image,
    the ghost's velocity, and the reaction reaches the owner."""
    a, gamma, T, rc = 25.0, 4.5, 1.0, 1.0
    x = np.array([[0.1, 2.5, 2.5], [4.75, 2.65, 2.4]])
    v = np.array([[-0.8, 0.3, 0.1], [0.6, -0.2, 0.4]])
    sim = build(tmp_path, x, v=v, T=T, rc=rc, coeffs=(f"1 1 {a} {gamma}",), lo=(0, 0, 0),
                hi=(5, 5, 5), boundary="p p p")
    sim.command("run 0")
    assert sim.particles.nghost > 0
    f, energy, virial = reference(x, v, [1, 2], [1, 1], {(1, 1): (a, gamma, rc)}, T=T,
                                  length=[5, 5, 5], periodic=(True, True, True))
    assert np.abs(f).max() > 1.0
    np.testing.assert_allclose(forces_by_tag(sim), f, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(forces_by_tag(sim).sum(axis=0), 0.0, atol=1e-13)
    assert sim.pe == pytest.approx(energy, rel=1e-12)
    # the virial of a pair is r_ij . F_ij with the minimum-image r_ij, not the raw positions
    np.testing.assert_allclose(sim.virial[:3], np.diag(virial), rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(sim.virial[3:], [virial[0, 1], virial[0, 2], virial[1, 2]],
                               rtol=1e-9, atol=1e-12)


def test_ghost_velocities_follow_their_owners_during_a_run(tmp_path):
    """Across the periodic face, after steps without a neighbor rebuild (ghosts refreshed by
    forward communication): the dissipative force uses the current half-step velocity of the ghost."""
    gamma, rc = 4.5, 1.0
    x = np.array([[0.1, 2.5, 2.5], [4.6, 2.6, 2.4]])
    v = np.array([[-1.0, 0.3, 0.0], [1.2, -0.2, 0.4]])
    sim = build(tmp_path, x, v=v, T=0.0, rc=rc, coeffs=(f"1 1 25.0 {gamma}",), lo=(0, 0, 0),
                hi=(5, 5, 5), boundary="p p p", skin=1.0)
    sim.command("fix 1 all nve\nrun 3")
    assert sim.neighbor.builds == 1
    # forces of the last step were computed with v(t - dt/2) = v(t) - dt/(2m) f(t)
    table = {(1, 1): (25.0, gamma, rc)}
    v_half = by_tag(sim, sim.v) - 0.5 * DT * forces_by_tag(sim)
    now = by_tag(sim, sim.x)
    f, _, _ = reference(now, v_half, [1, 2], [1, 1], table, T=0.0, length=[5, 5, 5],
                        periodic=(True, True, True))
    np.testing.assert_allclose(forces_by_tag(sim), f, rtol=1e-10, atol=1e-12)
    # a ghost still carrying the velocity it had when it was made would give another force
    stale, _, _ = reference(now, np.array([v_half[0], v[1]]), [1, 2], [1, 1], table, T=0.0,
                            length=[5, 5, 5], periodic=(True, True, True))
    assert np.abs(stale - f).max() > 1e-3


def test_pair_across_a_box_corner_counts_once(tmp_path):
    x = np.array([[0.1, 0.1, 0.1], [2.8, 2.9, 2.85]])
    sim = build(tmp_path, x, T=0.0, coeffs=("1 1 25.0 0.0",), lo=(0, 0, 0), hi=(3, 3, 3),
                boundary="p p p")
    sim.command("run 0")
    f, energy, _ = reference(x, np.zeros((2, 3)), [1, 2], [1, 1], {(1, 1): (25.0, 0.0, 1.0)}, T=0.0,
                             length=[3, 3, 3], periodic=(True, True, True))
    np.testing.assert_allclose(forces_by_tag(sim), f, rtol=1e-12)
    assert sim.pe == pytest.approx(energy, rel=1e-12)


def test_small_box_two_images_of_one_partner_both_interact(tmp_path):
    """Box 1.8 long, rc 1: the partner 0.85 away has an image 0.95 away on the other side; both act."""
    x = np.array([[0.4, 0.9, 0.9], [1.25, 0.9, 0.9]])
    sim = build(tmp_path, x, T=0.0, coeffs=("1 1 25.0 0.0",), lo=(0, 0, 0), hi=(1.8, 1.8, 1.8),
                boundary="p p p")
    sim.command("run 0")
    expected_x = -25.0 * (1 - 0.85) + 25.0 * (1 - 0.95)
    np.testing.assert_allclose(forces_by_tag(sim)[0], [expected_x, 0, 0], atol=1e-12)
    assert sim.pe == pytest.approx(0.5 * 25.0 * (0.15 ** 2 + 0.05 ** 2), rel=1e-12)


def test_many_particles_match_reference_and_newtons_third_law(tmp_path):
    """30 particles, two types, periodic box, all three force parts: every force matches the pair
    sum and the total force is zero to round-off."""
    rng = np.random.default_rng(7)
    n, L = 30, 3.0
    x = rng.random((n, 3)) * L
    v = rng.normal(size=(n, 3))
    types = rng.integers(1, 3, size=n)
    types[:2] = (1, 2)
    coeff = {(1, 1): (25.0, 4.5, 1.0), (2, 2): (30.0, 3.0, 1.0), (1, 2): (40.0, 6.0, 1.2)}
    lines = [f"{i} {j} {a} {g} {rc}" for (i, j), (a, g, rc) in coeff.items()]
    sim = build(tmp_path, x, v=v, types=types, T=1.3, rc=1.0, coeffs=lines, lo=(0, 0, 0),
                hi=(L, L, L), boundary="p p p")
    sim.command("reset_timestep 42\nrun 0")
    f, energy, virial = reference(x, v, np.arange(1, n + 1), types, coeff, T=1.3, step=42,
                                  length=[L, L, L], periodic=(True, True, True))
    scale = np.abs(f).max()
    np.testing.assert_allclose(forces_by_tag(sim), f, rtol=1e-10, atol=1e-12 * scale)
    assert np.abs(forces_by_tag(sim).sum(axis=0)).max() < 1e-12 * np.abs(forces_by_tag(sim)).sum()
    assert sim.pe == pytest.approx(energy, rel=1e-12)
    np.testing.assert_allclose(sim.virial[:3], np.diag(virial), rtol=1e-9)


# ---- types and cutoffs --------------------------------------------------------------------------
def test_per_type_pair_coefficients_and_cutoffs(tmp_path):
    """Three particles, types 1 1 2. The 1-1 pair at 1.2 is beyond its cutoff (1.0); the 1-2 pairs
    use a12, gamma12 and their own rc 1.5; a per-pair rc smaller than the distance gives nothing."""
    a11, a22, a12, g12, rc12 = 25.0, 10.0, 40.0, 2.0, 1.5
    x = np.array([[5.0, 5.0, 5.0], [6.2, 5.0, 5.0], [5.6, 6.1, 5.0]])
    v = np.array([[0.5, 0.0, 0.0], [-0.5, 0.2, 0.0], [0.0, -0.4, 0.3]])
    coeffs = (f"1 1 {a11} 4.5", f"2 2 {a22} 4.5", f"2 1 {a12} {g12} {rc12}")
    sim = build(tmp_path, x, v=v, types=[1, 1, 2], T=0.0, rc=1.0, coeffs=coeffs)
    sim.command("run 0")
    table = {(1, 1): (a11, 4.5, 1.0), (2, 2): (a22, 4.5, 1.0), (1, 2): (a12, g12, rc12)}
    f, energy, _ = reference(x, v, [1, 2, 3], [1, 1, 2], table, T=0.0)
    np.testing.assert_allclose(forces_by_tag(sim), f, rtol=1e-12, atol=1e-13)
    assert sim.pe == pytest.approx(energy, rel=1e-12)
    # the 1-1 pair (1.2 apart) does not interact: forces on 1 and 2 point away from particle 3 only
    for i in (0, 1):
        assert abs(np.cross(forces_by_tag(sim)[i], x[i] - x[2])).max() < 1e-9 * np.abs(forces_by_tag(sim)[i]).max()
    # shrinking the 1-2 cutoff below both distances switches every interaction off
    sim.command("pair_coeff 1 2 40.0 2.0 0.5\nrun 0")
    np.testing.assert_allclose(forces_by_tag(sim), 0.0, atol=0)
    assert sim.pe == 0.0


def test_star_coefficients_then_override_one_pair(tmp_path):
    x = np.array([[5.0, 5.0, 5.0], [5.5, 5.0, 5.0], [5.0, 5.5, 5.0]])
    sim = build(tmp_path, x, types=[1, 2, 2], T=0.0, coeffs=("* * 25.0 0.0", "1 2 60.0 0.0"))
    sim.command("run 0")
    table = {(1, 1): (25.0, 0.0, 1.0), (2, 2): (25.0, 0.0, 1.0), (1, 2): (60.0, 0.0, 1.0)}
    f, energy, _ = reference(x, np.zeros((3, 3)), [1, 2, 3], [1, 2, 2], table, T=0.0)
    np.testing.assert_allclose(forces_by_tag(sim), f, rtol=1e-12)
    assert sim.pe == pytest.approx(energy, rel=1e-12)


@pytest.mark.parametrize("r", [1.0, 1.0 + 1e-12, 1.05, 1.29])
def test_pairs_at_or_beyond_cutoff_give_nothing(tmp_path, r):
    """Within the neighbor skin (listed) but at or beyond rc: no force of any kind, no energy."""
    e = unit([0.2, 0.3, 0.9])
    x = np.array([[5.0, 5.0, 5.0] + r * e, [5.0, 5.0, 5.0]])
    v = np.array([[-2.0, 1.0, 0.5], [1.0, 0.0, -1.0]])
    sim = build(tmp_path, x, v=v, T=2.0, rc=1.0, coeffs=("1 1 25.0 4.5",))
    sim.command("run 0")
    assert sim.pair_list.offsets[-1] == 1    # the pair is in the list: the kernel must cut it
    assert np.all(forces_by_tag(sim) == 0.0)
    assert sim.pe == 0.0


@pytest.mark.parametrize("offset", [0.0, 1e-11, 5e-11])
def test_coincident_particles_give_no_nan(tmp_path, offset):
    """r = 0 or r < 1e-10 has no direction: the pair is skipped; a third particle still acts."""
    x = np.array([[5.0, 5.0, 5.0], [5.0, 5.0, 5.0 + offset], [5.5, 5.0, 5.0]])
    v = np.array([[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    sim = build(tmp_path, x, v=v, T=1.0, coeffs=("1 1 25.0 4.5",))
    sim.command("run 0")
    assert np.isfinite(forces_by_tag(sim)).all() and math.isfinite(sim.pe)
    f, energy, _ = reference(x, v, [1, 2, 3], [1, 1, 1], {(1, 1): (25.0, 4.5, 1.0)}, T=1.0)
    np.testing.assert_allclose(forces_by_tag(sim), f, rtol=1e-10, atol=1e-10)
    assert sim.pe == pytest.approx(energy, rel=1e-12)
    sim.command("fix 1 all nve\nrun 5")
    assert np.isfinite(sim.x).all() and np.isfinite(sim.v).all()


# ---- over a run --------------------------------------------------------------------------------
class _Record(Fix):
    """Test fix: remembers total momentum and COM-free temperature after every step."""
    name = "test_dpd_record"

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.momentum, self.temperature = [], []

    def end_of_step(self, sim):
        m = observables.masses(sim)
        v = sim.v
        self.momentum.append((m[:, None] * v).sum(axis=0))
        thermal = v - (m[:, None] * v).sum(axis=0) / m.sum()
        self.temperature.append(float(m @ (thermal ** 2).sum(axis=1)) / (3 * len(m) - 3))


register_styles(_Record)


# LAMMPS 22 Jul 2025 on the scene of the test below (the same lattice, every third id of mass 2, the
# same drift, compute temp/com), 16 pairs of pair and velocity seeds: the thermal temperature averaged
# over steps 101-600 is 1.0228 over the 16 runs; one run's average scatters about that by 0.0095
# (standard deviation between seeds), so the 16-run mean carries 0.0024.
LAMMPS_MIXTURE_T_101_600 = (1.0228, 0.0095, 0.0024)


def test_momentum_is_conserved_and_thermostat_is_galilean_invariant(make_sim):
    """512 particles, 600 steps: total momentum (with a net drift) stays put to round-off; the
    thermal temperature relaxes to LAMMPS's (kT = 1 and the dt = 0.04 excess of velocity Verlet)
    whatever the drift: within three standard deviations of one run's scatter and the calibration's
    error (0.029), where a thermostat that counted the drift's kinetic energy as heat would leave
    the thermal temperature 0.13 low."""
    sim = make_sim()
    sim.command("""
        units lj
        atom_modify sort 10 0.0
        lattice spacing x 0.7 y 0.7 z 0.7
        region box block 0 5.6 0 5.6 0 5.6
        create_box 2 box
        mass 1 1.0
        mass 2 2.0
        create_particle 1 box
        pair_style dpd 1.0 1.0 99
        pair_coeff * * 25.0 4.5
        pair_coeff 1 2 30.0 3.0
        timestep 0.04
        velocity all create 0.3 5 gaussian
    """)
    assert sim.nlocal == 512
    assert np.array_equal(sim.tag, np.arange(1, 513))
    sim.type[::3] = 2                                       # ids 1, 4, 7, ... as LAMMPS's id 1:512:3
    sim.v[:] += [0.5, -0.2, 0.1]
    m = observables.masses(sim)
    p0 = (m[:, None] * sim.v).sum(axis=0)
    scale = float((m * np.linalg.norm(sim.v, axis=1)).sum())
    sim.command(f"fix 1 all nve\nfix 2 all {_Record.name}\nrun 600")
    record = sim.fixes["2"]
    drift = np.abs(np.array(record.momentum) - p0).max()
    assert drift < 1e-10 * scale
    assert np.linalg.norm(p0) > 0.1 * scale
    reference, scatter, calibration = LAMMPS_MIXTURE_T_101_600
    temperature = np.mean(record.temperature[100:])
    assert abs(temperature - reference) < 3 * math.hypot(scatter, calibration), temperature


def _shuffled_run(tmp_path, order, name, sort_every):
    rng = np.random.default_rng(3)
    n, L = 120, 3.5
    x = rng.random((n, 3)) * L
    v = rng.normal(size=(n, 3))
    types = 1 + (np.arange(n) % 2)
    sim = testing.build(tmp_path, x[order], types=types[order], tags=order + 1, v=v[order],
                        hi=(L, L, L), name=name, setup=f"""
        atom_modify sort {sort_every} 0.0
        pair_style dpd 1.0 1.0 2024
        pair_coeff * * 25.0 4.5
        pair_coeff 1 2 35.0 4.5 1.1
        timestep 0.02
        fix 1 all nve
        run 8
    """)
    return sim


def test_trajectory_does_not_depend_on_particle_order(tmp_path):
    """The same system read with its Atoms lines shuffled (same ids), and re-sorted in memory at
    every neighbor rebuild, follows the same trajectory: the noise is keyed by (seed, step, tags),
    not by storage order."""
    n = 120
    first = _shuffled_run(tmp_path, np.arange(n), "ordered", sort_every=0)
    second = _shuffled_run(tmp_path, np.random.default_rng(11).permutation(n), "shuffled",
                           sort_every=1)
    assert not np.array_equal(first.tag, second.tag)
    for attribute in ("x", "v"):
        a = by_tag(first, getattr(first, attribute))
        b = by_tag(second, getattr(second, attribute))
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-10)
    # and the particles did move under the DPD forces
    assert np.abs(by_tag(first, first.v)).max() > 0


# ---- the generator ------------------------------------------------------------------------------
@pytest.mark.parametrize("counter, key, expected", [
    ((0, 0, 0, 0), (0, 0), (0x6627E8D5, 0xE169C58D, 0xBC57AC4C, 0x9B00DBD8)),
    ((0xFFFFFFFF,) * 4, (0xFFFFFFFF,) * 2, (0x408F276D, 0x41C83B0E, 0xA20BC7C6, 0x6D5451FD)),
    ((0x243F6A88, 0x85A308D3, 0x13198A2E, 0x03707344), (0xA4093822, 0x299F31D0),
     (0xD16CFE09, 0x94FDCCEB, 0x5001E420, 0x24126EA1)),
])
def test_philox4x32_10_known_answers(counter, key, expected):
    """Random123's kat_vectors for philox4x32 with 10 rounds."""
    result = philox4x32(*(np.uint64(c) for c in counter), *(np.uint64(k) for k in key))
    assert tuple(int(r) for r in result) == expected


def test_pair_gaussian_is_symmetric_and_uses_every_key_word():
    base = pair_gaussian(5, 7, 3, 9)
    assert base == pair_gaussian(5, 7, 9, 3)
    others = [pair_gaussian(5, 8, 3, 9), pair_gaussian(6, 7, 3, 9), pair_gaussian(5, 7, 4, 9),
              pair_gaussian(5, 7, 3, 10), pair_gaussian(5, 7 + 2 ** 32, 3, 9),
              pair_gaussian(5 + 2 ** 32, 7, 3, 9)]
    assert len({base, *others}) == 7


def test_pair_gaussian_statistics():
    """Over 40000 (pair, step) keys: mean 0, variance 1, Gaussian tails and fourth moment, and
    no correlation between neighbouring steps or neighbouring tags (5-sigma sampling bounds)."""
    n_pairs, n_steps = 4000, 10
    samples = np.empty((n_pairs, n_steps))
    for k in range(n_pairs):
        i = 1 + k
        j = 1 + (k * 7919) % 100003
        for s in range(n_steps):
            samples[k, s] = pair_gaussian(123, s, i, j + n_pairs)
    flat = samples.ravel()
    n = flat.size
    assert abs(flat.mean()) < 5 / math.sqrt(n)
    assert abs(flat.var() - 1.0) < 5 * math.sqrt(2.0 / n)
    assert abs(np.mean(flat ** 4) - 3.0) < 5 * math.sqrt(96.0 / n)
    inside = np.mean(np.abs(flat) < 1.0)
    assert abs(inside - 0.682689) < 5 * math.sqrt(0.2166 / n)
    step_corr = np.corrcoef(samples[:, :-1].ravel(), samples[:, 1:].ravel())[0, 1]
    tag_corr = np.corrcoef(samples[:-1].ravel(), samples[1:].ravel())[0, 1]
    assert abs(step_corr) < 5 / math.sqrt(n) and abs(tag_corr) < 5 / math.sqrt(n)


# ---- bad input ----------------------------------------------------------------------------------
def _box():
    return make_box(box="0 5 0 5 0 5", ntypes=2)


@pytest.mark.parametrize("line, words", [
    ("pair_style dpd -1.0 1.0 5", ("temperature", ">=", "(got -1.0)")),
    ("pair_style dpd 1.0 0 5", ("cutoff", ">", "(got 0)")),
    ("pair_style dpd 1.0 1.0 0", ("seed", ">= 1", "(got 0)")),
    ("pair_style dpd 1.0 1.0 5.5", ("seed", "integer", "(got 5.5)")),
    ("pair_style dpd 1.0 1.0", ("missing argument seed",)),
    ("pair_style dpd 1.0 nan 5", ("cutoff", "(got nan)")),
    ("pair_style dpd 1.0 1.0 5 noise lorentz", ("noise", "gaussian", "uniform", "(got lorentz)")),
])
def test_bad_pair_style_arguments(line, words):
    sim = _box()
    with pytest.raises(ScriptError) as info:
        sim.command(line)
    message = str(info.value)
    assert "pair_style" in message
    for word in words:
        assert word in message


@pytest.mark.parametrize("line, words", [
    ("pair_coeff 1 1 25.0 -4.5", ("gamma", ">=", "(got -4.5)")),
    ("pair_coeff 1 1 25.0 4.5 -1", ("cutoff", ">", "(got -1)")),
    ("pair_coeff 1 1 25.0", ("missing argument gamma",)),
    ("pair_coeff 1 1 abc 4.5", ("a must be", "(got abc)")),
    ("pair_coeff 1 1 25 4.5 1.0 7", ("unexpected",)),
    ("pair_coeff 1 3 25 4.5", ("out of range",)),
])
def test_bad_pair_coeff_arguments(line, words):
    sim = _box()
    sim.command("pair_style dpd 1.0 1.0 5")
    with pytest.raises(ScriptError) as info:
        sim.command(line)
    message = str(info.value)
    assert "pair_coeff" in message
    for word in words:
        assert word in message


def test_negative_gamma_message_is_the_designs_one_liner():
    sim = _box()
    sim.command("pair_style dpd 1.0 1.0 5")
    with pytest.raises(ScriptError) as info:
        sim.command("pair_coeff 1 1 25.0 -4.5")
    assert str(info.value).endswith("pair_coeff: gamma must be >= 0 (got -4.5)")


def test_unset_type_pair_is_an_error_at_run():
    sim = _box()
    sim.command("mass * 1\ncreate_particle 1 single 1 1 1\npair_style dpd 1.0 1.0 5\n"
                "pair_coeff 1 1 25 4.5\npair_coeff 2 2 25 4.5")
    with pytest.raises(ScriptError, match="not set for types 1 2"):
        sim.command("run 0")
