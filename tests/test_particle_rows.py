"""Particles' row operations used by migration and ghosts: removal in LAMMPS's order, keep (the
spatial sort, migration) in the order asked and in place, and ghost rows that carry what neighbours
read and not what is summed back."""

import tracemalloc

import numpy as np
import pytest

from pdps_core.state.particles import Particles


def _lammps_removal(doomed):
    """LAMMPS's AtomVec::copy loop, written out: the last particle takes a freed slot and is looked at
    again."""
    rows, gone = list(range(len(doomed))), [bool(d) for d in doomed]
    i = 0
    while i < len(rows):
        if gone[i]:
            rows[i], gone[i] = rows[-1], gone[-1]
            rows.pop()
            gone.pop()
        else:
            i += 1
    return rows


def test_remove_leaves_lammps_order_and_every_array_consistent():
    rng = np.random.default_rng(7)
    for _ in range(300):
        n = int(rng.integers(0, 30))
        doomed = rng.random(n) < rng.random()
        p = Particles()
        p.request("radius")
        p.request("molecule")
        p.add(rng.random((n, 3)), 1)
        p.radius[:] = np.arange(n) + 0.5
        p.molecule[:] = 10 * np.arange(n)
        x = p.x.copy()
        p.remove(doomed.copy())
        kept = _lammps_removal(doomed)
        assert p.nlocal == n - doomed.sum()
        assert p.tag.tolist() == [k + 1 for k in kept]
        assert p.radius.tolist() == [k + 0.5 for k in kept]
        assert p.molecule.tolist() == [10 * k for k in kept]
        assert np.array_equal(p.x, x[kept])


def _particles(n, rng):
    p = Particles()
    p.request("radius")
    p.request("history", width=12)
    p.add(rng.random((n, 3)), 1)
    p.radius[:] = np.arange(n) + 0.5
    p.history[:] = np.arange(n)[:, None] * 100.0 + np.arange(12)
    return p


@pytest.mark.parametrize("kind", ["permutation", "rising subset", "mask", "subset in any order"])
def test_keep_leaves_the_particles_asked_in_that_order_with_every_array(kind):
    rng = np.random.default_rng(3)
    for _ in range(200):
        n = int(rng.integers(1, 40))
        p = _particles(n, rng)
        x = p.x.copy()
        if kind == "permutation":
            selection = index = rng.permutation(n)
        elif kind == "rising subset":
            selection = index = np.flatnonzero(rng.random(n) < 0.6)
        elif kind == "mask":
            selection = rng.random(n) < 0.6
            index = np.flatnonzero(selection)
        else:
            selection = index = rng.choice(n, size=int(rng.integers(0, n + 1)), replace=False)
        p.keep(selection)
        assert p.nlocal == len(index)
        assert p.tag.tolist() == (index + 1).tolist()
        assert p.radius.tolist() == (index + 0.5).tolist()
        np.testing.assert_array_equal(p.x, x[index])
        np.testing.assert_array_equal(p.history, index[:, None] * 100.0 + np.arange(12))


def test_the_spatial_sort_moves_rows_without_a_copy_of_an_array():
    """keep() of a reordering of every particle works in place: no transient as large as the
    widest array (here 96 values, 768 bytes a particle), 9 bytes a particle for its index and flags."""
    n = 20000
    p = Particles()
    p.request("history", width=96)
    p.add(np.random.default_rng(1).random((n, 3)), 1)
    order = np.random.default_rng(2).permutation(n)
    p.keep(np.arange(n))                              # compiles the kernels outside the measurement
    tracemalloc.start()
    try:
        p.keep(order)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 16 * n
    assert p.tag.tolist() == (order + 1).tolist()


def test_ghost_blocks_carry_neighbour_values_and_zero_the_summed_ones():
    p = Particles()
    p.request("radius")
    p.request("torque")
    p.add(np.arange(12.0).reshape(4, 3), [1, 2, 3, 2])
    p.mask[:] = [3, 5, 9, 17]
    p.radius[:] = [0.1, 0.2, 0.3, 0.4]
    p.f[:] = 4.0
    p.torque[:] = 5.0
    p.image[:] = 2
    # x, v, tag, type, mask, radius: 3 + 3 + 1 + 1 + 1 + 1 values; f, torque and image stay home
    assert p.row_width(ghost=True) == 10
    # three ghosts: one for rank 0, none for rank 1, two for rank 2
    shift = np.array([[10.0, 0.0, 0.0], [0.0, -10.0, 0.0], [0.0, 0.0, 10.0]])
    counts = np.array([1, 0, 2])
    values = np.full(3 * 10, np.nan)
    p.pack_ghosts(np.array([3, 1, 0]), counts, values, shift)
    # rank 2's share: both x rows, then both v rows, then tags, types, masks, radii
    assert values[10:16].tolist() == [3.0, -6.0, 5.0, 0.0, 1.0, 12.0]
    assert values[22:].tolist() == [2.0, 1.0, 2.0, 1.0, 5.0, 3.0, 0.2, 0.1]
    p.f[:] = 4.0
    p.set_ghost_blocks(values, counts)
    assert p.nghost == 3
    assert np.array_equal(p.x[4:], [[19.0, 10.0, 11.0], [3.0, -6.0, 5.0], [0.0, 1.0, 12.0]])
    assert p.tag[4:].tolist() == [4, 2, 1] and p.type[4:].tolist() == [2, 2, 1]
    assert p.mask[4:].tolist() == [17, 5, 3] and p.radius[4:].tolist() == [0.4, 0.2, 0.1]
    assert not p.f[4:].any() and not p.torque[4:].any() and not p.image[4:].any()
    # a migrating particle takes everything with it
    p.append_owned(p.pack(np.array([2])))
    assert p.nlocal == 5 and p.nghost == 0
    assert p.f[4].tolist() == [4.0] * 3 and p.torque[4].tolist() == [5.0] * 3 and p.image[4].tolist() == [2] * 3
    assert p.mask[4] == 9 and p.tag[4] == 3


def test_owned_rows_finds_each_id_and_marks_the_others():
    p = Particles()
    p.add(np.zeros((5, 3)), 1, tags=np.array([40, 7, 19, 3, 25]))
    rows = p.owned_rows(np.array([3, 40, 8, 25, 3, 100, 0]))
    assert rows.tolist() == [3, 0, -1, 4, 3, -1, -1]
    assert all(p.index_of_tag(t) == r for t, r in zip([3, 40, 8, 25], rows[:4]))
    assert Particles().owned_rows(np.array([1, 2])).tolist() == [-1, -1]
