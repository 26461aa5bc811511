"""pdps as users install it: the wheels of `make dist`, installed (not editable) through the pdps
meta-distribution into a fresh virtual environment, whose files are then made read-only (as a
system-wide or shared install is), run the water example.

This catches what the editable installs of `make test` cannot: a module or data file missing from a
wheel (or a stale one packed from an old build/), a dependency not declared, an entry point naming
nothing, and numba (``cache=True``) or the core's generated pair loops wanting to write next to the
installed code. Numba then caches in the user's folder (``~/.cache/numba``, its UserWideCacheLocator),
and the second run must find everything the first one compiled there; where the home cannot be written
either, pdps_core points numba at the temporary folder.

Runs only when asked (`pytest -m wheels`, as .ci/run does): it builds and installs for a minute or two.
"""

import ctypes
import email.parser
import json
import os
import pathlib
import shutil
import stat
import subprocess
import sys
import tomllib
import zipfile

import pytest

pytestmark = pytest.mark.wheels

ROOT = pathlib.Path(__file__).resolve().parents[1]
PROJECTS = [ROOT] + sorted(path.parent for path in ROOT.glob("plugins/*/pyproject.toml"))
COMPILED = {".pyc", ".nbi", ".nbc"}
WRITE = stat.S_IWUSR | stat.S_IWGRP | stat.S_IWOTH

# Root may write into read-only folders (capabilities, linux/capability.h); the runs give that up.
PR_CAPBSET_DROP = 24
CAP_DAC_OVERRIDE = 1
CAP_DAC_READ_SEARCH = 2


def project(folder):
    return tomllib.loads((folder / "pyproject.toml").read_text())["project"]


def wheel_name(name):
    return name.replace("-", "_")


def source_files(folder):
    """Every file of the project's packages as it should appear in the wheel (no caches)."""
    files = set()
    for package in folder.glob("pdps_*/__init__.py"):
        for path in package.parent.rglob("*"):
            if path.is_file() and "__pycache__" not in path.parts and path.suffix not in COMPILED:
                files.add(path.relative_to(folder).as_posix())
    return files


def give_up_root_override():
    """preexec_fn: without CAP_DAC_OVERRIDE (dropped from the bounding set, so the program run does
    not regain it) root meets file permissions as any user does."""
    if os.geteuid() != 0:
        return
    libc = ctypes.CDLL(None, use_errno=True)
    for capability in (CAP_DAC_OVERRIDE, CAP_DAC_READ_SEARCH):
        if libc.prctl(PR_CAPBSET_DROP, capability, 0, 0, 0) != 0:
            raise OSError(ctypes.get_errno(), "prctl(PR_CAPBSET_DROP) failed")


def set_writable(folder, writable):
    for path in [folder, *folder.rglob("*")]:
        if path.is_symlink():
            continue
        mode = path.stat().st_mode
        os.chmod(path, mode | stat.S_IWUSR if writable else mode & ~WRITE)


@pytest.fixture(scope="module")
def dist(tmp_path_factory):
    folder = tmp_path_factory.mktemp("dist")
    done = subprocess.run(["make", "-s", "dist", f"DIST={folder}"], cwd=ROOT, capture_output=True, text=True,
                          timeout=900)
    assert done.returncode == 0, done.stderr
    return folder


@pytest.fixture(scope="module")
def installed(dist, tmp_path_factory):
    """A fresh venv with `pip install pdps` from the wheels, made read-only; (venv, HOME, env)."""
    top = tmp_path_factory.mktemp("installed")
    venv = top / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, timeout=300)
    meta = next(dist.glob("pdps-*.whl"))
    done = subprocess.run([str(venv / "bin" / "pip"), "install", "-q", "--find-links", str(dist), str(meta)],
                          capture_output=True, text=True, timeout=1800)
    assert done.returncode == 0, done.stderr
    home = top / "home"
    home.mkdir()
    env = {key: value for key, value in os.environ.items()
           if key not in ("NUMBA_CACHE_DIR", "XDG_CACHE_HOME", "PDPS_CACHE_DIR", "PYTHONPATH", "VIRTUAL_ENV")}
    env["HOME"] = str(home)
    set_writable(venv, False)
    yield venv, home, env
    set_writable(venv, True)
    shutil.rmtree(venv)


def run_installed(installed, *command, cwd, **env):
    venv, _, base = installed
    return subprocess.run([str(venv / "bin" / command[0]), *command[1:]], cwd=cwd, env={**base, **env},
                          text=True, capture_output=True, preexec_fn=give_up_root_override, timeout=1800)


