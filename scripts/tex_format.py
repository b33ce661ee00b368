"""The number and text formats of the reproduction report (scripts/report.py): LaTeX of a number in
each format of \\result[fmt], escaped prose, typewriter names that break, the opening of a longtable."""
import math
import re
import unicodedata

NA = None  # a value that cannot be shown


def sci(x, digits=2):
    """m\\times10^{e} with `digits` significant digits."""
    if x == 0:
        return "0"
    mant, exp = f"{x:.{digits - 1}e}".split("e")
    return mant if int(exp) == 0 else rf"{mant}\times10^{{{int(exp)}}}"


def sig(x, n):
    """Fixed notation with n significant digits, trailing zeros kept; large integers unrounded."""
    if x == 0:
        return "0"
    return f"{x:.{max(0, n - 1 - math.floor(math.log10(abs(x))))}f}"


def sci_or_sig(x, n):
    """Scientific below 1e-3 and from 1e4, else n significant digits."""
    return "0" if x == 0 else sci(x, n) if abs(x) < 1e-3 or abs(x) >= 1e4 else sig(x, n)


def grouped(x):
    n = int(round(x))
    return f"{n:,}".replace(",", r"\,") if abs(n) >= 10000 else f"{n}"


def tolerance(x):
    mant, exp = f"{x:.1e}".split("e")
    return f"10^{{{int(exp)}}}" if mant == "1.0" else sci(x)


FORMATS = {  # name -> math-mode text of a finite number
    "general": lambda x: "0" if x == 0 else sci(x) if abs(x) < 1e-3 or abs(x) >= 1e4 else sig(x, 4),
    "order": lambda x: f"{x:.3f}",
    "porder": lambda x: f"{x:.0f}" if float(x).is_integer() else f"{x:.3f}",
    "dorder": lambda x: f"{x:+.3f}",
    "int": grouped,
    "intplain": lambda x: f"{int(round(x))}",
    "err": lambda x: "0" if x == 0 else sci(x) if abs(x) < 1e-3 or abs(x) >= 1e4 else sig(x, 2),
    "sci": sci,
    "sci1": lambda x: sci(x, 1),
    "sci01": lambda x: "0" if x == 0 else sci(x) if abs(x) < 1e-2 else sig(x, 2),
    "fixed3": lambda x: f"{x:.3f}",
    "fixed5": lambda x: f"{x:.5f}",
    "sig3": lambda x: sig(x, 3),
    "sig4": lambda x: sig(x, 4),
    "sig5": lambda x: sig(x, 5),
    "sig7": lambda x: sig(x, 7),
    "sci3": lambda x: sci_or_sig(x, 3),
    "sci4": lambda x: sci_or_sig(x, 4),
    "us": lambda x: sig(x * 1e6, 2) if x > 0 else NA,
    "tol": tolerance,
    "ns": lambda x: f"{x:.1f}",
    "ns3": lambda x: sig(x, 3) if x > 0 else NA,
    "percent": lambda x: "0\\,\\%" if x == 0 else sig(100 * x, 3) + "\\,\\%",
    "ratio": lambda x: f"{x:.1f}",
    "seconds": lambda x: f"{x:.2g}" if abs(x) < 100 else f"{x:.0f}",
    "plain": lambda x: f"{x:g}",
}
def tex_escape(text):
    repl = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#", "_": r"\_", "{": r"\{",
            "}": r"\}", "~": r"\textasciitilde{}", "^": r"\textasciicircum{}", "<": r"\textless{}",
            ">": r"\textgreater{}", "|": r"\textbar{}"}
    return re.sub(r"-(?=-)", "-{}", "".join(repl.get(c, c) for c in str(text)))  # (--set, not an en dash)


UNICODE_MATH = {"ω": r"\omega", "β": r"\beta", "α": r"\alpha", "√": r"\surd", "→": r"\to", "≤": r"\le", "≥": r"\ge",
                "−": "-", "‹": "<", "›": ">", "′": "'"}
ACCENTS = {"\u0302": r"\hat", "\u0303": r"\tilde", "\u0304": r"\bar", "\u0307": r"\dot"}


def quote_tex(text):
    """A paper's words as its text here gives them: $...$ and $$...$$ (the LaTeX of the converted papers)
    as math, the rest escaped; Greek letters and symbols typed as Unicode (the OCR'd papers) as math."""
    out = []
    for i, part in enumerate(re.split(r"(\$\$.*?\$\$|\$.*?\$)", unicodedata.normalize("NFC", text))):
        if i % 2:
            out.append("$" + part.strip("$").strip() + "$")
        else:
            for j, piece in enumerate(re.split(r"(\w[\u0300-\u036f])", part)):  # a letter with an accent
                if j % 2:
                    out.append(f"${ACCENTS.get(piece[1], '')}{{{piece[0]}}}$")
                else:
                    out.append("".join(f"${UNICODE_MATH[c]}$" if UNICODE_MATH.get(c, "").startswith("\\")
                                       else tex_escape(UNICODE_MATH.get(c, c)) for c in piece))
    return "".join(out)


