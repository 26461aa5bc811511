"""Output beyond the thermo table: its CSV copy, `pdps plot`, and the progress line.

No test reads the wall clock: progress runs on a fake clock that moves a fixed amount per reading.
"""

import csv
import io
import re

import matplotlib.image          # the core's [bench] extra, installed by make
import pytest

from pdps_core.output import output as output_module
from pdps_core.output.plot import build_figure, choose_columns, read_csv, read_log
from pdps_core.output.progress import Progress, clock_text, progress_text

FLUID = """\
region box block 0 4 0 4 0 4
create_box 1 box
mass 1 1
create_particle 1 random_no_overlap 40 box 0.6 11
pair_style dpd 1.0 1.0 5
pair_coeff * * 25 4.5
velocity all create 1.0 4
fix 1 all nve
timestep 0.02
thermo 5
"""


def rows_of(path):
    with open(path, newline="") as handle:
        return list(csv.reader(handle))


def thermo_tables(log_path):
    """(header words, rows of words) of each thermo table of a log: the line after each header
    down to the Loop time line."""
    lines = open(log_path).read().splitlines()
    tables = []
    for k, line in enumerate(lines):
        if line.split()[:1] == ["Step"]:
            end = next(j for j in range(k + 1, len(lines)) if lines[j].startswith("Loop time"))
            tables.append((line.split(), [row.split() for row in lines[k + 1:end]]))
    return tables


class FakeClock:
    """Seconds that advance by ``tick`` at each reading."""

    def __init__(self, tick):
        self.now, self.tick = 0.0, tick

    def __call__(self):
        value = self.now
        self.now += self.tick
        return value


# ---- thermo CSV ---------------------------------------------------------------------------------
def test_csv_next_to_the_log_has_every_thermo_line_at_full_precision(make_sim, tmp_path):
    sim = make_sim(log="run.log")
    sim.command(FLUID + "run 20")
    values = sim.output.thermo.values()
    sim.close()
    ((header, lines),) = thermo_tables(tmp_path / "run.log")
    table = rows_of(tmp_path / "run.log.csv")
    assert table[0] == header == ["Step", "Temp", "PotEng", "KinEng", "TotEng", "Press"]
    assert [row[0] for row in table[1:]] == ["0", "5", "10", "15", "20"]
    for row, line in zip(table[1:], lines, strict=True):
        assert [float(v) for v in row] == pytest.approx([float(v) for v in line], rel=1e-7)
    assert any(len(value) > 12 for row in table[1:] for value in row[1:])    # more than 8 digits
    assert [float(v) for v in table[-1]] == values                        # exact: read back as is


def test_runs_append_rows_and_new_columns_start_a_numbered_file(make_sim, tmp_path):
    sim = make_sim(log="log.pdps")
    sim.command(FLUID + "run 10\nrun 10")
    first = rows_of(tmp_path / "log.pdps.csv")
    assert [row[0] for row in first] == ["Step", "0", "5", "10", "10", "15", "20"]  # one header
    sim.command("thermo_style custom step temp atoms\nrun 5")
    assert rows_of(tmp_path / "log.pdps.csv") == first
    second = rows_of(tmp_path / "log.pdps.2.csv")
    assert second[0] == ["Step", "Temp", "Atoms"]
    assert [row[0] for row in second[1:]] == ["20", "25"] and second[1][2] == "40"
    assert "the thermo CSV goes on in log.pdps.2.csv" in (tmp_path / "log.pdps").read_text()


def test_a_new_series_removes_the_numbered_files_of_an_old_one(make_sim, tmp_path):
    (tmp_path / "log.pdps.2.csv").write_text("stale\n")
    (tmp_path / "log.pdps.3.csv").write_text("stale\n")
    make_sim(log="log.pdps").command(FLUID + "run 5")
    assert sorted(p.name for p in tmp_path.glob("*.csv")) == ["log.pdps.csv"]


