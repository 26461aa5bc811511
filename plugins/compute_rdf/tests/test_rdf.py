"""compute rdf against freud on the same snapshot, against direct counts over periodic images, and on
a lattice with known shells.

freud works in float32: its pair counts are exact integers, its g(r) carries ~1e-7 rounding. So g is
compared at 1e-10 with freud's counts normalised in float64 by freud's own convention
(g = H / (N_I N_J dV / V), checked against freud's float32 g at 1e-5) converted to LAMMPS's
(N_I N_J - D instead of N_I N_J). Positions are rounded to float32 first, so both codes see the same
particles, and each snapshot is checked to have no pair distance within 1e-5 of a bin edge, where
float32 and float64 could put a pair in neighboring bins.
"""

import itertools
import math

import freud                # the [test] extra, installed by make
import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import make_box



def snapshot(positions, types, length, dimension=3, boundary="p p p", ntypes=None, extra=""):
    """A simulation holding exactly these particles in the box [0, length)^d."""
    ntypes = ntypes or int(max(types))
    zhi = length if dimension == 3 else 0.5
    zlo = 0 if dimension == 3 else -0.5
    lines = [f"mass {t} 1.0" for t in range(1, ntypes + 1)]
    lines += [f"create_particle {t} single {x!r} {y!r} {z!r}"
              for t, (x, y, z) in zip(np.asarray(types).tolist(), np.asarray(positions).tolist())]
    sim = make_box("\n".join(lines) + "\n" + extra, box=f"0 {length} 0 {length} {zlo} {zhi}",
                   boundary=boundary, ntypes=ntypes, dimension=dimension)
    order = np.argsort(sim.tag)
    assert np.array_equal(sim.x[order], positions)
    return sim


def random_snapshot(seed, n, length, dimension=3, ntypes=1):
    rng = np.random.default_rng(seed)
    x = rng.uniform(0.0, length, (n, 3)).astype(np.float32).astype(np.float64)
    x[x >= length] = 0.0
    if dimension == 2:
        x[:, 2] = 0.0
    types = rng.integers(1, ntypes + 1, n)
    return x, types


def min_image_distances(a, b, length, dimension):
    d = a[:, None, :dimension] - b[None, :, :dimension]
    d -= length * np.round(d / length)
    return np.sqrt((d ** 2).sum(axis=2))


def assert_clear_of_bin_edges(x, length, dimension, cutoff, nbin):
    r = min_image_distances(x, x, length, dimension)
    r = r[(r > 0) & (r < cutoff + 1e-3)]
    edges = np.linspace(0.0, cutoff, nbin + 1)
    assert np.abs(r[:, None] - edges[None, :]).min() > 1e-5


def freud_box(length, dimension):
    return freud.box.Box.cube(length) if dimension == 3 else freud.box.Box.square(length)


def freud_rdf(length, dimension, cutoff, nbin, points, query_points=None):
    """freud's RDF of positions given in [0, L): freud boxes span [-L/2, L/2)."""
    shift = np.array([length / 2, length / 2, length / 2 if dimension == 3 else 0.0])
    rdf = freud.density.RDF(bins=nbin, r_max=cutoff)
    query = None if query_points is None else query_points - shift
    rdf.compute((freud_box(length, dimension), points - shift), query_points=query)
    return rdf


def shell_fraction(length, dimension, cutoff, nbin):
    edges = np.linspace(0.0, cutoff, nbin + 1)
    if dimension == 3:
        return 4.0 / 3.0 * math.pi * np.diff(edges ** 3) / length ** 3
    return math.pi * np.diff(edges ** 2) / length ** 2


def direct_coordination(x, length, periodic, dimension, cutoff, upper_edges, centres, neighbors):
    """Mean number of neighbor particles (every periodic image) within each upper edge of a centre."""
    reach = [int(math.ceil(cutoff / length)) + 1 if (periodic[d] and d < dimension) else 0 for d in range(3)]
    counts = np.zeros(len(upper_edges))
    for shift in itertools.product(*(range(-k, k + 1) for k in reach)):
        s = np.array(shift, dtype=float) * length
        r = np.sqrt(((x[centres][:, None, :] - x[neighbors][None, :, :] - s) ** 2).sum(axis=2))
        if not any(shift):
            r[centres[:, None] == neighbors[None, :]] = np.inf
        counts += (r.ravel()[:, None] < upper_edges[None, :]).sum(axis=0)
    return counts / len(centres)


@pytest.mark.parametrize("dimension, seed, n, length, cutoff, nbin",
                         [(3, 11, 150, 6.0, 2.5, 25), (2, 2, 150, 10.0, 4.0, 20)])
