"""Base classes for styles, their script arguments, and the entry-point registry.

A style is a class with a ``name``, an ``Args`` pydantic model for its script arguments, and the hooks
it implements. Arguments are read from the script words in the order the model declares its fields;
a field made with ``keyword(...)`` is an optional ``name value...`` pair instead (a ``list[tuple[...]]`` keyword may be repeated). A field's ``alias`` is
the name scripts and messages use (``Field(0.5, alias="lambda")`` for a Python keyword). A ``tuple[...]`` field
takes as many words as it has members; a ``list[...]`` positional field takes every word left.

Styles are found through the entry-point groups ``pdps.pair``, ``pdps.fix``, ``pdps.compute``,
``pdps.analyze``, ``pdps.dump`` and ``pdps.region``; the entry-point name is the style name. Listing
styles reads package metadata only: a style's module is imported the first time a script names it.
"""

import difflib
import importlib
import math
import os
import re
import types
import typing
from dataclasses import dataclass
from importlib import metadata
from typing import ClassVar

import numpy as np
from packaging.specifiers import InvalidSpecifier, SpecifierSet
from packaging.utils import canonicalize_name
from packaging.version import Version
from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, ValidationError, field_validator
from pydantic_core import PydanticCustomError, core_schema

from .errors import ScriptError, SimulationError
from .state import limits

KINDS = ("pair", "bond", "fix", "compute", "analyze", "dump", "region")
TALLY = "pair_tally"    # the per-particle (energy, 6 virial components) array of Compute.peratom_tally


# ---- script arguments ---------------------------------------------------------------------------
@dataclass(frozen=True)
class VariableRef:
    """A style argument written ``v_NAME``: read it with ``sim.evaluate(arg)`` each time it is used."""
    name: str

    def __str__(self):
        return f"v_{self.name}"


def _number_or_variable(word):
    if isinstance(word, str) and word.startswith("v_") and len(word) > 2:
        return VariableRef(word[2:])
    return word


# A float argument that may also be given as v_NAME (an equal-style variable evaluated when read),
# as LAMMPS's fix addforce, setforce and the like allow.
FloatOrVariable = typing.Annotated[float | VariableRef, BeforeValidator(_number_or_variable)]


def _variable_only(word):
    if isinstance(word, str):
        if not (word.startswith("v_") and len(word) > 2):
            raise PydanticCustomError("variable", "expected a variable v_NAME (got {word})", {"word": word})
        return VariableRef(word[2:])
    return word


# An argument that must be a variable, written v_NAME (fix adapt's settings).
Variable = typing.Annotated[VariableRef, BeforeValidator(_variable_only)]


class StyleName:
    """``Annotated[str, StyleName("pair")]``: a word naming an installed style of a kind. As the first
    member of a run's entry (``tuple[Annotated[str, StyleName("pair")], tuple[str, ...]]``) it opens
    a section that takes the words up to the next style name: pair hybrid's sub-styles, each with
    the words its own ``parse`` reads. For a sub-model kind (``StyleName("gran.rolling", also=("off",))``)
    the word is one of the installed sub-models' names or of ``also``, told as a choice is."""

    def __init__(self, kind, also=()):
        self.kind = kind
        self.also = tuple(also)

    def names(self):
        return self.also + tuple(name for name in registry.names(self.kind) if name not in self.also)

    def __get_pydantic_core_schema__(self, source, handler):
        def installed(word):
            if word not in self.names():
                if is_sub_model_kind(self.kind) and not registry.names(self.kind):
                    raise PydanticCustomError("style_name", f"names no installed {self.kind} sub-model (none is)")
                if is_sub_model_kind(self.kind):
                    quoted = [f"'{name}'" for name in self.names()]
                    expected = " or ".join([", ".join(quoted[:-1]), quoted[-1]] if len(quoted) > 1 else quoted)
                    raise PydanticCustomError("literal_error", "must be one of {expected}", {"expected": expected})
                raise PydanticCustomError("style_name", f"must name an installed {self.kind} style")
            return word
        return core_schema.no_info_after_validator_function(installed, handler(source))


def _style_name(annotation):
    """The StyleName an ``Annotated`` member carries, or None."""
    if typing.get_origin(annotation) is typing.Annotated:
        return next((m for m in annotation.__metadata__ if isinstance(m, StyleName)), None)
    return None


class StyleArgs(BaseModel):
    """Base of every ``Args`` model: no NaN/inf, no unknown fields, immutable; every number 0 or of
    a magnitude from 1e-50 to 1e50 (``limits.MIN_SIZE``, ``MAX_SIZE``), whatever its unit, so that
    products and quotients of a few of them stay finite and nonzero."""
    model_config = ConfigDict(allow_inf_nan=False, extra="forbid", frozen=True, populate_by_name=True)

    @field_validator("*", mode="after")
    @classmethod
    def _representable(cls, value, info):
        for number in _numbers(value):
            if number != 0.0 and not limits.MIN_SIZE <= abs(number) <= limits.MAX_SIZE:
                bounds = {"low": limits.MIN_SIZE, "high": limits.MAX_SIZE}
                if not isinstance(value, float):
                    bounds["value"] = number        # the one number of several that is out of range
                raise PydanticCustomError("magnitude", "must be 0 or of magnitude from {low:g} to {high:g}", bounds)
        return value


def _numbers(value):
    """The floats in a value, at any depth of lists and tuples (runs of entries, repeated keywords)."""
    if isinstance(value, float):
        yield value
    elif isinstance(value, (list, tuple)):
        for item in value:
            yield from _numbers(item)


# the kinds of quantity LAMMPS's ``units`` command names, and counts; a unit of ``param`` is one of
# these or a product/quotient of them ("force/velocity", "mass/time", "1/distance")
UNIT_KINDS = frozenset({
    "mass", "distance", "time", "energy", "velocity", "force", "torque", "temperature", "pressure",
    "dynamic viscosity", "charge", "dipole", "electric field", "density", "acceleration", "area",
    "volume", "angle", "degrees", "dimensionless", "timesteps", "particles", "1",
    # the values of a property another style reads and gives the unit of (fix property/atom, /global),
    # and the parameters of a formula the script writes (pair formula), in the units it needs
    "as the property", "as the formula"})


def _check_unit(unit):
    parts = [part.strip() for part in unit.replace("*", "/").split("/")]
    unknown = [part for part in parts if part not in UNIT_KINDS]
    if unknown:
        raise ValueError(f"unit {unit!r}: {unknown[0]!r} is not a kind of quantity "
                         f"(known: {', '.join(sorted(UNIT_KINDS - {'1'}))}, combined with / or *)")


def param(default=..., *, unit=None, names=None, **field_kwargs):
    """A script argument with the kind of quantity it is: ``cutoff: float = param(gt=0,
    unit="distance")``; no default (``...``) makes it required. ``unit`` is a kind as LAMMPS's
    ``units`` command names them ("distance", "energy", "force/velocity", "dimensionless", ...),
    or a tuple of kinds, one per member of a ``tuple[...]`` field whose members differ
    (``unit=("temperature", "temperature", "time", "1")``), or for a choice of tuples picked by
    their first word the kinds of each (``unit={"vector": "1", "chute": "degrees"}``); ``pdps doc`` shows it with the bounds
    and the default. ``names`` says what each word of a list of names is (``names="region ID"``,
    ``names="group ID"``), for a ``list[str]`` that is not a list of raw words. Other keywords are
    pydantic's ``Field`` ones (``gt``, ``ge``, ``lt``, ``le``, ``alias``, ``default_factory``)."""
    extra = dict(field_kwargs.pop("json_schema_extra", None) or {})
    if names is not None:
        extra["names"] = names
    if unit is not None:
        variants = unit if isinstance(unit, dict) else {None: unit}
        shown = {}
        for word, kinds in variants.items():
            kinds = (kinds,) if isinstance(kinds, str) else tuple(kinds)
            for kind in kinds:
                _check_unit(kind)
            shown[word] = " ".join(kinds)
        extra["unit"] = shown[None] if None in shown else "; ".join(f"{w}: {k}" for w, k in shown.items())
    if "default_factory" in field_kwargs:
        return Field(json_schema_extra=extra or None, **field_kwargs)
    return Field(default, json_schema_extra=extra or None, **field_kwargs)


def keyword(default=None, *, unit=None, names=None, spelled_by_entries=False, **kwargs):
    """A field given in the script as ``name value...`` (any order, after the positional words);
    ``unit`` and ``names`` as for ``param``. ``spelled_by_entries``: a ``list`` of a choice of
    tuples picked by their first word, each of those words a keyword of its own (``scale S``,
    ``move DX DY DZ``), every use kept in the one list in the order written (LIGGGHTS applies a
    mesh's placements so)."""
    extra = kwargs.pop("json_schema_extra", {}) or {}
    extra = {**extra, "keyword": True, **({"spelled_by_entries": True} if spelled_by_entries else {})}
    return param(default, unit=unit, names=names, json_schema_extra=extra, **kwargs)


def _is_keyword(info):
    extra = info.json_schema_extra
    return isinstance(extra, dict) and extra.get("keyword", False)


def _entry_spellings(info):
    """{first word: the tuple it picks} of a ``keyword(spelled_by_entries=True)`` field, else {}."""
    extra = info.json_schema_extra
    if not (isinstance(extra, dict) and extra.get("spelled_by_entries")):
        return {}
    entry = _bare(typing.get_args(_bare(info.annotation))[0])
    choices = typing.get_args(entry) if _is_union(entry) else (entry,)
    return {word: choice for choice in choices for word in _first_words(choice)}


def _starts(annotation):
    """The words an entry of a positional run, or an optional positional tuple, starts with: the
    words of a ``list[Literal[...]]`` or the first words of its tuples; () for other fields."""
    annotation = _bare(annotation)
    if typing.get_origin(annotation) is list:
        entry = _bare(typing.get_args(annotation)[0])
        if typing.get_origin(entry) is typing.Literal:
            return tuple(map(str, typing.get_args(entry)))
        return _first_words(entry)
    return _first_words(annotation)


def _leading_run(annotation, words, i, stops, name):
    """A positional run that another positional follows: its entries while the words start one
    (``region R1 region R2`` before numbers; value names before mesh IDs)."""
    starts, entry = _starts(annotation), typing.get_args(_bare(annotation))[0]
    size, end = _arity(entry), i
    while end < len(words) and words[end] in starts and words[end] not in stops:
        end += size
    if size == 1:
        return list(words[i:end]), end
    end = min(end, len(words))
    return _entries(entry, words, i, end, name), end


def _arity(annotation):
    """How many words a field takes: 1, n for tuple[...] of n, or None for 'all the rest'."""
    if member_names(annotation):
        annotation = _bare(annotation)
    origin = typing.get_origin(annotation)
    if origin is typing.Annotated:
        return _arity(typing.get_args(annotation)[0])
    if origin is tuple:
        members = typing.get_args(annotation)
        if (len(members) == 2 and members[1] is Ellipsis) or any(_variadic(m) for m in members):
            return None
        return len(members)
    if origin is list:
        return None
    if _is_union(annotation):
        arities = {_arity(a) for a in typing.get_args(annotation) if a is not type(None)}
        return arities.pop() if len(arities) == 1 else 1
    return 1


