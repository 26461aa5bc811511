"""pair_style hybrid and hybrid/overlay write restart files that read back to the same trajectory:
each sub-style's coefficients and the type pairs' assignment go along (write_restart stopped with
"coefficients of types 1 1 are a tuple, which is not a class of the pair style")."""

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import by_tag, given_again, lj_fcc

ATOMS = "\n" + lj_fcc(3, 2) + """set type 1 type/fraction 2 0.5 4321
mass * 1.0
velocity all create 1.2 5511 loop geom
fix 1 all nve
"""
PAIRS = {
    "hybrid": "pair_style hybrid lj/cut 2.5 soft 1.12\npair_coeff * * lj/cut 1.0 1.0\n"
              "pair_coeff 1 2 soft 5.0\npair_coeff 2 2 lj/cut 0.5 1.1",
    "hybrid/overlay": "pair_style hybrid/overlay lj/cut 2.5 soft 1.12\npair_coeff * * lj/cut 1.0 1.0\n"
                      "pair_coeff 1 2 soft 5.0\npair_coeff 2 2 none\npair_coeff 2 2 soft 2.0",
}


@pytest.mark.parametrize("style", sorted(PAIRS))
def test_a_hybrid_restart_resumes_the_same_trajectory(tmp_path, style):
    setup = ATOMS + PAIRS[style]
    straight = Simulation(screen=False, log=None, dialect="lammps")
    straight.command(setup + "\nrun 30\nrun 30")
    path = tmp_path / "hybrid.restart"
    before = Simulation(screen=False, log=None, dialect="lammps")
    before.command(setup + f"\nrun 30\nwrite_restart {path}")
    resumed = Simulation(screen=False, log=None, dialect="lammps")
    resumed.command(f"read_restart {path}\n{given_again(setup)}run 30")
    assert resumed.pair.assigned == straight.pair.assigned
    for name in ("x", "v"):
        np.testing.assert_allclose(by_tag(resumed, getattr(resumed, name)), by_tag(straight, getattr(straight, name)),
                                   rtol=1e-12, atol=1e-12)


def test_a_damaged_assignment_is_refused_in_one_line():
    """A restart file's state assigning a type pair to a style the hybrid does not have is refused
    where it is read (read_restart hands the pair style its state, as here)."""
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(ATOMS + PAIRS["hybrid"] + "\nrun 0")
    state = sim.pair.state()
    state["assigned"][0][2] = ["morse"]
    with pytest.raises(ScriptError) as info:
        sim.pair.restore(state)
    assert str(info.value) == ("pair hybrid: the restart file assigns types 1 1 to morse, which is not one of "
                               "its sub-styles")
