"""Hypothesis strategies that damage input files the way users and disks do.

Scripts and data files are mutated as lines of bytes: a number becomes huge, tiny, negative, 0,
nan, inf, 1e308, 2147483648 or a neighbour of itself; a word is replaced (by another word of the
corpus, a special token, a non-UTF-8 byte), deleted or duplicated; lines are deleted, duplicated,
swapped, moved, or inserted (from another seed, or from a list of lines known to be hard); the file is
truncated, gets tabs, CRLF, continuation marks, stray quotes or bytes that are not UTF-8. Data files
also get their sections (Masses, Atoms, Velocities) duplicated, dropped, swapped and renamed.

Restart files (a zip of header.json and .npy arrays) are mutated at three levels: a value of the JSON
header (replaced by another value or type, removed, nested deeply), an array (values set to nan, inf,
huge, negative; rows dropped or added; reshaped; another dtype) and the archive (members dropped,
duplicated, renamed, compressed; bytes flipped; the file cut short).

Every strategy returns ``(files, mutations)``: the new file contents and one line per mutation saying
what was done, so a failing case can be read as well as rerun.
"""

import io
import json
import math
import re
import warnings
import zipfile
from collections import Counter

import numpy as np
from hypothesis import strategies as st

NUMBERS = ["0", "-0", "0.0", "-1", "-1e-300", "1", "2", "1e308", "-1e308", "1.8e308", "1e309",
           "1e-308", "5e-324", "1e-9", "1e9", "1e26", "nan", "NaN", "-nan", "inf", "-inf",
           "Infinity", "2147483647", "2147483648", "-2147483648", "-2147483649", "4294967296",
           "9223372036854775807", "9223372036854775808", "-9223372036854775809",
           "18446744073709551616", "99999999999999999999999999", "1" + "0" * 400, "0.5", "1.5",
           "-0.5", "0x10", "1e", "1e+", ".", "-", "+1", "--1", "1.0.0", "1,5", "1_000", "\u0661",
           "3.", ".5e1"]
TOKENS = ["*", "1*", "*1", "0*", "*0", "2*1", "1*99", "**", "${x}", "${", "$", "$x", "$(1/0)",
          "$(2^2000)", "$(v_nope)", "v_a", "v_", "c_1", "c_1[9]", "c_t[0][0]", "c_", "f_1", "\"",
          "'", '"""', "&", "#", "NULL", "EDGE", "INF", "-INF", "all", "none", "yes", "no", ".", "..",
          "/nonexistent/dir/x", "", "\t", "a" * 300, "box", "fill", "ITEM:", "Atoms", "Masses",
          "Velocities", "atomic", "sphere", "gaussian", "uniform", "units", "lattice", "region"]
BAD_BYTES = [b"\xff", b"\xfe\xff", b"\xc3\x28", b"\x80", b"\xed\xa0\x80", b"\xf4\x90\x80\x80",
             b"\x00", b"\x1b[2J", b"\r", b"\x0c", b"\xe2\x80\xa8", b"\xef\xbb\xbf"]
# Lines that the issue or experience names as hard; inserted anywhere in a script.
HARD_LINES = [
    "variable a equal v_a+1", "variable b equal v_c*2", "variable c equal v_b+1", 'print "${a}"',
    "print $(v_b)", "variable x equal 1e308*10", "variable y equal 1/0", "thermo_style custom step v_x",
    "log .", "log /nonexistent/dir/x.log", "log ..", "include in.fuzz", "include missing.inc",
    "include .", "create_box 2147483648 box", "create_box 99999999999999999999 box",
    "region box block 0 1e-9 0 1e-9 0 1e-9", "region box block 0 1e26 0 1e26 0 1e26",
    "region box block 0 1e300 0 1 0 1", "region box block 1 0 0 1 0 1",
    "run 99999999999999999999999999", "run 9223372036854775807", "run -1", "run 1e3", "run nan",
    "timestep nan", "timestep 1e308", "timestep 0", "timestep -1", "thermo 2147483648", "thermo -1",
    "neighbor 1e308", "neighbor nan", "neighbor -1", "neigh_modify every 0", "neigh_modify delay -1",
    "mass * inf", "mass * 0", "mass * nan", "mass 99 1", "velocity all set 1e308 1e308 1e308",
    "velocity all set nan 0 0", "velocity all create 1e308 1", "velocity all create 1 0",
    "reset_timestep 9223372036854775807", "reset_timestep -5", "write_restart /nonexistent/dir/r",
    "write_restart .", "dump 9 all atom 1 /nonexistent/dir/d", "dump 9 all atom 0 d9.atom",
    "next nosuch", "lattice spacing x 1e-9 y 1e-9 z 1e-9", "lattice fcc 1e308", "lattice sc 0",
    "create_particle 1 single nan 0 0", "create_particle 1 single 1e300 1 1",
    "create_particle 1 random_no_overlap 100000 box 1.0 7", "processors 0 1 1", "dimension 5",
    "boundary x y z", "units nonsense", "atom_modify sort 1 1e-300", "comm_modify vel yes",
    "group g1 type 0", "group g2 type 2147483648", "fix 99 all nve", "unfix nosuch",
    "pair_style none", "thermo_style custom c_nope", "write_restart w.restart",
    "read_restart w.restart", "read_data nowhere.data", "read_data in.fuzz", "read_restart in.fuzz",
]
DATA_SECTIONS = ("Masses", "Atoms", "Velocities")
NUMBER = re.compile(rb"^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")


