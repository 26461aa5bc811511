"""fix rigid/small, rigid/nve/small and rigid/nvt/small: the same motion as fix rigid, rigid/nve and
rigid/nvt on the same bodies (LAMMPS: "both variants should give identical numerical answers for
short runs"), runs going on with reinit no, and the errors of bad input."""

import io
import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation, SimulationError
from pdps_core.testing import mpiexec, thermo_rows

DATA = Path(__file__).with_name("data")
SCENE = """units lj
atom_style molecular
read_data {data}
pair_style lj/cut 2.5
pair_coeff * * 1.0 1.0
neigh_modify exclude molecule/intra all
timestep 0.001
"""
RUN = """fix 1 all {style} molecule{extra}
thermo_style custom step temp epair ke etotal press
thermo_modify format float %20.15g
thermo 100
run 2000
"""


def molecular_data(path, x, molecules, v=None, images=None, length=20.0):
    """A data file of unit-mass particles with molecule ids (and image flags), in a periodic cube from
    0 to ``length``."""
    lines = ["rigid/small test", "", f"{len(x)} atoms", "1 atom types", "", f"0 {length} xlo xhi",
             f"0 {length} ylo yhi", f"0 {length} zlo zhi", "", "Masses", "", "1 1.0", "", "Atoms # molecular", ""]
    images = np.zeros((len(x), 3), dtype=int) if images is None else images
    lines += [f"{k + 1} {m} 1 {p[0]:.17g} {p[1]:.17g} {p[2]:.17g} {i[0]} {i[1]} {i[2]}"
              for k, (p, m, i) in enumerate(zip(x, molecules, images))]
    if v is not None:
        lines += ["", "Velocities", ""] + [f"{k + 1} {w[0]:.17g} {w[1]:.17g} {w[2]:.17g}" for k, w in enumerate(v)]
    Path(path).write_text("\n".join(lines) + "\n")
    return path


def simulation(text):
    sim = Simulation(screen=io.StringIO(), log=None)
    sim.command(text)
    return sim


@pytest.mark.parametrize("rigid, small, extra", [("rigid", "rigid/small", ""),
                                                 ("rigid/nve", "rigid/nve/small", ""),
                                                 ("rigid/nvt", "rigid/nvt/small", " temp 0.5 0.4 1.0")])
def test_small_bodies_move_as_fix_rigid_moves_them(pdps_cli, tmp_path, rigid, small, extra):
    """fix rigid's LAMMPS scene (8 bodies, one across two periodic boundaries): temperature,
    energies and pressure of the two variants over 2000 steps."""
    shutil.copy(DATA / "rigid_lj.data", tmp_path)
    rows = {}
    for style in (rigid, small):
        done = pdps_cli(SCENE.format(data="rigid_lj.data") + RUN.format(style=style, extra=extra), "-log", "none")
        assert done.returncode == 0, done.stderr
        rows[style] = np.array(thermo_rows(done.stdout))
    assert rows[small].shape == rows[rigid].shape == (21, 6)
    scale = np.abs(rows[rigid]).max(axis=0)
    worst = (np.abs(rows[small] - rows[rigid]) / scale).max()
    print(f"{small} against {rigid}: largest difference {worst:.1e} of each column's largest value")
    assert worst < 1e-10


@pytest.mark.parametrize("style", ["rigid/small", "rigid/nve/small"])
def test_reinit_no_goes_on_as_one_run(tmp_path, style):
    """Two runs with reinit no (the bodies' records carried from one run to the next, not set up
    again from the particles) end where one run of both lengths ends."""
    text = SCENE.format(data=DATA / "rigid_small_lj.data") + f"fix 1 all {style} molecule reinit no\n"
    straight = simulation(text + "run 400")
    split = simulation(text + "run 150\nrun 250")
    a, b = straight.particles, split.particles
    order_a, order_b = np.argsort(a.tag[: a.nlocal]), np.argsort(b.tag[: b.nlocal])
    assert b.x[: b.nlocal][order_b] == pytest.approx(a.x[: a.nlocal][order_a], abs=1e-12)
    assert b.v[: b.nlocal][order_b] == pytest.approx(a.v[: a.nlocal][order_a], abs=1e-12)


