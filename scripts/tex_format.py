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
    "ratio": lambda x: next((t for t in (f"{x:.{d}f}" for d in (1, 2, 3)) if float(t) != 1), f"{x:.1f}"),  # (1.03,
    # not 1.0, beside a timing's verdict "slower": the digits that tell it from 1)
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


def unicode_tex(text):
    """Escaped text with its Greek letters and symbols typed as Unicode (the OCR'd papers) as math."""
    return "".join(f"${UNICODE_MATH[c]}$" if UNICODE_MATH.get(c, "").startswith("\\")
                   else tex_escape(UNICODE_MATH.get(c, c)) for c in text)


def quote_tex(text):
    """A paper's words as its text here gives them: $...$ and $$...$$ (the LaTeX of the converted papers)
    as inline and displayed math (and a text that is all LaTeX without its $), the rest escaped; Greek letters
    and symbols typed as Unicode (the OCR'd papers) and ASCII math (p2 < 0) as math."""
    out = []
    formula = re.fullmatch(r"([^$]*\\[A-Za-z]+[^$]*?)([.,;]?)", text.strip())
    if formula:  # (a formula in LaTeX without its $: "\frac{1}{2}k(r - l)^2 - mgr \cos(\theta).")
        return f"${formula.group(1)}${formula.group(2)}"
    for i, part in enumerate(re.split(r"(\$\$.*?\$\$|\$.*?\$)", unicodedata.normalize("NFC", text))):
        if i % 2:  # (a displayed formula displayed: a system of equations is wider than what is left of a line)
            out.append((r"\[{}\]" if part.startswith("$$") else "${}$").format(part.strip("$").strip()))
        else:
            for j, piece in enumerate(re.split(r"(\w[\u0300-\u036f])", part)):  # a letter with an accent
                if j % 2:
                    out.append(f"${ACCENTS.get(piece[1], '')}{{{piece[0]}}}$")
                else:
                    out.append(ascii_math(piece, unicode_tex))
    return "".join(out)


GNUPLOT_MATH = {"Φ": r"\Phi", "Ψ": r"\Psi", "²": "^2", "³": "^3"}


def gnuplot_tex(text, escape=tex_escape):
    """A gnuplot enhanced text (the registry's titles: "Φ^{(4)}_h", "h²/24") as LaTeX: its sub- and
    superscripts and Greek letters as math, the rest escaped by `escape` (matplotlib's mathtext: only "$")."""
    text = "".join(GNUPLOT_MATH.get(c, c) for c in text)
    out, at = [], 0
    for m in re.finditer(r"(?:\\[A-Za-z]+|[A-Za-z])?(?:[\^_](?:\{[^{}]*\}|\w))+|\\[A-Za-z]+", text):
        out += [escape(text[at:m.start()]), "$" + m.group(0) + "$"]
        at = m.end()
    return "".join(out + [escape(text[at:])])


# In free text (published.toml's notes, the registry's citations): a file (a/b.hpp, fig9.csv), a name
# with an underscore (se_compensated_energy_rms, cost.phase.h_max) or a test's (Lobatto.EquationTwelve),
# and a symbol with a one-letter subscript (p_x, H_0, Psi_{h,E}).
SYM = r"[A-Za-z]+_(?:\{[^{}\s]*\}|[A-Za-z0-9](?![\w]))"
NAME = re.compile(r"(?<![\w/.\\{])(?:(?P<file>(?:[\w.-]+/)*[\w-]+\.(?:csv|hpp|cpp|toml|json|py|gp|txt)\b)"
                  rf"|(?P<sym>{SYM})"
                  r"|(?P<name>(?:\w+\.)*\w*[A-Za-z]\w*_\w+(?:\.\w+)*|(?:\w+\.)+[A-Z][a-z]\w*[A-Z]\w*))")
GREEK = {"alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "kappa", "lambda", "mu", "nu", "xi",
         "pi", "rho", "sigma", "tau", "phi", "chi", "psi", "omega", "ell", "Gamma", "Delta", "Theta", "Lambda", "Xi",
         "Pi", "Sigma", "Phi", "Psi", "Omega"}


def breakable(text):
    """Escaped text that may break after a slash."""
    return re.sub(r"/(?=\w)", r"/\\allowbreak{}", tex_escape(text))


def prose(text, refs=None):
    """Escaped free text: files and names with an underscore as code (a name in `refs`, e.g. a comparison's
    key, as its reference instead), ASCII math (symbols with a subscript, h^2/24, omega h -> 2 sqrt(3)) as
    math; what is left may break after a slash."""
    out, at, text = [], 0, str(text)
    for m in NAME.finditer(text):
        if m.group("sym") and m.group(0) not in (refs or {}):  # (math: left to ascii_math with its neighbours)
            continue
        out.append(ascii_math(text[at:m.start()], breakable))
        out.append((refs or {}).get(m.group(0)) or code(m.group(0)))
        at = m.end()
    out.append(ascii_math(text[at:], breakable))
    return "".join(out)