def is_number(word):
    return bool(NUMBER.match(word))


def _format(value):
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e16:
        return str(int(value))
    return repr(value)


def number_for(draw, word):
    """A replacement for the number ``word``: an extreme, a value hypothesis picks, or a neighbour."""
    choice = draw(st.integers(0, 4))
    if choice == 0:
        return draw.choice(NUMBERS).encode()
    if choice == 1:
        value = draw(st.floats(allow_nan=True, allow_infinity=True))
        return _format(value).encode()
    if choice == 2:
        return str(draw(st.integers(-2**70, 2**70))).encode()
    value = float(word)
    if choice == 3:
        factor = draw(st.sampled_from([-1.0, 0.0, 0.5, 2.0, 10.0, 1e3, 1e-3, 1e6, 1e-6, 1.0001]))
        new = value * factor
    else:
        new = value + draw(st.sampled_from([-2.0, -1.0, 1.0, 2.0]))
    if b"." in word or b"e" in word.lower() or not math.isfinite(new):
        return _format(new).encode()
    return str(int(new)).encode()


def _words(line):
    return line.split()


def _lines(data):
    return data.split(b"\n")


def _join(lines):
    return b"\n".join(lines)


class Drawer:
    """Hypothesis's ``draw``, plus uniform picks of positions and list items from a random.Random that
    hypothesis seeds (its own integers favour small values: the first lines and keys of every file)."""

    def __init__(self, draw):
        self.draw = draw
        self.random = draw(st.randoms(use_true_random=True))

    def __call__(self, strategy):
        return self.draw(strategy)

    def pick(self, n):
        return self.random.randrange(n)

    def choice(self, items):
        return items[self.random.randrange(len(items))]


def _pick(draw, items):
    return draw.pick(len(items))


# ---- line-and-word mutations (scripts and data files) -----------------------------------------------
def mutate_number(draw, data, context):
    lines = _lines(data)
    spots = [(i, k) for i, line in enumerate(lines) for k, w in enumerate(_words(line)) if is_number(w)]
    if not spots:
        return None
    i, k = spots[_pick(draw, spots)]
    words = _words(lines[i])
    new = number_for(draw, words[k])
    old, words[k] = words[k], new
    lines[i] = b" ".join(words)
    return _join(lines), f"line {i + 1}: number {old!r} -> {new!r}"


def mutate_word(draw, data, context):
    lines = _lines(data)
    spots = [(i, k) for i, line in enumerate(lines) for k in range(len(_words(line)))]
    if not spots:
        return None
    i, k = spots[_pick(draw, spots)]
    words = _words(lines[i])
    how = draw(st.sampled_from(["replace", "token", "delete", "duplicate", "swap", "bytes"]))
    old = words[k]
    if how == "replace":
        words[k] = draw.choice(context["vocabulary"])
    elif how == "token":
        words[k] = draw.choice(TOKENS).encode()
    elif how == "delete":
        del words[k]
    elif how == "duplicate":
        words.insert(k, old)
    elif how == "swap" and k + 1 < len(words):
        words[k], words[k + 1] = words[k + 1], words[k]
    elif how == "bytes":
        words[k] = old + draw(st.sampled_from(BAD_BYTES))
    lines[i] = b" ".join(words)
    return _join(lines), f"line {i + 1}: word {k + 1} {old!r}: {how} -> {lines[i][:120]!r}"


