"""info against LIGGGHTS 3.8.0: the script of benchmarks/liggghts_references/info_lines.py asks
``info all`` before a run and ``info sys comm groups`` after ``run 0``; every fact LIGGGHTS printed
there (tests/data/liggghts_info.txt) that pdps has is printed by pdps too, line by line, after the
differences pdps_core/commands/info.py names: the style's two names, LIGGGHTS's thermo computes,
its "Xlo, zhi" spelling, its variable styles one place off, the lines of what pdps has not. Then
where the lines go (screen, log, a file appended to or overwritten) and an unknown word's warning."""

import io
import re
import sys
from pathlib import Path

from pdps_core.api import Simulation

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "benchmarks" / "liggghts_references"))
from info_lines import SCRIPT, kept  # noqa: E402

# the lines of what pdps has not (an atom map) or has of its own (the MPI level, its version)
NOT_COMPARED = ("Atom map", "MPI library level", "pdps version")
# its variable style table is one place off its enum (info.cpp): the style it prints -> the style given
LIGGGHTS_VARIABLE_STYLE = {"format": "equal", "equal": "atom", "string": "string"}


def liggghts_facts(lines):
    facts = []
    for line in lines:
        line = line.rstrip()
        if line.startswith(NOT_COMPARED) or "thermo_temp" in line or "thermo_kin_eng" in line:
            continue
        line = line.replace("Atom style = granular", "Atom style = sphere")
        line = line.replace("Xlo, zhi", "Xlo, xhi").replace("Ylo, zhi", "Ylo, yhi")
        line = re.sub(r"    Nthreads = \d+$", "", line)
        facts.append(variable(line, LIGGGHTS_VARIABLE_STYLE))
    return facts


def pdps_facts(lines):
    return [variable(line.rstrip(), None) for line in lines if not line.startswith(NOT_COMPARED)]


def variable(line, styles):
    """A Variable[k] line as (k, name, style, definition); LIGGGHTS's styles read through ``styles``
    and the "(null)" it writes after an equal-style definition left out."""
    match = re.match(r"Variable\[ *(\d+)\]: (\S+) +style = (\S+) +def = (.*?)( \(null\))?$", line)
    if not match:
        return line
    style = styles[match.group(3)] if styles else match.group(3)
    return (int(match.group(1)), match.group(2), style, match.group(4))


def renumbered(facts):
    """Compute[k] counted again (LIGGGHTS's two thermo computes come first in its list)."""
    out, k = [], 0
    for line in facts:
        if isinstance(line, str) and line.startswith("Compute["):
            line = re.sub(r"^Compute\[ *\d+\]", f"Compute[{k:3d}]", line)
            k += 1
        out.append(line)
    return out


def test_info_prints_the_facts_liggghts_prints(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "in.info").write_text(SCRIPT)
    Simulation(screen=False, log=None, dialect="liggghts").file(str(tmp_path / "in.info"))
    recorded = (ROOT / "tests" / "data" / "liggghts_info.txt").read_text().split("== after\n")
    before, after = recorded[0].splitlines()[1:], recorded[1].splitlines()
    assert "Fix[  5]: integr,  style = nve/sphere,  group = all" in before
    ours_before = pdps_facts(kept((tmp_path / "info.before").read_text()))
    assert ours_before == renumbered(liggghts_facts(before))
    assert pdps_facts(kept((tmp_path / "info.after").read_text())) == liggghts_facts(after)


def test_the_lines_go_where_out_says(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    screen = io.StringIO()
    sim = Simulation(screen=screen, log=str(tmp_path / "log.pdps"), dialect="liggghts")
    sim.command("region box block 0 1 0 2 0 3 units box\ncreate_box 1 box\ngroup g1 empty\n"
                "info grou\ninfo gro out log\ninfo groups out append info.txt\ninfo grou out app info.txt\n"
                "info reg out overwrite other.txt\ninfo grouping bogus gr\n")
    assert screen.getvalue().count("Group[ 1]: g1") == 2      # the first and the last (a prefix)
    assert (tmp_path / "log.pdps").read_text().count("Group[ 1]: g1") == 1
    assert (tmp_path / "info.txt").read_text().count("Group[ 1]: g1") == 2
    other = (tmp_path / "other.txt").read_text()
    assert "Region[  0]: box,  style = block,  side = in" in other and "Group" not in other
    assert sim.warnings == ["Ignoring unknown or incorrect info command flag bogus",
                            "Ignoring unknown or incorrect info command flag gr"]       # LIGGGHTS reads 3 letters
