"""Bad input found by fuzzing (issue 10), each with its reproducer: one line naming file, line,
command and value, exit code 1, never a crash, a hang, a traceback or silent garbage."""

import pytest

from pdps_core.testing import write_data

BOX = "region box block 0 1 0 1 0 1\ncreate_box 1 box\nmass 1 1.0\n"


def one_line(done, expected):
    assert done.returncode == 1, done.stdout + done.stderr
    lines = done.stderr.strip().splitlines()
    assert lines == [expected], done.stderr


# ---- geometry and counts ----------------------------------------------------------------------
def test_a_huge_box_with_dem_bins_coarsely_instead_of_crashing(pdps_cli):
    done = pdps_cli("""
        particle_style sphere
        region box block 0 1e26 0 1e26 0 1e26
        create_box 1 box
        create_particle 1 single 1 1 1
        create_particle 1 single 1.5 1 1
        pair_style dem/lsd 0.3 1.0
        pair_coeff * * 1000 16.6016 314.29 6.3008 0.5 1
        run 2
    """)
    assert done.returncode == 0, done.stderr


def test_a_box_far_smaller_than_the_cutoff_is_refused_at_the_run(pdps_cli):
    done = pdps_cli("""
        region box block 0 1e-9 0 1e-9 0 1e-9
        create_box 1 box
        mass 1 1
        create_particle 1 single 5e-10 5e-10 5e-10
        pair_style lj/cut 2.5
        pair_coeff * * 1 1
        run 1
    """)
    one_line(done, "ERROR: in.test:8: run: the cutoff plus skin 2.8 spans 2.8e+09 periodic images of the "
                   "box (length 1e-09 along x; at most 64): make the box larger or the cutoff smaller")


def test_a_nanometre_box_without_pair_forces_runs(pdps_cli):
    done = pdps_cli("region box block 0 1e-9 0 1e-9 0 1e-9\ncreate_box 1 box\nmass 1 1\nrun 10\n")
    assert done.returncode == 0, done.stderr


@pytest.mark.parametrize("bounds, message", [
    ("0 1e200 0 1 0 1", "box x bounds 0 1e+200 are beyond +-1e+150, where squared distances overflow"),
    ("1e6 1.0000000000000002e6 0 1 0 1", "box x length 2.32831e-10 is too small to resolve at 1e+06 (at least 1e-12 of it)"),
])
def test_boxes_that_cannot_hold_positions(pdps_cli, bounds, message):
    one_line(pdps_cli(f"region box block {bounds}\ncreate_box 1 box\n"),
             f"ERROR: in.test:2: create_box: {message}")


@pytest.mark.parametrize("line, message", [
    ("run 99999999999999999999999999", "run: N must be <= 2147483647 (got 99999999999999999999999999)"),
    ("run 2147483648", "run: N must be <= 2147483647 (got 2147483648)"),
    ("reset_timestep 9223372036854775808", "reset_timestep: timestep must be <= 9223372036854775807 (got 9223372036854775808)"),
])
def test_counts_beyond_their_integer_ranges(pdps_cli, line, message):
    one_line(pdps_cli(BOX + line + "\n"), f"ERROR: in.test:4: {message}")


def test_a_run_that_would_overflow_the_step_counter(pdps_cli):
    one_line(pdps_cli(BOX + "reset_timestep 9223372036854775000\nrun 1000\n"),
             "ERROR: in.test:5: run: run 1000 from step 9223372036854775000 goes past the last step a "
             "64-bit counter holds (9223372036854775807)")


@pytest.mark.parametrize("ntypes", ["2147483648", "201", "99999999999999999999"])
def test_create_box_with_too_many_types(pdps_cli, ntypes):
    one_line(pdps_cli(f"region box block 0 1 0 1 0 1\ncreate_box {ntypes} box\n"),
             f"ERROR: in.test:2: create_box: ntypes must be <= 200 (got {ntypes})")


# ---- files, decoding, recursion ---------------------------------------------------------------
def test_a_script_that_is_not_utf8(tmp_path, pdps_cli):
    (tmp_path / "in.bytes").write_bytes(b"region box block 0 1 0 1 0 1\ncreate_box 1 box\nprint \"\xff\xfe\"\n")
    done = pdps_cli("include in.bytes\n")
    one_line(done, f"ERROR: in.test:1: include: {tmp_path / 'in.bytes'}:3: not UTF-8 text (byte 0xff); "
                   "input scripts are read as UTF-8")


def test_the_top_script_not_utf8_is_located_by_its_line(tmp_path, pdps_cli):
    (tmp_path / "in.top").write_bytes(b"print hello\nprint \"\xc3(\"\n")
    from pdps_core import cli
    assert cli.main(["run", "in.top", "-log", "none"]) == 1


def test_a_script_that_includes_itself(tmp_path, pdps_cli):
    done = pdps_cli("include in.test\n")
    assert done.returncode == 1
    assert done.stderr.strip().endswith(f"include: scripts include each other more than 32 deep "
                                        f"({tmp_path / 'in.test'} includes itself?)"), done.stderr


