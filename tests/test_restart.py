"""Restart files (issue 5): write_restart, read_restart, restart N FILE [FILE2].

"Bit for bit" compares every per-atom array of the owned particles (same names, same order, every
bit), the step and the time. The reference for a restart written after ``run N`` is the same script
going on with ``run M`` (each run's setup recomputes the forces); for forces that depend on positions
only, that is also the uninterrupted ``run N+M``. Small systems: 500 DPD particles, 200 spheres.
"""

import json
import os
import signal
import subprocess
import sys
import textwrap
import time
import zipfile

import numpy as np
import pytest

from pdps_core.api import Fix, ScriptError, Simulation, StyleArgs, observables, registry
from pdps_core.state import restart as restart_files
from pdps_core.testing import by_tag, lj_fcc


def silent():
    return Simulation(screen=False, log=None)


WATER = """
    units lj
    boundary p p p
    lattice spacing x 0.5 y 0.5 z 1
    timestep {dt}
    neighbor 0.3
    neigh_modify every 1 delay 1 check yes
    region box block 0 5 0 5 0 5
    create_box 1 box
    mass 1 1
    create_particle 1 region box
    pair_style dpd {T} 1.0 3442527
    pair_coeff * * 25.0 {gamma} 1.0
    velocity all create {T0} 10342 gaussian
    {extra}
"""


def water(extra="fix 1 all nve", dt=0.04, T=1.0, gamma=4.5, T0=1.0):
    """The PDPS water example on a 5^3 box (500 particles)."""
    sim = silent()
    sim.command(WATER.format(dt=dt, T=T, gamma=gamma, T0=T0, extra=extra))
    return sim


BED = """
    particle_style sphere
    boundary p p f
    region box block 0 5 0 5 0 12
    create_box 1 box
    lattice spacing x 1.0 y 1.0 z 1.0
    region pour block 0.5 5 0.5 5 0.5 8
    create_particle 1 region pour diameter 0.98 density 1.9098593
    velocity all create 2.0 99 gaussian
    region floor block INF INF INF INF 0 12
    fix w all wall/dem lsd region floor 0.5 200000.0 50.0 57142.857 25.0 0.5 0.5
    pair_style dem/lsd 0.5 1.0
    pair_coeff * * 200000.0 25.0 57142.857 12.5 0.5
    neighbor 0.2 bin
    atom_modify sort 300 0.0
    timestep 0.0002
    fix grav all gravity 20.0 vector 0 0 -1
    fix 1 all nve/sphere
"""


def bed():
    """200 spheres in contact with each other and the floor: dem/lsd with friction history."""
    sim = silent()
    sim.command(BED)
    return sim


def restarted(path, *lines):
    sim = silent()
    sim.command(f"read_restart {path}")
    for line in lines:
        sim.command(line)
    return sim


def assert_same_state(a, b):
    pa, pb = a.particles, b.particles
    assert list(pa.arrays) == list(pb.arrays)
    assert pa.nlocal == pb.nlocal and pa.next_tag == pb.next_tag
    n = pa.nlocal
    different = [name for name in pa.arrays if not np.array_equal(pa.arrays[name][:n], pb.arrays[name][:n])]
    assert different == []
    assert (a.step, a.time, a.dt) == (b.step, b.time, b.dt)


# ---- continuation, bit for bit ------------------------------------------------------------------
@pytest.mark.parametrize("integrator", ["fix 1 all nve", "fix 1 all mvv/dpd 0.65"])
def test_dpd_water_read_back_goes_on_as_the_script_would_have(tmp_path, monkeypatch, integrator):
    monkeypatch.chdir(tmp_path)
    going_on = water(integrator)
    going_on.command("run 30\nwrite_restart water.restart\nrun 30")
    again = restarted("water.restart", "run 30")
    assert_same_state(going_on, again)
    assert again.step == 60 and again.fixes["1"].args == going_on.fixes["1"].args
    if "mvv" in integrator:
        assert list(again.particles.arrays)[-1] == "vest"


def test_dpd_with_its_thermostat_is_not_the_uninterrupted_run(tmp_path, monkeypatch):
    """The documented limit: velocity-dependent forces are recomputed at a run's start from the
    full-step velocities, where the uninterrupted run used the half-step ones (LAMMPS and LIGGGHTS
    alike), so run 30 + run 30 is another trajectory than run 60."""
    monkeypatch.chdir(tmp_path)
    split, whole = water(), water()
    split.command("run 30\nrun 30")
    whole.command("run 60")
    assert not np.array_equal(split.v, whole.v)


