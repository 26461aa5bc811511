"""compute cna/atom: perfect crystals and an icosahedron classified, against a brute-force CNA of
a perturbed crystal, groups, LIGGGHTS's limits (cutoff 0, too many neighbors), warnings, errors and
the same classes on 1 and 2 ranks."""

import itertools

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import NoForcePair, build, make_box, register_styles, run_ranks, write_data

UNKNOWN, FCC, HCP, BCC, ICOS, OTHER = range(6)


def crystal(style, cells, cutoff, setup=""):
    """A periodic box of ``cells`` unit cells a side of the lattice at reduced density 0.8442, and
    compute c all cna/atom ``cutoff`` after run 0; the classes in id order."""
    sim = Simulation(screen=False, log=None)
    sim.command(f"units lj\natom_style atomic\nlattice {style} 0.8442\n"
                f"region box block 0 {cells} 0 {cells} 0 {cells} units lattice\ncreate_box 1 box\n"
                f"create_atoms 1 box\nmass 1 1.0\n{setup}compute c all cna/atom {cutoff}\nrun 0")
    return sim, sim.computes["c"].peratom(sim)[np.argsort(sim.tag)]


def hcp_positions(nx, ny, nz, r0=1.0):
    """An ideal hcp crystal of nearest distance r0: orthogonal cells a x sqrt(3) a x sqrt(8/3) a of
    4 particles, nx x ny x nz of them; positions and box."""
    a = r0
    cell = np.array([a, np.sqrt(3.0) * a, np.sqrt(8.0 / 3.0) * a])
    basis = np.array([[0.0, 0.0, 0.0], [0.5, 0.5, 0.0], [0.5, 5.0 / 6.0, 0.5], [0.0, 1.0 / 3.0, 0.5]])
    x = [(np.array(ijk) + b) * cell for ijk in itertools.product(range(nx), range(ny), range(nz)) for b in basis]
    return np.array(x), cell * (nx, ny, nz)


def icosahedron(r=1.0, centre=(5.0, 5.0, 5.0)):
    """A centre and the 12 vertices of an icosahedron at distance r from it (edge 1.0515 r)."""
    phi = (1.0 + np.sqrt(5.0)) / 2.0
    vertices = []
    for s1, s2 in itertools.product((-1.0, 1.0), repeat=2):
        vertices += [(0.0, s1, s2 * phi), (s1, s2 * phi, 0.0), (s2 * phi, 0.0, s1)]
    vertices = np.array(vertices) * r / np.sqrt(1.0 + phi ** 2)
    return np.vstack([[0.0, 0.0, 0.0], vertices]) + centre


