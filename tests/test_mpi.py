"""The same script on 1, 2 and 4 ranks (mpiexec from the mpich wheel that `make test` installs)
gives the same answers: deterministic styles to the last printed digit, DPD's noise too since it is
keyed by particle ids, not by rank."""

import hashlib
import pathlib
import subprocess
import sys
import textwrap

import numpy as np
import pytest

from pdps_core.testing import bench_data as write_bench_data

ROOT = pathlib.Path(__file__).parents[1]
MPIEXEC = pathlib.Path(sys.executable).parent / "mpiexec"


def run(tmp_path, script, ranks, name="in.test", extra=()):
    (tmp_path / name).write_text(textwrap.dedent(script))
    assert MPIEXEC.exists(), "mpiexec missing: make test installs mpich with the core's [mpi] extra"
    result = subprocess.run([str(MPIEXEC), "-n", str(ranks), sys.executable, "-m", "pdps_core.cli", "run",
                             name, "-log", "none", *extra], cwd=tmp_path, capture_output=True, text=True,
                            timeout=900)
    return result


def thermo(stdout):
    return [line for line in stdout.splitlines() if line.strip()[:1].isdigit()]


WATER = (ROOT / "examples" / "water.in").read_text().replace(
    "dump              1 all atom 1 dump.atom", "dump 1 all custom 50 dump.water id type x y z vx vy vz").replace(
    "thermo            1", "thermo 10").replace("run               200", "run 100")


def test_water_example_gives_the_same_thermo_and_dump_on_1_2_and_4_ranks(tmp_path):
    outputs, dumps = {}, {}
    for ranks in (1, 2, 4):
        result = run(tmp_path, WATER, ranks)
        assert result.returncode == 0, result.stderr
        outputs[ranks] = thermo(result.stdout)
        dumps[ranks] = (tmp_path / "dump.water").read_text()
        assert f"on {ranks} procs for 100 steps with 4000 particles" in result.stdout
    assert len(outputs[1]) == 11 + 0 and outputs[1] == outputs[2] == outputs[4]
    # positions written with 10 digits: identical up to summation order over 100 chaotic steps
    assert dumps[1].count("ITEM: TIMESTEP") == 3
    assert dumps[1].splitlines()[:9] == dumps[4].splitlines()[:9]


@pytest.fixture(scope="module")
def bench_data(tmp_path_factory):
    folder = tmp_path_factory.mktemp("bench_data")
    for kind in ("dpd_gw", "gran_box"):
        write_bench_data(kind, folder / f"{kind}.data")
    return folder


# SHA-256 of the files the benchmark kit's make_data.py writes (the ones LAMMPS reads in the
# benchmarks), so the scenes here are the scenes the speed and accuracy figures are about
BENCH_DATA_SHA256 = {
    "dpd_gw": "40d1f04f71352ea38b8a2425a8576e2a48a83048b1d6ec8d0995ad910038001f",
    "gran_box": "30d64c8cb16bba97abb0563a9cbff8e10077dd6a94d473e6683a37a3b1d09445",
}


@pytest.mark.parametrize("kind", sorted(BENCH_DATA_SHA256))
def test_bench_data_is_the_benchmark_kits_file_byte_for_byte(bench_data, kind):
    digest = hashlib.sha256((bench_data / f"{kind}.data").read_bytes()).hexdigest()
    assert digest == BENCH_DATA_SHA256[kind]


@pytest.mark.parametrize("scene,steps", [("dpd_gw", 20), ("gran_box", 100)])
def test_bench_scenes_give_the_same_thermo_on_1_2_and_4_ranks(tmp_path, bench_data, scene, steps):
    script = (ROOT / "benchmarks" / "scenes" / f"in.{scene}").read_text()
    script = script.replace(f"thermo ${{nsteps}}", "thermo 10") if scene == "gran_box" else \
        script.replace("thermo 1\n", "thermo 5\n")
    outputs = {}
    for ranks in (1, 2, 4):
        result = run(tmp_path, script, ranks, extra=("-var", "data", str(bench_data / f"{scene}.data"),
                                                     "-var", "seed", "928342", "-var", "nsteps", str(steps)))
        assert result.returncode == 0, result.stderr
        outputs[ranks] = thermo(result.stdout)
    assert len(outputs[1]) >= 3
    assert outputs[1] == outputs[2] == outputs[4]


