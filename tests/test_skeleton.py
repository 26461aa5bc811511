"""`pdps new-plugin` writes a plugin whose own tests pass."""

import subprocess
import sys


def test_new_plugin_skeleton_passes_its_own_tests(tmp_path):
    made = subprocess.run([sys.executable, "-m", "pdps_core.cli", "new-plugin", "kick", "--dir", "."],
                          cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert made.returncode == 0, made.stderr
    root = tmp_path / "fix_kick"
    assert (root / "pyproject.toml").read_text().count('kick = "pdps_fix_kick.kick:FixKick"') == 1
    tests = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", "tests"],
                           cwd=root, capture_output=True, text=True, timeout=600,
                           env={"PYTHONPATH": str(root), "PATH": ""})
    assert tests.returncode == 0, tests.stdout + tests.stderr
    assert "2 passed" in tests.stdout


def test_new_plugin_refuses_bad_names_and_existing_folders(tmp_path):
    bad = subprocess.run([sys.executable, "-m", "pdps_core.cli", "new-plugin", "Bad-Name", "--dir", "."],
                         cwd=tmp_path, capture_output=True, text=True, timeout=600)
    assert bad.returncode == 1
    assert bad.stderr.strip() == "ERROR: plugin name must be lower-case letters, digits and _ (got Bad-Name)"
    for expected in (0, 1):
        again = subprocess.run([sys.executable, "-m", "pdps_core.cli", "new-plugin", "kick", "--dir", "."],
                               cwd=tmp_path, capture_output=True, text=True, timeout=600)
        assert again.returncode == expected
