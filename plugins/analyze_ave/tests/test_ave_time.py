"""ave/time on quantities known in closed form: the step number, the temperature of free particles
(constant), the centroid of particles drifting at one velocity (linear in time, so a symmetric window
averages to its middle), arrays from in-process computes that are simple functions of the step,
and compute rdf arrays averaged element by element."""

import io

import numpy as np
import pytest

from pdps_core.api import Compute, ScriptError
from pdps_core.testing import Record, by_tag, lj_fcc, register_styles


class StepArray(Compute):
    """[[step, step/2], [1, step^2]]: a known array at every step."""
    name = "test/steparray"

    def array(self, sim):
        s = float(sim.step)
        return np.array([[s, 0.5 * s], [1.0, s * s]])


class StepVector(Compute):
    name = "test/stepvector"

    def vector(self, sim):
        return np.array([float(sim.step), 10.0 - 2.0 * sim.step, 0.25])


register_styles(StepArray, StepVector)


@pytest.fixture
def sim(make_sim):
    """Eight free particles (no pair style) with hand-set velocities, integrated by fix nve."""
    s = make_sim()
    s.command("units lj\nregion box block 0 10 0 10 0 10\ncreate_box 2 box\nmass 1 1.0\nmass 2 3.0\n"
              "lattice spacing x 5 y 5 z 5\ncreate_particle 1 box\ntimestep 0.01\nfix 1 all nve\n"
              "thermo 0\nvariable s equal step")
    s.type[::2] = 2
    s.v[:] = np.arange(24, dtype=float).reshape(8, 3) / 10.0 - 1.0
    return s


def read(path):
    with open(path) as handle:
        return handle.read()


def test_step_averages_land_on_multiples_of_nfreq_and_continue_across_runs(sim):
    sim.command("analyze 1 all ave/time 2 3 10 v_s file steps.txt\n"
                "analyze 2 all ave/time 1 1 5 v_s file snap.txt\nrun 30")
    assert sim.analyzes["1"].scalar(sim) == 28.0          # (26 + 28 + 30) / 3
    sim.command("run 10")
    assert read("steps.txt") == ("# Time-averaged data for analyze 1\n# TimeStep v_s\n"
                                 "10 8\n20 18\n30 28\n40 38\n")
    # nrepeat 1 takes the run's first step; step 30 ends one run and starts the next: written once
    assert read("snap.txt").splitlines()[2:] == [f"{n} {n}" for n in range(0, 45, 5)]
    sim.command("reset_timestep 3\nrun 10")                # the window restarts: 6 8 10
    assert read("steps.txt").splitlines()[-1] == "10 8"


def test_temperature_of_free_particles_averages_to_itself(sim):
    sim.command("compute t all temp\ncompute th all temp\n"
                "analyze 1 all ave/time 1 4 4 c_t file t.txt\nrun 8")
    m = np.where(sim.type == 2, 3.0, 1.0)
    expected = (m * (sim.v ** 2).sum(axis=1)).sum() / (3 * 8 - 3)
    assert sim.analyzes["1"].scalar(sim) == pytest.approx(expected, rel=1e-14)
    lines = read("t.txt").splitlines()
    assert lines[:2] == ["# Time-averaged data for analyze 1", "# TimeStep c_t"]
    assert [line.split()[0] for line in lines[2:]] == ["4", "8"]
    assert float(lines[-1].split()[1]) == pytest.approx(expected, rel=1e-5)


def test_centroid_of_a_uniform_drift_averages_to_the_window_middle(sim):
    """All particles move with one velocity: the centroid is linear in time, so the mean over
    steps 6 8 10 is the centroid at step 8; whole vectors give one column per element."""
    sim.v[:] = [0.3, -0.2, 0.1]
    sim.command("compute c all centroid\nanalyze 1 all ave/time 2 3 10 c_c[0] c_c[2] c_c file c.txt")
    start = sim.computes["c"].vector(sim)
    sim.command("run 10")
    middle = start + 8 * 0.01 * np.array([0.3, -0.2, 0.1])
    np.testing.assert_allclose(sim.analyzes["1"].vector(sim), [middle[0], middle[2], *middle], rtol=1e-13)
    assert read("c.txt").splitlines()[1] == "# TimeStep c_c[0] c_c[2] c_c[0] c_c[1] c_c[2]"