def test_particles_crossing_ranks_and_periodic_faces_many_times(tmp_path):
    script = """
        region box block 0 4 0 4 0 4
        create_box 1 box
        mass 1 1
        create_particle 1 single 0.5 0.5 0.5
        create_particle 1 single 3.5 1.0 2.0
        velocity all set 7.3 -5.1 3.3
        pair_style dpd 0.0 1.0 5
        pair_coeff * * 0.0 0.0
        fix 1 all nve
        timestep 0.01
        compute c all centroid
        thermo 100
        thermo_style custom step c_c[0] c_c[1] c_c[2]
        run 500
    """
    outputs = {ranks: thermo(run(tmp_path, script, ranks).stdout) for ranks in (1, 4)}
    # free flight over 36 box lengths in x: the unwrapped centroid is exact arithmetic
    assert outputs[1] == outputs[4]
    last = [float(v) for v in outputs[4][-1].split()[1:]]
    assert last == pytest.approx([(0.5 + 3.5) / 2 + 7.3 * 5.0, (0.5 + 1.0) / 2 - 5.1 * 5.0, 1.25 + 3.3 * 5.0])


def test_a_rank_without_particles_and_sub_domains_thinner_than_the_cutoff(tmp_path):
    script = """
        processors 4 1 1
        region box block 0 2.4 0 6 0 6
        create_box 1 box
        mass 1 1
        create_particle 1 single 0.2 3.0 3.0
        create_particle 1 single 0.9 3.2 3.1
        create_particle 1 single 2.3 3.0 3.0
        pair_style dpd 0.0 1.0 5
        pair_coeff * * 25.0 0.0
        fix 1 all nve
        timestep 0.01
        thermo 10
        thermo_style custom step pe press
        run 30
    """
    one = run(tmp_path, script.replace("processors 4 1 1", "processors 1 1 1"), 1)
    four = run(tmp_path, script, 4)
    assert one.returncode == four.returncode == 0, four.stderr
    # sub-domains 0.6 wide, cutoff + skin 1.3: ghosts come from two ranks away and across the face
    assert thermo(one.stdout) == thermo(four.stdout)
    assert float(thermo(one.stdout)[0].split()[1]) > 0.0          # the pairs across ranks interact


def test_an_error_on_one_rank_stops_all_ranks_with_one_message(tmp_path):
    script = """
        boundary p p f
        region box block 0 8 0 8 0 8
        create_box 1 box
        mass 1 1
        create_particle 1 single 1 1 1
        create_particle 1 single 7 7 7
        velocity all set 0 0 0
        fix 1 all nve
        timestep 0.1
        run 0
        velocity all set 0 0 3
        run 100
    """
    result = run(tmp_path, script, 4)
    assert result.returncode != 0
    errors = [line for line in result.stderr.splitlines() if line.startswith("ERROR")]
    assert errors == [errors[0]] and "particle 2 lost through the fixed z boundary" in errors[0]


def test_frictional_contacts_across_ranks_keep_their_history(tmp_path):
    # a compressed packing: every sphere in contact from the start, contacts crossing rank faces,
    # 17 rebuilds in 1000 steps; without sending mirrored springs back to their owners the 4-rank
    # run departs from the serial one at step 800
    script = (ROOT / "tests" / "data" / "dense_granular.in").read_text()
    outputs = {}
    for ranks in (1, 4):
        result = run(tmp_path, script, ranks)
        assert result.returncode == 0, result.stderr
        outputs[ranks] = thermo(result.stdout)
    assert len(outputs[1]) == 6 and outputs[1] == outputs[4]


