"""Neighbor lists against brute force, and the rebuild decision of neigh_modify."""

import itertools

import numpy as np
import pytest

from pdps_core.api import Fix, registry


def brute_force_pairs(x, lengths, periodic, cut):
    """All unordered pairs (including a particle with its own images) within cut, by image search."""
    pairs = {}
    n = len(x)
    reach = [int(np.ceil(cut / lengths[d])) if periodic[d] else 0 for d in range(3)]
    for i in range(n):
        for j in range(i, n):
            for shift in itertools.product(*[range(-r, r + 1) for r in reach]):
                if i == j and not any(shift):
                    continue
                delta = x[j] + np.array(shift) * lengths - x[i]
                if delta @ delta < cut * cut:
                    key = (i, j, shift) if i != j or shift > tuple(-s for s in shift) else None
                    if key is not None:
                        pairs[key] = np.sqrt(delta @ delta)
    return sorted(round(r, 9) for r in pairs.values())


def listed_pairs(sim, kind):
    p = sim.particles
    nlist = sim.pair_list
    distances = []
    for i in range(p.nlocal):
        for j in nlist.neighbors[nlist.offsets[i]:nlist.offsets[i + 1]]:
            distances.append(round(float(np.linalg.norm(p.x[i] - p.x[j])), 9))
    return sorted(distances)


def setup_random(make_sim, n, length, cut, skin, seed=1, dimension=3, periodic="p p p"):
    sim = make_sim()
    z = "0 1" if dimension == 2 else f"0 {length}"
    sim.command(f"""
        dimension {dimension}
        boundary {periodic}
        region box block 0 {length} 0 {length} {z}
        create_box 1 box
        mass 1 1
        neighbor {skin}
        pair_style dpd 1.0 {cut} 5
        pair_coeff * * 25 4.5
        create_particle 1 random_no_overlap {n} box 0.0 {seed}
        run 0
    """)
    return sim


@pytest.mark.parametrize("n,length,cut,dimension", [
    (200, 5.0, 1.0, 3),     # ordinary periodic box
    (40, 1.5, 1.0, 3),      # box thinner than cutoff + skin: several images of one particle
    (100, 4.0, 1.2, 2),     # 2-d
])
def test_half_list_holds_every_pair_within_cut_plus_skin_exactly_once(make_sim, n, length, cut, dimension):
    skin = 0.3
    sim = setup_random(make_sim, n, length, cut, skin, dimension=dimension)
    p = sim.particles
    x = p.x[: p.nlocal]
    lengths = sim.box.length.copy()
    periodic = (True, True, dimension == 3)
    expected = brute_force_pairs(x, lengths, periodic, cut + skin)
    assert listed_pairs(sim, "half") == expected


def test_fixed_boundaries_make_no_ghosts(make_sim):
    sim = setup_random(make_sim, 100, 4.0, 1.0, 0.3, periodic="f f f")
    assert sim.particles.nghost == 0
    x = sim.particles.x[: sim.nlocal]
    expected = brute_force_pairs(x, sim.box.length, (False,) * 3, 1.3)
    assert listed_pairs(sim, "half") == expected


class Drift(Fix):
    """Moves every particle by a fixed displacement per step (no integrator, no forces needed)."""
    name = "test/drift"

    def initial_integrate(self, sim):
        sim.x[:, 0] += 0.1


@pytest.fixture
def drifting(make_sim):
    registry.register("fix", "test/drift", Drift)

    def make(modify):
        sim = make_sim()
        sim.command(f"""
            region box block 0 10 0 10 0 10
            create_box 1 box
            mass 1 1
            create_particle 1 single 5 5 5
            create_particle 1 single 1 1 1
            pair_style dpd 1.0 1.0 5
            pair_coeff * * 25 0
            neighbor 0.3
            {modify}
            fix 1 all test/drift
            run 0
        """)
        before = sim.neighbors.builds
        sim.command("run 12")
        setup_build = 1      # every run starts from a fresh list
        return sim.neighbors.builds - before - setup_build, sim.neighbors.dangerous
    return make


def test_check_yes_rebuilds_when_displacement_exceeds_half_skin(drifting):
    # 0.1 per step, half skin 0.15: the check fails at ago=1, passes at ago=2 -> every 2 steps
    builds, dangerous = drifting("neigh_modify every 1 delay 0 check yes")
    assert builds == 6
    assert dangerous == 0


def test_check_no_rebuilds_every_n_steps(drifting):
    builds, _ = drifting("neigh_modify every 3 delay 0 check no")
    assert builds == 4


def test_delay_holds_rebuilds_back_and_counts_dangerous_ones(drifting):
    # the displacement allows a rebuild at ago=2, but delay 3 forces ago=3: each is "dangerous"
    builds, dangerous = drifting("neigh_modify every 1 delay 3 check yes")
    assert builds == 4
    assert dangerous == 4


def test_pdps_spelling_neighbor_modify(drifting):
    builds, _ = drifting("neighbor_modify delay 0 every 3 check no")
    assert builds == 4
