"""LaTeX helpers: escaping of strings read from files, number formatting, tables, figures."""
import math
import os
import re

_SPECIAL = {"\\": r"\textbackslash{}", "&": r"\&", "%": r"\%", "$": r"\$", "#": r"\#",
            "_": r"\_", "{": r"\{", "}": r"\}", "~": r"\textasciitilde{}",
            "^": r"\textasciicircum{}", "<": r"\textless{}", ">": r"\textgreater{}",
            "|": r"\textbar{}", '"': r"\textquotedbl{}",
            # a hyphen stays one ("--set" is no en dash), a backtick no opening quote
            "-": "-{}", "`": r"\textasciigrave{}"}
_UNICODE = {"≤": r"$\le$", "≥": r"$\ge$", "±": r"$\pm$", "°": r"$^\circ$", "×": r"$\times$",
            "µ": r"$\mu$", "μ": r"$\mu$", "–": "--", "—": "---",
            "−": "-", "‘": "`", "’": "'", "“": "``", "”": "''", "·": r"$\cdot$", "≈": r"$\approx$",
            "∞": r"$\infty$", "Δ": r"$\Delta$", "ρ": r"$\rho$", "ν": r"$\nu$", "§": r"\S{}",
            "∈": r"$\in$", "→": r"$\to$",
            "√": r"$\surd$", "ζ": r"$\zeta$", "ω": r"$\omega$", "δ": r"$\delta$", "π": r"$\pi$",
            "κ": r"$\kappa$", "τ": r"$\tau$", "∝": r"$\propto$",
            "∫": r"$\int$",
            "é": r"\'e", "ü": r"\"u", "ö": r"\"o", "ä": r"\"a", "…": "..."}


# Unicode superscripts: a run of them is one math group (10⁻⁵ -> 10$^{-5}$), so that joining
# adjacent math groups (notation) never makes a double superscript.
_SUPERSCRIPT = {"⁰": "0", "¹": "1", "²": "2", "³": "3", "⁴": "4", "⁵": "5", "⁶": "6", "⁷": "7", "⁸": "8",
                "⁹": "9", "⁻": "-", "⁺": "+"}


def esc(text):
    """Any string from a file made safe for LaTeX text mode (non-ASCII beyond a small map -> ?)."""
    out = []
    run = []  # a run of superscript characters, set as one group when it ends
    for c in list(str(text)) + [None]:
        if c is not None and c in _SUPERSCRIPT:
            run.append(_SUPERSCRIPT[c])
            continue
        if run:
            out.append("$^{%s}$" % "".join(run))
            run = []
        if c is None:
            break
        if c in _SPECIAL:
            out.append(_SPECIAL[c])
        elif c in _UNICODE:
            out.append(_UNICODE[c])
        elif ord(c) < 32:
            out.append(" ")
        elif ord(c) > 126:
            out.append("?")
        else:
            out.append(c)
    return "".join(out)


def tt(text):
    """Typewriter text that may break after an underscore or slash (file and case names in narrow
    table columns)."""
    return r"\texttt{%s}" % esc(text).replace(r"\_", r"\_\allowbreak{}").replace("/", r"/\allowbreak{}")


def stacked_tt(text, width=12):
    """A typewriter table header broken after '_' or '.' into lines of about `width` characters,
    right-aligned (long column names of numeric tables, whose r columns do not wrap)."""
    parts = re.findall(r"[^_.]+[_.]?|[_.]", str(text))
    lines, line = [], ""
    for part in parts:
        if line and len(line) + len(part) > width:
            lines.append(line)
            line = ""
        line += part
    lines.append(line)
    if len(lines) == 1:
        return r"\texttt{%s}" % esc(text)
    return r"\begin{tabular}[b]{@{}r@{}}%s\end{tabular}" % r"\\".join(r"\texttt{%s}" % esc(x) for x in lines)


def num(value, digits=4):
    """Numbers as read (strings) or floats, printed compactly; empty -> '--'."""
    if value is None:
        return "--"
    if isinstance(value, str):
        s = value.strip()
        if not s:
            return "--"
        try:
            value = float(s)
        except ValueError:
            return esc(s)
    if math.isnan(value):
        return "nan"
    if math.isinf(value):  # e.g. 'never' (a first-fold time of a run whose rims never fold)
        return r"$\infty$" if value > 0 else r"$-\infty$"
    if value == 0:
        return "0"
    if 1e-3 <= abs(value) < 1e4:
        return "%.*g" % (digits, value)
    mant, ex = ("%.*e" % (digits - 1, value)).split("e")
    return r"$%s\times10^{%d}$" % (mant, int(ex))