def test_a_restart_written_on_2_ranks_continues_on_4_like_the_serial_run(tmp_path):
    first = WATER.replace("dump 1 all custom 50 dump.water id type x y z vx vy vz", "").replace(
        "run 100", "run 50\nwrite_restart water.restart")
    second = """
        read_restart water.restart
        thermo 10
        thermo_style custom step temp press
        run 50
    """
    serial = run(tmp_path, first.replace("write_restart water.restart", "run 50"), 1)
    assert serial.returncode == 0, serial.stderr
    written = run(tmp_path, first, 2)
    assert written.returncode == 0, written.stderr
    continued = run(tmp_path, second, 4, name="in.more")
    assert continued.returncode == 0, continued.stderr
    assert "Read restart file water.restart: 4000 particles at step 50" in continued.stdout
    # the serial run's second half, from its step-50 line on
    assert thermo(continued.stdout) == thermo(serial.stdout)[-6:]


def shardlow_liquid(height, n):
    """n DPD particles (pair dpd/fdt, density 3) at random in an 8 x 8 x ``height`` box, integrated
    with fix shardlow and nve."""
    return f"""
        region box block 0 8 0 8 0 {height}
        create_box 1 box
        mass 1 1
        create_particle 1 random_no_overlap {n} box 0.0 7
        pair_style dpd/fdt 1.0 1.0 4321
        pair_coeff * * 25.0 4.5 1.0
        velocity all create 1.0 5 gaussian
        fix 1 all shardlow
        fix 2 all nve
        timestep 0.04
    """


def test_shardlow_sweeps_in_one_order_on_any_number_of_ranks(tmp_path):
    script = shardlow_liquid(8, 1536) + """
        thermo 20
        thermo_style custom step temp press
        run 100
    """
    outputs = {ranks: thermo(run(tmp_path, script, ranks).stdout) for ranks in (1, 2, 4)}
    assert len(outputs[1]) == 6
    assert outputs[1] == outputs[2] == outputs[4]


def test_shardlow_in_a_box_thinner_than_two_cutoffs_sweeps_alike_on_1_2_and_4_ranks(tmp_path):
    """Along z (1.5 cutoffs) many pairs meet through two periodic images, swept by the component of
    their separation a box length apart. Deciding by round-off in the others (which differs between
    ranks) parted 1 and 2 ranks by 1e-7 in the temperature at step 5 and 1e-3 at step 40."""
    script = shardlow_liquid(1.5, 288) + """
        thermo 5
        thermo_style custom step temp press
        thermo_modify format float %.15g
        run 40
    """
    outputs = {}
    for ranks in (1, 2, 4):
        result = run(tmp_path, script, ranks)
        assert result.returncode == 0, result.stderr
        outputs[ranks] = np.array([[float(w) for w in line.split()] for line in thermo(result.stdout)])
    assert outputs[1].shape == (9, 3)
    for ranks in (2, 4):
        # chaos grows round-off from 1e-16 to about 1e-14 over 40 steps
        assert np.allclose(outputs[ranks], outputs[1], rtol=1e-10, atol=0), ranks