def run_water(installed, folder, **env):
    """Run examples/water.in in ``folder`` with the installed `pdps`; the final temperature."""
    shutil.copy(ROOT / "examples" / "water.in", folder)
    done = run_installed(installed, "pdps", "run", "water.in", "-log", "none", "--no-progress", cwd=folder,
                         **env)
    assert done.returncode == 0, done.stderr
    rows = [line.split() for line in done.stdout.splitlines()]
    final = [row for row in rows if len(row) == 3 and row[0] == "200"]
    assert len(final) == 1
    return float(final[0][1])


def compiled(folder):
    """numba's cache files under ``folder``, with their modification times."""
    return {path: path.stat().st_mtime_ns for path in folder.rglob("*") if path.suffix in (".nbi", ".nbc")}


def test_each_wheel_holds_exactly_its_packages_files(dist):
    for folder in PROJECTS:
        name, version = project(folder)["name"], project(folder)["version"]
        wheel = dist / f"{wheel_name(name)}-{version}-py3-none-any.whl"
        with zipfile.ZipFile(wheel) as archive:
            packed = {entry for entry in archive.namelist() if ".dist-info/" not in entry}
        assert packed == source_files(folder), name


def test_meta_distribution_requires_the_core_and_every_pack_at_this_version(dist):
    with zipfile.ZipFile(next(dist.glob("pdps-*.whl"))) as archive:
        metadata = next(entry for entry in archive.namelist() if entry.endswith(".dist-info/METADATA"))
        requires = email.parser.Parser().parsestr(archive.read(metadata).decode()).get_all("Requires-Dist")
    assert sorted(requires) == sorted(f"{project(f)['name']}=={project(f)['version']}" for f in PROJECTS)


def test_every_wheel_names_its_licence(dist):
    """BSD-3-Clause (LICENSE, as HOOMD-blue's), in every distribution's metadata, so a plugin author
    can tell what they may do with the core and the packs."""
    assert (ROOT / "LICENSE").read_text().startswith("BSD 3-Clause License")
    for folder in [*PROJECTS, ROOT / "packaging" / "pdps"]:
        name, version = project(folder)["name"], project(folder)["version"]
        with zipfile.ZipFile(dist / f"{wheel_name(name)}-{version}-py3-none-any.whl") as archive:
            entry = next(e for e in archive.namelist() if e.endswith(".dist-info/METADATA"))
            metadata = email.parser.Parser().parsestr(archive.read(entry).decode())
        assert metadata.get("License-Expression") == "BSD-3-Clause", name


def test_every_entry_point_loads_from_the_installed_wheels(installed, tmp_path):
    show = ("import importlib.metadata as md, json, sys\n"
            "print(json.dumps(sorted([d.metadata['Name'], ep.group, ep.name,\n"
            "                         sys.modules[ep.load().__module__].__file__]\n"
            "    for d in md.distributions() for ep in d.entry_points if ep.group.startswith('pdps.'))))")
    done = run_installed(installed, "python", "-c", show, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    loaded = json.loads(done.stdout)
    expected = sorted([project(folder)["name"], group, style]
                      for folder in PROJECTS
                      for group, styles in project(folder).get("entry-points", {}).items()
                      for style in styles if group.startswith("pdps."))
    assert [row[:3] for row in loaded] == expected
    assert all(pathlib.Path(row[3]).is_relative_to(installed[0]) for row in loaded)


def test_water_example_runs_from_a_read_only_install_and_caches_in_the_users_folder(installed, tmp_path):
    _, home, _ = installed
    write_into_site_packages = ("import sysconfig, tempfile\n"
                                "tempfile.TemporaryFile(dir=sysconfig.get_path('purelib'))")
    probe = run_installed(installed, "python", "-c", write_into_site_packages, cwd=tmp_path)
    assert "PermissionError" in probe.stderr, "site-packages is writable: the test would prove nothing"
    runs = []
    for _ in range(2):
        # what tests/test_smoke.py asks of the same example run from the source tree
        assert 0.9 <= run_water(installed, tmp_path) <= 1.1
        runs.append(compiled(home / ".cache"))
    assert any(path.is_relative_to(home / ".cache" / "numba") for path in runs[0])
    assert runs[1] == runs[0], "the second run compiled again: numba's cache was not found"


def test_water_example_runs_when_neither_the_install_nor_the_home_can_be_written(installed, tmp_path):
    home, scratch = tmp_path / "home", tmp_path / "tmp"
    home.mkdir(mode=0o555)
    scratch.mkdir()
    assert 0.9 <= run_water(installed, tmp_path, HOME=str(home), TMPDIR=str(scratch)) <= 1.1
    assert compiled(scratch / f"pdps-{os.getuid()}" / "numba")
