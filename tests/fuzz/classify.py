"""Runs one fuzz case in this process and says what became of it.

A case is a folder holding an input script and the files it reads. It runs as ``pdps run SCRIPT
-log log.pdps --no-progress`` does (``pdps_core.cli.main``), with the screen and stderr captured, and
ends in one of these classes:

    clean      exit 0, and no nan or inf in any number the run wrote (thermo on the screen and in the
               log, the thermo CSV, dumps, analysis files, VTK frames)
    error      exit 1 and stderr is exactly one line ``ERROR: FILE:LINE: ...`` naming one of the
               case's files (the script, an included script, the data or restart file)
    long       still running at the time limit, either advancing step by step toward an end step
               that a 64-bit counter can hold (``run 2000000`` on a small box is a valid script, and
               so is a loop of a hundred thousand short runs), or
               holding more than BIG particles (40 times the largest seed: a big system may take
               longer than the limit to set up); reported, not failed
    traceback  a Python exception other than the script errors reached the user ("internal error"),
               or a traceback was printed
    hang       over the time limit with fewer than BIG particles, without advancing (or toward an
               end step beyond 64 bits: ``run 99999999999999999999`` must be refused, not run)
    signal     the process died (segmentation fault, abort, kill); set by runner.py
    nonfinite  exit 0 with nan or inf in the output
    messy      exit 1, but stderr is not one located ERROR line (several lines, raw warnings, no
               FILE:LINE)

``clean``, ``error`` and ``long`` are accepted; every other class fails the fuzz tests.
"""

import contextlib
import io
import json
import math
import os
import re
import sys
import threading
import time
import traceback
import warnings

ACCEPTED = ("clean", "error", "long")
FAILING = ("traceback", "hang", "signal", "nonfinite", "messy")
CLASSES = ACCEPTED + FAILING
LARGEST_STEP = 2**63 - 1
BIG = 20_000
STATUS = "watchdog.json"        # what the watchdog saw last, for runner.py when it has to kill
LOCATED = re.compile(r"ERROR: (?P<file>[^\n]+?):(?P<line>\d+): ")


class _State:
    sim = None               # the Simulation of the running case
    traceback = None         # the traceback behind an "internal error" line
    recorded = None          # the particle count last written to STATUS


STATE = _State()


def prepare():
    """Import pdps, follow the Simulation a case creates, and keep the traceback that the command
    line turns into its one "internal error" line (the fuzz reports show where it came from)."""
    from pdps_core import cli, simulation
    from pdps_core.errors import ScriptError
    from pdps_core.script.interpreter import Script
    import pdps_core.commands  # noqa: F401  (the command table, for telling log files apart)

    created = simulation.Simulation.__init__

    def tracked(self, *args, **kwargs):
        STATE.sim = self
        created(self, *args, **kwargs)

    simulation.Simulation.__init__ = tracked
    # every command, a script's line or a typed call, goes through the script's execute
    execute = Script.execute

    def counted(self, words):
        try:
            return execute(self, words)
        finally:
            record_particles(self.sim)

    Script.execute = counted
    fail = cli._fail

    def recording_fail(sim, message, debug, alone=False):
        exc = sys.exc_info()[1]
        if exc is not None and not isinstance(exc, (ScriptError, KeyboardInterrupt)):
            STATE.traceback = traceback.format_exc()
        return fail(sim, message, debug, alone)

    cli._fail = recording_fail


# A case's limit is CPU time of its worker, so that a machine busy with other work slows a case down
# without making it fail. A case that used less than IDLE of the CPU over the last ``limit`` seconds
# on the clock is waiting (asleep, blocked), which a sound run never does; a busy machine still gives
# a running case many times that (two workers and two other CPU-bound processes on two cores: 50 %).
IDLE = 0.05


def idle(samples, now, cpu, span):
    """Whether (wall, cpu) ``samples`` show less than IDLE of ``span`` seconds used before ``now``."""
    earlier = [c for t, c in samples if t <= now - span]
    return bool(earlier) and cpu - earlier[-1] < IDLE * span


