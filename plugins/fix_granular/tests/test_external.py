"""fix external driven from Python as LAMMPS 22 Jul 2025 is driven by its Python module: the scene
of benchmarks/lammps_references/external.py (a periodic force field on 125 soft spheres, set by a
pf/callback function every second step, or by the program into the pf/array between four runs)
prints LAMMPS's thermo (tests/data/lammps_external.json, its energy in pe and f_ID included). Then
when the function is called, that its forces persist between calls, and the refusals."""

import json
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation

ROOT = Path(__file__).resolve().parents[3]
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
import external as scene  # noqa: E402

RECORDED = json.loads((Path(__file__).parent / "data" / "lammps_external.json").read_text())["rows"]


def thermo(tmp_path, name):
    return np.array(scene.thermo_rows((tmp_path / name).read_text().splitlines()))


def test_a_callback_drives_pdps_as_it_drives_lammps(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.callback"), dialect="lammps")
    sim.command(scene.CALLBACK)
    fix = sim.fixes["ext"]
    fix.set_callback(scene.callback, fix.set_energy)
    sim.command(f"run {scene.STAGES * scene.STEPS}")
    np.testing.assert_allclose(thermo(tmp_path, "log.callback"), RECORDED["callback"], rtol=1e-8, atol=1e-10)


def test_an_array_set_between_runs_drives_pdps_as_it_drives_lammps(tmp_path):
    sim = Simulation(screen=False, log=str(tmp_path / "log.array"), dialect="lammps")
    sim.command(scene.ARRAY)
    fix = sim.fixes["ext"]
    for _ in range(scene.STAGES):
        forces, energy = scene.periodic_force(sim.tag, sim.x)
        fix.fexternal[:] = forces
        fix.set_energy(energy)
        sim.command(f"run {scene.STEPS}")
    np.testing.assert_allclose(thermo(tmp_path, "log.array"), RECORDED["array"], rtol=1e-8, atol=1e-10)


def test_the_function_is_called_every_ncall_steps_and_its_forces_stay():
    """pf/callback 3 1 on one particle at rest in an empty box: calls at steps 0 (setup), 3, 6, 9; the
    force of the call at step 0 (1 in x) acts on steps 0, 1, 2 before the next call sets 2, so the
    velocity after 10 steps of dt = 0.1 (mass 1, fix nve) is 0.1 (1 * 3 + 2 * 3 + 3 * 3 + 4 * 1) - the
    halves of the first and last kicks: v = dt (f0/2 + f1 + ... + f9 + f10/2), f_n of the call before n."""
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\natom_style atomic\nregion box block 0 10 0 10 0 10\ncreate_box 1 box\n"
                "create_atoms 1 single 5 5 5 units box\nmass 1 1.0\nfix integr all nve\ntimestep 0.1\n"
                "fix ext all external pf/callback 3 1\n")
    calls = []

    def push(caller, step, nlocal, tag, x, fexternal):
        calls.append(step)
        fexternal[:, 0] = len(calls)
    sim.fixes["ext"].set_callback(push)
    sim.command("run 10")
    assert calls == [0, 3, 6, 9]
    forces = [1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4]
    expected = 0.1 * (forces[0] / 2 + sum(forces[1:10]) + forces[10] / 2)
    assert sim.v[0, 0] == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize("line, message", [
    ("fix ext all external pf/callback 1", "fix external pf/callback takes NCALL NAPPLY (got 1 numbers); usage: "
     "fix ID GROUP external pf/callback NCALL NAPPLY | fix ID GROUP external pf/array NAPPLY"),
    ("fix ext all external pf/array 0", "fix external pf/array: NAPPLY must be > 0 (got 0)"),
])
def test_bad_lines_are_refused(line, message):
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\nregion box block 0 1 0 1 0 1\ncreate_box 1 box\n")
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert caught.value.message == message


def test_a_run_without_the_function_is_refused():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("units lj\nregion box block 0 1 0 1 0 1\ncreate_box 1 box\nmass 1 1.0\n"
                "fix ext all external pf/callback 1 1\n")
    with pytest.raises(ScriptError) as caught:
        sim.command("run 1")
    assert caught.value.message == ("fix ext (external): Fix external callback function not set "
                                    "(sim.fixes['ext'].set_callback(function))")
