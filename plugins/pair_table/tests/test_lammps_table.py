"""pair_style table gives LAMMPS's thermo, step for step, on a 200-particle two-type fluid with
Lennard-Jones and Morse tables in each file form (data/pair_table.txt, recorded with LAMMPS by
benchmarks/lammps_references/pair_table.py); its forces are minus the gradient of its energy; bad
table files get one line naming the file, the line and the fault.

The thermo against LAMMPS's (with 2 ranks and restarts for the cases marked so) is checked by
tests/test_recorded_thermo.py from data/pair_table.cases.json; this file holds the rest."""

import math
import shutil
from pathlib import Path

import pytest

from pdps_core.api import ScriptError, Simulation, SimulationError
from pdps_core.testing import assert_force_is_minus_gradient, build, forces_by_tag, script_error, two_type_cluster

DATA = Path(__file__).parent / "data"


def _tables(tmp_path):
    shutil.copy(DATA / "pots.table", tmp_path / "pots.table")
    return tmp_path / "pots.table"


def test_spline_forces_are_minus_the_gradient(tmp_path, monkeypatch):
    _tables(tmp_path)
    monkeypatch.chdir(tmp_path)
    sim = two_type_cluster(tmp_path, "pair_style table spline 2000\npair_coeff 1 1 pots.table LJ_R\n"
                                     "pair_coeff 2 2 pots.table MORSE_FP\npair_coeff 1 2 pots.table LJ_RSQ 2.4")
    # energy and force are splined separately (LAMMPS's tables): they agree to the splines' accuracy
    assert_force_is_minus_gradient(sim, rel=1e-5, abs=1e-5, largest=0.1)


def test_linear_forces_interpolate_the_tabulated_force(tmp_path, monkeypatch):
    """A linear table's energy is piecewise linear in r^2, so its gradient is not the force; the force
    is the tabulated one, interpolated: at table points it is the file's value exactly."""
    _tables(tmp_path)
    monkeypatch.chdir(tmp_path)
    rsq = 0.7 ** 2 + (2.5 ** 2 - 0.7 ** 2) * 700 / 1199      # a point of the RSQ table
    r = math.sqrt(rsq)
    sim = build(tmp_path, [[5.0, 5.0, 5.0], [5.0 + r, 5.0, 5.0]],
                setup="pair_style table linear 1200\npair_coeff * * pots.table LJ_RSQ\nrun 0")
    s6 = rsq ** -3
    assert forces_by_tag(sim)[1, 0] == pytest.approx(24.0 * (2.0 * s6 * s6 - s6) / r, rel=1e-12)
    assert sim.pe == pytest.approx(4.0 * (s6 * s6 - s6), rel=1e-12)


def test_one_pair_equals_the_tabulated_law(tmp_path, monkeypatch):
    _tables(tmp_path)
    monkeypatch.chdir(tmp_path)
    r = 1.234
    sim = build(tmp_path, [[5.0, 5.0, 5.0], [5.0 + r, 5.0, 5.0]],
                setup="pair_style table spline 5000\npair_coeff * * pots.table LJ_R\nrun 0")
    s6 = r ** -6
    assert sim.pe == pytest.approx(4.0 * (s6 * s6 - s6), rel=1e-7)
    assert forces_by_tag(sim)[1, 0] == pytest.approx(24.0 * (2.0 * s6 * s6 - s6) / r, rel=1e-7)


def test_a_pair_inside_the_inner_cutoff_stops_the_run(tmp_path, monkeypatch):
    _tables(tmp_path)
    monkeypatch.chdir(tmp_path)
    with pytest.raises(SimulationError, match=r"run: pair table: two particles 0\.65 apart, inside the inner cutoff "
                                              r"0\.7 of table LJ_R \(pots\.table\) at step 0$"):
        build(tmp_path, [[5.0, 5.0, 5.0], [5.65, 5.0, 5.0]],
              setup="pair_style table linear 100\npair_coeff * * pots.table LJ_R\nrun 0")


