"""Record LAMMPS's compute ke/rigid and erotate/rigid on the 27 LJ bodies of rigid_small.py's scene
(plugins/fix_rigid/tests/data/rigid_small_lj.data) under fix rigid, rigid/small and rigid/nvt/small:
the reference plugins/fix_rigid/tests/test_rigid_energies.py compares pdps with.

    python benchmarks/lammps_references/rigid_energies.py [LMP]

Thermo (15 digits; lj units, so the extensive computes are printed per particle, as pdps prints them)
every 500 steps over 2000 steps, into plugins/fix_rigid/tests/data/rigid_energies.txt.
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from lammps_run import run_lammps, thermo_lines, write_blocks  # noqa: E402
from rigid import lj_bodies  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
DATA = ROOT / "plugins" / "fix_rigid" / "tests" / "data"
STYLES = {"rigid": "rigid molecule", "rigid/small": "rigid/small molecule",
          "rigid/nvt/small": "rigid/nvt/small molecule temp 0.5 0.4 1.0"}
SCRIPT = lj_bodies("rigid_small_lj.data") + """timestep 0.001
fix 1 all {fix}
compute trans all ke/rigid 1
compute rot all erotate/rigid 1
compute kinetic all ke
thermo_style custom step c_trans c_rot c_kinetic
thermo_modify format float %20.15g
thermo 500
run 2000
"""


def main():
    lmp = sys.argv[1] if len(sys.argv) > 1 else str(ROOT.parent / "shared" / "bench" / "lmp")
    tables = {name: thermo_lines(run_lammps(lmp, SCRIPT.format(fix=fix), [DATA / "rigid_small_lj.data"], name))
              for name, fix in STYLES.items()}
    write_blocks(DATA / "rigid_energies.txt", tables)
    print(f"wrote {DATA / 'rigid_energies.txt'}")


if __name__ == "__main__":
    main()
