"""Bad pair_style and pair_coeff lines for the gran styles: one located line, exit code 1."""

import pytest

from pdps_core.testing import assert_refused

SETUP = """\
units lj
atom_style sphere
region box block 0 10 0 10 0 10
create_box 1 box
"""
USAGE = "pair_style gran/hooke/history Kn Kt gamma_n gamma_t xmu dampflag [limit_damping]"


@pytest.mark.parametrize("line, message", [
    ("pair_style gran/hooke/history -1 NULL 50 NULL 0.5 1", "Kn must be >= 0 (got -1)"),
    ("pair_style gran/hooke/history 1e5 -2 50 NULL 0.5 1", "Kt must be >= 0 (got -2)"),
    ("pair_style gran/hooke/history 1e5 NULL 50 NULL 0.5 3", "dampflag must be <= 1 (got 3)"),
    ("pair_style gran/hooke/history 1e5 NULL 50 NULL 0.5 yes", "dampflag must be an integer (got yes)"),
    ("pair_style gran/hooke/history 1e5 NULL 50 NULL -0.5 1", "xmu must be >= 0 (got -0.5)"),
    ("pair_style gran/hooke/history 1e5 NULL 50 NULL 0.5", f"missing argument dampflag; usage: {USAGE}"),
    ("pair_style gran/hooke/history 1e5 NULL 50 NULL 0.5 1 limit", "limit_damping must be one of "
     "'limit_damping' (got limit)"),
    ("pair_style gran/hooke/history 1e5 NULL nan NULL 0.5 1", "gamma_n must be a finite number (got nan)"),
])
def test_bad_pair_style_lines(pdps_cli, line, message):
    assert_refused(pdps_cli(SETUP + line + "\n"), 5, f"pair_style: {message}")


def test_pair_coeff_takes_no_coefficients(pdps_cli):
    done = pdps_cli(SETUP + "pair_style gran/hooke 1e5 NULL 50 NULL 0.5 1\npair_coeff * * 1.0\n")
    assert done.returncode == 1
    assert done.stderr.strip() == ("ERROR: in.test:6: pair_coeff: too many arguments: unexpected '1.0'; "
                                   "usage: (no coefficients: pair_coeff * *)")


def test_point_particles_are_refused(pdps_cli):
    done = pdps_cli("units lj\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\n"
                    "create_atoms 1 single 5 5 5\nmass 1 1.0\n"
                    "pair_style gran/hooke 1e5 NULL 50 NULL 0.5 1\npair_coeff * *\nrun 0\n")
    assert done.returncode == 1
    assert done.stderr.strip() == ("ERROR: in.test:8: run: pair gran/hooke needs atom_style sphere "
                                   "(per-particle radius, mass and rotation)")


LIGGGHTS_SETUP = """\
atom_style granular
units {units}
{command}region box block 0 1 0 1 0 1 units box
create_box 1 box
create_atoms 1 single 0.5 0.5 0.5 units box
set atom 1 diameter 0.01 density 2500
fix m1 all property/global youngsModulus peratomtype {young}
fix m2 all property/global poissonsRatio peratomtype 0.3
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.5
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
run 0
"""


@pytest.mark.parametrize("units, young, message", [
    ("si", "4.9e6", "must be >= 5e+06 in si units (got 4.9e+06), as LIGGGHTS requires; give soft_particles yes to allow softer particles"),
    ("cgs", "4.9e7", "must be >= 5e+07 in cgs units (got 4.9e+07), as LIGGGHTS requires; give soft_particles yes to allow softer particles"),
    ("si", "1.1e9", "must be <= 1e+09 in si units (got 1.1e+09), as LIGGGHTS requires; give hard_particles yes to allow harder particles"),
    ("cgs", "2e10", "must be <= 1e+10 in cgs units (got 2e+10), as LIGGGHTS requires; give hard_particles yes to allow harder particles"),
])
def test_liggghts_bounds_on_youngs_modulus(pdps_cli, units, young, message):
    """LIGGGHTS 3.8.0 refuses a youngsModulus outside 5e6..1e9 in si units (5e7..1e10 in cgs) unless
    soft_particles yes or hard_particles yes lifts the bound (its global_properties.cpp; the
    hydrogel tutorials give soft_particles yes for their 23.3 kPa gel)."""
    done = pdps_cli(LIGGGHTS_SETUP.format(units=units, command="", young=young))
    assert_refused(done, 13, f"run: youngsModulus (fix m1) {message}")
    lifted = "soft_particles yes\n" if "soft" in message else "hard_particles yes\n"
    done = pdps_cli(LIGGGHTS_SETUP.format(units=units, command=lifted, young=young))
    assert done.returncode == 0, done.stderr
    done = pdps_cli(LIGGGHTS_SETUP.format(units="si", command="soft_particles maybe\n", young="5e6"))
    assert_refused(done, 3, "soft_particles: soft_particles must be one of yes, no (got maybe)")
