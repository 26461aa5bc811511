"""Fuzzing (issue 10): no input may crash pdps, hang it, trace back, or run on to nan with exit 0.

Hypothesis, with a fixed seed, draws mutated scripts, data files and restart files from the seeds
of corpus.py (mutate.py says how); the cases then run in parallel worker processes (runner.py), each
classified by classify.py as clean, error (one located line), long, traceback, hang, signal,
nonfinite or messy. A test fails when its kind of case met any class but the first three; its
message groups the failures by where they come from and shows one reproducer of each in full.

    PDPS_FUZZ_CASES     total number of cases (default 2,800: 2,000 scripts, 500 data files, 300
                        restart files; other totals keep those proportions); `make fuzz` runs 100,000
    PDPS_FUZZ_WORKERS   worker processes (default: the number of cores)
    PDPS_FUZZ_MPI       how many of the cases that ended in an error are run again under mpiexec -n 2
                        (default 8), where they must end in one located error line as well
    PDPS_FUZZ_LIMIT     CPU seconds a case may use before it is interrupted (default 10: a kernel
                        compiled for a new pair formula takes a few)
    PDPS_FUZZ_REPORT    a Markdown file to append the summary and the distinct failures to; the
                        failing cases' folders are copied beside it (REPORT-cases/)

A failing case is rerun by hand from its folder (kept under pytest's temporary folder, named in the
message): ``pdps run in.fuzz --debug``.
"""

import hashlib
import os
import re
import shutil
import time
from collections import Counter, defaultdict
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, given, seed, settings

from . import corpus, mutate
from .classify import ACCEPTED, CLASSES
from .runner import Case, run_cases
from .test_mpi_errors import one_located_line, run_parallel

DEFAULT_COUNTS = {"scripts": 2000, "data": 500, "restarts": 300}
HYPOTHESIS_SEED = 20240610
CHUNK = 2000
PROJECT = corpus.PROJECT
SEED_LIMIT = 300.0          # the unmutated seeds run first, compiling what numba has not cached


def counts():
    total = os.environ.get("PDPS_FUZZ_CASES")
    if not total:
        return dict(DEFAULT_COUNTS)
    scale = int(total) / sum(DEFAULT_COUNTS.values())
    return {kind: max(1, round(n * scale)) for kind, n in DEFAULT_COUNTS.items()}


def mpi_sample():
    return int(os.environ.get("PDPS_FUZZ_MPI", "8"))


def draw_cases(kind, strategy, count, start, seen, first=0):
    """``count`` cases drawn by hypothesis from ``strategy`` with the seed ``start`` (fixed: the same
    cases on every run of the same corpus), none drawn before (``seen``: their hashes); their
    indices from ``first``."""
    cases = []
    for attempt in range(10):
        if len(cases) >= count:
            break

        @settings(max_examples=int(1.1 * (count - len(cases))) + 20, database=None, deadline=None,
                  phases=[Phase.generate], suppress_health_check=list(HealthCheck))
        @seed(start + attempt)
        @given(strategy)
        def collect(drawn):
            if len(cases) >= count:
                return
            origin, files, mutations = drawn
            key = hashlib.sha256(b"".join(n.encode() + b"\0" + d + b"\0"
                                          for n, d in sorted(files.items()))).digest()
            if key not in seen:
                seen.add(key)
                cases.append(Case(kind, first + len(cases), origin.name, mutations, files,
                                  origin.script))

        collect()
    assert len(cases) == count, f"hypothesis drew {len(cases)} distinct {kind} cases of {count}"
    return cases


def drawn_cases(plan):
    """The cases of ``plan`` ([(kind, strategy, count)]), drawn CHUNK at a time as the workers need
    them, so that 100,000 cases (restart files of 100 kB among them) never sit in memory at once."""
    seen = set()
    for kind, strategy, count in plan:
        for k, first in enumerate(range(0, count, CHUNK)):
            yield from draw_cases(kind, strategy, min(CHUNK, count - first),
                                  HYPOTHESIS_SEED + 100 * k, seen, first)


def compact(result):
    """What the summary needs of an accepted case; its files and screen go (failures keep all)."""
    result.case.files = None
    stderr = result.reply.get("stderr") or ""
    result.reply = {"class": result.klass, "stderr": stderr.strip().split("\n")[0][:300]}


def _reporter(config):
    return config.pluginmanager.get_plugin("terminalreporter")


