"""The input-script lexer, following LAMMPS's parsing rules.

1. A line ending in ``&`` continues on the next line: the ``&`` is removed and the lines are joined
   as they stand. A line with an open ``\"\"\"`` continues too, keeping its line break.
2. ``#`` starts a comment, unless it stands inside quotes.
3. ``$x`` and ``${name}`` are replaced by the variable's value, unless inside quotes.
4. The line is split into words at white space; ``"..."``, ``'...'`` and ``\"\"\"...\"\"\"`` make one word.
"""

from ..errors import ScriptError

QUOTES = ('"""', '"', "'")


def logical_lines(text):
    """Yield (first physical line number, text) with continuations joined, as LAMMPS reads them."""
    pending, start = "", None
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.rstrip()
        if start is None:
            start = number
        if line.endswith("&"):
            pending += line[:-1]
            continue
        pending += line
        if pending.count('"""') % 2:
            pending += "\n"
            continue
        yield start, pending
        pending, start = "", None
    if start is not None:
        yield start, pending


def _shown(text):
    """A line as an error message quotes it: on one line, even when a triple quote spans several."""
    return " ".join(text.split())


def _quote_at(text, i):
    for quote in QUOTES:
        if text.startswith(quote, i):
            return quote
    return None


def _end_of_quote(text, i, quote):
    end = text.find(quote, i + len(quote))
    if end < 0:
        raise ScriptError(f"unbalanced quote {quote} in: {_shown(text)}")
    return end + len(quote)


def strip_comment(text):
    """Remove a ``#`` comment that is not inside quotes."""
    i = 0
    while i < len(text):
        quote = _quote_at(text, i)
        if quote:
            i = _end_of_quote(text, i, quote)
        elif text[i] == "#":
            return text[:i]
        else:
            i += 1
    return text


def substitute(text, value_of):
    """Replace ``$x``, ``${name}`` and ``$(expression)`` outside quotes; ``value_of(name)`` gives the text."""
    out, i = [], 0
    while i < len(text):
        quote = _quote_at(text, i)
        if quote:
            end = _end_of_quote(text, i, quote)
            out.append(text[i:end])
            i = end
            continue
        if text[i] != "$":
            out.append(text[i])
            i += 1
            continue
        if text.startswith("${", i):
            end = text.find("}", i)
            if end < 0:
                raise ScriptError(f"unterminated ${{ in: {_shown(text)}")
            name, i = text[i + 2:end], end + 1
            out.append(value_of(name))
        elif text.startswith("$(", i):
            depth, j = 0, i + 1
            while j < len(text):
                depth += {"(": 1, ")": -1}.get(text[j], 0)
                if depth == 0:
                    break
                j += 1
            if depth:
                raise ScriptError(f"unterminated $( in: {_shown(text)}")
            out.append(value_of("(" + text[i + 2:j] + ")"))
            i = j + 1
        elif i + 1 < len(text) and not text[i + 1].isspace():
            out.append(value_of(text[i + 1]))
            i += 2
        else:
            raise ScriptError(f"a lone $ in: {_shown(text)}")
    return "".join(out)


def split_words(text):
    """Split at white space; quoted text is one word, without its quotes."""
    words, i, n = [], 0, len(text)
    while i < n:
        if text[i].isspace():
            i += 1
            continue
        word, quoted = [], False
        while i < n and not text[i].isspace():
            quote = _quote_at(text, i)
            if quote:
                end = _end_of_quote(text, i, quote)
                word.append(text[i + len(quote):end - len(quote)])
                quoted, i = True, end
            else:
                word.append(text[i])
                i += 1
        if word or quoted:
            words.append("".join(word))
    return words


def read_text(path, what, shown=None, top=False):
    """The text of a file a script names (``what``: "input script", "data file"), as UTF-8; a file
    that cannot be read is a one-line error naming it, bad bytes one located as ``FILE:LINE:``
    (``shown``: the name to give the file, default its path). ``top``: the script pdps was given,
    which no line names, so the file itself is the error's location."""
    try:
        with open(path, "rb") as handle:
            raw = handle.read()
    except OSError as exc:
        if top:
            raise ScriptError(f"cannot read this {what}: {exc.strerror}", source=shown or path) from None
        raise ScriptError(f"cannot read {what} {path}: {exc.strerror}") from None
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        raise ScriptError(f"{shown or path}:{line}: not UTF-8 text (byte 0x{raw[exc.start]:02x}); "
                          f"{what}s are read as UTF-8") from None
    # a NUL is damage in any text file, and no file name may hold one
    nul = raw.find(b"\0")
    if nul >= 0:
        line = raw.count(b"\n", 0, nul) + 1
        raise ScriptError(f"{shown or path}:{line}: a NUL byte (0x00) in the text; {what}s are plain text")
    return text
