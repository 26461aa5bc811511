"""Styles come from entry points, are imported only when a script names them, and a name claimed
by two distributions is an error that names both. A plugin declares the style API range it
supports (PDPS_API) and is refused outside it; a distribution that fails to import breaks only the
scripts naming its styles; PDPS_DISABLE_PLUGINS switches distributions off."""

import os
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
        print(sim.neighbor.builds, len(sim.neighbor.requests), sim.particles.nghost)
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
        print(sim.neighbor.builds > 0, "pdps_pair_dpd.dpd" in sys.modules)
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
    assert ("pair", "dpd", "pdps-pair-dpd", "0.1.0") in rows
    assert ("fix", "nve", "pdps-fix-nve", "0.1.0") in rows
    assert ("compute", "temp", "pdps-compute-thermo", "0.1.0") in rows
    assert ("region", "block", "pdps-region-shapes", "0.1.0") in rows
    assert ("dump", "atom", "pdps-dump-text", "0.1.0") in rows


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
    assert out == ("fix style broken from pdps-broken 1.0 failed to import: "
                   "ModuleNotFoundError: No module named 'no_such_module_xyz'")


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


# ---- versions and isolation: distributions as installed (dist-info with entry points) -------------
BOX = "region box block 0 4 0 4 0 4\ncreate_box 1 box\nmass 1 1\n"

KICK = '''
from pdps_core.api import Fix


class FixKick(Fix):
    name = "kick"

    def end_of_step(self, sim):
        sim.particles.v[: sim.particles.nlocal, 0] += 1.0
'''


def plugin(root, dist, package, style, init, module=KICK):
    """An installed plugin distribution ``dist`` (version 1.0) whose package ``package`` has the
    given ``__init__.py`` and one fix style ``style`` in ``kick.py``."""
    (root / package).mkdir()
    (root / package / "__init__.py").write_text(init)
    (root / package / "kick.py").write_text(module)
    fake_distribution(root, dist, "pdps.fix", style, f"{package}.kick:FixKick")


def pdps(root, *argv, script=None, env=None):
    """The ``pdps`` command in ``root`` with the plugins there installed (on PYTHONPATH)."""
    if script is not None:
        (root / "in.test").write_text(script)
        argv = ("run", "in.test", "-log", "none", *argv)
    return subprocess.run([sys.executable, "-m", "pdps_core.cli", *argv], cwd=root, capture_output=True,
                          text=True, timeout=600, env={**os.environ, "PYTHONPATH": str(root), **(env or {})})


def styles_rows(result):
    """`pdps styles` rows by (kind, name): the rest of the row after the distribution's version."""
    assert result.returncode == 0, result.stderr
    rows = {}
    for line in result.stdout.splitlines():
        kind, name, dist, version, *status = line.split(maxsplit=4)
        rows[(kind, name)] = (dist, version, status[0] if status else "")
    return rows


def test_a_plugin_for_another_style_api_is_refused_by_name_before_its_module_is_imported(tmp_path):
    # kick.py imports a name this API does not have: the version check comes first and says why
    plugin(tmp_path, "pdps-fix-future", "pdps_fix_future", "kick/future", 'PDPS_API = ">=2,<3"\n',
           module="from pdps_core.api import Spacetime\n" + KICK)
    expected = ("fix style kick/future from pdps-fix-future 1.0 supports style API >=2,<3; "
                "this pdps has style API 1.0")
    result = pdps(tmp_path, script=BOX + "fix 1 all kick/future\n")
    assert (result.returncode, result.stderr) == (1, f"ERROR: in.test:4: fix: {expected}\n")
    rows = styles_rows(pdps(tmp_path, "styles"))
    assert rows[("fix", "kick/future")] == (
        "pdps-fix-future", "1.0", "incompatible: supports style API >=2,<3; this pdps has style API 1.0")
    assert rows[("fix", "nve")] == ("pdps-fix-nve", "0.1.0", "")


