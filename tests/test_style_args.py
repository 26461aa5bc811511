"""Style arguments as styles declare them: the shapes ``parse_args`` reads (a choice whose first word
picks how many values follow, counted lists, placeholders, repeated keywords), the one-line errors,
and the ``pdps.api`` word readers."""

import typing
from typing import Annotated, Literal

import pytest

from pdps_core.api import (FloatOrVariable, ScriptError, StyleArgs, StyleName, VariableRef, choice, integer, keyword, number,
                           param, parse_args, registry, yes_no)
from pdps_core.styledoc import document, models, names_of, unit_of
from pdps_core.styles import IN_PROCESS, KINDS, StyleEntry, member_names

Direction = (tuple[Literal["vector"], float, float, float] | tuple[Literal["chute"], float]
             | tuple[Literal["spherical"], float, float])


class Gravity(StyleArgs):
    magnitude: float = param(unit="acceleration")
    direction: Direction = param(unit={"vector": "dimensionless", "chute": "degrees", "spherical": "degrees"})
    region: str | None = keyword(None)


def test_the_first_word_of_a_choice_picks_how_many_values_follow():
    assert parse_args(Gravity, "9.81 vector 0 0 -1".split()).direction == ("vector", 0.0, 0.0, -1.0)
    assert parse_args(Gravity, "9.81 chute 24 region r".split()).direction == ("chute", 24.0)
    assert parse_args(Gravity, "1 spherical 10 20".split()).direction == ("spherical", 10.0, 20.0)


def test_a_bad_value_of_a_choice_names_the_argument_and_the_word():
    with pytest.raises(ScriptError, match=r"^direction must be a finite number \(got x\)$"):
        parse_args(Gravity, "9.81 chute x".split())
    with pytest.raises(ScriptError, match=r"^direction must be one of vector, chute, spherical \(got sideways\)$"):
        parse_args(Gravity, "9.81 sideways 1".split())
    with pytest.raises(ScriptError, match=r"^direction vector takes 3 value\(s\): number number number "
                                          r"\(got 1 2\)$"):
        parse_args(Gravity, "9.81 vector 1 2".split())
    with pytest.raises(ScriptError, match=r"^direction chute takes 1 value\(s\): number \(got nothing\)$"):
        parse_args(Gravity, "9.81 chute region r".split())


class Bodies(StyleArgs):
    bodystyle: Literal["single", "molecule"] | tuple[Literal["group"], int, tuple[str, ...]] = param()
    langevin: tuple[float, float, float, int] | None = keyword(
        None, unit=("temperature", "temperature", "time", "dimensionless"))


def test_a_count_reads_that_many_words():
    assert parse_args(Bodies, ["single"]).bodystyle == "single"
    args = parse_args(Bodies, "group 2 langevin clump langevin 1 1 1 5".split())
    assert args.bodystyle == ("group", 2, ("langevin", "clump"))
    assert args.langevin == (1.0, 1.0, 1.0, 5)
    with pytest.raises(ScriptError, match=r"^bodystyle group 3 needs 3 value\(s\) after 3 \(got 2\)$"):
        parse_args(Bodies, "group 3 a b".split())


class Wall(StyleArgs):
    xlo: float | Literal["EDGE", "NULL"] | VariableRef = keyword(None, unit="distance")
    side: list[tuple[Literal["xlo", "xhi"], float]] = keyword(default_factory=list, unit=("1", "distance"))


def test_placeholders_are_declared_words():
    assert parse_args(Wall, "xlo EDGE".split()).xlo == "EDGE"
    assert parse_args(Wall, "xlo 0.5".split()).xlo == 0.5
    with pytest.raises(ScriptError, match=r"^xlo must be a finite number or EDGE\|NULL or v_NAME \(got edge\)$"):
        parse_args(Wall, "xlo edge".split())


def test_a_repeated_keyword_keeps_each_use_in_order():
    assert parse_args(Wall, "side xlo 1 side xhi 2".split()).side == [("xlo", 1.0), ("xhi", 2.0)]
    with pytest.raises(ScriptError, match=r"^side must be one of 'xlo' or 'xhi' \(got ylo\)$"):
        parse_args(Wall, "side ylo 1".split())


class Kick(StyleArgs):
    kx: FloatOrVariable = param(unit="force")


def test_a_float_or_variable_error_names_the_argument_not_the_type():
    assert parse_args(Kick, ["v_push"]).kx == VariableRef("push")
    with pytest.raises(ScriptError, match=r"^kx must be a finite number or v_NAME \(got push\)$"):
        parse_args(Kick, ["push"])


def test_the_word_readers_of_the_api():
    assert number("2.5", "radius", low=0) == 2.5
    with pytest.raises(ScriptError, match=r"^radius must be >= 0 \(got -1\)$"):
        number("-1", "radius", low=0)
    assert integer("3", "count") == 3
    with pytest.raises(ScriptError, match=r"^count must be an integer \(got 3.5\)$"):
        integer("3.5", "count")
    assert choice("in", "side", ("in", "out")) == "in"
    assert yes_no("no", "flag") is False
    with pytest.raises(ScriptError, match=r"^flag must be one of yes, no \(got maybe\)$"):
        yes_no("maybe", "flag")