# ASCII math in free text ("h^2/24", "omega h -> 2 sqrt(3)", "x <= 0.3", "|J^T Omega J - Omega|") as LaTeX math: an
# expression is a run of atoms (numbers, one-letter variables with digits as a subscript, Greek letters by name,
# qbar-style accents, symbols with a subscript, groups in parentheses or bars, functions such as sqrt(...)) joined
# by operators or a single space; it is set as math when it holds a sign of math (^, ->, <=, >=, <, >, !=, ~, +-,
# sqrt, a Greek letter, a subscript, |...|). A relation or arrow left outside any expression becomes its symbol.
MATH_TOKEN = re.compile(rf"(?P<sym>{SYM})|(?P<num>\d+(?:\.\d+)?(?:[eE][-+]?\d+)?(?![\w]))"
                        r"|(?P<word>[A-Za-z]+\d*(?![\w]))|(?P<op>->|<=|>=|!=|\+-|[-+*/^=<>~±])|(?P<space> )"
                        r"|(?P<other>\w+|.)", re.S)
OPS = {"->": r"\to", "<=": r"\le", ">=": r"\ge", "!=": r"\ne", "+-": r"\pm", "±": r"\pm", "~": r"\sim", "*": r"\cdot"}
MATH_SIGNS = {"^", "->", "<=", ">=", "<", ">", "!=", "~", "+-", "±"}
FUNCTIONS = {"sqrt": r"\sqrt", "exp": r"\exp", "log": r"\log", "ln": r"\ln", "sin": r"\sin", "cos": r"\cos",
             "tan": r"\tan", "sinh": r"\sinh", "cosh": r"\cosh", "max": r"\max", "min": r"\min", "O": "O"}
ACCENT_WORDS = {"bar": r"\bar", "tilde": r"\tilde", "hat": r"\hat", "dot": r"\dot"}  # (hat, dot: on Greek only)


def math_number(text):
    """A number as math: 0.05e-6 as 0.05\\times10^{-6}."""
    mant, _, exp = text.lower().partition("e")
    if not exp:
        return text
    power = f"10^{{{int(exp)}}}"
    return power if mant == "1" else rf"{mant}\times{power}"


def math_variable(word):
    """A one-letter variable (digits as its subscript: x1, H0), a Greek letter by name, or a letter with an accent
    (qbar), as math; None if the word is none of these."""
    m = re.fullmatch(r"([A-Za-z]+?)(\d*)", word)
    name, digits = m.groups()
    for accent, command in ACCENT_WORDS.items():
        if name.endswith(accent) and (len(name) == len(accent) + 1 and accent in ("bar", "tilde")
                                      or name[: -len(accent)] in GREEK):
            base = name[: -len(accent)]
            return f"{command}{{{chr(92) + base if base in GREEK else base}}}" + (f"_{{{digits}}}" if digits else "")
    if len(name) == 1 or name in GREEK and word != "epsilon":  # (the machine epsilon: a word)
        return (chr(92) + name if name in GREEK else name) + (f"_{{{digits}}}" if digits else "")
    return None


