"""The `pdps` command: exit codes, the one-line error contract, logs, -var, and `pdps styles`.

Most cases run ``cli.main`` in-process (``pdps_cli``: the console script's code path, fast); a few run
the real process (``run_pdps``) where the process itself is the point: exit status, stray output.
"""

import re
import subprocess
import sys

import pytest

from pdps_core.styles import registry

BOX = """\
region box block 0 4 0 4 0 4
create_box 1 box
mass 1 1
"""

LINE = re.compile(r"^ERROR: in\.test:\d+: \S+: .+$")


def one_error_line(result):
    """The single stderr line of a failed run, checked against the contract."""
    assert result.returncode == 1, result
    lines = result.stderr.splitlines()
    assert len(lines) == 1, result.stderr
    assert "Traceback" not in result.stderr and "Traceback" not in result.stdout
    return lines[0]


# ---- exit codes, through the real process ------------------------------------------------------------
def test_a_good_script_exits_0_with_nothing_on_stderr(run_pdps):
    result = run_pdps(BOX + "create_particle 1 single 1 1 1\nprint done\nrun 2\n", "-log", "none")
    assert (result.returncode, result.stderr) == (0, "")
    assert "done" in result.stdout.splitlines()


def test_a_run_that_fails_exits_1_with_one_line_and_no_traceback(run_pdps, tmp_path):
    result = run_pdps(BOX + "create_particle 1 single 1 1 1\nvelocity all set 0 0 1\nfix 1 all nve\n"
                            "timestep 0.5\nrun 1\nbogus_command\n")
    assert one_error_line(result) == "ERROR: in.test:9: bogus_command: unknown command bogus_command"
    assert (tmp_path / "log.pdps").exists()


def test_usage_errors_exit_2(run_pdps):
    result = subprocess.run([sys.executable, "-m", "pdps_core.cli", "run", "--dialect", "fortran"],
                            capture_output=True, text=True)
    assert result.returncode == 2
    assert "usage: pdps run" in result.stderr


