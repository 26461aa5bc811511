"""The words of a ``pair_coeff`` line of LAMMPS's pair granular (and of ``fix wall/gran ...
granular``): a normal model and its coefficients first, then sections in any order, each a keyword,
a model word and that model's coefficients, and two settings::

    hertz/material E eta_n0 nu  damping coeff_restitution  tangential mindlin NULL 1.0 0.5
    rolling sds k_roll gamma_roll mu_roll  twisting marshall  limit_damping  cutoff 0.01

pdps_core's keyword parser takes keywords of a fixed form; here a keyword's model word decides how
many numbers follow, so the line is cut into sections here (a section starts at a keyword; a model
takes as many numbers as its ``Args`` has fields) and each model's numbers are then read by
``parse_args`` into its declared ``Args``: the bounds, units and messages are the declared ones.
"""

from pdps_core.api import ScriptError, parse_args, registry

from .base import Law

SECTIONS = ("damping", "tangential", "rolling", "twisting", "heat")
KEYWORDS = SECTIONS + ("limit_damping", "cutoff")
USAGE = ("NORMAL coefficients [damping DAMPING] tangential TANGENTIAL coefficients [rolling sds coefficients] "
         "[twisting marshall|sds coefficients] [limit_damping] [cutoff DISTANCE]")
# the parts LAMMPS lets a line leave out, and what it then uses
DEFAULTS = {"damping": "viscoelastic"}


def sub_model(part, word):
    """The class of ``part``'s model ``word``, or a one-line error listing the installed ones."""
    known = registry.names(f"granular.{part}")
    if word not in known:
        raise ScriptError(f"{part} model must be one of {', '.join(known)} (got {word})")
    return registry.lookup(f"granular.{part}", word)


def coefficients(part, cls, words, start):
    """The ``Args`` of model ``cls`` from the numbers at words[start:], and where they end."""
    names = cls.coefficient_names()
    taken = []
    for word in words[start:start + len(names)]:
        if word in KEYWORDS:
            break
        taken.append(word)
    if len(taken) < len(names):
        raise ScriptError(f"{part} {cls.name} needs {len(names)} coefficient(s) ({' '.join(names)}) "
                          f"(got {len(taken)}{': ' + ' '.join(taken) if taken else ''})")
    try:
        return parse_args(cls.Args, taken), start + len(names)
    except ScriptError as exc:
        raise ScriptError(f"{part} {cls.name}: {exc}") from None


def read_law(words):
    """The Law of one pair_coeff line's words (after the two types)."""
    if not words or words[0] in KEYWORDS:
        raise ScriptError(f"pair granular needs a normal model first (usage: pair_coeff I J {USAGE})"
                          + (f" (got {words[0]})" if words else ""))
    if words[0] == "classic":
        raise ScriptError("pair granular's classic model is not built in pdps: use pair_style gran/hooke, "
                          "gran/hooke/history or gran/hertz/history (got classic)")
    cls = sub_model("normal", words[0])
    args, i = coefficients("normal", cls, words, 1)
    parts, limit_damping, cutoff = {"normal": (cls, args)}, False, None
    while i < len(words):
        word = words[i]
        if word == "limit_damping":
            limit_damping, i = True, i + 1
            continue
        if word == "cutoff":
            if i + 1 >= len(words):
                raise ScriptError("cutoff needs a distance (got nothing)")
            try:
                cutoff = float(words[i + 1])
            except ValueError:
                raise ScriptError(f"cutoff must be a number (got {words[i + 1]})") from None
            if not cutoff > 0.0 and cutoff != -1.0:
                raise ScriptError(f"cutoff must be > 0 (got {words[i + 1]})")
            cutoff, i = (None if cutoff == -1.0 else cutoff), i + 2
            continue
        if word not in SECTIONS:
            raise ScriptError(f"keyword must be one of {', '.join(KEYWORDS)} (got {word})")
        if i + 1 >= len(words) or words[i + 1] in KEYWORDS:
            raise ScriptError(f"{word} needs a model (got {words[i + 1] if i + 1 < len(words) else 'nothing'})")
        if word in parts:
            raise ScriptError(f"{word} is given twice (got {words[i + 1]})")
        if words[i + 1] == "none" and word in ("rolling", "twisting", "heat"):
            i += 2
            continue
        if word == "heat":
            raise ScriptError(f"heat models of pair granular are not built in pdps: they need LAMMPS's fix heat/flow "
                              f"and atom style sphere/temp, which pdps has not (got heat {words[i + 1]})")
        cls = sub_model(word, words[i + 1])
        args, i = coefficients(word, cls, words, i + 2)
        parts[word] = (cls, args)
    if "tangential" not in parts:
        raise ScriptError("pair granular needs a tangential model: ... tangential TANGENTIAL coefficients (got none)")
    for part, word in DEFAULTS.items():
        if part not in parts:
            cls = sub_model(part, word)
            parts[part] = (cls, parse_args(cls.Args, []))
    law = Law(parts, limit_damping, cutoff, words=tuple(words))
    check(law)
    return law


def check(law):
    """LAMMPS's refusals of combinations, and each model's own checks."""
    normal = law.parts["normal"][0]
    if normal.cohesive and law.limit_damping:
        raise ScriptError(f"limit_damping cannot be used with a cohesive normal model (got {normal.name})")
    for part, (cls, _) in law.parts.items():
        if normal.cohesive and not cls.allows_cohesion:
            raise ScriptError(f"{part} {cls.name} cannot be used with a cohesive normal model (got {normal.name})")
        cls.check(law)