def test_whole_array_is_averaged_element_by_element_in_blocks(sim):
    sim.command("compute a all test/steparray\nanalyze 1 all ave/time 2 3 10 c_a file a.txt\nrun 20")
    np.testing.assert_allclose(sim.analyzes["1"].array(sim), [[18, 9], [1, (256 + 324 + 400) / 3]], rtol=1e-15)
    assert read("a.txt") == ("# Time-averaged data for analyze 1\n# TimeStep Number-of-rows\n"
                             "# Row c_a[0] c_a[1]\n"
                             "10 2\n1 8 4\n2 1 66.6667\n"
                             "20 2\n1 18 9\n2 1 326.667\n")


def test_lammps_mode_vector_takes_columns_under_the_fix_spelling(sim):
    sim.command("compute a all test/steparray\ncompute b all test/stepvector\n"
                "fix 2 all ave/time 5 1 5 c_a[*] file all.txt mode vector\n"
                "fix 3 all ave/time 5 1 5 c_a[1] file one.txt mode vector\n"
                "fix 4 all ave/time 5 1 5 c_b[*] file vec.txt\nrun 5")
    assert read("all.txt") == ("# Time-averaged data for fix 2\n# TimeStep Number-of-rows\n"
                               "# Row c_a[0] c_a[1]\n0 2\n1 0 0\n2 1 0\n5 2\n1 5 2.5\n2 1 25\n")
    assert read("one.txt").splitlines()[2:] == ["# Row c_a[1]", "0 2", "1 0", "2 0", "5 2", "1 2.5", "2 25"]
    assert read("vec.txt").splitlines()[1:] == ["# TimeStep c_b[0] c_b[1] c_b[2]", "0 0 10 0.25", "5 5 0 0.25"]
    np.testing.assert_array_equal(sim.fixes["3"].vector(sim), [2.5, 25.0])


def test_rdf_average_is_the_mean_of_the_snapshots(sim):
    """Separate runs give the snapshots at the sampled steps; fix nve with no forces is exact."""
    sim.command("compute r all rdf 6 cutoff 9.0\nanalyze 1 all ave/time 2 3 10 c_r")
    snapshots = []
    for steps in (6, 2, 2):
        sim.command(f"run {steps}")
        snapshots.append(sim.computes["r"].array(sim).copy())
    assert not np.allclose(snapshots[0], snapshots[2])
    np.testing.assert_allclose(sim.analyzes["1"].array(sim), sum(snapshots) / 3, rtol=1e-14, atol=1e-15)


def pressure_at_step(record, types, step, a=25.0, cutoff=1.0):
    """(sum m v^2 + sum_pairs r F) / 3V from the state ``test/record`` kept after ``step``, with the
    conservative DPD force F = a (1 - r/rc) written out: particles 1 and 2 (the first two ids) are
    the only pair closer than the cutoff."""
    x, v = record.x[step - 1], record.v[step - 1]
    m = np.where(types == 2, 3.0, 1.0)
    r = float(np.linalg.norm(x[1] - x[0]))
    assert r < cutoff and sum(np.linalg.norm(x[i] - x[j]) < 2.0 for i in range(8) for j in range(i)) == 1
    return ((m * (v ** 2).sum(axis=1)).sum() + a * (1.0 - r / cutoff) * r) / (3.0 * 1000.0)


@pytest.mark.parametrize("spelling", ["analyze", "fix"])
def test_pressure_average_has_the_virial_of_its_sampled_steps(sim, spelling):
    """Pressure needs the virial; thermo 0 asks for it only at a run's ends, the average on its
    sampled steps (the output flags read its needs). Sampling every 3rd step of 7 with nrepeat 1
    leaves the pressure of step 6, kinetic part and the one interacting pair's r F written out."""
    register_styles(Record)
    order = np.argsort(sim.tag)
    sim.x[order[1]] = sim.x[order[0]] + [0.6, 0.0, 0.0]        # one pair inside the cutoff
    sim.command(f"pair_style dpd 0.0 1.0 1\npair_coeff * * 25 0\ncompute p all pressure\n"
                f"fix r all test/record\n{spelling} 2 all ave/time 1 1 3 c_p\nrun 7")
    record, types = sim.fixes["r"], by_tag(sim, sim.type)
    expected = pressure_at_step(record, types, 6)
    got = (sim.analyzes if spelling == "analyze" else sim.fixes)["2"].scalar(sim)
    assert got == pytest.approx(expected, rel=1e-12)
    # the virial is a quarter of it, and steps 3 and 7 differ by 1 %: a stale or missing virial fails
    kinetic = (np.where(types == 2, 3.0, 1.0) * (record.v[5] ** 2).sum(axis=1)).sum() / 3000.0
    assert abs(expected - kinetic) > 0.1 * expected
    assert abs(pressure_at_step(record, types, 3) - expected) > 1e-6 * expected
    assert abs(pressure_at_step(record, types, 7) - expected) > 1e-6 * expected