def test_comm_modify_cutoff_gives_ghosts_without_a_pair_style(tmp_path):
    """A scene with no pair style makes no ghosts unless comm_modify cutoff asks for them (LAMMPS makes
    them then too): fix rigid/small's bodies reach their particles on the other rank through them.
    Before, the cutoff was ignored without lists, and this 2-d scene of the reviewer stopped on 2
    ranks with 'cannot find its body's owner particle'."""
    script = """
        units lj
        dimension 2
        atom_style molecular
        region box block 0 20 0 20 -0.5 0.5
        create_box 1 box
        mass 1 1.0
        create_atoms 1 single 5 5 0
        create_atoms 1 single 6 5 0
        create_atoms 1 single 18.5 10 0
        create_atoms 1 single 19.5 10 0
        create_atoms 1 single 18.8 11 0
        set atom 1*2 mol 1
        set atom 3*5 mol 2
        velocity all set 0.1 0.2 0
        comm_modify cutoff 3.0
        fix 1 all rigid/small molecule
        fix 2 all addforce 0.1 -0.05 0
        fix 3 all enforce2d
        thermo_style custom step temp ke
        thermo_modify format float %.15g
        thermo 200
        run 2000
    """
    outputs = {}
    for ranks in (1, 2, 4):
        result = run(tmp_path, script, ranks)
        assert result.returncode == 0, result.stderr
        rows = [line.split() for line in thermo(result.stdout)]
        outputs[ranks] = np.array([[float(w) for w in row] for row in rows if len(row) == 3 and row[0].isdigit()])
    assert outputs[1].shape == (11, 3)
    for ranks in (2, 4):
        assert np.allclose(outputs[ranks], outputs[1], rtol=1e-12, atol=1e-15), ranks


def test_degrees_of_freedom_below_zero_is_one_line_on_two_ranks(tmp_path):
    """Every rank counts the same totals and stops alike: one line, no abort messages (the reviewer saw
    it twice, with MPI_Abort lines, when each rank reported it as its own)."""
    script = """
        atom_style sphere
        region box block 0 10 0 10 0 10
        create_box 1 box
        create_atoms 1 single 4.8 5 5
        create_atoms 1 single 5.6 5 5
        fix 1 all rigid single
        thermo_style custom step temp
        run 10
    """
    result = run(tmp_path, script, 2)
    assert result.returncode == 1
    assert result.stderr.strip().splitlines() == [
        "ERROR: in.test:9: run: temperature of group all: degrees of freedom < 0 (3 x 2 particles - 3 - 6 removed "
        "by fix 1 (rigid) 6 = -3)"]


SWEEP_SHARES = """
import sys
import numpy as np
from pdps_core.api import Simulation
sim = Simulation(screen=False, log=None)
sim.command(open(sys.argv[1]).read())
share = np.array([[sim.fixes["1"].pairs_swept]], dtype=float)
shares = sim.comm.gather_rows(share)
if sim.comm.rank == 0:
    print(" ".join(str(int(v)) for v in shares[:, 0]))
"""


