"""One reading of a lab file, the compiler's: its text and its lines exactly as Python counts them.

Every part of the checker that numbers, compares or compiles a file's lines
(the step regions, the handout comparison, the step rules, the probe splices,
the child that runs it) reads it through here, so none of them can disagree
with Python about which code is on which line:

  decode(raw, name)   the bytes decoded as Python decodes them (tokenize.detect_encoding); a file that
                      declares any coding but UTF-8 (a student never needs one, and `unicode_escape` turns
                      comments into code) or that is not valid UTF-8 is refused with one line (SourceError)
  lines(text)         the lines split only where the tokenizer breaks them: \\n, \\r\\n, \\r (never at
                      \\x0c, \\x1c, \\x85, U+2028 ... which str.splitlines() also breaks at)
  read(path)          decode() of the file's bytes
  check(text, name)   the guard: the syntax tree's last line must be one of lines(text)
"""
import ast
import codecs
import encodings.utf_8_sig  # noqa: F401 - the BOM's codec, imported while the child may still read the stdlib
import io
import re
import tokenize

UTF8 = frozenset({"utf-8", "utf-8-sig"})      # codecs' names for utf-8, utf8, UTF_8, utf-8-sig ...
LINE_BREAK = re.compile(r"\r\n|\r|\n")        # the tokenizer's line ends, and only those


class SourceError(ValueError):
    """A file the checker refuses to read as Python source (one line: the file and what is wrong)."""


def decode(raw, name="the file"):
    """The text Python compiles from the bytes `raw`; SourceError unless it is UTF-8 (with or without a BOM)."""
    try:
        encoding, _ = tokenize.detect_encoding(io.BytesIO(raw).readline)
    except SyntaxError as exc:       # bytes that are not UTF-8, an unknown coding, a BOM with another coding
        _utf8(raw, name)             # the bytes, when that is the trouble
        raise SourceError(f"{name}: {exc.msg}; save it as UTF-8 and remove any `# coding:` line") from None
    if codecs.lookup(encoding).name not in UTF8:
        raise SourceError(f"{name} declares `# coding: {encoding}`; save it as UTF-8 and remove the line")
    return _utf8(raw, name, encoding)


def _utf8(raw, name, encoding="utf-8"):
    """raw decoded as `encoding` (utf-8 or utf-8-sig); SourceError naming the first byte that is not UTF-8."""
    try:
        return raw.decode(encoding)
    except UnicodeDecodeError as bad:
        line = raw[:bad.start].count(b"\n") + 1
        raise SourceError(f"{name} is not UTF-8 text: byte 0x{raw[bad.start]:02x} on line {line} cannot be "
                          "read; save the file as UTF-8") from None


def read(path, name=None):
    """decode() of the file at `path` (OSError if it cannot be read)."""
    with open(path, "rb") as handle:
        return decode(handle.read(), name or path)


def lines(text):
    """The lines of `text` as the tokenizer counts them, without their line ends (like str.splitlines())."""
    parts = LINE_BREAK.split(text)
    return parts[:-1] if parts[-1] == "" else parts


def check(text, name="the file"):
    """SourceError when the syntax tree reaches past the lines the checker counts; the tree otherwise.

    None when `text` does not parse (the checks that run it say so).
    """
    try:
        tree = ast.parse(text)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return None
    last = max((getattr(node, "end_lineno", None) or 0 for node in ast.walk(tree)), default=0)
    if last > len(lines(text)):
        raise SourceError(f"{name} has line breaks Python does not count (its code reaches line {last}, "
                          f"the checker counts {len(lines(text))}); save it again with ordinary line ends")
    return tree
