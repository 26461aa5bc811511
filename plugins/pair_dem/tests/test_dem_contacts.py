"""Oblique contacts: Coulomb's bound, Newton's third law, torques, angular momentum; the tangential
spring across periodic faces, neighbor rebuilds and re-sorting; static friction; separation."""

import numpy as np
import pytest

from pdps_core.testing import ContactsHeld, register_styles, sphere_mass, unwrapped

PAIRS = {"lsd": ("dem/lsd 0.3 1.0", ["* * kn 1000 e 0.7 mu 0.3"]),
         "hertz": ("dem/hertz", ["* * 2.0e5 0.3 0.7 0.3"])}


def oblique(dem, style, shift=0.0, steps=1200, extra=""):
    """Two unit spheres meet off-centre (offset 0.45 in y, crossing z during the contact), spinning:
    the contact sticks and slides. ``shift`` moves the scene along x (5.5: across the periodic face)."""
    pair, coeffs = PAIRS[style]
    x1, x2 = (4.0 + shift) % 10.0, (4.96 + shift) % 10.0
    sim = dem.spheres(pair, coeffs, [(1, x1, 5.0, 5.02, 1.0, 1.0), (1, x2, 5.45, 4.98, 1.0, 1.0)],
                      extra=("timestep 0.0001\nfix rec all test/dem/record\n"
                             f"fix move all test/nve_sphere\n{extra}"))
    dem.set_motion(sim, 1, v=(1.0, 0.0, -0.5), omega=(0.0, 3.0, 8.0))
    dem.set_motion(sim, 2, v=(-1.0, 0.0, 0.5), omega=(-4.0, 0.0, -2.0))
    sim.command(f"run {steps}")
    return sim, sim.fixes["rec"]


def normals(record):
    """Unit normals from particle 2 to particle 1 at each force evaluation, and the overlaps (unit
    spheres, nearest images in the box of edge 10)."""
    at = np.array(record.at)
    d = at[:, 0] - at[:, 1]
    d -= 10.0 * np.round(d / 10.0)
    r = np.linalg.norm(d, axis=1)
    return d / r[:, None], 1.0 - r


@pytest.mark.parametrize("style", ["lsd", "hertz"])
def test_oblique_contact_obeys_coulomb_newton_and_conserves_angular_momentum(dem, style):
    sim, record = oblique(dem, style)
    forces, torques = np.array(record.forces), np.array(record.torques)
    n, overlap = normals(record)
    touching = overlap > 0.0
    assert touching.sum() > 100 and not touching[-1]
    # Newton's third law, and nothing outside contact
    assert np.array_equal(forces[:, 0], -forces[:, 1])
    assert not forces[~touching].any() and not torques[~touching].any()
    # Coulomb: |Ft| <= mu |Fn|, reached while sliding, not while sticking
    f = forces[touching, 0]
    fn = np.einsum("ij,ij->i", f, n[touching])
    ft = np.linalg.norm(f - fn[:, None] * n[touching], axis=1)
    ratio = ft / (0.3 * np.abs(fn))
    assert ratio.max() <= 1.0 + 1e-12
    assert (ratio > 1.0 - 1e-9).sum() > 10 and (ratio < 0.99).sum() > 10
    # equal spheres: equal torques, each the moment of the contact force at the contact point
    arm = (0.5 - 0.5 * overlap[touching])[:, None] * n[touching]
    assert np.allclose(torques[touching, 0], torques[touching, 1], rtol=1e-12, atol=0.0)
    assert np.allclose(torques[touching, 0], np.cross(-arm, f), rtol=1e-10, atol=1e-12)
    assert np.allclose(torques[touching, 1], np.cross(arm, -f), rtol=1e-10, atol=1e-12)
    # angular momentum about the origin, orbital plus spin, to round-off; linear momentum too
    mass, radius = np.full(2, sphere_mass(1.0, 1.0)), np.full(2, 0.5)
    momenta = np.array([dem.angular_momentum(x, v, w, mass, radius)
                        for x, v, w in zip(record.x, record.v, record.omega)])
    assert np.abs(momenta - momenta[0]).max() < 1e-12 * np.abs(momenta[0]).max()
    linear = np.array([(mass[:, None] * v).sum(axis=0) for v in record.v])
    assert np.abs(linear - linear[0]).max() < 1e-14
    # the spin changed: the tangential force did act
    assert np.abs(record.omega[-1] - record.omega[0]).max() > 1.0