def test_a_data_file_that_is_not_utf8(tmp_path, pdps_cli):
    (tmp_path / "bad.data").write_bytes(b"title\n\n1 atoms\n1 atom types\n\xe9\n")
    one_line(pdps_cli("read_data bad.data\n"),
             f"ERROR: in.test:1: read_data: {tmp_path / 'bad.data'}:5: not UTF-8 text (byte 0xe9); "
             "data files are read as UTF-8")


def test_a_lattice_too_fine_for_memory_is_refused_before_any_array(pdps_cli):
    one_line(pdps_cli("region box block 0 3 0 3 0 3\ncreate_box 1 box\nlattice spacing x 1 y 1 z 1e-114\n"
                      "create_particle 1 box\n"),
             "ERROR: in.test:4: create_particle: the lattice (spacing 1 1 1e-114) fills the box with about "
             "7.5e+115 sites, more than 20000000 particles at once")


def test_a_lammps_lattice_of_23_million_sites_is_refused_at_once(pdps_cli):
    # the fuzz suite's: create_atoms spent 23 s making the sites before refusing them (a hang)
    one_line(pdps_cli("atom_style atomic\nlattice sc 0.9\nregion box block 0 4 0 4 0 1455100\n"
                      "create_box 2 box\ncreate_atoms 1 box\n"),
             "ERROR: in.test:5: create_atoms: the lattice has about 2.33e+07 sites in the box, more particles "
             "than one command makes (20000000)")


def test_a_lammps_lattice_region_too_full_stops_within_its_first_layers(pdps_cli):
    one_line(pdps_cli("atom_style atomic\nlattice sc 0.9\nregion box block 0 4 0 4 0 1455100\n"
                      "create_box 2 box\nregion most block 0 4 0 4 0 1400000\ncreate_atoms 1 region most\n"),
             "ERROR: in.test:6: create_atoms: the lattice has more than 20000000 sites in region most, more "
             "particles than one command makes")


def test_a_skin_beyond_any_distance_is_refused(pdps_cli):
    # the fuzz suite's: neighbor 1e308 made a mesh wall's bin grid infinite, and numba crashed on it
    one_line(pdps_cli("neighbor 1e308 bin\n"), "ERROR: in.test:1: neighbor: skin must be <= 1e+150 (got 1e308)")


def test_a_cutoff_many_times_the_box_is_refused(pdps_cli):
    one_line(pdps_cli("""region box block 0 6 0 6 0 6
create_box 1 box
mass 1 1
create_particle 1 random 500 4 box
pair_style dpd 1.0 99.0 5
pair_coeff * * 25 4.5
run 1
"""), "ERROR: in.test:7: run: the cutoff plus skin 99.3 would copy the 500 particles about 3.97e+04 "
      "times over as periodic ghosts (at most 1000): make the box larger or the cutoff smaller")


def test_tiny_spheres_are_refused(pdps_cli):
    one_line(pdps_cli("particle_style sphere\nregion box block 0 3 0 3 0 3\ncreate_box 1 box\n"
                      "create_particle 1 single 1 1 1 diameter 1e-300\n"),
             "ERROR: in.test:4: create_particle: diameter must be >= 1e-50 (got 1e-300)")


# ---- found by the first 100,000-case make fuzz run ----------------------------------------------
@pytest.mark.parametrize("lines, message", [
    ("dimension 2\nregion box block 0 129825674658350 0 3 -0.5 0.5\ncreate_box 1 box\nmass 1 1\n"
     "analyze 1 all ave/space 1 1 1 x lower 2 density/number\nrun 0",
     "ERROR: in.test:6: run: ave/space 1: bin width 2 along x over the box (0 to 1.29826e+14) makes "
     "6.491e+13 bins, more than 1e+06"),
    (BOX + "analyze 1 all ave/space 1 1 1 x lower 1e-3 y lower 1e-3 z lower 1e-3 density/number\nrun 0",
     "ERROR: in.test:5: run: ave/space 1: bins of 1000 by 1000 by 1000 makes 1e+09 bins, more than 1e+06"),
    (BOX + "compute r all rdf 8796093022207\n",
     "ERROR: in.test:4: compute: compute r (rdf): NBIN makes 8.796e+12 bins, more than 1e+06"),
    (BOX + "compute r all rdf 20 cutoff 5e202",
     "ERROR: in.test:4: compute: cutoff must be 0 or of magnitude from 1e-50 to 1e+50 (got 5e202)"),
    (BOX + "compute r all rdf 20 cutoff 1e40\nthermo_style custom step c_r[1][1]\nrun 0",
     "ERROR: in.test:6: run: compute r (rdf): cutoff 1e+40 spans 1e+40 periodic images of the box "
     "(length 1 along x; at most 64): make the box larger or the cutoff smaller"),
    (BOX + "pair_style lj/cut 1.0\npair_coeff * * 1.0 8.6e39\nrun 0",
     "ERROR: in.test:6: run: pair_coeff 1 1: the coefficients give lj1 = inf, not a finite number"),
    (BOX + "timestep 5e-324", "ERROR: in.test:4: timestep: timestep must be >= 1e-50 (got 5e-324)"),
    (BOX + "fix 1 all langevin 1.0 1.0 1e-320 5",
     "ERROR: in.test:4: fix: damp must be 0 or of magnitude from 1e-50 to 1e+50 (got 1e-320)"),
])
def test_grids_coefficients_and_numbers_beyond_what_the_machine_holds(pdps_cli, lines, message):
    one_line(pdps_cli(lines + "\n"), message)


