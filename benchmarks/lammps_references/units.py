"""Record what LAMMPS prints for one liquid-argon scene written in each of its unit systems, the
reference tests/test_units_lammps.py compares pdps with to the printed digits.

    python benchmarks/lammps_references/units.py [LMP]

The scene (script(style)): 256 argon atoms on an fcc lattice, velocities from ``velocity create``
(LAMMPS's Park-Miller numbers), lj/cut with epsilon = 1.654e-21 J and sigma = 3.405e-10 m written in
the style's units (the skin 0.3 sigma: the defaults of si, cgs and micro are larger than the box), 100 NVE steps of about 2 fs, thermo every 10 steps with 15 digits. Every constant of
the style enters: boltz (temperature), ftm2v (the kick), mvv2e (kinetic energy), nktv2p (pressure).
LAMMPS's thermo tables go to tests/data/lammps/units.txt, one block per style.
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from lammps_run import run_lammps, thermo_lines, write_blocks  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "tests" / "data" / "lammps" / "units.txt"
# (lattice constant, epsilon, sigma, mass, timestep, temperature) in each style's units
ARGON = {
    "real": (5.256, 0.2381, 3.405, 39.948, 2.0, 100.0),
    "metal": (5.256, 0.010323, 3.405, 39.948, 0.002, 100.0),
    "si": (5.256e-10, 1.654e-21, 3.405e-10, 6.6335e-26, 2e-15, 100.0),
    "cgs": (5.256e-8, 1.654e-14, 3.405e-8, 6.6335e-23, 2e-15, 100.0),
    "micro": (5.256e-4, 1.654e-6, 3.405e-4, 6.6335e-11, 2e-9, 100.0),
    "nano": (0.5256, 1.654, 0.3405, 6.6335e-5, 2e-6, 100.0),
}
STYLES = tuple(ARGON)


def script(style):
    a, epsilon, sigma, mass, dt, temperature = ARGON[style]
    return f"""units {style}
atom_style atomic
lattice fcc {a!r}
region box block 0 4 0 4 0 4
create_box 1 box
create_atoms 1 box
mass 1 {mass!r}
velocity all create {temperature!r} 4928459 loop geom
pair_style lj/cut {2.5 * sigma!r}
pair_coeff 1 1 {epsilon!r} {sigma!r}
neighbor {0.3 * sigma!r} bin
timestep {dt!r}
fix 1 all nve
thermo_style custom step temp pe ke etotal press
thermo_modify format float %20.15g
thermo 10
run 100
"""


def main(lmp):
    write_blocks(OUT, {style: thermo_lines(run_lammps(lmp, script(style), label=style)) for style in STYLES})


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp"))
