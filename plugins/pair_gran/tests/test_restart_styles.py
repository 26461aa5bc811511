"""Every granular pair style writes a restart file (``write_restart``, ``restart N``) that reads back
to the same trajectory: the contacts' springs go along. They stopped with "coefficients ... are a
StyleArgs, which is not a class of the pair style, so a restart cannot name it" only when the write
was reached, after the whole run."""

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import by_tag, given_again

SPHERES = """
atom_style sphere
units si
boundary p p f
region reg block -0.05 0.05 -0.05 0.05 0 0.1 units box
create_box 2 reg
create_atoms 1 single 0.0 0.0 0.05 units box
create_atoms 2 single 0.0059 0.0004 0.0501 units box
set atom * diameter 0.006 density 2500
velocity all set 0 0.05 0 units box
set atom 2 vy -0.05
neighbor 0.002 bin
timestep 1e-6
fix 1 all nve/sphere
"""
LAMMPS_LAW = "{style} 2e5 NULL 50 NULL 0.5 1"
LIGGGHTS_MATERIALS = """
fix m1 all property/global youngsModulus peratomtype 5.e6 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.9 0.9 0.9 0.9
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
"""
PAIRS = {
    "gran/hooke": f"pair_style {LAMMPS_LAW.format(style='gran/hooke')}\npair_coeff * *",
    "gran/hooke/history": f"pair_style {LAMMPS_LAW.format(style='gran/hooke/history')}\npair_coeff * *",
    "gran/hertz/history": f"pair_style {LAMMPS_LAW.format(style='gran/hertz/history')}\npair_coeff * *",
    "gran (LIGGGHTS)": LIGGGHTS_MATERIALS.replace("sphere", "granular")
    + "pair_style gran model hertz tangential history\npair_coeff * *",
}


@pytest.mark.parametrize("pair", sorted(PAIRS))
def test_a_granular_restart_resumes_the_same_trajectory(tmp_path, pair):
    setup = SPHERES + PAIRS[pair]
    if pair.endswith("(LIGGGHTS)"):
        setup = setup.replace("atom_style sphere", "atom_style granular")
    # two runs in one process, as reference: a run's setup forces take the full-step velocities,
    # so with velocity-dependent damping two runs differ from one run of their length (LAMMPS too)
    dialect = "liggghts" if pair.endswith("(LIGGGHTS)") else "lammps"
    straight = Simulation(screen=False, log=None, dialect=dialect)
    straight.command(setup + "\nrun 40\nrun 40")
    path = tmp_path / "gran.restart"
    before = Simulation(screen=False, log=None, dialect=dialect)
    before.command(setup + f"\nrun 40\nwrite_restart {path}")
    resumed = Simulation(screen=False, log=None, dialect=dialect)
    resumed.command(f"read_restart {path}\n{given_again(setup)}run 40")
    # the contact is held across the write: the spheres touch and slide
    assert np.linalg.norm(before.x[0] - before.x[1]) < 0.006
    for name in ("x", "v", "omega"):
        np.testing.assert_allclose(by_tag(resumed, getattr(resumed.particles, name)[: resumed.nlocal]),
                                   by_tag(straight, getattr(straight.particles, name)[: straight.nlocal]),
                                   rtol=1e-12, atol=1e-15)