def test_a_grid_written_as_millions_of_lines_is_refused(pdps_cli):
    # 2,000,000 bins of text each average: a hang of the 100,000-case fuzz run
    one_line(pdps_cli("dimension 2\nregion box block 0 6 0 3000000 -0.5 0.5\ncreate_box 1 box\nmass 1 1\n"
                      "create_particle 1 single 0.2 0.5 0\n"
                      "analyze 2 all ave/space 1 1 1 x lower 2 y lower 1.5 density/number file xy.txt\nrun 0\n"),
             "ERROR: in.test:7: run: ave/space 2: bin width 1.5 along y over the box (0 to 3e+06) makes 2e+06 "
             "bins, more than 1e+06")


def test_a_neighbor_list_overflow_is_one_line_not_gigabytes(pdps_cli):
    one_line(pdps_cli("region box block 0 3 0 3 0 3\ncreate_box 1 box\nmass 1 1\n"
                      "create_particle 1 random 3000 7 box\nneigh_modify one 100\n"
                      "pair_style dpd 1.0 1.0 5\npair_coeff * * 25 4.5\nrun 0\n"),
             "ERROR: in.test:8: run: neighbor list overflow: more than 100 neighbors per particle on "
             "average within 1.3 of 3000 particles (overlapping particles?); raise neigh_modify one "
             "if that is meant")


def test_a_nul_byte_in_a_script_is_located(tmp_path, pdps_cli):
    one_line(pdps_cli(BOX + "dump 1 all atom 10 du\0mp.atom\n"),
             "ERROR: in.test:4: a NUL byte (0x00) in the text; input scripts are plain text")


def test_a_scene_too_large_for_memory_is_one_line(tmp_path):
    import resource
    import subprocess
    import sys
    (tmp_path / "in.big").write_text(BOX.replace("0 1 0 1 0 1", "0 300 0 300 0 300")
                                     + "create_particle 1 random 19000000 5 box\n")
    limit = lambda: resource.setrlimit(resource.RLIMIT_AS, (1_500_000_000, 1_500_000_000))  # noqa: E731
    done = subprocess.run([sys.executable, "-m", "pdps_core.cli", "run", "in.big"], cwd=tmp_path,
                          capture_output=True, text=True, preexec_fn=limit, timeout=120)
    assert done.returncode == 1, done.stderr
    [line] = done.stderr.strip().splitlines()
    assert line.startswith("ERROR: in.big:4: create_particle: out of memory (")
    assert line.endswith("): the scene needs more memory than this machine gives")


@pytest.mark.parametrize("path, reason", [(".", "Is a directory"),
                                          ("/nonexistent/x.log", "No such file or directory")])
def test_a_log_that_cannot_be_opened_keeps_the_log_so_far(pdps_cli, tmp_path, path, reason):
    done = pdps_cli(f"print hello\nlog {path}\n", "-log", "first.log")
    one_line(done, f"ERROR: in.test:2: log: cannot open log file {path}: {reason}")
    assert "hello" in (tmp_path / "first.log").read_text()


def test_a_variable_that_refers_to_itself(pdps_cli):
    one_line(pdps_cli("variable a equal v_a+1\nprint ${a}\n"),
             "ERROR: in.test:2: print: variable a refers to itself (a -> a)")


def test_variables_in_a_cycle(pdps_cli):
    one_line(pdps_cli("variable a equal v_b*2\nvariable b equal v_c\nvariable c equal v_a\nprint ${a}\n"),
             "ERROR: in.test:4: print: variable a refers to itself (a -> b -> c -> a)")


# ---- data files ------------------------------------------------------------------------------
def data_text(atoms, header="2 atoms\n1 atom types\n", masses="1 1.0\n", extra=""):
    return (f"title\n\n{header}\n0 10 xlo xhi\n0 10 ylo yhi\n0 10 zlo zhi\n\nMasses\n\n{masses}\n"
            f"Atoms # atomic\n\n{atoms}{extra}")


