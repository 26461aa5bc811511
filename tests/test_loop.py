"""The timestep loop: hook order, what is computed on which step, what is allocated and sent."""

import weakref

import numpy as np
import pytest

from pdps_core.api import Analyze, Fix, ScriptError, SimulationError, registry
from pdps_core.testing import NoForcePair, liggghts_material

BOX = """
region box block 0 6 0 6 0 6
create_box 1 box
mass 1 1
lattice spacing x 1 y 1 z 1
create_particle 1 region box
"""

# what the test styles record, per simulation (a Simulation takes no attributes of its own)
NOTES = weakref.WeakKeyDictionary()


def notes(sim):
    return NOTES.setdefault(sim, {})


class Recorder(Fix):
    """Appends (fix id, hook, step) to notes(sim)["calls"] for every hook of the timestep."""
    name = "test/recorder"

    def _record(self, sim, hook):
        notes(sim).setdefault("calls", []).append((self.id, hook, sim.step))

    def setup(self, sim):
        self._record(sim, "setup")

    def initial_integrate(self, sim):
        self._record(sim, "initial_integrate")

    def post_integrate(self, sim):
        self._record(sim, "post_integrate")

    def pre_exchange(self, sim):
        self._record(sim, "pre_exchange")

    def pre_neighbor(self, sim):
        self._record(sim, "pre_neighbor")

    def pre_force(self, sim):
        self._record(sim, "pre_force")

    def post_force(self, sim):
        self._record(sim, "post_force")

    def final_integrate(self, sim):
        self._record(sim, "final_integrate")

    def end_of_step(self, sim):
        self._record(sim, "end_of_step")


class ListAndReverseRecorder(Recorder):
    """The hooks around the neighbor build and the reverse communication, recorded as Recorder's;
    in pre_reverse it pushes every ghost by (1, 0, 0), which the reverse sum must carry to owners."""
    name = "test/recorder2"

    def post_neighbor(self, sim):
        self._record(sim, "post_neighbor")
        notes(sim)["list version"] = sim.pair_list.version

    def pre_reverse(self, sim):
        self._record(sim, "pre_reverse")
        p = sim.particles
        p.f[p.nlocal:p.nall, 0] += 1.0
        notes(sim)["ghosts pushed"] = p.nghost

    def post_force(self, sim):
        self._record(sim, "post_force")
        notes(sim)["owned push"] = float(sim.particles.f[: sim.particles.nlocal, 0].sum())


class OnlyPostForce(Fix):
    name = "test/postforce"

    def post_force(self, sim):
        notes(sim).setdefault("calls", []).append((self.id, "post_force", sim.step))


class FlagPair(NoForcePair):
    """A pair style with no force that records the eflag/vflag it was asked for on each step."""
    name = "test/flags"

    def compute(self, sim, nlist, eflag, vflag):
        notes(sim).setdefault("flags", {})[sim.step] = (bool(eflag), bool(vflag))
        self.energy = 0.0


class NaNForce(Fix):
    name = "test/nan"

    def post_force(self, sim):
        if sim.step == 3:
            sim.f[2, 1] = np.nan


@pytest.fixture(autouse=True)
def test_styles():
    registry.register("fix", "test/recorder", Recorder)
    registry.register("fix", "test/recorder2", ListAndReverseRecorder)
    registry.register("fix", "test/postforce", OnlyPostForce)
    registry.register("fix", "test/nan", NaNForce)
    registry.register("pair", "test/flags", FlagPair)


def test_hooks_run_in_timestep_order_and_fixes_in_script_order(make_sim):
    sim = make_sim()
    sim.command(BOX + "pair_style test/flags\npair_coeff * *\nneigh_modify every 1 delay 0 check no\n"
                "fix b all test/recorder\nfix a all test/recorder\nrun 1")
    step1 = [(fid, hook) for fid, hook, step in notes(sim)["calls"] if step == 1]
    expected_hooks = ["initial_integrate", "post_integrate", "pre_exchange", "pre_neighbor",
                      "pre_force", "post_force", "final_integrate", "end_of_step"]
    assert step1 == [(fid, hook) for hook in expected_hooks for fid in ("b", "a")]
    setup = [(fid, hook) for fid, hook, step in notes(sim)["calls"] if step == 0]
    assert setup == [("b", "pre_neighbor"), ("a", "pre_neighbor"), ("b", "pre_force"),
                     ("a", "pre_force"), ("b", "setup"), ("a", "setup")]


