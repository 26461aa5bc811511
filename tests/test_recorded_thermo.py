"""The one driver for what every style recorded against LAMMPS must satisfy, as LAMMPS's own
unittest/force-styles YAML files do: each ``plugins/*/tests/data/*.cases.json`` table, written by a
recorder of benchmarks/lammps_references beside the thermo LAMMPS printed for its cases, holds each
case's script (as LAMMPS ran it) and the files it reads. For every case, pdps prints LAMMPS's thermo
step for step to the table's tolerance; the cases marked ``ranks`` print it on 2 ranks too; the
cases marked ``restart`` go on from a restart file written half-way as the run goes on in the
same process (``run N/2`` twice: a second run is not the middle of one, for LAMMPS as for pdps:
fixes ramp over a run, and a run's setup computes forces anew).
A plugin adds a table (``write_case_table`` in the recorders' lammps_run.py) and is checked here;
its own tests keep only what a table cannot say. A table of LIGGGHTS 3.8.0's numbers (recorded by
benchmarks/liggghts_references/cases.py) says so (``program``) and is read in its dialect; the core's
commands have their tables in tests/data."""

import json
import re
import shutil
from pathlib import Path

import numpy as np
import pytest

from pdps_core.api import Simulation
from pdps_core.testing import assert_thermo_as_lammps, by_tag, given_again, lammps_rows, lammps_thermo, run_ranks, thermo_csv

ROOT = Path(__file__).resolve().parents[1]
TABLES = sorted(ROOT.glob("plugins/*/tests/data/*.cases.json")) + sorted(ROOT.glob("tests/data/*.cases.json"))


def _owner(path):
    """The plugin whose table it is, or "core"."""
    return path.parts[-4] if path.parts[-5:-4] == ("plugins",) else "core"


def _dialect(table):
    """The dialect the table's scripts are read in: LAMMPS's unless the table names another."""
    return table.get("dialect", "lammps")


def _cases(check=None):
    found = []
    for path in TABLES:
        table = json.loads(path.read_text())
        for case, entry in table["cases"].items():
            if check is None or entry.get(check):
                found.append(pytest.param(path, case, id=f"{_owner(path)}:{path.name.split('.')[0]}:{case}"))
    return found


def _reference(path, table, case):
    """LAMMPS's thermo rows of ``case`` (step first), without the lines a fix printed."""
    rows = lammps_rows(path.parent / table["reference"], case)
    return [row for row in rows if row[0].isdigit()]


def _folder(path, table, folder):
    for name in table["files"]:
        shutil.copy(path.parent / name, Path(folder) / name)


def test_the_tables_are_found():
    assert len(TABLES) >= 10 and len(_cases()) >= 60


@pytest.mark.parametrize("path, case", _cases())
def test_thermo_as_lammps_prints_it(tmp_path, monkeypatch, path, case):
    table = json.loads(path.read_text())
    _, mine = lammps_thermo(tmp_path, monkeypatch, table["cases"][case]["script"], table["files"], path.parent,
                            dialect=_dialect(table))
    reference = _reference(path, table, case)
    assert_thermo_as_lammps(mine, reference, case, [int(row[0]) for row in reference], table["rtol"], table["atol"])


@pytest.mark.parametrize("path, case", _cases("ranks"))
def test_two_ranks_print_it_too(tmp_path, path, case):
    table = json.loads(path.read_text())
    _folder(path, table, tmp_path)
    run_ranks(table["cases"][case]["script"], 2, tmp_path, name="in.case", log="log.case", dialect=_dialect(table))
    columns = thermo_csv(tmp_path / "log.case.csv")
    mine = np.column_stack(list(columns.values()))
    reference = _reference(path, table, case)
    assert_thermo_as_lammps(mine.tolist(), reference, f"{case} on 2 ranks", [int(row[0]) for row in reference],
                            table["rtol"], table["atol"])


def _last_run(script):
    """(the script up to its last ``run N``, N)."""
    runs = list(re.finditer(r"^run (\d+)\s*$", script, re.MULTILINE))
    assert runs, "a restart case ends with run N"
    return script[:runs[-1].start()], int(runs[-1].group(1))


