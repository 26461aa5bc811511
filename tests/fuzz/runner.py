"""Runs fuzz cases in parallel worker processes (worker.py), each importing pdps once.

A case runs in-process in a worker (``classify.run_case``), which interrupts it at the time limit, in
CPU seconds of the worker (classify.Watchdog), so that other work on the machine cannot turn a sound
case into a hang. A worker that has used the limit plus a grace period of CPU time without answering
(or idled through that long on the clock, classify.IDLE) is stuck where it cannot be interrupted
(compiled code holding the interpreter lock): it is asked for its Python stack (SIGUSR1,
faulthandler), killed, and the case is a ``hang``. A worker that dies by itself (segmentation fault,
abort, exit) makes its case a ``signal``. Either way a fresh worker takes its place. Workers are also
replaced every ``recycle`` cases, so one case's leftovers (module state, memory) stay bounded.
"""

import json
import os
import selectors
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from .classify import ACCEPTED, BIG, STATUS, idle

WORKER = Path(__file__).with_name("worker.py")


@dataclass
class Case:
    """An input script and the files it reads; ``mutations`` say how they were made from a seed."""
    kind: str                     # scripts, data, restarts
    index: int
    seed: str
    mutations: list
    files: dict                   # name -> bytes
    script: str = "in.fuzz"

    @property
    def name(self):
        return f"{self.kind}-{self.index:06d}"


@dataclass
class Result:
    case: Case
    klass: str
    reply: dict = field(default_factory=dict)
    folder: Path = None
    seconds: float = 0.0


class _Worker:
    def __init__(self, folder, number, env):
        self.log_path = Path(folder) / f"worker-{number}.stderr"
        self.log = open(self.log_path, "ab")
        self.process = subprocess.Popen([sys.executable, str(WORKER)], stdin=subprocess.PIPE,
                                        stdout=subprocess.PIPE, stderr=self.log, cwd="/",
                                        env={**os.environ, **(env or {})})
        self.done = 0
        self.case = None
        self.started = None
        self.deadline = None        # when the limit plus grace has passed on the clock
        self.cpu_started = None
        self.cpu_limit = None
        self.clock = []             # (wall, CPU seconds) the runner saw, for idleness
        self.ready = False

    def send(self, case, folder, limit, grace):
        request = {"dir": str(folder), "script": case.script, "inputs": sorted(case.files),
                   "limit": limit}
        self.case, self.folder = case, folder
        self.started = time.monotonic()
        self.deadline = self.started + limit + grace
        self.cpu_started, self.cpu_limit = self.cpu_seconds(), limit + grace
        self.clock = [(self.started, self.cpu_started)]
        self.process.stdin.write((json.dumps(request) + "\n").encode())
        self.process.stdin.flush()

    def cpu_seconds(self):
        """CPU time the worker process has used (user + system, from /proc), or None where the
        system does not say."""
        try:
            with open(f"/proc/{self.process.pid}/stat") as handle:
                fields = handle.read().rsplit(")", 1)[1].split()
        except (OSError, IndexError):
            return None
        return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")

    def over(self, now):
        """The limit's reason when the current case has run past it (CPU time, or the limit on the
        clock with the CPU idle), else None."""
        cpu = self.cpu_seconds() if self.cpu_started is not None else None
        if cpu is None:                     # no /proc: the clock alone
            return f"{self.cpu_limit:g} s" if now > self.deadline else None
        self.clock.append((now, cpu))
        if cpu - self.cpu_started > self.cpu_limit:
            return f"{self.cpu_limit:g} s of CPU time"
        if now > self.deadline and idle(self.clock, now, cpu, self.cpu_limit):
            return f"{self.cpu_limit:g} s with the CPU idle"
        return None

    def stack(self):
        """What faulthandler wrote for the current case (the stack at a fatal signal or SIGUSR1)."""
        self.log.flush()
        try:
            text = self.log_path.read_text(errors="replace")
        except OSError:
            return ""
        marker = f"=== case {self.folder}"
        return text[text.rfind(marker) + len(marker):].strip()[-6000:] if marker in text else ""

    def kill(self):
        if self.process.poll() is None:
            self.process.kill()
        self.process.wait()
        self.log.close()