def test_shardlow_sweep_is_shared_between_ranks(tmp_path):
    """No rank sweeps everything: on 2 ranks each sweeps about half the pairs of a uniform fluid, and
    the shares add up to the one rank's count."""
    script = """
        region box block 0 8 0 8 0 8
        create_box 1 box
        mass 1 1
        create_particle 1 random_no_overlap 1536 box 0.0 7
        pair_style dpd/fdt 1.0 1.0 4321
        pair_coeff * * 25.0 4.5 1.0
        fix 1 all shardlow
        fix 2 all nve
        timestep 0.04
        run 1
    """
    (tmp_path / "in.shares").write_text(textwrap.dedent(script))
    (tmp_path / "shares.py").write_text(SWEEP_SHARES)
    counts = {}
    for ranks in (1, 2):
        done = subprocess.run([str(MPIEXEC), "-n", str(ranks), sys.executable, "shares.py", "in.shares"],
                              cwd=tmp_path, capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr
        counts[ranks] = [int(w) for w in done.stdout.split()]
    (total,) = counts[1]
    assert sum(counts[2]) == total
    assert max(counts[2]) < 0.6 * total


def test_spheres_on_a_mesh_wall_give_the_same_run_on_1_2_and_4_ranks(tmp_path):
    stl = ROOT / "plugins" / "fix_wall" / "tests" / "data" / "square.stl"
    script = (ROOT / "tests" / "data" / "mesh_plate.in").read_text().replace("{stl}", str(stl))
    outputs = {ranks: thermo(run(tmp_path, script, ranks).stdout) for ranks in (1, 2, 4)}
    assert len(outputs[1]) == 7
    assert outputs[1] == outputs[2] == outputs[4]


def test_molecule_exclusions_give_the_same_run_on_1_and_2_ranks(tmp_path):
    """Ghosts carry their molecule ids: the LAMMPS molecule script of benchmarks/lammps_references
    (intra- and inter-molecule exclusions, whole molecules deleted) prints the same table on 2 ranks."""
    sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
    from molecules import SCRIPT
    serial, parallel = run(tmp_path, SCRIPT, 1), run(tmp_path, SCRIPT, 2)
    assert serial.returncode == parallel.returncode == 0, parallel.stderr
    table = [[float(w) for w in line.split()] for line in thermo(serial.stdout)[2:]]
    again = [[float(w) for w in line.split()] for line in thermo(parallel.stdout)[2:]]
    assert len(table) == 11                           # steps 0 to 100
    # printed with 15 digits: sums over ranks differ in the last two
    assert sum(again, []) == pytest.approx(sum(table, []), rel=1e-12)


def test_max_and_min_of_arrays_are_taken_element_by_element(tmp_path):
    """The plugin guide lets styles reduce arrays: max and min of a numpy array over ranks, element
    by element (they raised on one rank and hung the other)."""
    (tmp_path / "reduce.py").write_text(textwrap.dedent("""
        import numpy as np
        from pdps_core.comm.mpi import MPIComm
        c = MPIComm()
        a = np.array([1.0, 5.0, -2.0]) * (c.rank + 1)
        high, low = c.max(a), c.min(a)
        if c.rank == 0:
            print(high.tolist(), low.tolist())
    """))
    done = subprocess.run([str(MPIEXEC), "-n", "2", sys.executable, "reduce.py"], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[0] == "[2.0, 10.0, -2.0] [1.0, 5.0, -4.0]"


SEND_ROWS_DRIVER = """
import numpy as np
from pdps_core.comm import world
comm = world()
me, size = comm.rank, comm.nprocs
problems = []
for width in (3, 14, 3, 10):
    for count in (0, 5, 40):
        # row k of rank me: (me, k, ...) to rank (me + k) % size
        rows = np.array([[me, k] + [me * 1000 + k + 0.5 * d for d in range(width - 2)] for k in range(count)],
                        dtype=np.float64).reshape(count, width)
        ranks = np.array([(me + k) % size for k in range(count)], dtype=np.int64)
        fresh, fresh_from = comm.send_rows(rows, ranks)
        fresh, fresh_from = fresh.copy(), fresh_from.copy()
        kept, kept_from = comm.send_rows(rows, ranks, kept=True)
        if not (np.array_equal(kept, fresh) and np.array_equal(kept_from, fresh_from)):
            problems.append((width, count, "kept differs"))
        # every row sent here, once, from the rank it names
        expected = sorted((r, k) for r in range(size) for k in range(count) if (r + k) % size == me)
        if sorted(map(tuple, kept[:, :2].astype(int).tolist())) != expected or \\
                not np.array_equal(kept_from, kept[:, 0].astype(int)):
            problems.append((width, count, "rows"))
with open(f"rank{me}.txt", "w") as out:        # a file each: the ranks' prints would interleave
    out.write("ok" if not problems else repr(problems))
"""


@pytest.mark.parametrize("ranks", [1, 3])
def test_send_rows_with_kept_buffers_delivers_what_fresh_arrays_do(tmp_path, ranks):
    """send_rows(rows, ranks, kept=True) (fix shardlow's messages at every step) gives the rows and
    source ranks of the plain call, for rows of alternating widths and empty messages."""
    (tmp_path / "driver.py").write_text(SEND_ROWS_DRIVER)
    done = subprocess.run([str(MPIEXEC), "-n", str(ranks), sys.executable, "driver.py"], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert [(tmp_path / f"rank{rank}.txt").read_text() for rank in range(ranks)] == ["ok"] * ranks
