"""fix rigid/npt/small and rigid/nph/small (LAMMPS's fix rigid/nh/small) against LAMMPS (22 Jul 2025) on 27
small bodies of Lennard-Jones particles (iso; aniso with a ramped target and pchain; x and z coupled with
a dilate group), fix rigid/nph's box change carrying rigid/small's bodies, and fix_modify temp and press
(naming computes of a group of half the bodies) for these and fix rigid/nph, recorded by
benchmarks/lammps_references/rigid_small.py into tests/data/rigid_small_lj.txt; 1 and 2 ranks; bad input."""

import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError
from pdps_core.testing import restart_round_trip, thermo_on_ranks

sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from lammps_run import read_blocks  # noqa: E402
from rigid_small import BAROSTAT_SCRIPT, BAROSTATS, PLANE_NPH  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
from test_rigid_lammps import pdps_thermo, relative_differences  # noqa: E402

DATA = Path(__file__).with_name("data")
COLUMNS = "step temp epair ke etotal press vol lx ly lz f_1 ecouple econserve".split()
# LAMMPS's script builds neighbor lists every step (the recorder says why); pdps re-images the bodies'
# centres whenever the box changes and runs it without that line
EVERY_STEP = "neigh_modify every 1 delay 0 check no\n"


def run_scene(pdps_cli, tmp_path, name, steps=None):
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    fix, length = BAROSTATS[name]
    text = BAROSTAT_SCRIPT.format(fix=fix, steps=steps or length).replace(EVERY_STEP, "")
    return pdps_thermo(pdps_cli, text)


@pytest.mark.parametrize("name", list(BAROSTATS))
def test_barostats_match_lammps(pdps_cli, tmp_path, name):
    """Temperature, pressure, volume, box lengths, f_1, ecouple and econserve as LAMMPS's, each column
    relative to its largest value, over the first 1000 steps and over the whole run."""
    ours = run_scene(pdps_cli, tmp_path, name)
    lammps = read_blocks(DATA / "rigid_small_lj.txt")[name]
    assert ours.shape == lammps.shape
    differences = relative_differences(ours, lammps)
    early = differences[:11].max()
    worst = differences.max(axis=0)
    print(f"{name}: largest difference from LAMMPS, of each column's largest value: {early:.1e} over 1000 steps, "
          + ", ".join(f"{c} {w:.1e}" for c, w in zip(COLUMNS[1:], worst)) + f" over {int(lammps[-1, 0])}")
    assert early < 1e-5
    assert worst.max() < 1e-5


@pytest.mark.parametrize("name", ["rigid/npt/small iso", "rigid/nph/small aniso", "rigid/nph carries rigid/small",
                                  "rigid/nph/small temp"])
def test_same_thermo_on_one_and_two_ranks(tmp_path, name):
    """Bodies owned on either rank, crossing the ranks' boundary while the box shrinks: the kinetic
    sums, degrees of freedom and pressure the barostat reads are all ranks', so 2 ranks run as one."""
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    fix, _ = BAROSTATS[name]
    text = BAROSTAT_SCRIPT.format(fix=fix, steps=1500).replace(EVERY_STEP, "")
    one, two = thermo_on_ranks(text, tmp_path)
    assert one.shape == two.shape == (16, 13)
    assert one[-1, 6] < 0.99 * one[0, 6]          # the box did change
    assert two == pytest.approx(one, rel=1e-10, abs=1e-12)


@pytest.mark.parametrize("line, message", [
    ("fix 1 all rigid/nph/small molecule", "fix rigid/nph/small needs a pressure: iso, aniso, x, y or z"),
    ("fix 1 all rigid/npt/small molecule iso 1 1 1", "fix rigid/npt/small needs temp TSTART TSTOP TDAMP and a"),
    ("fix 1 all rigid/npt/small molecule temp 1 1 1", "fix rigid/npt/small needs temp TSTART TSTOP TDAMP and a"),
    ("fix 1 all rigid/nph/small molecule iso 1 1 1 temp 1 1 1", "keyword temp of fix rigid/nph/small: fix "
     "rigid/nph/small controls no temperature"),
    ("fix 1 all rigid/nph/small molecule iso 1 1 1 tparam 3 1 3", "keyword tparam of fix rigid/nph/small: only "
     "fix rigid/nvt/small and rigid/npt/small take it"),
    ("fix 1 all rigid/npt/small molecule temp 1 1 1 iso 1 1 1 langevin 1 1 1 5", "keyword langevin of fix "
     "rigid/npt/small: fix rigid/nph/small and rigid/npt/small take no langevin"),
    ("fix 1 all rigid/nph/small molecule iso -1 1 1", r"iso: target pressures of fix rigid/nph/small cannot be < 0"),
    ("fix 1 all rigid/nph/small molecule x 1 1 0", r"x: PDAMP must be > 0 \(got 0\)"),
    ("fix 1 all rigid/nph/small molecule iso 1 1 1 pchain 0", "pchain: the barostat chain needs 1 to 1000"),
    ("fix 1 all rigid/npt/small molecule temp 1 1 1 iso 1 1 1 tparam 3 2000 3", "tparam: TCHAIN and TITER must be"),
    ("fix 1 all rigid/nph/small molecule x 1 1 1 y 2 2 1 couple xy", "couple xy: coupled axes need the same"),
    ("fix 1 all rigid/nph/small molecule iso 1 1 1 couple banana", "couple"),
    ("fix 1 all rigid/nph/small molecule iso 1 1 1 mol water", "keyword mol of fix rigid/nph/small: fix rigid/small and rigid/nve/small take it; this "
     "variant does not yet"),
    ("fix 1 all rigid/nph/small single iso 1 1 1", "fix rigid/nph/small takes bodystyle molecule only"),
    ("fix 1 all rigid/nvt/small molecule temp 1 1 1 iso 1 1 1", "keyword iso of fix rigid/nvt/small: only fix "
     "rigid/nph/small and rigid/npt/small take it"),
])
def test_bad_input_is_one_line(make_sim, tmp_path, line, message):
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    sim = make_sim()
    sim.command(f"units lj\natom_style molecular\nread_data {tmp_path / 'rigid_small_lj.data'}")
    with pytest.raises(ScriptError, match=message):
        sim.command(line)