@pytest.mark.parametrize("atoms, masses, extra, line, message", [
    ("1 1 1 1 1\n2 1 2 2 2\n", "1 inf\n", "", 12, "mass must be a finite number > 0 (got inf)"),
    ("1 1 1 1 1\n2 1 2 2 2\n", "1 0\n", "", 12, "mass must be a finite number > 0 (got 0)"),
    ("0 1 1 1 1\n2 1 2 2 2\n", "1 1.0\n", "", 16, "atom id must be from 1 to 4611686018427387904 (got 0)"),
    ("-3 1 1 1 1\n2 1 2 2 2\n", "1 1.0\n", "", 16, "atom id must be from 1 to 4611686018427387904 (got -3)"),
    ("99999999999999999999 1 1 1 1\n2 1 2 2 2\n", "1 1.0\n", "", 16,
     "atom id must be from 1 to 4611686018427387904 (got 99999999999999999999)"),
    ("1 4294967297 1 1 1\n2 1 2 2 2\n", "1 1.0\n", "", 16, "atom type 4294967297 is out of range 1..1"),
    ("1 1 1 1 1 0 0 9999999999\n2 1 2 2 2\n", "1 1.0\n", "", 16,
     "image flags must fit in 32 bits (got 0 0 9999999999)"),
    ("1 1 1e300 1 1\n2 1 2 2 2\n", "1 1.0\n", "", 16,
     "position must be finite and within +-1e+150: 1 1 1e300 1 1"),
    ("1 1 1e100 1 1\n2 1 2 2 2\n", "1 1.0\n", "", 16,
     "x = 1e+100 is 1e+99 box lengths away: its image flag would not fit in 32 bits"),
    ("1 1 1 1 1\n2 1 2 2 2\n", "1 1.0\n", "\nVelocities\n\n1 0 0 0\n2 0 0 0\n1 1 1 1\n", 23,
     "Velocities: atom 1 appears twice (first on line 21)"),
    ("1 1 1 1 1\n2 1 2 2 2\n", "1 1.0\n", "\nVelocities\n\n1 nan 0 0\n2 0 0 0\n", 21,
     "non-finite velocity: 1 nan 0 0"),
    # issue 30: Python's float() reads full-width digits and 1_0; LAMMPS 22 Jul 2025 refuses the first
    # ("Expected floating point parameter instead of ...")
    ("1 1 \uff11 1 1\n2 1 2 2 2\n", "1 1.0\n", "", 16,
     "\uff11 is not a number written in ASCII digits: 1 1 \uff11 1 1"),
    ("1 1 1_0 1 1\n2 1 2 2 2\n", "1 1.0\n", "", 16, "1_0 is not a number written in ASCII digits: 1 1 1_0 1 1"),
    ("1 1 1 1 1\n2 1 2 2 2\n", "\uff11 1.0\n", "", 12, "\uff11 is not a number written in ASCII digits: \uff11 1.0"),
    # issue 30: a Velocities header with no rows, or too few; LAMMPS 22 Jul 2025 reads one row per
    # atom ("Unexpected end of data file", "Incorrect format in Velocities section")
    ("1 1 1 1 1\n2 1 2 2 2\n", "1 1.0\n", "\nVelocities\n\n", 19,
     "header says 2 atoms but the Velocities section has 0"),
    ("1 1 1 1 1\n2 1 2 2 2\n", "1 1.0\n", "\nVelocities\n\n1 0 0 0\n", 19,
     "header says 2 atoms but the Velocities section has 1"),
])
def test_bad_values_in_data_files(tmp_path, pdps_cli, atoms, masses, extra, line, message):
    (tmp_path / "bad.data").write_text(data_text(atoms, masses=masses, extra=extra))
    one_line(pdps_cli("read_data bad.data\n"),
             f"ERROR: in.test:1: read_data: {tmp_path / 'bad.data'}:{line}: {message}")


def test_a_header_with_tabs_is_read(tmp_path, make_sim):
    (tmp_path / "tabs.data").write_text(data_text("1 1 1 1 1\n2 1 2 2 3\n", header="2\tatoms\n1\tatom\ttypes\n",
                                                  masses="1\t2.5\n"))
    sim = make_sim()
    sim.command("read_data tabs.data\nrun 0")
    assert sim.ntypes == 1 and sim.mass[1] == 2.5
    order = np.argsort(sim.tag)
    assert sim.tag[order].tolist() == [1, 2]
    assert sim.x[order].tolist() == [[1.0, 1.0, 1.0], [2.0, 2.0, 3.0]]


# ---- restart files: intact, but holding bad values -------------------------------------------
import io  # noqa: E402
import json  # noqa: E402
import zipfile  # noqa: E402

import numpy as np  # noqa: E402

RESTART_SCRIPT = BOX + """
create_particle 1 single 0.2 0.2 0.2
create_particle 1 single 0.7 0.7 0.7
pair_style lj/cut 0.5
pair_coeff * * 1.0 0.3
fix 1 all nve
run 2
write_restart good.restart
"""