def status_cell(status):
    s = status.strip()
    if s == "pass":
        return r"\textcolor{passgreen}{pass}"
    if s.lower().startswith("fail"):
        return r"\textcolor{red}{\textbf{FAIL}}"
    if s == "info":
        return r"\textcolor{gray}{info}"
    return esc(s) if s else "--"


def longtable(spec, header, rows, caption=None, size="small", tabcolsep="4pt", keep=False):
    """A longtable in the given font size environment (None: the surrounding size) with the given
    column separation (None: the surrounding one). keep: no page break inside the table (rows end
    in \\\\*), so that a short table's last row (a total) is not left alone on the next page."""
    lines = ([r"\begin{%s}" % size] + ([r"\setlength{\tabcolsep}{%s}" % tabcolsep] if tabcolsep else [])
             if size else []) + \
        [r"\begin{longtable}{%s}" % spec]
    end = r" \\*" if keep else r" \\"
    if caption:
        lines.append(r"\caption{%s}" % caption + end)
    head = " & ".join(r"\textbf{%s}" % h for h in header) + end + r" \midrule"
    lines += [r"\toprule", head, r"\endfirsthead", r"\toprule", head, r"\endhead",
              r"\bottomrule", r"\endlastfoot"]
    for r in rows:
        lines.append(" & ".join(r) + end)
    lines += [r"\end{longtable}"] + ([r"\end{%s}" % size] if size else []) + [""]
    return "\n".join(lines)


# Figure text at print size: no figure text below MIN_PRINT_PT once LaTeX scales the figure into
# its box (\\textwidth wide, `height` of \\textheight high, aspect kept). FIGURE_TEXT holds the
# smallest font size of each saved figure at its own size (report_figures.save); figure() records
# every figure printed with smaller text in SMALL_TEXT, which build_report reports as an error.
MIN_PRINT_PT = 7.0
# The dense tables' type (page 1's summary and list of misses, the traceability tables), size and
# baseline skip in pt: the document's smallest text, its sub- and superscripts at MIN_PRINT_PT
# (the preamble's \\DeclareMathSizes).
TABLE_PT = (7.5, 9)
TEXT_WIDTH_PT, TEXT_HEIGHT_PT = 504.6, 756.8  # A4 less the preamble's geometry margins
FIGURE_TEXT = {}
SMALL_TEXT = []


def pdf_size(path):
    """(width, height) in pt of a one-page PDF (its MediaBox), or (None, None)."""
    try:
        with open(path, "rb") as f:
            text = f.read()
    except OSError:
        return None, None
    m = re.search(rb"/MediaBox\s*\[\s*([-0-9.]+)\s+([-0-9.]+)\s+([-0-9.]+)\s+([-0-9.]+)\s*\]", text)
    if not m:
        return None, None
    return float(m.group(3)) - float(m.group(1)), float(m.group(4)) - float(m.group(2))


def print_scale(path, height):
    """The factor LaTeX scales a figure PDF by in figure(): its page fitted into \\textwidth by
    `height` \\textheight, aspect kept."""
    w, h = pdf_size(path)
    return min(TEXT_WIDTH_PT / w, height * TEXT_HEIGHT_PT / h) if w and h else None


def figure(path, caption, height=0.42):
    """A figure at full text width, at most `height` of the text height, aspect kept; the height
    allowance grows (to 0.9 at most) where the figure's smallest text would print below
    MIN_PRINT_PT, which is recorded in SMALL_TEXT where even that does not suffice."""
    smallest, scale = FIGURE_TEXT.get(path), print_scale(path, height)
    if smallest is not None and scale is not None and smallest * scale < MIN_PRINT_PT - 0.01:
        w, h = pdf_size(path)
        # rounded up to the hundredth the LaTeX source states
        height = max(height, min(0.9, math.ceil(100 * MIN_PRINT_PT / smallest * h / TEXT_HEIGHT_PT) / 100))
        scale = print_scale(path, height)
        if smallest * scale < MIN_PRINT_PT - 0.01:
            SMALL_TEXT.append((os.path.basename(path), smallest * scale))
    return "\n".join([r"\begin{figure}[H]", r"\centering",
                      r"\includegraphics[width=\textwidth,height=%.2f\textheight,keepaspectratio]{%s}"
                      % (height, os.path.basename(path)),
                      r"\caption{%s}" % caption, r"\end{figure}", ""])


