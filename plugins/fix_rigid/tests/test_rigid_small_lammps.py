"""fix rigid/small, rigid/nve/small and rigid/nvt/small against LAMMPS (22 Jul 2025) on 27 small bodies of
Lennard-Jones particles drifting across the periodic boundaries (one straddling x and y at the start):
temperature, total energy, pressure (the constraint virial) and f_1 over 10^4 steps, recorded by
benchmarks/lammps_references/rigid_small.py into tests/data/rigid_small_lj.txt; the same thermo on 1 and
2 ranks, bodies crossing the ranks' boundary."""

import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from pdps_core.testing import lj_fcc, run_ranks, thermo_on_ranks, thermo_rows

# the recorder's own scene and settings, so the test runs what LAMMPS ran
sys.path.insert(0, str(Path(__file__).resolve().parents[3] / "benchmarks" / "lammps_references"))
from lammps_run import read_blocks  # noqa: E402
from rigid import DRAG, SCRIPT as RIGID_SCRIPT  # noqa: E402  (fix rigid's scene, for the drag)
from rigid_small import FREE, INFILE, PLANE, STYLES as EXTRA, script  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
from test_rigid_lammps import assert_thermo_of_bodies_as_lammps, pdps_thermo, relative_differences  # noqa: E402

DATA = Path(__file__).with_name("data")
STYLES = ["rigid/small", "rigid/nve/small", "rigid/nvt/small"]


@pytest.mark.parametrize("style", STYLES)
def test_thermo_matches_lammps_over_ten_thousand_steps(pdps_cli, tmp_path, style):
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    ours = pdps_thermo(pdps_cli, script(style))
    lammps = read_blocks(DATA / "rigid_small_lj.txt")[style]
    assert ours.shape == lammps.shape
    assert_thermo_of_bodies_as_lammps(ours, lammps, f"{style} over 1e4 steps")
    # f_1: the bodies' temperature (rigid/small), the Hamiltonian's kinetic part (+ the chains' energy)
    assert ours[:, 6] == pytest.approx(lammps[:, 6], rel=1e-5)
    if style == "rigid/nvt/small":
        # ecouple and econserve (etotal + ecouple)
        assert ours[:, 7:] == pytest.approx(lammps[:, 7:], rel=1e-5, abs=1e-5 * np.abs(lammps[:, 7]).max())


def rigid_reference(name):
    return read_blocks(DATA / "rigid_lj.txt")[name]


@pytest.mark.parametrize("small, rigid", [("rigid/small", "rigid"), ("rigid/nve/small", "rigid/nve")])
def test_langevin_drag_matches_lammps_over_ten_thousand_steps(pdps_cli, tmp_path, small, rigid):
    """langevin 0.0 0.0 2.0 SEED: the Langevin drag alone (no noise at T = 0) on each body's
    translation and rotation about its principal axes, applied by the rank owning the body. Compared
    with LAMMPS's fix rigid and rigid/nve under the same keyword on fix rigid's scene (LAMMPS: the
    small variants give the same answers): LAMMPS's own rigid/small adds its Langevin array to the
    bodies' forces at the run's set-up before anything was written to it (22 Jul 2025: uninitialised
    memory; on the rigid/small recorder's scene one body's coordinates were NaN after one step of a
    20-step run), so its runs are no reference. Temperature and total energy to 5 significant
    digits over 10^4 steps, the bodies' temperature (f_1 of rigid/small; rigid/nve/small's f_1 is
    another quantity) and pressure too."""
    shutil.copy(DATA / "rigid_lj.data", tmp_path)
    ours = pdps_thermo(pdps_cli, RIGID_SCRIPT.format(style=small, extra=DRAG, steps=10000).replace(
        " f_1 ecouple econserve", " f_1"))
    lammps = rigid_reference(f"{rigid} drag")[:, :7]
    assert ours.shape == lammps.shape == (101, 7)
    # the drag does its work: the particles' temperature falls by more than half over the run
    assert lammps[-1, 1] < 0.5 * lammps[0, 1]
    assert_thermo_of_bodies_as_lammps(ours, lammps, f"{small} drag against LAMMPS's {rigid} drag over 1e4 steps")
    if small == "rigid/small":
        assert ours[:, 6] == pytest.approx(lammps[:, 6], rel=1e-5)