@pytest.mark.parametrize("style", ["lsd", "hertz"])
def test_a_contact_across_the_periodic_face_matches_the_same_contact_inside(dem, style):
    """The partner is a ghost; the pair is listed first on one side of the face, then (once dz
    changes sign, at the next rebuild) on the other, which reads the spring copy written to the
    ghost's owner."""
    every_step = "neigh_modify every 1 delay 0 check no"
    _, inside = oblique(dem, style, extra=every_step)
    sim, across = oblique(dem, style, shift=5.5, extra=every_step)
    _, overlap = normals(across)
    listers = set().union(*(across.ghost_listers[k] for k in np.flatnonzero(overlap > 0.0)))
    assert listers == {1, 2}
    assert not set().union(*inside.ghost_listers)
    assert np.allclose(across.v[-1], inside.v[-1], rtol=0, atol=1e-9)
    assert np.allclose(across.omega[-1], inside.omega[-1], rtol=0, atol=1e-9)
    assert np.allclose(np.array(across.forces), np.array(inside.forces), rtol=0, atol=1e-7)
    assert (sim.pair.history.partner == -1).all()


def test_spheres_apart_feel_exactly_nothing_and_their_contact_is_forgotten(dem):
    sim, record = oblique(dem, "lsd")
    assert (sim.pair.history.partner == -1).all()          # the collision's slots were freed
    sim = dem.spheres("dem/lsd 0.3 1.0", ["* * kn 1000 e 0.7 mu 0.3"],
                      [(1, 4.0, 5.0, 5.0, 1.0, 1.0), (1, 5.0 + 1e-12, 5.0, 5.0, 1.0, 1.0)],
                      extra="fix rec all test/dem/record\nfix move all test/nve_sphere")
    dem.set_motion(sim, 1, omega=(0.0, 0.0, 5.0))
    sim.command("run 3")
    record = sim.fixes["rec"]
    assert len(sim.pair_list.neighbors) == 1                # in the list, not in contact
    assert not np.array(record.forces).any() and not np.array(record.torques).any()
    assert (sim.pair.history.partner == -1).all()


def resting(dem, load_x, first_steps=1500, second_steps=1500):
    """Sphere B (tag 1, type 2) pressed onto a fixed sphere A (tag 2, type 1) by a normal load of 10
    and pulled sideways by ``load_x``; B translates only. Lists are rebuilt every step; the first run
    keeps the storage order (B first), the second re-sorts every step (A first, so the other sphere
    computes the contact from its own copy of the spring)."""
    kn, kt = 1.0e4, 2857.0
    sim = dem.spheres("dem/lsd 0.3 1.0", [f"* * {kn} 72.0 {kt} 38.7 0.5"],
                      [(2, 5.0, 5.0, 5.0 + 1.0 - 10.0 / kn, 1.0, 1.0), (1, 5.0, 5.0, 5.0, 1.0, 1.0)],
                      ntypes=2,
                      extra=("timestep 0.0002\nneigh_modify every 1 delay 0 check no\n"
                             "atom_modify sort 0 0\ngroup top type 2\n"
                             "fix rec all test/dem/record\nfix move top test/nve_sphere rotate no\n"
                             f"fix push top test/force {load_x} 0.0 -10.0"))
    builds = sim.neighbor.builds
    sim.command(f"run {first_steps}")
    first_order = list(sim.tag)
    middle = unwrapped(sim)[0].copy()
    sim.command(f"atom_modify sort 1 0\nrun {second_steps}")
    assert first_order == [1, 2] and list(sim.tag) == [2, 1]
    assert sim.neighbor.builds - builds >= first_steps + second_steps
    return sim, middle, kt


def test_a_sphere_under_a_tangential_load_below_mu_fn_stays_stuck_across_rebuilds_and_resorts(dem):
    load = 0.5 * 0.5 * 10.0
    sim, middle, kt = resting(dem, load)
    end = unwrapped(sim)[0]
    shift = middle[0] - 5.0
    # held by the tangential spring alone: displaced by load / kt, and still there after the re-sorts
    assert shift == pytest.approx(load / kt, rel=0.01)
    assert abs(end[0] - middle[0]) < 1e-4 * shift      # what is left of the settling oscillation
    assert np.abs(sim.v).max() < 1e-8
    # the contact is stored on both spheres, each in its own frame
    history = sim.pair.history
    a, b = sim.particles.index_of_tag(2), sim.particles.index_of_tag(1)
    slot_a, slot_b = list(history.partner[a]).index(1), list(history.partner[b]).index(2)
    spring_a = history.values[a, 3 * slot_a:3 * slot_a + 3]
    spring_b = history.values[b, 3 * slot_b:3 * slot_b + 3]
    assert np.array_equal(spring_a, -spring_b)
    assert spring_b[0] == pytest.approx(shift, rel=1e-3)