# ASCII notation of READMEs, results.csv metrics and test headers set as LaTeX: exponents (32^2,
# [1/s^2], 10^-4), one-letter or Greek symbols with a short subscript (c_D, u_min, v_0.30, rho_s,
# dV_l, sum_l) as math, Greek names standing alone (2 pi f t, h^2 / pi, at Omega) as their letters,
# relations (<=, >=, !=, ==, +-, ->, ~ before a number) as their signs, numbers in e-notation (1e-4,
# 5e-15) as powers of ten, sqrt(...) as a root, a digit x digit as a times sign, everything else
# escaped. Names of several letters joined by '_' (drag_coefficient_max, n_surface_points) are not
# subscripts and stay text; so does 'delta' before a word ("the four delta kernels").
_GREEK = ("alpha", "beta", "gamma", "Gamma", "delta", "Delta", "epsilon", "mu", "nu", "omega", "Omega", "phi",
          "Phi", "rho", "sigma", "tau", "theta", "kappa", "lambda", "xi", "zeta", "eta", "pi")
# (names both LaTeX and matplotlib's mathtext know: figure labels take the same notation)
_RELATIONS = {"<=": r"\leq", ">=": r"\geq", "!=": r"\neq", "==": "=", "+-": r"\pm", "->": r"\to", "~": r"\approx"}
_NOTATION = re.compile(
    r"\^(?P<exp>\{[^{}]*\}|-?\d+(?:\.\d+)?|[A-Za-z](?![A-Za-z]))"
    r"|(?<![\w\\.])(?P<base>sum|%s|d?[A-Za-z]|[ρνΔωδζπμ])_(?P<sub>[A-Za-z0-9]{1,5}(?:\.\d+)?)(?![\w])"
    r"|(?<=\))_(?P<psub>[A-Za-z0-9]{1,4})(?![\w])"
    r"|(?P<rel><=|>=|!=|==|\+-|->|(?<![\w~])~(?=\d))"
    r"|(?<![\w.])(?P<mant>\d+(?:\.\d+)?)[eE](?P<ten>[+-]?\d+)(?!\w|\.\d)"
    r"|(?<![\w\\])sqrt\((?P<root>[^()]*)\)"
    r"|(?<=\d) ?x ?(?=\d)"
    r"|(?<![\w\\])(?P<greek>%s)(?![\w])(?!(?<=delta) [A-Za-z])" % ("|".join(_GREEK), "|".join(_GREEK)))


def _sub(text):
    return text if len(text) == 1 or re.fullmatch(r"[0-9.]+", text) else r"\mathrm{%s}" % text


def _symbol(name):
    """LaTeX of a subscript's base or a standalone name: a Greek name or letter as its letter, sum as
    the summation sign, a letter as itself."""
    if name in _GREEK or name == "sum":
        return "\\" + name
    return _UNICODE[name].strip("$") if name in _UNICODE else name


def notation(text, escape=esc):
    """Plain text (no code spans) with its ASCII notation (above) as LaTeX math, the rest escaped
    (`escape`: esc for LaTeX, mathtext() for a figure's labels); adjacent math groups are joined
    ($T_{c}^{2}$, not $T_{c}$$^{2}$)."""
    out, pos = [], 0
    for m in _NOTATION.finditer(text):
        out.append(escape(text[pos:m.start()]))
        if m.group("exp") is not None:
            exp = m.group("exp").strip("{}")
            out.append(r"$^{%s}$" % (esc(exp).replace("-{}", "-") if escape is esc else exp))
        elif m.group("base") is not None:
            out.append(r"$%s_{%s}$" % (_symbol(m.group("base")), _sub(m.group("sub"))))
        elif m.group("psub") is not None:
            out.append(r"$_{%s}$" % _sub(m.group("psub")))
        elif m.group("rel") is not None:
            out.append(r"$%s$" % _RELATIONS[m.group("rel")])
        elif m.group("mant") is not None:
            mant, ten = m.group("mant"), int(m.group("ten"))
            out.append(r"$10^{%d}$" % ten if float(mant) == 1 else r"$%s\times10^{%d}$" % (mant, ten))
        elif m.group("root") is not None and escape is esc:
            out.append(r"$\sqrt{\mbox{%s}}$" % notation(m.group("root")))
        elif m.group("root") is not None:  # mathtext has no \mbox: the root's text as math
            out.append(r"$\sqrt{%s}$" % m.group("root"))
        elif m.group("greek") is not None:
            out.append(r"$%s$" % _symbol(m.group("greek")))
        else:  # digit x digit
            out.append(r"$\times$")
        pos = m.end()
    out.append(escape(text[pos:]))
    return re.sub(r"(?<!\\)\$\$", "", "".join(out))