def test_post_neighbor_follows_the_build_and_pre_reverse_forces_on_ghosts_reach_their_owners(make_sim):
    sim = make_sim()
    sim.command(BOX + "pair_style test/flags\npair_coeff * *\nneigh_modify every 1 delay 0 check no\n"
                "fix r all test/recorder2\nrun 1")
    step1 = [hook for _, hook, step in notes(sim)["calls"] if step == 1]
    assert step1 == ["initial_integrate", "post_integrate", "pre_exchange", "pre_neighbor", "post_neighbor",
                     "pre_force", "pre_reverse", "post_force", "final_integrate", "end_of_step"]
    setup = [hook for _, hook, step in notes(sim)["calls"] if step == 0]
    assert setup == ["pre_neighbor", "post_neighbor", "pre_force", "pre_reverse", "setup"]
    assert notes(sim)["list version"] == sim.pair_list.version      # called after this step's build
    # the pair style adds no force: all the owners hold is the ghosts' pushes, one per ghost image
    assert notes(sim)["ghosts pushed"] > 0
    assert notes(sim)["owned push"] == notes(sim)["ghosts pushed"]


def test_a_fix_is_called_only_for_the_hooks_it_defines(make_sim):
    sim = make_sim()
    sim.command(BOX + "fix p all test/postforce\nrun 3")
    assert [hook for _, hook, _ in notes(sim)["calls"]] == ["post_force"] * 3
    assert set(sim.run_state.integrator.hooks) == {"post_force"}


def test_redefining_a_fix_keeps_its_place_and_unfix_removes_it(make_sim):
    sim = make_sim()
    sim.command(BOX + "fix x all test/postforce\nfix y all test/postforce\nfix x all test/postforce\nrun 1")
    assert [fid for fid, _, step in notes(sim)["calls"] if step == 1] == ["x", "y"]
    notes(sim)["calls"].clear()
    sim.command("unfix x\nrun 1")
    assert [fid for fid, _, _ in notes(sim)["calls"]] == ["y"]


def test_energy_and_virial_only_on_steps_that_read_them(make_sim):
    sim = make_sim()
    sim.command(BOX + "pair_style test/flags\npair_coeff * *\nthermo 5\nthermo_style custom step temp pe\nrun 12")
    flags = notes(sim)["flags"]
    assert flags[0] == (True, True)                     # setup always computes both
    energy_steps = [s for s in range(1, 13) if flags[s][0]]
    virial_steps = [s for s in range(1, 13) if flags[s][1]]
    assert energy_steps == [5, 10, 12]                  # thermo steps and the last step
    assert virial_steps == [12]                         # nothing reads the virial but the last step
    sim.command("thermo_style custom step press\nrun 4")
    assert [s for s in range(13, 17) if notes(sim)["flags"][s][1]] == [15, 16]
    assert [s for s in range(13, 17) if notes(sim)["flags"][s][0]] == [16]


def test_compute_pressure_asks_for_the_virial(make_sim):
    sim = make_sim()
    sim.command(BOX + "pair_style test/flags\npair_coeff * *\ncompute p all pressure\n"
                "thermo 2\nthermo_style custom step c_p\nrun 5")
    assert [s for s in range(1, 6) if notes(sim)["flags"][s][1]] == [2, 4, 5]
    assert [s for s in range(1, 6) if notes(sim)["flags"][s][0]] == [5]


def test_reading_energy_on_a_step_where_it_was_not_computed_is_an_error(make_sim):
    sim = make_sim()
    sim.command(BOX + "pair_style test/flags\npair_coeff * *\nrun 2\n")
    sim.run_state.step += 1        # as if a step ran that tallied nothing
    with pytest.raises(ScriptError, match="potential energy was not computed on step 3"):
        sim.command("variable e equal pe\nprint ${e}")


