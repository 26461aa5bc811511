"""Fixes nvt, npt, nph and deform give LAMMPS's thermo (temp, pe, press, volume, box lengths) over 100 steps of
a 200-particle Lennard-Jones fluid (data/nh.txt, recorded with LAMMPS by
benchmarks/lammps_references/nh.py): thermostat chains, iso/aniso/x-y-z barostats, couple, drag,
sub-cycles, ramps, dilate and fixedpoint as LAMMPS integrates them; deform's six styles with remap
x, v and none, and deform beside a barostat. data/nh_options.txt likewise for ptemp, disc, flip,
fix_modify temp and press (in both orders), deform volume (its three cases), wiggle and variable,
and 2-d barostats on a 144-particle fluid (data/plane.data).

The thermo against LAMMPS's (with 2 ranks and restarts for the cases marked so) is checked by
tests/test_recorded_thermo.py from data/nh.cases.json, data/nh_options.cases.json and
data/ecouple.cases.json; this file holds the rest."""

import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation, observables
from pdps_core.testing import by_tag, lammps_thermo, restart_round_trip, script_error, total_energy

DATA = Path(__file__).parent / "data"
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from nh import script  # noqa: E402

BOX = "region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1"


def run_case(tmp_path, monkeypatch, case):
    return lammps_thermo(tmp_path, monkeypatch, script(case), ["fluid.data"], DATA)


def fluid(tmp_path, monkeypatch, lines):
    shutil.copy(DATA / "fluid.data", tmp_path / "fluid.data")
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("\n".join(CONSERVE + lines))
    return sim


@pytest.mark.parametrize("styles", ["x erate 0.5 y volume", "x volume y trate -0.4 z volume",
                                    "x erate 0.3 y scale 0.9 z volume"])
def test_deform_volume_keeps_the_volume(tmp_path, monkeypatch, styles):
    """Whatever the other axes do, the volume axes keep Lx Ly Lz at its value at the run's start, every
    step, about the box's centre; the other axes follow their own formulas (erate: L0 (1 + R t))."""
    sim = fluid(tmp_path, monkeypatch, [f"fix 1 all nve\nfix 2 all deform 1 {styles} units box"])
    volume, centre = sim.box.volume, 0.5 * (sim.box.lo + sim.box.hi)
    for steps in (13, 25):
        length = sim.box.length.copy()
        sim.command(f"run {steps}")
        assert sim.box.volume == pytest.approx(volume, rel=1e-13)
        np.testing.assert_allclose(0.5 * (sim.box.lo + sim.box.hi), centre, rtol=1e-13)
        if styles.startswith("x erate"):
            rate = float(styles.split()[2])
            assert sim.box.length[0] == pytest.approx(length[0] * (1 + rate * steps * 0.001), rel=1e-13)


def test_deform_wiggle_follows_its_sine(tmp_path, monkeypatch):
    """L(t) = L0 + A sin(2 pi t / TP) at the end of a run, t and L0 from the run's start, with A in
    lattice spacings under units lattice (sc at reduced density 0.8: (1/0.8)^(1/3))."""
    sim = fluid(tmp_path, monkeypatch, ["lattice sc 0.8", "fix 1 all nve",
                                        "fix 2 all deform 1 x wiggle 0.3 0.02 y wiggle -0.2 0.05 z wiggle 0.1 0.03"])
    spacing = (1 / 0.8) ** (1 / 3)
    for steps in (7, 13):
        length0 = sim.box.length.copy()
        sim.command(f"run {steps}")
        t = steps * 0.001
        want = length0 + spacing * np.array([0.3 * np.sin(2 * np.pi * t / 0.02), -0.2 * np.sin(2 * np.pi * t / 0.05),
                                             0.1 * np.sin(2 * np.pi * t / 0.03)])
        np.testing.assert_allclose(sim.box.length, want, rtol=1e-13)


def test_fix_modify_temp_points_the_pressure_compute_at_it(tmp_path, monkeypatch):
    """As LAMMPS's reset_extra_compute_fix: after fix_modify press P, fix_modify temp T makes P's
    temperature T (so c_P reads it too), and a group other than all draws LAMMPS's warning."""
    sim = fluid(tmp_path, monkeypatch, ["group light type 1", "compute light_t light temp",
                                        "compute p all pressure", "fix 1 all nph iso 0.5 0.5 1.0",
                                        "fix_modify 1 press p temp light_t"])
    assert sim.computes["p"].args.temperature == "light_t"
    assert sim.warnings[-1] == ("fix 1 nph: temperature compute light_t is of group light, not all "
                                "(LAMMPS's fix_modify warns so too)")
    sim.command("run 0")
    expected = observables.pressure(sim, observables.temperature(sim, "light"), "light")
    assert sim.compute_value("p") == pytest.approx(expected, rel=1e-14)


