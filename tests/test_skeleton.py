"""`pdps new-plugin` writes, for each kind, a distribution that installs (a wheel, not editable),
passes its own tests, and whose style a script uses through its entry point."""

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

PLUGINS = {       # kind -> (new-plugin words, style, folder, package, module)
    "fix": (["kick"], "kick", "fix_kick", "pdps_fix_kick", "kick"),
    "compute": (["ke", "--kind", "compute", "--style", "ke/particle"], "ke/particle", "compute_ke",
                "pdps_compute_ke", "ke_particle"),
    "region": (["ball", "--kind", "region"], "ball", "region_ball", "pdps_region_ball", "ball"),
    "dump": (["xyz", "--kind", "dump"], "xyz", "dump_xyz", "pdps_dump_xyz", "xyz"),
    "pair": (["soft/harmonic", "--kind", "pair"], "soft/harmonic", "pair_soft_harmonic",
             "pdps_pair_soft_harmonic", "soft_harmonic"),
    "contact": (["sticky", "--kind", "contact"], "sticky", "contact_sticky", "pdps_contact_sticky", "sticky"),
}
# the kind `pdps styles` lists: a contact plugin holds a sub-model of pair gran's cohesion
LISTED = {"contact": "gran.cohesion"}


def pdps(*argv, cwd, env=None):
    return subprocess.run([sys.executable, "-m", "pdps_core.cli", *argv], cwd=cwd, capture_output=True,
                          text=True, timeout=600, env=env)


@pytest.fixture(scope="module")
def installed(tmp_path_factory):
    """Every kind's skeleton, written to a temporary folder and installed as wheels into a site
    folder of its own (put on PYTHONPATH, beside the project's venv); returns (root, environment)."""
    root = tmp_path_factory.mktemp("skeletons")
    for words, *_ in PLUGINS.values():
        made = pdps("new-plugin", *words, "--dir", ".", cwd=root)
        assert made.returncode == 0, made.stderr
    site = root / "site"
    install = subprocess.run([sys.executable, "-m", "pip", "install", "-q", "--no-deps", "--no-index",
                              "--no-build-isolation", "--target", str(site),
                              *(f"./{folder}" for _, _, folder, _, _ in PLUGINS.values())],
                             cwd=root, capture_output=True, text=True, timeout=600)
    assert install.returncode == 0, install.stderr
    return root, {**os.environ, "PYTHONPATH": str(site)}


def test_names_entry_points_and_declared_api_range(installed):
    root, _ = installed
    for kind, (_, style, folder, package, module) in PLUGINS.items():
        plugin = root / folder
        cls = next(line.split()[1].split("(")[0] for line in (plugin / package / f"{module}.py").read_text()
                   .splitlines() if line.startswith("class "))
        entry = f'"{style}" = "{package}.{module}:{cls}"'
        assert (plugin / "pyproject.toml").read_text().count(entry) == 1
        assert 'PDPS_API = ">=1.0,<2"' in (plugin / package / "__init__.py").read_text()
        assert (plugin / "tests" / f"test_{module}.py").exists()


@pytest.mark.parametrize("kind, passed", [("fix", 2), ("compute", 3), ("region", 3), ("dump", 2), ("pair", 10),
                                          ("contact", 2)])
def test_skeleton_passes_its_own_tests_as_installed(installed, kind, passed):
    root, env = installed
    plugin = root / PLUGINS[kind][2]
    tests = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "tests"],
                           cwd=plugin, capture_output=True, text=True, timeout=600, env=env)
    assert tests.returncode == 0, tests.stdout + tests.stderr
    assert f"{passed} passed" in tests.stdout
    # the tests imported the installed wheel, not the source folder
    check = subprocess.run([sys.executable, "-c", f"import {PLUGINS[kind][3]} as p; print(p.__file__)"],
                           cwd=root, capture_output=True, text=True, env=env)
    assert Path(check.stdout.strip()).is_relative_to(root / "site")


