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