def mathtext(text):
    """A figure label's ASCII notation (pi/N_l, 10^-4, <=) as matplotlib mathtext, line by line (a
    math group ends with its line); its other characters as they are, a '$' escaped."""
    return "\n".join(notation(line, escape=lambda s: s.replace("$", r"\$")) for line in str(text).split("\n"))


def md_text(text):
    """Markdown-ish text of a README or a source header as LaTeX: `code` spans in typewriter
    (breakable after '_' and '/'), **bold** markers dropped, *emphasis* in italics, ASCII notation
    set by notation(); an unpaired backtick (text cut inside a code span) is dropped."""
    text = str(text).replace("**", "")
    parts = text.split("`")
    if len(parts) % 2 == 0:  # an unpaired backtick: the last one opens nothing
        parts = parts[:-2] + [parts[-2] + parts[-1]]
    return "".join(tt(p) if k % 2 else _emphasis(p) for k, p in enumerate(parts))


def _emphasis(text):
    """notation() of text whose *words* between single asterisks are set in italics (an asterisk
    that pairs with none, as in 'J*', stays)."""
    pieces = re.split(r"(?<![\w*])\*(?=\S)([^*]+?)(?<=\S)\*(?![\w*])", text)
    return "".join(r"\emph{%s}" % notation(p) if k % 2 else notation(p) for k, p in enumerate(pieces))


def join_lines(lines):
    """Lines of a Markdown paragraph or a source comment joined into one text, one line break
    between them (sentence_ends reads a full stop at a line's end as a sentence end), runs of
    spaces collapsed and list-item markers ('- ', '* ', '+ ' opening a line) dropped, so that the
    items read as the clauses they are ("...: on square cells ...; on cells dx x dy ...") instead of
    printing a dash."""
    return "\n".join(" ".join(re.sub(r"^\s*[-*+]\s+(?=\S)", "", line).split()) for line in lines).strip()


# A full stop after one of these is no sentence end.
_ABBREVIATION = re.compile(r"(?:\bet al|\be\.g|\bi\.e|\bcf|\bvs|\bFigs?|\bEqs?|\bNo|\bapprox|\bresp|\bSec)\.$")


def sentence_ends(text):
    """The indices just after each sentence end of text: a '.', '!' or '?' at a line's end, or
    followed by a space and a capital, a digit, an opening bracket or quote, or by the end of the
    text; not inside brackets or a code span, not an ellipsis ('FILE...'), an abbreviation ('et
    al.', 'e.g.') or an item number ('1. it reached')."""
    ends, depth, code = [], 0, False
    for i, c in enumerate(text):
        if c == "`":
            code = not code
        elif code:
            continue
        elif c in "([{":
            depth += 1
        elif c in ")]}":
            depth = max(0, depth - 1)
        elif c in ".!?" and depth == 0:
            rest = text[i + 1:]
            if rest and not rest[0].isspace():
                continue  # 3.4, file.cpp, e.g
            if c == "." and text[i - 1:i] == ".":
                continue  # an ellipsis
            line_end = rest.lstrip(" \t")[:1] == "\n"
            rest = rest.lstrip()
            if rest and not line_end and not (rest[0].isupper() or rest[0].isdigit() or rest[0] in "([`\"'"):
                continue
            if c == "." and (_ABBREVIATION.search(text[:i + 1]) or re.search(r"(?:^|\s)\d{1,2}\.$", text[:i + 1])
                             and rest and not rest[0].isupper()):
                continue
            ends.append(i + 1)
    return ends


def _one_line(text):
    return " ".join(text.split())


def first_sentence(text):
    """The first sentence of text (sentence_ends), whole, on one line; the text itself when it has
    no end."""
    ends = sentence_ends(text)
    return _one_line(text[:ends[0]] if ends else text)


def sentences_within(text, limit):
    """text whole (on one line) if it has at most `limit` characters, else its sentences up to the
    last end at or before `limit` (at least the first sentence): (text, True when cut)."""
    if len(_one_line(text)) <= limit:
        return _one_line(text), False
    ends = [e for e in sentence_ends(text) if len(_one_line(text[:e])) <= limit] or sentence_ends(text)[:1]
    if not ends or not text[ends[-1]:].strip():
        return _one_line(text), False
    return _one_line(text[:ends[-1]]), True
