"""Lattice sites with LAMMPS's arithmetic: on LAMMPS's obstacle scene (a hex lattice at 0.7 in 2d), a
region sphere whose surface passes through lattice sites holds the sites LAMMPS finds in it, since
pdps rounds each site as LAMMPS's Lattice::lattice2box does. LAMMPS 22 Jul 2025 here: 35 particles in
the sphere, and atom 82 at the y printed below (%.17g), where a premultiplied cell gave
3.3368566547532956 and 37 particles."""

from pdps_core.api import Simulation

HEX = """dimension 2
boundary p s p
atom_style atomic
lattice hex 0.7
region box block 0 40 0 10 -0.25 0.25
create_box 3 box
create_atoms 1 box
mass * 1.0
region void2 sphere 20 7 0 3
group v2 region void2
"""


def test_sites_on_a_sphere_fall_where_lammps_puts_them():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(HEX)
    assert int(sim.groups.select(sim, "v2").sum()) == 35
    row = list(sim.tag).index(82)
    assert sim.x[row, 0] == 0.6421783626230032
    assert sim.x[row, 1] == 3.336856654753296
