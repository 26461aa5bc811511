"""The Python API drives the same code path as scripts."""

import numpy as np
import pytest

from pdps_core.api import ScriptError


def build_typed(sim):
    (sim.units_style("lj").boundary("p", "p", "p")
        .region("box", "block", 0, 4, 0, 4, 0, 4).create_box(1, "box").set_mass(1, 1.0))
    sim.command("lattice spacing x 1 y 1 z 1")
    sim.create_particle(1, "region", "box")
    sim.pair_style("dpd", 1.0, 1.0, 77).pair_coeff("*", "*", 25.0, 4.5)
    sim.velocity("all", "create", 1.0, 5, "gaussian").fix("1", "all", "nve").timestep(0.02)
    sim.run(20)
    return sim


SCRIPT = """
units lj
boundary p p p
region box block 0 4 0 4 0 4
create_box 1 box
mass 1 1.0
lattice spacing x 1 y 1 z 1
create_particle 1 region box
pair_style dpd 1.0 1.0 77
pair_coeff * * 25.0 4.5
velocity all create 1.0 5 gaussian
fix 1 all nve
timestep 0.02
run 20
"""


def test_typed_calls_and_script_give_the_same_trajectory(make_sim):
    typed = build_typed(make_sim())
    scripted = make_sim().command(SCRIPT)
    assert typed.nlocal == scripted.nlocal == 64
    np.testing.assert_array_equal(typed.x, scripted.x)
    np.testing.assert_array_equal(typed.v, scripted.v)


def test_numpy_views_write_through(make_sim):
    sim = make_sim().command(SCRIPT.replace("run 20", "run 0"))
    sim.v[:] = 0.0
    sim.v[0] = [1.0, 0.0, 0.0]
    sim.command("run 1")
    assert sim.x[0, 0] > 0.0 and np.isfinite(sim.f).all()
    assert sim.tag.dtype == np.int64 and sim.type.dtype == np.int32


def test_typed_call_errors_name_the_command(make_sim):
    sim = make_sim()
    with pytest.raises(ScriptError, match=r"^timestep: timestep must be > 0 \(got -1\)$"):
        sim.timestep(-1)
