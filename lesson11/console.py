"""Output that survives a console that is not UTF-8 (Windows' cp1252 when output is redirected, an ASCII locale).

The lesson's messages use θ, ω, ×, ², ½, ≤, → ...; a stream whose encoding cannot hold one would raise
UnicodeEncodeError in the middle of a report. `safe_output()`, called once at a program's start, makes
sys.stdout and sys.stderr write a readable ASCII stand-in instead (θ -> theta, × -> x, ² -> ^2,
½ -> 1/2, ≤ -> <=, → -> ->), and `\\u....` for a character that has none. A stream that can encode
everything (UTF-8, the usual case on Linux, macOS and a real Windows console) is left exactly as it was.
Shared by the checker's command line, the lab windows (through lesson11.runtime), the explorer, the quiz,
the examples and the benchmarks.
"""
import codecs
import sys
import unicodedata

HANDLER = "lesson11-readable"

# Characters the lesson and the checker print, and what a console that cannot show them gets instead.
STAND_INS = {
    "θ": "theta", "ω": "omega", "μ": "mu", "µ": "mu", "π": "pi", "Σ": "Sum", "Δ": "Delta", "ζ": "zeta",
    "α": "alpha", "β": "beta", "λ": "lambda", "ε": "eps", "φ": "phi", "τ": "tau",
    "×": "x", "·": "*", "÷": "/", "±": "+/-", "√": "sqrt", "°": " deg", "∞": "inf", "≈": "~",
    "≤": "<=", "≥": ">=", "≠": "!=", "→": "->", "←": "<-", "↑": "up", "↓": "down",
    "½": "1/2", "⅓": "1/3", "⅔": "2/3", "¼": "1/4", "¾": "3/4",
    "–": "-", "—": "--", "‘": "'", "’": "'", "“": '"', "”": '"', "…": "...", "§": "section ",
    "\u00a0": " ",
}
# Superscripts: a run of them becomes ^ and plain characters (10⁻⁶ -> 10^-6, m/s² -> m/s^2).
SUPERSCRIPTS = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+"))


def readable(text, after=""):
    """text with every character of STAND_INS / SUPERSCRIPTS replaced, an accented letter by its plain one
    (a student's name: José -> Jose), others kept; `after` is the character just before text (a superscript
    run that continues one gets no second ^)."""
    out, previous = [], after
    for char in text:
        if char in SUPERSCRIPTS:
            out.append(("" if previous in SUPERSCRIPTS else "^") + SUPERSCRIPTS[char])
        elif char in STAND_INS:
            out.append(STAND_INS[char])
        else:
            plain = unicodedata.normalize("NFKD", char).encode("ascii", "ignore").decode("ascii")
            out.append(plain if plain and unicodedata.category(char).startswith("L") else char)
        previous = char
    return "".join(out)


def _stand_in(error):
    """codecs error handler: the unencodable run as readable ASCII, anything left as a backslash escape."""
    if not isinstance(error, UnicodeEncodeError):
        raise error
    run = error.object[error.start:error.end]
    text = readable(run, error.object[error.start - 1] if error.start else "")
    return text.encode("ascii", "backslashreplace").decode("ascii"), error.end


codecs.register_error(HANDLER, _stand_in)


def needs_stand_ins(encoding):
    """True when `encoding` cannot write every character (any encoding but UTF-8/16/32)."""
    try:
        return not codecs.lookup(encoding or "ascii").name.startswith("utf")
    except LookupError:
        return True


def safe_output(streams=None):
    """Make each stream (default sys.stdout and sys.stderr) write stand-ins instead of raising
    UnicodeEncodeError; streams that are UTF-8, or that cannot be reconfigured (a test's capture), are left."""
    for stream in (sys.stdout, sys.stderr) if streams is None else streams:
        reconfigure = getattr(stream, "reconfigure", None)
        if reconfigure is not None and needs_stand_ins(getattr(stream, "encoding", None)):
            try:
                reconfigure(errors=HANDLER)
            except (ValueError, OSError):  # a stream closed or detached under us: leave it as it is
                pass