CONSERVE = ["units lj", "atom_style atomic", "read_data fluid.data", "pair_style lj/cut 2.5",
            "pair_coeff 1 1 1.0 1.0", "pair_coeff 2 2 0.5 1.2", "pair_modify shift yes", "timestep 0.001",
            "thermo 0"]


@pytest.mark.parametrize("fix", ["fix 1 all nvt temp 1.0 1.0 0.1",
                                 "fix 1 all npt temp 1.0 1.0 0.1 iso 0.5 0.5 1.0",
                                 "fix 1 all nph aniso 0.5 0.5 1.0"])
def test_the_extended_energy_is_conserved(tmp_path, monkeypatch, fix):
    """pe + ke + ecouple (LAMMPS's econserve; ecouple is the fix's scalar) over 2,000 steps of
    dt 0.001 with a shifted LJ potential: it stays within 0.1 (5e-4 per particle, the integrator's
    O(dt^2) fluctuation) while pe + ke alone moves by more than 50 as the reservoir exchanges
    energy with the fluid. With iso, LAMMPS's ecouple counts the barostat chain's first element as
    d_p k_B T eta_p1 while its equations drive it with k_B T, so LAMMPS's own econserve drifts (by
    0.065 per particle over this run, measured with LAMMPS); pdps prints LAMMPS's ecouple, and the
    quantity conserved is econserve less (d_p - 1) k_B T eta_p1."""
    shutil.copy(DATA / "fluid.data", tmp_path / "fluid.data")
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("\n".join(CONSERVE + [fix, "run 0"]))
    conserved, total = [], []
    for _ in range(20):
        sim.command("run 100")
        energy = total_energy(sim) + observables.kinetic_energy(sim)
        total.append(energy)
        nh = sim.fixes["1"]
        iso_term = (nh.pdim - 1) * nh.boltz * nh.t_target * nh.etap[0] if nh.pstat and nh.iso else 0.0
        conserved.append(energy + nh.ecouple(sim) - iso_term)
    assert np.ptp(total) > 50
    assert np.ptp(conserved) < 0.1


@pytest.mark.slow
@pytest.mark.parametrize("fix, target_t, target_p", [
    ("fix 1 all nvt temp 1.0 1.0 0.5", 1.0, None),
    ("fix 1 all npt temp 1.0 1.0 0.5 iso 0.5 0.5 5.0", 1.0, 0.5),
    ("fix 1 all npt temp 0.9 0.9 0.5 aniso 0.3 0.3 5.0", 0.9, 0.3),
])
def test_long_runs_reach_the_targets(tmp_path, monkeypatch, fix, target_t, target_p):
    """After 2,000 steps of equilibration, 30 blocks of 2,000 steps (10 tau, longer than the
    barostat's period) average to the target temperature and pressure within three standard errors
    of the block means."""
    shutil.copy(DATA / "fluid.data", tmp_path / "fluid.data")
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("\n".join(SETUP_LONG + [fix, "variable t equal temp", "variable p equal press",
                                        "fix av all ave/time 10 200 2000 v_t v_p", "run 2000"]))
    blocks = []
    for _ in range(30):
        sim.command("run 2000")
        blocks.append([sim.fix_value("av", (1,)), sim.fix_value("av", (2,))])
    blocks = np.array(blocks)
    mean, error = blocks.mean(axis=0), blocks.std(axis=0, ddof=1) / np.sqrt(len(blocks))
    assert abs(mean[0] - target_t) < 3 * error[0], (mean, error)
    if target_p is not None:
        assert abs(mean[1] - target_p) < 3 * error[1], (mean, error)


SETUP_LONG = ["units lj", "atom_style atomic", "read_data fluid.data", "pair_style lj/cut 2.5",
              "pair_coeff 1 1 1.0 1.0", "pair_coeff 2 2 0.5 1.2", "timestep 0.005", "thermo 0"]


