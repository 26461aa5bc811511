"""Computes pe, pe/atom, stress/atom, ke/atom and vacf give LAMMPS's numbers on a 200-particle
two-type Lennard-Jones fluid: thermo every 25 steps of a 100-step NVE run to 1e-9, per-particle
values at steps 0 and 100 to 1e-12 (data/, recorded with LAMMPS by
benchmarks/lammps_references/computes.py); the per-particle values add up to the global ones.

The thermo against LAMMPS's (with 2 ranks and restarts for the cases marked so) is checked by
tests/test_recorded_thermo.py from data/computes.cases.json; this file holds the rest."""

import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation, observables
from pdps_core.testing import build, by_tag, script_error

DATA = Path(__file__).parent / "data"
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from computes import COLUMNS, SETUP, THERMO  # noqa: E402


def lammps_dump(step):
    lines = (DATA / f"computes_step{step}.dump").read_text().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    return np.array([[float(v) for v in line.split()] for line in lines[start + 1:]])


def mine(sim):
    """The dump's columns, computed by pdps now, in id order."""
    rows = [np.sort(sim.tag).astype(float)]
    for word in COLUMNS.split()[1:]:
        ident, _, index = word[2:].partition("[")
        values = np.asarray(sim.computes[ident].peratom(sim))
        if index:
            values = values[:, int(index.rstrip("]")) - 1]
        rows.append(by_tag(sim, values))
    return np.column_stack(rows)


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    folder = tmp_path_factory.mktemp("computes")
    shutil.copy(DATA / "fluid.data", folder / "fluid.data")
    sim = Simulation(screen=False, log=str(folder / "log.case"), dialect="lammps")
    with pytest.MonkeyPatch.context() as patch:
        patch.chdir(folder)
        sim.command(SETUP + THERMO + "\nrun 0")
        first = mine(sim)
        sim.command("run 100")
        last = mine(sim)
        sim.close()
    rows = [line.split(",") for line in (folder / "log.case.csv").read_text().splitlines()[1:]]
    return first, last, rows


@pytest.mark.parametrize("step", [0, 100])
def test_per_particle_values_equal_lammps_dump(run, step):
    got = run[0] if step == 0 else run[1]
    want = lammps_dump(step)
    assert got.shape == want.shape == (200, 14)
    np.testing.assert_allclose(got, want, rtol=1e-12, atol=1e-12 * np.abs(want).max())


def test_per_particle_energies_and_virials_add_up(tmp_path):
    """Sum of pe/atom = pe, sum of the stress/atom traces = -3 P V (with all 3N degrees of freedom in
    the kinetic part, as stress/atom's ke term), on a small box where ghosts carry half the pairs."""
    rng = np.random.default_rng(5)
    x = np.array([[i, j, k] for i in range(3) for j in range(3) for k in range(3)], dtype=float) * 1.5 + 0.4
    x += rng.uniform(-0.1, 0.1, size=x.shape)
    sim = build(tmp_path, x, v=rng.normal(size=x.shape), hi=(4.5, 4.5, 4.5),
                setup="pair_style lj/cut 1.8\npair_coeff * * 1 1\ncompute e all pe/atom\n"
                      "compute s all stress/atom NULL\nrun 0")
    energy = np.sum(sim.computes["e"].peratom(sim))
    stress = sim.computes["s"].peratom(sim)
    assert energy == pytest.approx(observables.potential_energy(sim), rel=1e-12)
    n, volume = len(x), 4.5 ** 3
    ke = observables.kinetic_energy(sim)
    pressure_3n = (2.0 * ke + observables.virial_trace(sim)) / (3.0 * volume)
    assert np.sum(stress[:, :3]) == pytest.approx(-3.0 * pressure_3n * volume, rel=1e-12)
    assert abs(observables.virial_trace(sim)) > 1.0 and n == 27


