"""Commands that create styles from plugins: pair_style, pair_coeff, fix, compute, analyze, dump,
and their removal (unfix, uncompute, unanalyze, undump)."""

from ..errors import ScriptError
from ..styles import Pair, registry
from ..state import restart as restart_files
from . import command
from .words import choice, count, integer, number, type_range


def spelled(sim, kind, name, words):
    """The style class and words a line names, as the script's dialect means them (Style.respell)."""
    cls = registry.lookup(kind, name)
    respelled = cls.respell(sim.dialect.name, list(words))
    if respelled is None:
        return cls, list(words)
    cls, words = respelled
    return registry.checked(kind, name, cls), list(words)


@command("pair_style")
def pair_style(sim, args):
    if not args:
        raise ScriptError(f"expected a style; installed: {', '.join(registry.names('pair')) or 'none'}")
    if args[0] == "none":
        sim.styles.pair = None
        return
    cls, words = spelled(sim, "pair", args[0], args[1:])
    pair = cls(sim, cls.parse(words))
    if sim.pair is not None and sim.pair.name == pair.name:
        pair.coeffs = sim.pair.coeffs          # LAMMPS keeps coefficients when the style is the same
    sim.styles.pair = pair


@command("pair_coeff")
def pair_coeff(sim, args):
    if sim.pair is None:
        raise ScriptError("pair_coeff before pair_style")
    sim.require_box("pair_coeff")
    if len(args) < 2:
        raise ScriptError(f"expected I J and coefficients; usage: pair_coeff I J {sim.pair.coeff_usage}")
    ilo, ihi = type_range(args[0], sim.ntypes, "I")
    jlo, jhi = type_range(args[1], sim.ntypes, "J")
    if "*" not in args[0] + args[1] and ilo > jhi:
        ilo, ihi, jlo, jhi = jlo, jhi, ilo, ihi      # pair_coeff 2 1 means pair_coeff 1 2
    coeff = sim.pair.parse_coeff(args[2:])
    # as LAMMPS: a range sets only the pairs with I <= J (pair_coeff * 2 sets 1 2 and 2 2, not 2 3)
    pairs = [(i, j) for i in range(ilo, ihi + 1) for j in range(max(jlo, i), jhi + 1)]
    if not pairs:
        raise ScriptError(f"pair_coeff {args[0]} {args[1]} names no type pair with I <= J")
    for i, j in pairs:
        sim.pair.coeff(i, j, coeff)


def _create(sim, kind, table, args, usage):
    if len(args) < 3:
        raise ScriptError(f"expected: {usage}")
    ident, group, style = args[0], args[1], args[2]
    if sim.box is not None or kind != "fix":
        sim.require_box(kind)
    cls, words = spelled(sim, kind, style, args[3:])
    if sim.box is None and not getattr(cls, "before_box", False):
        sim.require_box(kind)
    sim.require_group(group)
    previous = table.get(ident)
    if previous is not None and kind != "fix":
        raise ScriptError(f"{kind} {ident} is already defined")
    if previous is not None and previous.name != cls.name:
        raise ScriptError(f"fix {ident} is already defined with style {previous.name}; unfix it first")
    instance = cls(sim, ident, group, cls.parse(words))
    sim.particles.request_all(cls.per_atom)
    table[ident] = instance          # a replaced fix keeps its place in the order
    if sim.styles.restored_states:
        restart_files.take_up_state(sim, kind, ident, instance)
    return instance


def _remove(sim, kind, table, args):
    count(args, 1, f"un{kind} ID")
    instance = table.get(args[0])
    if instance is None:
        raise ScriptError(f"{kind} {args[0]} is not defined")
    # a style leaves what it changed as it is now (fix move/mesh: the mesh stays where it went);
    # it may refuse, and then it stays defined
    removed = getattr(instance, "removed", None)
    if callable(removed):
        removed(sim)
    del table[args[0]]
    return instance


@command("fix")
def fix(sim, args):
    _create(sim, "fix", sim.fixes, args, "fix ID GROUP STYLE args")


@command("fix_modify")
def fix_modify(sim, args):
    """``fix_modify ID energy yes|no virial yes|no``: whether a fix's energy and virial count in
    thermo ``pe`` and ``press`` (LAMMPS's keywords); any other keyword goes to the fix's
    ``modify_param`` (LAMMPS's, e.g. ``temp`` and ``press`` of fix nvt/npt/nph)."""
    usage = "expected: fix_modify ID [energy yes|no] [virial yes|no]"
    if len(args) < 3 or len(args) % 2 == 0:
        raise ScriptError(usage)
    fix = sim.fixes.get(args[0])
    if fix is None:
        raise ScriptError(f"fix {args[0]} is not defined")
    for keyword, value in zip(args[1::2], args[2::2]):
        if keyword not in ("energy", "virial"):
            if not fix.modify_param(sim, keyword, value):
                raise ScriptError(f"unknown keyword {keyword}; {usage}")
            continue
        on = choice(value, keyword, ("yes", "no")) == "yes"
        if on and not (fix.can_energy if keyword == "energy" else fix.can_virial):
            raise ScriptError(f"fix {fix.id} ({fix.name}) has no {keyword} to contribute")
        setattr(fix, f"thermo_{keyword}", on)


