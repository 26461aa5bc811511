"""Granular clumps under fix rigid/small and rigid/nve/small against LAMMPS (22 Jul 2025): spheres with
molecule ids (atom_style hybrid sphere molecular), a resting dimer and a spinning, falling triangle
between wall/gran planes, touching through pair gran/hooke/history. Every sphere's position, velocity
and angular velocity every 500 steps over 3000, recorded by
benchmarks/lammps_references/rigid_small_clumps.py. The contacts take each clump's mass for their
effective mass, as LAMMPS's mass_rigid does (with the spheres' own masses the triangle's spin parts from
LAMMPS's by 0.02 in the first step); the same run on 2 ranks."""

import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.testing import run_ranks

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from rigid_small_clumps import DATA as CLUMPS, SCRIPT, STYLES  # noqa: E402

REFERENCE = Path(__file__).with_name("data") / "rigid_small_clumps.txt"


def lammps(style):
    blocks, name = {}, None
    for line in REFERENCE.read_text().splitlines():
        if line.startswith("# "):
            name = line[2:]
            blocks[name] = []
        else:
            blocks[name].append([float(w) for w in line.split()])
    return np.array(blocks[style])


def run(tmp_path, style, ranks):
    (tmp_path / "clumps.data").write_text(CLUMPS)
    done = run_ranks(SCRIPT.format(style=style), ranks, tmp_path)
    assert done.returncode == 0, done.stderr
    rows = []
    for frame in (tmp_path / "clumps.dump").read_text().split("ITEM: TIMESTEP")[1:]:
        lines = frame.strip().splitlines()
        rows += [[float(lines[0])] + [float(w) for w in line.split()] for line in lines[8:]]
    return np.array(rows)


@pytest.mark.parametrize("style", STYLES)
def test_clumps_move_as_in_lammps(tmp_path, style):
    ours, theirs = run(tmp_path, style, 1), lammps(style)
    assert ours.shape == theirs.shape == (7 * 5, 11)
    difference = np.abs(ours - theirs).max()
    print(f"{style}: largest difference from LAMMPS over 3000 steps {difference:.1e}")
    # the triangle lands on the dimer and both on the floor (the dimer's z moves): contacts happened
    assert np.ptp(theirs[theirs[:, 1] == 1, 4]) > 1e-3
    assert difference < 1e-9


def test_two_ranks_move_the_clumps_as_one(tmp_path):
    one = run(tmp_path, "rigid/small", 1)
    two = run(tmp_path, "rigid/small", 2)
    assert np.abs(one - two).max() < 1e-12
