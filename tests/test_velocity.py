"""velocity: in the LAMMPS dialect the velocities LAMMPS gives (tests/data/velocity: LAMMPS's own
numbers for the same scripts, recorded by benchmarks/lammps_references/velocity.py), on one rank and
two; in the PDPS dialect the counter-based numbers; every style's physics; the errors."""

import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from pdps_core.errors import ScriptError
from pdps_core.random_park import park_gaussian, park_reset_coord, park_state, park_uniform
from pdps_core.state import observables as obs
from pdps_core.testing import mpiexec, write_data

DATA = Path(__file__).parent / "data" / "velocity"
SCENES = ["uniform", "gaussian_rot", "gaussian_mom_no", "group", "sum", "two_d", "loop_local",
          "loop_local_gaussian", "loop_geom", "loop_geom_gaussian", "temp_compute", "set_lattice",
          "set_no_lattice", "ramp", "scale", "zero", "sphere", "metal"]
TOLERANCE = 1e-14


def lammps_velocities(name):
    """LAMMPS's dump: (ids, velocities) in id order."""
    lines = (DATA / f"ref.{name}").read_text().splitlines()
    start = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
    table = np.array([[float(w) for w in line.split()] for line in lines[start:]])
    return table[:, 0].astype(np.int64), table[:, 1:]


def by_id(sim):
    order = np.argsort(sim.particles.tag[: sim.nlocal])
    return sim.particles.tag[: sim.nlocal][order], sim.v[order]


def assert_lammps(ids, v, name):
    ref_ids, ref_v = lammps_velocities(name)
    assert np.array_equal(ids, ref_ids)
    scale = np.sqrt((ref_v ** 2).sum(axis=1).mean())
    assert scale > 0
    assert np.abs(v - ref_v).max() <= TOLERANCE * scale, np.abs(v - ref_v).max() / scale


# ---- the generator -------------------------------------------------------------------------------
def test_park_miller_minimal_standard_check_value():
    """Park & Miller (1988): from seed 1, the 10,000th seed is 1043618065."""
    state = park_state(1)
    assert park_uniform(state) == 16807 / 2147483647
    for _ in range(9999):
        value = park_uniform(state)
    assert state[0] == 1043618065
    assert value == 1043618065 * (1.0 / 2147483647)


def test_park_gaussian_returns_the_saved_second_value_then_draws_anew():
    state = park_state(5)
    copy = state.copy()
    first, second = park_gaussian(state), park_gaussian(state)
    v1, v2 = 2.0 * park_uniform(copy) - 1.0, 2.0 * park_uniform(copy) - 1.0
    while not 0.0 < v1 * v1 + v2 * v2 < 1.0:
        v1, v2 = 2.0 * park_uniform(copy) - 1.0, 2.0 * park_uniform(copy) - 1.0
    rsq = v1 * v1 + v2 * v2
    fac = np.sqrt(-2.0 * np.log(rsq) / rsq)
    assert (first, second) == (v2 * fac, v1 * fac)
    assert state[0] == copy[0]          # the second value cost no draw


def test_park_reset_coord_depends_on_every_coordinate_and_the_seed():
    seeds = set()
    for ibase, coord in [(1, (0.0, 0.0, 0.0)), (2, (0.0, 0.0, 0.0)), (1, (1e-300, 0.0, 0.0)),
                         (1, (0.0, 0.5, 0.0)), (1, (0.0, 0.0, -0.5))]:
        state = park_state(1)
        park_reset_coord(state, ibase, np.array(coord))
        assert 1 <= state[0] < 2147483647 and state[1] == 0.0
        seeds.add(state[0])
    assert len(seeds) == 5


def test_park_seeds_out_of_range_are_refused():
    for seed in (0, 2147483647):
        with pytest.raises(ScriptError, match="seed must be from 1 to 2147483646"):
            park_state(seed)