def _bare(annotation):
    """The annotation without ``Annotated[...]`` and without ``None`` in a union; a NamedTuple as
    the ``tuple[...]`` of its members."""
    while typing.get_origin(annotation) is typing.Annotated:
        annotation = typing.get_args(annotation)[0]
    if _is_union(annotation):
        members = [m for m in typing.get_args(annotation) if m is not type(None)]
        if len(members) == 1:
            return _bare(members[0])
    if member_names(annotation):
        return tuple[tuple(typing.get_type_hints(annotation, include_extras=True).values())]
    return annotation


def member_names(annotation):
    """The names of a NamedTuple's members (an entry whose words errors and ``pdps doc`` name), or ()."""
    return getattr(annotation, "_fields", ()) if isinstance(annotation, type) and issubclass(annotation, tuple) else ()


def _is_union(annotation):
    return typing.get_origin(annotation) in (typing.Union, types.UnionType)


def _variadic(annotation):
    """Whether one member of a tuple takes a run of words: ``tuple[X, ...]`` or ``list[X]``."""
    annotation = _bare(annotation)
    origin, members = typing.get_origin(annotation), typing.get_args(annotation)
    return origin is list or (origin is tuple and len(members) == 2 and members[1] is Ellipsis)


def _first_words(annotation):
    """The words a ``tuple[Literal[...], ...]`` (or a tuple opened by a StyleName) must start with
    (how a union picks it), else ()."""
    annotation = _bare(annotation)
    if typing.get_origin(annotation) is tuple and not _variadic(annotation):
        named = _style_name(typing.get_args(annotation)[0])
        if named is not None:
            return named.names()
        first = _bare(typing.get_args(annotation)[0])
        if typing.get_origin(first) is typing.Literal:
            return tuple(str(word) for word in typing.get_args(first))
    return ()


def describe_type(annotation):
    """How a script writes a value of ``annotation``: "number", "vector X Y Z | chute ANGLE", ..."""
    named = _style_name(annotation)
    if named is not None:
        return "|".join(named.names()) if is_sub_model_kind(named.kind) else f"{named.kind.upper()}-STYLE"
    if member_names(annotation):
        return " ".join(member_names(annotation))
    annotation = _bare(annotation)
    origin, members = typing.get_origin(annotation), typing.get_args(annotation)
    if origin is typing.Literal:
        return "|".join(map(str, members))
    if _is_union(annotation):
        return " | ".join(describe_type(m) for m in members if m is not type(None))
    if _variadic(annotation):
        return f"{describe_type(members[0]) if members else 'word'}..."
    if origin is tuple:
        return " ".join(describe_type(m).replace(" | ", "|") for m in members)
    return {float: "number", int: "integer", bool: "yes|no", str: "word", VariableRef: "v_NAME"}.get(
        annotation, getattr(annotation, "__name__", str(annotation)))


def _stop(words, i, stops):
    return next((k for k in range(i, len(words)) if words[k] in stops), len(words))


def _read(annotation, words, i, stops, name):
    """One value of ``annotation`` read from ``words[i:]``: (value for pydantic, index after it).
    A union of tuples is picked by its first word (a ``Literal``), else it is the longest that fits
    before the next keyword; a variadic member takes the words up to the next keyword, or as many
    as an integer member just before it says (``group N G1 ... GN``)."""
    annotation = _bare(annotation)
    end = _stop(words, i, stops)
    if _is_union(annotation):
        members = [m for m in typing.get_args(annotation) if m is not type(None)]
        word = words[i] if i < len(words) else None
        if any(typing.get_origin(_bare(m)) is typing.Literal and word in map(str, typing.get_args(_bare(m)))
               for m in members):
            return word, i + 1
        matching = [m for m in members if word in _first_words(m)]
        if matching:
            fits = [m for m in matching if _arity(m) is None or _arity(m) <= end - i]
            if fits:
                return _read(max(fits, key=lambda m: _arity(m) or len(words)), words, i, stops, name)
            rests = [describe_type(tuple[typing.get_args(_bare(m))[1:]]) for m in matching]
            counted = f"{_arity(matching[0]) - 1} value(s): " if len(matching) == 1 else ""
            raise ScriptError(f"{name} {words[i]} takes {counted}{' or '.join(rests)} "
                              f"(got {' '.join(words[i + 1:end]) or 'nothing'})")
        choices = [_first_words(m) or (tuple(map(str, typing.get_args(_bare(m))))
                                       if typing.get_origin(_bare(m)) is typing.Literal else ()) for m in members]
        if i < len(words) and all(choices):
            known = dict.fromkeys(w for c in choices for w in c)     # two lengths of one word name it once
            raise ScriptError(f"{name} must be one of {', '.join(known)} (got {words[i]})")
        arities = {_arity(m) for m in members}
        if len(arities) > 1 or None in arities:
            fixed = sorted(a for a in arities if a is not None and a <= end - i)
            taken = end - i if None in arities or not fixed else fixed[-1]
            value = tuple(words[i:i + taken])
            return (value[0] if taken == 1 and 1 in arities else value), i + taken
    if _variadic(annotation):
        entry = typing.get_args(annotation)[0] if typing.get_args(annotation) else str
        size = _arity(entry)
        if typing.get_origin(_bare(entry)) is tuple and size is not None and size > 1:
            return _entries(entry, words, i, end, name, stops), end
        if size is None and _first_words(entry):
            return _sections(entry, words, i, end, name), end
        value = words[i:end]
        return (list(value) if typing.get_origin(annotation) is list else tuple(value)), end
    if typing.get_origin(annotation) is tuple:
        value, k = [], i
        members = typing.get_args(annotation)
        for m, member in enumerate(members):
            if _variadic(member):
                count = _stop(words, k, stops) - k
                if m and _bare(members[m - 1]) is int and words[k - 1].isdigit():
                    count = int(words[k - 1])
                    if k + count > len(words):
                        raise ScriptError(f"{name} {' '.join(words[i:k])} needs {count} value(s) after "
                                          f"{words[k - 1]} (got {len(words) - k})")
                value.append(tuple(words[k:k + count]))
                k += count
            else:
                member_value, k = _read(member, words, k, (), name) if k < len(words) else (None, k + 1)
                if member_value is None:
                    break
                value.append(member_value)
        return tuple(value), min(k, len(words))
    arity = _arity(annotation)
    if arity is None or arity == 1:
        return words[i], i + 1
    return tuple(words[i:i + arity]), i + arity


def _entries(entry, words, i, end, name, stops=()):
    """A run of ``entry`` tuples (``xlo 0 xhi EDGE``, LIGGGHTS's ``keyword value`` runs) in
    ``words[i:end]``, each checked for its first word and its length."""
    size, first, run = _arity(entry), _first_words(entry), []
    while i < end:
        if first and words[i] not in first:
            if stops:
                raise ScriptError(f"unknown keyword {words[i]} (known: {', '.join((*first, *stops))})")
            raise ScriptError(f"{name}: expected {', '.join(first)} (got {words[i]})")
        taken = words[i:min(i + size, end)]
        if len(taken) < size:
            names = member_names(entry)
            rest = " ".join(names[1:]) if names else describe_type(tuple[typing.get_args(_bare(entry))[1:]])
            raise ScriptError(f"{name} {taken[0]} needs {rest} (got {' '.join(taken[1:]) or 'nothing'})")
        run.append(tuple(taken))
        i += size
    return run


def _sections(entry, words, i, end, name):
    """A run of ``entry`` tuples each opened by one of its first words and taking the words up to
    the next one (pair hybrid's ``STYLE ARGS... STYLE ARGS...``)."""
    first, run = set(_first_words(entry)), []
    if words[i] not in first:
        named = _style_name(typing.get_args(_bare(entry))[0])
        what = f"the name of a {named.kind} style" if named else f"one of {', '.join(_first_words(entry))}"
        raise ScriptError(f"{name} must start with {what} (got {words[i]})")
    while i < end:
        k = next((j for j in range(i + 1, end) if words[j] in first), end)
        value, _ = _read(entry, words[:k], i, (), name)
        run.append(value)
        i = k
    return run


def _label(part):
    """Whether a part of a pydantic error location names a union member (not a field or index)."""
    return isinstance(part, str) and ("[" in part or part in _SCALAR_LABELS)


_SCALAR_LABELS = {"float", "int", "str", "bool", "VariableRef", "function-after", "function-before",
                  "function-plain", "function-wrap", "is-instance[VariableRef]"}
_MISMATCH = {"literal_error", "missing", "too_short", "too_long"}


def _best(errors):
    """Of the errors pydantic gives for one value, the one the user's words mean: a union member
    whose first word matched and whose length was right, else None (no member fits)."""
    first = errors[0]["loc"]
    same = [e for e in errors if e["loc"][:1] == first[:1]]
    labelled = [e for e in same if any(_label(part) for part in e["loc"])]
    if not labelled:
        return errors[0]
    members = {}
    for error in labelled:
        cut = next(k for k, part in enumerate(error["loc"]) if _label(part))
        members.setdefault(error["loc"][:cut + 1], []).append(error)
    for errs in members.values():
        wrong_shape = any(e["type"] in _MISMATCH and (e["type"] != "literal_error" or e["loc"][-1] == 0)
                          for e in errs)
        scalar = all(_label(e["loc"][-1]) for e in errs)
        if not wrong_shape and not scalar:
            return errs[0]
    return None


def explain(error, annotation=None):
    """One pydantic error as the sentence a user reads; ``annotation`` (the field's type) words the
    error of a value that fits none of a union's members."""
    loc = ".".join(str(part) for part in error["loc"] if not isinstance(part, int) and not _label(part)) \
        or "argument"
    kind, ctx, value = error["type"], error.get("ctx", {}), error.get("input")
    shown = " ".join(map(str, value)) if isinstance(value, (list, tuple)) else value
    got = f"(got {shown})"
    if annotation is not None:
        alternatives = [describe_type(m) for m in typing.get_args(_bare(annotation)) if m is not type(None)]
        wording = {"number": "a finite number", "integer": "an integer"}
        return f"{loc} must be {' or '.join(wording.get(a, a) for a in alternatives)} {got}"
    limits = {"greater_than": ">", "greater_than_equal": ">=", "less_than": "<", "less_than_equal": "<="}
    if kind in limits:
        bound = ctx.get({"greater_than": "gt", "greater_than_equal": "ge",
                         "less_than": "lt", "less_than_equal": "le"}[kind])
        bound = f"{bound:g}" if isinstance(bound, (int, float)) else bound
        return f"{loc} must be {limits[kind]} {bound} {got}"
    if kind == "magnitude":
        got = f"(got {ctx['value']:g})" if "value" in ctx else got
        return f"{loc} must be 0 or of magnitude from {ctx['low']:g} to {ctx['high']:g} {got}"
    if kind in ("float_parsing", "float_type", "finite_number"):
        return f"{loc} must be a finite number {got}"
    if kind in ("int_parsing", "int_type", "int_from_float"):
        return f"{loc} must be an integer {got}"
    if kind in ("bool_parsing", "bool_type"):
        return f"{loc} must be yes or no {got}"
    if kind in ("literal_error", "enum"):
        return f"{loc} must be one of {ctx.get('expected')} {got}"
    if kind == "missing":
        return f"missing argument {loc}"
    if kind in ("too_short", "too_long"):
        if isinstance(value, list) and value and isinstance(value[0], tuple):
            bound = "at least" if kind == "too_short" else "at most"
            return f"{loc} takes {bound} {ctx.get('min_length', ctx.get('max_length'))} entries (got {len(value)})"
        return f"{loc} takes {ctx.get('min_length', ctx.get('max_length'))} value(s) {got}"
    message = error["msg"].removeprefix("Value error, ")
    if not error["loc"]:
        return message          # a model-level check: its message names what is wrong itself
    return f"{loc}: {message} {got}" if value is not None else f"{loc}: {message}"