def test_a_plugin_in_range_is_used_and_one_without_a_range_is_refused(tmp_path):
    plugin(tmp_path, "pdps-fix-now", "pdps_fix_now", "kick/now", 'PDPS_API = ">=1.0,<2"\n')
    plugin(tmp_path, "pdps-fix-old", "pdps_fix_old", "kick/old", '"""written before style API versions"""\n')
    out = run_python("""
        from pdps_core.api import ScriptError, Simulation
        sim = Simulation(screen=False, log=None)
        sim.command("region box block 0 4 0 4 0 4\\ncreate_box 1 box\\nmass 1 1\\n"
                    "create_particle 1 single 1 1 1\\nfix 1 all kick/now\\nrun 3")
        print(sim.particles.v[0, 0])
        try:
            sim.command("fix 2 all kick/old")
        except ScriptError as exc:
            print(exc)
    """, tmp_path, env={**os.environ, "PYTHONPATH": str(tmp_path)})
    assert out.splitlines() == [
        "3.0",
        "<command>:1: fix: fix style kick/old from pdps-fix-old 1.0 declares no style API range (PDPS_API in "
        "pdps_fix_old/__init__.py); this pdps has style API 1.0"]


@pytest.mark.parametrize("declared, reason", [
    ('">=0.1,<1"', "supports style API >=0.1,<1"),
    ('"==1.*"', ""),
    ('"1.0 or later"', "declares style API '1.0 or later', not a version range such as '>=1.0,<2' "
                       "(PDPS_API in pkg/__init__.py)"),
    ("(1, 0)", "declares style API (1, 0), not a version range such as '>=1.0,<2' "
               "(PDPS_API in pkg/__init__.py)"),
])
def test_declared_ranges_are_read_as_pep_440_specifiers(declared, reason):
    from pdps_core.styles import PluginError, check_api
    value = eval(declared)
    if not reason:
        check_api(value, "fix style x from pkg 1.0", "pkg/__init__.py")
        return
    with pytest.raises(PluginError) as info:
        check_api(value, "fix style x from pkg 1.0", "pkg/__init__.py")
    assert str(info.value) == f"fix style x from pkg 1.0 {reason}; this pdps has style API 1.0"
    assert info.value.status == "incompatible"


def test_a_distribution_that_fails_to_import_breaks_only_the_scripts_naming_its_styles(tmp_path):
    plugin(tmp_path, "pdps-fix-gpu", "pdps_fix_gpu", "kick/gpu", 'PDPS_API = ">=1.0,<2"\n',
           module='raise RuntimeError("no GPU found:\\n  check the driver")\n')
    fine = pdps(tmp_path, script=BOX + "create_particle 1 single 1 1 1\nfix 1 all nve\nrun 2\n")
    assert (fine.returncode, fine.stderr) == (0, "")
    broken = pdps(tmp_path, script=BOX + "fix 1 all kick/gpu\n")
    assert (broken.returncode, broken.stderr) == (
        1, "ERROR: in.test:4: fix: fix style kick/gpu from pdps-fix-gpu 1.0 failed to import: "
           "RuntimeError: no GPU found: check the driver\n")
    rows = styles_rows(pdps(tmp_path, "styles"))
    assert rows[("fix", "kick/gpu")] == ("pdps-fix-gpu", "1.0", "broken: RuntimeError: no GPU found: check the driver")
    assert rows[("pair", "dpd")] == ("pdps-pair-dpd", "0.1.0", "")


def test_disabled_distributions_are_unknown_to_scripts_and_shown_as_disabled(tmp_path):
    env = {"PDPS_DISABLE_PLUGINS": "pdps-fix-nve, PDPS_Dump_Text"}     # names as pip compares them
    result = pdps(tmp_path, script=BOX + "fix 1 all nve\n", env=env)
    assert result.returncode == 1
    assert result.stderr.startswith("ERROR: in.test:4: fix: unknown fix style nve: pdps-fix-nve is switched "
                                    "off by PDPS_DISABLE_PLUGINS; did you mean nvt? (installed: ")
    assert " nve," not in result.stderr and "nve/limit" in result.stderr
    other = pdps(tmp_path, script=BOX + "create_particle 1 single 1 1 1\nfix 1 all nve/limit 0.1\nrun 2\n",
                 env=env)
    assert (other.returncode, other.stderr) == (0, "")
    rows = styles_rows(pdps(tmp_path, "styles", env=env))
    assert rows[("fix", "nve")] == ("pdps-fix-nve", "0.1.0", "disabled (PDPS_DISABLE_PLUGINS)")
    assert rows[("dump", "custom")] == ("pdps-dump-text", "0.1.0", "disabled (PDPS_DISABLE_PLUGINS)")
    assert rows[("fix", "nve/limit")] == ("pdps-fix-granular", "0.1.0", "")