def test_the_csv_follows_the_log_command(make_sim, tmp_path):
    sim = make_sim(log=None)
    sim.command(FLUID + "run 5")
    assert not list(tmp_path.glob("*.csv"))
    sim.command("log second.log\nrun 5\nlog none\nrun 5")
    assert [row[0] for row in rows_of(tmp_path / "second.log.csv")] == ["Step", "5", "10"]
    sim.output.thermo_csv(str(tmp_path / "chosen.csv"))      # the hook for a thermo_csv command
    sim.command("run 5")
    assert [row[0] for row in rows_of(tmp_path / "chosen.csv")] == ["Step", "15", "20"]


def test_csv_rows_are_flushed_before_a_run_fails(pdps_cli, tmp_path):
    result = pdps_cli("""\
        boundary p f p
        region box block 0 4 0 4 0 4
        create_box 1 box
        mass 1 1
        create_particle 1 single 2 3.55 2
        velocity all set 0 1 0
        fix 1 all nve
        timestep 0.1
        neigh_modify every 1 delay 0 check no
        thermo 1
        run 20
        """)
    assert result.returncode == 1
    assert [row[0] for row in rows_of(tmp_path / "log.pdps.csv")] == ["Step", "0", "1", "2", "3", "4"]


def test_no_log_no_csv(pdps_cli, tmp_path):
    assert pdps_cli(FLUID + "run 5", "-log", "none").returncode == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.test"]


# ---- pdps plot ----------------------------------------------------------------------------------
LOG = """\
units lj
      Step           Temp          Press
         0            1.5            2.5
WARNING: something the run said
        10            1.25           2.0
Loop time of 0.1 on 1 procs for 10 steps with 4 particles
thermo_style custom step temp pe
      Step           Temp         PotEng
        10            1.25          -3.0
        20            1.0           -3.5
Loop time of 0.1 on 1 procs for 10 steps with 4 particles
"""


def test_read_log_joins_the_tables_of_several_runs(tmp_path):
    (tmp_path / "log.x").write_text(LOG)
    table = read_log(str(tmp_path / "log.x"))
    assert table.names == ["Step", "Temp", "Press", "PotEng"]
    assert table.column("Step") == [0, 10, 10, 20]
    assert table.column("Temp") == [1.5, 1.25, 1.25, 1.0]
    press, pe = table.column("Press"), table.column("PotEng")
    assert press[:2] == [2.5, 2.0] and pe[2:] == [-3.0, -3.5]
    assert all(v != v for v in press[2:] + pe[:2])            # blank (NaN) where a run had none
    assert choose_columns(table, ["temp", "PotEng", "press"], "log.x") == ["Temp", "PotEng", "Press"]


def test_read_log_finds_the_tables_pdps_writes(make_sim, tmp_path):
    sim = make_sim(log="log.pdps")
    sim.command(FLUID + "run 10\nthermo_style custom step temp press\nrun 10")
    from_log = read_log(str(tmp_path / "log.pdps"))
    assert from_log.names == ["Step", "Temp", "PotEng", "KinEng", "TotEng", "Press"]
    assert from_log.column("Step") == [0, 5, 10, 10, 15, 20]
    from_csv = read_csv(str(tmp_path / "log.pdps.2.csv"))
    assert from_csv.column("Step") == [10, 15, 20]
    assert from_csv.column("Temp") == pytest.approx(from_log.column("Temp")[3:], rel=1e-7)


def test_figure_has_one_panel_per_column_on_a_shared_step_axis(tmp_path):
    (tmp_path / "log.x").write_text(LOG)
    table = read_log(str(tmp_path / "log.x"))
    figure = build_figure(table, ["Temp", "PotEng"])
    axes = figure.axes
    assert [ax.get_ylabel() for ax in axes] == ["Temp", "PotEng"]
    assert axes[0].get_shared_x_axes().joined(axes[0], axes[1])
    (temp,), (pe,) = axes[0].get_lines(), axes[1].get_lines()
    assert list(temp.get_xdata()) == [0, 10, 10, 20] and list(temp.get_ydata()) == [1.5, 1.25, 1.25, 1.0]
    assert list(pe.get_xdata()) == [10, 20] and list(pe.get_ydata()) == [-3.0, -3.5]
    assert axes[1].get_xlabel() == "Step"


