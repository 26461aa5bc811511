"""A LIGGGHTS script is a LAMMPS-family script: where pdps's commands follow LAMMPS's rules in the
LAMMPS dialect (create_atoms random's generator and retries, group's static definitions), the
LIGGGHTS dialect follows them too, to the same particles. (displace_atoms random still draws with
pdps's generator in the LIGGGHTS dialect: plugins/pair_gran's heap test is tuned to that draw.)"""

import numpy as np

from pdps_core.api import Simulation

SCRIPT = """
units si
atom_style {style}
boundary p p p
region box block -1 1 -1 1 -1 1 units box
create_box 1 box
create_atoms 1 random 40 4711 NULL
region half block 0 1 INF INF INF INF units box
group right region half
"""


def read(dialect, style):
    sim = Simulation(screen=False, log=None)
    sim.command(f"dialect {dialect}")
    sim.command(SCRIPT.format(style=style))
    order = np.argsort(sim.tag)
    return sim.x[order], (sim.particles.mask[: sim.nlocal][order] & sim.groups.bit("right")) != 0


def test_liggghts_places_and_groups_as_lammps():
    x_lammps, right_lammps = read("lammps", "sphere")
    x_liggghts, right_liggghts = read("liggghts", "granular")
    assert len(x_lammps) == 40
    np.testing.assert_array_equal(x_liggghts, x_lammps)
    np.testing.assert_array_equal(right_liggghts, right_lammps)
    assert 0 < right_lammps.sum() < 40