def _member_at(annotation, path):
    """The type at ``path`` (list and tuple indices) inside ``annotation``."""
    for part in path:
        annotation = _bare(annotation)
        members = typing.get_args(annotation)
        if typing.get_origin(annotation) is list or _variadic(annotation):
            annotation = members[0]
        elif typing.get_origin(annotation) is tuple and part < len(members):
            annotation = members[part]
        else:
            break
    return annotation


def _named(error, values, model):
    """The error with its location named as a user reads it: an entry of a run or of a repeated
    keyword by its first word (``wall xlo``) and a NamedTuple's member by its name (``wall xlo:
    cutoff``), union members and indices left out."""
    loc = error["loc"]
    value = values.get(loc[0]) if loc else None
    if len(loc) > 2 and isinstance(loc[1], int) and isinstance(value, list) and loc[1] < len(value):
        entry = value[loc[1]]
        if isinstance(entry, tuple) and entry and loc[2] != 0:
            fields = {info.alias or name: info for name, info in model.model_fields.items()}
            info = fields.get(loc[0])
            names = member_names(_member_at(info.annotation, loc[1:2])) if info is not None else ()
            if names and isinstance(loc[2], int) and loc[2] < len(names):
                return {**error, "loc": (f"{loc[0]} {entry[0]}: {names[loc[2]]}", *loc[3:])}
            return {**error, "loc": (f"{loc[0]} {entry[0]}", *loc[2:])}
    return error


def _explain_all(model, errors, values):
    """The sentence for a ValidationError of ``model``: the error of the union member the words
    picked, or, when they fit none, what the union at that place accepts."""
    error = _best(errors)
    if error is not None:
        return explain(_named(error, values, model))
    error = next(e for e in errors if any(_label(part) for part in e["loc"]))
    cut = next(k for k, part in enumerate(error["loc"]) if _label(part))
    fields = {info.alias or name: info for name, info in model.model_fields.items()}
    info = fields.get(error["loc"][0])
    path = error["loc"][1:cut]
    union = _member_at(info.annotation, path) if info is not None else None
    shown = values.get(error["loc"][0])
    for part in path:
        if isinstance(shown, (list, tuple)) and isinstance(part, int) and part < len(shown):
            shown = shown[part]
    named = _named({"loc": error["loc"][:cut]}, values, model)
    return explain({"type": "union", "loc": named["loc"], "input": shown}, union)


def parse_args(model, words, usage="", refused=None):
    """Read script words into ``model``; any problem becomes a one-line ScriptError. ``refused``:
    {keyword: the error} for keywords of kindred styles this one does not take."""
    refused = refused or {}
    fields = {info.alias or name: info for name, info in model.model_fields.items()}
    positional = [(n, f) for n, f in fields.items() if not _is_keyword(f)]
    keywords = {n: f for n, f in fields.items() if _is_keyword(f)}
    spelled = {}        # the first word of an entry of a keyword(spelled_by_entries=True): (field, its tuple)
    for n, f in list(keywords.items()):
        spellings = _entry_spellings(f)
        for word, choice in spellings.items():
            spelled[word] = (n, choice)
            keywords[word] = f
        if spellings:
            del keywords[n]
    values, i = {}, 0
    # a refused keyword ends a run of positional words as a keyword does, so that its error is the one
    stops = {**keywords, **refused}
    for k, (name, info) in enumerate(positional):
        # an optional style word (wall/reflect's) is left out when a later argument follows instead
        choices = _bare(info.annotation)
        skipped = (not info.is_required() and i < len(words) and k + 1 < len(positional)
                   and typing.get_origin(choices) is typing.Literal
                   and words[i] not in map(str, typing.get_args(choices)))
        # so is an optional tuple whose first word is not the one given (``output face``)
        skipped = skipped or (not info.is_required() and i < len(words) and typing.get_origin(choices) is tuple
                              and bool(_first_words(choices)) and words[i] not in _first_words(choices))
        # a run another positional follows takes the words that start its entries (region R1 region R2)
        leading = k + 1 < len(positional) and typing.get_origin(choices) is list and bool(_starts(choices))
        if i >= len(words) or words[i] in stops or skipped or (leading and words[i] not in _starts(choices)):
            if info.is_required():
                got = f" (got {words[i]})" if i < len(words) and words[i] not in stops else ""
                hint = f"; usage: {usage}" if usage else ""
                raise ScriptError(f"missing argument {name}{got}{hint}")
            continue
        if leading:
            values[name], i = _leading_run(choices, words, i, stops, name)
            continue
        values[name], i = _read(info.annotation, words, i, stops, name)
    while i < len(words):
        word = words[i]
        if word in refused:
            raise ScriptError(refused[word])
        if word not in keywords:
            if not keywords:
                raise ScriptError(f"too many arguments: unexpected {word!r}" + (f"; usage: {usage}" if usage else ""))
            raise ScriptError(f"unknown keyword {word} (known: {', '.join(keywords)})")
        if word in spelled:
            field, choice = spelled[word]
            size = _arity(choice) - 1
            taken = words[i + 1:i + 1 + size]
            given = next((k for k, w in enumerate(taken) if w in keywords), len(taken))
            if given < size:
                raise ScriptError(f"keyword {word} needs {size} value(s) (got {' '.join(taken[:given]) or 'nothing'})")
            value, i = _read(choice, words, i, (), field)
            values.setdefault(field, []).append(value)
            continue
        info = keywords[word]
        repeated = typing.get_origin(_bare(info.annotation)) is list
        member = typing.get_args(_bare(info.annotation))[0] if repeated else info.annotation
        arity = _arity(member)
        if arity is None or (_is_union(_bare(member)) and len({_arity(m) for m in typing.get_args(_bare(member))
                                                               if m is not type(None)}) > 1):
            if i + 1 >= len(words) or words[i + 1] in keywords:
                raise ScriptError(f"keyword {word} needs a value: {describe_type(member)}")
            value, end = _read(member, words, i + 1, keywords, word)
        else:
            taken = words[i + 1:i + 1 + arity]
            if len(taken) < arity:
                raise ScriptError(f"keyword {word} needs {arity} value(s) (got {len(taken)})")
            value, end = _read(member, words, i + 1, (), word)
        if repeated:
            values.setdefault(word, []).append(value)
        else:
            values[word] = value
        i = end
    # a keyword declared without a default (LIGGGHTS's seed, model, ...) must be given
    missing = next((name for name, info in fields.items() if _is_keyword(info) and info.is_required()
                    and name not in values), None)
    if missing is not None:
        raise ScriptError(f"missing keyword {missing}" + (f"; usage: {usage}" if usage else ""))
    try:
        return model(**values)
    except ValidationError as exc:
        raise ScriptError(_explain_all(model, exc.errors(), values)) from None


# ---- style base classes -------------------------------------------------------------------------
class Style:
    """What every style shares: its name, its arguments, and what it needs from the core."""
    name: ClassVar[str] = ""
    kind: ClassVar[str] = ""
    Args: ClassVar[type[StyleArgs]] = StyleArgs
    usage: ClassVar[str] = ""
    per_atom: ClassVar[tuple] = ()   # per-atom arrays to allocate: "radius", "omega", or ("name", width)
    ghost_velocity: ClassVar[bool] = False     # ghosts must carry v (DPD, granular damping)
    ghost_fields: ClassVar[tuple] = ()         # other per-atom arrays ghosts need every step ("omega")
    # keywords of kindred styles this one does not take, and why ("temp": "only fix rigid/nvt takes it")
    refused: ClassVar[dict[str, str]] = {}
    # the array's row count changes from output to output (LAMMPS's size_array_rows_variable: fix
    # ave/chunk): ID[i][j] of a row past the last reads 0, as LAMMPS's, rather than an error
    array_rows_vary: ClassVar[bool] = False

    @classmethod
    def parse(cls, words):
        refused = {word: f"keyword {word} of {cls.kind} {cls.name}: {why}" for word, why in cls.refused.items()}
        args = parse_args(cls.Args, words, cls.usage, refused)
        cls.check_args(args)
        return args

    @classmethod
    def check_args(cls, args):
        """Checks of the arguments read that name the style (one ``Args`` shared by several styles);
        a ScriptError for a bad combination."""

    @classmethod
    def spellings(cls):
        """The classes ``respell`` may hand this style's lines to (another spelling of its name with
        arguments of its own), so that ``pdps doc`` shows their parameters too; () by default."""
        return ()

    @classmethod
    def respell(cls, dialect, words):
        """(class, words) when, in ``dialect`` (its name: pdps, lammps, liggghts), this style's name
        with these words spells another style of the same plugin, as LIGGGHTS 2.x's ``pair_style
        gran/hertz/history`` without coefficients spells today's ``gran model hertz tangential
        history``; None (the default): this style, these words. Called before the words are parsed,
        so a dialect's spellings live in the plugin whose styles they name, not in the core."""
        return None


