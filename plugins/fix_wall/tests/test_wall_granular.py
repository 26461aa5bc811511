"""fix wall/gran ... granular (LAMMPS's walls with pair granular's models): its refused lines (its
trajectories against LAMMPS's, data/wall_granular, are test_wall_gran.py's)."""

import pytest

from pdps_core.testing import assert_refused

SETUP = """\
units lj
atom_style sphere
boundary p p f
region box block 0 10 0 10 0 10
create_box 1 box
"""
MODEL = "hertz/material 1e5 0.5 0.3 tangential mindlin NULL 1.0 0.5"


@pytest.mark.parametrize("words, message", [
    (f"{MODEL}", "a wall style is needed after the model words: xplane|yplane|zplane LO HI or zcylinder RADIUS "
     "(got none); usage: fix ID GROUP wall/gran granular NORMAL coefficients [damping DAMPING] tangential "
     "TANGENTIAL coefficients [rolling ...] [twisting ...] [limit_damping] xplane|yplane|zplane LO HI | zcylinder "
     "RADIUS [wiggle dim A T] [shear dim V]"),
    (f"{MODEL} region box", "the region wall style is not built (fix wall/gran/region neither) (got region)"),
    ("jkr 1e5 0.5 0.3 1.0 tangential mindlin NULL 1.0 0.5 zplane 0.0 NULL",
     "jkr on a wall is not built: its contact would outlast touching the wall (got jkr)"),
    ("hertz/material 1e5 0.5 tangential mindlin NULL 1.0 0.5 zplane 0.0 NULL",
     "normal hertz/material needs 3 coefficient(s) (E eta_n0 nu) (got 2: 1e5 0.5)"),
    ("hertz/material 1e5 0.5 0.3 tangential mindlin NULL -1.0 0.5 zplane 0.0 NULL",
     "tangential mindlin: x_gamma_t must be >= 0 (got -1.0)"),
])
def test_bad_lines_are_refused_at_their_line(pdps_cli, words, message):
    assert_refused(pdps_cli(SETUP + f"fix w all wall/gran granular {words}\n"), 6, f"fix: {message}")


@pytest.mark.parametrize("words, message", [
    (f"granular {MODEL}", "missing keyword region; usage: fix ID GROUP wall/gran/region hooke|hooke/history|"
     "hertz/history Kn Kt gamma_n gamma_t xmu dampflag [limit_damping] region REGION-ID | granular NORMAL "
     "coefficients ... region REGION-ID"),
    (f"granular {MODEL} region box contacts", "unknown keyword contacts (known: region)"),
    (f"granular {MODEL} region ball", "region ball (sphere) has no granular wall surface (LAMMPS's "
     "surface_interior and surface_exterior are not built for it)"),
    ("granular jkr 1e5 0.5 0.3 1.0 tangential mindlin NULL 1.0 0.5 region box",
     "jkr on a wall is not built: its contact would outlast touching the wall (got jkr)"),
])
def test_bad_region_wall_lines_are_refused_at_their_line(pdps_cli, words, message):
    done = pdps_cli(SETUP + f"region ball sphere 5 5 5 3\nfix w all wall/gran/region {words}\n")
    assert_refused(done, 7, f"fix: {message}")