def edited_restart(folder, header_edit=None, arrays_edit=None, raw_header=None):
    """good.restart with its header or arrays changed, written as bad.restart."""
    with zipfile.ZipFile(folder / "good.restart") as archive:
        members = {name: archive.read(name) for name in archive.namelist()}
    header = json.loads(members["header.json"])
    if header_edit:
        header_edit(header)
    members["header.json"] = raw_header if raw_header is not None else json.dumps(header).encode()
    if arrays_edit:
        for name, values in arrays_edit.items():
            buffer = io.BytesIO()
            np.lib.format.write_array(buffer, values(np.lib.format.read_array(io.BytesIO(members[f"{name}.npy"]))))
            members[f"{name}.npy"] = buffer.getvalue()
    with zipfile.ZipFile(folder / "bad.restart", "w") as archive:
        for name, data in members.items():
            archive.writestr(name, data)


def set_field(path, value):
    def edit(header):
        record = header
        for key in path[:-1]:
            record = record[key]
        record[path[-1]] = value
    return edit


@pytest.mark.parametrize("edit, message", [
    (set_field(["dimension"], 0), "field dimension must be 2 or 3 (got 0)"),
    (set_field(["dimension"], 5), "field dimension must be 2 or 3 (got 5)"),
    (set_field(["neighbor", "every"], 0), "field every must be from 1 to 9223372036854775807 (got 0)"),
    (set_field(["neighbor", "skin"], float("nan")), "field skin must be a number from 0 to 1e+150 (got nan)"),
    (set_field(["dt"], -1.0), "field dt must be from 1e-50 to 1e+50 (got -1.0)"),
    (set_field(["neighbor", "last_sort"], [[1]]), "field last_sort must be a step or null (got [[1]])"),
    (set_field(["step"], -4), "field step must be from 0 to 9223372036854775807 (got -4)"),
    (set_field(["particles", "nlocal"], float("inf")), "field nlocal must be a particle count (got inf)"),
    (set_field(["particle_style"], "ellipsoid"), "field particle_style must be a particle style or hybrid S1 S2 ... (got 'ellipsoid')"),
    (set_field(["ntypes"], 0), "field ntypes must be from 1 to 200 (got 0)"),
    (set_field(["fixes", 0, "group"], {"a": 1}), "field group must be a name (got {'a': 1})"),
    (set_field(["fixes", 0, "group"], "nowhere"), "fixes '1' uses group 'nowhere', which the file does not define"),
    (set_field(["groups", "bits", "all"], 40), "group 'all' has bit 40, not 0 to 31"),
    # fuzz, issue 12: the image flags' default beyond int32 (particle arrays grown in place)
    (set_field(["particles", "properties", 6, "default"], 2147483648),
     "per-atom array image has a default 2147483648 that is not an int32"),
    # issue 30: a skin of 1e10 was read, and the run crashed at its first rebuild
    (set_field(["neighbor", "skin"], 1e10),
     "field skin 1e+10 spans 1e+10 periodic images of the box (length 1 along x; at most 64)"),
    (set_field(["neighbor", "built_with", "skin"], 1e10),
     "field skin 1e+10 spans 1e+10 periodic images of the box (length 1 along x; at most 64)"),
    (set_field(["neighbor", "ago"], 10 ** 30),
     "field ago must be from 0 to 9223372036854775807 (got 1000000000000000000000000000000)"),
    (set_field(["energy_step"], -5), "field energy_step must be a step or null (got -5)"),
    # issue 30: next_tag at or below an id, and create_atoms made a second particle 1
    (set_field(["particles", "next_tag"], 1),
     "field next_tag 1 is not above the largest particle id 2 (new particles would reuse ids)"),
    (set_field(["particles", "next_tag"], 2),
     "field next_tag 2 is not above the largest particle id 2 (new particles would reuse ids)"),
])
def test_restart_header_values_are_checked(tmp_path, make_sim, edit, message):
    make_sim().command(RESTART_SCRIPT)
    edited_restart(tmp_path, header_edit=edit)
    sim = make_sim()
    with pytest.raises(Exception) as caught:
        sim.command("read_restart bad.restart")
    assert str(caught.value) == f"<command>:1: read_restart: restart file bad.restart: {message}"