def test_ghost_velocities_sent_only_when_a_style_needs_them(make_sim):
    sim = make_sim()
    sim.command(BOX + "pair_style test/flags\npair_coeff * *\nrun 0")
    assert sim.run_state.integrator.forward == ("x",)
    sim.command("pair_style dpd 1.0 1.0 3\npair_coeff * * 25 4.5\nrun 0")
    assert sim.run_state.integrator.forward == ("x", "v")
    sim.command("pair_style test/flags\npair_coeff * *\ncomm_modify vel yes\nrun 0")
    assert sim.run_state.integrator.forward == ("x", "v")


def test_optional_per_atom_arrays_exist_only_when_asked_for(make_sim):
    sim = make_sim()
    sim.command(BOX + "pair_style dpd 1.0 1.0 3\npair_coeff * * 25 4.5\nfix 1 all nve\nrun 2")
    assert set(sim.particles.arrays) == {"x", "v", "f", "tag", "type", "mask", "image"}
    sphere = make_sim()
    sphere.command("particle_style sphere\n" + BOX + "run 0")
    assert {"radius", "rmass", "omega", "torque"} <= set(sphere.particles.arrays)
    assert sphere.run_state.integrator.reverse == ("f", "torque")


def test_non_finite_force_stops_the_run_naming_step_and_particle(make_sim):
    sim = make_sim()
    sim.command(BOX + "fix 1 all nve\nfix n all test/nan")
    with pytest.raises(SimulationError) as info:
        sim.command("run 10")
    tag = int(sim.tag[2])
    assert str(info.value).startswith(f"<command>:1: run: particle {tag} has a non-finite force (0, nan, 0) at step 3")


def test_a_particle_leaving_a_fixed_boundary_stops_the_run(make_sim):
    sim = make_sim()
    sim.command("boundary p p f\n" + BOX + "velocity all set 0 0 0\nvelocity all set NULL NULL 0\nfix 1 all nve")
    assert sim.x[7, 2] == 1.0
    sim.v[7, 2] = 2.0
    tag = int(sim.tag[7])
    with pytest.raises(SimulationError) as info:
        sim.command("timestep 0.1\nrun 100")
    message = str(info.value)
    assert f"particle {tag} lost through the fixed z boundary at step" in message
    step = int(message.split("at step ")[1].split(":")[0])
    # at 0.2 per step from z = 1 it passes z = 6 on step 25 (checked every step: skin/2 < 0.2)
    assert step in (25, 26)
    assert message.endswith("outside [0, 6] (1 particle(s) outside)")


def test_run_reports_where_the_time_went(make_sim):
    import io
    screen = io.StringIO()
    sim = make_sim(screen=screen)
    sim.command(BOX + "pair_style dpd 1.0 1.0 3\npair_coeff * * 25 4.5\nfix 1 all nve\nrun 5")
    text = screen.getvalue()
    assert "Loop time of " in text and "for 5 steps with 216 particles" in text
    for stage in ("Pair", "Neigh", "Comm", "Modify", "Output", "Other"):
        assert f"\n{stage} " in text
    assert "fix 1 (nve)" in text
    assert "Neighbor list builds = " in text


class CountingAnalyze(Analyze):
    """An analyze style that counts the steps it was called on."""
    name = "test/count"

    def end_of_step(self, sim):
        notes(sim).setdefault("analyzed", []).append((self.id, sim.step))


def test_analyze_styles_are_called_at_end_of_step_until_unanalyze(make_sim):
    registry.register("analyze", "test/count", CountingAnalyze)
    sim = make_sim()
    sim.command(BOX + "analyze a all test/count\nrun 3")
    assert notes(sim)["analyzed"] == [("a", 1), ("a", 2), ("a", 3)]
    sim.command("unanalyze a\nrun 2")
    assert len(notes(sim)["analyzed"]) == 3
    with pytest.raises(ScriptError, match="analyze a is not defined"):
        sim.command("unanalyze a")