BAD = {
    "missing keyword": ("", "NOPE", "table file bad.table has no section NOPE"),
    "N mismatch": ("T\nN 4 R 1.0 2.0\n\n1 1.0 1.0 1.0\n2 1.5 0.5 0.5\n3 2.0 0.0 0.0\n", "T",
                   "table file bad.table: section T declares N 4 but has 3 lines of values"),
    "too many lines": ("T\nN 2 R 1.0 2.0\n\n1 1.0 1.0 1.0\n2 1.5 0.5 0.5\n3 2.0 0.0 0.0\n", "T",
                       "table file bad.table:6: section T declares N 2 but has more lines of values"),
    "bad number": ("T\nN 3\n\n1 1.0 1.0 1.0\n2 1.5 O.5 0.5\n3 2.0 0.0 0.0\n", "T",
                   "table file bad.table:5: energy 'O.5' is not a finite number"),
    "short line": ("T\nN 3\n\n1 1.0 1.0 1.0\n2 1.5 0.5\n3 2.0 0.0 0.0\n", "T",
                   "table file bad.table:5: expected 'index r energy force', got '2 1.5 0.5'"),
    "no N": ("T\nR 1.0 2.0\n\n1 1.0 1.0 1.0\n", "T", "table file bad.table:2: section T does not set N"),
    "bitmap": ("T\nN 4 BITMAP 1.0 2.0\n\n1 1.0 1.0 1.0\n", "T",
               "table file bad.table:2: BITMAP tables are not supported; tabulate with R or RSQ"),
    "unknown parameter": ("T\nN 2 SPACING 3\n\n1 1.0 1.0 1.0\n2 2.0 0 0\n", "T",
                          "table file bad.table:2: unknown table parameter 'SPACING' (expected N, R, RSQ, FPRIME)"),
    "decreasing r": ("T\nN 3\n\n1 1.0 1.0 1.0\n2 0.9 0.5 0.5\n3 2.0 0.0 0.0\n", "T",
                     "table file bad.table: section T: r must increase (r = 0.9 after 1)"),
    "not a file": (None, "T", "cannot open table file bad.table (No such file or directory)"),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_bad_table_files_get_one_line(tmp_path, monkeypatch, case):
    text, keyword, message = BAD[case]
    if text is not None:
        (tmp_path / "bad.table").write_text(text)
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass * 1\npair_style table linear 100")
    with pytest.raises(ScriptError) as caught:
        sim.command(f"pair_coeff * * bad.table {keyword}")
    assert str(caught.value).endswith(message)
    assert "\n" not in str(caught.value)


def test_a_cutoff_outside_the_table_is_refused(tmp_path, monkeypatch):
    _tables(tmp_path)
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass * 1\npair_style table linear 100")
    with pytest.raises(ScriptError, match=r"cutoff 3 is outside table LJ_R \(r from 0\.7 to 2\.5\)$"):
        sim.command("pair_coeff * * pots.table LJ_R 3.0")


def test_the_bitmap_style_is_refused():
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 5 0 5 0 5\ncreate_box 1 box")
    with pytest.raises(ScriptError, match="bitmap"):
        sim.command("pair_style table bitmap 12")


def test_table_does_not_mix(tmp_path, monkeypatch):
    _tables(tmp_path)
    monkeypatch.chdir(tmp_path)
    refused = script_error("region box block 0 5 0 5 0 5\ncreate_box 2 box\nmass * 1\ncreate_particle 1 single 1 1 1\n"
                           "pair_style table linear 100\npair_coeff 1 1 pots.table LJ_R\n"
                           "pair_coeff 2 2 pots.table LJ_R\npair_modify mix arithmetic", "run 0")
    assert refused.message == ("pair coefficients are not set for types 1 2 (pair style table does not mix; give "
                               "pair_coeff for every type pair)")


@pytest.mark.parametrize("text, message", [
    ("T\nN 2\n\n1 1 1 1\n2 1.0000000000000002 1 1\n",
     "table T (bad.table): interpolating it with 100 points gives non-finite values (r values too close "
     "together, or values too large)"),
    ("T\nN 2\n\n1 0 1 1\n2 1 1 1\n", "table file bad.table: section T: r must lie in (0, 1e154) (got 0 to 1)"),
    ("T\nN 2\n\n1 1e300 1 1\n2 1.7e308 1 1\n",
     "table file bad.table: section T: r must lie in (0, 1e154) (got 1e+300 to 1.7e+308)"),
])
def test_tables_that_cannot_be_interpolated_are_refused(tmp_path, monkeypatch, text, message):
    (tmp_path / "bad.table").write_text(text)
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None)
    sim.command("region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass * 1\npair_style table spline 100")
    with pytest.raises(ScriptError) as caught:
        sim.command("pair_coeff * * bad.table T")
    assert str(caught.value).endswith(message)


def test_a_table_file_is_found_beside_its_script_and_named_as_written(pdps_cli, tmp_path):
    (tmp_path / "sub").mkdir()
    shutil.copy(DATA / "pots.table", tmp_path / "sub" / "pots.table")
    setup = ("units lj\nregion box block 0 5 0 5 0 5\ncreate_box 1 box\nmass * 1\ncreate_particle 1 single 1 1 1\n"
             "pair_style table linear 100\n")
    done = pdps_cli(setup + "pair_coeff * * pots.table LJ_R\nrun 0\n", name="sub/in.table")
    assert done.returncode == 0, done.stderr
    done = pdps_cli(setup + "pair_coeff * * pots.table NOPE\n", name="sub/in.table")
    assert (done.returncode, done.stderr) == (1, "ERROR: in.table:7: pair_coeff: table file pots.table has no "
                                                 "section NOPE\n")
