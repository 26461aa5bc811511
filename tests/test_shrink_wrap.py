"""boundary s and m (LAMMPS, LIGGGHTS): shrink-wrapped faces follow the particles at each neighbor
list rebuild, m never inside its first position; f loses the particle instead."""

import numpy as np
import pytest

from pdps_core.api import Simulation

SCRIPT = """
units lj
atom_style atomic
boundary {x} p {z}
region r block 0 10 0 10 0 10
create_box 1 r
create_atoms 1 single 5 5 5 units box
create_atoms 1 single 5 5 6 units box
mass 1 1.0
velocity all set 0 0 {vz} units box
fix 1 all nve
"""


@pytest.mark.parametrize("z", ["m", "fm", "sm", "s"])
def test_a_particle_leaving_through_a_shrink_wrapped_face_grows_the_box(z):
    """Moving up at 2 for 5 time units from z = 6: z = 16, past the face at 10, which follows it at
    each rebuild (1e-4 of the box length beyond it, LAMMPS's margin), so the particle is never more
    than half the skin (0.15) beyond it; the lower face stays (f, m) or wraps the lower particle
    now at z = 15 (s)."""
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SCRIPT.format(x="f", z=z, vz=2.0) + "run 1000")
    top = sim.x[:, 2].max()
    assert top == pytest.approx(16.0, rel=1e-12)
    assert 0.0 <= top - sim.box.hi[2] < 0.15
    if z in ("m", "fm"):
        assert sim.box.lo[2] == 0.0
    else:
        assert 0.0 < 15.0 - sim.box.lo[2] < 0.15 + 2e-3


def test_m_faces_never_move_inside_their_first_position_and_s_faces_do():
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SCRIPT.format(x="s", z="m", vz=0.0) + "run 10")
    # x shrinks to the particles (margin 1e-4 of the first length, 10), z keeps [0, 10]
    assert list(sim.box.lo[[0, 2]]) == pytest.approx([5.0 - 1e-3, 0.0], rel=1e-12)
    assert sim.box.hi[0] == pytest.approx(5.0 + 1e-3, rel=1e-12)
    assert sim.box.hi[2] == 10.0


def test_a_fixed_face_loses_the_particle(pdps_cli):
    done = pdps_cli(SCRIPT.format(x="f", z="f", vz=2.0) + "run 1000\n")
    assert done.returncode == 1
    assert "lost through the fixed z boundary" in done.stderr


def test_bad_boundary_word(pdps_cli):
    done = pdps_cli("boundary p p pm\n")
    assert done.returncode == 1
    assert done.stderr.strip() == ("ERROR: in.test:1: boundary: boundary z must be one of p, f, s, m, ff, fs, fm, "
                                   "sf, ss, sm, mf, ms, mm (got pm)")


def test_a_restart_keeps_the_shrink_wrapped_faces(tmp_path):
    """Written and read back, boundary m still grows the box: the run goes on instead of losing
    the particle (the restart's box is the m face's new minimum, as LAMMPS's read_restart)."""
    path = tmp_path / "r.restart"
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(SCRIPT.format(x="f", z="m", vz=2.0) + f"run 100\nwrite_restart {path}")
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(f"read_restart {path}\nfix 1 all nve\nrun 900")
    assert sim.x[:, 2].max() == pytest.approx(16.0, rel=1e-12)
    assert sim.system.periodicity == ("f", "p", "m")


# A 2-d LJ slab pulled apart in y (boundary s s p; this file's own script, after LAMMPS's examples/crack),
# LAMMPS 22 Jul 2025 thermo step pe press vol lx ly. The faces keep the margin of the box they were made
# with (LAMMPS's small); with the margin of the current box pdps's volume was 5e-7 off from step 200.
PULLED_SLAB = """
dimension 2
boundary s s p
atom_style atomic
neighbor 0.3 bin
neigh_modify delay 5
lattice hex 0.93
region box block 0 30 0 12 -0.25 0.25
create_box 2 box
create_atoms 1 box
mass * 1.0
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0 2.5
region 1 block INF INF INF 1.25 INF INF
group lower region 1
region 2 block INF INF 10.75 INF INF INF
group upper region 2
group boundary union lower upper
group mobile subtract all boundary
set group upper type 2
velocity mobile create 0.01 887723
velocity upper set 0.0 0.3 0.0
velocity mobile ramp vy 0.0 0.3 y 1.25 10.75 sum yes
fix 1 all nve
fix 2 boundary setforce NULL 0.0 0.0
timestep 0.003
thermo 200
thermo_style custom step pe press vol lx ly
run 1000
"""
PULLED_SLAB_LAMMPS = [
    [0, -3.1449816, 0.00026364857, 774.50326, 33.434999, 23.164447],
    [200, -3.1298252, -0.6488798, 784.52035, 33.451051, 23.452787],
    [400, -3.1026804, -1.0977736, 793.7124, 33.444195, 23.732441],
    [600, -3.0631202, -1.3432866, 805.90787, 33.39589, 24.131948],
    [800, -3.0148224, -1.4638292, 817.92723, 33.330178, 24.54014],
    [1000, -2.9587072, -1.4620988, 824.27196, 33.240507, 24.797214],
]


def test_shrink_wrapped_faces_keep_the_margin_of_the_box_made_as_lammps(pdps_cli):
    from pdps_core.testing import thermo_rows
    result = pdps_cli(PULLED_SLAB, name="in.slab")
    assert result.returncode == 0, result.stderr
    np.testing.assert_allclose(thermo_rows(result.stdout), PULLED_SLAB_LAMMPS, rtol=5e-8)