Face = Literal["xlo", "xhi", "ylo", "yhi"]


class Walls(StyleArgs):
    style: Literal["specular", "bounce_back"] | None = param(None)
    walls: list[tuple[Face, float | Literal["EDGE"]]] = param(min_length=1, unit=("1", "distance"))
    units: Literal["box", "lattice"] | None = keyword(None)


def test_a_run_of_keyword_value_pairs_keeps_its_order():
    assert parse_args(Walls, "xhi EDGE xlo 0 units box".split()).walls == [("xhi", "EDGE"), ("xlo", 0.0)]
    args = parse_args(Walls, "bounce_back ylo 1".split())
    assert (args.style, args.walls) == ("bounce_back", [("ylo", 1.0)])


@pytest.mark.parametrize("words, message", [
    ("xlo 1 xhi", "walls xhi needs number|EDGE (got nothing)"),
    ("sideways xlo 1", "unknown keyword sideways (known: xlo, xhi, ylo, yhi, units)"),
    ("xlo 1 xhi abc", "walls xhi must be a finite number or EDGE (got abc)"),
    ("xlo 1e60", "walls must be 0 or of magnitude from 1e-50 to 1e+50 (got 1e+60)"),
    ("specular units box", "missing argument walls"),
])
def test_a_bad_entry_of_a_run_is_named_by_its_first_word(words, message):
    with pytest.raises(ScriptError) as error:
        parse_args(Walls, words.split())
    assert str(error.value).split("; usage")[0] == message


class Profile(StyleArgs):
    bins: list[tuple[Literal["x", "y", "z"], float, float]] = param(min_length=1, unit=("1", "distance", "distance"))
    values: list[Literal["vx", "density/number"]] = param(min_length=1)
    file: str | None = keyword(None)


def test_a_run_ends_where_the_next_argument_starts():
    args = parse_args(Profile, "z 0 1 x 0.5 2 vx density/number file out".split())
    assert (args.bins, args.values, args.file) == ([("z", 0.0, 1.0), ("x", 0.5, 2.0)], ["vx", "density/number"], "out")
    with pytest.raises(ScriptError, match=r"^missing argument bins \(got vx\)$"):
        parse_args(Profile, "vx".split())
    with pytest.raises(ScriptError, match=r"^values must be one of 'vx' or 'density/number' \(got temp\)$"):
        parse_args(Profile, "z 0 1 vx temp".split())


class Hybrid(StyleArgs):
    substyles: list[tuple[Annotated[str, StyleName("pair")], tuple[str, ...]]] = param(min_length=1, names="style, args")


def test_a_style_name_opens_a_section_up_to_the_next_one():
    assert parse_args(Hybrid, "lj/cut 2.5 soft 1.12 table linear 100".split()).substyles == [
        ("lj/cut", ("2.5",)), ("soft", ("1.12",)), ("table", ("linear", "100"))]
    with pytest.raises(ScriptError, match=r"^substyles must start with the name of a pair style \(got 2.5\)$"):
        parse_args(Hybrid, "2.5 lj/cut".split())


class Placed(StyleArgs):
    placement: list[tuple[Literal["scale"], float] | tuple[Literal["move"], float, float, float]] = keyword(
        default_factory=list, spelled_by_entries=True, unit={"scale": "1", "move": "distance"})
    type: int = keyword(1, unit="1")


def test_entries_spelled_by_their_own_words_keep_their_order_across_words():
    args = parse_args(Placed, "move 1 0 0 scale 2 type 2 scale 3".split())
    assert args.placement == [("move", 1.0, 0.0, 0.0), ("scale", 2.0), ("scale", 3.0)]
    assert parse_args(Placed, "scale 2 move 1 0 0".split()).placement == [("scale", 2.0), ("move", 1.0, 0.0, 0.0)]
    with pytest.raises(ScriptError, match=r"^keyword move needs 3 value\(s\) \(got 1 2\)$"):
        parse_args(Placed, "move 1 2 type 1".split())
    with pytest.raises(ScriptError, match=r"^placement scale must be a finite number \(got x\)$"):
        parse_args(Placed, "scale x".split())
    with pytest.raises(ScriptError, match=r"^unknown keyword placement \(known: type, scale, move\)$"):
        parse_args(Placed, "placement 2".split())


class Law(StyleArgs):
    model: (tuple[Literal["lsd"], float, float, float, float] | tuple[Literal["lsd"], float, float]
            | tuple[Literal["hertz"], float]) = keyword(..., unit={"lsd": "1", "hertz": "pressure"})