def mutate_line(draw, data, context):
    lines = _lines(data)
    how = draw(st.sampled_from(["delete", "duplicate", "swap", "move", "insert", "hard", "repeat"]))
    i = _pick(draw, lines)
    if how == "delete":
        del lines[i]
    elif how == "duplicate":
        lines.insert(i, lines[i])
    elif how in ("swap", "move"):
        j = _pick(draw, lines)
        if how == "swap":
            lines[i], lines[j] = lines[j], lines[i]
        else:
            lines.insert(j, lines.pop(i))
        how += f" with line {j + 1}"
    elif how == "insert":
        new = draw.choice(context["lines"])
        lines.insert(i, new)
        how += f" {new!r}"
    elif how == "hard":
        new = draw.choice(HARD_LINES).encode()
        lines.insert(i, new)
        how += f" {new!r}"
    else:
        count = draw(st.sampled_from([2, 3, 10, 100]))
        lines[i:i + 1] = [lines[i]] * count
        how += f" x{count}"
    return _join(lines), f"line {i + 1}: {how}"


def mutate_bytes(draw, data, context):
    how = draw(st.sampled_from(["truncate", "insert", "tabs", "crlf", "continue", "quote", "empty",
                                "double"]))
    at = draw.pick(len(data) + 1)
    if how == "truncate":
        return data[:at], f"truncated to {at} bytes"
    if how == "insert":
        bad = draw(st.sampled_from(BAD_BYTES))
        return data[:at] + bad + data[at:], f"byte {at}: inserted {bad!r}"
    if how == "tabs":
        if draw(st.booleans()):
            return data.replace(b" ", b"\t"), "every space a tab"
        lines = _lines(data)
        i = _pick(draw, lines)
        lines[i] = re.sub(rb" +", b"\t", lines[i])
        return _join(lines), f"line {i + 1}: spaces -> tabs"
    if how == "crlf":
        return data.replace(b"\n", b"\r\n"), "CRLF line ends"
    if how == "continue":
        lines = _lines(data)
        i = _pick(draw, lines)
        lines[i] += b" &"
        return _join(lines), f"line {i + 1}: & appended"
    if how == "quote":
        mark = draw(st.sampled_from([b'"', b"'", b'"""']))
        return data[:at] + mark + data[at:], f"byte {at}: inserted {mark!r}"
    if how == "empty":
        return b"", "emptied"
    return data + b"\n" + data, "the whole file twice"


# ---- data-file sections ------------------------------------------------------------------------------
def _sections(lines):
    """[(start, end)] of each section: its name line up to the next section name (header excluded)."""
    starts = [i for i, line in enumerate(lines) if i > 0 and line.strip()[:1].isalpha()
              and line.split()[0] in [s.encode() for s in DATA_SECTIONS]]
    return [(s, e) for s, e in zip(starts, starts[1:] + [len(lines)])]


def mutate_section(draw, data, context):
    lines = _lines(data)
    sections = _sections(lines)
    if not sections:
        return None
    how = draw(st.sampled_from(["delete", "duplicate", "swap", "rename", "empty", "header", "count"]))
    k = _pick(draw, sections)
    s, e = sections[k]
    name = lines[s].split()[0]
    if how == "delete":
        del lines[s:e]
    elif how == "duplicate":
        lines[e:e] = lines[s:e]
    elif how == "swap":
        j = _pick(draw, sections)
        s2, e2 = sections[j]
        if j != k:
            (a, b), (c, d) = sorted([(s, e), (s2, e2)])
            lines = lines[:a] + lines[c:d] + lines[b:c] + lines[a:b] + lines[d:]
        how += f" with {lines[s2].split()[0] if s2 < len(lines) and lines[s2].split() else b''!r}"
    elif how == "rename":
        new = draw(st.sampled_from([b"Atoms # sphere", b"Atoms # atomic", b"Atoms # full", b"Atoms",
                                    b"masses", b"Velocities", b"Masses", b"Bonds", b"Pair Coeffs",
                                    b"Atoms # atomic # sphere"]))
        lines[s] = new
        how += f" -> {new!r}"
    elif how == "empty":
        del lines[s + 1:e]
    elif how == "header":
        end = sections[0][0]
        i = draw.pick(max(1, end))
        new = draw(st.sampled_from([b"0 atoms", b"-1 atoms", b"2147483648 atoms", b"1e3 atoms",
                                    b"0 atom types", b"99 atom types", b"2147483648 atom types",
                                    b"nan 1 xlo xhi", b"0 0 xlo xhi", b"1 0 ylo yhi",
                                    b"0 1e-9 zlo zhi", b"-1e308 1e308 xlo xhi", b"0 1e26 ylo yhi",
                                    b"inf -inf zlo zhi", b"1 atoms", b"3 bonds", b"0.0 0.0 0.0 xy xz yz",
                                    b"1\tatom\ttypes", b"2 atoms # comment"]))
        lines.insert(i, new)
        how += f" line {new!r} at {i + 1}"
    else:
        body = [i for i in range(s + 1, e) if lines[i].strip()]
        if not body:
            return None
        i = body[_pick(draw, body)]
        count = draw(st.sampled_from([0, 2, 50]))
        lines[i:i + 1] = [lines[i]] * count
        how += f": line {i + 1} x{count}"
    return _join(lines), f"section {name!r} (line {s + 1}): {how}"