def test_pdps_plot_writes_a_png_with_a_panel_per_column(pdps_cli, tmp_path, capsys):
    from pdps_core import cli
    from pdps_core.output import plot
    assert pdps_cli(FLUID + "run 10").returncode == 0
    capsys.readouterr()
    chosen = ["--columns", "temp", "Press", "-o", "t.png"]
    for argv, png, panels in [(["plot", "log.pdps.csv"], "log.pdps.csv.png", 5),
                              (["plot", "log.pdps", *chosen], "t.png", 2)]:
        assert cli.main(argv) == 0
        assert capsys.readouterr().out == png + "\n"
        height, width, _ = matplotlib.image.imread(tmp_path / png).shape
        assert (width, height) == (plot.WIDTH * plot.DPI,
                                   round((plot.PANEL_HEIGHT * panels + plot.MARGIN) * plot.DPI))


@pytest.mark.parametrize("argv, message", [
    (["plot", "log.pdps", "--columns", "bogus"],
     "ERROR: log.pdps: no column bogus (columns: Step, Temp, PotEng, KinEng, TotEng, Press)\n"),
    (["plot", "in.test"],
     "ERROR: in.test: no thermo table found (a header line followed by a line of numbers)\n"),
    (["plot", "nothing.csv"], "ERROR: cannot read nothing.csv: No such file or directory\n"),
])
def test_pdps_plot_bad_input_is_one_line(pdps_cli, capsys, argv, message):
    from pdps_core import cli
    pdps_cli(FLUID + "run 5")
    capsys.readouterr()
    assert cli.main(argv) == 1
    assert capsys.readouterr().err == message


# ---- progress -----------------------------------------------------------------------------------
def test_progress_text_and_clock():
    assert progress_text(4500, 0, 10000, 4.5) == (
        "progress:  45% (step 4500 of 10000), 1000 steps/s, 0:00:06 left")
    assert progress_text(1099, 100, 1100, 2.0).startswith("progress:  99% (step 1099 of 1100)")
    assert progress_text(100, 100, 1100, 0.0).endswith("0 steps/s, ? left")
    assert [clock_text(s) for s in (0, 59.4, 3661, 90061)] == ["0:00:00", "0:00:59", "1:01:01",
                                                               "1d 01:01:01"]


def test_plain_lines_every_further_10_percent_but_not_within_30_s():
    stream = io.StringIO()
    progress = Progress(stream=stream, clock=FakeClock(1.0), tty=False)
    progress.start(0, 1000)                   # the clock reads 0; each update reads 1 s later
    for step in range(1, 1001, 10):
        progress.update(step)
    text = stream.getvalue()
    assert "\r" not in text
    assert [int(p) for p in re.findall(r"(\d+)% ", text)] == [29, 59, 89]
    assert text.splitlines()[0] == "progress:  29% (step 291 of 1000), 9.7 steps/s, 0:01:13 left"


def test_plain_lines_at_least_every_10_minutes_when_marks_are_far_apart():
    stream = io.StringIO()
    progress = Progress(stream=stream, clock=FakeClock(100.0), tty=False)
    progress.start(0, 10000)
    for step in range(1, 30):                 # 2900 s for 0.3 % of the run
        progress.update(step)
    assert [line.split(",")[0] for line in stream.getvalue().splitlines()] == [
        "progress:   0% (step 6 of 10000)", "progress:   0% (step 12 of 10000)",
        "progress:   0% (step 18 of 10000)", "progress:   0% (step 24 of 10000)"]