@pytest.mark.parametrize("schedule", ["neigh_modify every 1 delay 1 check yes\natom_modify sort 7 0.0",
                                      "neigh_modify every 3 delay 6 check no\natom_modify sort 5 0.0"])
def test_position_only_forces_continue_the_uninterrupted_run(tmp_path, monkeypatch, schedule):
    """Soft repulsion only (T = 0, gamma = 0): run 33 + run 67, and a restart read at step 33, both
    follow run 100 to the last bit, although particles sit outside the periodic box at step 33
    (a wrap at the second run's start would move them) and sorts happen after it."""
    monkeypatch.chdir(tmp_path)
    options = dict(extra=f"fix 1 all nve\n{schedule}", dt=0.005, T=0.0, gamma=0.0)
    whole, split = water(**options), water(**options)
    whole.command("run 100")
    split.command("run 33")
    assert not split.box.inside(split.x).all()
    split.command("write_restart soft.restart\nrun 67")
    again = restarted("soft.restart", "run 67")
    assert whole.neighbor.last_sort > 33
    assert_same_state(split, whole)
    assert_same_state(again, whole)


def test_granular_bed_with_contact_history_read_back_goes_on_bit_for_bit(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    going_on = bed()
    assert going_on.nlocal == 200
    going_on.command("run 750")
    p = going_on.particles
    assert (p.pair_shear_partner[:200] >= 0).sum() > 50           # springs between spheres
    assert (p.wall_w_partner[:200] >= 0).sum() > 5                # and with the floor
    assert np.abs(p.pair_shear_history[:200]).max() > 0
    going_on.command("write_restart bed.restart\nrun 500")
    again = restarted("bed.restart", "run 500")
    assert_same_state(going_on, again)
    assert again.neighbor.last_sort > 750                          # re-sorted after the restart


def test_a_restart_written_during_a_run_goes_on_as_two_runs_would(tmp_path, monkeypatch):
    """``restart 20 water.*`` inside run 40: water.20 read back and run 20 more is run 20 + run 20."""
    monkeypatch.chdir(tmp_path)
    writer = water()
    writer.command("restart 20 water.*\nrun 40")
    assert sorted(os.listdir(tmp_path)) == ["water.20", "water.40"]
    two_runs = water()
    two_runs.command("run 20\nrun 20")
    again = restarted("water.20", "run 20")
    assert_same_state(again, two_runs)


# ---- what the file holds ------------------------------------------------------------------------
def test_settings_groups_regions_styles_and_neighbor_settings_come_back(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = silent()
    sim.command("""
        units lj
        boundary p p f
        lattice spacing x 1 y 1 z 1
        region box block 0 6 0 6 0 6
        create_box 2 box
        mass 1 1.0
        mass 2 2.5
        region left block INF 3 INF INF INF INF
        create_particle 1 region box
        group left region left
        group heavy type 2
        group light type 1
        group light delete
        group second type 1*2
        pair_style dpd 1.0 1.0 77
        pair_coeff 1 1 25.0 4.5
        pair_coeff 2 2 35.0 3.0 0.9
        pair_modify mix arithmetic
        timestep 0.02
        neighbor 0.4
        neigh_modify every 2 delay 4 check no
        atom_modify sort 50 0.0
        compute t all temp
        fix 1 all nve
        fix push left addforce 0.1 0 0
        comm_modify vel yes
        run 10
        write_restart all.restart
    """)
    again = restarted("all.restart")
    assert (again.units, again.dimension, again.system.periodicity) == (sim.units, 3, ("p", "p", "f"))
    assert np.array_equal(again.box.lo, sim.box.lo) and again.box.periodic == (True, True, False)
    assert again.ntypes == 2 and np.array_equal(again.mass, sim.mass, equal_nan=True)
    assert again.groups.bits == sim.groups.bits
    assert again.groups.definitions == sim.groups.definitions
    assert list(again.system.regions) == ["box", "left"] and again.system.regions["left"].args == sim.system.regions["left"].args
    assert again.pair.coeffs == sim.pair.coeffs and again.pair.mix_rule == "arithmetic"
    assert again.pair.args == sim.pair.args
    assert list(again.fixes) == ["1", "push"] and again.fixes["push"].group == "left"
    assert again.compute_value("t") == sim.compute_value("t")
    neighbor, saved = again.neighbor, sim.neighbor
    assert (neighbor.skin, neighbor.every, neighbor.delay, neighbor.check, neighbor.sort_every,
            neighbor.last_sort, neighbor.ago) == (0.4, 2, 4, False, 50, 0, saved.ago)
    assert again.dt == 0.02 and again.system.ghost_velocity and again.lattice is not None
    assert again.pe == sim.pe and again.run_state.energy_step == 10
    again.command("run 10")
    sim.command("run 10")
    assert_same_state(sim, again)


class Counter(Fix):
    """A fix with state beyond its arguments: steps seen, and an array."""
    name = "test/restart/counter"

    class Args(StyleArgs):
        start: int = 0

    def __init__(self, sim, id, group, args):
        super().__init__(sim, id, group, args)
        self.steps = args.start
        self.seen = np.zeros(2, dtype=np.int32)
        self.extra = object()

    def end_of_step(self, sim):
        self.steps += 1
        self.seen += 1

    def state(self):
        return {"steps": self.steps, "nested": {"seen": [self.seen, (1, 2)]}}

    def restore(self, state):
        self.steps = state["steps"]
        self.seen = state["nested"]["seen"][0]


class Unsaveable(Counter):
    name = "test/restart/unsaveable"

    def state(self):
        return {"handle": self.extra}


@pytest.fixture
def counter():
    registry.register("fix", Counter.name, Counter)
    registry.register("fix", Unsaveable.name, Unsaveable)


def test_a_style_state_is_saved_restored_and_handed_to_a_fix_given_again(tmp_path, monkeypatch, counter):
    monkeypatch.chdir(tmp_path)
    sim = water(f"fix 1 all nve\nfix c all {Counter.name} 5")
    sim.command("run 3\nwrite_restart c.restart")
    again = restarted("c.restart")
    fix = again.fixes["c"]
    assert fix.steps == 8 and fix.seen.dtype == np.int32 and list(fix.seen) == [3, 3]
    # a LAMMPS script gives its fixes again after read_restart: the new instance gets the state
    again.command(f"fix c all {Counter.name} 0\nrun 2")
    assert again.fixes["c"] is not fix and again.fixes["c"].steps == 10
    sim.command(f"fix bad all {Unsaveable.name}")
    with pytest.raises(ScriptError, match="fix bad: state\\(\\) holds a object"):
        sim.command("write_restart bad.restart")


LJ_RESTART = """units lj
atom_style atomic
lattice fcc 0.8442
region box block 0 3 0 3 0 3
create_box 1 box
create_atoms 1 box
mass 1 1.0
velocity all create 1.0 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
region low block INF INF INF INF INF 1.5
fix 1 all nve
fix pull all addforce 0.0 0.0 1.0
compute k all ke
"""


@pytest.mark.parametrize("dialect", ["lammps", "liggghts"])
def test_a_lammps_restart_holds_no_fixes_computes_or_regions(tmp_path, monkeypatch, dialect):
    """LAMMPS's and LIGGGHTS's rule (their read_restart pages): the file holds the particles, box,
    groups, masses and pair style; the reading script gives its fixes, computes and regions again. A
    fix it leaves out does not act (no addforce: the run is the straight run without it), a compute
    may take its old ID, a region defined before read_restart stays, and the timestep comes back."""
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect=dialect)
    sim.command(LJ_RESTART + "timestep 0.002\nrun 20\nwrite_restart lj.restart")
    again = Simulation(screen=False, log=None, dialect=dialect)
    again.command("region early block INF INF INF INF INF 1.0\nread_restart lj.restart")
    assert not again.fixes and not again.computes
    assert sorted(again.system.regions) == ["early"]
    assert again.run_state.dt == 0.002
    again.command("compute k all ke\nfix 1 all nve\nrun 20")
    # the reference: the same particles going on with nve alone
    alone = Simulation(screen=False, log=None, dialect=dialect)
    alone.command(LJ_RESTART + "timestep 0.002\nrun 20\nunfix pull\nrun 20")
    np.testing.assert_allclose(by_tag(again, again.v), by_tag(alone, alone.v), rtol=1e-10, atol=1e-12)
    pulled = Simulation(screen=False, log=None, dialect=dialect)
    pulled.command(LJ_RESTART + "timestep 0.002\nrun 40")
    assert np.abs(by_tag(pulled, pulled.v) - by_tag(alone, alone.v)).max() > 1e-3


def test_a_pdps_restart_brings_back_the_whole_simulation(tmp_path, monkeypatch):
    """In the PDPS dialect read_restart brings back the fixes, computes and regions as well."""
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command(LJ_RESTART + "run 5\nwrite_restart lj.restart")
    again = Simulation(screen=False, log=None, dialect="pdps")
    again.command("read_restart lj.restart")
    assert sorted(again.fixes) == ["1", "pull"] and sorted(again.computes) == ["k"]
    assert "low" in again.system.regions


STL = """solid plate
facet normal 0 0 1
 outer loop
  vertex -4 -4 0
  vertex 4 -4 0
  vertex 4 4 0
 endloop
endfacet
facet normal 0 0 1
 outer loop
  vertex -4 -4 0
  vertex 4 4 0
  vertex -4 4 0
 endloop
endfacet
endsolid plate
"""


def test_a_moving_mesh_keeps_its_clock(tmp_path, monkeypatch):
    """wall/mesh's elapsed time is state: read back (and when the fix is given again) the plate is
    where it was, and the spheres on it go on bit for bit."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "plate.stl").write_text(STL)
    mesh = "wall/mesh file plate.stl velocity 0.5 0 0 model lsd 0.5 10000 0.5"
    script = f"""
        particle_style sphere
        boundary f f f
        region box block -5 5 -5 5 -2 5
        create_box 1 box
        create_particle 1 single 0 0 0.49 diameter 1 density 1
        create_particle 1 single 1.2 0 0.49 diameter 1 density 1
        timestep 0.001
        fix grav all gravity 10.0 vector 0 0 -1
        fix 1 all nve/sphere
        fix plate all {mesh}
    """
    going_on = silent()
    going_on.command(script + "run 200")
    placed = going_on.fixes["plate"].vertices.copy()
    going_on.command("write_restart mesh.restart\nrun 100")
    again = restarted("mesh.restart")
    assert again.fixes["plate"].elapsed == pytest.approx(0.2)
    assert np.array_equal(again.fixes["plate"].vertices, placed)
    again.command("run 100")
    given_again = restarted("mesh.restart", f"fix plate all {mesh}", "run 100")
    assert_same_state(going_on, again)
    assert_same_state(going_on, given_again)
    assert np.abs(going_on.particles.omega[:2]).max() > 0      # the plate set the spheres rolling


# ---- the restart command's schedule ---------------------------------------------------------------
def header_step(path):
    header, _ = restart_files.read_file(str(path))
    return header["step"]


def test_two_files_take_turns_and_restart_0_stops(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = water()
    sim.command("restart 10 first.restart second.restart\nrun 40")
    assert (header_step("first.restart"), header_step("second.restart")) == (30, 40)
    sim.command("restart 0\nrun 20")
    assert sorted(os.listdir(tmp_path)) == ["first.restart", "second.restart"]
    assert header_step("second.restart") == 40
    sim.command("write_restart now.*")
    latest = restarted("now.*")        # a * reads the file of the largest step
    assert latest.step == 60 and os.path.exists("now.60")


# ---- crashes ---------------------------------------------------------------------------------------
CHILD = """
import os, signal, sys
import numpy as np
from pdps_core.api import Simulation

if sys.argv[1] == "die-inside-the-second-file":
    # SIGKILL while the second restart's arrays are being written, in the middle of the temp file
    write_array, replace, state = np.lib.format.write_array, os.replace, {"renamed": 0, "arrays": 0}
    def counting_replace(*args):
        replace(*args)
        state["renamed"] += 1
    def dying_write_array(*args, **kwargs):
        if state["renamed"] == 1:
            state["arrays"] += 1
            if state["arrays"] == 4:
                os.kill(os.getpid(), signal.SIGKILL)
        return write_array(*args, **kwargs)
    os.replace, np.lib.format.write_array = counting_replace, dying_write_array

sim = Simulation(screen=False, log=None)
sim.command('''SCRIPT''')
# two files of one name: the file written over every step (one name alone gets .STEP after it)
sim.command("restart 1 r.restart r.restart\\ndump 1 all atom 1 d.atom\\nrun 1000000")
"""


def child(tmp_path, name, mode):
    folder = tmp_path / name
    folder.mkdir()
    script = CHILD.replace("SCRIPT", WATER.format(dt=0.04, T=1.0, gamma=4.5, T0=1.0,
                                                  extra="fix 1 all nve"))
    (folder / "child.py").write_text(textwrap.dedent(script))
    return folder, subprocess.Popen([sys.executable, "child.py", mode], cwd=folder,
                                    stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def dump_frames(text):
    """Complete frames of a LAMMPS text dump, as (step, rows); a cut-off last frame is left out."""
    lines, frames, k = text.split("\n"), [], 0
    while k + 9 <= len(lines) and lines[k] == "ITEM: TIMESTEP":
        try:
            step, n = int(lines[k + 1]), int(lines[k + 3])
        except ValueError:
            break
        end = k + 9 + n
        if end >= len(lines):          # the last row has no newline after it: cut off
            break
        width = len(lines[k + 8].split()) - 2
        rows = [line.split() for line in lines[k + 9:end]]
        if any(len(row) != width for row in rows):
            break
        frames.append((step, np.array(rows, dtype=float)))
        k = end
    return frames


def test_killed_while_writing_the_restart_and_the_dump_stay_readable(tmp_path):
    """Runs that write a restart and a dump frame every step are killed (SIGKILL): one inside the
    second restart's temp file, two at random moments. The restart file is always a complete one
    (the half-written temp file is refused), and the dump holds whole frames, at most followed by
    a cut-off one. The three run at once."""
    rng = np.random.default_rng(5)
    children = [child(tmp_path, name, mode) for name, mode in
                (("inside", "die-inside-the-second-file"), ("random1", "loop"), ("random2", "loop"))]
    for folder, process in children[1:]:
        try:
            for _ in range(1200):           # until the first restart is there (at most 2 minutes)
                if (folder / "r.restart").exists() or process.poll() is not None:
                    break
                time.sleep(0.1)
            time.sleep(rng.uniform(0.0, 0.3))
            process.send_signal(signal.SIGKILL)
        finally:
            process.wait(timeout=120)
    try:
        children[0][1].wait(timeout=120)
    finally:
        for _, process in children:
            if process.poll() is None:
                process.kill()
                process.wait()
    for folder, process in children:
        assert process.returncode == -signal.SIGKILL, process.stderr.read().decode()
        sim = silent().command(f"read_restart {folder / 'r.restart'}")
        assert sim.step >= 1 and sim.nlocal == 500
        frames = dump_frames((folder / "d.atom").read_text())
        assert frames and [step for step, _ in frames] == list(range(len(frames)))
        assert all(rows.shape == (500, 5) for _, rows in frames)
        assert sim.step <= frames[-1][0]          # a step's dump frame comes before its restart
    inside = children[0][0]
    assert silent().command(f"read_restart {inside / 'r.restart'}").step == 1
    assert (inside / "r.restart.tmp").exists()       # the half-written one, never renamed
    with pytest.raises(ScriptError, match="is truncated, damaged or not a pdps restart file"):
        silent().command(f"read_restart {inside / 'r.restart.tmp'}")


def test_a_truncated_dump_reads_up_to_its_last_complete_frame(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = water("fix 1 all nve\ndump 1 all atom 1 d.atom")
    sim.command("run 4")
    sim.close()
    text = (tmp_path / "d.atom").read_text()
    whole = dump_frames(text)
    assert [step for step, _ in whole] == [0, 1, 2, 3, 4]
    ends = [text.index("ITEM: TIMESTEP", 1 + text.index(f"ITEM: TIMESTEP\n{s}\n")) for s in range(4)]
    ends.append(len(text))
    rng = np.random.default_rng(3)
    for cut in [*ends, *(e - 1 for e in ends), *rng.integers(0, len(text), 20)]:
        frames = dump_frames(text[:cut])
        complete = sum(end <= cut for end in ends)
        assert [step for step, _ in frames] == list(range(complete))
        for (_, rows), (_, full) in zip(frames, whole):
            assert np.array_equal(rows, full)


# ---- errors ----------------------------------------------------------------------------------------
@pytest.fixture
def saved(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = water()
    sim.command("run 0\nwrite_restart good.restart")
    return tmp_path / "good.restart"


def one_line_error(command):
    sim = silent()
    with pytest.raises(ScriptError) as error:
        sim.command(command)
    message = str(error.value)
    assert "\n" not in message
    assert sim.box is None             # nothing half-read stays behind
    return message


def test_missing_truncated_foreign_and_newer_files_are_one_line_errors(saved, tmp_path):
    assert "nothing.restart does not exist" in one_line_error("read_restart nothing.restart")
    data = saved.read_bytes()
    for cut in (10, len(data) // 2, len(data) - 1):
        (tmp_path / "cut.restart").write_bytes(data[:cut])
        assert ("cut.restart is truncated, damaged or not a pdps restart file"
                in one_line_error("read_restart cut.restart"))
    (tmp_path / "text.restart").write_text("units lj\n")
    assert "text.restart is truncated, damaged or not" in one_line_error("read_restart text.restart")
    with zipfile.ZipFile(saved) as source, zipfile.ZipFile(tmp_path / "new.restart", "w") as target:
        for item in source.namelist():
            content = source.read(item)
            if item == "header.json":
                header = json.loads(content)
                header["version"] = 99
                content = json.dumps(header)
            target.writestr(item, content)
    message = one_line_error("read_restart new.restart")
    assert "new.restart has format version 99 (written by a newer pdps)" in message
    assert "reads version 1" in message


def test_flipped_bits_are_caught_by_the_checksum(saved, tmp_path):
    data = bytearray(saved.read_bytes())
    data[len(data) // 3] ^= 0xFF
    (tmp_path / "flipped.restart").write_bytes(bytes(data))
    assert "flipped.restart is truncated, damaged" in one_line_error("read_restart flipped.restart")


def test_command_errors(saved):
    sim = silent()
    with pytest.raises(ScriptError, match="write_restart before the simulation box exists"):
        sim.command("write_restart x.restart")
    sim.command(f"read_restart {saved.name}")
    with pytest.raises(ScriptError, match="read_restart needs no box"):
        sim.command(f"read_restart {saved.name}")
    with pytest.raises(ScriptError, match="N must be >= 0"):
        sim.command("restart -5 a")
    with pytest.raises(ScriptError, match="usage: restart 0 | restart N FILE"):
        sim.command("restart 10 a b c")
    with pytest.raises(ScriptError, match="cannot write restart file no/such/dir/x.restart"):
        sim.command("write_restart no/such/dir/x.restart")
    assert not any(name.endswith(".tmp") for name in os.listdir("."))


@pytest.mark.parametrize("exclude", ["type 1 2", "group left right", "type 1 1 exclude group left right"])
def test_neigh_modify_exclude_survives_a_restart(tmp_path, exclude):
    """Neighbor settings are saved, exclusions included: after read_restart the energy leaves out
    the excluded pairs as before (it counted them until the exclusion was given again)."""
    path = tmp_path / "exclude.restart"
    writer = Simulation(screen=False, log=None, dialect="lammps")
    writer.command(lj_fcc(4, 2) + f"""
        set type 1 type/fraction 2 0.5 4321
        region lefthalf block INF 2 INF INF INF INF
        group left region lefthalf
        group right subtract all left
        mass * 1.0
        pair_style lj/cut 2.5
        pair_coeff * * 1.0 1.0
        neigh_modify exclude {exclude}
        thermo_style custom step pe
        run 0
        write_restart {path}
    """)
    whole = Simulation(screen=False, log=None, dialect="lammps")
    whole.command(f"read_restart {path}\nneigh_modify exclude none\nrun 0")
    resumed = Simulation(screen=False, log=None, dialect="lammps")
    resumed.command(f"read_restart {path}\nrun 0")
    pe = {name: observables.potential_energy(sim) for name, sim in
          (("writer", writer), ("whole", whole), ("resumed", resumed))}
    assert pe["resumed"] == pytest.approx(pe["writer"], rel=1e-14)
    assert abs(pe["whole"] - pe["writer"]) > 0.1