def test_outputs_are_zero_before_the_first_average(sim):
    sim.command("analyze 1 all ave/time 1 1 10 v_s\nanalyze 2 all ave/time 1 1 10 v_s v_s")
    assert sim.analyzes["1"].scalar(sim) == 0.0
    # LAMMPS reads 0 before the first average; a row of single values has its length from the start
    np.testing.assert_array_equal(sim.analyzes["2"].vector(sim), [0.0, 0.0])


# Averages of 3 samples 2 steps apart every 10 steps, of an LJ crystal melting from T = 1.5 (the
# LAMMPS dialect: velocity create draws LAMMPS's numbers). LAMMPS 22 Jul 2025, recorded on this
# machine: step, temp, f_one, f_avg[1], f_avg[2] at steps 0, 10, 20; 0 before the first average.
AVE_TIME_SCRIPT = lj_fcc(3) + """mass 1 1.0
velocity all create 1.5 87287 loop geom
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0
fix 1 all nve
variable t equal temp
fix avg all ave/time 2 3 10 v_t v_t
fix one all ave/time 2 3 10 v_t
thermo 10
thermo_style custom step temp f_one f_avg[1] f_avg[2]
thermo_modify format float %.15g
run 20"""
AVE_TIME_LAMMPS = [[0, 1.5, 0, 0, 0],
                   [10, 1.17565905594515, 1.29652339732162, 1.29652339732162, 1.29652339732162],
                   [20, 0.66404039212863, 0.686323405367074, 0.686323405367074, 0.686323405367074]]


def test_fix_ave_time_prints_what_lammps_prints():
    from pdps_core.api import Simulation
    from pdps_core.testing import thermo_rows
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None, dialect="lammps")
    sim.command(AVE_TIME_SCRIPT)
    rows = thermo_rows(screen.getvalue())
    assert [row[0] for row in rows] == [0, 10, 20]
    np.testing.assert_allclose(rows, AVE_TIME_LAMMPS, rtol=1e-12, atol=0)


@pytest.mark.parametrize("command, message", [
    ("analyze 1 all ave/time 0 1 10 v_s", "analyze: nevery must be > 0 (got 0)"),
    ("analyze 1 all ave/time 1 0 10 v_s", "analyze: nrepeat must be > 0 (got 0)"),
    ("analyze 1 all ave/time 1 1 -5 v_s", "analyze: nfreq must be > 0 (got -5)"),
    ("analyze 1 all ave/time 3 1 10 v_s", "analyze: nfreq must be a multiple of nevery (got nevery 3, nfreq 10)"),
    ("analyze 1 all ave/time 2 6 10 v_s", "analyze: nrepeat * nevery must not exceed nfreq (got 6 * 2 = 12 > 10)"),
    ("fix 9 all ave/time 2 6 10 v_s", "fix: nrepeat * nevery must not exceed nfreq (got 6 * 2 = 12 > 10)"),
    ("analyze 1 all ave/time 1 1 10 file x.txt",
     "analyze: missing argument values; usage: "
     "analyze ID GROUP ave/time NEVERY NREPEAT NFREQ value... [file NAME] [mode scalar|vector] "
     "[ave one|running|window M] [start S] [off M] [overwrite] [title1|title2|title3 S]"),
    ("analyze 1 all ave/time 1 1 10 c_nope", "analyze: compute nope is not defined (value c_nope)"),
    ("analyze 1 all ave/time 1 1 10 v_nope", "analyze: variable nope is not defined (value v_nope)"),
    ("analyze 1 all ave/time 1 1 10 temp", "analyze: value must be c_ID, c_ID[i], c_ID[i][j], c_ID[*], f_ID, f_ID[i], f_ID[*] or v_NAME (got temp)"),
    ("analyze 1 all ave/time 1 1 10 v_s every 2", "analyze: value must be c_ID, c_ID[i], c_ID[i][j], c_ID[*], f_ID, f_ID[i], f_ID[*] or v_NAME "
     "(got every)"),
    ("analyze 1 all ave/time 1 1 10 c_t[1 file x", "analyze: value must be c_ID, c_ID[i], c_ID[i][j], c_ID[*], f_ID, f_ID[i], f_ID[*] or v_NAME (got c_t[1)"),
    ("analyze 1 all ave/time 1 1 10 f_nope", "analyze: fix nope is not defined (value f_nope)"),
    ("analyze 1 all ave/time 1 1 10 v_s mode matrix", "analyze: mode must be one of 'scalar' or 'vector' (got matrix)"),
    ("analyze 1 all ave/time 1 1 10 v_s file", "analyze: keyword file needs 1 value(s) (got 0)"),
    ("analyze 1 all ave/time 1 1 10 c_a v_s",
     "analyze: c_a is averaged as a block of rows and v_s as a single number: average them in two analyze commands"),
])
def test_bad_input_is_one_line(sim, command, message):
    sim.command("compute a all test/steparray")
    with pytest.raises(ScriptError) as error:
        sim.command(command)
    assert str(error.value) == f"<command>:1: {message}"