def test_bodies_straddling_the_box_are_whole_and_owned_once(tmp_path):
    """A triangle across the x, y and z faces of the periodic box (wrapped positions, image flags of
    the whole body in the file) and a dimer inside: 2 bodies of the particles' masses, the
    triangle's centre of mass mapped back into the box; after 300 steps of free flight each
    particle is where the whole body has carried it."""
    x = np.array([[19.6, 19.6, 19.6], [0.4, 19.6, 19.6], [19.6, 0.5, 0.3], [5, 5, 5], [6, 5, 5]])
    images = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 1], [0, 0, 0], [0, 0, 0]])
    unwrapped = np.array([[19.6, 19.6, 19.6], [20.4, 19.6, 19.6], [19.6, 20.5, 20.3], [5, 5, 5], [6, 5, 5]])
    path = molecular_data(tmp_path / "straddle.data", x, [1, 1, 1, 2, 2], v=np.tile([0.3, -0.2, 0.1], (5, 1)),
                          images=images)
    sim = simulation(f"units lj\natom_style molecular\nread_data {path}")
    p = sim.particles
    sim.command("pair_style lj/cut 1.0\npair_coeff * * 1.0 1.0\nfix 1 all rigid/small molecule\nrun 300")
    fix = sim.fixes["1"]
    assert fix.nbody == 2 and fix.nlocal_body == 2
    assert sorted(fix.masstotal[:2]) == [2.0, 3.0]
    n = p.nlocal
    xu = p.x[:n] + p.image[:n] * sim.box.length
    order = np.argsort(p.tag[:n])
    xu = xu[order]
    moved = 300 * 0.005 * np.array([0.3, -0.2, 0.1])
    assert xu[:3] == pytest.approx(unwrapped[:3] + moved, abs=1e-9)
    triangle = list(fix.masstotal[:2]).index(3.0)
    assert np.all((fix.xcm[triangle] >= 0) & (fix.xcm[triangle] < 20))


@pytest.mark.parametrize("line, message", [
    ("fix 1 all rigid/small single", "fix rigid/small takes bodystyle molecule only"),
    ("fix 1 all rigid/nvt/small molecule temp 1 1 1 langevin 1 1 1 5", "keyword langevin of fix rigid/nvt/small: "
     "fix rigid/nvt/small thermostats with temp; langevin is for rigid/small and rigid/nve/small"),
    ("fix 1 all rigid/small molecule langevin 1 1 0 5", r"langevin: Tperiod must be > 0 \(got 0\)"),
    ("fix 1 all rigid/nve/small molecule langevin 1 1 1 0", r"langevin: the seed must be a positive integer \(got 0\)"),
    ("fix 1 all rigid/small molecule langevin -1 1 1 5", r"langevin: Tstart and Tstop must be >= 0 \(got -1 1\)"),
    ("fix 1 all rigid/small molecule langevin 1 1 1", "langevin"),
    ("fix 1 all rigid/small molecule mol water", r"molecule template water is not defined \(defined: none\)"),
    ("fix 1 all rigid/nvt/small molecule temp 1 1 1 mol water", "keyword mol of fix rigid/nvt/small: fix rigid/small and "
     "rigid/nve/small take it; this variant does not yet"),
    ("fix 1 all rigid/small molecule infile nowhere.txt", "infile nowhere.txt: cannot read it"),
    ("fix 1 all rigid/small molecule infile BODIES", r"BODIES:3: no body 5 in fix 1 \(its bodies: 1..2\)"),
    ("fix 1 all rigid/small molecule force 1 off off off", "force"),
    ("fix 1 all rigid/small molecule reinit maybe", "reinit"),
    ("fix 1 all rigid/nvt/small molecule", "fix rigid/nvt/small needs temp TSTART TSTOP TDAMP"),
    ("fix 1 all rigid/nvt/small molecule temp 1 1 0", "temp: TSTART, TSTOP and TDAMP must be > 0"),
    ("fix 1 all rigid/nvt/small molecule temp 1 1 1 tparam 3 1 4", "tparam: TCHAIN and TITER must be from 1 to 1000"),
    ("fix 1 all rigid/nvt/small molecule temp 1 1 1 tparam 9223372036854775807 1 3", "TCHAIN and TITER must be from 1 to"),
    ("fix 1 all rigid/nvt/small molecule temp 1 1 1 tparam 3 100000000 3", "TCHAIN and TITER must be from 1 to 1000"),
    ("fix 1 all rigid/nvt/small molecule temp 1 1 1 iso 1 1 1", "keyword iso of fix rigid/nvt/small: only fix "
     "rigid/nph/small and rigid/npt/small take it"),
    ("fix 1 all rigid/small molecule temp 1 1 1", "keyword temp of fix rigid/small: only fix rigid/nvt/small and "
     "rigid/npt/small take it"),
    ("fix 1 all rigid/nve/small molecule tparam 3 1 3", "keyword tparam of fix rigid/nve/small: only fix"),
])
def test_bad_input_is_one_line(tmp_path, line, message):
    path = molecular_data(tmp_path / "two.data", np.array([[1, 1, 1], [2, 1, 1], [5, 5, 5], [5, 6, 5]]), [1, 1, 2, 2])
    bodies = tmp_path / "bodies.txt"
    bodies.write_text("# a body the fix does not have\n1\n5 2.0 1.5 1 1 0 0.5 0.5 0 0 0 0 0 0 0 0 0 0 0 0\n")
    line, message = line.replace("BODIES", str(bodies)), message.replace("BODIES", str(bodies))
    sim = simulation(f"units lj\natom_style molecular\nread_data {path}")
    with pytest.raises(ScriptError, match=message):
        sim.command(line)


