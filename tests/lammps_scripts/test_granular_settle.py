"""The granular settling scene of the bench in LAMMPS's pair granular (benchmarks/scenes/lammps/
in.granular_settle, pdps's own file, run with its thermo printed to 15 digits) against LAMMPS 22 Jul
2025's numbers for the same file and data: 20,000 Hertz beads (hertz/material, coeff_restitution,
mindlin NULL, rolling sds) under gravity between a floor and four side walls of fix wall/gran
granular. LAMMPS printed (``thermo 1000``, ``format float %.15g``):

    Step  Atoms  KinEng               c_rke
       0  20000  0.00474224662970621  0
    1000  20000  0.00526249211471218  0.000333791345296328

pdps printed the same to 1e-15 (5e-15 for c_rke). Beyond step 1000 LAMMPS's own numbers depend on
its atom sort (every 1000 steps by default): it hands a contact's rolling displacement to the other
sphere negated, so a sort that makes the other sphere hold the contact flips its rolling spring
(LAMMPS with ``atom_modify sort 0 0.0`` prints 0.0081351732525921 at step 1500, with its default sort
0.00813515661099386); pdps hands it on unchanged, as it is the same seen from either sphere, and
prints 0.00813517325259166 there, LAMMPS's unsorted number to 6e-14.
"""

from pathlib import Path

import pytest

from pdps_core.testing import bench_data

SCENE = Path(__file__).parents[2] / "benchmarks" / "scenes" / "lammps" / "in.granular_settle"
LAMMPS = {"0": (0.00474224662970621, 0.0), "1000": (0.00526249211471218, 0.000333791345296328)}


def test_the_settling_scene_in_pair_granular_runs_as_in_lammps(pdps_cli, tmp_path):
    bench_data("settle", tmp_path / "settle.data")
    script = SCENE.read_text().replace("thermo_modify norm no", "thermo_modify norm no format float %.15g")
    done = pdps_cli(script, "-var", "scenes", ".", "-var", "nsteps", "1000", "-log", "none", "--no-progress",
                    name="in.granular_settle")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    start = next(k for k, line in enumerate(lines) if line.split()[:1] == ["Step"])
    for line in lines[start + 1:start + 3]:
        step, atoms, ke, rke = line.split()
        assert atoms == "20000"
        assert float(ke) == pytest.approx(LAMMPS[step][0], rel=1e-13, abs=0)
        assert float(rke) == pytest.approx(LAMMPS[step][1], rel=1e-13, abs=0)
