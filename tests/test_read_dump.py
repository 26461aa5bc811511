"""read_dump beyond the recorded cases (tests/data/liggghts.cases.json: read_dump, read_dump_add,
LIGGGHTS's thermo after reading): columns named with label, scaled and unwrapped coordinates, image
flags, gzipped files and a pattern of files, the step set, and one-line refusals of bad lines and
broken files."""

import gzip

import numpy as np
import pytest

from pdps_core.api import ScriptError, Simulation
from pdps_core.testing import by_tag

SETUP = """units si
atom_style sphere
boundary p p f
region box block 0 1 0 2 0 1 units box
create_box 2 box
create_atoms 1 single 0.5 0.5 0.5 units box
create_atoms 1 single 0.2 0.2 0.2 units box
"""


def snapshot(step, columns, rows, bounds="pp pp ff", box=((0, 1), (0, 2), (0, 1))):
    lines = [f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ATOMS\n{len(rows)}\nITEM: BOX BOUNDS {bounds}\n"]
    lines += [f"{lo} {hi}\n" for lo, hi in box]
    lines.append(f"ITEM: ATOMS {columns}\n")
    lines += [" ".join(str(v) for v in row) + "\n" for row in rows]
    return "".join(lines)


def simulation(tmp_path, monkeypatch, text, name="dump.snap"):
    monkeypatch.chdir(tmp_path)
    (tmp_path / name).write_text(text)
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(SETUP)
    return sim


def test_labelled_scaled_unwrapped_columns_are_unscaled_and_wrapped(tmp_path, monkeypatch):
    """ax, ay read as x, y (scaled yes wrapped no): x = 1.25 * 1 + 0 -> 0.25 with image 1, y = -0.25 * 2
    -> 1.5 with image -1; the unwrapped coordinates reset the image flags read before wrapping."""
    text = snapshot(40, "id type ax ay zz radius ix", [(1, 1, 1.25, -0.25, 0.3, 0.05, 7),
                                                       (2, 1, 0.5, 0.5, 0.6, 0.06, 7)])
    sim = simulation(tmp_path, monkeypatch, text)
    sim.command("read_dump dump.snap 40 x y z radius ix label x ax label y ay label z zz scaled yes wrapped no")
    x, image = by_tag(sim, sim.x), by_tag(sim, sim.particles.image[:sim.nlocal])
    np.testing.assert_allclose(x[0], [0.25, 1.5, 0.3])
    np.testing.assert_array_equal(image[0], [1, -1, 0])
    np.testing.assert_allclose(x[1], [0.5, 1.0, 0.6])
    np.testing.assert_array_equal(image[1], [0, 0, 0])
    np.testing.assert_allclose(by_tag(sim, sim.particles.radius[:sim.nlocal]), [0.05, 0.06])
    assert sim.step == 40


def test_the_first_coordinate_column_is_taken_and_wrapped_ones_keep_image_flags(tmp_path, monkeypatch):
    """xs (scaled, wrapped) before xu: xs is read, unscaled by the snapshot's box (0..2 in x, box yes),
    and the image flags read stay; the box becomes the snapshot's."""
    text = snapshot(7, "id type xs xu ys zs radius ix iy", [(1, 1, 0.75, 9.0, 0.25, 0.5, 0.1, 2, -3),
                                                            (2, 1, 0.25, 9.0, 0.25, 0.5, 0.1, 0, 0)],
                    box=((0, 2), (0, 2), (0, 1)))
    sim = simulation(tmp_path, monkeypatch, text)
    sim.command("read_dump dump.snap 7 x y z radius ix iy")
    np.testing.assert_allclose(sim.box.hi, [2, 2, 1])
    np.testing.assert_allclose(by_tag(sim, sim.x), [[1.5, 0.5, 0.5], [0.5, 0.5, 0.5]])
    np.testing.assert_array_equal(by_tag(sim, sim.particles.image[:sim.nlocal])[0], [2, -3, 0])


def test_a_gzipped_file_of_a_pattern_is_found_by_its_number(tmp_path, monkeypatch):
    """dump.*.gz: dump.20.gz is searched before dump.100.gz (by number, not by name); added particles
    take new ids after the largest, their types and the coordinates read."""
    monkeypatch.chdir(tmp_path)
    for step, z in ((20, 0.1), (100, 0.7)):
        with gzip.open(tmp_path / f"dump.{step}.gz", "wt") as handle:
            handle.write(snapshot(step, "id type x y z radius", [(1, 1, 0.5, 0.5, z, 0.1), (9, 2, 0.3, 0.3, z, 0.2)]))
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command(SETUP + "read_dump dump.*.gz 100 x y z radius add yes box no")
    assert sim.nlocal == 3 and sim.step == 100
    np.testing.assert_array_equal(np.sort(sim.tag), [1, 2, 3])
    np.testing.assert_allclose(by_tag(sim, sim.x)[:, 2], [0.7, 0.2, 0.7])
    assert list(by_tag(sim, sim.type)) == [1, 1, 2]


@pytest.mark.parametrize("line, message", [
    ("read_dump dump.snap 5 x y z", "the radius field is required to be read (LIGGGHTS's rule)"),
    ("read_dump dump.snap 5 x radius purge yes", "purge yes cannot go with replace yes or trim yes "
     "(LIGGGHTS's rule; replace is yes by default)"),
    ("read_dump dump.snap 5 x radius format xyz", "format xyz: LIGGGHTS requires the radius field, which "
     "an XYZ file does not hold (its reader leaves the radii undefined); write the snapshot with dump custom"),
    ("read_dump dump.snap 6 x radius", "dump.snap holds no snapshot of step 6"),
    ("read_dump dump.snap 5 x vx radius", "dump.snap: field vx not found in the dump file's columns "
     "(id type x radius)"),
    ("read_dump dump.snap 5 x radius label vy q", "label vy: not a field read (fields: x radius, id, type)"),
    ("read_dump dump.snap 5 x radius format native box no", "format must be the last keyword (got box no after it); "
     "usage: " + "read_dump FILE NSTEP FIELD... [box|replace|purge|trim|add|scaled|wrapped yes|no] "
     "[label FIELD COLUMN] [format native]"),
    ("read_dump nothere 5 x radius", "cannot open dump file nothere"),
    ("read_dump nowhere/d.* 5 x radius", "cannot search nowhere for dump files nowhere/d.*: No such file or directory"),
    ("read_dump dump.snap 5", "no field to read; usage: " + "read_dump FILE NSTEP FIELD... "
     "[box|replace|purge|trim|add|scaled|wrapped yes|no] [label FIELD COLUMN] [format native]"),
])
def test_bad_lines_are_refused_in_one_line(tmp_path, monkeypatch, line, message):
    sim = simulation(tmp_path, monkeypatch, snapshot(5, "id type x radius", [(1, 1, 0.5, 0.1)]))
    with pytest.raises(ScriptError) as caught:
        sim.command(line)
    assert caught.value.message == message


@pytest.mark.parametrize("text, message", [
    (snapshot(5, "id type x radius", [(1, 1, "nan", 0.1)]), "dump.snap:10: a value is not finite in '1 1 nan 0.1'"),
    (snapshot(5, "id type x radius", [(1, 1, 0.5, -0.1)]), "dump.snap:10: radius must be > 0 (got -0.1)"),
    (snapshot(5, "id type x radius", [(1.5, 1, 0.5, 0.1)]), "dump.snap:10: id must be an integer in "
     "1..4611686018427387904 (got 1.5)"),
    (snapshot(5, "id type x radius", [(1, 1, 0.5)]), "dump.snap:10: 3 columns, expected 4"),
    (snapshot(5, "id type x radius", [(1, 1, 0.5, 0.1)]).replace("ATOMS\n1", "ATOMS\n3"),
     "dump.snap: unexpected end of dump file (1 of 3 atom lines)"),
    ("garbage\n", "dump.snap:1: dump file is incorrectly formatted (expected ITEM: TIMESTEP, got 'garbage')"),
    (snapshot(5, "id type x radius", [(1, 1, 0.5, 0.1)], bounds="xy xz yz pp pp ff").replace("0 1\n", "0 1 0\n"),
     "dump.snap: the snapshot of step 5 has a triclinic box, pdps's is orthogonal (LIGGGHTS: Read_dump triclinic "
     "status does not match simulation)"),
])
def test_broken_files_are_refused_in_one_line(tmp_path, monkeypatch, text, message):
    sim = simulation(tmp_path, monkeypatch, text)
    with pytest.raises(ScriptError) as caught:
        sim.command("read_dump dump.snap 5 x radius")
    assert caught.value.message == message


def test_coordinates_of_two_kinds_are_refused(tmp_path, monkeypatch):
    sim = simulation(tmp_path, monkeypatch, snapshot(5, "id type xs y radius", [(1, 1, 0.5, 0.5, 0.1)]))
    with pytest.raises(ScriptError) as caught:
        sim.command("read_dump dump.snap 5 x y radius")
    assert caught.value.message == ("dump.snap: the x, y, z columns read do not have one scaling and wrapping "
                                    "(LIGGGHTS's rule)")


def test_a_2d_simulation_reads_no_z(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    sim = Simulation(screen=False, log=None, dialect="liggghts")
    sim.command("dimension 2\natom_style sphere\nregion box block 0 1 0 1 -0.5 0.5 units box\ncreate_box 1 box\n")
    (tmp_path / "dump.snap").write_text(snapshot(5, "id type x z radius", [(1, 1, 0.5, 0.0, 0.1)]))
    with pytest.raises(ScriptError) as caught:
        sim.command("read_dump dump.snap 5 x z radius")
    assert caught.value.message == "a 2-d simulation reads no z, vz or iz field"
