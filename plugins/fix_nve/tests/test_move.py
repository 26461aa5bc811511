"""Fix move. Its paths against LAMMPS's thermo (linear, wiggle, rotate with units lattice and box,
variable with equal- and atom-style variables) are cases of plugins/fix_simple/tests/data/fixes.txt,
checked by tests/test_recorded_thermo.py; here: the exact path of a free particle, spheres turning
with a rotation, the time origin across reset_timestep (LAMMPS's thermo), and bad lines."""

import io
import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import script_error, thermo_rows

FLUID = Path(__file__).resolve().parents[2] / "fix_simple" / "tests" / "data" / "fluid.data"
BOX = "region box block 0 10 0 10 0 10\ncreate_box 1 box\nmass 1 1\n"


def test_linear_and_wiggle_follow_their_formulas_across_periodic_faces(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command(BOX + "create_atoms 1 single 9.5 5 5 units box\ncreate_atoms 1 single 2 2 2 units box\n"
                "group one id 1\ngroup two id 2\ntimestep 0.01\n"
                "fix 1 one move linear 3.0 NULL 0.0 units box\nfix 2 two move wiggle 0 2.0 0 0.5 units box\nrun 100")
    p = sim.particles
    one, two = p.index_of_tag(1), p.index_of_tag(2)
    # 1 s at 3 along x from 9.5: 12.5, wrapped to 2.5 with one image
    assert p.x[one, 0] == pytest.approx(2.5, abs=1e-12) and p.image[one, 0] == 1
    assert tuple(p.v[one]) == (3.0, 0.0, 0.0)
    assert p.x[two, 1] == pytest.approx(2.0 + 2.0 * math.sin(2 * math.pi * 1.0 / 0.5), abs=1e-12)
    assert p.v[two, 1] == pytest.approx(2.0 * 4 * math.pi * math.cos(4 * math.pi), rel=1e-12)


def test_rotate_turns_spheres_with_the_rotation(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command("atom_style sphere\n" + BOX.replace("mass 1 1\n", "") +
                "create_atoms 1 single 7 5 5 units box\nset atom 1 diameter 1.0 density 1.0\ntimestep 0.01\n"
                "fix 1 all move rotate 5 5 5 0 0 1 4.0 units box\nrun 100")
    p = sim.particles
    angle = 2 * math.pi * 1.0 / 4.0
    np.testing.assert_allclose(p.x[0], [5 + 2 * math.cos(angle), 5 + 2 * math.sin(angle), 5], atol=1e-12)
    np.testing.assert_allclose(p.omega[0], [0, 0, 2 * math.pi / 4.0], atol=1e-15)
    np.testing.assert_allclose(p.v[0], [-2 * math.sin(angle) * math.pi / 2, 2 * math.cos(angle) * math.pi / 2, 0],
                               atol=1e-12)


# LAMMPS 22 Jul 2025 on this machine: the fluid's heavy particles moved linearly (units box), 10
# steps, reset_timestep 0, 10 steps: thermo at 0, 5, 10 of the second run. The origin stays a step:
# after the reset the heavy particles are put back on the path's start.
RESET_LAMMPS = [[0, 1.31476948663639, -0.412761910780433, 10.6389952168941],
                [5, 1.65844214209706, -0.938952200304671, 9.35573629852166],
                [10, 1.92074871127066, -1.32145654312335, 8.40253774150917]]


def test_the_time_origin_is_a_step_across_reset_timestep_as_lammps(tmp_path, monkeypatch):
    shutil.copy(FLUID, tmp_path / "fluid.data")
    monkeypatch.chdir(tmp_path)
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None, dialect="lammps")
    sim.command("""units lj
atom_style atomic
read_data fluid.data
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0
pair_coeff 2 2 0.5 1.2
group heavy type 2
group light type 1
fix 1 light nve
fix 2 heavy move linear 0.5 NULL -0.2 units box
timestep 0.002
thermo 5
thermo_style custom step temp pe press
thermo_modify format float %.15g
run 10
reset_timestep 0""")
    screen.seek(0)
    screen.truncate()
    sim.command("run 10")
    np.testing.assert_allclose(thermo_rows(screen.getvalue()), RESET_LAMMPS, rtol=1e-11, atol=1e-13)


@pytest.mark.parametrize("line, message", [
    ("fix 2 all move spin 1 2 3", "motion must be one of linear, wiggle, rotate, variable (got spin)"),
    ("fix 2 all move wiggle 1 0 0 0 units box", "PERIOD must be > 0 (got 0)"),
    ("fix 2 all move rotate 0 0 0 0 0 0 1 units box", "the rotation axis RX RY RZ has zero length"),
    ("fix 2 all move variable v_nope NULL NULL NULL NULL NULL", "variable nope is not defined (v_nope)"),
    ("fix 2 all move variable dx NULL NULL NULL NULL NULL", "fix move variable takes v_NAME or NULL (got dx)"),
])
def test_bad_fix_move_lines(line, message):
    error = script_error(BOX, line)
    assert error.message == message, error.message
