"""Compute temp/sphere: translational and rotational kinetic energy over LAMMPS's degrees of
freedom (6 a sphere in 3-d, 3 in 2-d; rotations alone with dof rotate, no dimension taken off), and
its extensive kinetic energy tensor. LAMMPS 22 Jul 2025 printed SPHERES_3D_LAMMPS and
SPHERES_2D_LAMMPS on this machine for SPHERES_3D and SPHERES_2D: granular gases with spins."""

import pytest

from pdps_core.api import Simulation
from pdps_core.testing import assert_prints_as_lammps, script_error

SPHERES_3D = """units lj
atom_style sphere
boundary p p f
comm_modify vel yes
region box block 0 6 0 6 0 6
create_box 1 box
create_atoms 1 random 40 12345 NULL overlap 1.0 maxtry 200
set type 1 diameter 0.9
set group all density 1.5
set atom 1*5 diameter 0.5
velocity all create 1.0 4928459 loop geom
set group all omega 0.3 -0.2 0.5
set atom 7 omega 1 2 3
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * * 
fix 1 all nve/sphere
fix 2 all wall/gran hooke 2000.0 NULL 50.0 NULL 0.5 1 zplane 0 6
fix 3 all gravity 1.0 vector 0 0 -1
compute 2 all temp/sphere
compute 3 all temp/sphere dof rotate
compute 4 all temp
timestep 0.001
thermo_style custom step temp c_2 c_3 c_2[1] c_2[4] c_3[3] c_3[6] c_4
thermo 200
run 1000
"""
SPHERES_3D_LAMMPS = [
    [0, 1, 0.49905344, 0.010630538, 1.1087315, 0.068310216, 0.020737236, 0.0028355799, 1],
    [200, 1.4445548, 0.7477234, 0.068312791, 1.0745943, 0.031761017, 0.027979212, 0.012982773, 1.4445548],
    [400, 1.3549047, 0.71268991, 0.086530514, 1.0468239, 0.024968229, 0.03303466, 0.017970559, 1.3549047],
    [600, 1.1557745, 0.62840158, 0.11421299, 0.79633376, 0.21460688, 0.053129964, 0.025473998, 1.1557745],
    [800, 0.8047034, 0.45553055, 0.11508702, 0.76119668, 0.24451706, 0.057364606, 0.030656762, 0.8047034],
    [1000, 0.80905019, 0.45704872, 0.11384729, 0.77110139, 0.21829326, 0.045683784, 0.015779905, 0.80905019],
]
SPHERES_2D = """units lj
dimension 2
atom_style sphere
comm_modify vel yes
region box block 0 8 0 8 -0.5 0.5
create_box 1 box
create_atoms 1 random 30 12345 NULL overlap 1.0 maxtry 200
set type 1 diameter 0.9
set group all density 1.5
velocity all create 1.0 4928459 loop geom
set group all omega 0.0 0.0 0.5
set atom 7 omega 0 0 3
pair_style gran/hooke 2000.0 NULL 50.0 NULL 0.5 1
pair_coeff * *
fix 1 all nve/sphere
fix 2 all enforce2d
compute 2 all temp/sphere
compute 3 all temp/sphere dof rotate
thermo_style custom step temp c_2 c_3 c_2[1] c_2[3] c_3[3]
thermo 250
run 1000
"""
SPHERES_2D_LAMMPS = [
    [0, 1, 0.66765484, 0.025120862, 0.91043675, 0.025120862, 0.025120862],
    [250, 0.29477071, 0.21254078, 0.053562917, 0.2661979, 0.053562917, 0.053562917],
    [500, 0.11368123, 0.092030785, 0.050173259, 0.11729581, 0.050173259, 0.050173259],
    [750, 0.064748556, 0.054646244, 0.035115108, 0.0620762, 0.035115108, 0.035115108],
    [1000, 0.039683951, 0.03772236, 0.033929951, 0.04147439, 0.033929951, 0.033929951],
]


@pytest.mark.parametrize("script, lammps", [(SPHERES_3D, SPHERES_3D_LAMMPS), (SPHERES_2D, SPHERES_2D_LAMMPS)],
                         ids=["3d", "2d"])
def test_temp_sphere_prints_lammps_numbers(tmp_path, script, lammps):
    assert_prints_as_lammps(tmp_path, script, lammps)


def test_temperature_is_the_formula_with_its_degrees_of_freedom():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SPHERES_2D.split("thermo_style")[0] + "run 0")
    p = sim.particles
    n = p.nlocal
    m, v, w, r = p.rmass[:n], p.v[:n], p.omega[:n], p.radius[:n]
    twice_ke = (m * (v * v).sum(axis=1)).sum() + (0.4 * m * r * r * (w * w).sum(axis=1)).sum()
    assert sim.compute_value("2", ()) == pytest.approx(twice_ke / (3 * n - 2), rel=1e-12)
    twice_rotational = (0.4 * m * r * r * w[:, 2] ** 2).sum()
    assert sim.compute_value("3", ()) == pytest.approx(twice_rotational / n, rel=1e-12)


SETUP = "dialect lammps\n" + SPHERES_2D.split("compute 2")[0]


@pytest.mark.parametrize("line, message", [
    ("compute 5 all temp/sphere bias 3",
     "<command>:1: compute: bias 3: compute temp/sphere with a velocity bias is not in pdps"),
    ("compute 5 all temp/sphere dof some",
     "<command>:1: compute: dof must be one of 'all' or 'rotate' (got some)"),
])
def test_bad_temp_sphere_is_refused(line, message):
    assert str(script_error(SETUP, line)) == message


def test_temp_sphere_needs_spheres():
    assert str(script_error("dialect lammps\nregion box block 0 4 0 4 0 4\ncreate_box 1 box",
                            "compute 5 all temp/sphere")) == (
        "<command>:1: compute: compute temp/sphere needs particle_style sphere (radius, rmass, omega)")
