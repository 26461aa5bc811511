"""What ``pdps styles -v`` and ``pdps doc`` say about a style, read from its class and its module.

``describe(cls)`` reads the class attributes a style declares (hooks it defines, per-atom arrays,
ghost data, neighbor lists, what it adds to thermo). ``document(entry, cls)`` lays out the module
docstring and the ``Args``/``Coeff`` models in the PDPS manual's sections: Syntax, Examples,
Description, Parameters, Default; each parameter with its script name, type, bounds, default and
the kind of quantity declared with ``param(..., unit=...)``.
"""

import inspect
import sys
import types
import typing

import annotated_types
from pydantic_core import PydanticUndefined

from .run.hookspec import HOOKS
from .styles import BASES, IN_PROCESS, Pair, StyleArgs, SubModel, VariableRef, _is_keyword, member_names

NONE = "-"


# ---- styles -v ----------------------------------------------------------------------------------
def _defines(cls, name):
    """Whether the style (not its kind's base class) defines method ``name``."""
    method = getattr(cls, name, None)
    return callable(method) and method is not getattr(BASES[cls.kind], name, None)


def _per_atom_name(item):
    if isinstance(item, tuple):
        name, width = item[0], item[1] if len(item) > 1 else 1
        return f"{name}[{width}]" if width != 1 else name
    return str(item)


def describe(cls):
    """{"hooks": [...], "needs": [...], "contributes": [...]}: a style's declared behaviour."""
    hooks = [hook for hook in ("init_run", *HOOKS) if _defines(cls, hook)]
    needs, contributes = [], []
    if cls.per_atom:
        needs.append("per-atom " + ", ".join(_per_atom_name(item) for item in cls.per_atom))
    if issubclass(cls, Pair):
        needs.append(f"{cls.neighbor_list} neighbor list")
        law_atom = getattr(cls, "law_atom", ())
        if getattr(cls, "law", None) is not None or getattr(cls, "law_source", None) is not None:
            hooks.insert(0, "force law in the core's pair loop")
            if law_atom:
                needs.append("per-atom " + ", ".join(law_atom) + " in the force law")
        else:
            hooks.insert(0, "compute (its own pair loop)")
        contributes.append("pair forces, energy and virial")
    if getattr(cls, "neighbor_lists_needed", False):
        needs.append("neighbor lists (requested in init_run)")
    if cls.ghost_velocity:
        needs.append("ghost velocities")
    if cls.ghost_fields:
        needs.append("ghost " + ", ".join(cls.ghost_fields))
    if getattr(cls, "needs_energy", False):
        needs.append("energy on the steps it is read")
    if getattr(cls, "needs_virial", False):
        needs.append("virial on the steps it is read")
    if getattr(cls, "can_energy", False):
        contributes.append("energy to pe (fix_modify ID energy yes)")
    if getattr(cls, "can_virial", False):
        contributes.append("virial to press (on; fix_modify ID virial no)" if getattr(cls, "virial_default", False)
                           else "virial to press (fix_modify ID virial yes)")
    if _defines(cls, "dof_removed"):
        contributes.append("removed degrees of freedom to temperatures")
    return {"hooks": hooks, "needs": needs, "contributes": contributes}


def verbose_lines(cls):
    """The indented lines ``pdps styles -v`` prints under a style."""
    facts = describe(cls)
    return [f"    {label + ':':<13} {'; '.join(facts[label]) or NONE}" for label in ("hooks", "needs", "contributes")]


# ---- pdps doc -----------------------------------------------------------------------------------
def _blocks(lines):
    """The docstring's top-level blocks as (kind, first line, end line): "para" paragraphs, and
    "literal" indented blocks after a paragraph that ends with ``::``."""
    blocks, i = [], 0
    while i < len(lines):
        if not lines[i].strip():
            i += 1
            continue
        start = i
        if lines[i].startswith((" ", "\t")) and blocks and lines[blocks[-1][2] - 1].rstrip().endswith("::"):
            while i < len(lines) and (not lines[i].strip() or lines[i].startswith((" ", "\t"))):
                i += 1
            while not lines[i - 1].strip():
                i -= 1
            blocks.append(("literal", start, i))
            continue
        while i < len(lines) and lines[i].strip():
            i += 1
        blocks.append(("para", start, i))
    return blocks