def test_a_pair_style_without_a_tally_is_named():
    refused = script_error("particle_style sphere\nregion box block 0 5 0 5 0 5\ncreate_box 1 box\n"
                           "create_particle 1 single 1 1 1\npair_style dem/lsd 0.3 1.0\n"
                           "pair_coeff * * 1000 16.6016 314.29 6.3008 0.5 1\ncompute e all pe/atom", "run 0")
    assert refused.message == ("compute e (pe/atom) needs per-particle energies and virials, which pair style "
                               "dem/lsd does not tally")


def test_stress_atom_takes_only_a_null_temperature(tmp_path):
    with pytest.raises(ScriptError, match="compute: temperature t: only NULL"):
        build(tmp_path, [[1.0, 1.0, 1.0]], setup="compute t all temp\ncompute s all stress/atom t")


def test_pe_must_use_group_all(tmp_path):
    with pytest.raises(ScriptError, match="compute pe must use group all"):
        build(tmp_path, [[1.0, 1.0, 1.0]], setup="group one id 1\ncompute p one pe")


# LAMMPS 22 Jul 2025 on this machine (2026-12-02): the scene below, write_dump id c_e (%.17g) and
# thermo c_s (compute reduce sum, %.15g)
EROTATE_SCENE = """
units si
atom_style sphere
atom_modify map array
region b block 0 5 0 5 0 5
create_box 1 b
create_atoms 1 single 1 1 1
create_atoms 1 single 3 3 3
create_atoms 1 single 2 4 1
set atom 1 diameter 1.0 density 2.0
set atom 2 diameter 2.0 density 1.0
set atom 3 diameter 0.3 density 7.0
set atom 1 omega 1.5 -2 0.5
set atom 2 omega 0 0 3
set atom 3 omega -4 1 2
group two id 1 2
compute e two erotate/sphere/atom
compute s all reduce sum c_e
pair_style zero 3.0
pair_coeff * *
fix n all nve/sphere
run 0
"""
LAMMPS_EROTATE = [0.34033920413889424, 7.5398223686155035, 0.0]


def test_erotate_sphere_atom_as_lammps(make_sim):
    """Half I w^2 per sphere of the group, 0 outside it (sphere 3), to LAMMPS's last bits."""
    sim = make_sim(dialect="lammps")
    sim.command(EROTATE_SCENE)
    got = by_tag(sim, sim.computes["e"].peratom(sim))
    np.testing.assert_allclose(got, LAMMPS_EROTATE, rtol=1e-15, atol=0)
    assert sim.computes["s"].scalar(sim) == pytest.approx(7.8801615727544, rel=1e-14)


# LIGGGHTS 3.8.0 on this machine (2026-12-02): two spheres sliding on a wall spin up; thermo c_e c_es
# (erotate, erotate/sphere) alike, 23.1959640967083 at step 1000 and 23.1959640857466 at 2000
EROTATE_LIGGGHTS_SCENE = """
atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region b block 0 5 0 5 0 5 units box
create_box 1 b
create_atoms 1 single 1 1 0.2 units box
create_atoms 1 single 3 3 0.3 units box
set atom 1 diameter 0.4 density 2000
set atom 2 diameter 0.6 density 1000
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 0.3
fix m4 all property/global coefficientFriction peratomtypepair 1 0.5
pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.001
compute e all erotate
compute es all erotate/sphere
fix g all gravity 9.81 vector 0 0 -1
fix w all wall/gran model hertz tangential history primitive type 1 zplane 0.0
velocity all set 1.0 0.5 0 units box
fix n all nve/sphere
thermo_style custom step c_e c_es
thermo_modify format float %.15g
thermo 1000
run 2000
"""


def test_liggghts_erotate_is_erotate_sphere_on_spheres(pdps_cli):
    done = pdps_cli(EROTATE_LIGGGHTS_SCENE, "-log", "none")
    assert done.returncode == 0, done.stderr
    rows = {int(w[0]): (float(w[1]), float(w[2])) for w in (line.split() for line in done.stdout.splitlines())
            if len(w) == 3 and w[0].isdigit()}
    assert all(e == es for e, es in rows.values())
    assert rows[1000][0] == pytest.approx(23.1959640967083, rel=1e-12)
    assert rows[2000][0] == pytest.approx(23.1959640857466, rel=1e-11)
