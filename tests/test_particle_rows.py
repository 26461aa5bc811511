"""Particles' row operations used by migration and ghosts: removal in LAMMPS's order, and ghost rows
that carry what neighbours read and not what is summed back."""

import numpy as np

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
