"""A type's mass under particle_style sphere: honored in the PDPS dialect (PDPS's spheres have no
mass of their own), refused with one line in the LAMMPS and LIGGGHTS dialects (LAMMPS's rule: the
mass comes from diameter and density); never silently replaced."""

import math

import numpy as np
import pytest

from pdps_core.api import Simulation, observables

PDPS = """
particle_style sphere
region box block 0 10 0 10 0 10
create_box 2 box
"""


def test_pdps_type_mass_holds_for_spheres_created_before_and_after():
    sim = Simulation(screen=False, log=None)
    sim.command(PDPS + """
create_particle 1 single 2 2 2 diameter 1.0
create_particle 2 single 5 5 5 diameter 0.5 density 3.0
mass 1 2.5
create_particle 1 single 8 8 8 diameter 2.0
""")
    order = np.argsort(sim.tag)
    rmass = sim.particles.rmass[: sim.nlocal][order]
    assert rmass[0] == 2.5 and rmass[2] == 2.5
    # type 2 has no mass line: its density gives the mass
    assert rmass[1] == pytest.approx(3.0 * math.pi / 6.0 * 0.5 ** 3, rel=1e-15)
    # the dynamics see it: 1/2 m v^2 of the type-1 spheres
    sim.command("velocity all set 1.0 0 0\nrun 0")
    ke = observables.kinetic_energy(sim, "all")
    assert ke == pytest.approx(0.5 * (2.5 + 2.5 + rmass[1]) * 1.0, rel=1e-14)


def test_pdps_mass_and_density_for_one_type_is_refused(pdps_cli):
    done = pdps_cli(PDPS + "mass 1 2.5\ncreate_particle 1 single 2 2 2 density 3.0\n")
    assert done.returncode == 1
    assert done.stderr.strip() == ("ERROR: in.test:6: create_particle: type 1 has mass 2.5 (mass command), which "
                                   "a density would replace: give the mass or the density, not both")


@pytest.mark.parametrize("style, dialect", [("sphere", "LAMMPS"), ("granular", "LIGGGHTS")])
def test_lammps_and_liggghts_refuse_a_type_mass_for_spheres(pdps_cli, style, dialect):
    done = pdps_cli(f"units si\natom_style {style}\nregion r block 0 1 0 1 0 1\ncreate_box 1 r\nmass 1 2.0\n")
    assert done.returncode == 1
    assert done.stdout.splitlines()[0].startswith(f"read as {dialect}")
    assert done.stderr.strip() == ("ERROR: in.test:5: mass: cannot set a per-type mass for atom_style sphere "
                                   "(LAMMPS's rule): each particle's mass comes from its diameter and density "
                                   "(set type 1 density RHO)")


def test_lammps_point_particles_keep_their_type_mass():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("region r block 0 5 0 5 0 5\ncreate_box 1 r\ncreate_atoms 1 single 1 1 1\nmass 1 4.0\n"
                "velocity all set 1 0 0\nrun 0")
    assert observables.kinetic_energy(sim, "all") == pytest.approx(2.0, rel=1e-15)


@pytest.mark.parametrize("dialect", ["lammps", "pdps"])
def test_a_masses_section_for_spheres_is_refused(pdps_cli, tmp_path, dialect):
    """LAMMPS's read_data: "Cannot set mass for atom style sphere"; the data file's densities give
    the masses in every dialect (the mass command after read_data gives a PDPS type one mass)."""
    (tmp_path / "s.data").write_text("s\n\n1 atoms\n1 atom types\n\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n\n"
                                     "Masses\n\n1 3.0\n\nAtoms # sphere\n\n1 1 1.0 1.0 5 5 5\n")
    done = pdps_cli(f"dialect {dialect}\natom_style sphere\nread_data s.data\n")
    assert done.returncode == 1
    assert done.stderr.strip() == ("ERROR: in.test:3: read_data: s.data: Masses: cannot set a per-type mass for "
                                   "atom_style sphere (LAMMPS's rule): each particle's mass comes from its diameter "
                                   "and density columns")


# A sphere made by create_atoms (diameter 1, density 1) and by read_data (diameter 1, density 1),
# then `set atom 1 density 2500 diameter 0.5` and `set atom 1 diameter 0.25`: its mass after each,
# recorded with LAMMPS 22 Jul 2025 (atom_style sphere) and LIGGGHTS 3.8.0 (atom_style granular) on
# this machine kind. LAMMPS keeps the mass when the diameter changes and takes a sphere's volume in 2-d
# too; LIGGGHTS keeps the density and takes the disc's area in 2-d. pdps kept the mass in LIGGGHTS
# scripts (a bed 10^7 times too heavy) and took the disc's area in LAMMPS's 2-d ones.
SET_MASSES = {
    ("lammps", 3): (0.523598775598299, 1308.99693899575, 1308.99693899575, 0.523598775598299),
    ("lammps", 2): (0.523598775598299, 1308.99693899575, 1308.99693899575, 0.523598775598299),
    ("liggghts", 3): (0.523598775598299, 163.624617374468, 20.4530771718085, 0.523598775598299),
    ("liggghts", 2): (0.785398163397448, 490.873852123405, 122.718463030851, 0.785398163397448),
}


@pytest.mark.parametrize("dialect, dimension", sorted(SET_MASSES))
def test_set_diameter_and_density_give_the_reference_programs_masses(tmp_path, dialect, dimension):
    style = "granular" if dialect == "liggghts" else "sphere"
    z = "-0.5 0.5" if dimension == 2 else "0 10"
    (tmp_path / "data.sphere").write_text(f"""one sphere

1 atoms
1 atom types

0 10 xlo xhi
0 10 ylo yhi
{z} zlo zhi

Atoms # sphere

1 1 1.0 1.0 5 5 {0 if dimension == 2 else 5}
""")

    def mass(sim):
        return float(sim.particles.rmass[0])

    sim = Simulation(screen=False, log=None, dialect=dialect)
    sim.command(f"""
        units si
        dimension {dimension}
        atom_style {style}
        region reg block 0 10 0 10 {z}
        create_box 1 reg
        create_atoms 1 single 5 5 {0 if dimension == 2 else 5}
    """)
    masses = [mass(sim)]
    sim.command("set atom 1 density 2500 diameter 0.5")
    masses.append(mass(sim))
    sim.command("set atom 1 diameter 0.25")
    masses.append(mass(sim))
    reader = Simulation(screen=False, log=None, dialect=dialect)
    reader.command(f"units si\ndimension {dimension}\natom_style {style}\nread_data {tmp_path / 'data.sphere'}")
    masses.append(mass(reader))
    assert masses == pytest.approx(SET_MASSES[dialect, dimension], rel=1e-14)