SKIPPED = Counter()        # mutations that could not apply to what earlier ones left, by kind


def _apply(operation, draw, data, context):
    """``operation(draw, data, context)``, or None (counted in SKIPPED) when it cannot apply to
    what earlier mutations left (a member already removed, an array already unreadable)."""
    try:
        return operation(draw, data, context)
    except Exception as exc:                   # noqa: BLE001  (hypothesis's own stops pass: BaseException)
        SKIPPED[f"{operation.__name__}: {type(exc).__name__}"] += 1
        return None


MUTATION_COUNTS = [1, 1, 1, 2, 2, 3, 4]        # mostly one: a case close to a valid input goes deeper
TEXT_MUTATIONS = [mutate_number, mutate_number, mutate_word, mutate_line, mutate_bytes]


def mutated_text(draw, data, context, operations):
    """``data`` after 1 to 4 of ``operations`` (mostly 1); the list of what was done."""
    done = []
    for _ in range(draw(st.sampled_from(MUTATION_COUNTS))):
        operation = draw(st.sampled_from(operations))
        result = _apply(operation, draw, data, context)
        if result is None:
            continue
        data, what = result
        done.append(what)
    return data, done


@st.composite
def script_case(draw, seeds, context):
    """A seed script (and its files) with its script, or one of its other text files, mutated."""
    draw = Drawer(draw)
    seed = draw.choice(seeds)
    files = dict(seed.files)
    target = seed.script
    others = [n for n in files if n != seed.script and not n.endswith(".stl")]
    if others and draw(st.integers(0, 9)) == 0:
        target = draw(st.sampled_from(sorted(others)))
    data, done = mutated_text(draw, files[target], context, TEXT_MUTATIONS)
    files[target] = data
    return seed, files, [f"{target}: {d}" for d in done]


@st.composite
def data_case(draw, seeds, context):
    """A seed data file mutated (lines, words, numbers, bytes, sections); its script as it is."""
    draw = Drawer(draw)
    seed = draw.choice(seeds)
    files = dict(seed.files)
    operations = TEXT_MUTATIONS + [mutate_section, mutate_section]
    data, done = mutated_text(draw, files[seed.target], context, operations)
    files[seed.target] = data
    return seed, files, [f"{seed.target}: {d}" for d in done]


# ---- restart files -----------------------------------------------------------------------------------
JSON_VALUES = [float("nan"), float("inf"), float("-inf"), 0, -1, 1e308, -1e308, 2**31, 2**63, 2**64,
               10**30, -(2**63) - 1, 0.5, -0.0, 5e-324, "", "x", "nan", "lj", "atomic", "sphere", None,
               True, False, [], {}, [1, 2], [0, 0, 0], {"a": 1}, [[1]], "p", "f", 3, 5, 99]


def _paths(value, path=()):
    yield path
    if isinstance(value, dict):
        for k, v in value.items():
            yield from _paths(v, path + (k,))
    elif isinstance(value, list):
        for k, v in enumerate(value):
            yield from _paths(v, path + (k,))


def _get(value, path):
    for key in path:
        value = value[key]
    return value


def _set(value, path, new):
    if not path:
        return new
    _get(value, path[:-1])[path[-1]] = new
    return value