class Watchdog(threading.Thread):
    """Interrupts the case once it has used ``limit`` seconds of CPU time, or waited ``limit``
    seconds on the clock with the CPU idle, deciding first whether it is a long run (the step
    counter still advancing toward a representable end) or a hang. A case stuck in compiled code
    that holds the interpreter lock never lets this thread run: runner.py kills it (a hang)."""

    def __init__(self, limit):
        super().__init__(daemon=True)
        self.limit = limit
        self.done = threading.Event()
        self.verdict = None
        self.where = None
        self.main = threading.main_thread().ident
        self.lock = threading.Lock()
        self.running = True

    def run(self):
        cpu_start = time.process_time()
        samples, clock = [], [(time.monotonic(), 0.0)]
        while not self.done.wait(0.2):
            now, cpu = time.monotonic(), time.process_time() - cpu_start
            clock.append((now, cpu))
            sim = STATE.sim
            samples.append((now, cpu, getattr(sim, "step", None)))
            record_particles(sim)
            if cpu < self.limit and not idle(clock, now, cpu, self.limit):
                continue
            # advancing over the last 1.5 s of CPU time (on a busy machine as many steps as on an
            # idle one) and over the last half of the limit's span on the clock: the idle test fires
            # when the case has waited nearly the whole span, so the whole span can still hold the
            # last step it made before it stopped (a hang then read as a long run)
            by_cpu = [step for _, t, step in samples if t >= cpu - 1.5 and step is not None]
            by_clock = [step for t, _, step in samples if t >= now - 0.5 * self.limit and step is not None]
            last = getattr(sim, "run_last_step", None)
            # across runs too: a loop of short runs (``variable i loop 100000`` ... ``jump``) advances
            stepping = all(len(r) >= 2 and r[-1] > r[0] for r in (by_cpu, by_clock))
            representable = last is not None and last <= LARGEST_STEP
            big = (particle_count(sim) or 0) >= BIG
            self.verdict = "long" if (stepping and representable) or big else "hang"
            frame = sys._current_frames().get(self.main)
            stack = "".join(traceback.format_stack(frame)) if frame is not None else ""
            self.where = {"source": sim.script.source, "line": sim.script.line,
                          "step": getattr(sim, "step", None), "last_step": str(last),
                          "particles": particle_count(sim),
                          "stack": stack[-4000:]}
            with self.lock:
                if self.running:
                    import _thread
                    _thread.interrupt_main()
            return

    def stop(self):
        """No interrupt after this returns; one already sent arrives at the next Python call."""
        with self.lock:
            self.running = False
        _pending_interrupt_lands_here()


def particle_count(sim):
    try:
        return int(sim.particles.nlocal)
    except Exception:                                    # noqa: BLE001  (no simulation, or half made)
        return None


def record_particles(sim):
    """Write the case's particle count to STATUS when it changed: after every command (so it is
    there before a run that may never let the watchdog look again) and at each watchdog sample."""
    count = particle_count(sim)
    if count is not None and count != STATE.recorded:
        STATE.recorded = count
        with open(STATUS, "w") as handle:
            json.dump({"particles": count}, handle)


def run_case(folder, script, inputs, limit):
    """Run ``script`` in ``folder`` (its input files named in ``inputs``) and classify the result:
    a dict with the class, the exit code, the captured screen and stderr (trimmed) and details."""
    from pdps_core import cli
    import numpy as np
    os.chdir(folder)
    STATE.sim, STATE.traceback, STATE.recorded = None, None, None
    out, err = io.StringIO(), io.StringIO()
    watchdog = Watchdog(limit)
    code, escaped = None, None
    numpy_errors = np.geterr()
    watchdog.start()
    try:
        # catch_warnings: each case shows its warnings as a fresh process would, and leaves no filter
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), warnings.catch_warnings():
            try:
                code = cli.main(["run", script, "-log", "log.pdps", "--no-progress"])
            except SystemExit as exc:
                code = exc.code if isinstance(exc.code, int) else 1
            except KeyboardInterrupt:
                code = 1
            except BaseException:                      # noqa: BLE001  (what the user would see)
                escaped = traceback.format_exc()
                code = 1
            watchdog.stop()
    except KeyboardInterrupt:                          # the watchdog's, after cli.main returned
        code = 1 if code is None else code
    finally:
        watchdog.done.set()
        try:
            watchdog.stop()
        except KeyboardInterrupt:                      # it fired once, and only once
            pass
    watchdog.join()
    np.seterr(**numpy_errors)
    sim, STATE.sim = STATE.sim, None
    if sim is not None:
        with contextlib.suppress(BaseException):
            sim.close()
    os.chdir("/")
    stdout, stderr = out.getvalue(), err.getvalue()
    reply = {"class": None, "code": code, "stdout": stdout[-3000:], "stderr": stderr[:4000],
             "traceback": escaped or STATE.traceback, "detail": None}
    if watchdog.verdict is not None:
        reply["class"], reply["detail"] = watchdog.verdict, watchdog.where
        return reply
    if escaped:
        reply["class"] = "traceback"
    elif code == 0:
        found = nonfinite_output(folder, inputs, stdout)
        reply["class"] = "nonfinite" if found else "clean"
        reply["detail"] = found
    elif STATE.traceback or "internal error" in stderr or "Traceback" in stderr:
        reply["class"] = "traceback"
    else:
        reply["class"] = "error" if located(stderr, inputs) else "messy"
    return reply


