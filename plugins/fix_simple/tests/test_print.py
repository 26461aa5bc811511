"""fix print beside LAMMPS: which steps print, and the energies its text reads on steps that are not
thermo steps."""

import numpy as np
import pytest

from pdps_core.testing import lj_fcc


# LAMMPS 22 Jul 2025 on FIX_PRINT (this file's script): its PRINT lines. A line at each run's first
# step that is a multiple of N (step 9 twice with runs of 9 and 3), and pe and press on steps that
# are not thermo steps; pdps printed no first line and stopped at step 3 ("potential energy was not
# computed").
FIX_PRINT = "\n" + lj_fcc(3) + """mass 1 1.0
velocity all create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
fix 1 all nve
fix p all print 3 "PRINT $(step) $(pe:%.10f) $(press:%.10f)"
thermo 10
run {first}
run {second}
"""
FIX_PRINT_LAMMPS = {
    (10, 5): [(0, -6.7733680533, -4.9807422701), (3, -6.7413067384, -4.7805119126),
              (6, -6.6300383420, -4.1409783178), (9, -6.3972689947, -2.9643536934),
              (12, -6.0446596988, -1.3234450529), (15, -5.7027470830, 0.2275920203)],
    (9, 3): [(0, -6.7733680533, -4.9807422701), (3, -6.7413067384, -4.7805119126),
             (6, -6.6300383420, -4.1409783178), (9, -6.3972689947, -2.9643536934),
             (9, -6.3972689947, -2.9643536934), (12, -6.0446596988, -1.3234450529)],
}


@pytest.mark.parametrize("runs", sorted(FIX_PRINT_LAMMPS))
def test_fix_print_lines_and_energies_are_lammps(pdps_cli, runs):
    result = pdps_cli(FIX_PRINT.format(first=runs[0], second=runs[1]), name="in.print")
    assert result.returncode == 0, result.stderr
    lines = [line.split()[1:] for line in result.stdout.splitlines() if line.startswith("PRINT")]
    got = [(int(step), float(pe), float(press)) for step, pe, press in lines]
    assert [row[0] for row in got] == [row[0] for row in FIX_PRINT_LAMMPS[runs]]
    np.testing.assert_allclose([row[1:] for row in got], [row[1:] for row in FIX_PRINT_LAMMPS[runs]], rtol=1e-9)
