"""Record LAMMPS's statistics for fix langevin's omega, tally and gjf keywords, the reference
plugins/fix_langevin/tests/test_langevin_options.py compares pdps with.

    python benchmarks/lammps_references/langevin_options.py [LMP]

pdps's random numbers are not LAMMPS's, so the comparison is of averages with honest error bars, not
of trajectories. The scenes are the scripts in plugins/fix_langevin/tests/data (OPTIONS, SEED and
STEPS filled in here and by the test alike):

- in.harmonic: 200 particles in a harmonic well along x at dt = 1/omega, with ``gjf no``, ``gjf
  vhalf`` and ``gjf vfull``: the mean wall energy per particle (kT/2 when positions are Boltzmann's)
  and the mean kinetic temperature, block averages over 20 blocks of 100 thermo lines (1000 time
  units, hundreds of relaxation times each).
- in.spheres: 300 free spheres with ``omega yes``: the mean translational temperature and the mean
  rotational one, 2 E_rot / (3 N), 20 blocks of 100 lines (10 time units each, 20 damping times).
- in.heating: 500 LJ atoms heated from 1.0 to 1.6 with ``tally yes``, on a ramp over 2000 steps and
  at once (target 1.6 from the first step): the slope of f_t against time on the ramp (the rate the
  bath gives energy, negative), f_t's change at once, and the changes of econserve, one value per seed
  over 16 seeds.

Each line of plugins/fix_langevin/tests/data/langevin_options.txt: case, quantity, mean, standard
error, number of blocks (or seeds).

The exact part: at T = 0 the thermostat is friction only, so LAMMPS's forces and torques on two
spheres (``scale 2 4.0 omega yes``) at ``run 0``'s thermo are recorded
(particle 1's torque is the larger, -2.5 against -5) to 15 digits as case ``friction``.
"""

import sys
from pathlib import Path

import numpy as np

from pdps_core.testing import lj_fcc

from lammps_run import run_lammps, thermo_lines

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "fix_langevin" / "tests" / "data"
BLOCKS = 20

FRICTION = """units lj
atom_style sphere
atom_modify map yes
region box block 0 10 0 10 0 10
create_box 2 box
create_atoms 1 single 2 2 2
create_atoms 2 single 6 6 6
set type 1 diameter 1.0
set type 2 diameter 2.0
set type 1 mass 1.0
set type 2 mass 2.0
velocity all set 0.5 -0.25 0.125
set atom * omega 0.5 -1.0 3.0
fix 1 all langevin 0 0 0.4 9 scale 2 4.0 omega yes
compute tq all property/atom tqz
compute t1 all reduce max c_tq
compute t2 all reduce min c_tq
variable f1 equal fx[1]
variable f2 equal fx[2]
thermo_style custom step v_f1 v_f2 c_t1 c_t2
thermo_modify format float %.15g
run 0
"""

# At T = 0 the thermostat is deterministic (friction, GJF's scaling, the tally): thermo to 15 digits
EXACT = lj_fcc(4, density=0.8) + """mass 1 1.0
velocity all create 1.5 4928 dist gaussian
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0
timestep 0.005
fix t all langevin 0.0 0.0 0.5 5 OPTIONS
fix 1 all nve
thermo_style custom step temp pe etotal f_t
thermo_modify format float %.15g norm no
thermo 25
run 100
"""
EXACT_CASES = {"exact_tally": "tally yes", "exact_vhalf": "gjf vhalf tally yes",
               "exact_vfull": "gjf vfull tally yes", "exact_vhalf_zero": "gjf vhalf zero yes"}


def script(name, seed, options="", steps=20000, tstart=1.0):
    text = (DATA / name).read_text()
    return (text.replace("SEED", str(seed)).replace("OPTIONS", options).replace("STEPS", str(steps))
            .replace("TSTART", str(tstart)))


def production(log):
    """The thermo lines of the last table (the production run), as floats."""
    tables, rows = [], None
    for line in log.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            rows = []
            tables.append(rows)
        elif line.startswith("Loop time"):
            rows = None
        elif rows is not None and words:
            rows.append([float(w) for w in words])
    return np.array(tables[-1])


def block_mean(values, blocks=BLOCKS):
    usable = len(values) // blocks * blocks
    means = values[:usable].reshape(blocks, -1).mean(axis=1)
    return means.mean(), means.std(ddof=1) / np.sqrt(blocks), blocks


def main(lmp):
    lines = []
    log = run_lammps(lmp, FRICTION, label="friction")
    lines.append("friction\tvalues\t" + "\t".join(f"{float(w):.15g}" for w in thermo_lines(log)[0][1:]))
    for case, options in EXACT_CASES.items():
        for words in thermo_lines(run_lammps(lmp, EXACT.replace("OPTIONS", options), label=case)):
            lines.append(f"{case}\tthermo\t" + "\t".join(words))
    for case, options in (("gjf_no", ""), ("gjf_vhalf", "gjf vhalf"), ("gjf_vfull", "gjf vfull")):
        rows = production(run_lammps(lmp, script("in.harmonic", 5807, options), label=case))
        rows = rows[1:]                          # the run's first line repeats the equilibration's last
        for quantity, values in (("temp", rows[:, 1]), ("wall_energy_per_particle", rows[:, 2] / 200)):
            lines.append(f"{case}\t{quantity}\t" + "\t".join(f"{x:.10g}" for x in block_mean(values)))
    rows = production(run_lammps(lmp, script("in.spheres", 3319), label="omega"))[1:]
    lines.append("omega\ttemp\t" + "\t".join(f"{x:.10g}" for x in block_mean(rows[:, 1])))
    lines.append("omega\trotational_temp\t"
                 + "\t".join(f"{x:.10g}" for x in block_mean(rows[:, 2] * 2.0 / (3.0 * 300))))
    slopes, ramp_changes, exchanged, step_changes = [], [], [], []
    for seed in range(101, 117):
        rows = production(run_lammps(lmp, script("in.heating", seed, steps=2000), label=f"tally {seed}"))
        slopes.append(np.polyfit(rows[:, 0] * 0.005, rows[:, 3], 1)[0])
        ramp_changes.append(rows[-1, 4] - rows[0, 4])
        rows = production(run_lammps(lmp, script("in.heating", seed, steps=2000, tstart=1.6),
                                     label=f"tally {seed}"))
        exchanged.append(rows[-1, 3] - rows[0, 3])
        step_changes.append(rows[-1, 4] - rows[0, 4])
    for quantity, values in (("f_t_slope", slopes), ("econserve_change_ramp", ramp_changes),
                             ("f_t_change_step", exchanged), ("econserve_change_step", step_changes)):
        values = np.array(values)
        lines.append(f"tally\t{quantity}\t{values.mean():.10g}\t{values.std(ddof=1) / np.sqrt(len(values)):.10g}"
                     f"\t{len(values)}")
    (DATA / "langevin_options.txt").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
