"""Dumps atom and custom, read back with an independent parser of LAMMPS's text dump format:

    ITEM: TIMESTEP / step / ITEM: NUMBER OF ATOMS / n / ITEM: BOX BOUNDS xx yy zz / 3 x "lo hi" /
    ITEM: ATOMS col... / n rows
"""

import re

import MDAnalysis               # independent readers of the dumps: the [test] extra, installed by make
import numpy as np
import ovito.io
import pytest

from pdps_core.api import ScriptError, SimulationError
from pdps_core.testing import build

LO = np.array([-2.0, 1.0, 0.0])
HI = np.array([3.0123456789012345, 5.0, 4.5])


def read_dump(path):
    """Every frame of a LAMMPS text dump; fails on a frame that is cut short or malformed."""
    lines = path.read_text().splitlines()
    frames, i = [], 0
    while i < len(lines):
        assert lines[i] == "ITEM: TIMESTEP", (i, lines[i])
        step = int(lines[i + 1])
        assert lines[i + 2] == "ITEM: NUMBER OF ATOMS"
        n = int(lines[i + 3])
        head = lines[i + 4].split()
        assert head[:3] == ["ITEM:", "BOX", "BOUNDS"] and len(head) == 6
        bounds = np.array([[float(w) for w in lines[i + 5 + d].split()] for d in range(3)])
        assert bounds.shape == (3, 2)
        atoms = lines[i + 8].split()
        assert atoms[:2] == ["ITEM:", "ATOMS"]
        columns = atoms[2:]
        rows = lines[i + 9:i + 9 + n]
        assert len(rows) == n, f"frame at step {step} has {len(rows)} of {n} rows"
        table = np.array([[float(w) for w in row.split()] for row in rows]).reshape(n, len(columns))
        frames.append({"step": step, "n": n, "labels": head[3:], "lo": bounds[:, 0],
                       "hi": bounds[:, 1], "columns": columns, "rows": rows,
                       "data": {c: table[:, k] for k, c in enumerate(columns)}})
        i += 9 + n
    return frames


def particles(n=40, seed=4):
    """Positions in the box LO..HI, types and ids (not contiguous, not sorted)."""
    rng = np.random.default_rng(seed)
    ids = rng.permutation(np.arange(1, n + 1) * 3)
    x = LO + rng.random((n, 3)) * (HI - LO)
    return x, 1 + (ids % 2), ids


def make(tmp_path, monkeypatch, boundary="p p p"):
    monkeypatch.chdir(tmp_path)
    x, types, ids = particles()
    sim = build(tmp_path, x, types=types, tags=ids, masses={1: 1.0, 2: 2.0}, lo=LO, hi=HI,
                boundary=boundary, name="data.in", setup="""
        atom_modify sort 1 0.0
        pair_style dpd 1.0 1.0 77
        pair_coeff * * 25.0 4.5
        velocity all create 1.0 3
        timestep 0.02
        fix 1 all nve
    """)
    return sim, ids


def state_by_tag(sim):
    order = np.argsort(sim.tag)
    return order, sim.tag[order]


def test_dump_atom_frames_ids_scaled_coordinates_and_box(tmp_path, monkeypatch):
    sim, ids = make(tmp_path, monkeypatch)
    sim.command("dump 1 all atom 5 dump.atom\nrun 20")
    frames = read_dump(tmp_path / "dump.atom")
    assert [f["step"] for f in frames] == [0, 5, 10, 15, 20]      # steps / N + 1 frames
    for frame in frames:
        assert frame["columns"] == ["id", "type", "xs", "ys", "zs"]
        assert frame["labels"] == ["pp", "pp", "pp"]
        np.testing.assert_array_equal(frame["lo"], LO)
        np.testing.assert_array_equal(frame["hi"], HI)
        assert frame["n"] == len(ids)
        np.testing.assert_array_equal(frame["data"]["id"], np.sort(ids))
        assert all(re.fullmatch(r"\d+ [12] \S+ \S+ \S+", row) for row in frame["rows"])
    order, tags = state_by_tag(sim)
    last = frames[-1]["data"]
    np.testing.assert_array_equal(last["type"], sim.type[order])
    scaled = (sim.x[order] - LO) / (HI - LO)
    for d, name in enumerate(("xs", "ys", "zs")):
        np.testing.assert_allclose(last[name], scaled[:, d], rtol=1e-7, atol=1e-8)
    # the particles moved between the first and the last frame
    assert not np.allclose(frames[0]["data"]["xs"], last["xs"])