def test_needs_molecule_ids_and_two_particles_a_body(tmp_path):
    sim = simulation("units lj\nregion b block 0 10 0 10 0 10\ncreate_box 1 b\nmass 1 1.0\n"
                     "create_atoms 1 single 1 1 1\ncreate_atoms 1 single 2 1 1")
    with pytest.raises(ScriptError, match="fix 1: bodystyle molecule needs molecule ids"):
        sim.command("fix 1 all rigid/small molecule")
    path = molecular_data(tmp_path / "lone.data", np.array([[1, 1, 1], [2, 1, 1], [5, 5, 5]]), [1, 1, 7])
    sim = simulation(f"units lj\natom_style molecular\nread_data {path}\nfix 1 all rigid/small molecule")
    with pytest.raises(SimulationError, match="fix 1: body of molecule 7 has 1 particle"):
        sim.command("run 1")


def test_particle_in_two_bodies_is_an_error_naming_both(tmp_path):
    path = molecular_data(tmp_path / "two.data", np.array([[1, 1, 1], [2, 1, 1], [5, 5, 5], [5, 6, 5]]), [1, 1, 2, 2])
    sim = simulation(f"units lj\natom_style molecular\nread_data {path}\ngroup pair id 2:3\n"
                     "fix 1 pair rigid single")
    with pytest.raises(ScriptError, match=r"particle 2 is in two bodies: molecule 1 of fix 2 and a body of fix 1 "
                                          r"\(rigid\)"):
        sim.command("fix 2 all rigid/small molecule")
    # the other way round: found when the run starts
    sim = simulation(f"units lj\natom_style molecular\nread_data {path}\ngroup pair id 2:3\n"
                     "fix 1 all rigid/small molecule\nfix 2 pair rigid single")
    with pytest.raises(ScriptError, match=r"particle 2 is in two bodies: molecule 1 of fix 1 and a body of fix 2 "
                                          r"\(rigid\)"):
        sim.command("run 0")