def test_fix_values_are_averaged_as_lammps_allows():
    from pdps_core.api import Simulation
    sim = Simulation(screen=False, log=None, dialect="lammps")
    sim.command("region box block 0 5 0 5 0 5\ncreate_box 1 box\nmass 1 1\ncreate_atoms 1 single 1 1 1\n"
                "create_atoms 1 single 2 1 1\nvelocity all set 1 0 0\nfix 1 all nve\nvariable s equal step\n"
                "fix a all ave/time 1 5 5 v_s\nfix b all ave/time 5 2 10 f_a f_a[*]\nrun 10")
    # f_a: the mean step of 1..5 (3) and of 6..10 (8); f_b averages them at steps 5 and 10
    assert sim.fix_value("a", ()) == 8.0
    assert sim.fix_value("b", (1,)) == sim.fix_value("b", (2,)) == 5.5


# ave running with off, ave window M with start, overwrite with titles, on the scene above. LAMMPS
# 22 Jul 2025, recorded on this machine: step, temp, press, f_run[1], f_run[2], f_win; the file holds
# the two titles and the last running average only.
AVE_KEYWORDS_SCRIPT = AVE_TIME_SCRIPT.split("fix avg")[0] + """variable p equal press
fix run all ave/time 2 3 10 v_t v_p ave running off 2
fix win all ave/time 2 3 10 v_t ave window 2 start 30
fix ovr all ave/time 1 1 10 v_t ave running overwrite file ovr.txt title1 "# mine" title2 "# step T"
thermo 10
thermo_style custom step temp press f_run[1] f_run[2] f_win
thermo_modify format float %.15g
run 60"""
AVE_KEYWORDS_LAMMPS = [
    [0, 1.5, -4.98074227008559, 0, 0, 0],
    [10, 1.17565905594515, -2.45684768334709, 1.29652339732162, -2.45684768334709, 0],
    [20, 0.66404039212863, 1.18404584704705, 0.991423401344348, 1.18404584704705, 0],
    [30, 0.770483075003006, 0.70681065976391, 0.917893398663652, 0.70681065976391, 0.770833393302261],
    [40, 0.726906012675251, 0.881249905334628, 0.86933053588651, 0.881249905334628, 0.747237670428671],
    [50, 0.738589600043814, 0.746711945145139, 0.843755749740652, 0.746711945145139, 0.732549276356151],
    [60, 0.731035222693949, 0.721069171616776, 0.822551416674925, 0.721069171616776, 0.728993178251756]]


def test_ave_running_window_start_off_and_overwrite_as_lammps(tmp_path, monkeypatch):
    from pdps_core.api import Simulation
    from pdps_core.testing import thermo_rows
    monkeypatch.chdir(tmp_path)
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=None, dialect="lammps")
    sim.command(AVE_KEYWORDS_SCRIPT)
    rows = thermo_rows(screen.getvalue())
    assert [row[0] for row in rows] == list(range(0, 61, 10))
    np.testing.assert_allclose(rows, AVE_KEYWORDS_LAMMPS, rtol=1e-11, atol=1e-13)
    assert (tmp_path / "ovr.txt").read_text() == "# mine\n# step T\n60 0.900959\n"


@pytest.mark.parametrize("keywords, message", [
    ("ave window 0", "ave window M needs M >= 1 (got 0)"),
    ("overwrite", "overwrite needs ave running (LAMMPS)"),
    ("off 3", "off 3: there are 2 values"),
    ("ave sometimes", "ave"),
])
def test_bad_ave_keywords_are_one_line(sim, keywords, message):
    with pytest.raises(ScriptError) as error:
        sim.command(f"variable s equal step\nfix 9 all ave/time 1 1 10 v_s v_s {keywords}")
    assert message in str(error.value)