def test_dump_custom_columns_match_the_particle_state(tmp_path, monkeypatch):
    sim, ids = make(tmp_path, monkeypatch)
    columns = "id type mass x y z xs xu yu zu ix iy iz vx vy vz fx fy fz step"
    sim.command(f"dump 2 all custom 4 dump.custom {columns}\nrun 12")
    frames = read_dump(tmp_path / "dump.custom")
    assert [f["step"] for f in frames] == [0, 4, 8, 12]
    for frame in frames:
        assert frame["columns"] == columns.split()
        np.testing.assert_array_equal(frame["data"]["id"], np.sort(ids))
        np.testing.assert_array_equal(frame["data"]["step"], frame["step"])
    order, _ = state_by_tag(sim)
    last = frames[-1]["data"]
    p = sim.particles
    image = p.image[: sim.nlocal][order]
    length = HI - LO
    expected = {"type": sim.type[order], "mass": np.where(sim.type[order] == 1, 1.0, 2.0),
                "xs": (sim.x[order, 0] - LO[0]) / length[0]}
    for d, axis in enumerate("xyz"):
        expected[axis] = sim.x[order, d]
        expected[f"{axis}u"] = sim.x[order, d] + image[:, d] * length[d]
        expected[f"i{axis}"] = image[:, d]
        expected[f"v{axis}"] = sim.v[order, d]
        expected[f"f{axis}"] = sim.f[order, d]
    for name, values in expected.items():
        np.testing.assert_allclose(last[name], values, rtol=1e-9, atol=1e-12, err_msg=name)
    # integer columns are written as integers
    assert all(re.fullmatch(r"-?\d+", w) for row in frames[-1]["rows"]
               for k, w in enumerate(row.split()) if columns.split()[k] in ("id", "ix", "step"))


def test_dump_of_a_group_and_fixed_boundaries(tmp_path, monkeypatch):
    sim, ids = make(tmp_path, monkeypatch, boundary="p f p")
    # nothing integrates: with no wall, particles would leave through the fixed y faces
    sim.command("unfix 1\ngroup odd type 2\ndump 3 odd custom 10 dump.odd id type\nrun 10")
    frames = read_dump(tmp_path / "dump.odd")
    assert len(frames) == 2
    for frame in frames:
        assert frame["labels"] == ["pp", "ff", "pp"]
        np.testing.assert_array_equal(frame["data"]["id"], np.sort(ids[ids % 2 == 1]))
        assert np.all(frame["data"]["type"] == 2)


def test_dump_of_an_empty_group_writes_headers_only(tmp_path, monkeypatch):
    sim, _ = make(tmp_path, monkeypatch)
    sim.command("region far block 100 101 100 101 100 101\ngroup none region far\n"
                "dump 4 none atom 1 dump.none\nrun 2")
    frames = read_dump(tmp_path / "dump.none")
    assert [(f["step"], f["n"]) for f in frames] == [(0, 0), (1, 0), (2, 0)]


def test_run_stopped_by_an_error_keeps_complete_frames(tmp_path, make_sim):
    """A particle flies out through a fixed face; the run stops with an error. Every frame written
    before is complete and readable at once (flushed), though the dump was never closed."""
    sim = make_sim()
    sim.command("""
        boundary f f f
        region box block 0 10 0 10 0 10
        create_box 1 box
        mass 1 1.0
        create_particle 1 single 5.0 5.0 5.0
        create_particle 1 single 9.0 5.0 5.0
        timestep 0.01
        fix 1 all nve
        dump 1 all custom 2 dump.lost id x vx
    """)
    sim.v[sim.tag == 2] = [10.0, 0.0, 0.0]
    with pytest.raises(SimulationError, match="lost through the fixed x boundary") as info:
        sim.command("run 100")
    failed_at = int(re.search(r"at step (\d+)", str(info.value)).group(1))
    frames = read_dump(tmp_path / "dump.lost")
    steps = [f["step"] for f in frames]
    assert len(steps) >= 3
    assert steps == list(range(0, 2 * len(steps), 2))
    assert steps[-1] < failed_at <= steps[-1] + 2
    assert all(f["n"] == 2 for f in frames)
    # rows are sorted by id: row 1 is particle 2, flying at 10 per unit time
    np.testing.assert_allclose(frames[-1]["data"]["x"][1], 9.0 + 0.1 * steps[-1], rtol=1e-9)


