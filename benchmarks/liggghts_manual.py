"""The LIGGGHTS manual's commands and styles, item by item, and what pdps makes of each (issue 33).

    .venv/bin/python benchmarks/liggghts_manual.py [--print]

The items are the headings of LIGGGHTS 3.8.0's manual pages (Debian's ``liggghts-doc``, fetched
into build/corpus/ as ``make corpus`` does): "NAME command" (``fix insert/pack command``, ``run
command``) and the contact sub-models' "gran KIND NAME model" (``gran model hertz model``), each
once. For each, pdps's answer without running anything:
- ``style``: pdps has a style of that kind and name (installed plugins; for a sub-model, a
  sub-model of pair gran), or ``command``: a command of that name;
- ``refused``: a line naming it stops with a reason (pdps_core.script.unsupported);
- ``unknown``: neither; a script reaching it stops at "unknown command" or "unknown fix style".
What "works fully" needs beyond being known (its options, its numbers against LIGGGHTS's) is the
next column, filled in docs/liggghts.md item by item; this tool gives the first.

The manual is LIGGGHTS's (GPL): it is read where it is unpacked, never copied; the table holds names.
"""

import argparse
import gzip
import re
import sys
from pathlib import Path

from pdps_core.api import registry
from pdps_core.commands import COMMANDS
from pdps_core.script.unsupported import ALTERNATIVES, unsupported_style

sys.path.insert(0, str(Path(__file__).resolve().parent))
import corpus  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
PAGE = ROOT / "docs" / "liggghts.md"
BEGIN, END = "<!-- manual:begin -->", "<!-- manual:end -->"
# heading words -> pdps's style kind
KINDS = {"fix": "fix", "compute": "compute", "pair_style": "pair", "dump": "dump", "region": "region"}
# "gran KIND NAME model" -> the sub-model kind of pdps's pair gran
SUBMODELS = {"model": "gran.normal", "tangential": "gran.tangential", "cohesion": "gran.cohesion",
             "rolling_friction": "gran.rolling", "surface": "gran.surface"}
HEADING = re.compile(r"^(?P<words>[a-z_][a-z0-9_/ ]*?)\s+(?P<end>command|model)\s*:h3")
# the CFD coupling the issue leaves out
COUPLING = ("couple/cfd", "continuum/weighted")


def pages(doc):
    for path in sorted(doc.glob("*.txt")) + sorted(doc.glob("*.txt.gz")):
        opener = gzip.open if path.suffix == ".gz" else open
        with opener(path, "rt", errors="replace") as text:
            yield text.read()


def items(texts):
    """(family, name) of each heading, sorted, once each: ("fix", "adapt"), ("run", None),
    ("gran", "model hertz")."""
    found = set()
    for text in texts:
        for line in text.splitlines():
            match = HEADING.match(line.strip())
            if not match:
                continue
            words = match.group("words").split()
            if match.group("end") == "model":
                if words[0] == "gran" and len(words) == 3:
                    found.add(("gran", " ".join(words[1:])))
            elif len(words) == 1:
                found.add((words[0], None))
            elif len(words) == 2:
                found.add((words[0], words[1]))
    return sorted(found, key=lambda item: (item[0], item[1] or ""))


def known_styles(kind):
    return set(registry.names(kind))


def answer(family, name, styles):
    """(pdps's answer, detail) for one item."""
    if name in COUPLING:
        return "coupling", "CFD coupling (out of the issue)"
    if family == "gran":
        kind, _, sub = name.partition(" ")
        sub = "default" if (kind, sub) == ("surface", "sphere") else sub
        return ("style", "") if sub in registry.names(SUBMODELS[kind]) else ("unknown", "")
    if (family, name) == ("pair_style", "none"):
        return "command", "pair_style none"
    kind = KINDS.get(family)
    if name is None or kind is None:
        command = family if name is None else family
        if command in COMMANDS:
            return "command", "" if name is None else f"{family} {name}"
        if command in ALTERNATIVES:
            return "refused", ALTERNATIVES[command]
        return "unknown", ""
    if name in styles[kind]:
        return "style", ""
    alternative = unsupported_style(kind, name)
    if alternative:
        return "refused", alternative
    return "unknown", ""


def table(texts):
    styles = {kind: known_styles(kind) for kind in KINDS.values()}
    rows = [(family, name, *answer(family, name, styles)) for family, name in items(texts)]
    counted = [r for r in rows if r[2] != "coupling"]
    known = sum(r[2] in ("style", "command") for r in counted)
    refused = sum(r[2] == "refused" for r in counted)
    lines = ["| item | pdps |", "|---|---|"]
    for family, name, status, detail in rows:
        lines.append(f"| `{family}{' ' + name if name else ''}` | {status}{': ' + detail if detail else ''} |")
    lines += ["", f"{len(counted)} items (CFD coupling left out): {known} known to pdps, {refused} refused with "
                  f"a reason, {len(counted) - known - refused} unknown."]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--doc", help="an unpacked liggghts/doc folder instead of build/corpus's")
    parser.add_argument("--print", action="store_true", help="print the table, leave docs/ as it is")
    args = parser.parse_args()
    doc = Path(args.doc) if args.doc else corpus.doc_folder(None).parents[2] / "doc"
    text = table(pages(doc))
    if args.print:
        print(text)
        return
    page = PAGE.read_text()
    head, rest = page.split(BEGIN, 1)
    PAGE.write_text(head + BEGIN + "\n" + text + "\n" + END + rest.split(END, 1)[1])


if __name__ == "__main__":
    main()