def _particles(folder):
    """How many particles the case held when its watchdog last looked (classify.STATUS)."""
    try:
        return json.loads((Path(folder) / STATUS).read_text())["particles"]
    except (OSError, ValueError, KeyError):
        return None


def run_cases(cases, root, *, workers=2, limit=10.0, grace=5.0, recycle=400, keep=None,
              on_result=None, env=None):
    """Run every case of the iterable ``cases`` (each in a folder of its own under ``root``, taken
    from the iterable only when a worker is free); returns their Results in the order they ended.
    The folders of accepted cases are removed unless ``keep`` says to keep them (kept: failures);
    ``on_result`` sees each Result as it ends."""
    root = Path(root)
    root.mkdir(parents=True, exist_ok=True)
    results = []
    source = iter(cases)
    pending = [next(source, None)]            # the next case, drawn ahead; None: no more

    def take():
        case, pending[0] = pending[0], next(source, None)
        return case

    selector = selectors.DefaultSelector()
    pool = []
    started = 0

    def start():
        nonlocal started
        worker = _Worker(root, started, env)
        started += 1
        selector.register(worker.process.stdout, selectors.EVENT_READ, worker)
        pool.append(worker)

    def retire(worker):
        selector.unregister(worker.process.stdout)
        pool.remove(worker)
        worker.kill()

    def finish(worker, klass, reply):
        case, folder = worker.case, worker.folder
        result = Result(case, klass, reply, folder, time.monotonic() - worker.started)
        results.append(result)
        worker.case = None
        worker.done += 1
        if klass in ACCEPTED and not (keep and keep(result)):
            shutil.rmtree(folder, ignore_errors=True)
        if on_result is not None:
            on_result(result)

    for _ in range(workers):
        start()
    try:
        while pending[0] is not None or any(w.case is not None for w in pool):
            for worker in list(pool):
                if worker.ready and worker.case is None:
                    if worker.done >= recycle and pending[0] is not None:
                        retire(worker)
                        start()
                    elif pending[0] is not None:
                        case = take()
                        folder = root / case.name
                        shutil.rmtree(folder, ignore_errors=True)
                        folder.mkdir(parents=True)
                        for name, data in case.files.items():
                            (folder / name).write_bytes(data)
                        worker.send(case, folder, limit, grace)
            busy = any(w.case is not None for w in pool)
            timeout = 0.5 if busy else 1.0          # CPU time is looked at twice a second
            for key, _ in selector.select(timeout=timeout):
                worker = key.data
                line = worker.process.stdout.readline()
                if not line:                                  # the worker died
                    code = worker.process.wait()
                    stack = worker.stack()
                    retire(worker)
                    if not worker.ready:
                        raise RuntimeError(f"a fuzz worker failed to start (exit status {code}): "
                                           f"{worker.log_path.read_text(errors='replace')[-3000:]}")
                    if worker.case is not None:
                        name = signal.Signals(-code).name if code < 0 else f"exit status {code}"
                        finish(worker, "signal", {"code": code, "stderr": "", "stdout": "",
                                                  "traceback": stack, "detail": name})
                    if pending[0] is not None:
                        start()
                    continue
                reply = json.loads(line)
                if "ready" in reply:
                    worker.ready = True
                    continue
                finish(worker, reply["class"], reply)
            now = time.monotonic()
            for worker in list(pool):
                reason = worker.over(now) if worker.case is not None else None
                if reason is not None:
                    worker.process.send_signal(signal.SIGUSR1)       # faulthandler: the stack
                    time.sleep(0.3)
                    stack = worker.stack()
                    retire(worker)
                    particles = _particles(worker.folder)
                    klass = "long" if particles is not None and particles >= BIG else "hang"
                    finish(worker, klass, {"code": None, "stderr": "", "stdout": "",
                                           "traceback": stack,
                                           "detail": f"no answer within {reason}, {particles} particles"})
                    if pending[0] is not None:
                        start()
    finally:
        for worker in list(pool):
            retire(worker)
        selector.close()
    return results