def test_a_script_on_standard_input_runs_as_lmp_reads_it(tmp_path):
    # lmp < in.script: no script named, the script piped in
    result = subprocess.run([sys.executable, "-m", "pdps_core.cli", "run", "-log", "none"], cwd=tmp_path,
                            input="atom_style atomic\nvariable a equal 2^3^2\nprint $a\n",
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == ["read as LAMMPS: atom_style on line 1", "64"]


def test_lmp_flags(tmp_path):
    (tmp_path / "in.flags").write_text("print ${n}-${m}\nvariable z equal 1\n")
    result = subprocess.run([sys.executable, "-m", "pdps_core.cli", "-in", "in.flags", "-var", "n", "7",
                             "-v", "m", "a", "b", "-screen", "screen.txt", "-log", "log.txt", "-echo", "both"],
                            cwd=tmp_path, capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert result.stdout == ""
    screen = (tmp_path / "screen.txt").read_text().splitlines()
    assert screen == ["read as PDPS: no command names a dialect (PDPS is the default)", "print 7-a",
                      "7-a", "variable z equal 1"]
    assert (tmp_path / "log.txt").read_text().splitlines() == screen


def test_styles_lists_every_style_with_its_distribution_and_version():
    result = subprocess.run([sys.executable, "-m", "pdps_core.cli", "styles"], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    rows = {tuple(line.split()) for line in result.stdout.splitlines()}
    for expected in [("pair", "dpd", "pdps-pair-dpd"), ("fix", "nve", "pdps-fix-nve"),
                     ("compute", "temp", "pdps-compute-thermo"), ("compute", "pressure", "pdps-compute-thermo"),
                     ("compute", "centroid", "pdps-compute-thermo"), ("dump", "atom", "pdps-dump-text"),
                     ("dump", "custom", "pdps-dump-text"), ("region", "block", "pdps-region-shapes"),
                     ("region", "polygon", "pdps-region-shapes")]:
        assert (*expected, "0.1.0") in rows          # loaded and usable: nothing after the version
    installed = {(e.kind, e.name, e.dist, e.version) for e in registry.entries()
                 if e.dist != "(registered in process)"}     # other tests may register styles in-process
    assert rows == installed


def styles_verbose(capsys):
    """`pdps styles -v` in-process: style (kind, name) -> its three indented lines."""
    from pdps_core import cli
    capsys.readouterr()
    assert cli.main(["styles", "-v"]) == 0
    blocks, key = {}, None
    for line in capsys.readouterr().out.splitlines():
        if line.startswith("    "):
            blocks[key].append(line.strip())
        else:
            key = tuple(line.split()[:2])
            blocks[key] = [line]
    return blocks


def test_styles_verbose_shows_hooks_needs_and_contributions(capsys, monkeypatch):
    from pdps_core.styles import Fix

    class FixHolder(Fix):
        """A test double declaring every contribution a fix can make."""
        name = "holder"
        per_atom = (("anchor", 3),)
        ghost_fields = ("anchor",)
        neighbor_lists_needed = True
        can_energy, can_virial, virial_default = True, True, True

        def post_force(self, sim):
            pass

        def dof_removed(self, sim, group):
            return 0

    monkeypatch.setattr(registry, "_local", {**registry._local, "fix": {"holder": FixHolder}})
    blocks = styles_verbose(capsys)
    assert blocks[("pair", "dpd")][1:] == [
        "hooks:        force law in the core's pair loop",
        "needs:        half neighbor list; per-atom v, tag in the force law; ghost velocities",
        "contributes:  pair forces, energy and virial"]
    assert blocks[("fix", "wall/reflect")][0].split() == ["fix", "wall/reflect", "pdps-fix-wall", "0.1.0"]
    assert blocks[("fix", "wall/reflect")][1] == "hooks:        setup; post_integrate; end_of_step"
    assert blocks[("fix", "wall/dem")][1] == "hooks:        setup; pre_neighbor; post_force"
    assert blocks[("pair", "dem/lsd")][2] == (
        "needs:        per-atom radius, rmass, omega, torque; half neighbor list; ghost velocities; ghost omega")
    assert blocks[("compute", "coord/atom")][1:3] == [
        "hooks:        init_run", "needs:        neighbor lists (requested in init_run)"]
    assert blocks[("fix", "holder")][1:] == [
        "hooks:        post_force",
        "needs:        per-atom anchor[3]; neighbor lists (requested in init_run); ghost anchor",
        "contributes:  energy to pe (fix_modify ID energy yes); virial to press (on; fix_modify ID virial no); "
        "removed degrees of freedom to temperatures"]


def test_doc_lays_out_the_manual_sections_with_parameters_bounds_and_units(capsys):
    from pdps_core import cli
    capsys.readouterr()
    assert cli.main(["doc", "pair", "dem/lsd"]) == 0
    page = capsys.readouterr().out.splitlines()
    assert page[0] == "pair style dem/lsd  (pdps-pair-dem 0.1.0)"
    headings = [line for line in page if line in ("Syntax:", "Examples:", "Description:", "Parameters:", "Default:")]
    assert headings == ["Syntax:", "Examples:", "Description:", "Parameters:", "Default:"]
    syntax = page.index("Syntax:")
    assert page[syntax + 2:syntax + 4] == [
        "    pair_style dem/lsd e cutoff [limit_damping yes|no] [max_contacts N]",
        "    pair_coeff I J kn cn kt ct mu [cutoff]  or  kn KN [kt KT] [e E] mu MU [ct CT] [cutoff RC]"]
    examples = page.index("Examples:")
    assert page[examples + 2:examples + 5] == [
        "    particle_style sphere", "    pair_style dem/lsd 0.3 1.0", "    pair_coeff * * 1000 16.6016 314.29 6.3008 0.5 1"]
    parameters = page[page.index("Parameters:"):page.index("Default:")]
    for line in ["- e: number; 0 < e <= 1; unit: dimensionless; required",
                 "- cutoff: number; cutoff > 0; unit: distance; required",
                 "- max_contacts (keyword): integer; max_contacts >= 2; unit: dimensionless; default 16",
                 "- limit_damping (keyword): yes|no; default no",
                 "- cn: number; cn >= 0; unit: force/velocity; required",
                 "- kt (keyword): number; kt >= 0; unit: force/distance; optional"]:
        assert line in parameters
    assert page[page.index("Default:") + 2] == "limit_damping = no, max_contacts = 16"
    capsys.readouterr()
    assert cli.main(["doc", "fix", "addforce"]) == 0
    page = capsys.readouterr().out.splitlines()
    assert "- fx: number or v_NAME; unit: force; optional" in page
    assert "- drag_stokes (keyword): number; drag_stokes >= 0; unit: dynamic viscosity; optional" in page


def test_doc_of_an_unknown_style_is_one_line(capsys):
    from pdps_core import cli
    capsys.readouterr()
    assert cli.main(["doc", "fix", "nvee"]) == 1
    assert capsys.readouterr().err.startswith("ERROR: unknown fix style nvee; did you mean nve? (installed: ")


# ---- the one-line error contract -----------------------------------------------------------------
@pytest.mark.parametrize("script, expected", [
    # unknown command, with and without a close match
    ("pair_cof 1 1 1 1", "ERROR: in.test:1: pair_cof: unknown command pair_cof; did you mean pair_coeff?"),
    ("print ok\nfrobnicate 3", "ERROR: in.test:2: frobnicate: unknown command frobnicate; did you mean communicate?"),
    # unknown style: the installed ones, and a close match
    ("region box blok 0 1 0 1 0 1",
     "ERROR: in.test:1: region: unknown region style blok; did you mean block? (installed: {region})"),
    (BOX + "fix 1 all nvee",
     "ERROR: in.test:4: fix: unknown fix style nvee; did you mean nve? (installed: {fix})"),
    ("pair_style quadrupole 2.5", "ERROR: in.test:1: pair_style: unknown pair style quadrupole (installed: {pair})"),
    # wrong argument count
    ("boundary p p", "ERROR: in.test:1: boundary: expected 3 argument(s), got 2; usage: boundary x y z  (each p, f, s, m, or two of f, s, m)"),
    (BOX + "fix 1 all nve extra", "ERROR: in.test:4: fix: too many arguments: unexpected 'extra'; usage: fix ID GROUP nve"),
    ("region box block 0 1 0 1 0",
     "ERROR: in.test:1: region: missing argument zhi; usage: region ID block xlo xhi ylo yhi zlo zhi "
     "[side in|out] [units box|lattice]"),
    # non-numeric and out-of-range values, quoted as given
    ("timestep fast", "ERROR: in.test:1: timestep: timestep must be a number (got fast)"),
    (BOX + "mass 1 heavy", "ERROR: in.test:4: mass: mass must be a number (got heavy)"),
    ("region box block 0 1 0 x 0 1", "ERROR: in.test:1: region: yhi must be a number, INF, -INF or EDGE (got x)"),
    (BOX + "pair_style dpd 1.0 1.0 1\npair_coeff 1 1 abc 4.5",
     "ERROR: in.test:5: pair_coeff: a must be a finite number (got abc)"),
    (BOX + "pair_style dpd 1.0 1.0 1\npair_coeff 1 1 25 -4.5",
     "ERROR: in.test:5: pair_coeff: gamma must be >= 0 (got -4.5)"),
    # undefined names
    (BOX + "velocity hot create 1.0 1", "ERROR: in.test:4: velocity: group hot is not defined (defined: all)"),
    (BOX + "create_particle 1 region nowhere",
     "ERROR: in.test:4: create_particle: region nowhere is not defined (defined: box)"),
    (BOX + "uncompute 7", "ERROR: in.test:4: uncompute: compute 7 is not defined"),
    (BOX + "thermo_style custom step c_7\nrun 0",
     "ERROR: in.test:5: run: thermo_style: compute 7 is not defined (thermo keyword c_7)"),
    (BOX + "thermo_style custom step v_nope\nrun 0",
     "ERROR: in.test:5: run: thermo_style: variable nope is not defined (thermo keyword v_nope)"),
    ('print "${nope}"', "ERROR: in.test:1: print: undefined variable nope"),
    ('variable a equal v_nope+1\nprint "$(v_a)"', "ERROR: in.test:2: print: undefined variable nope"),
    # state a command needs
    ("run 0", "ERROR: in.test:1: run: run before the simulation box exists (use create_box or read_data first)"),
    ("region box block 0 4 0 4 0 4\ncreate_box 1 box\ncreate_particle 1 single 1 1 1\nrun 0",
     "ERROR: in.test:4: run: mass is not set for type 1 (use the mass command)"),
    (BOX + "processors 2 1 1",
     "ERROR: in.test:4: processors: processor grid 2 x 1 x 1 = 2 does not match the 1 rank(s) of this run"),
])
def test_bad_input_gives_one_line(pdps_cli, script, expected):
    if "(installed: {" in expected:      # the list is read when the test runs: tests may register styles
        expected = expected.format(**{kind: ", ".join(registry.names(kind)) for kind in ("pair", "fix", "region")})
    result = pdps_cli(script, "-log", "none")
    assert one_error_line(result) == expected
    assert LINE.match(expected)


@pytest.mark.parametrize("script, expected", [
    ("timestep ${dt}", "ERROR: in.test:1: timestep: undefined variable dt"),
    ("print ok\nthermo $n", "ERROR: in.test:2: thermo: undefined variable n"),
    ("variable a equal 1/0\ntimestep $a", "ERROR: in.test:2: timestep: divide by 0 in formula '1/0'"),
    ('print "open', 'ERROR: in.test:1: print: unbalanced quote " in: print "open'),
])
def test_errors_found_while_substituting_name_the_command(pdps_cli, script, expected):
    assert one_error_line(pdps_cli(script, "-log", "none")) == expected


def test_missing_pair_coeff_for_a_type_pair(pdps_cli):
    result = pdps_cli("""\
        region box block 0 4 0 4 0 4
        create_box 2 box
        mass * 1
        create_particle 1 single 1 1 1
        create_particle 2 single 2 2 2
        pair_style dpd 1.0 1.0 1234
        pair_coeff 1 1 25 4.5
        pair_coeff 2 2 25 4.5
        run 0
        """, "-log", "none")
    assert one_error_line(result).startswith(
        "ERROR: in.test:9: run: pair coefficients are not set for types 1 2 (give pair_coeff")


def test_missing_script_file(tmp_path):
    result = subprocess.run([sys.executable, "-m", "pdps_core.cli", "run", "nowhere.in", "-log", "none"],
                            cwd=tmp_path, capture_output=True, text=True)
    assert result.returncode == 1
    assert result.stderr == "ERROR: nowhere.in: cannot read this input script: No such file or directory\n"


def test_a_script_that_is_a_folder(tmp_path):
    # issue 30: the error named neither file nor line; LAMMPS 22 Jul 2025 reads a folder as an empty
    # script and runs nothing without a word
    (tmp_path / "in.folder").mkdir()
    result = subprocess.run([sys.executable, "-m", "pdps_core.cli", "run", "in.folder", "-log", "none"],
                            cwd=tmp_path, capture_output=True, text=True)
    assert result.returncode == 1
    assert result.stderr == "ERROR: in.folder: cannot read this input script: Is a directory\n"


# ---- a particle leaving through an f boundary, and what is kept ----------------------------------
LOST = """\
boundary p f p
region box block 0 4 0 4 0 4
create_box 1 box
mass 1 1
create_particle 1 single 1 1 1
create_particle 1 single 2 3.55 2
velocity all set 0 1 0
fix 1 all nve
timestep 0.1
neigh_modify every 1 delay 0 check no
thermo 1
dump 1 all atom 1 frames.atom
run 20
"""


def test_lost_particle_names_particle_axis_and_step(pdps_cli):
    line = one_error_line(pdps_cli(LOST))
    assert line == ("ERROR: in.test:13: run: particle 2 lost through the fixed y boundary at step 5: "
                    "y = 4.05 outside [0, 4] (1 particle(s) outside)")


def test_output_written_before_the_error_is_kept(pdps_cli, tmp_path):
    result = pdps_cli(LOST)
    error = one_error_line(result)
    log = (tmp_path / "log.pdps").read_text().splitlines()
    assert log[-1] == error                               # the error closes the log
    rows = [line.split() for line in log if re.match(r"^\s+\d+\s", line)]
    assert [int(r[0]) for r in rows] == [0, 1, 2, 3, 4]   # every thermo line up to the failing step
    frames = (tmp_path / "frames.atom").read_text().split("ITEM: TIMESTEP\n")[1:]
    assert [int(f.split()[0]) for f in frames] == [0, 1, 2, 3, 4]
    for frame in frames:                                  # every frame is complete
        lines = frame.splitlines()
        assert lines[1:3] == ["ITEM: NUMBER OF ATOMS", "2"]
        assert len(lines) == 1 + 2 + 4 + 1 + 2


@pytest.fixture
def broken_fix(monkeypatch):
    """A fix style whose hook raises a plain Python error: a bug in a plugin, not bad input."""
    from pdps_core.styles import Fix

    class Broken(Fix):
        name = "broken"

        def initial_integrate(self, sim):
            raise ZeroDivisionError("boom")

    monkeypatch.setattr(registry, "_local", {**registry._local, "fix": {"broken": Broken}})
    monkeypatch.setattr(registry, "_loaded", {})
    return BOX + "create_particle 1 single 1 1 1\nfix 1 all broken\nrun 3\n"


def test_internal_error_is_one_line_too(pdps_cli, broken_fix):
    line = one_error_line(pdps_cli(broken_fix, "-log", "none"))
    assert line.startswith("ERROR: internal error")
    assert line.endswith(": ZeroDivisionError: boom (run with --debug for the traceback)")


def test_debug_shows_the_traceback(pdps_cli, broken_fix):
    result = pdps_cli(broken_fix, "-log", "none", "--debug")
    assert result.returncode == 1
    assert "Traceback" in result.stderr and "ZeroDivisionError: boom" in result.stderr
    assert result.stderr.splitlines()[-1].startswith("ERROR: internal error")


def test_internal_error_names_file_and_line(pdps_cli, broken_fix):
    assert one_error_line(pdps_cli(broken_fix, "-log", "none")) == (
        "ERROR: internal error at in.test:6: ZeroDivisionError: boom (run with --debug for the traceback)")


# ---- -log and -var -------------------------------------------------------------------------------
def test_default_log_file(pdps_cli, tmp_path):
    result = pdps_cli(BOX + 'print "hello log"\n')
    assert result.returncode == 0
    log = (tmp_path / "log.pdps").read_text().splitlines()
    assert "region box block 0 4 0 4 0 4" in log          # commands are echoed to the log
    assert log[-1] == "hello log"


def test_log_file_named(pdps_cli, tmp_path):
    assert pdps_cli(BOX + "print there\n", "-log", "run.log").returncode == 0
    assert (tmp_path / "run.log").read_text().splitlines()[-1] == "there"
    assert not (tmp_path / "log.pdps").exists()


def test_log_none_writes_no_file(pdps_cli, tmp_path):
    result = pdps_cli(BOX + "print quiet\n", "-log", "none")
    assert result.returncode == 0
    assert "quiet" in result.stdout.splitlines()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.test"]


def test_var_overrides_the_scripts_index_variable(pdps_cli):
    script = "variable T index 1.0\nvariable n index 3\nprint T=${T} n=$n\n"
    assert "T=1.0 n=3" in pdps_cli(script, "-log", "none").stdout.splitlines()
    result = pdps_cli(script, "-log", "none", "-var", "T", "2.5", "-var", "n", "7")
    assert result.returncode == 0
    assert "T=2.5 n=7" in result.stdout.splitlines()


def test_var_defines_a_variable_the_script_only_reads(pdps_cli):
    result = pdps_cli('print "seed ${seed}"\n', "-log", "none", "-var", "seed", "4242")
    assert "seed 4242" in result.stdout.splitlines()


def test_bad_var_name(pdps_cli):
    result = pdps_cli("print ok\n", "-log", "none", "-var", "bad-name", "1")
    assert result.returncode == 1
    assert result.stderr == "ERROR: variable name must be letters, digits and _ (got bad-name)\n"


def test_styles_into_a_pipe_closed_early_prints_no_traceback():
    result = subprocess.run(f"{sys.executable} -m pdps_core.cli styles | head -1", shell=True,
                            capture_output=True, text=True)
    assert result.stdout.count("\n") == 1 and "Traceback" not in result.stderr and "Error" not in result.stderr


# ---- quit and shell (LAMMPS's; LIGGGHTS 3.8.0's recorded in tests/data/liggghts.cases.json, shell_quit)
def test_quit_ends_the_script_with_its_status_keeping_the_output(pdps_cli, tmp_path):
    (tmp_path / "in.rest").write_text("print 'in the included file'\nquit 3\nprint 'never'\n")
    result = pdps_cli("atom_style atomic\n" + BOX + "create_atoms 1 single 1 1 1\nfix 1 all nve\n"
                      "dump d all custom 1 frames.txt id x\nrun 2\ninclude in.rest\nrun 2\n")
    assert (result.returncode, result.stderr) == (3, "")
    assert "in the included file" in result.stdout and "never" not in result.stdout
    # the dump's frames of the first run, complete; the second run never started
    assert (tmp_path / "frames.txt").read_text().count("ITEM: TIMESTEP") == 3


def test_quit_without_a_status_exits_0_and_1_in_the_liggghts_dialect(pdps_cli):
    assert pdps_cli("atom_style atomic\nquit\n").returncode == 0
    assert pdps_cli("atom_style atomic\nif '1 > 0' then quit\nprint no\n").returncode == 0
    # the lines after a quit are never read, so never refused
    assert pdps_cli("atom_style atomic\nquit\nbogus_command\n").returncode == 0
    assert pdps_cli("atom_style atomic\nquit\n", "--dialect", "liggghts").returncode == 1


@pytest.mark.parametrize("script, expected", [
    ("quit 1 2\n", "ERROR: in.test:2: quit: expected 0 to 1 argument(s), got 2; usage: quit [STATUS]"),
    ("quit 300\n", "ERROR: in.test:2: quit: quit STATUS is an exit code from 0 to 255 (got 300)"),
    ("shell mv a\n", "ERROR: in.test:2: shell: expected: shell mv OLD NEW (got 1 words)"),
    ("shell putenv X\n", "ERROR: in.test:2: shell: shell putenv takes NAME=VALUE (got 'X')"),
    ("shell\n", "ERROR: in.test:2: shell: expected: shell cd|mkdir|mv|rm|rmdir|putenv ARGS, or a shell command"),
])
def test_bad_quit_and_shell_lines(pdps_cli, script, expected):
    assert one_error_line(pdps_cli("atom_style atomic\n" + script)) == expected


def test_quit_with_a_status_is_refused_in_the_liggghts_dialect(pdps_cli):
    line = one_error_line(pdps_cli("atom_style atomic\nquit 0\n", "--dialect", "liggghts"))
    assert line == ("ERROR: in.test:2: quit: expected 0 argument(s), got 1; usage: quit "
                    "(the LIGGGHTS dialect's quit takes no status)")


def test_shell_makes_moves_and_removes_files_and_sets_the_environment(pdps_cli, tmp_path, monkeypatch):
    monkeypatch.delenv("PDPS_SHELL_TEST", raising=False)
    result = pdps_cli("atom_style atomic\nshell mkdir a/b c\nshell cd a\nprint here file here.txt\n"
                      "shell cd ..\nshell mv a/here.txt c/there.txt\nshell rmdir a/b\nshell putenv PDPS_SHELL_TEST=7\n"
                      "variable v getenv PDPS_SHELL_TEST\nprint 'v=${v}'\nshell echo from-the-shell > c/echo.txt\n"
                      "shell rm c/gone.txt\nshell false\nprint end\n")
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "c" / "there.txt").read_text() == "here\n"
    assert not (tmp_path / "a" / "b").exists() and (tmp_path / "a").is_dir()
    assert (tmp_path / "c" / "echo.txt").read_text() == "from-the-shell\n"
    assert "v=7" in result.stdout.splitlines()
    # a failure warns, as LAMMPS does, and the script goes on
    assert "WARNING: shell rm: No such file or directory (c/gone.txt)" in result.stdout
    assert "WARNING: shell false: the command exited with status 1" in result.stdout
    assert result.stdout.splitlines()[-1] == "end"


def test_an_internal_error_on_one_rank_stops_every_rank(tmp_path):
    """A bug one rank alone meets (a plugin's exception) must not leave the other ranks waiting in
    their next collective call: the rank that met it reports it and stops them all."""
    from pdps_core.testing import mpiexec
    (tmp_path / "in.test").write_text(BOX + "create_particle 1 single 1 1 1\ncreate_particle 1 single 3 3 3\n"
                                      "fix 1 all broken\nrun 3\n")
    (tmp_path / "driver.py").write_text(
        "import sys\n"
        "from pdps_core.styles import Fix, registry\n"
        "class Broken(Fix):\n"
        "    name = 'broken'\n"
        "    def initial_integrate(self, sim):\n"
        "        if sim.comm.rank == 1:\n"
        "            raise ZeroDivisionError('boom')\n"
        "registry._local = {**registry._local, 'fix': {'broken': Broken}}\n"
        "registry._loaded = {}\n"
        "from pdps_core.cli import main\n"
        "sys.exit(main(['run', 'in.test', '-log', 'none', '--no-progress']))\n")
    # the timeout only tells a hang from an answer: the run takes seconds
    done = subprocess.run([mpiexec(), "-n", "2", sys.executable, "driver.py"], cwd=tmp_path, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode != 0
    assert ("ERROR: internal error at in.test:7: ZeroDivisionError: boom (run with --debug for the traceback)"
            in done.stderr.splitlines())
