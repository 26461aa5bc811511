"""Each of LIGGGHTS's contact sub-models gives LIGGGHTS's trajectory: two spheres of two materials
meeting off-centre with spin (pair gran), and a sphere bouncing and rolling on a primitive wall (fix
wall/gran model), under every normal, tangential, rolling and cohesion model and setting pdps has;
every coordinate, velocity and spin equals LIGGGHTS 3.8.0's at the end (recorded by
benchmarks/liggghts_references/contacts.py into data/liggghts_submodels.json, with the scripts).
The mesh cases roll the sphere over fix mesh/surface (an STL of two triangles, flat and tilted)
across the triangles' shared edge, where it touches both at once.
The sjkr case fails if the cohesion lowers the tangential Coulomb limit without tangential_reduce
(pdps did so before 11-28 and parted from LIGGGHTS by 6e-4 m/s and 0.37 rad/s); the wall cases with
rolling friction if cdt's arm against a wall is R - delta/2 (it was until 11-28)."""

import json
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation

TABLE = json.loads((Path(__file__).parent / "data" / "liggghts_submodels.json").read_text())["cases"]


@pytest.mark.parametrize("case", sorted(TABLE))
def test_trajectory_as_liggghts(case, tmp_path, monkeypatch):
    # a mesh case's STL, by the name its script reads, in the run's folder
    monkeypatch.chdir(tmp_path)
    for name, text in TABLE[case].get("files", {}).items():
        (tmp_path / name).write_text(text)
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(TABLE[case]["script"])
    p = sim.particles
    order = np.argsort(p.tag[:p.nlocal])
    got = np.hstack([p.x[order], p.v[order], p.omega[order]])
    want = np.array(TABLE[case]["state"])
    scale = np.abs(want).max(axis=0)
    # relative to each column's largest value: round-off of thousands of steps summed in another order
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-9 * scale.max())
    error = np.abs(got - want) / np.maximum(scale, 1e-300)
    assert error.max() < 1e-8, (case, error.max(axis=0))