SCRIPT = """\
region box block 0 10 0 10 0 10
create_box 1 box
mass 1 1
region inner ball 5 5 5 3
create_particle 1 random 100 4242 inner overlap 0.5
velocity all create 1.0 4 gaussian
pair_style soft/harmonic 1.0
pair_coeff * * 25
fix 1 all nve
fix 2 all kick 0 0 0.001
compute ke all ke/particle
thermo_style custom step c_ke
thermo 10
dump 1 all xyz 10 out.xyz
run 20
"""


def test_a_script_uses_every_kind_through_its_entry_point(installed):
    root, env = installed
    (root / "in.skeletons").write_text(SCRIPT)
    run = pdps("run", "in.skeletons", "-log", "none", "--no-progress", cwd=root, env=env)
    assert (run.returncode, run.stderr) == (0, "")
    frames = (root / "out.xyz").read_text().splitlines()
    assert [frames[k * 102] for k in range(3)] == ["100"] * 3
    assert [frames[k * 102 + 1] for k in range(3)] == ["Timestep: 0", "Timestep: 10", "Timestep: 20"]
    start = np.array([[float(w) for w in line.split()[1:]] for line in frames[2:102]])
    assert np.linalg.norm(start - 5.0, axis=1).max() <= 3.0           # placed in the sphere
    header = next(line for line in run.stdout.splitlines() if line.split()[:1] == ["Step"])
    assert header.split() == ["Step", "c_ke"]


def test_styles_and_doc_show_the_installed_skeletons(installed):
    root, env = installed
    listed = pdps("styles", cwd=root, env=env)
    assert listed.returncode == 0, listed.stderr
    rows = {tuple(line.split()) for line in listed.stdout.splitlines()}
    for kind, (_, style, folder, _, _) in PLUGINS.items():
        dist = "pdps-" + folder.replace("_", "-")
        assert (LISTED.get(kind, kind), style, dist, "0.1.0") in rows          # loaded, compatible: no mark
    doc = pdps("doc", "pair", "soft/harmonic", cwd=root, env=env)
    page = doc.stdout.splitlines()
    assert page[0] == "pair style soft/harmonic  (pdps-pair-soft-harmonic 0.1.0)"
    assert "- epsilon: number; epsilon >= 0; unit: energy; required" in page
    assert "- cutoff: number; cutoff > 0; unit: distance; optional" in page
    assert page[page.index("Examples:") + 2] == "    pair_style soft/harmonic 1.0"


def test_new_plugin_refuses_bad_names_and_existing_folders(tmp_path):
    bad = pdps("new-plugin", "Bad-Name", "--dir", ".", cwd=tmp_path)
    assert bad.returncode == 1
    assert bad.stderr.strip() == "ERROR: plugin name must be lower-case letters, digits, _ and / (got Bad-Name)"
    bad = pdps("new-plugin", "soft", "--kind", "pair", "--style", "soft//x", "--dir", ".", cwd=tmp_path)
    assert bad.stderr.strip() == "ERROR: style name must be letters, digits, _ and / (got soft//x)"
    for expected in (0, 1):
        again = pdps("new-plugin", "kick", "--dir", ".", cwd=tmp_path)
        assert again.returncode == expected
    assert again.stderr.strip() == "ERROR: fix_kick already exists"


def test_a_style_name_with_capitals_as_scripts_spell_them_is_taken(tmp_path):
    """LIGGGHTS names styles with capitals (dump mesh/gran/VTK): the entry point keeps the name as
    scripts spell it; the module file is lower-case."""
    made = pdps("new-plugin", "vtk_mesh", "--kind", "dump", "--style", "mesh/out/VTK", "--dir", ".", cwd=tmp_path)
    assert made.returncode == 0, made.stderr
    root = tmp_path / "dump_vtk_mesh"
    assert '"mesh/out/VTK" = "pdps_dump_vtk_mesh.mesh_out_vtk:DumpMeshOutVtk"' in (root / "pyproject.toml").read_text()
    assert 'name = "mesh/out/VTK"' in (root / "pdps_dump_vtk_mesh" / "mesh_out_vtk.py").read_text()