def test_g_and_coordination_agree_with_freud(dimension, seed, n, length, cutoff, nbin):
    x, types = random_snapshot(seed, n, length, dimension)
    assert_clear_of_bin_edges(x, length, dimension, cutoff, nbin)
    sim = snapshot(x, types, length, dimension, extra=f"compute r all rdf {nbin} 1 1 cutoff {cutoff}")
    ours = sim.computes["r"].array(sim)

    reference = freud_rdf(length, dimension, cutoff, nbin, x)
    counts = reference.bin_counts.astype(np.float64)
    fraction = shell_fraction(length, dimension, cutoff, nbin)
    freud_g = counts / (n * n * fraction)                     # freud's 'exact' normalisation
    np.testing.assert_allclose(freud_g, reference.rdf, rtol=1e-5)
    lammps_g = freud_g * n / (n - 1)                          # N_I N_J / (N_I N_J - D), D = N
    np.testing.assert_allclose(ours[:, 1], lammps_g, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(ours[:, 0], reference.bin_centers, rtol=1e-7)   # freud's are float32
    np.testing.assert_allclose(ours[:, 2], np.cumsum(counts) / n, rtol=1e-12)
    np.testing.assert_allclose(ours[:, 2], reference.n_r, rtol=1e-5)
    assert counts.sum() > 1000


def test_unlike_types_agree_with_freud_and_each_other():
    n, length, cutoff, nbin = 200, 6.0, 2.5, 25
    x, types = random_snapshot(3, n, length, ntypes=2)
    assert_clear_of_bin_edges(x, length, 3, cutoff, nbin)
    sim = snapshot(x, types, length, extra=f"compute r all rdf {nbin} 1 2 2 1 1 1 cutoff {cutoff}")
    ours = sim.computes["r"].array(sim)
    assert ours.shape == (nbin, 7)
    ones, twos = x[types == 1], x[types == 2]
    n1, n2 = len(ones), len(twos)
    assert 80 < n1 < 120
    fraction = shell_fraction(length, 3, cutoff, nbin)

    # I != J: disjoint sets, D = 0, both conventions agree
    cross = freud_rdf(length, 3, cutoff, nbin, twos, query_points=ones)
    np.testing.assert_allclose(cross.bin_counts / (n1 * n2 * fraction), cross.rdf, rtol=1e-5)
    np.testing.assert_allclose(ours[:, 1], cross.bin_counts / (n1 * n2 * fraction), rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(ours[:, 2], np.cumsum(cross.bin_counts) / n1, rtol=1e-12)
    # 2 around 1 and 1 around 2 count the same pairs; coordination numbers differ by N1/N2
    np.testing.assert_allclose(ours[:, 3], ours[:, 1], rtol=1e-12)
    np.testing.assert_allclose(ours[:, 4] * n2, ours[:, 2] * n1, rtol=1e-12)
    # 1 around 1: freud's finite_size mode is LAMMPS's normalisation when I = J
    like = freud.density.RDF(bins=nbin, r_max=cutoff, normalization_mode="finite_size")
    like.compute((freud.box.Box.cube(length), ones - length / 2))
    np.testing.assert_allclose(ours[:, 5], like.bin_counts / (n1 * (n1 - 1) * fraction), rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(ours[:, 5], like.rdf, rtol=1e-5)


@pytest.mark.parametrize("boundary, length, cutoff", [("p p p", 3.0, 4.5), ("p p f", 3.0, 2.0),
                                                      ("p p p", 5.0, 3.2)])
def test_coordination_counts_every_periodic_image_within_the_cutoff(boundary, length, cutoff):
    """Cutoffs beyond half the box (and beyond the box): each periodic image is a neighbor, as
    LAMMPS's ghosts are; minimum-image distances would miss them. A fixed face has no images."""
    n, nbin = 24, 9
    x, types = random_snapshot(3, n, length, ntypes=2)
    sim = snapshot(x, types, length, boundary=boundary,
                   extra=f"compute r all rdf {nbin} 1 2 * * cutoff {cutoff}")
    ours = sim.computes["r"].array(sim)
    upper = cutoff / nbin * np.arange(1, nbin + 1)
    periodic = [word == "p" for word in boundary.split()]
    index = np.arange(n)
    ones, twos = index[types == 1], index[types == 2]
    np.testing.assert_allclose(ours[:, 2], direct_coordination(x, length, periodic, 3, cutoff, upper, ones, twos),
                               rtol=1e-12)
    np.testing.assert_allclose(ours[:, 4], direct_coordination(x, length, periodic, 3, cutoff, upper, index, index),
                               rtol=1e-12)
    # a particle sees its own images too once the cutoff passes the box length (LAMMPS alike)
    if cutoff > length and boundary == "p p p":
        single = snapshot(x[:1], [1], length, extra=f"compute r all rdf {nbin} cutoff {cutoff}")
        coordination = single.computes["r"].array(single)[:, 2]
        assert coordination[-1] == 6 + 12 * (cutoff > length * math.sqrt(2))


def test_simple_cubic_lattice_has_6_then_18_neighbors():
    sim = make_box("mass 1 1\nlattice spacing x 1 y 1 z 1\ncreate_particle 1 box\n"
                   "compute r all rdf 10 1 1 cutoff 1.5", box="0 6 0 6 0 6")
    n = sim.nlocal
    assert n == 216
    ours = sim.computes["r"].array(sim)
    # r = 1 in bin 6 (0.90-1.05), r = sqrt(2) in bin 9 (1.35-1.5)
    assert ours[:, 2].tolist() == [0, 0, 0, 0, 0, 0, 6, 6, 6, 18]
    shell = 4.0 / 3.0 * math.pi * (np.arange(1, 11) ** 3 - np.arange(10) ** 3) * 0.15 ** 3
    expected = np.zeros(10)
    expected[6] = 6 * n / (n * (n - 1) * shell[6] / 216.0)
    expected[9] = 12 * n / (n * (n - 1) * shell[9] / 216.0)
    np.testing.assert_allclose(ours[:, 1], expected, rtol=1e-13)


def test_group_restricts_both_centres_and_neighbors():
    n, length, cutoff, nbin = 60, 5.0, 2.4, 8
    x, types = random_snapshot(7, n, length, ntypes=1)
    sim = snapshot(x, types, length, extra="region low block 0 2.5 INF INF INF INF\ngroup low region low\n"
                                           f"compute r low rdf {nbin} cutoff {cutoff}")
    inside = np.flatnonzero(x[:, 0] < 2.5)
    assert 15 < len(inside) < 45
    ours = sim.computes["r"].array(sim)
    upper = cutoff / nbin * np.arange(1, nbin + 1)
    np.testing.assert_allclose(ours[:, 2], direct_coordination(x, length, [True] * 3, 3, cutoff, upper,
                                                               inside, inside), rtol=1e-12)


def test_default_cutoff_is_the_pair_cutoff_and_the_keyword_goes_beyond_it():
    x, types = random_snapshot(5, 40, 5.0)
    sim = snapshot(x, types, 5.0, extra="pair_style dpd 1.0 1.2 4928\npair_coeff * * 25 4.5\n"
                                        "compute pair all rdf 12\ncompute far all rdf 12 1 1 cutoff 2.4")
    with pytest.raises(ScriptError, match=r"known once a run has set the pair style up \(run 0\)"):
        sim.compute_value("pair", (0, 0))
    sim.command("run 0")
    near = sim.computes["pair"].array(sim)
    far = sim.computes["far"].array(sim)
    assert near[0, 0] == pytest.approx(0.05, rel=1e-14)
    assert far[-1, 0] == pytest.approx(2.3, rel=1e-14)
    # the first half of the long histogram covers the pair cutoff in bins twice as wide
    np.testing.assert_allclose(far[:6, 2], near[1::2, 2], rtol=1e-12)


def test_values_are_read_through_references_and_follow_the_configuration():
    sim = make_box("mass 1 1\ncreate_particle 1 single 1 1 1\ncreate_particle 1 single 2.5 1 1\n"
                   "compute r all rdf 4 cutoff 2\nvariable n equal c_r[3][2]")
    assert sim.variables.value("n") == 1.0                 # one neighbor at 1.5 < 2
    assert sim.compute_value("r", (3, 0)) == 1.75
    sim.x[1, 0] = 3.5                                      # now 2.5 apart: no neighbor
    assert sim.variables.value("n") == 0.0


def _two_type_box():
    return make_box("mass * 1\ncreate_particle 1 single 1 1 1", box="0 5 0 5 0 5", ntypes=2)


@pytest.mark.parametrize("command, message", [
    ("compute r all rdf 10 1", "type pairs come as I J (got 1 words: 1)"),
    ("compute r all rdf 10 1 3 cutoff 2", "type 3 is out of range: the box has types 1 to 2"),
    ("compute r all rdf 10 1 0*2", "type 0*2 is out of range: the box has types 1 to 2"),
    ("compute r all rdf 0 cutoff 2", "nbin must be > 0 (got 0)"),
    ("compute r all rdf 10 1 1 cutoff -1", "cutoff must be > 0 (got -1)"),
    ("compute r all rdf 10 1 1 cutoff 2 1 1", "unknown keyword 1 (known: cutoff)"),
])
def test_bad_arguments_are_one_line(command, message):
    with pytest.raises(ScriptError) as error:
        _two_type_box().command(command)
    assert str(error.value) == f"<command>:1: compute: {message}"


def test_no_cutoff_without_a_pair_style_is_an_error_when_read():
    sim = _two_type_box()
    sim.command("compute r all rdf 10\nthermo_style custom step c_r[0][1]")
    with pytest.raises(ScriptError) as error:
        sim.command("run 0")
    assert str(error.value) == ("<command>:1: run: compute r (rdf) needs a pair style for its default "
                                "cutoff, or the keyword cutoff R")