def test_non_periodic_axis_is_refused(make_sim, tmp_path):
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    sim = make_sim()
    sim.command(f"units lj\natom_style molecular\nboundary p p f\nread_data {tmp_path / 'rigid_small_lj.data'}")
    with pytest.raises(ScriptError, match="fix rigid/nph/small cannot change the non-periodic z length"):
        sim.command("fix 1 all rigid/nph/small molecule iso 1 1 1")


@pytest.mark.parametrize("lines, message", [
    ("fix_modify 1 temp nope", r"compute nope is not defined \(temperature of fix 1 rigid/nph/small\)"),
    ("compute p2 all pressure\nfix_modify 1 temp p2", "temp: compute p2 \\(pressure\\) is not a temp "
     "compute, so it gives no temperature"),
    ("compute t2 high temp\nfix_modify 1 press t2", r"press: compute t2 \(temp\) is not a pressure compute"),
    ("compute t2 high temp\nfix_modify 1 temp t2\nuncompute t2\nrun 1", r"compute t2 is not defined \(temperature of "
     "fix 1 rigid/nph/small\\)"),
    ("compute t2 high temp\ncompute p2 all pressure t2\nfix_modify 1 press p2\nuncompute p2\nrun 1",
     r"compute p2 is not defined \(pressure of fix 1 rigid/nph/small\)"),
])
def test_fix_modify_bad_computes_are_one_line(make_sim, tmp_path, lines, message):
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    sim = make_sim()
    sim.command(f"units lj\natom_style molecular\nread_data {tmp_path / 'rigid_small_lj.data'}\n"
                "group high molecule > 13\nfix 1 all rigid/nph/small molecule iso 0.05 0.05 2.0")
    with pytest.raises(ScriptError, match=message):
        sim.command(lines)


def test_fix_modify_temp_is_not_taken_by_fixes_without_a_barostat(make_sim, tmp_path):
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    sim = make_sim()
    sim.command(f"units lj\natom_style molecular\nread_data {tmp_path / 'rigid_small_lj.data'}\n"
                "fix 1 all rigid/small molecule\ncompute t2 all temp")
    with pytest.raises(ScriptError, match="unknown keyword temp"):
        sim.command("fix_modify 1 temp t2")


def test_restart_goes_on_as_a_second_run(tmp_path):
    """rigid/npt/small run 200 steps, written to a restart file, read back and run 200 more, against
    the same two runs in one simulation (each run's set-up gives the strain rate its half kick, in
    LAMMPS as here, so a straight run of 400 is another run): the chains and strain rates come back
    from the file, the bodies from the particles; the same particles and box to round-off."""
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    setup = (f"units lj\natom_style molecular\nread_data {tmp_path / 'rigid_small_lj.data'}\npair_style lj/cut 2.5\n"
             "pair_coeff * * 1.0 1.0\nneigh_modify exclude molecule/intra all\ntimestep 0.001\n"
             "fix 1 all rigid/npt/small molecule temp 0.5 0.5 1.0 iso 0.05 0.05 2.0 pchain 3\n")
    # neighbor exclusions are not in restart files: the script gives them again
    straight, resumed = restart_round_trip(tmp_path, setup, 200, 200, split=True,
                                           again="neigh_modify exclude molecule/intra all")
    a, b = straight.particles, resumed.particles
    order_a, order_b = np.argsort(a.tag[: a.nlocal]), np.argsort(b.tag[: b.nlocal])
    assert b.x[: b.nlocal][order_b] == pytest.approx(a.x[: a.nlocal][order_a], abs=1e-9)
    assert b.v[: b.nlocal][order_b] == pytest.approx(a.v[: a.nlocal][order_a], abs=1e-9)
    assert resumed.box.length == pytest.approx(straight.box.length, abs=1e-10)
    fix_a, fix_b = straight.fixes["1"], resumed.fixes["1"]
    assert np.all(fix_a.epsilon_dot != 0.0)
    for name in ("epsilon_dot", "eta_dot_b", "eta_dot_t", "eta_r"):
        assert getattr(fix_b, name) == pytest.approx(getattr(fix_a, name), abs=1e-12)


def test_two_dimensional_bodies_match_lammps(pdps_cli, tmp_path):
    """A dimer and a triangle pushed across the periodic x boundary in 2d (fix enforce2d) under
    rigid/nph/small iso (x and y coupled; 1 degree of freedom of rotation a body): temperature,
    kinetic energy, pressure, area, f_1 and ecouple as LAMMPS's over 2000 steps."""
    ours = pdps_thermo(pdps_cli, PLANE_NPH)
    lammps = read_blocks(DATA / "rigid_small_lj.txt")["plane rigid/nph/small"]
    assert ours.shape == lammps.shape == (11, 7)
    assert lammps[-1, 4] < 0.8 * lammps[0, 4]        # the box did shrink
    worst = (np.abs(ours[:, 1:] - lammps[:, 1:]) / np.abs(lammps[:, 1:]).max(axis=0)).max()
    print(f"plane rigid/nph/small: largest difference from LAMMPS, of each column's largest value: {worst:.1e}")
    assert worst < 1e-5
