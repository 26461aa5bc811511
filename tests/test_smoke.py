"""The PDPS manual's water example, end to end."""

import numpy as np


def test_water_example_relaxes_to_unit_temperature(make_sim):
    import pathlib
    script = pathlib.Path(__file__).parents[1] / "examples" / "water.in"
    sim = make_sim()
    temps = []
    sim.file(str(script))
    # 4000 particles on the 20x20x10 lattice of the manual
    assert sim.nlocal == 4000
    assert 0.9 <= sim.compute_value("1") <= 1.1
    assert np.isfinite(sim.x).all()