def test_a_sphere_under_a_tangential_load_above_mu_fn_slides_with_the_friction_force(dem):
    load = 1.5 * 0.5 * 10.0
    sim, _, kt = resting(dem, load, first_steps=300, second_steps=300)
    record = sim.fixes["rec"]
    # driven by at least load - mu Fn from the start: far beyond what the spring alone would allow
    slid = unwrapped(sim)[0][0] - 5.0
    duration = 600 * 0.0002
    assert slid > 0.9 * 0.5 * (load - 0.5 * 10.0) / sphere_mass(1.0, 1.0) * duration ** 2
    assert slid > 20 * 0.5 * 0.5 * 10.0 / kt
    # the contact force on the fixed sphere: sliding friction mu |Fn| once the spring has stretched
    n, _ = normals(record)
    f = np.array(record.forces)[100:, 1]
    fn = np.einsum("ij,ij->i", f, n[100:])
    ft = np.linalg.norm(f - fn[:, None] * n[100:], axis=1)
    assert ft == pytest.approx(0.5 * np.abs(fn), rel=1e-9)


@pytest.mark.parametrize("style, coeff", [("dem/lsd 0.3 1.0", "* * 1.0e4 70 2857 40 0.5"),
                                          ("dem/hertz", "* * 1.0e6 0.3 0.5 0.5")])
def test_a_sphere_spinning_on_another_is_braked_by_sliding_friction(dem, style, coeff):
    """B spins about x on a fixed sphere A at constant overlap: the contact point slips, and the
    friction torque (R - delta/2) mu Fn takes the spin down at a constant rate."""
    overlap = 1.0e-3
    sim = dem.spheres(style, [coeff], [(1, 5.0, 5.0, 5.0, 1.0, 1.0), (2, 5.0, 5.0, 6.0 - overlap, 1.0, 1.0)],
                      ntypes=2, extra=("timestep 0.0002\ngroup top type 2\nfix rec all test/dem/record\n"
                                       "fix spin top test/nve_sphere translate no"))
    dem.set_motion(sim, 2, omega=(5.0, 0.0, 0.0))
    sim.command("run 300")
    record = sim.fixes["rec"]
    fn = -np.array(record.forces)[:, 0, 2]                  # the normal force on A, along -z
    assert fn == pytest.approx(fn[0], rel=1e-12) and fn[0] > 0
    inertia = 0.4 * sphere_mass(1.0, 1.0) * 0.25
    rate = (0.5 - 0.5 * overlap) * 0.5 * fn[0] / inertia
    spin = np.array(record.omega)[:, 1, 0]
    assert spin == pytest.approx(5.0 - rate * 0.0002 * np.arange(1, 301), rel=1e-9)
    assert spin[-1] > 0.5


@pytest.mark.parametrize("pair, coeff", [("dem/lsd 0.3 1.0", "* * kn 200000 e 0.7 mu 0.3"),
                                         ("dem/hertz", "* * 5.0e7 0.3 0.7 0.3")])
def test_contact_slots_hold_exactly_the_contacts_of_each_step(dem, pair, coeff):
    """A contact is forgotten at the end of the step its spheres came apart: 100 spheres near the
    sites of a lattice of spacing 1.2 in a periodic box 6 wide, with Gaussian velocities of deviation
    8, so that the lists are rebuilt every few steps (between builds only the rows that held or made
    a contact are swept) and contacts last about as long (stiff springs): at every step the slots
    hold exactly the pairs that touch."""
    register_styles(ContactsHeld)
    rng = np.random.default_rng(6)
    sites = (np.stack(np.meshgrid(*[np.arange(5)] * 3, indexing="ij"), -1).reshape(-1, 3)[:100] * 1.2
             + 0.6 + rng.uniform(-0.02, 0.02, (100, 3)))
    sim = dem.spheres(pair, [coeff], [(1, *site, 1.0, 1.0) for site in sites], box="0 6 0 6 0 6",
                      extra=("timestep 0.0004\nneighbor 0.1 bin\nneigh_modify delay 0 every 1 check yes\n"
                             "fix move all test/nve_sphere\nfix check all test/contacts_held"))
    for tag in range(1, 101):
        dem.set_motion(sim, tag, v=tuple(rng.normal(0.0, 8.0, 3)))
    sim.command("run 400")
    check = sim.fixes["check"]
    print(f"builds {sim.neighbor.builds}, contacts per step up to {max(check.contacts)}")
    assert sim.neighbor.builds > 20 and sum(check.contacts) > 400
    assert all(check.exact)