class _Math:
    """A parser of the ASCII math in a list of tokens (kind, text); each method returns (LaTeX, next index, whether
    it holds a sign of math) or None."""

    def __init__(self, tokens):
        self.t = tokens

    def kind(self, i, *kinds):
        return i < len(self.t) and self.t[i][0] in kinds

    def text(self, i):
        return self.t[i][1] if i < len(self.t) else ""

    def group(self, i, close):
        """An expression between the bracket at i and `close`."""
        inner = self.expression(i + 1)
        if inner and self.text(inner[1]) == close:
            return inner[0], inner[1] + 1, inner[2]
        return None

    def atom(self, i):
        kind, text = self.t[i] if i < len(self.t) else ("", "")
        if kind == "num":
            return math_number(text), i + 1, False
        if kind == "sym":
            base, sub = text.split("_", 1)
            return f"{chr(92) + base if base in GREEK else base}_{{{sub.strip('{}')}}}", i + 1, True
        if kind == "word" and text in FUNCTIONS and self.text(i + 1) == "(":
            arg = self.group(i + 1, ")")
            if arg:
                body = f"{{{arg[0]}}}" if text == "sqrt" else f"({arg[0]})"
                return FUNCTIONS[text] + body, arg[1], arg[2] or text == "sqrt"
        if kind == "word" and math_variable(text):
            return math_variable(text), i + 1, len(text) > 1 and not text[1:].isdigit()
        if text in ("(", "|"):
            inner = self.group(i, ")" if text == "(" else "|")
            if inner:
                return (f"({inner[0]})" if text == "(" else f"|{inner[0]}|"), inner[1], inner[2] or text == "|"
        return None

    def exponent(self, i):
        """What follows ^: a number, a variable, -x, (...) (its parentheses kept around one atom: Phi^(4)), {...}."""
        sign = "-" if self.text(i) == "-" else ""
        i += len(sign)
        if self.text(i) == "{":
            inner = self.group(i, "}")
            return (f"{sign}{inner[0]}", inner[1]) if inner else None
        if self.text(i) == "(":
            inner = self.group(i, ")")
            one = inner and inner[1] - i == 3
            return (sign + (f"({inner[0]})" if one else inner[0]), inner[1]) if inner else None
        a = self.atom(i)
        return (sign + a[0], a[1]) if a else None

    def term(self, i):
        """An atom, with a power (x^2) and an argument in parentheses (O(h^2), Q(q), H(0)); a Greek letter's number
        in parentheses is its index (Phi(4): Phi^(4), the method of 003)."""
        a = self.atom(i)
        if a is None:
            return None
        if self.text(i) in GREEK and self.text(i + 1) == "(" and self.kind(i + 2, "num") and self.text(i + 3) == ")":
            a = f"{a[0]}^{{({self.text(i + 2)})}}", i + 4, True  # (an index: Phi(4), mu(4) are Phi^(4), mu^(4))
        latex, i, sign = a
        while True:
            if self.text(i) == "^" and self.exponent(i + 1):
                e, i = self.exponent(i + 1)
                latex, sign = f"{latex}^{{{e}}}", True
            elif self.text(i) == "(" and self.group(i, ")"):
                g = self.group(i, ")")
                latex, i, sign = f"{latex}({g[0]})", g[1], sign or g[2]
            else:
                return latex, i, sign

    def operator(self, i):
        """An operator with a space either side or none: (its LaTeX, the index after it, whether it is a sign)."""
        j = i + 1 if self.kind(i, "space") else i
        if not self.kind(j, "op") or self.text(j) == "^":
            return None
        k = j + 2 if self.kind(j + 1, "space") else j + 1
        op = self.text(j)
        return OPS.get(op, op), k, op in MATH_SIGNS

    def expression(self, i):
        """The longest expression from i: [relation] term (operator term | space term)*."""
        latex, sign = "", False
        op = self.operator(i)
        if op and op[0] not in ("/", r"\cdot", "+"):  # a leading relation or sign: "< 0.1", "-1"
            latex, i, sign = op[0] + " ", op[1], op[2]
        t = self.term(i)
        if t is None:
            return None
        latex, i, sign = latex + t[0], t[1], sign or t[2]
        while True:
            op = self.operator(i)
            nxt = self.term(op[1]) if op else None
            if op and nxt is None and self.text(op[1]) == "-":  # (a sign after an operator: "= -1")
                nxt = self.term(op[1] + 1)
                nxt = nxt and ("-" + nxt[0], nxt[1], nxt[2])
            if op and nxt:
                glue = op[0] if op[0] == "/" else f" {op[0]} "
                latex, i, sign = f"{latex}{glue}{nxt[0]}", nxt[1], sign or op[2] or nxt[2]
                continue
            j = i + 1 if self.kind(i, "space") else None  # two atoms side by side: "omega h", "2 sqrt(3)"
            juxt = self.term(j) if j is not None and self.text(i - 1) not in ("a", "A", "I") and \
                self.text(j) not in ("a", "A", "I") else None
            if juxt:
                latex, i, sign = f"{latex} {juxt[0]}", juxt[1], sign or juxt[2]
                continue
            return latex, i, sign


def ascii_math(text, escape=tex_escape):
    """Free text with its ASCII math as LaTeX math ($h^{2}/24$, $\\omega h \\to 2 \\sqrt{3}$), the rest escaped
    by `escape`."""
    tokens = [(m.lastgroup, m.group(0)) for m in MATH_TOKEN.finditer(str(text))]
    parser, out, plain, i = _Math(tokens), [], [], 0
    while i < len(tokens):
        starts = i == 0 or tokens[i - 1][0] not in ("word", "num", "sym")
        found = parser.expression(i) if starts and tokens[i][0] != "space" else None
        if found and found[2]:
            out += [escape("".join(plain)), f"${found[0]}$"]
            plain, i = [], found[1]
        elif tokens[i][1] in OPS and tokens[i][1] != "*" or tokens[i][1] in ("<", ">"):
            out += [escape("".join(plain)), f"${OPS.get(tokens[i][1], tokens[i][1])}$"]
            plain, i = [], i + 1
        else:
            plain.append(tokens[i][1])
            i += 1
    return "".join(out + [escape("".join(plain))])


# An absolute path in a message (a test's refusal, a command it ran): "/" not after a word, a dot or a colon
# (1/2, a/b, https://), then its components; not /proc/self and /dev/..., the same on every machine.
ABSOLUTE_PATH = re.compile(r"(?<![\w.~/\\:-])/(?!proc/self\b|dev/)[\w.*+@%-]+(?:/[\w.*+@%-]*)*")


def repo_paths(text, roots=()):
    """A text with its absolute paths relative to the first of `roots` (source trees) that holds them, and any
    other (a test's temporary directory) as DIR/<its last component>: no path of the machine that ran it."""
    def relative(m):
        path = m.group(0)
        for root in sorted((str(r).rstrip("/") for r in roots), key=len, reverse=True):
            if path == root or path.startswith(root + "/"):
                return path[len(root) + 1:] or "."
        last = [part for part in path.split("/") if part]
        return "DIR/" + last[-1] + ("/" if path.endswith("/") else "")
    return ABSOLUTE_PATH.sub(relative, str(text))


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
    return "not computed" if v is None else ascii_math(v)  # (a printed claim: "< 0.00063")


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