def brute_force_cna(x, box, rc):
    """CNA by its definition over minimum images (no neighbor caps: for scenes with at most 16 near
    neighbors and 8 common ones)."""
    n = len(x)
    d = x[:, None, :] - x[None, :, :]
    d -= box * np.round(d / box)
    close = (np.einsum("ijk,ijk->ij", d, d) < rc * rc) & ~np.eye(n, dtype=bool)
    out = np.full(n, OTHER)
    for i in range(n):
        near = np.flatnonzero(close[i])
        if len(near) not in (12, 14):
            continue
        signatures = []
        for j in near:
            common = near[close[j, near]]
            bonds = close[np.ix_(common, common)].sum(axis=1)
            signatures.append((len(common), bonds.sum() // 2, bonds.max(initial=0), bonds.min(initial=8)))
        count = {s: signatures.count(s) for s in set(signatures)}
        if len(near) == 12:
            if count.get((4, 2, 1, 1)) == 12:
                out[i] = FCC
            elif count.get((4, 2, 1, 1)) == 6 and count.get((4, 2, 2, 0)) == 6:
                out[i] = HCP
            elif count.get((5, 5, 2, 2)) == 12:
                out[i] = ICOS
        elif count.get((4, 4, 2, 2)) == 6 and count.get((6, 6, 2, 2)) == 8:
            out[i] = BCC
    return out


def test_perfect_fcc_and_bcc_lattices():
    sim, fcc = crystal("fcc", 4, 1.3)          # a = 1.680: shells at 1.188, 1.680
    assert len(fcc) == 256 and np.all(fcc == FCC)
    assert sim.warnings == []
    _, bcc = crystal("bcc", 4, 1.6)            # a = 1.333: shells at 1.154, 1.333, 1.885
    assert len(bcc) == 128 and np.all(bcc == BCC)
    # bcc's first shell only: 8 near neighbors, OTHER (only 12 or 14 are analysed)
    _, first = crystal("bcc", 4, 1.25)
    assert np.all(first == OTHER)


def test_perfect_hcp(tmp_path):
    x, box = hcp_positions(4, 3, 3)
    sim = build(tmp_path, x, hi=box, setup="compute c all cna/atom 1.2\nrun 0")
    assert len(x) == 144
    assert np.all(sim.computes["c"].peratom(sim) == HCP)


def test_icosahedron_centre(tmp_path):
    x = icosahedron()
    sim = build(tmp_path, x, hi=(10.0, 10.0, 10.0), setup="compute c all cna/atom 1.2\nrun 0")
    values = sim.computes["c"].peratom(sim)[np.argsort(sim.tag)]
    assert values[0] == ICOS
    assert np.all(values[1:] == OTHER)          # a vertex has 6 near neighbors


def test_perturbed_crystals_as_brute_force(tmp_path):
    rng = np.random.default_rng(11)
    x, box = hcp_positions(4, 3, 3)
    x += rng.normal(0.0, 0.06, x.shape)
    x %= box
    sim = build(tmp_path, x, hi=box, setup="compute c all cna/atom 1.2\nrun 0")
    values = sim.computes["c"].peratom(sim)[np.argsort(sim.tag)]
    expected = brute_force_cna(x, box, 1.2)
    assert values == pytest.approx(expected, abs=0)
    assert 10 < np.count_nonzero(expected == HCP) < len(x) - 10     # some of each
    assert np.count_nonzero(expected == OTHER) > 10


def test_thermal_fcc_has_fcc_and_other():
    sim = Simulation(screen=False, log=None)
    sim.command("units lj\natom_style atomic\nlattice fcc 0.8442\nregion box block 0 4 0 4 0 4 units lattice\n"
                "create_box 1 box\ncreate_atoms 1 box\nmass 1 1.0\ndisplace_atoms all random 0.08 0.08 0.08 5\n"
                "compute c all cna/atom 1.45\nrun 0")
    order = np.argsort(sim.tag)
    values = sim.computes["c"].peratom(sim)[order]
    expected = brute_force_cna(sim.x[order], sim.box.length, 1.45)
    assert values == pytest.approx(expected, abs=0)
    assert 0 < np.count_nonzero(values == FCC) < len(values)
    assert set(np.unique(values)) <= {FCC, HCP, OTHER}


def test_particles_outside_the_group_are_unknown():
    sim, values = crystal("fcc", 4, 1.3, setup="region low block INF INF INF INF 0 1.9 units lattice\n"
                                                "group low region low\ncompute cl low cna/atom 1.3\n")
    order = np.argsort(sim.tag)
    low = sim.computes["cl"].peratom(sim)[order]
    inside = sim.x[order][:, 2] < 1.9 * sim.lattice.spacing[2]
    assert 0 < inside.sum() < len(inside)
    assert np.all(low[inside] == FCC)            # their neighbors outside the group still count
    assert np.all(low[~inside] == UNKNOWN)


@pytest.mark.parametrize("cutoff", [0, 0.5, 1.0])
def test_cutoff_below_the_first_shell_gives_other(cutoff):
    sim, values = crystal("fcc", 3, cutoff)
    assert np.all(values == OTHER)
    assert sim.warnings == []


def test_too_many_neighbors_other_and_warned():
    # fcc at 1.8: 12 + 6 = 18 near neighbors, more than LIGGGHTS's 16
    sim, values = crystal("fcc", 3, 1.8)
    assert np.all(values == OTHER)
    assert sim.warnings == ["Too many neighbors in CNA for 108 atoms"]
    # read again on the same step: computed and warned once, as LIGGGHTS invokes a compute once a step
    sim.computes["c"].peratom(sim)
    assert sim.warnings == ["Too many neighbors in CNA for 108 atoms"]


def test_warnings_of_liggghts(tmp_path):
    register_styles(NoForcePair)
    sim = build(tmp_path, [[1.0, 1.0, 1.0], [2.0, 1.0, 1.0]], setup="""
        pair_style test/no_force
        pair_coeff * *
        neighbor 0.3 bin
        compute a all cna/atom 0.6
        compute b all cna/atom 0.7
        run 0
    """)
    # LIGGGHTS's test: 2 cutoff > pair cutoff (1.0) + skin (0.3)
    assert sim.warnings.count("Compute cna/atom cutoff may be too large to find ghost atom neighbors") == 1
    assert sim.warnings.count("More than one compute cna/atom defined") == 2
    quiet = build(tmp_path, [[1.0, 1.0, 1.0]], setup="""
        pair_style test/no_force
        pair_coeff * *
        compute a all cna/atom 0.65
        run 0
    """)
    assert quiet.warnings == []


def test_read_before_a_run_is_a_clear_error():
    sim = build_one()
    with pytest.raises(ScriptError, match=r"compute c \(cna/atom\) is read before any run: run 0 first"):
        sim.computes["c"].peratom(sim)


def build_one():
    sim = Simulation(screen=False, log=None)
    sim.command("units lj\natom_style atomic\nlattice sc 1.0\nregion box block 0 2 0 2 0 2 units lattice\n"
                "create_box 1 box\ncreate_atoms 1 box\nmass 1 1.0\ncompute c all cna/atom 1.0")
    return sim


@pytest.mark.parametrize("words, message", [
    ("", "missing argument cutoff; usage: compute ID GROUP cna/atom RC"),
    ("-1", "cutoff must be >= 0 (got -1)"),
    ("-0.5", "cutoff must be >= 0 (got -0.5)"),
    ("cutoff", "cutoff must be a finite number (got cutoff)"),
    ("inf", "cutoff must be a finite number (got inf)"),
    ("1.3 fcc", "too many arguments: unexpected 'fcc'; usage: compute ID GROUP cna/atom RC"),
])
def test_bad_arguments(words, message):
    sim = make_box()
    with pytest.raises(ScriptError) as caught:
        sim.command(f"compute c all cna/atom {words}".rstrip())
    assert str(caught.value) == f"<command>:1: compute: {message}"


@pytest.mark.parametrize("ranks", [1, 2])
def test_same_classes_on_1_and_2_ranks(tmp_path, ranks):
    rng = np.random.default_rng(3)
    x, box = hcp_positions(6, 4, 4)
    x = (x + rng.normal(0.0, 0.06, x.shape)) % box
    write_data(tmp_path / "data.hcp", (0, 0, 0), box, x)
    run_ranks("""
        read_data data.hcp
        group some id <= 200
        compute c all cna/atom 1.2
        compute s some cna/atom 1.2
        dump d all custom 1 cna.txt id c_c c_s
        run 0
    """, ranks, tmp_path)
    rows = np.loadtxt(tmp_path / "cna.txt", skiprows=9)
    rows = rows[np.argsort(rows[:, 0])]
    expected = brute_force_cna(x, box, 1.2)
    assert rows[:, 1] == pytest.approx(expected, abs=0)
    assert rows[:, 2] == pytest.approx(np.where(np.arange(1, len(x) + 1) <= 200, expected, UNKNOWN), abs=0)
    assert 0 < np.count_nonzero(expected == HCP) < len(x)