def _sections(doc):
    """(summary, syntax blocks, example blocks, description) of a module docstring: the summary is
    its first paragraph; ``Syntax::`` and ``Example...::`` blocks go to their sections; the
    description is the rest, as written."""
    lines = inspect.cleandoc(doc or "").splitlines()
    blocks = _blocks(lines)
    summary, syntax, examples, taken = "", [], [], set()
    for k, (kind, start, end) in enumerate(blocks):
        text = "\n".join(lines[start:end])
        heading = text.strip().lower()
        if kind == "para" and not summary:
            summary = text
            taken.add(k)
        elif kind == "para" and heading.startswith(("syntax", "example")) and "::" in heading:
            # "Example::" heading a literal block, or "Syntax::  fix ID ..." on one line
            rest = text.partition("::")[2].strip()
            target = syntax if heading.startswith("syntax") else examples
            if rest:
                target.append(inspect.cleandoc(rest))
            elif k + 1 < len(blocks) and blocks[k + 1][0] == "literal":
                target.append(inspect.cleandoc("\n".join(lines[blocks[k + 1][1]:blocks[k + 1][2]])))
                taken.add(k + 1)
            taken.add(k)
    kept = [lines[start:end] for k, (_, start, end) in enumerate(blocks) if k not in taken]
    description = "\n\n".join("\n".join(block) for block in kept)
    return summary, syntax, examples, description


def _indent(text, prefix="    "):
    return "\n".join(prefix + line if line.strip() else "" for line in text.splitlines())


def _number(value):
    return f"{value:g}" if isinstance(value, float) else str(value)


def _type_name(annotation):
    if member_names(annotation):
        return " ".join(member_names(annotation))
    origin, members = typing.get_origin(annotation), typing.get_args(annotation)
    if origin is typing.Annotated:
        return _type_name(members[0])
    if origin is typing.Literal:
        return "|".join(map(str, members))
    if origin in (typing.Union, types.UnionType):
        return " or ".join(_type_name(m) for m in members if m is not type(None))
    if origin is tuple:
        if len(members) == 2 and members[1] is Ellipsis:
            return f"{_type_name(members[0])}..."
        return " ".join(_type_name(m) for m in members)
    if origin is list:
        return f"{_type_name(members[0]) if members else 'word'}..."
    return {float: "number", int: "integer", bool: "yes|no", str: "word", VariableRef: "v_NAME"}.get(
        annotation, getattr(annotation, "__name__", str(annotation)))


def _bounds(name, info):
    low = high = None
    for item in info.metadata:
        if isinstance(item, annotated_types.Gt):
            low = f"{_number(item.gt)} <"
        elif isinstance(item, annotated_types.Ge):
            low = f"{_number(item.ge)} <="
        elif isinstance(item, annotated_types.Lt):
            high = f"< {_number(item.lt)}"
        elif isinstance(item, annotated_types.Le):
            high = f"<= {_number(item.le)}"
        elif isinstance(item, annotated_types.MinLen):
            low = f"at least {item.min_length} word(s)" if item.min_length else None
    if low and low.startswith("at least"):
        return low
    if low and high:
        return f"{low} {name} {high}"
    if low:
        flipped = {"<": ">", "<=": ">="}[low.split()[1]]
        return f"{name} {flipped} {low.split()[0]}"
    return f"{name} {high}" if high else ""


def _default(info):
    """The default as a script would write it, "" for a required field, None for none."""
    if info.is_required():
        return ""
    if info.default_factory is not None:
        value = info.default_factory()
    else:
        value = info.default
    if value is None or value is PydanticUndefined or value == [] or value == ():
        return None
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (tuple, list)):
        return " ".join(_number(v) for v in value)
    return _number(value)


def unit_of(info):
    extra = info.json_schema_extra
    return extra.get("unit") if isinstance(extra, dict) else None


