"""Shared helpers: run a script in-process or through the `pdps` command."""

import os
import subprocess
import sys
import textwrap

import pytest

from pdps_core.api import Simulation

PDPS = [sys.executable, "-m", "pdps_core.cli"]


@pytest.fixture
def make_sim(tmp_path, monkeypatch):
    """A silent Simulation working in a temporary directory."""
    monkeypatch.chdir(tmp_path)

    def make(**kwargs):
        kwargs.setdefault("screen", False)
        kwargs.setdefault("log", None)
        return Simulation(**kwargs)
    return make


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
def pdps_cli(tmp_path, monkeypatch, capsys):
    """`pdps run` in-process (``cli.main``, the code path of the console script) in a temp dir:
    writes the script, runs it and returns a CompletedProcess (exit code, stdout, stderr).
    As fast as ``make_sim``; use ``run_pdps`` where the process itself matters."""
    from pdps_core import cli
    monkeypatch.chdir(tmp_path)

    def run(script, *extra, name="in.test"):
        (tmp_path / name).write_text(textwrap.dedent(script))
        argv = ["run", name, *extra]
        capsys.readouterr()
        code = cli.main(argv)
        out, err = capsys.readouterr()
        return subprocess.CompletedProcess(argv, code, out, err)
    return run