def test_post_run_is_called_once_after_the_last_step(make_sim):
    class Summary(Fix):
        name = "test/summary"

        def post_run(self, sim):
            sim.info(f"summary at step {sim.step}")
            notes(sim).setdefault("summaries", []).append(sim.step)

    registry.register("fix", "test/summary", Summary)
    import io
    screen = io.StringIO()
    sim = make_sim(screen=screen)
    sim.command(BOX + "fix s all test/summary\nrun 4\nrun 2")
    assert notes(sim)["summaries"] == [4, 6]
    assert "summary at step 6" in screen.getvalue().splitlines()


def test_fix_and_analyze_values_are_read_as_f_id(make_sim):
    class Counter(Fix):
        name = "test/counter"

        def end_of_step(self, sim):
            self.count = getattr(self, "count", 0) + 1

        def scalar(self, sim):
            return getattr(self, "count", 0)

        def vector(self, sim):
            return np.array([1.5, 2.5])

    registry.register("fix", "test/counter", Counter)
    import io
    screen = io.StringIO()
    sim = make_sim(screen=screen)
    sim.command(BOX + "fix n all test/counter\nthermo 3\nthermo_style custom step f_n f_n[1]\n"
                "variable twice equal 2*f_n\nrun 6")
    rows = [line.split() for line in screen.getvalue().splitlines() if line.strip()[:1].isdigit()]
    assert rows[-1] == ["6", "6", "2.5"]
    assert sim.variables.value("twice") == 12.0
    with pytest.raises(ScriptError, match=r"f_n\[5\] is out of range"):
        sim.command("thermo_style custom step f_n[5]\nrun 1")
    with pytest.raises(ScriptError, match="thermo_style: fix nope is not defined"):
        sim.command("thermo_style custom step f_nope\nrun 1")


LIGGGHTS_LOSS = """atom_style granular
atom_modify map array
boundary f f f
newton off
communicate single vel yes
units si
region reg block -0.05 0.05 -0.05 0.05 -0.05 0.05 units box
create_box 1 reg
neighbor 0.002 bin
neigh_modify delay 0
""" + liggghts_material(5.e6, 0.45, 0.9, 0.05) + """pair_style gran model hertz tangential history
pair_coeff * *
timestep 0.00001
create_atoms 1 single 0.0 0.0 0.0 units box
create_atoms 1 single 0.02 0.0 0.0 units box
create_atoms 1 single -0.02 0.0 0.0 units box
set group all diameter 0.01 density 2500
velocity all set 0 0 0
set atom 2 vx 10.0
fix integr all nve/sphere
thermo_style custom step atoms
thermo 100
"""


def test_liggghts_drops_a_particle_leaving_a_fixed_boundary_and_says_so_once(pdps_cli):
    """LIGGGHTS 3.8.0 ignores lost particles by default (thermo_modify lost ignore): this scene, run
    there, prints Atoms 3 to step 200 and 2 from step 300 on, with no message; pdps drops it too,
    and warns once."""
    done = pdps_cli(LIGGGHTS_LOSS + "run 1000\n")
    assert done.returncode == 0
    rows = {int(w[0]): int(w[1]) for w in (line.split() for line in done.stdout.splitlines())
            if len(w) == 2 and w[0].isdigit()}
    assert [rows[s] for s in range(0, 1001, 100)] == [3, 3, 3] + [2] * 8
    warned = [line for line in done.stdout.splitlines() + done.stderr.splitlines() if "lost through fixed" in line]
    assert len(warned) == 1 and "as LIGGGHTS does by default (thermo_modify lost ignore)" in warned[0]


def test_liggghts_lost_error_stops_the_run_as_lammps_does(pdps_cli):
    done = pdps_cli(LIGGGHTS_LOSS + "thermo_modify lost error\nrun 1000\n")
    assert done.returncode == 1
    assert "particle 2 lost through the fixed x boundary at step" in done.stderr