@pytest.mark.parametrize("line, message", [
    ("fix 1 all nvt temp 1 1 0.1 iso 1 1 1", "fix nvt controls no pressure (use fix npt for temp and pressure)"),
    ("fix 1 all nvt tchain 3", "fix nvt needs temp TSTART TSTOP TDAMP"),
    ("fix 1 all npt temp 1 1 0.1", "fix npt needs a pressure: iso, aniso, x, y or z PSTART PSTOP PDAMP"),
    ("fix 1 all nph temp 1 1 0.1 iso 1 1 1", "fix nph controls no temperature (use fix npt for temp and pressure)"),
    ("fix 1 all nvt temp 0 1 0.1", "temp: target temperatures must be > 0 (got 0 1)"),
    ("fix 1 all nvt temp 1 1 0", "temp: damping must be > 0 (got 0)"),
    ("fix 1 all nph aniso 1 1 -2", "x: pressure damping must be > 0 (got -2)"),
    ("fix 1 all nph tri 1 1 1", "tri: pdps boxes are orthogonal (no tilt), so only iso, aniso, x, y and z can be barostatted"),
    ("fix 1 all nph x 1 1 1 xy 0 0 1", "xy: pdps boxes are orthogonal (no tilt), so only iso, aniso, x, y and z can be barostatted"),
    ("fix 1 all nph x 1 1 1 couple xy", "couple xy: every coupled axis needs a pressure (iso, aniso or x/y/z)"),
    ("fix 1 all nph x 1 1 1 y 2 2 1 couple xy", "couple xy: coupled axes need the same PSTART PSTOP PDAMP"),
    ("fix 1 all nph x 1 1 1 dilate nobody", "group nobody is not defined (defined: all)"),
    ("fix 1 all nvt temp 1 1 0.1 tchain 0", "tchain must be >= 1 (got 0)"),
    ("fix 1 all nph z 1 1 1", "z is not periodic: a barostat needs periodic axes it changes"),
    ("fix 1 all nvt temp 1 1 0.1 mtk maybe", "mtk must be one of 'yes' or 'no' (got maybe)"),
    ("fix 1 all nph x 1 1 1 y 1 1 1 ptemp 0", "ptemp must be > 0 (got 0)"),
    ("fix 1 all npt temp 1 1 0.1 x 1 1 1 ptemp 2", "ptemp: fix npt has a thermostat, whose target temperature "
                                                   "sets the barostat's mass (ptemp is for nph)"),
    ("fix 1 all nvt temp 1 1 0.1 flip maybe", "flip must be one of 'yes' or 'no' (got maybe)"),
    ("fix 1 all nph x 1 1 1 scalexy yes", "unknown keyword scalexy (known: temp, iso, aniso, x, y, z, tri, xy, "
                                          "xz, yz, couple, tchain, pchain, mtk, tloop, ploop, nreset, drag, dilate, "
                                          "fixedpoint, ptemp, flip, disc)"),
])
def test_bad_nh_fixes(line, message):
    assert script_error("boundary p p f\n" + BOX, line).message == message


@pytest.mark.parametrize("line, message", [
    ("fix 1 all nph x 1 1 1\nfix_modify 1 temp nobody", "compute nobody is not defined (temperature of fix 1)"),
    ("fix 1 all nph x 1 1 1\ncompute p all pressure\nfix_modify 1 temp p",
     "compute p (pressure) is not a temp compute, so it gives no temperature"),
    ("fix 1 all nph x 1 1 1\ncompute t all temp\nfix_modify 1 press t",
     "compute t (temp) is not a pressure compute, so it gives no pressure"),
    ("fix 1 all nvt temp 1 1 0.1\ncompute p all pressure\nfix_modify 1 press p",
     "press: fix 1 (nvt) controls no pressure"),
    ("fix 1 all nvt temp 1 1 0.1\nfix_modify 1 dof 3",
     "unknown keyword dof; expected: fix_modify ID [energy yes|no] [virial yes|no]"),
])
def test_bad_fix_modify_of_nh(line, message):
    assert script_error(BOX, line).message == message


@pytest.mark.parametrize("setup, message", [
    ("fix 1 all nph iso 1 1 1", "fix 1 nph: the temperature is 0, too close to 0 to set the barostat's mass; "
                                "give ptemp T"),
    ("compute t all temp\nfix 1 all nvt temp 1 1 1\nfix_modify 1 temp t\nuncompute t",
     "fix 1 nvt: temperature compute t is not defined"),
    ("compute t all temp\ncompute p all pressure t\nfix 1 all nph iso 1 1 1 ptemp 1\nfix_modify 1 press p\n"
     "uncompute p", "fix 1 nph: pressure compute p is not defined"),
])
def test_nh_refused_at_the_run(setup, message):
    """LAMMPS 2025 stops a barostat without ptemp at T = 0 (it once guessed 1 or 300); computes named
    by fix_modify must still exist when a run starts."""
    two = BOX + "\ncreate_particle 1 single 1 1 1\ncreate_particle 1 single 3 3 3\n"
    assert script_error(two + setup, "run 1").message == message


