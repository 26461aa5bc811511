"""dump custom with dump_modify against LAMMPS (22 Jul 2025), line by line: the script of
benchmarks/lammps_references/dump_modify.py, run by pdps, writes the three dump files LAMMPS wrote
(tests/data/lammps/dump_modify/): headers, columns, ``format float|line|int|N``, ``sort id|N|-N``,
``every``, ``first yes`` and ``append yes``; the three dumps with no explicit format ``sort`` differ
from LAMMPS's defaults only where docs/lammps.md says (dump_modify row)."""

import sys
from pathlib import Path

import pytest

from pdps_core.api import Simulation

ROOT = Path(__file__).resolve().parents[1]
DATA = ROOT / "tests" / "data" / "lammps" / "dump_modify"
sys.path.insert(0, str(ROOT / "benchmarks" / "lammps_references"))
from dump_modify import FILES, SCRIPT  # noqa: E402


@pytest.fixture(scope="module")
def pdps_dumps(tmp_path_factory):
    folder = tmp_path_factory.mktemp("dump_modify")
    (folder / "in.dump").write_text(SCRIPT)
    with pytest.MonkeyPatch.context() as patch:
        patch.chdir(folder)
        sim = Simulation(screen=False, log=None)
        sim.file("in.dump")
        sim.close()
    return folder


def frames(text):
    """The timesteps of a dump's frames."""
    lines = text.splitlines()
    return [int(lines[k + 1]) for k, line in enumerate(lines) if line == "ITEM: TIMESTEP"]


def test_the_reference_holds_what_the_script_asks_for():
    assert frames((DATA / "dump.sorted").read_text()) == [0, 10, 20, 30, 40, 50, 60, 70, 80]
    # every 20 replaces the dump's 25; first yes adds only the first step after the dump command (0
    # here, a multiple anyway), not the second run's first step
    assert frames((DATA / "dump.every").read_text()) == [0, 20, 40, 60, 80]
    # the second run's dump appends its frames (every 15, none at 50) to the first one's (every 10)
    assert frames((DATA / "dump.desc").read_text()) == [0, 10, 20, 30, 40, 50, 60, 75]
    # defined at step 50 with first yes: a frame there, then every 20
    assert frames((DATA / "dump.late").read_text()) == [50, 60, 80]


@pytest.mark.parametrize("name", FILES)
def test_pdps_writes_lammps_dump_text(pdps_dumps, name):
    mine = (pdps_dumps / name).read_text().splitlines()
    lammps = (DATA / name).read_text().splitlines()
    assert len(mine) == len(lammps)
    for number, (a, b) in enumerate(zip(mine, lammps), start=1):
        assert a == b, f"{name} line {number}"
