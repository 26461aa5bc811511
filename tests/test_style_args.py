"""Style arguments as styles declare them: the shapes ``parse_args`` reads (a choice whose first word
picks how many values follow, counted lists, placeholders, repeated keywords), the one-line errors,
and the ``pdps.api`` word readers."""

from typing import Literal

import pytest

from pdps_core.api import (FloatOrVariable, ScriptError, StyleArgs, VariableRef, choice, integer, keyword, number,
                           param, parse_args, yes_no)

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
    with pytest.raises(ScriptError, match=r"^direction must be vector number number number or chute number or "
                                          r"spherical number number \(got sideways 1\)$"):
        parse_args(Gravity, "9.81 sideways 1".split())
    with pytest.raises(ScriptError, match=r"^direction must be .* \(got vector 1 2\)$"):
        parse_args(Gravity, "9.81 vector 1 2".split())


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
    ("xlo 1 xhi", "walls: xhi needs a value (xlo|xhi|ylo|yhi number|EDGE)"),
    ("sideways xlo 1", "walls: expected xlo, xhi, ylo, yhi (got sideways)"),
    ("xlo 1 xhi abc", "walls xhi must be a finite number or EDGE (got abc)"),
    ("xlo 1e60", "walls must be 0 or of magnitude from 1e-50 to 1e+50 (got 1e+60)"),
    ("specular units box", "missing argument walls"),
])
def test_a_bad_entry_of_a_run_is_named_by_its_first_word(words, message):
    with pytest.raises(ScriptError) as error:
        parse_args(Walls, words.split())
    assert str(error.value).split("; usage")[0] == message