def test_consecutive_runs_do_not_duplicate_a_frame(tmp_path, monkeypatch):
    sim, _ = make(tmp_path, monkeypatch)
    sim.command("dump 1 all atom 5 dump.atom\nrun 10\nrun 10")
    assert [f["step"] for f in read_dump(tmp_path / "dump.atom")] == [0, 5, 10, 15, 20]


@pytest.mark.parametrize("line, words", [
    ("dump 1 all custom 5 d.txt id bogus", ("unknown dump column bogus",)),
    ("dump 1 all custom 5 d.txt id radius", ("radius", "particle_style sphere")),
    ("dump 1 all atom 0 d.txt", ("N must be >= 1",)),
    ("dump 1 all atom 5 no/such/dir/d.txt", ("cannot open dump file",)),
    ("dump 1 nobody atom 5 d.txt", ("group nobody is not defined",)),
])
def test_bad_dump_commands(tmp_path, monkeypatch, line, words):
    sim, _ = make(tmp_path, monkeypatch)
    with pytest.raises(ScriptError) as info:
        sim.command(line)
    for word in words:
        assert word in str(info.value)


def test_mdanalysis_reads_the_dumps(tmp_path, monkeypatch):
    """MDAnalysis, an independent reader, reads both dumps frame by frame. It shifts positions so the
    box starts at 0 (it subtracts the lower corner, also from scaled coordinates, which are already
    relative to it): the custom dump's x y z read back as x - lo; the atom dump's xs ys zs as
    xs * L - lo."""
    sim, ids = make(tmp_path, monkeypatch)
    sim.command("dump 1 all atom 5 dump.atom\ndump 2 all custom 5 dump.xyz id type x y z vx vy vz\nrun 10")
    length = HI - LO
    for name, columns, expected in (("dump.xyz", ("x", "y", "z"), lambda q: q - LO),
                                    ("dump.atom", ("xs", "ys", "zs"), lambda q: q * length - LO)):
        ours = read_dump(tmp_path / name)
        universe = MDAnalysis.Universe(str(tmp_path / name), format="LAMMPSDUMP")
        assert universe.trajectory.n_frames == len(ours) == 3
        assert len(universe.atoms) == len(ids)
        for ts, frame in zip(universe.trajectory, ours):
            np.testing.assert_allclose(ts.dimensions[:3], length, rtol=1e-6)
            order = np.argsort(frame["data"]["id"])
            mine = np.column_stack([frame["data"][c] for c in columns])[order]
            theirs = ts.positions[np.argsort(universe.atoms.ids)]
            np.testing.assert_allclose(theirs, expected(mine), atol=1e-4)


def test_ovito_reads_the_dumps(tmp_path, monkeypatch):
    """OVITO (the visualiser most LAMMPS users open dumps with) reads both dumps: every frame, the
    box origin, and the positions to the printed precision."""
    sim, ids = make(tmp_path, monkeypatch)
    sim.command("dump 1 all atom 5 dump.atom\ndump 2 all custom 5 dump.xyz id type x y z vx vy vz\nrun 10")
    order = np.argsort(sim.tag)
    positions = sim.x[order]
    for name, tolerance in (("dump.atom", 1e-6), ("dump.xyz", 1e-8)):
        pipeline = ovito.io.import_file(str(tmp_path / name))
        assert pipeline.source.num_frames == 3
        data = pipeline.compute(2)
        assert data.particles.count == len(ids)
        np.testing.assert_allclose(np.asarray(data.cell[:, 3]), LO, atol=1e-12)
        read = np.asarray(data.particles.positions)[np.argsort(np.asarray(data.particles["Particle Identifier"]))]
        np.testing.assert_allclose(read, positions, atol=tolerance * (HI - LO).max())


def test_a_star_in_the_file_name_writes_a_file_per_frame(tmp_path, monkeypatch):
    """LAMMPS's wildcard: dump.*.txt holds one frame each, named by its step; % is refused."""
    sim, ids = make(tmp_path, monkeypatch)
    sim.command("dump 2 all custom 5 dump.*.txt id x y z\nrun 10")
    for step in (0, 5, 10):
        (frame,) = read_dump(tmp_path / f"dump.{step}.txt")
        assert frame["step"] == step
        np.testing.assert_array_equal(frame["data"]["id"], np.sort(ids))
    assert not (tmp_path / "dump.*.txt").exists()
    with pytest.raises(ScriptError, match=r"per-processor dump files \(% in dump.%.txt\) are not supported"):
        sim.command("dump 3 all custom 5 dump.%.txt id x y z")


