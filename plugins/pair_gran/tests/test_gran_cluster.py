"""LIGGGHTS's forgetting of contacts: 36 cohesive spheres in the tutorials' box end where LIGGGHTS
3.8.0's do, which needs a contact that came apart kept until the next list build."""

from pathlib import Path

import numpy as np

from pdps_core.api import Simulation

CLUSTER = Path(__file__).parent / "data" / "liggghts_cohesive_cluster"


def test_cohesive_cluster_in_the_tutorials_box_as_liggghts():
    """36 cohesive spheres (sjkr, the cohesion tutorial's material) thrown onto the floor of the
    tutorials' cylinder (primitive walls), 1500 steps: every coordinate, velocity and spin equals
    LIGGGHTS's (data/liggghts_cohesive_cluster.ref, benchmarks/liggghts_references/gran_cluster.py).
    Spheres part and touch again before the next list build, and take up their old spring then, as
    in LIGGGHTS 3.8: pdps, which forgot it when they parted, left LIGGGHTS at step 747 and was
    6e-10 m, 7e-7 m/s and 9e-4 rad/s off at the end (now 7e-16 m, 1e-12 m/s, 1e-9 rad/s)."""
    sim = Simulation(screen=False, log=None)
    sim.file(str(CLUSTER.with_suffix(".in")))
    p = sim.particles
    order = np.argsort(p.tag[:p.nlocal])
    got = np.hstack([p.tag[order, None], p.x[order], p.v[order], p.omega[order]])
    want = np.loadtxt(CLUSTER.with_suffix(".ref"))
    assert len(want) == 36 and np.array_equal(got[:, 0], want[:, 0])
    # round-off grown over 1500 steps of many contacts (the measured differences above, 100x)
    np.testing.assert_allclose(got[:, 1:4], want[:, 1:4], rtol=0, atol=1e-13)
    np.testing.assert_allclose(got[:, 4:7], want[:, 4:7], rtol=0, atol=1e-10)
    np.testing.assert_allclose(got[:, 7:], want[:, 7:], rtol=0, atol=1e-7)
    assert np.abs(want[:, 7:]).max() > 10.0                 # the spheres spin from their contacts
