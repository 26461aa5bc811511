"""MPI error paths: bad input under ``mpiexec -n 2`` stops with exactly one located ERROR line, exit
status 1, whichever rank finds the problem (every rank: a script error; one rank alone: a particle
lost from its sub-domain). test_fuzz.py reruns a sample of the fuzz cases' errors the same way."""

import os
import signal
import subprocess
import sys

import pytest

from pdps_core.testing import mpiexec

from .classify import located

BOX = "units lj\nregion box block 0 4 0 4 0 4\ncreate_box 1 box\nmass 1 1\n"
LOST = ("boundary p f p\nprocessors 1 2 1\n" + BOX.replace("units lj\n", "") +
        "create_particle 1 single 1 1 1\ncreate_particle 1 single 2 3.55 2\nvelocity all set 0 1 0\n"
        "fix 1 all nve\ntimestep 0.1\nneigh_modify every 1 delay 0 check no\nthermo 1\nrun 20\n")
DATA = """outside

2 atoms
1 atom types

0 4 xlo xhi
0 4 ylo yhi
0 4 zlo zhi

Atoms # atomic

1 1 1 1 1
2 1 2 9 2
"""
CASES = {
    "script error on every rank": (BOX + "pair_style dpd 1.0 1.0 5\npair_coeff * * 25 -4.5\n", {}),
    "particle lost on one rank": (LOST, {}),
    "data file: a particle outside a fixed box": ("boundary p f p\nread_data d.data\n", {"d.data": DATA}),
    "data file: id 0": ("read_data d.data\n", {"d.data": DATA.replace("1 1 1 1 1", "0 1 1 1 1")}),
    "restart file: truncated": ("read_restart r.restart\nrun 1\n", {"r.restart": "PK\x03\x04 cut"}),
    "script: not UTF-8": (BOX.encode() + b"run 1\xff\n", {}),
    "variable defined by itself": (BOX + "variable a equal v_a+1\nprint ${a}\n", {}),
    "non-finite velocity": (BOX + "create_particle 1 single 1 1 1\nvelocity all set nan 0 0\n"
                            "fix 1 all nve\nrun 2\n", {}),
    "include of a missing file": (BOX + "include nowhere.in\n", {}),
}


def run_parallel(folder, script="in.fuzz", ranks=2, timeout=120):
    """``mpiexec -n RANKS pdps run SCRIPT`` in ``folder``: (exit status, stderr text); a run over
    ``timeout`` seconds is killed with all its ranks and reported as exit status None."""
    command = [mpiexec(), "-n", str(ranks), sys.executable, "-m", "pdps_core.cli", "run", script,
               "-log", "none", "--no-progress"]
    process = subprocess.Popen(command, cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               start_new_session=True)
    try:
        _, stderr = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        _, stderr = process.communicate()
        return None, stderr.decode("utf-8", "replace")
    return process.returncode, stderr.decode("utf-8", "replace")


def one_located_line(done, inputs):
    code, stderr = done
    return code == 1 and located(stderr, inputs) and "internal error" not in stderr


@pytest.mark.parametrize("name", CASES)
def test_bad_input_on_two_ranks_gives_one_located_error_line(tmp_path, name):
    script, files = CASES[name]
    (tmp_path / "in.fuzz").write_bytes(script if isinstance(script, bytes) else script.encode())
    for file, text in files.items():
        (tmp_path / file).write_bytes(text.encode("latin-1"))
    done = run_parallel(tmp_path)
    assert one_located_line(done, ["in.fuzz", *files]), done