@pytest.mark.parametrize("arrays, message", [
    ({"particles/type": lambda t: np.full_like(t, 99)}, "particle types must be from 1 to 1 (got 99 to 99)"),
    ({"particles/type": lambda t: np.zeros_like(t)}, "particle types must be from 1 to 1 (got 0 to 0)"),
    ({"particles/tag": lambda t: np.ones_like(t)}, "particle ids must be unique (an id appears twice)"),
    ({"particles/x": lambda x: x[:1]}, "array particles/x has shape (1, 3), not (2, 3)"),
    ({"mass": lambda m: np.full_like(m, np.inf)}, "masses must be finite numbers > 0 (or unset)"),
    ({"mass": lambda m: np.full_like(m, np.nan)}, "particles of type 1 have no mass (NaN in the file)"),
    ({"box/lo": lambda lo: np.full_like(lo, np.nan)}, "array box/lo holds non-finite values"),
    ({"box/lo": lambda lo: lo.astype(complex)}, "array box/lo holds complex128 values, which pdps does not write"),
    ({"mass": lambda m: m.astype(np.float16)}, "array mass holds float16 values, which pdps does not write"),
    ({"mass": lambda m: m.astype(np.float32)}, "array mass holds float32 values, not numbers of the saved kind"),
    ({"neighbor/xhold": lambda x: x.astype("U3")}, "array neighbor/xhold holds <U3 values, which pdps does not write"),
    ({"neighbor/xhold": lambda x: np.float64(1.0)}, "array neighbor/xhold has shape (), not (2, 3)"),
    ({"particles/v": lambda v: np.full_like(v, 1e200)},
     "array particles/v holds values that are not finite or beyond +-1e+150"),
])
def test_restart_array_values_are_checked(tmp_path, make_sim, arrays, message):
    make_sim().command(RESTART_SCRIPT)
    edited_restart(tmp_path, arrays_edit=arrays)
    with pytest.raises(Exception) as caught:
        make_sim().command("read_restart bad.restart")
    assert str(caught.value) == f"<command>:1: read_restart: restart file bad.restart: {message}"


def test_a_restart_array_in_the_other_byte_order_reads_as_written(tmp_path, make_sim):
    make_sim().command(RESTART_SCRIPT)
    swapped = {name: (lambda a: a.astype(a.dtype.newbyteorder(">")))
               for name in ("mass", "particles/x", "particles/v", "neighbor/xhold")}
    edited_restart(tmp_path, arrays_edit=swapped)
    runs = []
    for path in ("good.restart", "bad.restart"):
        sim = make_sim()
        sim.command(f"read_restart {path}\nfix 1 all nve\nrun 5")
        runs.append((sim.x.copy(), sim.v.copy()))
    assert np.array_equal(runs[0][0], runs[1][0]) and np.array_equal(runs[0][1], runs[1][1])


def test_an_unknown_compression_method_is_damage(tmp_path, make_sim):
    make_sim().command(RESTART_SCRIPT)
    raw = bytearray((tmp_path / "good.restart").read_bytes())
    # the compression method of the first central-directory entry set to one zipfile cannot read
    entry = raw.find(b"PK\x01\x02")
    raw[entry + 10:entry + 12] = (99).to_bytes(2, "little")
    (tmp_path / "bad.restart").write_bytes(bytes(raw))
    with pytest.raises(Exception) as caught:
        make_sim().command("read_restart bad.restart")
    assert str(caught.value) == ("<command>:1: read_restart: restart file bad.restart is truncated, "
                                 "damaged or not a pdps restart file")


def test_a_deeply_nested_restart_header_is_damaged_not_a_crash(tmp_path, make_sim):
    make_sim().command(RESTART_SCRIPT)
    edited_restart(tmp_path, raw_header=b"[" * 100000 + b"]" * 100000)
    with pytest.raises(Exception) as caught:
        make_sim().command("read_restart bad.restart")
    assert str(caught.value) == ("<command>:1: read_restart: restart file bad.restart is truncated, "
                                 "damaged or not a pdps restart file")


# ---- random numbers ---------------------------------------------------------------------------
from pdps_core.api import pair_gaussian  # noqa: E402

DPD = BOX.replace("0 1 0 1 0 1", "0 4 0 4 0 4") + """
create_particle 1 random 100 5 box
pair_style dpd 1.0 1.0 4211
pair_coeff * * 25.0 4.5
velocity all create 1.0 77
timestep 0.01
fix 1 all nve
"""


def test_a_run_after_reset_timestep_back_draws_new_noise(make_sim):
    first = make_sim()
    first.command(DPD + "run 0")
    noise_at_0 = first.f.copy()
    first.command("run 20\nreset_timestep 0")
    x, v = first.x.copy(), first.v.copy()
    first.command("run 0")
    replay = make_sim()
    replay.command(DPD + "run 0")
    replay.x[:], replay.v[:] = x, v
    replay.command("run 0")
    # same positions and velocities at step 0: only the noise (the key) can differ
    assert not np.allclose(first.f, replay.f)
    assert first.random_key(4211) != 4211 and replay.random_key(4211) == 4211
    assert noise_at_0.shape == first.f.shape


def test_reset_timestep_forward_keeps_the_key(make_sim):
    sim = make_sim()
    sim.command(DPD + "run 5\nreset_timestep 100\nrun 0")
    assert sim.random_key(4211) == 4211


def test_pair_noise_uses_every_bit_of_64_bit_ids():
    base = pair_gaussian(9, 3, 1, 2)
    assert pair_gaussian(9, 3, 1, 2 + 2 ** 32) != base
    assert pair_gaussian(9, 3, 1 + 2 ** 40, 2) != base
    assert pair_gaussian(9, 3, 1 + 2 ** 40, 2) != pair_gaussian(9, 3, 1 + 2 ** 41, 2)
    assert pair_gaussian(9, 3, 2, 1 + 2 ** 40) == pair_gaussian(9, 3, 1 + 2 ** 40, 2)


