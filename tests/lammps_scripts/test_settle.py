"""The granular settling scene of the bench (benchmarks/scenes/liggghts/in.settle, pdps's own file in
LIGGGHTS's syntax, run unmodified) against LIGGGHTS 3.8.0's numbers for the same file and data: 20,000
Hertz beads with friction and rolling friction colliding from their jittered lattice under gravity,
between a floor and four side walls. LIGGGHTS printed (``thermo 100``, 300 steps; its kinetic energy
is the translational one, J):

    Step  Atoms  KinEng        rke
     300  20000  0.0041225099  0.00014045951

pdps printed 0.0041225255 and 0.00014046888: the kinetic energy is held to 2e-5 of LIGGGHTS's, the
rotational, which the collisions alone make, to 1e-3. The data file's beads neither overlap each
other nor the box's walls.
"""

import itertools
from pathlib import Path

import numpy as np
import pytest

from pdps_core.testing import bench_data

SCENE = Path(__file__).parents[2] / "benchmarks" / "scenes" / "liggghts" / "in.settle"
LIGGGHTS_KE, LIGGGHTS_RKE = 0.0041225099, 0.00014045951


def test_the_settling_beads_start_apart_inside_the_box(tmp_path):
    """Each bead within 0.04 mm (per axis) of its own site of the 50 x 50 x 8 lattice of spacing
    3.7 mm, so only beads of neighbouring sites can touch (farther ones are 7.3 mm apart, the widest
    pair 3.6 mm across): every such pair has a gap, and every bead is inside the walls."""
    lines = bench_data("settle", tmp_path / "settle.data").read_text().splitlines()
    start = lines.index("Atoms # sphere") + 2
    atoms = np.array([line.split() for line in lines[start:start + 20000]], dtype=float)
    assert len(atoms) == 20000 and lines[start + 20000] == ""
    radius, x = atoms[:, 2] / 2, atoms[:, 4:7]
    assert 0.0015 <= radius.min() and radius.max() <= 0.0018
    assert (x - radius[:, None] > 0).all() and (x[:, :2] + radius[:, None] < 0.185).all()
    offset = (x - [0.00185, 0.00185, 0.00195]) / 0.0037
    site = np.rint(offset).astype(int)
    assert np.abs(offset - site).max() * 0.0037 <= 0.00004 + 1e-12
    grid = np.full((50, 50, 8), -1)
    grid[tuple(site.T)] = np.arange(20000)
    assert (grid >= 0).all()
    gaps = []
    for shift in itertools.product((-1, 0, 1), repeat=3):
        if shift == (0, 0, 0):
            continue
        lo = [max(0, -s) for s in shift]
        hi = [n - max(0, s) for n, s in zip(grid.shape, shift)]
        a = grid[lo[0]:hi[0], lo[1]:hi[1], lo[2]:hi[2]].ravel()
        b = grid[lo[0] + shift[0]:hi[0] + shift[0], lo[1] + shift[1]:hi[1] + shift[1],
                 lo[2] + shift[2]:hi[2] + shift[2]].ravel()
        gaps.append(np.linalg.norm(x[a] - x[b], axis=1) - radius[a] - radius[b])
    assert np.concatenate(gaps).min() > 0


def test_the_settling_scene_runs_as_in_liggghts(pdps_cli, tmp_path):
    bench_data("settle", tmp_path / "settle.data")
    done = pdps_cli(SCENE.read_text(), "-var", "scenes", ".", "-var", "nsteps", "300", "-log", "none",
                    "--no-progress", name="in.settle")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    start = next(k for k, line in enumerate(lines) if line.split()[:1] == ["Step"])
    step, atoms, ke, rke = lines[start + 2].split()
    assert (step, atoms) == ("300", "20000")
    assert float(ke) == pytest.approx(LIGGGHTS_KE, rel=2e-5)
    assert float(rke) == pytest.approx(LIGGGHTS_RKE, rel=1e-3)
