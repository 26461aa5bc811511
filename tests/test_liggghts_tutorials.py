"""LIGGGHTS's cohesion and contactModels tutorials (Tutorials_public/cohesion/in.cohesion,
contactModels/in.newModels; issue 32): pdps's translational and rotational kinetic energies at every
thermo row against LIGGGHTS 3.8.0's over eight insertion seeds, recorded by
benchmarks/liggghts_references/tutorials.py into benchmarks/results/liggghts_tutorials.json. The
scenes are written here from the tutorials' settings (the scripts are GPL and stay out of the
project): the same commands with the dumps left out and the seeds of particletemplate/sphere,
particledistribution/discrete and insert/pack replaced. Full length, unshortened: 20-70 s per run,
four runs; behind the `slow` marker.

The criterion, per tutorial, energy and row: the geometric mean of pdps's two runs lies within
LIGGGHTS's range over its eight seeds (log10) widened by that range on each side (by 0.1 % where the
runs agree, as in free fall before any contact). Measured (the benchmark, six pdps seeds): every
pair of pdps seeds passes, the worst at 0.61 of the widening. The old faults fail it: the rotational
energy at the first impact 0.36 of LIGGGHTS's by 7 times the widening at step 9000, the
contactModels bed's kinetic energy 2 or 4 times too low after step 27,000 by up to 6 or 12 times (at
7 or 17 of 24 rows). Tighter criteria do not hold for LIGGGHTS itself: one of its runs lies outside
the min..max band of three others at 5-38 of 42-50 rows, and even this one, two of its seeds held
out against the other six, fails in 2, 8, 3 and 3 of the 28 choices (cohesion ke, rke; contactModels
ke, rke): the seed-to-seed spread has long tails."""

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

RESULTS = Path(__file__).resolve().parents[1] / "benchmarks" / "results" / "liggghts_tutorials.json"
# the first two of the benchmark's PDPS_SEEDS
SEEDS = [(110000017, 110000039, 110000057), (120000007, 120000031, 120000043)]
EVERY = 1000
SAME = 4e-4         # log10 of 1.001: the range of rows where all of LIGGGHTS's runs agree

COMMON = """atom_style granular
atom_modify map array
boundary m m m
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 0. 0.15 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
fix m1 all property/global youngsModulus peratomtype 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 1 {e}
fix m4 all property/global coefficientFriction peratomtypepair 1 0.05
{material}pair_style gran model hertz tangential history{cohesion}
pair_coeff * *
timestep 0.00001
fix gravi all gravity 9.81 vector 0.0 0.0 -1.0
fix zwalls1 all wall/gran model hertz tangential history primitive type 1 zplane 0.0
fix zwalls2 all wall/gran model hertz tangential history primitive type 1 zplane 0.15
fix cylwalls all wall/gran model hertz tangential history primitive type 1 zcylinder 0.05 0. 0.
"""
THERMO = """compute rke all erotate/sphere
thermo_style custom step atoms ke c_rke vol
thermo 1000
thermo_modify lost ignore norm no
"""
SCENES = {
    "cohesion": COMMON.format(
        e=0.9, cohesion=" cohesion sjkr",
        material="fix m5 all property/global characteristicVelocity scalar 2.\n"
                 "fix m6 all property/global cohesionEnergyDensity peratomtypepair 1 300000\n") + """\
region bc cylinder z 0.01 0.01 0.025 0.05 0.0603 units box
group nve_group region reg
fix pts1 all particletemplate/sphere {0} atom_type 1 density constant 2500 radius constant 0.0015
fix pdd1 all particledistribution/discrete {1} 1 pts1 1.0
fix ins nve_group insert/pack seed {2} distributiontemplate pdd1 maxattempt 100 insert_every 3000 &
    overlapcheck yes all_in yes vel constant 0.0 0.0 -0.2 region bc particles_in_region 250 ntry_mc 10000
fix integr nve_group nve/sphere
""" + THERMO + """run 1
run 10000
unfix ins
run 50000 upto
""",
    "contactModels": COMMON.format(e=0.95, cohesion="", material="") + """\
region bc cylinder z 0. 0. 0.045 0.00 0.15 units box
fix pts1 all particletemplate/sphere {0} atom_type 1 density constant 2500 radius constant 0.0025
fix pdd1 all particledistribution/discrete {1} 1 pts1 1.0
fix ins all insert/pack seed {2} distributiontemplate pdd1 vel constant 0. 0. -0.5 &
    insert_every once overlapcheck yes all_in yes particles_in_region 1800 region bc
fix integr all nve/sphere
""" + THERMO + """run 5000
unfix ins
run 50000 upto
""",
}


def thermo_table(screen):
    """[step, atoms, ke, rke] of the thermo rows at multiples of EVERY, each step's first printing."""
    rows = {}
    for line in screen.splitlines():
        words = line.split()
        if len(words) == 5 and words[0].isdigit() and words[1].isdigit() and int(words[0]) % EVERY == 0:
            rows.setdefault(int(words[0]), [int(words[0]), int(words[1]), float(words[2]), float(words[3])])
    return np.array([rows[step] for step in sorted(rows)])


def run_pdps(script, folder):
    (folder / "in.tutorial").write_text(script)
    done = subprocess.run([sys.executable, "-m", "pdps_core.cli", "run", "in.tutorial", "-log", "none",
                           "--no-progress"], cwd=folder, capture_output=True, text=True, timeout=1800)
    assert done.returncode == 0, done.stderr
    return thermo_table(done.stdout)


def widened_range_excess(liggghts, pdps):
    """Per row, how far the log10 geometric mean of ``pdps``'s runs lies outside LIGGGHTS's range
    over its runs, in units of that range (0 inside; at most 1 passes), and the rows' ranges."""
    logs, mine = np.log10(liggghts), np.log10(pdps).mean(axis=0)
    low, high = logs.min(axis=0), logs.max(axis=0)
    spread = np.maximum(high - low, SAME)
    return np.maximum(np.maximum(low - mine, mine - high), 0.0) / spread, spread


@pytest.mark.slow
@pytest.mark.parametrize("name", sorted(SCENES))
def test_tutorial_energies_within_liggghts_spread_over_seeds(name, tmp_path):
    recorded = json.loads(RESULTS.read_text())
    assert recorded["steps"] is None                    # recorded unshortened, as run here
    liggghts = np.array(recorded["runs"][name])         # (seed, row, [step, atoms, ke, rke])
    pdps = np.array([run_pdps(SCENES[name].format(*seeds), tmp_path) for seeds in SEEDS])
    assert pdps.shape[1:] == liggghts.shape[1:]
    np.testing.assert_array_equal(pdps[:, :, :2], liggghts[:2, :, :2])     # steps and particle counts
    for column, label in ((2, "ke"), (3, "rke")):
        moving = liggghts[:, :, column].min(axis=0) > 0.0
        excess, spread = widened_range_excess(liggghts[:, moving, column], pdps[:, moving, column])
        steps = liggghts[0, moving, 0].astype(int)
        worst = int(np.argmax(excess))
        print(f"{name} {label}: {moving.sum()} rows, worst at step {steps[worst]}: {excess[worst]:.2f} of the "
              f"range (x/ {10 ** spread[worst]:.3f})")
        assert excess.max() <= 1.0, [(int(s), round(float(x), 2)) for s, x in zip(steps, excess) if x > 1.0]
        # no spin before the first contact, in LIGGGHTS and here
        assert (pdps[:, ~moving, column] == 0.0).all()