def test_velocity_create_with_huge_ids_needs_no_array_of_the_largest_id(tmp_path, make_sim):
    write_data(tmp_path / "far.data", (0, 0, 0), (5, 5, 5), [[1, 1, 1], [2, 2, 2], [3, 3, 3]],
               tags=[1, 2 ** 40, 2 ** 61])
    sim = make_sim()
    sim.command(f"read_data {tmp_path / 'far.data'}\nvelocity all create 1.5 8 dist gaussian\nrun 0")
    assert np.isfinite(sim.v).all() and np.abs(sim.v).max() > 0


# ---- parallel runs: one line per failure, counts over all ranks ---------------------------------
import subprocess  # noqa: E402
import sys  # noqa: E402

from pdps_core.testing import mpiexec  # noqa: E402


def on_two_ranks(folder, script):
    (folder / "in.test").write_text(script)
    return subprocess.run([mpiexec(), "-n", "2", sys.executable, "-m", "pdps_core.cli", "run", "in.test",
                           "-log", "none", "--no-progress"], cwd=folder, capture_output=True, text=True,
                          timeout=300)


def test_a_data_file_particle_outside_a_fixed_box_is_one_line_on_two_ranks(tmp_path):
    write_data(tmp_path / "out.data", (0, 0, 0), (10, 10, 10), [[1, 1, 1], [12, 2, 2]])
    done = on_two_ranks(tmp_path, "boundary f f f\nread_data out.data\nrun 1\n")
    one_line(done, "ERROR: in.test:2: read_data: particle 2 lost through the fixed x boundary at step 0: "
                   "x = 12 outside [0, 10] (1 particle(s) outside)")


def test_particles_lost_on_two_ranks_are_counted_together(tmp_path):
    done = on_two_ranks(tmp_path, """
boundary p p f
region box block 0 10 0 10 0 10
create_box 1 box
mass 1 1
processors 2 1 1
create_particle 1 single 1 1 9.9
create_particle 1 single 9 9 9.9
create_particle 1 single 9 1 9.9
velocity all set 0 0 5
fix 1 all nve
run 10
""")
    assert done.returncode == 1
    errors = [line for line in done.stderr.splitlines() if line.strip()]
    assert len(errors) == 1 and errors[0].endswith("(3 particle(s) outside)"), done.stderr


# ---- physics undefined: a warning, not silence ------------------------------------------------
def test_coincident_dem_spheres_are_named_in_a_warning(pdps_cli):
    done = pdps_cli("""
        particle_style sphere
        region box block 0 5 0 5 0 5
        create_box 1 box
        create_particle 1 single 2 2 2
        create_particle 1 single 2 2 2
        pair_style dem/lsd 0.3 1.0
        pair_coeff * * 1000 16.6016 314.29 6.3008 0.5 1
        fix 1 all nve/sphere
        run 1
    """)
    assert done.returncode == 0
    assert ("WARNING: pair dem/lsd: particles 1 and 2 sit at the same point at step 0: their contact has "
            "no normal, so they exert no force on each other (separate them, or start with fix "
            "nve/limit)") in done.stdout


def test_numpy_warnings_never_reach_the_screen(pdps_cli):
    """m v^2 overflows in numpy (mass 1e300, v 1e150): the thermo guard speaks, numpy does not."""
    done = pdps_cli(BOX.replace("mass 1 1.0", "mass 1 1e300") + """
        create_particle 1 single 0.5 0.5 0.5
        create_particle 1 single 0.2 0.5 0.5
        velocity all set 1e150 0 0
        run 0
    """)
    one_line(done, "ERROR: in.test:8: run: thermo Temp is inf at step 0: the run stops rather than go on "
                   "with non-finite values (velocities or forces too large?)")
    assert "RuntimeWarning" not in done.stdout


def test_a_non_finite_thermo_value_stops_the_run_naming_its_column(pdps_cli, tmp_path):
    done = pdps_cli(BOX + """
        create_particle 1 single 0.5 0.5 0.5
        create_particle 1 single 0.2 0.5 0.5
        mass 1 1e300
        velocity all set 1e100 0 0
        thermo_style custom step ke
        run 0
    """, "-log", "log.huge")
    one_line(done, "ERROR: in.test:10: run: thermo KinEng is inf at step 0: the run stops rather than go "
                   "on with non-finite values (velocities or forces too large?)")
    assert "inf" in (tmp_path / "log.huge").read_text()       # the line that showed it stays written


def test_velocities_beyond_what_squares_hold_are_refused(pdps_cli):
    one_line(pdps_cli(BOX + "velocity all set 1e200 0 0\n"),
             "ERROR: in.test:4: velocity: vx must be <= 1e+150 (got 1e200)")


