"""kill -9 trials: ``pdps run`` writing a thermo line, a dump frame (text and custom) and a restart file
every step is killed with SIGKILL at a random moment; whatever it wrote must still be readable.

After each kill: the restart file (if one was written yet) reads back with read_restart; each dump
holds whole frames, steps 0, 1, 2, ... (a cut-off last frame at most); the log's thermo table and the
thermo CSV hold whole rows, steps 0, 1, 2, ... (a cut-off last line at most); and, since a step's
thermo line and dump frame are flushed before its restart file is written, the log, the CSV and the
dumps reach at least the restart's step. Nothing a run wrote is lost.

    PDPS_FUZZ_KILLS   number of trials (default 10; `make fuzz` runs 100), two at a time
"""

import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from pdps_core.simulation import Simulation

SCRIPT = """units lj
region box block 0 5 0 5 0 5
create_box 1 box
mass 1 1
lattice spacing x 0.625 y 0.625 z 0.625
create_particle 1 region box
pair_style dpd 1.0 1.0 9
pair_coeff * * 25.0 4.5
velocity all create 1.0 5 gaussian
fix 1 all nve
timestep 0.02
thermo 1
thermo_style custom step temp pe ke press
dump a all atom 1 d.atom
dump c all custom 1 d.custom id type x y z vx vy vz
restart 1 r.restart r.restart
run 100000000
"""
PARTICLES = 512


def trials():
    return int(os.environ.get("PDPS_FUZZ_KILLS", "10"))


def dump_frames(text, columns):
    """Steps of the whole frames of a LAMMPS text dump; a cut-off last frame is left out, anything
    else that is not a whole frame is an error."""
    lines, steps, k = text.split("\n"), [], 0
    while k < len(lines) and lines[k] == "ITEM: TIMESTEP":
        end = k + 9 + PARTICLES
        if end >= len(lines):                   # the last frame, cut off (its last row has no \n)
            break
        assert lines[k + 3] == str(PARTICLES) and lines[k + 8].startswith("ITEM: ATOMS")
        rows = np.array([line.split() for line in lines[k + 9:end]], dtype=float)
        assert rows.shape == (PARTICLES, columns) and np.isfinite(rows).all()
        steps.append(int(lines[k + 1]))
        k = end
    rest = "\n".join(lines[k:])
    assert "ITEM: TIMESTEP" not in rest[1:], "a frame is broken before the last one"
    return steps


def table_steps(rows, width):
    """Steps of the complete rows (``width`` numbers each); only the last row may be cut off."""
    steps = []
    for number, row in enumerate(rows):
        try:
            values = [float(v) for v in row]
        except ValueError:
            values = None
        if values is None or len(values) != width:
            assert number == len(rows) - 1, f"row {number} of {len(rows)} is broken: {row}"
            break
        assert all(np.isfinite(values))
        steps.append(int(values[0]))
    return steps


def check_outputs(folder):
    """What a killed run left in ``folder``: {output: last complete step}."""
    last = {}
    log = (folder / "log.pdps").read_text()
    lines = log.split("\n")
    header = next(k for k, line in enumerate(lines) if line.split()[:1] == ["Step"])
    rows = [line.split() for line in lines[header + 1:]]
    complete = log.endswith("\n")
    rows = rows[:-1] if complete else rows              # split leaves "" after a final \n
    steps = table_steps(rows, 5)
    assert steps == list(range(len(steps)))
    last["log"] = steps[-1] if steps else -1
    csv = (folder / "log.pdps.csv").read_text().split("\n")
    assert csv[0] == "Step,Temp,PotEng,KinEng,Press"
    rows = [line.split(",") for line in csv[1:]]
    rows = rows[:-1] if csv[-1] == "" else rows
    steps = table_steps(rows, 5)
    assert steps == list(range(len(steps)))
    last["csv"] = steps[-1] if steps else -1
    for name, columns in (("d.atom", 5), ("d.custom", 8)):
        steps = dump_frames((folder / name).read_text(), columns)
        assert steps == list(range(len(steps)))
        last[name] = steps[-1] if steps else -1
    restart = folder / "r.restart"
    if restart.exists():
        sim = Simulation(screen=False, log=None).command(f"read_restart {restart}")
        assert sim.nlocal == PARTICLES and np.isfinite(sim.x).all()
        last["restart"] = sim.step
    return last


def start(folder):
    folder.mkdir()
    (folder / "in.kill").write_text(SCRIPT)
    return subprocess.Popen([sys.executable, "-m", "pdps_core.cli", "run", "in.kill", "--no-progress"],
                            cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def test_outputs_survive_kill_9_at_random_moments(tmp_path):
    rng = np.random.default_rng(99)
    n = trials()
    outcomes = []
    for first in range(0, n, 2):
        batch = [(tmp_path / f"trial-{k:03d}", None) for k in range(first, min(first + 2, n))]
        batch = [(folder, start(folder)) for folder, _ in batch]
        for folder, process in batch:
            try:
                for _ in range(1200):       # until the run is stepping (at most 2 minutes)
                    if (folder / "r.restart").exists() or process.poll() is not None:
                        break
                    time.sleep(0.05)
                time.sleep(rng.uniform(0.0, 0.5))
                process.send_signal(signal.SIGKILL)
            finally:
                process.wait(timeout=120)
            assert process.returncode == -signal.SIGKILL, process.stderr.read().decode()
            last = check_outputs(folder)
            outcomes.append(last)
            assert min(last["log"], last["csv"], last["d.atom"], last["d.custom"]) >= last["restart"], last
    assert len(outcomes) == n
    steps = sorted(o["restart"] for o in outcomes)
    lost = sum(min(o["log"], o["csv"], o["d.atom"], o["d.custom"]) < o["restart"] for o in outcomes)
    line = (f"kill -9 trials: {n}, killed at steps {steps[0]}..{steps[-1]} (the restart's step); "
            f"every restart read back, every log, CSV and dump whole up to its last line or frame, "
            f"{lost} outputs behind their restart")
    report = os.environ.get("PDPS_FUZZ_REPORT")
    if report:
        with open(report, "a") as handle:
            handle.write(f"\n{line}\n")


def _frame(step, columns):
    rows = [" ".join(["1"] + ["0.5"] * (columns - 1))] * PARTICLES
    return "\n".join(["ITEM: TIMESTEP", str(step), "ITEM: NUMBER OF ATOMS", str(PARTICLES),
                      "ITEM: BOX BOUNDS pp pp pp", "0 5", "0 5", "0 5", "ITEM: ATOMS id x y z"]
                     + rows) + "\n"


def test_the_checks_accept_a_cut_off_last_row_or_frame_and_nothing_worse():
    """What a kill can leave (a cut-off last row or frame) passes the checks above; a row or frame
    broken before the last does not."""
    rows = [["0", "1", "2", "3", "4"], ["1", "1", "2", "3", "4"], ["2", "1.5"]]
    assert table_steps(rows, 5) == [0, 1]
    with pytest.raises(AssertionError, match="row 1 of 3 is broken"):
        table_steps([rows[0], rows[2], rows[1]], 5)
    text = _frame(0, 5) + _frame(1, 5) + _frame(2, 5)
    assert dump_frames(text, 5) == [0, 1, 2]
    assert dump_frames(text[:-40], 5) == [0, 1]
    broken = _frame(0, 5) + _frame(1, 5)[:-300] + "\n" + _frame(2, 5)
    with pytest.raises((AssertionError, ValueError)):
        dump_frames(broken, 5)