@command("unfix")
def unfix(sim, args):
    _remove(sim, "fix", sim.fixes, args)


@command("compute")
def compute(sim, args):
    _create(sim, "compute", sim.computes, args, "compute ID GROUP STYLE args")


@command("compute_modify")
def compute_modify(sim, args):
    """LAMMPS's ``compute_modify ID dynamic|dynamic/dof yes [extra/dof N]`` for a temperature
    compute or thermo's own (``thermo_temp``): pdps counts a temperature's particles each time it
    is read, which is ``dynamic yes`` (particles inserted or lost during a run count at once); ``no``
    is refused. ``extra/dof N`` (``extra`` in LIGGGHTS) sets the degrees of freedom a temperature
    compute of the script or thermo's own (``thermo_temp``) takes off (LAMMPS's default: the
    dimension); thermo's pressure and ke follow its temperature's."""
    usage = "compute_modify ID [dynamic yes] [dynamic/dof yes] [extra/dof N]"
    if len(args) < 3 or len(args) % 2 == 0:
        raise ScriptError(f"expected an ID and keyword/value pairs; usage: {usage}")
    ident = args[0]
    if ident not in ("thermo_temp", "thermo_press") and ident not in sim.computes:
        raise ScriptError(f"compute {ident} is not defined")
    for key, value in zip(args[1::2], args[2::2]):
        choice(key, "compute_modify keyword", ("dynamic", "dynamic/dof", "extra/dof", "extra"))
        if key in ("dynamic", "dynamic/dof"):
            if choice(value, key, ("yes", "no")) == "no":
                raise ScriptError(f"{key} no is not supported: pdps counts a temperature's particles each time "
                                  f"it is read (LAMMPS's {key} yes)")
            continue
        extra = number(value, key)
        compute = sim.computes.get(ident)
        if compute is not None and hasattr(compute, "extra_dof"):
            compute.extra_dof = extra
        elif ident == "thermo_temp" and compute is None:
            sim.output.thermo.extra_dof = extra
        elif extra != sim.dimension:
            raise ScriptError(f"{key} {value} is not supported for {ident}: it takes no degrees of freedom off")


@command("uncompute")
def uncompute(sim, args):
    _remove(sim, "compute", sim.computes, args)


@command("analyze")
def analyze(sim, args):
    _create(sim, "analyze", sim.analyzes, args, "analyze ID GROUP STYLE args")


@command("unanalyze")
def unanalyze(sim, args):
    _remove(sim, "analyze", sim.analyzes, args)


@command("dump")
def dump(sim, args):
    usage = "dump ID GROUP STYLE N FILE [columns...]"
    if len(args) < 5:
        raise ScriptError(f"expected: {usage}")
    if args[0] in sim.output.dumps:
        raise ScriptError(f"dump {args[0]} is already defined")
    integer(args[3], "N", low=1)
    resolved = list(args)
    _create(sim, "dump", sim.output.dumps, resolved, usage)


# dump_modify keywords and how many words each takes (format: a kind and a format string)
DUMP_MODIFY = {"every": 1, "first": 1, "append": 1, "sort": 1, "format": 2, "flush": 1, "pad": 1,
               "units": 1, "time": 1, "thresh": 3, "element": None, "region": 1, "colname": 2,
               "scale": 1, "image": 1, "precision": 1, "delay": 1, "skip": 1, "maxfiles": 1, "nfile": 1,
               "fileper": 1, "header": 1, "buffer": 1, "refresh": 1, "label": 1}