GNUPLOT_MATH = {"Φ": r"\Phi", "Ψ": r"\Psi", "²": "^2", "³": "^3"}


def gnuplot_tex(text):
    """A gnuplot enhanced text (the registry's titles: "Φ^{(4)}_h", "h²/24") as LaTeX: its sub- and
    superscripts and Greek letters as math, the rest escaped."""
    text = "".join(GNUPLOT_MATH.get(c, c) for c in text)
    out, at = [], 0
    for m in re.finditer(r"(?:\\[A-Za-z]+|[A-Za-z])?(?:[\^_](?:\{[^{}]*\}|\w))+|\\[A-Za-z]+", text):
        out += [tex_escape(text[at:m.start()]), "$" + m.group(0) + "$"]
        at = m.end()
    return "".join(out + [tex_escape(text[at:])])


# In free text (published.toml's notes, the registry's citations): a file (a/b.hpp, fig9.csv), a name
# with an underscore (se_compensated_energy_rms, cost.phase.h_max) or a test's (Lobatto.EquationTwelve),
# and a symbol with a one-letter subscript (p_x, H_0, Psi_{h,E}).
NAME = re.compile(r"(?<![\w/.\\{])(?:(?P<file>(?:[\w.-]+/)*[\w-]+\.(?:csv|hpp|cpp|toml|json|py|gp|txt)\b)"
                  r"|(?P<sym>[A-Za-z]+_(?:\{[^{}\s]*\}|[A-Za-z0-9](?![\w])))"
                  r"|(?P<name>(?:\w+\.)*\w*[A-Za-z]\w*_\w+(?:\.\w+)*|(?:\w+\.)+[A-Z][a-z]\w*[A-Z]\w*))")
GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "lambda", "mu", "phi", "psi", "omega", "sigma", "theta",
         "Phi", "Psi", "Omega", "Lambda", "Delta", "Gamma", "Sigma", "Theta"}


def prose(text):
    """Escaped free text: files and names with an underscore as code, symbols with a one-letter subscript as
    math; what is left may break after a slash."""
    out, at = [], 0
    for m in NAME.finditer(str(text)):
        out.append(re.sub(r"/(?=\w)", r"/\\allowbreak{}", tex_escape(text[at:m.start()])))
        if m.group("sym"):
            base, sub = m.group("sym").split("_", 1)
            out.append(f"${chr(92) + base if base in GREEK else base}_{{{sub.strip('{}')}}}$")
        else:
            out.append(code(m.group(0)))
        at = m.end()
    out.append(re.sub(r"/(?=\w)", r"/\\allowbreak{}", tex_escape(str(text)[at:])))
    return "".join(out)


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def number(v, fmt):
    """Math-mode text of a number in a format, or None if it has none (null, NaN, inf, out of domain)."""
    if not is_number(v) or not math.isfinite(v):
        return None
    return FORMATS[fmt](v)


def value_text(v):
    """A published or reproduced value: a number, or a table of them keyed by a parameter."""
    if isinstance(v, dict):  # keyed by a name, or by a number written as %.17g (shown as %g)
        return "; ".join(f"{prose(key_text(k))}: {value_text(x)}" for k, x in v.items())
    if is_number(v):
        return "$" + (number(v, "sci3") or tex_escape(v)) + "$" if math.isfinite(v) else tex_escape(v)
    return "not computed" if v is None else tex_escape(v)


def key_text(k):
    try:
        return f"{float(k):g}"
    except ValueError:
        return k


def longtable(size, *fractions):
    """The opening of a longtable of ragged-right columns whose widths are these fractions of the line,
    their padding (2 tabcolsep between two columns) included, so that the table never runs past the margin."""
    n = len(fractions)
    pad = f"{2 * (n - 1) / n:.4f}"
    cols = "".join(f">{{\\raggedright\\arraybackslash}}p{{\\dimexpr{f}\\linewidth-{pad}\\tabcolsep\\relax}}"
                   for f in fractions)
    return f"{{\\{size}\\begin{{longtable}}{{@{{}}{cols}@{{}}}}"


def code(text):
    """Typewriter text that may break after its dots, slashes and underscores."""
    broken = re.sub(r"(\.|/|\\_)", r"\1\\allowbreak{}", tex_escape(text))
    return r"\texttt{" + re.sub(r"(?<=[a-z0-9])(?=[A-Z])", r"\\allowbreak{}", broken) + "}"  # (and in CamelCase)