def test_a_gz_name_is_written_gzip_compressed_frame_by_frame(tmp_path, monkeypatch):
    """dump.atom.gz is gzip (as LAMMPS writes it), holding the same text as the plain dump of the
    same frames, and every frame written so far decompresses while the run goes on; a local dump
    and a per-frame ``*`` name too. pdps wrote plain text under the .gz name."""
    import gzip
    import zlib
    sim, _ = make(tmp_path, monkeypatch)
    sim.command("dump 1 all atom 5 plain.atom\ndump 2 all atom 5 packed.atom.gz\ndump 3 all atom 5 packed.*.gz\n"
                "run 5")
    # mid-run: what is on disk decompresses to the frames written so far (a gzip stream not yet closed)
    partial = zlib.decompressobj(16 + zlib.MAX_WBITS).decompress((tmp_path / "packed.atom.gz").read_bytes())
    assert partial.decode() == (tmp_path / "plain.atom").read_text()
    sim.command("run 5")
    sim.close()
    assert (tmp_path / "packed.atom.gz").read_bytes()[:2] == b"\x1f\x8b"
    text = gzip.decompress((tmp_path / "packed.atom.gz").read_bytes()).decode()
    assert text == (tmp_path / "plain.atom").read_text()
    assert [f["step"] for f in read_dump(tmp_path / "plain.atom")] == [0, 5, 10]
    frame = gzip.decompress((tmp_path / "packed.10.gz").read_bytes()).decode()
    assert frame == text[text.rindex("ITEM: TIMESTEP\n10\n"):]


def test_a_bin_name_is_refused_at_the_dump_line(pdps_cli):
    """LAMMPS's .bin is its binary format, which pdps does not write: one line at the dump command
    (pdps wrote text under the name)."""
    result = pdps_cli("""
        region box block 0 4 0 4 0 4
        create_box 1 box
        create_particle 1 single 1 1 1
        dump 1 all atom 10 dump.bin
        run 10
    """)
    assert result.returncode == 1
    assert result.stderr.strip().splitlines()[-1] == (
        "ERROR: in.test:5: dump: dump file dump.bin: LAMMPS's binary dump format (.bin) is not written by pdps; "
        "name the file without .bin (text), or with .gz (compressed text)")


LJ_BOX = """units lj
boundary p s fm
lattice fcc 0.8442
region box block 0 2 0 2 0 2
create_box 1 box
create_atoms 1 box
mass 1 1.0
pair_style lj/cut 2.5
pair_coeff 1 1 1.0 1.0 2.5
dump d all custom 1 d.txt id x y z
"""


def test_the_header_names_each_boundary_as_lammps(pdps_cli, tmp_path):
    """LAMMPS (22 Jul 2025) writes "ITEM: BOX BOUNDS pp ss fm" and last row "40 2.519 3.359 2.519"
    for this script."""
    done = pdps_cli(LJ_BOX + 'dump_modify d format line "%d %.3f %.3f %.3f"\nrun 0\n')
    assert done.returncode == 0, done.stderr
    lines = (tmp_path / "d.txt").read_text().splitlines()
    assert lines[4] == "ITEM: BOX BOUNDS pp ss fm" and lines[-1] == "40 2.519 3.359 2.519"


def test_liggghts_takes_one_format_string_for_the_line_and_lammps_refuses_it(pdps_cli, tmp_path):
    """LIGGGHTS 3.8.0's dump_modify format STRING (LAMMPS's before 2016); LAMMPS now: "Illegal
    dump_modify format command: missing argument(s)"."""
    # LIGGGHTS's region and create_atoms default to box units: lattice ones asked for, as LAMMPS's
    liggghts = ("atom_style granular\n" + LJ_BOX.replace("units lj", "units si").replace("mass 1 1.0\n", "")
                .replace("block 0 2 0 2 0 2", "block 0 2 0 2 0 2 units lattice")
                .replace("pair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0 2.5\n", "")
                + 'dump_modify d format "%d %.3f %.3f %.3f"\nrun 0\n')
    done = pdps_cli(liggghts)
    assert done.returncode == 0, done.stderr
    rows = (tmp_path / "d.txt").read_text().splitlines()[9:]
    assert len(rows) == 40 and all(re.fullmatch(r"\d+ -?\d+\.\d{3} -?\d+\.\d{3} -?\d+\.\d{3}", row) for row in rows)
    done = pdps_cli(LJ_BOX + 'dump_modify d format "%d %.3f %.3f %.3f"\nrun 0\n')
    assert done.returncode == 1
    assert "dump_modify format needs 2 value(s)" in done.stderr
