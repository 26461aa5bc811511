"""Shared helpers: run a script through the `pdps` command, a simulation that keeps what it prints
(``make_sim`` and ``pdps_cli`` come from the test kit, pdps_core.testing)."""

import io
import os
import subprocess
import sys
import textwrap

import pytest


PDPS = [sys.executable, "-m", "pdps_core.cli"]


@pytest.fixture
def run_pdps(tmp_path):
    """Write a script into a temp dir and run `pdps run` on it; returns the CompletedProcess."""
    def run(script, *extra, name="in.test", env=None):
        path = tmp_path / name
        path.write_text(textwrap.dedent(script))
        return subprocess.run([*PDPS, "run", name, *extra], cwd=tmp_path, capture_output=True,
                              text=True, env={**os.environ, **(env or {})}, timeout=600)
    return run


@pytest.fixture
def sim(make_sim):
    """A silent simulation whose screen output is kept in ``sim.output.screen`` (a StringIO)."""
    screen = io.StringIO()
    s = make_sim(screen=screen)
    return s