# ---- found by the 100,000-case make fuzz run on the LAMMPS-dialect code ---------------------------
@pytest.mark.parametrize("lines, message", [
    (BOX.replace("create_box 1", "create_box 2") + "mass 2 1\npair_style lj/cut 2.5\npair_coeff 1 1 1.0 1.0\n"
     "pair_coeff 2 2 -258 1.0\nrun 0",
     "ERROR: in.test:8: run: pair coefficients for types 1 2 cannot be mixed (math domain error) from 1 1 and "
     "2 2: give pair_coeff 1 2"),
    (BOX + "pair_style lj/cut 1e-38\npair_coeff * * 1.0 1.0\npair_modify tail yes\nrun 0",
     "ERROR: in.test:7: run: pair_coeff 1 1: cutoff 1e-38 too small or large for the tail correction (rc^9 is "
     "not a positive finite number)"),
    ("label a\njump nowhere.in a\n", None),
])
def test_lammps_dialect_code_found_by_the_fuzz_run(pdps_cli, lines, message):
    done = pdps_cli(lines + "\n")
    if message is None:
        assert done.returncode == 1
        [line] = done.stderr.strip().splitlines()
        assert line.startswith("ERROR: in.test:2: jump: cannot read input script ") and line.endswith(
            "nowhere.in: No such file or directory")
    else:
        one_line(done, message)


# ---- issue 30: what the 15,558-case fuzz campaign and real scripts found ----------------------------
def test_a_100000_character_word_is_quoted_by_its_ends(pdps_cli):
    word = "a" * 50_000 + "b" * 50_000
    one_line(pdps_cli(f"units {word}\n"),
             f"ERROR: in.test:1: units: units style must be one of lj, real, metal, si, cgs, micro, nano "
             f"(got {'a' * 60}...{'b' * 19})")     # the run clipped ends at its ')'


@pytest.mark.parametrize("formula, value", [
    ("(" * 100 + "1+1" + ")" * 100, "2"),                  # LAMMPS takes 100 levels
    ("sqrt(" * 64 + "(" * 64 + "4" + ")" * 128, "1"),      # 128 levels of calls and parentheses
    ("-" * 2000 + "3", "3"),
    ("-" * 2001 + "3", "-3"),
    ("!" * 3 + "-" + "0", "1"),
    ("+".join(["1"] * 100_000), "100000"),                 # folded left to right, no recursion
])
def test_deep_and_long_formulas_evaluate(pdps_cli, formula, value):
    done = pdps_cli(f"variable a equal {formula}\nprint ${{a}}\n", "-log", "none")
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1] == value


def test_formulas_nested_beyond_the_limit_are_one_line(pdps_cli):
    formula = "(" * 129 + "1" + ")" * 129
    one_line(pdps_cli(f"variable a equal {formula}\n"),
             "ERROR: in.test:1: variable: variable a: parentheses and function calls nested more than 128 "
             f"deep in formula '{'(' * 60}...{')' * 20}'")


def test_a_long_quoted_formula_is_shown_by_its_ends(pdps_cli):
    formula = " + ".join(["1"] * 50_000) + ")"
    one_line(pdps_cli(f"variable a equal {formula}\n"),
             f"ERROR: in.test:1: variable: variable a: unexpected ')' in formula '{formula[:60]}...{formula[-20:]}'")


@pytest.mark.parametrize("append, kept", [
    ("", ["print three", "three"]),         # LAMMPS: the log begins again, its old lines gone
    (" append", ["print one", "one", "print two", "two", "log first.log append", "print three", "three"]),
])
def test_a_log_command_naming_the_current_log(pdps_cli, tmp_path, append, kept):
    # issue 30: the new log was opened before the old one was flushed, whose stale lines then
    # ended up after the new ones
    done = pdps_cli(f"print one\nprint two\nlog first.log{append}\nprint three\n", "-log", "first.log")
    assert done.returncode == 0, done.stderr
    lines = (tmp_path / "first.log").read_text().splitlines()
    assert lines[-len(kept):] == kept
    assert len(lines) == len(kept) + (1 if append else 0)     # + the first line, naming the dialect


@pytest.mark.parametrize("line, message", [
    # the fuzz suite's (issue 30's corpus): a LIGGGHTS density of 1.5e208, and Hertz's contact time overflowed
    ("set type 1 density 1.4831253087569968e+208",
     "density must be from 1e-50 to 1e+50 (got 1.4831253087569968e+208)"),
    ("set type 1 diameter 1e60", "diameter must be from 1e-50 to 1e+50 (got 1e60)"),
    ("set type 1 mass 1e-160", "mass must be from 1e-150 to 1e+150 (got 1e-160)"),
])
def test_set_sphere_sizes_beyond_normal_numbers(pdps_cli, line, message):
    one_line(pdps_cli("atom_style sphere\nregion box block 0 1 0 1 0 1\ncreate_box 1 box\n"
                      f"create_atoms 1 single 0.5 0.5 0.5\n{line}\n"), f"ERROR: in.test:5: set: {message}")