class Pair(Style):
    """A pair style: ``pair_style NAME args`` then ``pair_coeff I J coeffs`` for each type pair.

    Subclasses set ``Coeff`` (the pair_coeff model) and implement ``init_one`` (derived constants and
    the cutoff of one type pair, from ``self.resolved[(i, j)]``: the pair's explicit or mixed
    coefficients) and ``compute``. The core builds the ``neighbor_list`` kind they ask
    for with the cutoffs ``init_one`` returned, sums ghost forces back (newton on), and derives the
    virial from sum(x * f) over owned and ghost particles when asked for it (on a half list; a style
    on a full list sets ``virial``).
    """
    kind = "pair"
    Coeff: ClassVar[type[StyleArgs]] = StyleArgs
    coeff_usage: ClassVar[str] = ""
    neighbor_list: ClassVar[str] = "half"
    # fills the per-particle tally (energy, virial) on the steps ``sim.run_state.tally_atom`` asks for it
    peratom_tally: ClassVar[bool] = False
    # the cutoff of types i, j is at least the largest radius of i plus that of j, and forces come from
    # the radii themselves (granular contact): where a fix grows radii in a run (Fix.varies_radius),
    # the core widens the cutoffs at its rebuilds by the growth
    cutoff_from_radii: ClassVar[bool] = False
    # On a full list (each pair seen from both particles, no force on ghosts) sum r.f misses every
    # pair across a periodic or rank boundary, so a style on one sets ``virial`` itself in compute
    # on vflag steps (LAMMPS's no_virial_fdotr_compute): xx, yy, zz, xy, xz, yz of its pairs on this
    # rank (energy units), half of r_ij f_ij for each listed pair.
    virial = None

    # may be a sub-style of pair hybrid: a force law (PairLaw), or a loop of its own over a half list
    # that skips the type pairs of cutoff 0 (those ``init(ntypes, pairs)`` leaves to other sub-styles)
    hybrid_sub_style: ClassVar[bool] = False

    def __init__(self, sim, args):
        self.sim = sim
        self.args = args
        self.coeffs = {}        # (i, j) with i <= j -> Coeff
        self.energy = 0.0

    def coeff(self, i, j, coeff):
        self.coeffs[(min(i, j), max(i, j))] = coeff

    def parse_coeff(self, words):
        return parse_args(self.Coeff, words, self.coeff_usage)

    mix_rule: str | None = None     # set by pair_modify mix
    mix_default: ClassVar[str | None] = None    # the style's own rule (LAMMPS lj/cut: geometric)
    shift: bool = False             # pair_modify shift yes: energies shifted to 0 at the cutoff
    tail: bool = False              # pair_modify tail yes: long-range corrections (styles with tail_ij)
    etail = ptail = 0.0             # their totals over type pairs, set by init; divided by the volume

    def tail_ij(self, i, j, count_i, count_j):
        """LAMMPS's long-range corrections of one type pair with the global counts of its types, from
        ``self.resolved[(i, j)]``: (etail_ij, ptail_ij), energy*volume units. Thermo ``pe`` gains
        sum etail_ij / V and each diagonal virial component sum ptail_ij / V (i != j counted twice,
        as LAMMPS). None (the default): the style has no tail correction."""
        return None

    def mix(self, i, j):
        """Coefficients for an unset i != j pair: an error unless ``pair_modify mix`` or the style's
        ``mix_default`` gives a rule, then the style's ``mix_coeff`` combines the i i and j j
        coefficients."""
        rule = self.mix_rule or self.mix_default
        if rule is None:
            raise ScriptError(f"pair coefficients are not set for types {i} {j}"
                              " (give pair_coeff for every type pair, or a rule with pair_modify mix)")
        for k in (i, j):
            if (k, k) not in self.coeffs:
                raise ScriptError(f"pair coefficients for types {k} {k} are needed to mix {i} {j}")
        try:
            return self.mix_coeff(self.coeffs[(i, i)], self.coeffs[(j, j)], rule)
        except (ValueError, OverflowError, ZeroDivisionError) as exc:
            raise ScriptError(f"pair coefficients for types {i} {j} cannot be mixed ({_reason(exc)}) from "
                              f"{i} {i} and {j} {j}: give pair_coeff {i} {j}") from None

    def mix_coeff(self, ci, cj, rule):
        raise ScriptError(f"pair style {self.name} has no mixing rule; give pair_coeff {rule} pairs")

    def init(self, ntypes, pairs=None):
        """Called at the start of every run; returns the (ntypes+1)^2 cutoff matrix. ``pairs``: the
        (i, j), i <= j, this style acts on (a sub-style of pair hybrid), all by default; the others
        get cutoff 0, so that the loop skips them."""
        cut = np.zeros((ntypes + 1, ntypes + 1))
        # explicit coefficients, and mixed ones derived afresh each run (LAMMPS re-mixes at init)
        self.resolved = {}
        for i in range(1, ntypes + 1):
            for j in range(i, ntypes + 1):
                if pairs is not None and (i, j) not in pairs:
                    continue
                if (i, j) in self.coeffs:
                    self.resolved[(i, j)] = self.coeffs[(i, j)]
                elif i == j:
                    raise ScriptError(f"pair coefficients are not set for types {i} {j}"
                                      " (give pair_coeff for every type pair)")
                else:
                    self.resolved[(i, j)] = self.mix(i, j)
                cut[i, j] = cut[j, i] = self._cutoff_of(i, j)
        self.sum_tails(ntypes, lambda i, j, count_i, count_j: (self.tail_ij(i, j, count_i, count_j),))
        return cut

    def sum_tails(self, ntypes, terms):
        """``etail`` and ``ptail``: over the type pairs of ``self.resolved``, the sum of what
        ``terms(i, j, count_i, count_j)`` gives ((etail_ij, ptail_ij) each, None for none), i != j
        counted twice as LAMMPS does; 0 without ``pair_modify tail yes``."""
        self.etail = self.ptail = 0.0
        if self.tail and self.shift:
            # a shifted potential with a correction for the unshifted tail is neither (LAMMPS refuses it)
            raise ScriptError("pair_modify shift yes and tail yes cannot both be set")
        if not self.tail:
            return
        p = self.sim.particles
        counts = self.sim.comm.sum(np.bincount(p.type[: p.nlocal], minlength=ntypes + 1))
        for (i, j) in self.resolved:
            weight = 1.0 if i == j else 2.0
            for term in terms(i, j, float(counts[i]), float(counts[j])):
                if term is not None:
                    self.etail += weight * term[0]
                    self.ptail += weight * term[1]

    def _cutoff_of(self, i, j):
        try:
            cutoff = self.init_one(i, j)
        except (OverflowError, ZeroDivisionError) as exc:
            raise ScriptError(f"pair_coeff {i} {j}: the coefficients overflow ({_reason(exc)})") from None
        return _finite_cutoff(cutoff, i, j)

    def init_one(self, i, j):
        raise NotImplementedError

    def compute(self, sim, nlist, eflag, vflag):
        raise NotImplementedError

    def single(self, sim, i, j, delta):
        """Force and energy of chosen pairs, as LAMMPS's ``Pair::single``: for a compute that needs
        this style's interaction pair by pair (compute group/group). ``i``, ``j``: rows of the
        particle arrays (owned or ghost; integer arrays of one length n); ``delta``: their
        separations x_i - x_j, (n, 3) (distance; the minimum image, or a ghost row for j as a
        neighbor list gives). Returns (fpair, energy), two (n,) arrays: F/r (force/distance: the
        force on i is ``fpair * delta``, on j its opposite) and the pair's energy (energy), 0 for
        pairs at or beyond their cutoff. Valid once a run has set the style up (``init``). A law
        with friction or noise gives its conservative part, as LAMMPS's dpd does."""
        raise ScriptError(f"pair style {self.name} cannot evaluate chosen pairs (it has no single())")

    def extract(self, name):
        """A named coefficient of this style, as LAMMPS's ``Pair::extract``: a field of ``Coeff``
        as an (ntypes+1, ntypes+1) array over type pairs (mixed ones included; NaN where a pair has
        no value, index 0 unused), valid once a run has set the style up; else a field of ``Args``
        (the pair_style line's value). A one-line error names the fields there are."""
        if name in self.Coeff.model_fields and hasattr(self, "resolved"):
            ntypes = max((j for _, j in self.resolved), default=0)
            table = np.full((ntypes + 1, ntypes + 1), np.nan)
            for (i, j), coeff in self.resolved.items():
                value = getattr(coeff, name)
                if value is None and name in self.Args.model_fields:
                    value = getattr(self.args, name)       # a pair cutoff left to the global one
                table[i, j] = table[j, i] = np.nan if value is None else value
            return table
        if name in self.Args.model_fields:
            return getattr(self.args, name)
        known = sorted(set(self.Coeff.model_fields) | set(self.Args.model_fields))
        raise ScriptError(f"pair style {self.name} has no value {name} (it has: {', '.join(known) or 'none'})")


def _reason(exc):
    # math's OverflowError reads "(34, 'Numerical result out of range')"
    return exc.args[-1] if exc.args and isinstance(exc.args[-1], str) else str(exc)


def _finite_cutoff(cutoff, i, j):
    # squared in the loop: a cutoff whose square overflows is as wrong as an infinite one
    if not (math.isfinite(cutoff) and cutoff >= 0 and math.isfinite(cutoff * cutoff)):
        raise ScriptError(f"pair_coeff {i} {j}: cutoff {cutoff:g} is not a finite distance")
    return cutoff


