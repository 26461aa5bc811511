"""What the reference recorders share: run LAMMPS on a script in a temporary folder (its log, or its
screen), and read the thermo table of its log."""

import json
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path


def run_lammps(lmp, script, files=(), label="", outputs=None):
    """The log LAMMPS writes for ``script``, run with copies of ``files`` beside it; ``outputs``
    {name: path}: files the run wrote, copied out before the folder goes. Stops the recorder with the
    log's end when LAMMPS fails."""
    with tempfile.TemporaryDirectory() as folder:
        for path in files:
            shutil.copy(path, Path(folder) / Path(path).name)
        (Path(folder) / "in.case").write_text(script)
        log = run_lammps_file(lmp, folder, "in.case", label=label)
        for name, path in (outputs or {}).items():
            shutil.copy(Path(folder) / name, path)
        return log


def lammps_screen(lmp, script, label=""):
    """What LAMMPS prints on its screen for ``script`` (run in a temporary folder, no log); stops the
    recorder with the screen's end when LAMMPS fails."""
    with tempfile.TemporaryDirectory() as folder:
        (Path(folder) / "in.case").write_text(script)
        done = subprocess.run([lmp, "-in", "in.case", "-log", "none", "-screen", "screen.txt"], cwd=folder,
                              capture_output=True, text=True)
        screen = (Path(folder) / "screen.txt").read_text()
    if done.returncode != 0:
        sys.exit(f"LAMMPS failed ({label or 'in.case'}):\n{done.stderr}\n{screen[-3000:]}")
    return screen


def marked_lines(screen):
    """The lines a script printed with ``print "@@ ..."``, as printed."""
    return [line for line in screen.splitlines() if line.startswith("@@ ")]


def run_lammps_file(lmp, folder, script, variables=(), label=""):
    """The log of LAMMPS run on the file ``script`` in ``folder``, with ``-var NAME VALUE`` for each
    (name, value) of ``variables``."""
    command = [lmp, "-in", script, "-log", "log.lammps", "-screen", "none"]
    for name, value in variables:
        command += ["-var", name, str(value)]
    done = subprocess.run(command, cwd=folder, capture_output=True, text=True)
    log = (Path(folder) / "log.lammps").read_text()
    if done.returncode != 0:
        sys.exit(f"LAMMPS failed ({label or script}):\n{log[-2000:]}")
    return log


def thermo_table(log):
    """The header and the lines of the log's first thermo table, split into words."""
    lines = log.splitlines()
    start = next(k for k, line in enumerate(lines) if line.split()[:1] == ["Step"])
    rows = []
    for line in lines[start + 1:]:
        if line.startswith("Loop time"):
            break
        rows.append(line.split())
    return lines[start].split(), rows


def thermo_lines(log):
    """The lines of the log's first thermo table after its header, split into words."""
    return thermo_table(log)[1]


def record_cases(lmp, scripts, files, path):
    """Run each script of ``scripts`` {case: script} with ``files`` beside it; write LAMMPS's thermo
    lines to ``path`` as tab-separated ``case step value...`` rows (what lammps_rows reads)."""
    rows = []
    for case, script in scripts.items():
        log = run_lammps(lmp, script, files, case)
        rows += [f"{case}\t" + "\t".join(words) for words in thermo_lines(log)]
    Path(path).write_text("\n".join(rows) + "\n")
    print("\n".join(rows))


def write_blocks(path, tables):
    """Thermo tables {name: rows of words} as one file: a "# name" line, then the rows."""
    blocks = [f"# {name}\n" + "\n".join(" ".join(row) for row in rows) for name, rows in tables.items()]
    Path(path).write_text("\n".join(blocks) + "\n")


def read_blocks(path):
    """The tables write_blocks wrote, as {name: float array (rows, columns)}."""
    import numpy as np
    tables, name = {}, None
    for line in Path(path).read_text().splitlines():
        if line.startswith("# "):
            name = line[2:]
            tables[name] = []
        else:
            tables[name].append([float(w) for w in line.split()])
    return {name: np.array(rows) for name, rows in tables.items()}


def write_case_table(path, recorder, reference, files, scripts, *, rtol=1e-9, atol=1e-12, ranks=(), restart=(),
                     dialect="lammps", program=None, checks=None, outputs=None):
    """Write the table tests/test_recorded_thermo.py runs: for each case of ``scripts`` {case: script
    as LAMMPS ran it}, the script and the files it reads (names in the table's folder), the rows file
    ``reference`` (beside the table) holding LAMMPS's thermo, and what else the case must satisfy:
    ``ranks`` the cases that must print the same thermo on 2 ranks, ``restart`` those whose run must
    go on from a restart file written half-way as it goes on in the same process. Tolerances are the table's;
    ``recorder``: the recording module's ``__file__``. A table of another program's numbers names it
    (``program``, "LIGGGHTS 3.8.0") and the dialect pdps reads its scripts in; ``checks`` {case: the
    manual items it checks} goes into each case (benchmarks/liggghts_manual.py reads them), and
    ``outputs`` {case: {file: text}} the files the program wrote that pdps must write again."""
    cases = {case: {"script": script, "ranks": case in ranks, "restart": case in restart}
             for case, script in scripts.items()}
    for case, items in (checks or {}).items():
        cases[case]["checks"] = list(items)
    for case, written in (outputs or {}).items():
        if written:
            cases[case]["outputs"] = dict(written)
    unknown = (set(ranks) | set(restart) | set(checks or ())) - set(cases)
    if unknown:
        sys.exit(f"{path}: no case named {sorted(unknown)[0]}")
    recorder = Path(recorder).resolve()
    table = {"recorded_by": f"benchmarks/{recorder.parent.name}/{recorder.name}", "reference": reference,
             "files": [Path(name).name for name in files], "rtol": rtol, "atol": atol, "cases": cases}
    if program is not None:
        table = {"program": program, "dialect": dialect, **table}
    Path(path).write_text(json.dumps(table, indent=1) + "\n")