@command("dump_modify")
def dump_modify(sim, args):
    """LAMMPS's ``dump_modify ID keyword value ...``: every and first for any dump; sort, format,
    append (and flush, accepted) for the text dumps; a style's own keywords, as many words as its
    ``modify_words`` says (dump image's acolor, amap, element...). In the LIGGGHTS dialect ``format "F1 F2 ..."``
    is LIGGGHTS's one string for the whole line (LAMMPS's ``format line``; LAMMPS refuses it now)."""
    usage = "dump_modify ID [every N] [first yes|no] [sort id|off|N|-N] [format line|int|float|N FMT] [append yes|no]"
    if len(args) < 3:
        raise ScriptError(f"expected a dump ID and keywords; usage: {usage}")
    dump = sim.output.dumps.get(args[0])
    if dump is None:
        raise ScriptError(f"dump {args[0]} is not defined")
    k, words = 1, args
    while k < len(words):
        keyword = words[k]
        own = dump.modify_words(sim, keyword, words[k + 1:])
        if own is not None:
            if len(words) - k - 1 < own:
                raise ScriptError(f"dump_modify {keyword} needs {own} value(s) here (got {len(words) - k - 1})")
            dump.modify(sim, keyword, words[k + 1:k + 1 + own])
            k += 1 + own
            continue
        arity = DUMP_MODIFY.get(keyword, 0)
        if keyword not in DUMP_MODIFY:
            raise ScriptError(f"unknown dump_modify keyword {keyword}; usage: {usage}")
        if arity is None or keyword in ("thresh", "element", "region", "colname", "scale", "image", "precision",
                                        "delay", "skip", "maxfiles", "nfile", "fileper", "header", "buffer",
                                        "refresh", "label", "units", "time", "pad"):
            raise ScriptError(f"dump_modify {keyword} is not supported (supported: every, first, sort, format, "
                              "append, flush)")
        if keyword == "format" and k + 1 < len(words) and words[k + 1] == "none":
            arity = 1
        one_string = (keyword == "format" and sim.dialect.dump_format_string and k + 1 < len(words)
                      and words[k + 1] not in ("line", "int", "float", "none") and not words[k + 1].isdigit())
        if one_string:
            arity = 1
        values = ["line", words[k + 1]] if one_string else words[k + 1:k + 1 + arity]
        if len(values) < arity:
            raise ScriptError(f"dump_modify {keyword} needs {arity} value(s); usage: {usage}")
        if keyword == "flush":
            choice(values[0], "flush", ("yes", "no"))   # pdps flushes every frame whole
        else:
            dump.modify(sim, keyword, values)
        k += 1 + arity


@command("undump")
def undump(sim, args):
    _remove(sim, "dump", sim.output.dumps, args).close()


@command("write_dump")
def write_dump(sim, args):
    """LAMMPS's ``write_dump GROUP STYLE FILE [columns...] [modify dump_modify-words...]``: one frame of
    a dump of that style now, as ``dump`` with the same words would write it at this step, then the
    dump is gone (LAMMPS's WRITE_DUMP)."""
    usage = "write_dump GROUP STYLE FILE [columns...] [modify dump_modify-keywords...]"
    if len(args) < 3:
        raise ScriptError(f"expected a group, a style and a file; usage: {usage}")
    words, modify = list(args), []
    if "modify" in words:
        k = words.index("modify")
        words, modify = words[:k], words[k + 1:]
        if not modify:
            raise ScriptError(f"modify needs dump_modify keywords; usage: {usage}")
    sim.require_box("write_dump")
    name = "WRITE_DUMP"
    if name in sim.output.dumps:
        raise ScriptError(f"dump {name} is defined by the script: write_dump needs the name")
    group, style, file, *columns = words
    dump(sim, [name, group, style, "1", file, *columns])
    try:
        if modify:
            dump_modify(sim, [name, *modify])
        sim.output.dumps[name].write(sim)
    finally:
        undump(sim, [name])


@command("pair_modify")
def pair_modify(sim, args):
    """``pair_modify mix geometric|arithmetic|sixthpower shift yes|no tail yes|no``: how unset i != j
    coefficients are derived, whether energies are shifted to zero at the cutoff, whether the long-range
    tail corrections join pe and press (LAMMPS's keywords)."""
    usage = "expected: pair_modify [mix geometric|arithmetic|sixthpower] [shift yes|no] [tail yes|no]"
    if sim.pair is None:
        raise ScriptError("pair_modify before pair_style")
    if not args or len(args) % 2:
        raise ScriptError(usage)
    for keyword, value in zip(args[::2], args[1::2]):
        if keyword == "mix":
            sim.pair.mix_rule = choice(value, "mix rule", ("geometric", "arithmetic", "sixthpower"))
        elif keyword == "shift":
            sim.pair.shift = choice(value, "shift", ("yes", "no")) == "yes"
        elif keyword == "tail":
            sim.pair.tail = choice(value, "tail", ("yes", "no")) == "yes"
            if sim.pair.tail and type(sim.pair).tail_ij is Pair.tail_ij:
                raise ScriptError(f"pair style {sim.pair.name} has no tail correction")
        else:
            raise ScriptError(f"unknown keyword {keyword}; {usage}")