@pytest.fixture(scope="module")
def fuzz(tmp_path_factory, request):
    """Runs every case once for the module: {kind: [Result]}, plus the seeds' own results."""
    root = tmp_path_factory.mktemp("fuzz")
    workers = int(os.environ.get("PDPS_FUZZ_WORKERS") or os.cpu_count() or 2)
    limit = float(os.environ.get("PDPS_FUZZ_LIMIT", "10"))
    started = time.monotonic()

    scripts = corpus.script_seeds()
    writers = corpus.restart_writers()
    data_seeds = corpus.data_seeds(root / "data-seeds")
    unmutated = [Case("seed", k, s.name, [], s.files) for k, s in enumerate(scripts)]
    unmutated += [Case("writer", k, s.name, [], s.files) for k, s in enumerate(writers)]
    # the data seeds too: their scripts compile kernels no script seed reaches (rigid/small on spheres),
    # which on a fresh clone would otherwise be compiled inside a mutated case's time limit
    unmutated += [Case("seed", len(scripts) + k, s.name, [], s.files) for k, s in enumerate(data_seeds)]
    ran = run_cases(unmutated, root / "seeds", workers=workers, limit=SEED_LIMIT,
                    keep=lambda r: r.case.kind == "writer")
    written = {}
    for result in ran:
        if result.case.kind == "writer":
            restart = result.folder / corpus.RESTART
            assert result.klass == "clean" and restart.exists(), \
                f"seed {result.case.seed} did not write its restart file: {result.reply}"
            written[result.case.seed] = (result.case.files, restart.read_bytes())

    context = corpus.script_context(scripts)
    wanted = counts()
    restart_seeds = corpus.restart_seeds(written)
    plan = [("scripts", mutate.script_case(scripts, context), wanted["scripts"]),
            ("data", mutate.data_case(data_seeds, context), wanted["data"]),
            ("restarts", mutate.restart_case(restart_seeds, context), wanted["restarts"])]
    seeded = time.monotonic()
    total, done = sum(wanted.values()), Counter()
    # one case in every stride is kept when it ends in an error, for the MPI reruns
    stride = max(1, total // (4 * mpi_sample()))

    def sampled(result):
        return result.klass == "error" and result.case.index % stride == 0

    def progress(result):
        if result.klass in ACCEPTED and not sampled(result):
            compact(result)
        done[result.klass] += 1
        n = sum(done.values())
        if total >= 5000 and (n % 2000 == 0 or n == total):
            rate = n / (time.monotonic() - seeded)
            classes = ", ".join(f"{k} {v}" for k, v in sorted(done.items()))
            line = f"fuzz: {n}/{total} cases ({rate:.1f}/s): {classes}"
            if reporter is not None:
                reporter.write_line(line)
                reporter.flush()

    reporter = _reporter(request.config)
    results = run_cases(drawn_cases(plan), root / "cases", workers=workers, limit=limit,
                        on_result=progress, keep=sampled)
    seconds = time.monotonic() - started
    by_kind = defaultdict(list)
    for result in sorted(results, key=lambda r: r.case.index):
        by_kind[result.case.kind].append(result)
    summary = summarize(by_kind, seconds, seeded - started, workers, limit)
    if reporter is not None:
        for line in summary.splitlines():
            reporter.write_line(line)
    report = os.environ.get("PDPS_FUZZ_REPORT")
    if report:
        write_report(Path(report), summary, by_kind)
    mpi = [r for r in results if sampled(r)]
    mpi = [mpi[round(k * len(mpi) / mpi_sample())] for k in range(min(mpi_sample(), len(mpi)))]
    return {"seeds": ran, "mpi": mpi, **by_kind}


def summarize(by_kind, seconds, setup, workers, limit):
    lines = [f"fuzz: {sum(len(r) for r in by_kind.values())} cases in {seconds:.0f} s "
             f"({setup:.0f} s of running the seeds; {workers} workers, {limit:g} CPU s per case)"]
    for kind, results in by_kind.items():
        count = Counter(r.klass for r in results)
        classes = ", ".join(f"{k} {count[k]}" for k in CLASSES if count[k])
        lines.append(f"fuzz {kind}: {len(results)} cases: {classes}")
    if mutate.SKIPPED:
        lines.append("mutations that could not apply to what earlier ones left (skipped): "
                     + ", ".join(f"{k} {n}" for k, n in mutate.SKIPPED.most_common()))
    return "\n".join(lines)


# ---- failures: grouped by where they come from --------------------------------------------------------
def _normalize(text):
    text = re.sub(r"0x[0-9a-f]+", "0x?", text)
    text = re.sub(r"[-+]?\d+(\.\d*)?([eE][-+]?\d+)?", "N", text)
    return re.sub(r"'[^']*'|\"[^\"]*\"", "'?'", text)[:160]


def _project_frames(text):
    """(file, line, function) of each frame of a Python traceback or faulthandler dump that is in
    the project (tests/fuzz excluded), innermost last."""
    frames = []
    for match in re.finditer(r'File "([^"]+)", line (\d+),? in (\S+)', text or ""):
        path, line, function = match.groups()
        try:
            relative = Path(path).resolve().relative_to(PROJECT)
        except ValueError:
            continue
        if relative.parts[:2] != ("tests", "fuzz") and relative.parts[0] not in (".venv", "build"):
            frames.append((str(relative), int(line), function))
    return frames


def _main_thread(dump):
    """The faulthandler block of the thread running the case, innermost frame first."""
    blocks = re.split(r"\n(?=(?:Current thread|Thread) 0x)", dump or "")
    for block in blocks:
        if "run_case" in block:
            return "\n".join(reversed(block.splitlines()))     # innermost last, as tracebacks
    return dump or ""


def signature(result):
    """What a failure is, independent of the particular numbers: class, exception and place."""
    reply, klass = result.reply, result.klass
    if klass == "traceback":
        text = reply.get("traceback") or ""
        if text:
            # the last "Type: message" line (numba's errors end in notes, not in that line)
            named = re.findall(r"^([A-Za-z_][\w.]*(?:Error|Exception|Exit))\b", text, re.M)
            exception = named[-1] if named else text.strip().splitlines()[-1].split(":")[0]
        else:
            found = re.search(r"internal error(?: at \S+)?: (\w+)", reply.get("stderr") or "")
            exception = found[1] if found else _normalize((reply.get("stderr") or "?")[:80])
        frames = _project_frames(text)
        where = f"{frames[-1][0]}:{frames[-1][2]}" if frames else "?"
        return f"traceback {exception} in {where}"
    if klass in ("hang", "signal"):
        detail = reply.get("detail")
        stack = detail.get("stack") if isinstance(detail, dict) else _main_thread(reply.get("traceback"))
        frames = _project_frames(stack)
        where = f"{frames[-1][0]}:{frames[-1][2]}" if frames else "?"
        what = reply.get("detail") if klass == "signal" else "hang"
        return f"{what} in {where}"
    if klass == "nonfinite":
        detail = reply.get("detail") or ""
        name = detail.split(":")[0]
        column = re.search(r"column (\S+)", detail)
        kind = "screen" if name == "<screen>" else "csv" if name.endswith(".csv") else \
            "log" if "log" in name else "dump" if name.startswith("dump") else name
        return f"nonfinite in {kind}" + (f" column {column[1]}" if column else "") + \
            f" (seed {result.case.seed})"
    first = (reply.get("stderr") or "").strip().splitlines()[:1] or ["(nothing on stderr)"]
    return f"{klass}: {_normalize(first[0])}"


def _show(data, lines=60):
    if b"\0" in data[:4096]:
        return f"({len(data)} bytes of binary)"
    text = data.decode("utf-8", "backslashreplace").splitlines()
    more = f"\n... ({len(text) - lines} more lines)" if len(text) > lines else ""
    return "\n".join(text[:lines]) + more


def reproducer(result):
    case, reply = result.case, result.reply
    parts = [f"case {case.name} (seed {case.seed}), folder {result.folder}",
             "mutations: " + ("; ".join(case.mutations) or "none")]
    target = case.script if case.kind == "scripts" else \
        corpus.DATA if case.kind == "data" else corpus.RESTART
    names = [case.script] + ([target] if target != case.script else [])
    for name in names:
        parts.append(f"--- {name} ---\n{_show(case.files[name])}")
    if reply.get("stderr"):
        parts.append(f"--- stderr ---\n{reply['stderr'].strip()[:1500]}")
    detail = reply.get("detail")
    if isinstance(detail, dict):
        parts.append(f"--- interrupted at {detail['source']}:{detail['line']}, step {detail['step']} "
                     f"of a run to step {detail['last_step']}; where it was ---\n"
                     + "\n".join(detail["stack"].strip().splitlines()[-12:]))
    elif detail:
        parts.append(f"--- detail ---\n{str(detail)[:2500]}")
    if reply.get("traceback"):
        tail = "\n".join(reply["traceback"].strip().splitlines()[-14:])
        parts.append(f"--- traceback (last frames) ---\n{tail}")
    return "\n".join(parts)


def failures(results):
    groups = defaultdict(list)
    for result in results:
        if result.klass not in ACCEPTED:
            groups[signature(result)].append(result)
    return dict(sorted(groups.items(), key=lambda item: -len(item[1])))


def failure_message(kind, results, shown=25):
    groups = failures(results)
    count = Counter(r.klass for r in results)
    lines = [f"{sum(len(g) for g in groups.values())} of {len(results)} {kind} cases failed "
             f"({', '.join(f'{k} {count[k]}' for k in CLASSES if count[k])}); "
             f"{len(groups)} distinct failures:"]
    lines += [f"  {len(cases):5d}  {name}" for name, cases in groups.items()]
    for name, cases in list(groups.items())[:shown]:
        lines += ["", f"=== {name} ({len(cases)} cases)", reproducer(cases[0])]
        others = [str(c.folder) for c in cases[1:6]]
        if others:
            lines.append("others: " + ", ".join(others) + (" ..." if len(cases) > 6 else ""))
    return "\n".join(lines)


def write_report(path, summary, by_kind):
    cases_folder = path.with_name(path.stem + "-cases")
    with open(path, "a") as report:
        report.write(f"\n## Fuzz run {time.strftime('%Y-%m-%d %H:%M')}\n\n```\n{summary}\n```\n")
        for kind, results in by_kind.items():
            messages = Counter(_normalize(re.sub(r"^ERROR: \S+?:\d+: ", "", r.reply["stderr"].strip()))
                               for r in results if r.klass == "error")
            report.write(f"\n{kind}: the most frequent of {len(messages)} distinct error messages "
                         "(numbers and quoted words as N and '?'):\n\n")
            report.write("".join(f"    {n:6d}  {m}\n" for m, n in messages.most_common(30)))
            groups = failures(results)
            if not groups:
                continue
            report.write(f"\n### {kind}: {len(groups)} distinct failures\n\n")
            for name, cases in groups.items():
                first = cases[0]
                kept = cases_folder / first.case.name
                if first.folder is not None and first.folder.exists():
                    shutil.copytree(first.folder, kept, dirs_exist_ok=True)
                report.write(f"#### {name} ({len(cases)} cases)\n\nreproducer: {kept}\n\n"
                             f"```\n{reproducer(first)}\n```\n\n")


# ---- the tests ---------------------------------------------------------------------------------------
def test_the_seeds_run_as_they_should(fuzz):
    """The unmutated seeds end cleanly (lost_particle.in: with its one-line error), so what the
    mutated cases meet comes from the mutations."""
    wrong = [(r.case.seed, r.klass, r.reply.get("stderr")) for r in fuzz["seeds"]
             if r.klass != ("error" if r.case.seed == "lost_particle" else "clean")]
    assert not wrong


@pytest.mark.parametrize("kind", ["scripts", "data", "restarts"])
def test_mutated_inputs_end_in_a_clean_exit_or_one_located_error(fuzz, kind):
    results = fuzz[kind]
    assert len(results) == counts()[kind]
    assert not failures(results), failure_message(kind, results)


def test_errors_found_in_serial_are_one_located_line_on_two_ranks(fuzz, tmp_path):
    """A sample of the cases that ended in an error, run again under ``mpiexec -n 2``: still one
    located line, exit status 1, whichever rank met the problem."""
    assert len(fuzz["mpi"]) == mpi_sample()
    wrong = []
    for result in fuzz["mpi"]:
        folder = tmp_path / result.case.name
        folder.mkdir()
        for name, data in result.case.files.items():
            (folder / name).write_bytes(data)
        done = run_parallel(folder, result.case.script)
        if not one_located_line(done, list(result.case.files)):
            wrong.append(f"{result.case.name} ({'; '.join(result.case.mutations)}): serial "
                         f"{result.reply['stderr'].strip()!r}, on 2 ranks: exit status {done[0]}, "
                         f"stderr {done[1].strip()[:600]!r}")
    report = os.environ.get("PDPS_FUZZ_REPORT")
    if report:
        with open(report, "a") as handle:
            handle.write(f"\nMPI: {len(fuzz['mpi'])} cases that ended in an error, run again on 2 ranks: "
                         f"{len(fuzz['mpi']) - len(wrong)} ended in one located line\n"
                         + "".join(f"    {w}\n" for w in wrong))
    assert not wrong, "\n".join(wrong)