def test_owner_out_of_ghost_reach_is_one_line(tmp_path):
    """On 2 ranks, a body longer than the ghost cutoff: its particles on the far rank cannot see the
    owner (LAMMPS's 'Rigid body atoms missing'); the run stops with a line naming the particle."""
    x = np.array([[1.0, 5, 5], [5.0, 5, 5], [16.0, 5, 5], [12.0, 10, 10], [13.0, 10, 10]])
    molecular_data(tmp_path / "long.data", x, [1, 1, 1, 2, 2])
    (tmp_path / "in.long").write_text("units lj\natom_style molecular\nprocessors 2 1 1\nread_data long.data\n"
                                      "pair_style lj/cut 1.0\npair_coeff * * 1.0 1.0\n"
                                      "fix 1 all rigid/small molecule\nrun 10\n")
    import subprocess
    import sys
    done = subprocess.run([mpiexec(), "-n", "2", sys.executable, "-m", "pdps_core.cli", "run", "in.long", "-log",
                           "none", "--no-progress"], cwd=tmp_path, capture_output=True, text=True, timeout=300)
    assert done.returncode == 1
    assert "particle 3 cannot find its body's owner particle 2" in done.stderr
    assert "use comm_modify cutoff" in done.stderr
    assert "Traceback" not in done.stderr


@pytest.mark.parametrize("style, extra", [("rigid/small", ""), ("rigid/nve/small", ""),
                                          ("rigid/nvt/small", " temp 0.5 0.5 1.0")])
def test_restart_goes_on_as_the_straight_run(tmp_path, style, extra):
    """A run of 400 steps, and one of 200 written to a restart file, read back and run 200 more: the
    bodies are set up again from the particles (as LAMMPS's rigid/small: its restart files carry no
    body), rigid/nvt/small's chains come back from the file; the same particles to round-off."""
    from pdps_core.testing import restart_round_trip
    setup = SCENE.format(data=DATA / "rigid_small_lj.data") + f"fix 1 all {style} molecule{extra}\n"
    straight, resumed = restart_round_trip(tmp_path, setup, 200, 200)
    a, b = straight.particles, resumed.particles
    order_a, order_b = np.argsort(a.tag[: a.nlocal]), np.argsort(b.tag[: b.nlocal])
    assert b.x[: b.nlocal][order_b] == pytest.approx(a.x[: a.nlocal][order_a], abs=1e-9)
    assert b.v[: b.nlocal][order_b] == pytest.approx(a.v[: a.nlocal][order_a], abs=1e-9)
    if style == "rigid/nvt/small":
        assert resumed.fixes["1"].eta_dot_t == pytest.approx(straight.fixes["1"].eta_dot_t, abs=1e-12)
        assert resumed.fixes["1"].eta_r == pytest.approx(straight.fixes["1"].eta_r, abs=1e-12)


def test_lost_bodies(tmp_path):
    """Bodies pushed out of a closed box (thermo_modify lost ignore): a dimer whose two particles
    are both lost leaves the fix (one body left, its rows alone in compute rigid/local); a triangle
    whose owner particle is lost first while the others remain stops the run with a line naming
    both."""
    x = np.array([[5, 5, 5], [6, 5, 5], [10, 10, 10], [11, 10, 10], [10.3, 11, 10.4]])
    path = molecular_data(tmp_path / "lost.data", x, [1, 1, 2, 2, 2])
    text = (f"units lj\natom_style molecular\nboundary f f f\nread_data {path}\nthermo_modify lost ignore\n"
            "group dimer molecule 1\ngroup triangle molecule 2\nfix 1 all rigid/small molecule\n"
            "compute 1 all rigid/local 1 mass\n")
    sim = simulation(text + "fix 2 dimer addforce 5.0 0 0\nrun 1000")
    fix = sim.fixes["1"]
    assert sim.particles.nlocal == 3 and fix.nbody == fix.nlocal_body == 1
    assert list(sim.computes["1"].local(sim)) == [3.0]
    sim = simulation(text + "fix 2 triangle addforce 5.0 0 0")
    with pytest.raises(SimulationError, match="fix 1: particle 3 cannot find its body's owner particle 5 at step "
                                              r"\d+: it was lost"):
        sim.command("run 1000")