class PairLaw(Pair):
    r"""A pair style written as a force law; the core owns the loop around it.

    Subclasses give:

    - ``params``: names of the per-type-pair values the law reads, in order;
    - ``init_one(i, j)`` returning ``(cutoff, values)``, the values in the order of ``params``
      (read the pair's coefficients from ``self.resolved[(i, j)]``);
    - ``law``, a numba function (a ``staticmethod`` of one decorated ``@njit(cache=True,
      inline="always")``: numba then compiles it into the loop, as fast as a hand-written one)::

          law(rsq, dx, dy, dz, coeff, i, j, atom, state) -> (fpair, energy)

      ``rsq`` = r^2 and (dx, dy, dz) = r_i - r_j (distance units); ``coeff`` the type pair's values
      (a tuple of floats in the order of ``params``: ``coeff[0]``...); ``i``, ``j`` rows of the pair in the particle arrays;
      ``atom`` the tuple of per-atom arrays named in ``law_atom`` (e.g. ``("v", "tag")``);
      ``state`` the tuple ``law_state(sim)`` returns for this step (default ``()``). It returns
      ``fpair`` = F/r, so that the force on i is ``fpair * (dx, dy, dz)`` (force/distance units),
      and the pair's energy (energy units; only summed when the step asks for energy).

    The core calls the law for every pair with ``r < cutoff`` and ``r >= 1e-10`` (coincident
    particles have no direction and are skipped), applies Newton's third law on a half list (or
    the force on i only on a full list, ``neighbor_list = "full"``), and tallies energy only on
    steps that read it; the virial comes from sum(r . f) on a half list, pair by pair on a full one
    (ghosts there get no force, so sum(r . f) would miss the pairs across a boundary). The tables are
    ``self.coeff_table`` ((ntypes+1, ntypes+1, len(params)), symmetric) and ``self.cutsq``.

    When the neighbor list would be rebuilt at nearly every step (DPD at its usual time steps), the
    core runs the same law over its cell bins instead, with no list (the list's direct mode in
    pdps_core.neighbor): same forces, summed in another order.
    """
    peratom_tally = True
    hybrid_sub_style = True
    params: ClassVar[tuple] = ()
    law_atom: ClassVar[tuple] = ()
    law: ClassVar = None            # the force law (a static numba function)
    law_source: str | None = None   # or Python source defining ``law`` (generated laws)
    # what ``single`` evaluates: the force law itself (None), or its conservative part for a law
    # with friction or noise (a static numba function of the same signature; dpd's, as LAMMPS's)
    single_law: ClassVar = None
    # True for a cheap law defined at every distance of the list (no table lookups, no random
    # numbers): the core evaluates it for every listed pair and keeps those within the cutoff,
    # without a branch (pdps_core.pair_loop.MASKED_TEST)
    masked: ClassVar[bool] = False

    def init(self, ntypes, pairs=None):
        size = ntypes + 1
        self.coeff_table = np.zeros((size, size, max(len(self.params), 1)))
        self._values = {}
        cut = super().init(ntypes, pairs)
        for (i, j), values in self._values.items():
            if len(values) != len(self.params):
                raise ScriptError(f"pair style {self.name}: init_one gave {len(values)} values for "
                                  f"{len(self.params)} params ({', '.join(self.params)})")
            self.coeff_table[i, j, :len(values)] = self.coeff_table[j, i, :len(values)] = values
        self.cutsq = cut * cut
        self._loops = None
        self._full_list_rows = None
        return cut

    @property
    def cell_loops(self):
        """True when the core may compute this style from its cell bins (a half list, and the
        core's own loop: a subclass with a compute of its own reads the list)."""
        return self.neighbor_list == "half" and type(self).compute is PairLaw.compute

    def _cutoff_of(self, i, j):
        try:
            cutoff, values = self.init_one(i, j)
            values = tuple(float(v) for v in values)
        except (OverflowError, ZeroDivisionError) as exc:
            raise ScriptError(f"pair_coeff {i} {j}: the coefficients overflow ({_reason(exc)})") from None
        for name, value in zip(self.params, values):
            if not math.isfinite(value):
                raise ScriptError(f"pair_coeff {i} {j}: the coefficients give {name} = {value}, "
                                  "not a finite number")
        self._values[(i, j)] = values
        return _finite_cutoff(cutoff, i, j)

    def law_state(self, sim):
        """Per-step scalars the law reads (seed, step, 1/sqrt(dt), ...), as a tuple."""
        return ()

    # the coefficients fix adapt pair may change in a run: LAMMPS's names (Pair::extract) -> Coeff field
    adaptable: ClassVar[dict] = {}

    def adapt(self, changes):
        """fix adapt pair: ``changes`` maps type pairs (i, j), i <= j, to {Coeff field: value} for the
        rest of the run; the law's values follow, and mixed pairs are mixed afresh from their i i and
        j j (LAMMPS's Pair::reinit). A change that would move a cutoff is an error: the neighbor
        lists were built for the run's cutoffs."""
        if self.tail:
            raise SimulationError(f"fix adapt pair {self.name}: with pair_modify tail yes the tail corrections "
                                  "would have to follow the coefficients, which pdps does not do")
        for pair, fields in changes.items():
            if pair in self.resolved:
                self.resolved[pair] = self.resolved[pair].model_copy(update=fields)
        rule = self.mix_rule or self.mix_default
        for (i, j) in self.resolved:
            if i != j and (i, j) not in self.coeffs:
                self.resolved[(i, j)] = self.mix_coeff(self.resolved[(i, i)], self.resolved[(j, j)], rule)
        for (i, j) in self.resolved:
            cutoff, values = self.init_one(i, j)
            if not math.isclose(cutoff * cutoff, self.cutsq[i, j], rel_tol=1e-12):
                raise SimulationError(f"fix adapt pair {self.name}: types {i} {j} would change their cutoff "
                                      f"({math.sqrt(self.cutsq[i, j]):g} to {cutoff:g}) in a run")
            self.coeff_table[i, j, :len(values)] = self.coeff_table[j, i, :len(values)] = values

    def force_law(self):
        """The law to compile for this run (default ``law``); a style with variants (dpd without its
        thermostat under a splitting integrator) returns the one its settings call for, rather than
        branching inside the law for every pair."""
        return type(self).law

    def compute(self, sim, nlist, eflag, vflag):
        if self._loops is None:
            self._loops = self._loops_around(self.force_law())
        p = sim.particles
        atom = tuple(p.arrays[name] for name in self.law_atom)
        tally = sim.run_state.tally_atom
        # one particle type: the loop that reads its pair's cutoff and coefficients once
        one_type = ("one type",) if len(self.cutsq) == 2 else ()
        if nlist.direct and not tally:
            self.energy = self._loops[("cells", bool(eflag), *one_type)](
                p.x, p.f, p.type, p.nlocal, self.cutsq, self.coeff_table, atom, self.law_state(sim), *nlist.cells)
            return
        args = (p.x, p.f, p.type, nlist.offsets, nlist.neighbors, p.nlocal, self.cutsq, self.coeff_table, atom,
                self.law_state(sim))
        if tally or (vflag and not nlist.half_list):
            rows = p.arrays[TALLY] if tally else self._virial_rows(p.nlocal)
            self.energy = self._loops[(nlist.half_list, "tally")](*args, rows)
            if not nlist.half_list:
                self.virial = rows[:p.nlocal, 1:7].sum(axis=0)
        else:
            self.energy = self._loops[(nlist.half_list, bool(eflag), *one_type)](*args)

    def single(self, sim, i, j, delta):
        i = np.ascontiguousarray(i, dtype=np.int64).reshape(-1)
        j = np.ascontiguousarray(j, dtype=np.int64).reshape(-1)
        delta = np.ascontiguousarray(delta, dtype=np.float64).reshape(-1, 3)
        if not len(i) == len(j) == len(delta):
            raise ScriptError(f"pair style {self.name}: single() takes as many rows j and separations as "
                              f"rows i (got {len(i)}, {len(j)}, {len(delta)})")
        if not hasattr(self, "cutsq"):
            raise ScriptError(f"pair style {self.name}: single() is valid once a run has set the style up (run 0)")
        loops = self._loops_around(type(self).single_law or self.force_law())
        p = sim.particles
        fpair, energy = np.zeros(len(i)), np.zeros(len(i))
        loops["single"](i, j, delta, p.type, self.cutsq, self.coeff_table,
                        tuple(p.arrays[name] for name in self.law_atom), self.law_state(sim), fpair, energy)
        return fpair, energy

    def _loops_around(self, law):
        """The compiled loops around ``law`` (around ``law_source`` for a generated law)."""
        from .pair_loop import loops_for
        if self.law_source is not None:
            return loops_for(len(self.params), source=self.law_source, name=self.name.replace("/", "_"))
        return loops_for(len(self.params), law=law, masked=self.masked)

    def _virial_rows(self, nlocal):
        """Zeroed per-particle rows of the full-list tally loop, kept between steps: on a full list the
        virial is the sum of its columns 1-6."""
        if self._full_list_rows is None or len(self._full_list_rows) < nlocal:
            self._full_list_rows = np.zeros((nlocal + nlocal // 4 + 16, 7))
        rows = self._full_list_rows
        rows[:nlocal] = 0.0
        return rows


class Bond(Style):
    r"""A bond style: ``bond_style NAME`` then ``bond_coeff N coeffs`` for each bond type; a force law,
    the core owns the loop over the bonds (pdps_core/bond_loop.py, the bond list of
    pdps_core/state/topology.py).

    Subclasses give ``Coeff`` (the bond_coeff model), ``params`` (the per-type values the law reads,
    in order), ``values(coeff)`` returning them from one type's Coeff, and ``law``, a numba function
    (a ``staticmethod`` decorated ``@njit(cache=True, inline="always")``)::

        law(rsq, coeff) -> (fbond, energy)

    ``rsq`` = r^2 of the bond (distance^2), ``coeff`` its type's values as a tuple; it returns
    ``fbond`` = F/r (force/distance units: the force on the first particle is ``fbond * (r_1 - r_2)``)
    and the bond's energy (energy units). The core applies it to every bond of a type the style
    owns, with Newton's third law (LAMMPS's newton_bond on), tallies energy and virial on the steps
    that read them, and sums the forces on ghost partners back to their owners.
    """
    kind = "bond"
    Coeff: ClassVar[type[StyleArgs]] = StyleArgs
    coeff_usage: ClassVar[str] = ""
    params: ClassVar[tuple] = ()
    law: ClassVar = None

    def __init__(self, sim, args):
        self.sim = sim
        self.args = args
        self.coeffs = {}        # bond type -> Coeff

    def parse_coeff(self, words):
        return parse_args(self.Coeff, words, self.coeff_usage)

    def values(self, coeff):
        """The law's values of one bond type, in the order of ``params``, from its Coeff."""
        return tuple(float(getattr(coeff, name)) for name in self.params)

    def equilibrium_distance(self, coeff):
        """r0 of one bond type (LAMMPS's Bond::equilibrium_distance), or None."""
        return getattr(coeff, "r0", None)

    # a law defined only up to some length (fene) gives the lengths (distance) of one type beyond
    # which the core warns, and stops the run, saying what they are in these words
    stretch_warning: ClassVar[str] = ""
    stretch_failure: ClassVar[str] = ""

    def stretch_limits(self, coeff):
        """(warning length, failure length) of one bond type; inf for a law defined at every length."""
        return math.inf, math.inf


class Fix(Style):
    """A fix: joins the timestep through hooks. Define any of the methods named in
    ``pdps_core.run.hookspec`` (``initial_integrate(self, sim)``, ``post_force(self, sim)``, ...);
    only the hooks a fix defines are ever called for it.

    Contributions to thermo (LAMMPS's ``fix_modify energy/virial`` and ``dof``):

    - ``can_energy = True`` and ``compute_energy(sim)``: the fix's potential energy on this rank at the
      current step (energy units, not per particle); added to thermo ``pe`` (and ``etotal``) after
      ``fix_modify ID energy yes``.
    - ``can_virial = True`` and ``compute_virial(sim)``: this rank's six virial components (xx, yy, zz, xy,
      xz, yz; energy units) of the fix's forces at the current step; added to ``press`` when on:
      ``virial_default`` (True where LAMMPS's own fix contributes by default), or ``fix_modify ID
      virial yes``. Walls tally r . f relative to the wall (as LAMMPS's walls), so a confined gas
      reads the pressure on the walls.
    - ``dof_removed(sim, group)``: how many degrees of freedom the fix removes from the particles
      of ``group`` (global count); temperatures and the kinetic pressure use N_dof minus it.

    They are methods (compute_*: worked out when asked) where the pair style's ``energy`` and
    ``virial`` are the step's values. ``compute_energy`` and ``compute_virial`` are called after
    ``post_force`` on steps where something reads them
    (``sim.eflag`` / ``sim.vflag`` are True during that step's force hooks, so a fix can tally only
    then). A fix whose virial is complete only after its ``final_integrate`` (constraint forces, as
    LAMMPS's fix rigid tallies in set_v) sets ``virial_after = "final_integrate"``: its ``compute_virial`` is
    then read after every fix's final_integrate (and after ``setup``), before ``end_of_step`` and
    output; fixes reading ``sim.virial`` within final_integrate (barostats) do not see it.

    Minimization: a fix defining ``min_post_force(self, sim)`` applies its forces there (LAMMPS's
    fixes with a min_post_force: addforce, setforce, walls...). A fix that changes forces in a run
    (``pre_force``, ``post_force``) but does nothing in a minimization, as LAMMPS leaves its fix out
    (gravity, langevin, granular walls), sets ``minimize_idle = True``; a force fix that says neither
    is refused by ``minimize``, at its line, rather than silently left out. A fix adding global
    degrees of freedom to the search (fix box/relax's box lengths: LAMMPS's min_dof, min_energy,
    min_store, min_step, max_alpha, min_reset_ref) sets ``min_dof`` and defines those methods as
    pdps_core/run/minimize.py's docstring says.

    ``modify_param(sim, keyword, value)``: a ``fix_modify ID keyword value`` other than energy and
    virial (LAMMPS's modify_param); returns True when the fix took it, False for an unknown keyword.

    Inserting and deleting particles: set ``self.next_reneighbor`` to the step on which the fix
    will act (the same on every rank); that step rebuilds neighbor lists, and the fix's
    ``pre_exchange(sim)`` calls ``sim.add_particles`` / ``sim.delete_particles`` before particles
    are wrapped, migrated and listed. A fix inserting spheres says in ``inserted_radius(type_)`` the
    largest radius of that type it will insert: granular pair styles size their cutoffs by it
    before the particles exist (LAMMPS's ``extract("radius")`` of fix pour).

    ``removed(sim)``: called by unfix before the fix goes (it may refuse with a ScriptError, and
    stays): what it leaves behind, as LAMMPS's fix destructors do (fix move/mesh leaves its mesh
    where it moved it).

    ``reset_timestep(sim, new, old)``: called by the reset_timestep command after the step changed
    from ``old`` to ``new``, for a fix that keeps a schedule in steps it should move with the clock
    (LIGGGHTS's insertion fixes shift their next insertion by new - old).

    ``box_extent(sim)``: the (lo, hi) corners of what a shrink-wrapped box encloses besides the
    particles (LIGGGHTS's Fix::box_extent: a mesh's nodes, wherever they have moved), or None; the
    same on every rank.

    ``reset_dt(sim)``: the time step changed in the middle of a run (``sim.change_timestep``: fix
    dt/reset); a fix that keeps constants of the step from ``init_run`` redoes them (LAMMPS's
    reset_dt), or refuses with a ScriptError where it cannot follow a changing step. Fixes reading
    ``sim.dt`` each step need nothing.
    """
    kind = "fix"
    can_energy: ClassVar[bool] = False
    can_virial: ClassVar[bool] = False
    virial_default: ClassVar[bool] = False
    virial_after: ClassVar[str] = "post_force"
    minimize_idle: ClassVar[bool] = False
    # the fix may be defined before the box exists (LAMMPS's fix property/atom, whose values read_data's
    # fix keyword then reads)
    before_box: ClassVar[bool] = False
    # the box lengths (0 x, 1 y, 2 z) the fix changes itself (fix deform): barostats refuse to share them
    deformed_axes: tuple = ()
    # hooks the fix defines but does not join for now (LAMMPS's fix mask, changed by fix_modify: fix
    # rigid's post_force only with bodyforces early); read when a run is set up
    idle_hooks: frozenset = frozenset()
    # the fix changes the box during a run (fix deform, the barostats): LAMMPS's box_change, which
    # adds Volume to thermo_style one's columns
    changes_box: bool = False
    # the fix holds its group's particles at rest (LAMMPS's fix freeze): granular pair styles give a
    # contact with a held particle the other one's mass as its effective mass, as LAMMPS does
    holds_at_rest: ClassVar[bool] = False
    # the fix moves its particles through time (LAMMPS's time_integrate): fix nve and its kin, the
    # Nose-Hoover fixes, the rigid bodies; a fix that wraps an integrator's steps (langevin gjf)
    # looks for one by this flag, never by a style name
    time_integrate: ClassVar[bool] = False
    next_reneighbor: int | None = None
    # the fix changes particle radii during a run (fix adapt; LIGGGHTS's rad_mass_vary_flag): the
    # rebuild decision counts radius growth as it counts moves, and a granular pair's cutoffs grow with
    # the radii at the rebuilds (Pair.cutoff_from_radii); ghosts need the radii then (ghost_fields)
    varies_radius: bool = False

    def __init__(self, sim, id, group, args):
        self.sim, self.id, self.group, self.args = sim, id, group, args
        self.thermo_energy = False
        self.thermo_virial = self.virial_default

    def compute_energy(self, sim):
        return 0.0

    def compute_virial(self, sim):
        return (0.0,) * 6

    def modify_param(self, sim, keyword, value):
        return False

    def inserted_radius(self, type_):
        """The largest radius of particles of type ``type_`` this fix will insert (0: none)."""
        return 0.0

    def box_extent(self, sim):
        """(lo, hi) a shrink-wrapped box encloses besides the particles, or None."""
        return None

    def extract(self, name):
        """A named value other styles may read (LAMMPS's Fix::extract), or None where this fix has
        none: fix gravity's "gvec" is its acceleration (3 floats), which fix rigid's gravity keyword
        applies to its bodies' masses."""
        return None


class Compute(Style):
    """A compute: a global value read as ``c_ID`` (scalar), ``c_ID[i]`` (vector) or ``c_ID[i][j]``
    (array). Indices count from 0 in the PDPS dialect, from 1 in LAMMPS's. ``needs_energy``/``needs_virial`` tell the
    core to compute them on the steps this compute is read.

    A per-atom compute also (or only) defines ``peratom(sim)``: one value per owned particle, a
    (nlocal,) array, or (nlocal, k) for k values each, in the order of the owned particles (0 for
    particles outside the compute's group, as LAMMPS). Dumps read it as ``c_ID`` or ``c_ID[k]``
    (column k, 0-based); reducing computes (``compute reduce``) combine it over ranks themselves,
    so it holds this rank's particles only."""
    kind = "compute"
    needs_energy: ClassVar[bool] = False
    needs_virial: ClassVar[bool] = False
    # reads the pair style's per-particle tally (``pair_tally``) on the steps it is read: pe/atom,
    # stress/atom (the core then allocates it and has the pair style fill it on those steps)
    peratom_tally: ClassVar[bool] = False
    # a total over particles (LAMMPS's extscalar): thermo divides it by the particle count when it
    # normalises energies (lj units), as LAMMPS does; variables read it as it is. A style whose array
    # (ID[i][j]) is not, where its scalar is, sets extensive_array = False (LAMMPS's extarray); one
    # whose vector (ID[i]) differs from its scalar sets extensive_vector (LAMMPS's extvector: a
    # temperature's kinetic tensor is extensive where its scalar is not)
    extensive: ClassVar[bool] = False
    # what a thermostat or barostat may take the compute for (LAMMPS's tempflag, pressflag): a
    # temperature (scalar T, vector the kinetic tensor) or a pressure (scalar p, vector the tensor)
    gives_temperature: ClassVar[bool] = False
    gives_pressure: ClassVar[bool] = False

    def __init__(self, sim, id, group, args):
        self.sim, self.id, self.group, self.args = sim, id, group, args

    def scalar(self, sim):
        raise ScriptError(f"compute {self.id} ({self.name}) has no scalar value; use c_{self.id}[i]")

    def vector(self, sim):
        raise ScriptError(f"compute {self.id} ({self.name}) has no vector value")

    def array(self, sim):
        raise ScriptError(f"compute {self.id} ({self.name}) has no array value")

    def peratom(self, sim):
        raise ScriptError(f"compute {self.id} ({self.name}) has no per-atom values")

    def local(self, sim):
        """This rank's rows of local data (contacts, bonds, bodies): ``(n,)`` or ``(n, k)``, for dump
        local and compute reduce (LAMMPS's local_flag)."""
        raise ScriptError(f"compute {self.id} ({self.name}) has no local data")

    def pair_tally(self, sim):
        """This step's per-particle pair tally of the owned particles (``peratom_tally = True``), a
        (nlocal, 7) view: energy, then virial xx yy zz xy xz yz, each pair's half (energy units)."""
        if sim.run_state.tally_step != sim.step:
            raise ScriptError(f"compute {self.id} ({self.name}): per-particle energies and virials were not "
                              f"computed on step {sim.step}: read them on a thermo or dump step, or run 0 first")
        return sim.particles.arrays[TALLY][: sim.particles.nlocal]


def peratom_column(sim, style, column, what):
    """Column ``column`` (None: the only one; else as the script wrote it, counted from the dialect's
    first index) of a style's ``peratom(sim)`` values, as (nlocal,) floats, for whatever reads per-atom
    values (reduce, dump custom); ``what`` names the reference (``c_ID[k]``, ``dump column c_ID[k]``)
    in errors."""
    values = np.asarray(style.peratom(sim), dtype=np.float64)
    n = sim.particles.nlocal
    base = sim.dialect.index_base
    if values.shape[:1] != (n,) or values.ndim > 2:
        raise ScriptError(f"{what}: {style.kind} {style.id} ({style.name}) returned per-atom values of "
                          f"shape {values.shape}, not ({n},) or ({n}, k)")
    if column is None:
        if values.ndim == 2:
            raise ScriptError(f"{what}: {style.kind} {style.id} has {values.shape[1]} values per particle; "
                              f"name one with [k], k from {base}")
        return values
    if values.ndim == 1:
        raise ScriptError(f"{what}: {style.kind} {style.id} has one value per particle; drop the [k]")
    k = sim.dialect_index(column, what)
    if k >= values.shape[1]:
        raise ScriptError(f"{what}: column {column} is out of range ({style.kind} {style.id} has "
                          f"{values.shape[1]} values per particle, from {base})")
    return values[:, k]


PERATOM_REFERENCE = re.compile(r"^(c|f|v)_([A-Za-z0-9_]+)(?:\[(\d+)\])?$")
# arrays every particle style has: a LIGGGHTS f_NAME never means them
_CORE_ARRAYS = ("x", "v", "f", "tag", "type", "mask", "image")


class PeratomReference:
    """A ``c_ID``, ``c_ID[k]``, ``f_ID``, ``f_ID[k]`` or ``v_NAME`` that a dump or compute reads per
    particle, checked when it is made (one-line errors that start with ``what``, which names the
    reference: ``dump column c_ke``) and read over the
    owned particles by ``values(sim)``:

    - ``c_ID[k]``, ``f_ID[k]``: column k (counted from the dialect's first index) of a compute's or
      fix's (or analyze style's) ``peratom`` values; without [k], the only column;
    - in the LIGGGHTS dialect, ``f_NAME`` also names a per-atom property a fix made: ``f_NAME`` or
      ``f_NAME[0]`` a scalar one (``f_Temp[0]`` of fix heat/gran: LIGGGHTS reads index 0 as no
      index), ``f_NAME[k]`` column k from 1 of a vector one (``f_force_ID[3]`` of wall/gran's
      store_force: the z component, recorded with LIGGGHTS 3.8.0);
    - ``v_NAME``: an atom-style variable's values (LAMMPS's), another style's value on every row.
    """

    def __init__(self, sim, word, what):
        match = PERATOM_REFERENCE.match(word)
        if match is None:
            raise ScriptError(f"{what}: {word} is not c_ID, c_ID[k], f_ID, f_ID[k] or v_NAME")
        self.word, self.what = word, what
        self.prefix, self.ident, k = match.groups()
        self.column = None if k is None else int(k)
        self.style = None
        if self.prefix == "v":
            if self.column is not None:
                raise ScriptError(f"{what}: a variable has one value per particle, no [k]")
            if self.ident not in sim.variables:
                raise ScriptError(f"{what}: variable {self.ident} is not defined")
            return
        if self.prefix == "f" and self._property(sim) is not None:
            return
        if self.prefix == "c":
            self.style, kind = sim.computes.get(self.ident), "compute"
            offers = self.style is not None and type(self.style).peratom is not Compute.peratom
        else:
            self.style, kind = sim.fixes.get(self.ident) or sim.analyzes.get(self.ident), "fix"
            offers = callable(getattr(self.style, "peratom", None))
        if self.style is None:
            raise ScriptError(f"{what}: {kind} {self.ident} is not defined")
        if not offers:
            raise ScriptError(f"{what}: {kind} {self.ident} ({self.style.name}) has no per-atom values")

    def needs(self, sim):
        """What the values need computed on the step they are read (``energy``, ``virial``)."""
        if self.prefix == "c":
            return sim.compute_needs(self.ident)
        return {"energy", "virial"} if self.prefix == "v" else set()

    def values(self, sim):
        """(nlocal,) floats."""
        if self.prefix == "v":
            return sim.variables.atom_values(self.ident)
        if self.style is None:
            return self._property(sim)
        return peratom_column(sim, self.style, self.column, self.what)

    def _property(self, sim):
        """The LIGGGHTS per-atom property's column, or None where ``f_NAME`` names no property."""
        p = sim.particles
        if sim.dialect.name != "liggghts" or self.ident in _CORE_ARRAYS or not p.has(self.ident):
            return None
        array = p.arrays[self.ident]
        width = 1 if array.ndim == 1 else array.shape[1]
        k = self.column
        if width == 1:
            if k not in (None, 0):
                raise ScriptError(f"{self.what}: per-atom property {self.ident} has one value per particle: "
                                  f"f_{self.ident} or f_{self.ident}[0] (got [{k}])")
            return array[: p.nlocal] if array.ndim == 1 else array[: p.nlocal, 0]
        if k is None or not 1 <= k <= width:
            raise ScriptError(f"{self.what}: per-atom property {self.ident} has {width} values per particle, "
                              f"f_{self.ident}[1] to [{width}] (got {self.word})")
        return array[: p.nlocal, k - 1]


class Analyze(Style):
    """An analyze style: reads computes at end_of_step and reduces them (time/space averages)."""
    kind = "analyze"

    def __init__(self, sim, id, group, args):
        self.sim, self.id, self.group, self.args = sim, id, group, args


class Dump(Style):
    """A dump: ``dump ID group STYLE N FILE args``; ``write(sim)`` is called every N steps."""
    kind = "dump"

    def __init__(self, sim, id, group, args):
        self.sim, self.id, self.group, self.args = sim, id, group, args
        self.every = int(getattr(args, "every", 1))
        self.first = False              # dump_modify first yes: a frame at the first step after the dump command

    def write(self, sim):
        raise NotImplementedError

    def modify_words(self, sim, keyword, rest):
        """How many words a ``dump_modify`` keyword of this style's own takes, given the words after
        it (``rest``), or None where the keyword is not one of its own (then the core's table of
        keywords says, as for sort, format and append). For keywords whose count depends on the
        dump or the words (dump image's ``element`` E1 ... EN, ``amap``)."""
        return None

    def modify(self, sim, keyword, values):
        """One ``dump_modify`` keyword with its values (words); ``every`` and ``first`` here, a style
        adds its own (a text dump: sort, format, append)."""
        if keyword == "every":
            self.every = _positive_int(values[0], "every")
        elif keyword == "first":
            if values[0] not in ("yes", "no"):
                raise ScriptError(f"first must be yes or no (got {values[0]})")
            self.first = values[0] == "yes"
        else:
            raise ScriptError(f"dump {self.id} ({self.name}) has no dump_modify keyword {keyword}")

    def close(self):
        pass


def _positive_int(word, name):
    try:
        value = int(word)
    except ValueError:
        raise ScriptError(f"{name} must be an integer (got {word})") from None
    if value < 1:
        raise ScriptError(f"{name} must be >= 1 (got {word})")
    return value


class RegionArgs(StyleArgs):
    """Keywords every LAMMPS region style takes after its own arguments: ``side in|out`` (``match``
    selects the inside or the outside) and ``units box|lattice`` (coordinates in distance units or in
    lattice spacings; the default is the dialect's: box in PDPS, lattice in LAMMPS); ``move v_dx v_dy
    v_dz`` (each v_NAME or NULL) and ``rotate v_theta Px Py Pz Rx Ry Rz``: the region displaced and
    turned by equal-style variables evaluated at each use (pdps_core.region_motion); in the LIGGGHTS
    dialect also ``volume_limit V``, the smallest volume (distance^3, default 1e-10) an insertion
    fix accepts of the region, as LIGGGHTS's region.cpp."""
    side: typing.Literal["in", "out"] = keyword("in")
    units: typing.Literal["box", "lattice"] | None = keyword(None)
    move: tuple[str, str, str] | None = keyword(None)
    rotate: tuple[str, float, float, float, float, float, float] | None = keyword(
        None, unit=("1", "distance", "distance", "distance", "1", "1", "1"))
    volume_limit: float | None = keyword(None, unit="volume")
    open: int | None = keyword(None, unit="1")


class Region(Style):
    """A region: ``region ID STYLE args``; ``inside(x)`` marks positions inside its shape, ``match(x)``
    the positions the region selects (its inside, or its outside with ``side out``). A style whose
    Args derive from ``RegionArgs`` scales its coordinates by ``self.scale`` (x, y, z lattice spacings
    with ``units lattice``, else 1; radii by the x spacing, as LAMMPS), and moves with RegionArgs's
    ``move`` and ``rotate`` (``self.motion``, applied by ``match`` and ``surface``: ``inside`` and
    ``surface_contacts`` see the shape in its own frame). ``deleted`` is set by ``region ID delete``."""
    kind = "region"
    deleted = False

    def __init__(self, sim, id, args):
        self.sim, self.id, self.args = sim, id, args
        units = getattr(args, "units", "box") or sim.dialect.region_units
        self.scale = np.ones(3)
        if units == "lattice" and sim.lattice is not None:
            self.scale = np.asarray(sim.lattice.spacing, dtype=np.float64).copy()
        self.side_out = getattr(args, "side", "in") == "out"
        self.motion = None
        if getattr(args, "open", None) is not None:
            raise ScriptError(f"open faces are not built (LAMMPS's open keyword: a region's face left out of its "
                              f"surface and its test of points) (got open {args.open})")
        if isinstance(args, RegionArgs) and (args.move or args.rotate):
            from .region_motion import RegionMotion
            self.motion = RegionMotion(id, args.move, args.rotate, self.scale)
        limit = getattr(args, "volume_limit", None)
        if limit is not None and sim.dialect.name != "liggghts":
            raise ScriptError("volume_limit is a LIGGGHTS region keyword (read as LIGGGHTS to use it)")
        self.volume_limit = 1.0e-10 if limit is None else limit

    def inside(self, x):
        raise ScriptError(f"region {self.id} ({self.name}) has no inside: it is a surface")

    def refuse_deleted(self):
        if self.deleted:
            raise ScriptError(f"region {self.id} was deleted (region {self.id} delete) but a style or region made "
                              f"with it still uses it: define that again after the new region {self.id}")

    def match(self, x):
        self.refuse_deleted()
        if self.motion is not None:
            self.motion.update(self.sim)
            x = self.motion.to_frame(np.asarray(x, dtype=np.float64).reshape(-1, 3))
        return ~self.inside(x) if self.side_out else self.inside(x)

    def surface(self, x, reach, out=None):
        """``surface_contacts`` where the region is now: a moving region's contacts found in its own
        frame and brought back (LAMMPS's Region::surface). Walls that follow a region call this."""
        self.refuse_deleted()
        if self.motion is None:
            return self.surface_contacts(x, reach, out)
        self.motion.update(self.sim)
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1, 3)
        frame = self.motion.to_frame(x)
        index, distance, normal, element = self.surface_contacts(frame, reach, out)
        self.motion.contacts_back(x, frame, index, distance, normal)
        return index, distance, normal, element

    @property
    def dynamic(self):
        """Whether the region moves (LAMMPS's dynamic_check): move or rotate, its own or a part's."""
        return self.motion is not None

    def wall_contacts(self, x, reach, out=None):
        """LAMMPS's Region::surface for granular walls where the region is now: (index, distance,
        normal, element, curvature), the contacts of ``own_wall_contacts`` found in the region's
        frame and brought back; the region remembers them for ``wall_velocity``."""
        self.refuse_deleted()
        out = out if out is not None else SurfaceContacts()
        x = np.ascontiguousarray(x, dtype=np.float64).reshape(-1, 3)
        if self.motion is None:
            rows = self.own_wall_contacts(x, reach, out)
        else:
            self.motion.update(self.sim)
            frame = self.motion.to_frame(x)
            rows = self.own_wall_contacts(frame, reach, out)
            self.motion.contacts_back(x, frame, *rows[:3])
        self._wall_rows = (x, rows)
        return rows

    def own_wall_contacts(self, x, reach, out):
        """In the region's own frame: LAMMPS's surface_interior (side in) or surface_exterior (side
        out), each contact's normal LAMMPS's (the vector from the surface to the point times 1 /
        distance) and its surface's radius of curvature (0 flat; negative concave, LAMMPS's -2R of a
        cylinder's inside); (index, distance, normal, element, curvature) in point order, in ``out``.
        A region with a granular wall surface overrides it."""
        raise ScriptError(f"region {self.id} ({self.name}) has no granular wall surface (LAMMPS's surface_interior "
                          "and surface_exterior are not built for it)")

    def set_velocity(self, step, dt):
        """The motion's velocity over the last step (LAMMPS's set_velocity); nothing for a still region."""
        if self.motion is not None:
            self.motion.set_velocity(step, dt)

    def start_run(self, moved_in):
        """A run begins (LAMMPS's init); ``moved_in``: a fix takes this region up (reset_vel)."""
        if self.motion is not None:
            if moved_in:
                self.motion.reset_velocity()
            self.motion.start_run()

    def wall_velocity(self, rows, out):
        """The wall's velocity at the contacts ``rows`` of the last ``wall_contacts`` into out (LAMMPS's
        velocity_contact)."""
        x, (index, distance, normal, _, _) = self._wall_rows
        if self.motion is None:
            out[:] = 0.0
            return
        self.motion.wall_velocity(x, index[rows], distance[rows], normal[rows], out)

    def bounds(self):
        """(lo, hi) of a box that holds the region, for create_box and lattice filling."""
        raise ScriptError(f"region {self.id} ({self.name}) has no extent to make a box from")

    def extent(self):
        """(lo, hi) like ``bounds``, but an unbounded side (INF) is a huge number instead of an error:
        LAMMPS's extent, to which create_atoms random narrows its tries."""
        return self.bounds()

    def surface_contacts(self, x, reach, out=None):
        """Where the region's surface is within ``reach`` of the points ``x`` (n x 3), for walls:
        (indices of the points, their distances to the surface, unit normals pointing from the
        surface to the point, surface element ids), in the order of the points. Several rows per
        point are allowed (one per face touched). With ``out`` (a SurfaceContacts a wall keeps) the
        rows are written into its buffers and the arrays returned are views of them, so a wall that
        asks at every step allocates nothing."""
        raise ScriptError(f"region {self.id} ({self.name}) cannot act as a wall")


class SurfaceContacts:
    """Buffers for ``Region.surface_contacts(x, reach, out)``, grown when a call needs more rows
    (a quarter more than asked, so a slowly growing count does not grow them at every step)."""

    def __init__(self):
        self.index = np.empty(0, dtype=np.int64)
        self.distance = np.empty(0)
        self.normal = np.empty((0, 3))
        self.element = np.empty(0, dtype=np.int64)
        self.curvature = np.empty(0)

    def room(self, rows):
        """(index, distance, normal, element) with room for at least ``rows`` rows (and ``curvature``,
        each contact's radius of curvature, for ``Region.own_wall_contacts``)."""
        if len(self.index) < rows:
            size = rows + rows // 4 + 16
            self.index = np.empty(size, dtype=np.int64)
            self.distance = np.empty(size)
            self.normal = np.empty((size, 3))
            self.element = np.empty(size, dtype=np.int64)
            self.curvature = np.empty(size)
        return self.index, self.distance, self.normal, self.element

    def rows(self, count):
        """The first ``count`` rows written, as surface_contacts returns them."""
        return self.index[:count], self.distance[:count], self.normal[:count], self.element[:count]

    def wall_rows(self, count):
        """The first ``count`` rows with their curvature, as own_wall_contacts returns them."""
        return (*self.rows(count), self.curvature[:count])


class SubModel(Style):
    """A part a style is composed of rather than a style of its own: one term of a granular contact
    (its normal force, its rolling friction, ...), named by a word among the host style's arguments.
    Its kind is two words, ``FAMILY.PART`` (``gran.cohesion``), and it is found in the entry-point
    group ``pdps.FAMILY.PART`` like any style, so ``pdps doc gran.cohesion sjkr`` shows it and a
    distribution can add one; what it computes and how the host calls it is the family's contract
    (the library that defines the family's base class), not the core's."""
    kind = ""


BASES = {"pair": Pair, "bond": Bond, "fix": Fix, "compute": Compute, "analyze": Analyze, "dump": Dump,
         "region": Region}


def base_of(kind):
    """The class every style of ``kind`` derives from: SubModel for a two-word kind (``gran.normal``)."""
    return BASES.get(kind, SubModel if is_sub_model_kind(kind) else None)


def is_sub_model_kind(kind):
    family, dot, part = kind.partition(".")
    return bool(dot and family.isidentifier() and part.isidentifier())


# ---- registry -----------------------------------------------------------------------------------
API_VERSION = "1.0"     # the style API (pdps_core.api) this pdps offers; plugins declare a range
DISABLE_VARIABLE = "PDPS_DISABLE_PLUGINS"
IN_PROCESS = "(registered in process)"


class PluginError(ScriptError):
    """A style that cannot be used: its distribution failed to import (``status`` "broken") or
    supports another style API ("incompatible"). ``reason`` says why, without the style's name."""

    def __init__(self, label, status, reason):
        message = f"failed to import: {reason}" if status == "broken" else reason
        super().__init__(f"{label} {message}")
        self.status, self.reason = status, reason


@dataclass(frozen=True)
class StyleEntry:
    """One style as its distribution's metadata declares it; nothing is imported to make it."""
    kind: str
    name: str
    dist: str               # distribution name, or IN_PROCESS
    version: str
    target: str             # "module:Class"
    disabled: bool = False  # its distribution is named in PDPS_DISABLE_PLUGINS


def disabled_distributions():
    """Canonical names of the distributions PDPS_DISABLE_PLUGINS (comma-separated) switches off."""
    words = os.environ.get(DISABLE_VARIABLE, "").split(",")
    return {canonicalize_name(word.strip()) for word in words if word.strip()}


def _one_line(exc):
    message = " ".join(str(exc).split())
    return f"{type(exc).__name__}: {message}" if message else type(exc).__name__


def check_api(declared, label, where):
    """Refuse (PluginError) a plugin whose declared PDPS_API range does not hold API_VERSION."""
    tail = f"this pdps has style API {API_VERSION}"
    if declared is None:
        raise PluginError(label, "incompatible", f"declares no style API range (PDPS_API in {where}); {tail}")
    try:
        if not isinstance(declared, str):
            raise TypeError("a range is a string")
        supported = SpecifierSet(declared)
    except (InvalidSpecifier, TypeError):
        raise PluginError(label, "incompatible", f"declares style API {declared!r}, not a version range "
                                                 f"such as '>=1.0,<2' (PDPS_API in {where}); {tail}") from None
    if not supported.contains(Version(API_VERSION), prereleases=True):
        raise PluginError(label, "incompatible", f"supports style API {declared.strip()}; {tail}")


class Registry:
    """Styles by kind and name: entry points of installed distributions, plus in-process ones.

    A style's distribution is imported when a script first names the style: the top-level package
    first, whose ``PDPS_API`` (a PEP 440 range such as ``">=1.0,<2"``) must hold API_VERSION, then
    the style's module. A distribution that fails either way breaks only the scripts that name its
    styles; one named in PDPS_DISABLE_PLUGINS is not seen at all."""

    def __init__(self):
        self._local = {kind: {} for kind in KINDS}
        self._entry_points = None
        self._sub_model_kinds = ()
        self._disabled = set()
        self._loaded = {}

    def _scan(self):
        """kind -> name -> distribution -> entry point, disabled distributions included."""
        if self._entry_points is None:
            found = {kind: {} for kind in KINDS}
            # one pass over the installed distributions' metadata, not one per kind (60 ms at start-up)
            installed = metadata.entry_points()
            parts = sorted({group[len("pdps."):] for group in installed.groups if group.startswith("pdps.")
                            and is_sub_model_kind(group[len("pdps."):])})
            self._sub_model_kinds = tuple(parts)
            for kind in (*KINDS, *parts):
                found[kind] = {}
                for ep in installed.select(group=f"pdps.{kind}"):
                    dist = ep.dist.name if ep.dist is not None else "?"
                    claims = found[kind].setdefault(ep.name, {})
                    claims.setdefault(dist, ep)
            self._entry_points = found
            self._disabled = disabled_distributions()
        return self._entry_points

    def _enabled(self, claims):
        return {dist: ep for dist, ep in claims.items() if canonicalize_name(dist) not in self._disabled}

    def kinds(self):
        """The style kinds, then the sub-model kinds installed distributions or this process name."""
        self._scan()
        local = [kind for kind in self._local if kind not in KINDS]
        return (*KINDS, *sorted(set(self._sub_model_kinds) | set(local)))

    def register(self, kind, name, cls):
        """Make a style class available in this process (for Python users and tests)."""
        if base_of(kind) is None:
            raise ValueError(f"unknown style kind {kind}")
        self._local.setdefault(kind, {})[name] = cls
        self._loaded.pop((kind, name), None)

    def names(self, kind):
        enabled = {name for name, claims in self._scan().get(kind, {}).items() if self._enabled(claims)}
        return sorted(enabled | set(self._local.get(kind, {})))

    def entries(self):
        """Every installed style (disabled ones marked) and every in-process one, by kind and name."""
        rows = []
        for kind in self.kinds():
            claims_by_name = self._scan().get(kind, {})
            for name, claims in sorted(claims_by_name.items()):
                enabled = self._enabled(claims)
                for dist, ep in claims.items():
                    version = ep.dist.version if ep.dist is not None else "?"
                    rows.append(StyleEntry(kind, name, dist, version, ep.value, dist not in enabled))
            for name, cls in sorted(self._local.get(kind, {}).items()):
                rows.append(StyleEntry(kind, name, IN_PROCESS, "", f"{cls.__module__}:{cls.__qualname__}"))
        return rows

    def listing(self):
        """(kind, name, distribution, module) for every installed style, without importing any."""
        return [(e.kind, e.name, e.dist, e.target) for e in self.entries()]

    def load(self, entry):
        """The class of one entry (any of several distributions claiming a name), checked as
        ``lookup`` checks it; PluginError when its distribution is broken or incompatible."""
        if entry.dist == IN_PROCESS:
            return self.checked(entry.kind, entry.name, self._local[entry.kind][entry.name])
        ep = self._scan()[entry.kind][entry.name][entry.dist]
        return self.checked(entry.kind, entry.name, self._load_entry_point(entry.kind, entry.name, ep))

    def _load_entry_point(self, kind, name, ep):
        dist = ep.dist.name if ep.dist is not None else "?"
        version = ep.dist.version if ep.dist is not None else "?"
        label = f"{kind} style {name} from {dist} {version}"
        package = ep.module.split(".")[0]
        try:
            top = importlib.import_module(package)
        except (Exception, SystemExit) as exc:
            raise PluginError(label, "broken", _one_line(exc)) from exc
        check_api(getattr(top, "PDPS_API", None), label, f"{package}/__init__.py")
        try:
            return ep.load()
        except (Exception, SystemExit) as exc:
            raise PluginError(label, "broken", _one_line(exc)) from exc

    def checked(self, kind, name, cls):
        """``cls`` if it is a style class of ``kind``, else a one-line error naming ``name``."""
        base = base_of(kind)
        if not (isinstance(cls, type) and issubclass(cls, base)):
            raise ScriptError(f"{kind} style {name} is not a {base.__name__} subclass")
        return cls

    def lookup(self, kind, name):
        key = (kind, name)
        if key in self._loaded:
            return self._loaded[key]
        if name in self._local.get(kind, {}):
            cls = self._local[kind][name]
        else:
            claims = self._scan().get(kind, {}).get(name, {})
            enabled = self._enabled(claims)
            if not enabled:
                known = self.names(kind)
                close = difflib.get_close_matches(name, known, n=1)
                hint = f"; did you mean {close[0]}?" if close else ""
                off = (f": {' and '.join(sorted(claims))} is switched off by {DISABLE_VARIABLE}"
                       if claims else "")
                from .script.unsupported import style_origin, unsupported_style
                instead = unsupported_style(kind, name)
                if instead is not None and not claims:
                    program, page = style_origin(kind, name)
                    raise ScriptError(f"{kind} style {name} is a {program} style pdps does not have; instead: "
                                      f"{instead} ({page})")
                raise ScriptError(f"unknown {kind} style {name}{off}{hint} "
                                  f"(installed: {', '.join(known) or 'none'})")
            if len(enabled) > 1:
                raise ScriptError(f"{kind} style {name} is provided by more than one distribution: "
                                  f"{' and '.join(sorted(enabled))}; uninstall one of them")
            (ep,) = enabled.values()
            cls = self._load_entry_point(kind, name, ep)
        self._loaded[key] = self.checked(kind, name, cls)
        return self._loaded[key]


registry = Registry()