# ---- LAMMPS's numbers ---------------------------------------------------------------------------
@pytest.mark.parametrize("name", SCENES)
def test_velocities_equal_lammps(make_sim, name):
    sim = make_sim()
    sim.file(str(DATA / f"in.{name}"))
    assert sim.dialect.name == "lammps"
    assert_lammps(*by_id(sim), name)


def test_every_recorded_scene_is_tested():
    assert sorted(p.name[3:] for p in DATA.glob("in.*")) == sorted(SCENES)


DRIVER = """
import sys
import numpy as np
from pdps_core.simulation import Simulation
sim = Simulation(screen=False, log=None)
sim.file(sys.argv[1])
p = sim.particles
rows = sim.comm.gather_rows(np.column_stack([p.tag[: p.nlocal], p.v[: p.nlocal]]))
sizes = sim.comm.gather_rows(np.array([p.nlocal]))
if sim.comm.is_root:
    np.save(sys.argv[2], rows)
    np.save(sys.argv[3], sizes)
"""


@pytest.mark.parametrize("name", ["uniform", "gaussian_rot", "loop_geom", "loop_geom_gaussian"])
def test_two_ranks_give_lammps_velocities_for_loop_all_and_geom(tmp_path, name):
    (tmp_path / "driver.py").write_text(DRIVER)
    done = subprocess.run([mpiexec(), "-n", "2", sys.executable, "driver.py", str(DATA / f"in.{name}"),
                           "v.npy", "n.npy"], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    sizes = np.load(tmp_path / "n.npy")
    assert len(sizes) == 2 and sizes.min() > 0          # both ranks own particles
    rows = np.load(tmp_path / "v.npy")
    rows = rows[np.argsort(rows[:, 0])]
    assert_lammps(rows[:, 0].astype(np.int64), rows[:, 1:], name)


# ---- semantics the references do not show ----------------------------------------------------------
LAMMPS_BOX = "units lj\natom_style atomic\n"


def lammps_sim(make_sim, tmp_path, n=20, tags=None, extra=""):
    rng = np.random.default_rng(3)
    write_data(tmp_path / "s.data", (0, 0, 0), (4, 4, 4), rng.random((n, 3)) * 4, tags=tags,
               types=np.arange(n) % 2 + 1, masses={1: 1.0, 2: 2.0})
    sim = make_sim(dialect="lammps")
    sim.command(LAMMPS_BOX + f"read_data {tmp_path / 's.data'}\n" + extra)
    return sim


def test_loop_all_needs_ids_one_to_n_but_geom_and_local_do_not(make_sim, tmp_path):
    sim = lammps_sim(make_sim, tmp_path, n=3, tags=[1, 2, 5])
    with pytest.raises(ScriptError) as caught:
        sim.command("velocity all create 1.0 7")
    assert caught.value.message == ("loop all needs the particle ids to be 1..N (LAMMPS's rule); the 3 "
                                    "particles have ids 1..5: use loop local or loop geom")
    assert np.all(sim.v == 0)
    for loop in ("local", "geom"):
        sim.command(f"velocity all create 1.0 7 loop {loop}")
        assert obs.temperature(sim) == pytest.approx(1.0, rel=1e-14)


def test_create_then_scale_gives_the_temperature_and_zero_momentum(make_sim, tmp_path):
    sim = lammps_sim(make_sim, tmp_path, n=30)
    sim.command("velocity all create 2.0 11 dist gaussian rot yes\nvelocity all scale 0.5")
    m = obs.masses(sim)
    assert obs.temperature(sim) == pytest.approx(0.5, rel=1e-14)
    momentum = (m[:, None] * sim.v).sum(axis=0)
    x = sim.x - (m[:, None] * sim.x).sum(axis=0) / m.sum()
    angular = (m[:, None] * np.cross(x, sim.v)).sum(axis=0)
    typical = (m * np.linalg.norm(sim.v, axis=1)).sum() * 4
    assert np.abs(momentum).max() < 1e-14 * typical
    assert np.abs(angular).max() < 1e-13 * typical


def test_uniform_and_gaussian_give_every_mass_the_same_temperature(make_sim, tmp_path):
    """v = r / sqrt(m): equipartition between a light and a heavy species, in both dialects."""
    for dialect, dist in [("lammps", "uniform"), ("lammps", "gaussian"), ("pdps", "uniform"),
                          ("pdps", "gaussian")]:
        rng = np.random.default_rng(1)
        n = 4000
        write_data(tmp_path / "m.data", (0, 0, 0), (20, 20, 20), rng.random((n, 3)) * 20,
                   types=np.arange(n) % 2 + 1, masses={1: 1.0, 2: 9.0})
        sim = make_sim(dialect=dialect)
        sim.command(f"read_data {tmp_path / 'm.data'}\ngroup light type 1\ngroup heavy type 2\n"
                    f"velocity all create 1.5 4242 dist {dist}")
        assert obs.temperature(sim) == pytest.approx(1.5, rel=1e-13)
        for group in ("light", "heavy"):
            assert obs.temperature(sim, group) == pytest.approx(1.5, rel=0.05), (dialect, dist, group)


def test_pdps_numbers_are_the_counter_based_ones_and_ignore_loop(make_sim, tmp_path):
    write_data(tmp_path / "p.data", (0, 0, 0), (4, 4, 4), np.random.default_rng(2).random((10, 3)) * 4,
               tags=[1, 2, 3, 4, 5, 6, 7, 8, 9, 2 ** 40])
    results = []
    for loop in ("all", "local", "geom"):
        sim = make_sim(dialect="pdps")
        sim.command(f"read_data {tmp_path / 'p.data'}\nvelocity all create 1.0 10342 gaussian loop {loop}")
        results.append(by_id(sim)[1])
    assert np.array_equal(results[0], results[1]) and np.array_equal(results[0], results[2])
    lammps = make_sim(dialect="lammps")
    lammps.command(f"read_data {tmp_path / 'p.data'}\nvelocity all create 1.0 10342 gaussian loop geom")
    assert not np.allclose(by_id(lammps)[1], results[0])


def test_units_default_is_box_in_pdps_and_lattice_in_lammps(make_sim):
    setup = "lattice sc 0.5\nregion b block 0 4 0 4 0 4\ncreate_box 1 b\nmass 1 1\ncreate_atoms 1 single 1 1 1\n"
    spacing = 2.0 ** (1.0 / 3.0)        # sc in lj units: (1 / rho*)^(1/3)
    pdps = make_sim(dialect="pdps")
    pdps.command(setup + "velocity all set 1 0 0\nvelocity all ramp vy 0 3 x 0 4")
    assert pdps.v[0, 0] == 1.0 and pdps.v[0, 1] == pytest.approx(3 * (spacing - 0) / 4, rel=1e-15)
    lammps = make_sim(dialect="lammps")
    lammps.command(setup + "velocity all set 1 0 0\nvelocity all ramp vy 0 3 x 0 4")
    assert lammps.v[0, 0] == pytest.approx(spacing, rel=1e-15)
    assert lammps.v[0, 1] == pytest.approx(3 * spacing * 0.25, rel=1e-15)      # x = 1 of 0..4 spacings
    pdps.command("velocity all set 1 NULL NULL units lattice")
    assert pdps.v[0, 0] == pytest.approx(spacing, rel=1e-15)


def test_set_sum_ramp_and_zero_linear(make_sim, tmp_path):
    sim = lammps_sim(make_sim, tmp_path, n=12)
    sim.command("velocity all set 1 2 3 units box\nvelocity all set -1 NULL 1 sum yes units box\n"
                "variable w atom 2*x\nvelocity all set NULL v_w NULL units box")
    assert np.array_equal(sim.v[:, 0], np.zeros(12)) and np.array_equal(sim.v[:, 2], np.full(12, 4.0))
    assert np.array_equal(sim.v[:, 1], 2 * sim.x[:, 0])
    sim.command("velocity all ramp vx 1 3 z 1 3 units box")
    expected = 1 + 2 * np.clip((sim.x[:, 2] - 1) / 2, 0, 1)
    assert np.allclose(sim.v[:, 0], expected, rtol=1e-15, atol=0)
    sim.command("velocity all zero linear")
    m = obs.masses(sim)
    assert np.abs((m[:, None] * sim.v).sum(axis=0)).max() < 1e-13


# ---- errors -------------------------------------------------------------------------------------
@pytest.mark.parametrize("line, message", [
    ("velocity all create 1 1 bias yes",
     "velocity keyword bias is not supported (supported: dist, sum, mom, rot, temp, loop, units)"),
    ("velocity all create 1 1 rigid body",
     "velocity keyword rigid is not supported (supported: dist, sum, mom, rot, temp, loop, units)"),
    ("velocity all create 1 1 loop sideways", "loop must be one of all, local, geom (got sideways)"),
    ("velocity all create 1 1 units furlong", "units must be one of box, lattice (got furlong)"),
    ("velocity all create 1 1 temp nothere", "temp nothere: compute nothere is not defined"),
    ("compute k all ke\nvelocity all create 1 1 temp k", "temp k: compute k (ke) does not compute a temperature"),
    ("velocity all create 1 1 dist", "keyword dist needs a value; usage: velocity GROUP create T SEED | set "
     "VX VY VZ | scale T | ramp vx|vy|vz VLO VHI x|y|z CLO CHI | zero linear|angular, then [dist "
     "uniform|gaussian] [sum yes|no] [mom yes|no] [rot yes|no] [temp COMPUTE-ID] [loop all|local|geom] "
     "[units box|lattice]"),
    ("velocity all create 1 2147483647", "seed must be <= 2147483646 (got 2147483647)"),
    ("velocity all create 1e51 3", "temperature must be <= 1e+50 (got 1e51)"),
    ("velocity all scale -1", "temperature must be >= 0 (got -1)"),
    ("velocity all scale", "expected a temperature; usage: velocity GROUP create T SEED | set VX VY VZ | "
     "scale T | ramp vx|vy|vz VLO VHI x|y|z CLO CHI | zero linear|angular, then [dist uniform|gaussian] "
     "[sum yes|no] [mom yes|no] [rot yes|no] [temp COMPUTE-ID] [loop all|local|geom] [units box|lattice]"),
    ("velocity all ramp vw 0 1 x 0 1", "ramp component must be one of vx, vy, vz (got vw)"),
    ("velocity all ramp vx 0 1 w 0 1", "ramp coordinate must be one of x, y, z (got w)"),
    ("velocity all ramp vx 0 1 x 2 2", "ramp needs clo != chi (got 2 2)"),
    ("velocity all ramp vx 0 inf x 0 1", "vhi must be finite (got inf)"),
    ("velocity all set v_none 0 0", "vx: variable none is not defined"),
    ("variable s string abc\nvelocity all set v_s 0 0",
     "vx: variable s is string-style; velocity set takes equal- or atom-style variables"),
    ("variable big equal 1e200\nvelocity all set v_big 0 0", "vx: variable big is 1e+200, beyond +-1e+150"),
    ("lattice none 1e100\nvelocity all set 1e100 0 0",
     "vx 1e100 times the lattice spacing 1e+100 is beyond +-1e+150"),
    ("velocity all zero sideways", "zero must be one of linear, angular (got sideways)"),
    ("group none empty\nvelocity none zero linear", "group none has no particles to zero the momentum of"),
    ("group none empty\nvelocity none create 1 1", "group none has no particles"),
    ("velocity all spin 1", "velocity style must be one of create, set, scale, ramp, zero (got spin)"),
])
def test_errors_in_the_lammps_dialect(make_sim, tmp_path, line, message):
    sim = lammps_sim(make_sim, tmp_path)
    sim.command("velocity all set 0.5 0.25 0 units box")
    before = sim.v.copy()
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert caught.value.command == "velocity"
    assert caught.value.message == message
    assert np.array_equal(sim.v, before)


def test_a_result_beyond_what_squares_hold_is_refused(make_sim, tmp_path):
    sim = lammps_sim(make_sim, tmp_path)
    sim.command("velocity all set 1e150 0 0 units box")
    before = sim.v.copy()
    with pytest.raises(ScriptError) as caught:
        sim.command("velocity all set 1e150 NULL NULL sum yes units box")
    assert caught.value.message == "velocity set gives a velocity of 2e+150, beyond +-1e+150 where squares overflow"
    assert np.array_equal(sim.v, before)


def test_scaling_a_group_at_rest_is_refused(make_sim, tmp_path):
    sim = lammps_sim(make_sim, tmp_path)
    with pytest.raises(ScriptError) as caught:
        sim.command("velocity all scale 1")
    assert caught.value.message == ("the group's temperature is 0, which no factor scales (particles at rest, "
                                    "or no degrees of freedom)")


def test_2d_refuses_z_velocities(make_sim, tmp_path):
    write_data(tmp_path / "f.data", (0, 0, -0.5), (4, 4, 0.5), [[1, 1, 0], [2, 3, 0]])
    sim = make_sim(dialect="lammps")
    sim.command(f"dimension 2\nread_data {tmp_path / 'f.data'}\nvariable z equal 0")
    for line, message in [("velocity all set 0 0 1", "vz must be 0 or NULL in 2-d (got 1)"),
                          ("velocity all set 0 0 v_z", "vz cannot be a variable in 2-d (got v_z)"),
                          ("velocity all ramp vz 0 1 x 0 1", "ramp of vz in 2-d")]:
        with pytest.raises(ScriptError) as caught:
            sim.command(line)
        assert caught.value.message == message
    sim.command("velocity all set 1 2 0")
    assert np.array_equal(sim.v, [[1, 2, 0], [1, 2, 0]])


def test_a_single_particle_has_no_temperature_to_scale(make_sim, tmp_path):
    """LAMMPS: 'Attempting to rescale a 0.0 temperature'; PDPS keeps the particle at rest."""
    write_data(tmp_path / "one.data", (0, 0, 0), (4, 4, 4), [[1, 1, 1]])
    lammps = make_sim(dialect="lammps")
    lammps.command(f"read_data {tmp_path / 'one.data'}")
    with pytest.raises(ScriptError, match="the group's temperature is 0"):
        lammps.command("velocity all create 1.0 5")
    pdps = make_sim(dialect="pdps")
    pdps.command(f"read_data {tmp_path / 'one.data'}\nvelocity all create 1.0 5")
    assert np.all(pdps.v == 0)


def test_loop_local_seed_plus_rank_must_stay_a_valid_seed(make_sim, tmp_path):
    sim = lammps_sim(make_sim, tmp_path)
    sim.command("velocity all create 1.0 2147483646 loop local")       # one rank: SEED + 0
    assert obs.temperature(sim) == pytest.approx(1.0, rel=1e-14)


def test_mass_must_be_set(make_sim):
    sim = make_sim(dialect="lammps")
    sim.command("region b block 0 4 0 4 0 4\ncreate_box 2 b\nmass 1 1\ncreate_atoms 1 single 1 1 1 units box\n"
                "create_atoms 2 single 2 2 2 units box")
    with pytest.raises(ScriptError) as caught:
        sim.command("velocity all create 1.0 5")
    assert caught.value.message == "mass is not set for type 2 (use the mass command)"


def test_the_pdps_manual_example_still_runs(make_sim):
    sim = make_sim()
    sim.command(textwrap.dedent("""\
        region box block 0 4 0 4 0 4
        create_box 1 box
        mass 1 1.0
        lattice spacing x 1 y 1 z 1
        create_particle 1 box
        velocity all create 10.0 10342 gaussian
    """))
    assert sim.dialect.name == "pdps"
    assert obs.temperature(sim) == pytest.approx(10.0, rel=1e-13)