def test_a_word_that_picks_tuples_of_two_lengths_is_named_once():
    assert parse_args(Law, "model lsd 1 2".split()).model == ("lsd", 1.0, 2.0)
    assert parse_args(Law, "model lsd 1 2 3 4".split()).model == ("lsd", 1.0, 2.0, 3.0, 4.0)
    with pytest.raises(ScriptError, match=r"^model must be one of lsd, hertz \(got jkr\)$"):
        parse_args(Law, "model jkr 1".split())
    with pytest.raises(ScriptError, match=r"^model lsd takes number number number number or number number "
                                          r"\(got 1\)$"):
        parse_args(Law, "model lsd 1".split())


class Walled(StyleArgs):
    model: Literal["lsd"] = param()
    region: list[tuple[Literal["region"], str]] = param(default_factory=list, names="region ID")
    law: tuple[float, float, float] = param(unit="1")


class Written(StyleArgs):
    output: tuple[Literal["output"], Literal["face"]] | None = param(None)
    values: list[Literal["stress", "area"]] = param(default_factory=list)
    meshes: list[str] = param(default_factory=list, names="mesh ID")


def test_a_run_that_another_argument_follows_ends_at_a_word_that_starts_no_entry():
    args = parse_args(Walled, "lsd region a region b 1 2 3".split())
    assert (args.region, args.law) == ([("region", "a"), ("region", "b")], (1.0, 2.0, 3.0))
    assert parse_args(Walled, "lsd 1 2 3".split()).region == []
    with pytest.raises(ScriptError, match=r"^region region needs word \(got nothing\)$"):
        parse_args(Walled, "lsd region".split())
    args = parse_args(Written, "stress area a b".split())
    assert (args.output, args.values, args.meshes) == (None, ["stress", "area"], ["a", "b"])
    args = parse_args(Written, "output face area b".split())
    assert (args.output, args.values, args.meshes) == (("output", "face"), ["area"], ["b"])
    with pytest.raises(ScriptError, match=r"^output must be one of 'face' \(got interpolate\)$"):
        parse_args(Written, "output interpolate stress".split())


class Seeded(StyleArgs):
    seed: int = keyword(..., ge=1, unit="1")
    region: str | None = keyword(None, names="region ID")


def test_a_keyword_without_a_default_must_be_given():
    assert parse_args(Seeded, "region r seed 5".split()).seed == 5
    with pytest.raises(ScriptError, match=r"^missing keyword seed; usage: fix ID all insert seed S$"):
        parse_args(Seeded, "region r".split(), "fix ID all insert seed S")


# ---- every style of the registry declares its arguments ------------------------------------------
def _numeric(annotation):
    """Whether a value of ``annotation`` holds a number anywhere (a tuple member, a union member)."""
    if annotation in (float, int, VariableRef):
        return True
    if member_names(annotation):
        return any(_numeric(member) for member in typing.get_type_hints(annotation).values())
    return any(_numeric(member) for member in typing.get_args(annotation) if isinstance(member, type)
               or typing.get_args(member))


def _raw_words(annotation):
    """A list or tuple of bare words: ``list[str]``, ``tuple[str, ...]``, or either inside a union,
    a tuple or a list."""
    origin, members = typing.get_origin(annotation), typing.get_args(annotation)
    if origin in (list, tuple) and members and members[0] is str and (origin is list or members[-1] is Ellipsis):
        return True
    return any(_raw_words(member) for member in members if typing.get_args(member))


def _styles():
    """Every installed style (not those tests register in process)."""
    return sorted({(entry.kind, entry.name) for entry in registry.entries()
                   if entry.dist != IN_PROCESS and not entry.disabled}, key=lambda e: (registry.kinds().index(e[0]), e[1]))


def _hand_parsed(cls):
    """Whether the style, or a plugin class it derives from, reads its words with its own ``parse``."""
    return any("parse" in vars(klass) for klass in cls.__mro__ if not klass.__module__.startswith("pdps_core"))


@pytest.mark.parametrize("kind, name", _styles())
def test_every_style_declares_each_argument_with_its_unit(kind, name):
    cls = registry.lookup(kind, name)
    problems = ["reads its words by hand (overrides parse)"] if _hand_parsed(cls) else []
    for attr, model in models(cls):
        for field, info in model.model_fields.items():
            label = f"{attr}.{info.alias or field}"
            if _raw_words(info.annotation) and not names_of(info):
                problems.append(f"{label} is a list of raw words (declare each value, or names=...)")
            if _numeric(info.annotation) and not unit_of(info):
                problems.append(f"{label} is a number without a unit")
    assert not problems, f"{kind} {name}: " + "; ".join(problems)


@pytest.mark.parametrize("kind, name", _styles())
def test_pdps_doc_shows_every_parameter_with_its_unit(kind, name):
    cls = registry.lookup(kind, name)
    page = document(StyleEntry(kind, name, "pdps-test", "1.0", ""), cls)
    lines = page.splitlines()
    for attr, model in models(cls):
        for field, info in model.model_fields.items():
            label = info.alias or field
            shown = [line for line in lines if line.startswith((f"- {label}: ", f"- {label} (keyword): "))]
            assert shown, f"pdps doc {kind} {name} does not show {attr}.{label}"
            if unit_of(info):
                assert any(f"unit: {unit_of(info)}" in line for line in shown), shown
