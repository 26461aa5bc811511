"""compute coord/atom against a brute-force count over periodic images, on 1 and 2 ranks."""

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import build, fluid, run_ranks, write_data

L, RC = 6.0, 1.5


def system():
    x, _ = fluid(300, 300 / L ** 3, seed=5, min_distance=0.6)
    types = 1 + (np.arange(300) % 3 == 0)       # every third particle is type 2
    return x, types


def brute_force(x, types, rc, type_ranges, center=None, neighbor=None):
    """counts[i, m]: particles j != i (every periodic image within rc) with a type in range m."""
    n = len(x)
    center = np.ones(n, bool) if center is None else center
    neighbor = np.ones(n, bool) if neighbor is None else neighbor
    counts = np.zeros((n, len(type_ranges)))
    shifts = np.array([[a, b, c] for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)]) * L
    for i in range(n):
        if not center[i]:
            continue
        for s in shifts:
            r = np.linalg.norm(x + s - x[i], axis=1)
            close = (r < rc) & neighbor
            close[i] &= s.any()
            for m, (lo, hi) in enumerate(type_ranges):
                counts[i, m] += np.count_nonzero(close & (types >= lo) & (types <= hi))
    return counts


def test_counts_equal_brute_force_with_type_ranges_and_groups(tmp_path):
    x, types = system()
    sim = build(tmp_path, x, types=types, hi=(L, L, L), setup=f"""
        group twos type 2
        compute all_types all coord/atom cutoff {RC}
        compute by_type all coord/atom cutoff {RC} 1 2 *
        compute of_twos all coord/atom cutoff {RC} 1*2 group twos
        compute around_twos twos coord/atom cutoff {RC}
        run 0
    """)
    tags = np.argsort(sim.tag)
    expected = brute_force(x, types, RC, [(1, 2)])[:, 0]
    assert sim.computes["all_types"].peratom(sim)[tags] == pytest.approx(expected, abs=0)
    assert expected.mean() > 5          # a real test: several neighbors each
    by_type = brute_force(x, types, RC, [(1, 1), (2, 2), (1, 2)])
    assert sim.computes["by_type"].peratom(sim)[tags] == pytest.approx(by_type, abs=0)
    # one type range: one value per particle (LAMMPS's per-atom vector, c_ID), not a column
    twos = brute_force(x, types, RC, [(1, 2)], neighbor=types == 2)[:, 0]
    assert sim.computes["of_twos"].peratom(sim)[tags] == pytest.approx(twos, abs=0)
    around = brute_force(x, types, RC, [(1, 2)], center=types == 2)[:, 0]
    assert sim.computes["around_twos"].peratom(sim)[tags] == pytest.approx(around, abs=0)


def test_cutoff_beyond_the_pair_cutoff_and_after_particles_moved(tmp_path):
    x, types = system()
    sim = build(tmp_path, x, types=types, hi=(L, L, L), setup="""
        pair_style lj/cut 1.0
        pair_coeff * * 0.1 0.5
        velocity all create 0.5 77
        fix 1 all nve
        timestep 0.002
        compute c all coord/atom cutoff 2.2
        run 150
    """)
    order = np.argsort(sim.tag)
    expected = brute_force(sim.x[order], sim.type[order], 2.2, [(1, 2)])[:, 0]
    assert sim.computes["c"].peratom(sim)[order] == pytest.approx(expected, abs=0)


def test_read_before_a_run_is_a_clear_error(tmp_path):
    sim = build(tmp_path, [[1.0, 1.0, 1.0]], setup="compute c all coord/atom cutoff 1.0")
    with pytest.raises(ScriptError, match=r"compute c \(coord/atom\) is read before any run: run 0 first"):
        sim.computes["c"].peratom(sim)


@pytest.mark.parametrize("words, message", [
    ("radius 1.0", "cutoff must be a finite number (got radius)"),
    ("1.0 1 mix yes", "mix yes counts neighbors of the particle's own type: give it without type ranges"),
    ("cutoff -1", "cutoff must be > 0 (got -1)"),
    ("cutoff 1.0 4", "type 4 is out of range 1..2"),
    ("cutoff 1.0 group", "keyword group needs 1 value(s) (got 0)"),
    ("cutoff 1.0 group all 2", "unknown keyword 2 (known: mix, group)"),
])
def test_bad_arguments(tmp_path, words, message):
    x, types = system()
    sim = build(tmp_path, x[:3], types=[1, 2, 1], hi=(L, L, L))
    with pytest.raises(ScriptError) as caught:
        sim.command(f"compute c all coord/atom {words}")
    assert str(caught.value) == f"<command>:1: compute: {message}"


@pytest.mark.parametrize("ranks", [1, 2])
def test_same_counts_on_1_and_2_ranks(tmp_path, ranks):
    x, types = system()
    write_data(tmp_path / "data.coord", (0, 0, 0), (L, L, L), x, types=types)
    run_ranks(f"""
        read_data data.coord
        compute c all coord/atom cutoff {RC} 1 2
        dump d all custom 1 coord.txt id c_c[0] c_c[1]
        run 0
    """, ranks, tmp_path)
    rows = np.loadtxt(tmp_path / "coord.txt", skiprows=9)
    rows = rows[np.argsort(rows[:, 0])]
    assert rows[:, 0] == pytest.approx(np.arange(1, 301))
    assert rows[:, 1:] == pytest.approx(brute_force(x, types, RC, [(1, 1), (2, 2)]), abs=0)