def test_in_place_line_on_a_terminal_and_cleared_at_the_end():
    stream = io.StringIO()
    progress = Progress(stream=stream, clock=FakeClock(0.25), tty=True)
    progress.start(0, 20)
    for step in range(1, 4):                  # 0.25 .. 0.75 s: too early for a line
        progress.update(step)
    assert stream.getvalue() == ""
    for step in range(4, 20):
        progress.update(step)
    draws = stream.getvalue().split("\r")[1:]
    assert [int(re.search(r"step (\d+)", d).group(1)) for d in draws] == [4, 6, 8, 10, 12, 14, 16, 18]
    assert "\n" not in stream.getvalue()
    progress.update(20)                      # the last step: the line is wiped
    assert stream.getvalue().endswith("\r" + " " * len(draws[-1]) + "\r")


def test_screen_output_clears_the_line_and_the_log_never_sees_it(make_sim, monkeypatch, tmp_path):
    """Screen and progress share one stream, as on a terminal: a progress line is always wiped or
    redrawn (``\r``) before anything else is written, and never ends up in the log."""
    terminal = io.StringIO()
    monkeypatch.setattr(output_module, "Progress",
                        lambda: Progress(stream=terminal, clock=FakeClock(1.0), tty=True))
    sim = make_sim(screen=terminal, log="log.pdps")
    sim.command(FLUID + "thermo 4\nrun 12")
    text = terminal.getvalue()
    assert len(re.findall(r"\rprogress:", text)) >= 3
    assert not re.search(r"progress:[^\r]*(\n|$)", text)
    visible = [line.split("\r")[-1] for line in text.split("\n")]     # what a terminal shows
    assert [line.split()[0] for line in visible if re.match(r"\s+\d+\s", line)] == ["0", "4", "8", "12"]
    assert "progress" not in (tmp_path / "log.pdps").read_text()


def test_pdps_run_progress_goes_to_stderr_unless_turned_off(pdps_cli, monkeypatch):
    monkeypatch.setattr(output_module, "Progress", lambda: Progress(clock=FakeClock(10.0)))
    result = pdps_cli(FLUID + "run 20", "-log", "none")
    lines = result.stderr.splitlines()
    # the clock reads 0 at the start and 10 s later at each step from step 0 on
    assert [int(re.search(r"(\d+)%", line).group(1)) for line in lines] == [10, 25, 40, 55, 70, 85]
    assert lines[0] == "progress:  10% (step 2 of 20), 0.06667 steps/s, 0:04:30 left"
    assert "\r" not in result.stderr and "progress" not in result.stdout
    quiet = pdps_cli(FLUID + "run 20", "-log", "none", "--no-progress")
    assert (quiet.returncode, quiet.stderr) == (0, "")


def test_a_silent_simulation_has_no_progress(make_sim):
    assert make_sim(screen=False).output.progress is None


# ---- lattice spacings ---------------------------------------------------------------------------
@pytest.mark.parametrize("lattice, spacings", [
    # LAMMPS 22 Jul 2025 printed these for the same lines (%20.15g)
    ("lattice fcc 0.8442 orient x 1 1 0 orient y -1 1 0 orient z 0 0 1",
     (2.37530771316334, 2.37530771316334, 1.67959619138251)),
    ("lattice none 2.5", (2.5, 2.5, 2.5)),
    ("", (1.0, 1.0, 1.0)),                           # before any lattice command: none 1.0
])
def test_thermo_xlat_ylat_zlat_are_the_lattice_spacings(make_sim, lattice, spacings):
    screen = io.StringIO()
    sim = make_sim(dialect="lammps", screen=screen)
    sim.command(f"units lj\n{lattice}\nregion box block 0 2 0 2 0 2 units box\ncreate_box 1 box\nmass 1 1.0\n"
                "thermo_style custom step xlat ylat zlat\nrun 0")
    assert sim.output.thermo.values()[1:] == pytest.approx(spacings, rel=1e-14)
    assert "Step           Xlat           Ylat           Zlat" in screen.getvalue()
