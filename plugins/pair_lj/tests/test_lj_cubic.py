"""Pair style lj/cubic: LJ to the inflection point, then the cubic to zero at r_m, against its formula
(continuity of energy and force at both radii) and finite differences, and LAMMPS's thermo:
LAMMPS 22 Jul 2025 printed LJ_CUBIC_LAMMPS on this machine for LJ_CUBIC (two types, mixed
geometrically and then arithmetically)."""

import pytest

from pdps_core.testing import assert_prints_as_lammps, assert_force_is_minus_gradient, script_error, two_type_cluster

LJ_CUBIC = """units metal
atom_style atomic
lattice fcc 5.358
region box block 0 4 0 4 0 4
create_box 2 box
create_atoms 1 box
region half block 0 2 INF INF INF INF
set region half type 2
mass * 39.903
velocity all create 60 2357 mom yes dist gaussian
pair_style lj/cubic
pair_coeff 1 1 0.0102701 3.42
pair_coeff 2 2 0.008 3.6
neighbor 1 bin
timestep 0.002
fix nve all nve
thermo_style custom step temp pe etotal press
thermo 100
run 500
pair_modify mix arithmetic
run 200
"""
LJ_CUBIC_LAMMPS = [
    [0, 60, -13.238058, -11.260377, 3082.4134],
    [100, 26.392089, -12.13022, -11.260301, 3936.9447],
    [200, 35.164869, -12.419373, -11.260292, 3819.9663],
    [300, 26.697496, -12.14026, -11.260274, 4042.1088],
    [400, 34.66438, -12.402875, -11.260291, 3806.8536],
    [500, 35.983828, -12.446374, -11.260299, 3709.2143],
    [500, 35.983828, -12.44363, -11.257555, 3715.1407],
    [600, 34.580691, -12.397394, -11.257568, 3701.7964],
    [700, 34.060869, -12.380254, -11.257562, 3749.5536],
]


def test_lj_cubic_prints_lammps_thermo(tmp_path):
    assert_prints_as_lammps(tmp_path, LJ_CUBIC, LJ_CUBIC_LAMMPS)


def _law(r, epsilon=1.0, sigma=1.0):
    from pdps_pair_lj.lj_cubic import lj_cubic_law, PairLJCubic
    style = PairLJCubic.__new__(PairLJCubic)
    style.resolved = {(1, 1): PairLJCubic.Coeff(epsilon=epsilon, sigma=sigma)}
    cutoff, values = style.init_one(1, 1)
    fpair, energy = lj_cubic_law(r * r, r, 0.0, 0.0, values, 0, 0, (), ())
    return fpair * r, energy, cutoff


def test_energy_and_force_are_continuous_and_vanish_at_the_cutoff():
    sigma = 1.3
    inner = (26.0 / 7.0) ** (1 / 6) * sigma
    f_in, e_in, cutoff = _law(inner * (1 - 1e-12), sigma=sigma)
    f_out, e_out, _ = _law(inner * (1 + 1e-12), sigma=sigma)
    assert cutoff == pytest.approx(67.0 / 48.0 * inner, rel=1e-15)
    assert e_in == pytest.approx(e_out, rel=1e-10) and f_in == pytest.approx(f_out, rel=1e-10)
    lj = 4 * ((sigma / inner) ** 12 - (sigma / inner) ** 6)
    assert e_in == pytest.approx(lj, rel=1e-10)
    f_end, e_end, _ = _law(cutoff * (1 - 1e-9), sigma=sigma)
    assert abs(e_end) < 1e-15 and abs(f_end) < 1e-7


def test_forces_are_minus_the_energy_gradient(tmp_path):
    sim = two_type_cluster(tmp_path, "pair_style lj/cubic\npair_coeff 1 1 1.0 1.0\npair_coeff 2 2 0.8 1.2")
    assert_force_is_minus_gradient(sim, rel=1e-6, abs=1e-7, largest=0.5)


def test_lj_cubic_takes_two_coefficients():
    setup = "dialect lammps\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\npair_style lj/cubic"
    assert str(script_error(setup, "pair_coeff * * 1.0 1.0 2.5")).startswith(
        "<command>:1: pair_coeff: too many arguments: unexpected '2.5'")