def mutate_header(draw, members, context):
    try:
        header = json.loads(members["header.json"])
    except (KeyError, ValueError, RecursionError):  # an earlier mutation removed or broke it
        return None
    paths = list(_paths(header))
    path = paths[_pick(draw, paths)]
    where = "/".join(str(p) for p in path) or "(top)"
    how = draw(st.sampled_from(["value", "value", "number", "delete", "nest", "text", "duplicate"]))
    old = _get(header, path)
    if how == "number" and isinstance(old, (int, float)) and not isinstance(old, bool):
        new = draw(st.sampled_from([-old, old * 0, old * 2, old + 1, old - 1, old * 1e300,
                                    old * 1e-300]))
        header = _set(header, path, new)
        text = json.dumps(header).encode()
        what = f"{where}: {old!r} -> {new!r}"
    elif how == "delete" and path:
        parent = _get(header, path[:-1])
        del parent[path[-1]]
        text = json.dumps(header).encode()
        what = f"{where}: removed"
    elif how == "nest":
        depth = draw(st.sampled_from([50, 2000, 100000]))
        marker = "\u0000NEST\u0000"
        text = json.dumps(_set(header, path, marker)).encode()
        text = text.replace(json.dumps(marker).encode(), b"[" * depth + b"1" + b"]" * depth)
        what = f"{where}: nested {depth} deep"
    elif how == "text":
        raw = members["header.json"]
        choice = draw(st.sampled_from(["truncate", "bytes", "empty", "not json", "array"]))
        at = draw.pick(len(raw) + 1)
        text = {"truncate": raw[:at], "bytes": raw[:at] + b"\xff\xfe" + raw[at:], "empty": b"",
                "not json": b"not json", "array": b"[" + raw + b"]"}[choice]
        what = f"header.json: {choice} at {at}"
    elif how == "duplicate" and path and isinstance(path[-1], str):
        raw = json.dumps(header)
        key = json.dumps(path[-1])
        new = draw.choice(JSON_VALUES)
        text = raw.replace(f"{key}: ", f"{key}: {json.dumps(new)}, {key}: ", 1).encode()
        what = f"{where}: key given twice, first as {new!r}"
    else:
        new = draw.choice(JSON_VALUES)
        header = _set(header, path, new)
        text = json.dumps(header).encode()
        what = f"{where}: {old!r:.60} -> {new!r}"
    members = dict(members)
    members["header.json"] = text
    return members, f"header.json {what}"


def _npy(array):
    buffer = io.BytesIO()
    np.lib.format.write_array(buffer, array, allow_pickle=False)
    return buffer.getvalue()


def _set_value(draw, array):
    """One element of ``array`` set to an extreme of its kind: (new array, what was done)."""
    flat = array.reshape(-1).copy()
    k = draw.pick(flat.size)
    if flat.dtype.kind == "f":
        new = draw(st.sampled_from([np.nan, np.inf, -np.inf, 1e308, -1e308, 0.0, -1.0, 1e-300,
                                    flat[k] * 1e6, -flat[k]]))
    elif flat.dtype.kind in "iu":
        info = np.iinfo(flat.dtype)
        new = draw(st.sampled_from([0, -1, 1, 99, info.max, info.min, int(flat[k]) + 1]))
        new = min(max(new, info.min), info.max)
    elif flat.dtype.kind == "b":
        new = not flat[k]
    else:
        return None
    old = flat[k]
    flat[k] = new
    return flat.reshape(array.shape), f"element {k}: {old!r} -> {new!r}"


