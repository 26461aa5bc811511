"""Styles come from entry points, are imported only when a script names them, and a name claimed
by two distributions is an error that names both."""

import subprocess
import sys
import textwrap

import pytest

from pdps_core.api import ScriptError, registry

NO_PAIR_SCRIPT = """
region box block 0 5 0 5 0 5
create_box 1 box
mass 1 1
lattice spacing x 1 y 1 z 1
create_particle 1 region box
velocity all create 1.0 4 gaussian
fix 1 all nve
run 20
"""


def run_python(code, cwd, env=None):
    result = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], cwd=cwd,
                            capture_output=True, text=True, env=env, timeout=600)
    assert result.returncode == 0, result.stderr
    return result.stdout.strip()


def test_script_without_pair_style_builds_no_list_and_imports_no_dpd(tmp_path):
    (tmp_path / "in.free").write_text(NO_PAIR_SCRIPT)
    out = run_python("""
        import sys
        from pdps_core.api import Simulation
        sim = Simulation(screen=False, log=None)
        sim.file("in.free")
        print(sim.neighbors.builds, len(sim.neighbors.requests), sim.particles.nghost)
        print(sorted(m for m in sys.modules if m.startswith("pdps_pair_dpd")))
    """, tmp_path)
    counts, modules = out.splitlines()
    assert counts == "0 0 0"
    assert modules == "[]"


def test_naming_dpd_imports_it(tmp_path):
    (tmp_path / "in.dpd").write_text(NO_PAIR_SCRIPT.replace(
        "fix 1", "pair_style dpd 1.0 1.0 9\npair_coeff * * 25 4.5\nfix 1"))
    out = run_python("""
        import sys
        from pdps_core.api import Simulation
        sim = Simulation(screen=False, log=None)
        sim.file("in.dpd")
        print(sim.neighbors.builds > 0, "pdps_pair_dpd.dpd" in sys.modules)
    """, tmp_path)
    assert out == "True True"


def test_listing_styles_imports_no_plugin(tmp_path):
    out = run_python("""
        import sys
        from pdps_core.styles import registry
        rows = registry.listing()
        print(len(rows), sorted(m for m in sys.modules if m.startswith("pdps_") and not m.startswith("pdps_core")))
    """, tmp_path)
    count, modules = out.split(" ", 1)
    assert int(count) >= 8
    assert modules == "[]"


def test_pdps_styles_lists_style_kind_and_distribution(tmp_path):
    result = subprocess.run([sys.executable, "-m", "pdps_core.cli", "styles"], capture_output=True,
                            text=True, cwd=tmp_path, timeout=600)
    assert result.returncode == 0
    rows = {tuple(line.split()) for line in result.stdout.splitlines()}
    assert ("pair", "dpd", "pdps-pair-dpd") in rows
    assert ("fix", "nve", "pdps-fix-nve") in rows
    assert ("compute", "temp", "pdps-compute-thermo") in rows
    assert ("region", "block", "pdps-region-shapes") in rows
    assert ("dump", "atom", "pdps-dump-text") in rows


def fake_distribution(root, name, group, style, target):
    info = root / f"{name.replace('-', '_')}-1.0.dist-info"
    info.mkdir()
    (info / "METADATA").write_text(f"Metadata-Version: 2.1\nName: {name}\nVersion: 1.0\n")
    (info / "entry_points.txt").write_text(f"[{group}]\n{style} = {target}\n")


def test_a_style_claimed_by_two_distributions_is_an_error_naming_both(tmp_path):
    fake_distribution(tmp_path, "pdps-dpd-alpha", "pdps.pair", "dpd2", "nowhere_a:Pair")
    fake_distribution(tmp_path, "pdps-dpd-beta", "pdps.pair", "dpd2", "nowhere_b:Pair")
    out = run_python("""
        from pdps_core.api import ScriptError, registry
        try:
            registry.lookup("pair", "dpd2")
        except ScriptError as exc:
            print(exc)
    """, tmp_path, env={"PYTHONPATH": str(tmp_path), "PATH": ""})
    assert out == ("pair style dpd2 is provided by more than one distribution: "
                   "pdps-dpd-alpha and pdps-dpd-beta; uninstall one of them")


def test_unknown_style_lists_installed_and_suggests_close_match():
    with pytest.raises(ScriptError) as info:
        registry.lookup("pair", "dpdd")
    message = str(info.value)
    assert message.startswith("unknown pair style dpdd; did you mean dpd? (installed: ")
    assert "dpd" in message.split("installed: ")[1]


def test_a_broken_plugin_is_reported_in_one_line(tmp_path):
    fake_distribution(tmp_path, "pdps-broken", "pdps.fix", "broken", "no_such_module_xyz:Fix")
    out = run_python("""
        from pdps_core.api import ScriptError, registry
        try:
            registry.lookup("fix", "broken")
        except ScriptError as exc:
            print(exc)
    """, tmp_path, env={"PYTHONPATH": str(tmp_path), "PATH": ""})
    assert out == "fix style broken from pdps-broken failed to import: No module named 'no_such_module_xyz'"


def test_a_repeated_keyword_of_several_words_collects_each_use():
    from pydantic import Field

    from pdps_core.api import StyleArgs, keyword, parse_args

    class Args(StyleArgs):
        gamma: float = Field(ge=0)
        scale: list[tuple[int, float]] = keyword(default_factory=list)

    args = parse_args(Args, ["0.5", "scale", "1", "2.0", "scale", "3", "0.5"])
    assert args.scale == [(1, 2.0), (3, 0.5)]
    with pytest.raises(ScriptError, match=r"keyword scale needs 2 value\(s\) \(got 1\)"):
        parse_args(Args, ["0.5", "scale", "1"])