def names_of(info):
    """What each word of a declared list of names is ("region ID"), or None."""
    extra = info.json_schema_extra
    return extra.get("names") if isinstance(extra, dict) else None


def parameter_lines(model):
    """One manual line per field: ``- name: type; bounds; unit; default`` (keywords marked)."""
    lines = []
    for field, info in model.model_fields.items():
        name = info.alias or field
        names = names_of(info)
        plain = typing.get_origin(info.annotation) is list and typing.get_args(info.annotation) == (str,)
        parts = [f"{names}..." if names and plain else _type_name(info.annotation)]
        if names and not plain:
            parts.append(f"names: {names}")
        bounds = _bounds(name, info)
        if bounds:
            parts.append(bounds)
        unit = unit_of(info)
        if unit:
            parts.append(f"unit: {unit}")
        default = _default(info)
        parts.append("required" if default == "" else "optional" if default is None else f"default {default}")
        label = f"{name} (keyword)" if _is_keyword(info) else name
        lines.append(f"- {label}: {'; '.join(parts)}")
    return lines


def defaults(model):
    values = []
    for field, info in model.model_fields.items():
        default = _default(info)
        if default:
            values.append(f"{info.alias or field} = {default}")
    return values


def models(cls):
    """The style's argument models: Args, Coeff, then any other nested StyleArgs class, then those
    of the other spellings of its name (``spellings()``, labelled ``Class.Args``)."""
    found = {}
    for klass in reversed(cls.__mro__):
        for attr, value in vars(klass).items():
            if isinstance(value, type) and issubclass(value, StyleArgs) and value is not StyleArgs:
                found[attr] = value
    ordered = sorted(found, key=lambda attr: ({"Args": 0, "Coeff": 1}.get(attr, 2), attr))
    own = [(attr, found[attr]) for attr in ordered if found[attr].model_fields]
    return own + [(f"{other.__name__}.{attr}", model) for other in cls.spellings() for attr, model in models(other)
                  if model not in dict(own).values()]


def _command(cls, attr):
    if attr == "Args":
        return cls.usage or f"{cls.kind} ... {cls.name}"
    if issubclass(cls, Pair):
        return f"pair_coeff I J {cls.coeff_usage}".rstrip()
    return ""


def document(entry, cls):
    """The manual page of a style (module docstring plus its argument models)."""
    module = sys.modules.get(cls.__module__)
    doc = inspect.getdoc(module) if module is not None else None
    summary, syntax, examples, description = _sections(doc or inspect.getdoc(cls) or "")
    origin = entry.dist if entry.dist == IN_PROCESS else f"{entry.dist} {entry.version}"
    what = "sub-model" if issubclass(cls, SubModel) else "style"
    out = [f"{cls.kind} {what} {cls.name}  ({origin})", ""]
    if summary:
        out += [summary, ""]
    usage = [cls.usage] if cls.usage else []
    if issubclass(cls, Pair) and cls.coeff_usage:
        usage.append(f"pair_coeff I J {cls.coeff_usage}")
    if syntax or usage:
        out += ["Syntax:", ""] + [_indent(text) for text in (syntax or ["\n".join(usage)])] + [""]
    if examples:
        out += ["Examples:", ""] + [_indent(text) + "\n" for text in examples]
    if description:
        out += ["Description:", "", description, ""]
    out += ["Parameters:", ""]
    declared = models(cls)
    spelled = {other.__name__: other for other in cls.spellings()}
    for attr, model in declared:
        heading = inspect.getdoc(model) if model.__doc__ else None
        command = _command(cls, attr)
        title = command if attr in ("Args", "Coeff") else f"{attr}: {heading or command}"
        owner, _, inner = attr.partition(".")
        if owner in spelled:
            title = f"or, as {_command(spelled[owner], inner) or attr}"
        out += [title.splitlines()[0] if title else attr] + parameter_lines(model) + [""]
    if not declared:
        out += ["(none)", ""]
    values = [value for _, model in declared for value in defaults(model)]
    out += ["Default:", "", ", ".join(values) if values else "none", ""]
    return "\n".join(out).rstrip() + "\n"