@pytest.mark.parametrize("style", STYLES)
def test_same_thermo_on_one_and_two_ranks(tmp_path, style):
    """On 2 ranks bodies are owned by the rank of their owner particle, cross the ranks' boundary
    and the periodic ones, and have particles on both ranks: the same thermo as on one."""
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    text = script(style, steps=3000)
    one, two = thermo_on_ranks(text, tmp_path)
    assert one.shape == two.shape == (31, 9 if style == "rigid/nvt/small" else 7)
    assert two == pytest.approx(one, rel=1e-10, abs=1e-13)


@pytest.mark.parametrize("style", ["rigid/small", "rigid/nve/small"])
def test_langevin_noise_is_the_same_on_one_and_two_ranks(tmp_path, style):
    """langevin at T = 1 (noise keyed by the id of each body's owner particle, not by a body number a
    rank gives it): the same thermo on 2 ranks as on one while the bodies cross the ranks' boundary;
    and the noise acts (the run ends far from the drag-free run's temperature)."""
    shutil.copy(DATA / "rigid_small_lj.data", tmp_path)
    plain = script(style, steps=3000)
    text = plain.replace(f"{style} molecule\n", f"{style} molecule langevin 1.0 1.0 0.5 428984\n")
    assert text != plain
    one, two = thermo_on_ranks(text, tmp_path)
    free = np.array(thermo_rows(run_ranks(plain, 1, tmp_path).stdout))
    assert one.shape == two.shape == (31, 7)
    assert two == pytest.approx(one, rel=1e-10, abs=1e-13)
    assert abs(one[-1, 1] - free[-1, 1]) > 0.05


@pytest.mark.parametrize("scene", ["free", "plane", "infile"])
@pytest.mark.parametrize("style", STYLES)
def test_linear_2d_and_infile_bodies_match_lammps(pdps_cli, tmp_path, scene, style):
    """A dimer (linear: 5 degrees of freedom in 3d) and a triangle pushed across the periodic x
    boundary by fix addforce, in 3d and in 2d (fix enforce2d), and in 3d with the bodies' masses,
    centres of mass (one given with an image flag), inertia tensors and motion from an infile:
    temperature, kinetic energy, pressure and f_1 (LAMMPS's count: 6 a body less its linear ones in
    3d, 6 a body in 2d) over 2000 steps."""
    shutil.copy(DATA / "rigid_small_bodies.txt", tmp_path)
    text = {"free": FREE, "plane": PLANE, "infile": INFILE}[scene].format(style=style, extra=EXTRA[style])
    ours = pdps_thermo(pdps_cli, text)
    lammps = read_blocks(DATA / "rigid_small_lj.txt")[f"{scene} {style}"]
    assert ours.shape == lammps.shape == (11, 5)
    worst = relative_differences(ours, lammps).max()
    print(f"{scene} {style}: largest difference from LAMMPS, relative to each column's largest value: {worst:.1e}")
    assert worst < 1e-5


def test_langevin_on_bodies_of_equal_moments_is_the_same_on_one_and_two_ranks(tmp_path):
    """Regular tetrahedra (four fcc lattice neighbours: three equal moments, so any axes are principal
    and round-off picks them) under langevin over two runs, the second setting the bodies up again
    from sums taken in another order on 2 ranks: the rotational noise, a box-frame vector projected on
    the axes, gives the same torque whichever axes were picked, so 2 ranks run as one (with one draw
    per axis they parted by 5e-4 in the temperature ten steps into the second run)."""
    text = lj_fcc(3, density=0.5, atom_style="molecular") + """mass * 1.0
variable m atom floor((id-1)/4)+1
set group all mol v_m
velocity all create 1.0 87287 loop geom
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
neigh_modify exclude molecule/intra all
fix 1 all rigid/small molecule langevin 1.0 0.5 0.2 4928
thermo_style custom step temp epair etotal press f_1
thermo_modify format float %20.15g
thermo 10
run 20
run 20
"""
    one, two = thermo_on_ranks(text, tmp_path)
    assert one.shape == two.shape == (6, 6)
    assert two == pytest.approx(one, rel=1e-10, abs=1e-12)