@pytest.mark.parametrize("path, case", _cases("restart"))
def test_a_restart_goes_on_as_the_run_did(tmp_path, monkeypatch, path, case):
    table = json.loads(path.read_text())
    _folder(path, table, tmp_path)
    monkeypatch.chdir(tmp_path)
    script = table["cases"][case]["script"]
    start, steps = _last_run(script)
    straight = Simulation(screen=False, log=None, dialect=_dialect(table))
    straight.command(f"{start}run {steps // 2}\nrun {steps - steps // 2}")
    before = Simulation(screen=False, log=None, dialect=_dialect(table))
    before.command(f"{start}run {steps // 2}\nwrite_restart half.restart")
    resumed = Simulation(screen=False, log=None, dialect=_dialect(table))
    # as a LAMMPS script reading a restart file: its fixes, computes and settings given again
    resumed.command(f"read_restart half.restart\n{given_again(start)}run {steps - steps // 2}")
    assert resumed.step == straight.step == steps
    np.testing.assert_allclose(resumed.box.length, straight.box.length, rtol=1e-12)
    for name in ("x", "v"):
        np.testing.assert_allclose(by_tag(resumed, getattr(resumed, name)), by_tag(straight, getattr(straight, name)),
                                   rtol=1e-9, atol=1e-9, err_msg=f"{case}: {name} after the restart")


def _legacy_vtk(text):
    """{name: array} of an ASCII legacy VTK file as LIGGGHTS writes them: "points" and the FIELD
    arrays of a POLYDATA, or the X/Y/Z_COORDINATES of a RECTILINEAR_GRID."""
    words, data, k = text.split(), {}, 0
    while k < len(words):
        word = words[k]
        if word == "POINTS":
            n = int(words[k + 1])
            data["points"] = np.array(words[k + 3:k + 3 + 3 * n], dtype=float).reshape(n, 3)
            k += 3 + 3 * n
        elif word.endswith("_COORDINATES"):
            n = int(words[k + 1])
            data[word] = np.array(words[k + 3:k + 3 + n], dtype=float)
            k += 3 + n
        elif word == "FIELD":
            k += 3
            for _ in range(int(words[k - 1])):
                name, width, n = words[k], int(words[k + 1]), int(words[k + 2])
                values = np.array(words[k + 4:k + 4 + width * n], dtype=float)
                data[name] = values.reshape(n, width) if width > 1 else values
                k += 4 + width * n
        else:
            k += 1
    return data


def _assert_same_vtk(case, name, path, recorded):
    """A VTK file pdps wrote (meshio's, or ASCII) holds the recorded one's points and arrays, row for
    row by particle id, to the recorded digits (points as floats: six)."""
    import meshio
    theirs = _legacy_vtk(recorded)
    try:
        mine = _legacy_vtk(path.read_text())
    except (UnicodeDecodeError, ValueError):
        mesh = meshio.read(path)
        mine = {"points": mesh.points, **{key: np.squeeze(np.asarray(v)) for key, v in mesh.point_data.items()}}
    vectors = {"v": ("vx", "vy", "vz"), "f": ("fx", "fy", "fz"), "omega": ("omegax", "omegay", "omegaz")}
    for vector, parts in vectors.items():
        if vector in mine and all(part in theirs for part in parts):
            theirs[vector] = np.column_stack([theirs.pop(part) for part in parts])
    assert set(mine) == set(theirs), f"{case}: {name} has {sorted(mine)}, the recorded one {sorted(theirs)}"
    if "id" in theirs:
        order_mine, order_theirs = np.argsort(mine["id"]), np.argsort(theirs["id"])
        mine = {key: value[order_mine] for key, value in mine.items()}
        theirs = {key: value[order_theirs] for key, value in theirs.items()}
    for key, value in theirs.items():
        np.testing.assert_allclose(mine[key], value, rtol=1e-5, atol=1e-12, err_msg=f"{case}: {name} {key}")


def _numbers_or_words(text):
    out = []
    for word in text.split():
        try:
            out.append(float(word))
        except ValueError:
            out.append(word)
    return out


@pytest.mark.parametrize("path, case", _cases("outputs"))
def test_the_files_a_case_writes_are_the_program_s(tmp_path, monkeypatch, path, case):
    """Every file the recorded program wrote (dumps), word for word, numbers to the printed digits
    (%g's six: 1e-5 relative) and 1e-12 absolute (round-off printed near zero)."""
    table = json.loads(path.read_text())
    entry = table["cases"][case]
    lammps_thermo(tmp_path, monkeypatch, entry["script"], table["files"], path.parent, dialect=_dialect(table))
    for name, text in entry["outputs"].items():
        if name.endswith(".vtk"):
            _assert_same_vtk(case, name, tmp_path / name, text)
            continue
        mine, theirs = _numbers_or_words((tmp_path / name).read_text()), _numbers_or_words(text)
        assert len(mine) == len(theirs), f"{case}: {name} has {len(mine)} words, the recorded one {len(theirs)}"
        for k, (a, b) in enumerate(zip(mine, theirs)):
            if isinstance(b, float) and isinstance(a, float):
                assert a == pytest.approx(b, rel=1e-5, abs=1e-12), f"{case}: {name} word {k}: {a} against {b}"
            else:
                assert a == b, f"{case}: {name} word {k}: {a!r} against {b!r}"