def mutate_array(draw, members, context):
    names = sorted(n for n in members if n.endswith(".npy"))
    if not names:
        return None
    name = draw.choice(names)
    try:
        array = np.lib.format.read_array(io.BytesIO(members[name]), allow_pickle=False)
    except Exception:                              # noqa: BLE001  (an earlier mutation broke it)
        return None
    how = draw(st.sampled_from(["value", "value", "rows", "rows", "reshape", "dtype", "empty",
                                "duplicate", "bytes"]))
    if how == "value" and array.size:
        with np.errstate(all="ignore"):
            result = _set_value(draw, array)
        if result is None:
            return None
        array, what = result
    elif how == "rows" and array.ndim:
        count = draw(st.sampled_from([-1, -2, 1, 2, -10**6]))
        if count > 0:
            array = np.concatenate([array, array[-1:].repeat(count, axis=0)]) if len(array) else array
        else:
            array = array[:count] if -count < len(array) else array[:0]
        what = f"rows {count:+d}"
    elif how == "reshape":
        shape = draw(st.sampled_from(["flat", "transpose", "column", "scalar", "3d"]))
        if shape == "flat":
            array = array.reshape(-1)
        elif shape == "transpose":
            array = array.T.copy()
        elif shape == "column":
            array = array.reshape(-1, 1)
        elif shape == "scalar":
            array = np.asarray(array.reshape(-1)[0] if array.size else 0)
        else:
            array = array.reshape(1, 1, -1)
        what = f"reshaped {shape} to {array.shape}"
    elif how == "dtype":
        dtype = draw(st.sampled_from(["float32", "int8", "uint64", "bool", "complex128", "<U3",
                                      ">f8", "float16"]))
        with np.errstate(all="ignore"), warnings.catch_warnings():
            warnings.simplefilter("ignore")      # numpy's ComplexWarning: the loss is the point
            try:
                array = array.astype(dtype)
            except (TypeError, ValueError):
                return None
        what = f"dtype -> {dtype}"
    elif how == "empty":
        array = np.zeros((0,) + array.shape[1:], dtype=array.dtype)
        what = "emptied"
    elif how == "duplicate" and array.ndim and len(array) >= 2:
        array = array.copy()
        array[1] = array[0]
        what = "row 1 = row 0"
    elif how == "bytes":
        raw = bytearray(members[name])
        at = draw.pick(len(raw))
        raw[at] ^= draw(st.integers(1, 255))
        members = dict(members)
        members[name] = bytes(raw)
        return members, f"{name}: byte {at} flipped"
    else:
        return None
    members = dict(members)
    members[name] = _npy(array)
    return members, f"{name}: {what}"


def mutate_archive(draw, members, context):
    """Archive-level damage: returns the mutated member table, or raw bytes for the whole file."""
    names = sorted(members)
    how = draw(st.sampled_from(["drop", "duplicate", "rename", "extra", "deflate", "flip", "cut",
                                "empty", "text"]))
    members = dict(members)
    name = draw.choice(names)
    if how == "drop":
        del members[name]
        return members, f"member {name} removed"
    if how == "duplicate":
        return (members, [(name, members[name])]), f"member {name} stored twice"
    if how == "rename":
        new = draw(st.sampled_from(["header.JSON", "x.npy", "../evil.npy", "particles/tag.npy",
                                    name + ".bak", "mass.npy"]))
        members[new] = members.pop(name)
        return members, f"member {name} renamed {new}"
    if how == "extra":
        members[draw(st.sampled_from(["junk.npy", "particles/extra.npy", "notes.txt"]))] = \
            _npy(np.arange(3.0))
        return members, "an extra member"
    if how == "deflate":
        return (members, "deflate"), "members compressed (deflate)"
    whole = build_restart(members)
    at = draw.pick(len(whole))
    if how == "flip":
        raw = bytearray(whole)
        raw[at] ^= draw(st.integers(1, 255))
        return bytes(raw), f"byte {at} of the file flipped"
    if how == "cut":
        return whole[:at], f"file cut to {at} bytes"
    if how == "empty":
        return b"", "empty file"
    return b"read_restart is not a script\n", "a text file"


def build_restart(members, extra=(), compression=zipfile.ZIP_STORED):
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression) as archive, warnings.catch_warnings():
        warnings.simplefilter("ignore")          # a duplicate member is the point
        for name, data in members.items():
            archive.writestr(name, data)
        for name, data in extra:
            archive.writestr(name, data)
    return buffer.getvalue()


def read_restart_members(data):
    with zipfile.ZipFile(io.BytesIO(data)) as archive:
        return {name: archive.read(name) for name in archive.namelist()}


@st.composite
def restart_case(draw, seeds, context):
    """A seed restart file damaged by 1 to 3 mutations of its header, arrays or archive."""
    draw = Drawer(draw)
    seed = draw.choice(seeds)
    files = dict(seed.files)
    members = read_restart_members(files[seed.target])
    done, raw = [], None
    operations = [mutate_header, mutate_header, mutate_header, mutate_array, mutate_array,
                  mutate_array, mutate_archive]
    for _ in range(draw(st.integers(1, 3))):
        result = _apply(draw(st.sampled_from(operations)), draw, members, context)
        if result is None:
            continue
        value, what = result
        done.append(what)
        if isinstance(value, bytes):
            raw = value
            break
        if isinstance(value, tuple):
            members, extra = value
            raw = build_restart(members, compression=zipfile.ZIP_DEFLATED) if extra == "deflate" \
                else build_restart(members, extra)
            break
        members = value
    files[seed.target] = raw if raw is not None else build_restart(members)
    return seed, files, [f"{seed.target}: {d}" for d in done]