def _pending_interrupt_lands_here():
    return None


def located(stderr, inputs):
    """True for exactly one line ``ERROR: FILE:LINE: ...`` where FILE is one of the case's files."""
    lines = stderr.splitlines()
    if len(lines) != 1:
        return False
    match = LOCATED.match(lines[0])
    return bool(match) and os.path.basename(match["file"]) in inputs


# ---- non-finite numbers in what a run wrote ---------------------------------------------------------
def _numbers(words):
    """The words as floats, or None when one is not a number."""
    try:
        return [float(w) for w in words]
    except ValueError:
        return None


def _bad(values):
    return values is not None and not all(math.isfinite(v) for v in values)


def thermo_table_rows(lines):
    """(line number, words) of each row of each thermo table: the numeric lines after a header
    whose first word is Step."""
    inside = False
    for number, line in enumerate(lines, 1):
        words = line.split()
        if words and words[0] == "Step":
            inside = True
            continue
        if inside:
            if words and _numbers(words) is not None:
                yield number, words
            else:
                inside = False


def _scan_text(name, text, commands):
    lines = text.splitlines()
    if not lines:
        return None
    if name.endswith(".csv") or ("," in lines[0] and lines[0].startswith("Step")):
        header = lines[0].split(",")
        for number, line in enumerate(lines[1:], 2):
            values = _numbers(line.split(","))
            if _bad(values):
                column = next(h for h, v in zip(header, values) if not math.isfinite(v))
                return f"{name}:{number}: column {column}: {line[:200]}"
        return None
    if any(line.split()[:1] and line.split()[0] in commands for line in lines[:200]):
        rows = thermo_table_rows(lines)                  # a log: its echoed lines are script text
    else:                                                # dumps, analysis files, XDMF text
        rows = ((n, line.split()) for n, line in enumerate(lines, 1)
                if line.split() and not line.lstrip().startswith("#"))
    for number, words in rows:
        if _bad(_numbers(words)):
            return f"{name}:{number}: {' '.join(words)[:200]}"
    return None


def _scan_vtu(path, name):
    import meshio
    import numpy as np
    try:
        mesh = meshio.read(path)
    except Exception:                                    # noqa: BLE001  (a cut-off frame is no number)
        return None
    arrays = {"points": mesh.points, **mesh.point_data}
    for key, values in arrays.items():
        values = np.asarray(values)
        if values.dtype.kind == "f" and not np.isfinite(values).all():
            return f"{name}: {key} holds non-finite values"
    return None


def nonfinite_output(folder, inputs, stdout):
    """Where the first nan or inf of a run's numeric output is (``FILE:LINE: text``), or None."""
    from pdps_core.commands import COMMANDS
    found = _scan_text("<screen>", stdout, COMMANDS)
    if found:
        return found
    for root, _, files in os.walk(folder):
        for name in sorted(files):
            path = os.path.join(root, name)
            relative = os.path.relpath(path, folder)
            if relative in inputs or name == STATUS or os.path.getsize(path) > 50_000_000:
                continue
            if name.endswith(".vtu"):
                found = _scan_vtu(path, relative)
            else:
                with open(path, "rb") as handle:
                    data = handle.read()
                if b"\0" in data[:4096]:                 # binary (restart files, HDF5)
                    continue
                found = _scan_text(relative, data.decode("utf-8", "replace"), COMMANDS)
            if found:
                return found
    return None