@pytest.mark.parametrize("line, message", [
    ("fix 2 all deform 1", "fix deform needs at least one of x, y, z with a style"),
    ("fix 2 all deform 0 x erate 0.1", "every must be >= 1 (got 0)"),
    ("fix 2 all deform 1 x shear 1", "x must be one of final, delta, scale, vel, erate, trate, volume, wiggle, "
                                     "variable (got shear)"),
    ("fix 2 all deform 1 x volume", "x volume: another of x, y, z must change by a style other than volume for "
                                    "this one to keep the volume"),
    ("fix 2 all deform 1 x volume y volume z erate 0.1 z volume",
     "x volume: another of x, y, z must change by a style other than volume for this one to keep the volume"),
    ("fix 2 all deform 1 x wiggle 0.1 0", "x wiggle: the period must be > 0 (got 0)"),
    ("fix 2 all deform 1 x wiggle 0.1", "x wiggle takes 2 value(s): number number (got 0.1)"),
    ("fix 2 all deform 1 y variable v_a b", "y: variable takes two equal-style variables v_LENGTH v_RATE (got b)"),
    ("fix 2 all deform 1 x final 0", "x final takes 2 value(s): number number (got 0)"),
    ("fix 2 all deform 1 y scale big", "y must be a finite number (got big)"),
    ("fix 2 all deform 1 xy erate 0.1",
     "keyword xy of fix deform: pdps boxes are orthogonal (no tilt), so only x, y and z can deform"),
    ("fix 2 all deform 1 x erate 0.1 remap y", "remap must be one of 'x', 'v' or 'none' (got y)"),
    ("fix 2 all deform 1 x erate 0.1 shape no", "unknown keyword shape (known: x, y, z, remap, flip, units)"),
])
def test_bad_deform(line, message):
    assert script_error(BOX, line).message == message


@pytest.mark.parametrize("fixes, message", [
    ("fix 2 all deform 1 x final 3 2 units box", "fix 2 deform: the box's x length would reach -1 by the run's end "
                                                   "(it must stay > 0)"),
    ("fix 1 all nph iso 1 1 1\nfix 2 all deform 1 y erate 0.1", "fix 1 nph and fix 2 deform change the same box "
                                                                  "length"),
    ("variable a equal 0.1\nfix 2 all deform 1 z variable v_a v_b", "fix 2 deform: variable b is not defined "
                                                                       "(z variable)"),
    ("variable a atom x\nvariable b equal 0\nfix 2 all deform 1 z variable v_a v_b",
     "v_a is atom-style: name one element, v_a[i]"),
])
def test_deform_refused_at_the_run(fixes, message):
    assert script_error(BOX + "\ncreate_particle 1 single 1 1 1\n" + fixes, "run 10").message == message


@pytest.mark.parametrize("fix", ["fix 1 all nvt temp 1.0 1.0 0.1",
                                 "fix 1 all npt temp 1.0 1.0 0.1 aniso 0.5 0.5 0.5 fixedpoint 1 2 3"])
def test_a_restart_goes_on_as_the_run_would(tmp_path, fix):
    """run 60 equals run 30, write_restart, read_restart, run 30: the chain and barostat variables,
    the reference volume, the fixed point and the changed box travel in the restart file."""
    shutil.copy(DATA / "fluid.data", tmp_path / "fluid.data")
    setup = "\n".join(line.replace("fluid.data", str(tmp_path / "fluid.data")) for line in CONSERVE + [fix])
    straight, resumed = restart_round_trip(tmp_path, setup, 30, 30)
    np.testing.assert_allclose(resumed.box.length, straight.box.length, rtol=1e-12)
    np.testing.assert_allclose(by_tag(resumed, resumed.x), by_tag(straight, straight.x), rtol=1e-10, atol=1e-10)
    np.testing.assert_allclose(by_tag(resumed, resumed.v), by_tag(straight, straight.v), rtol=1e-10, atol=1e-10)

