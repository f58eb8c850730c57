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
            "µ": r"$\mu$", "μ": r"$\mu$", "²": r"$^2$", "³": r"$^3$", "–": "--", "—": "---",
            "−": "-", "‘": "`", "’": "'", "“": "``", "”": "''", "·": r"$\cdot$", "≈": r"$\approx$",
            "∞": r"$\infty$", "Δ": r"$\Delta$", "ρ": r"$\rho$", "ν": r"$\nu$", "§": r"\S{}",
            "∈": r"$\in$", "→": r"$\to$", "⁻": r"$^-$", "¹": r"$^1$", "⁴": r"$^4$", "⁷": r"$^7$", "⁶": r"$^6$", "⁰": r"$^0$",
            "√": r"$\surd$", "ζ": r"$\zeta$", "ω": r"$\omega$", "δ": r"$\delta$", "π": r"$\pi$",
            "é": r"\'e", "ü": r"\"u", "ö": r"\"o", "ä": r"\"a", "…": "..."}


def esc(text):
    """Any string from a file made safe for LaTeX text mode (non-ASCII beyond a small map -> ?)."""
    out = []
    for c in str(text):
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
    if smallest is not None and scale is not None and smallest * scale < MIN_PRINT_PT - 0.05:
        w, h = pdf_size(path)
        height = max(height, min(0.9, 1.005 * MIN_PRINT_PT / smallest * h / TEXT_HEIGHT_PT))
        scale = print_scale(path, height)
        if smallest * scale < MIN_PRINT_PT - 0.05:
            SMALL_TEXT.append((os.path.basename(path), smallest * scale))
    return "\n".join([r"\begin{figure}[H]", r"\centering",
                      r"\includegraphics[width=\textwidth,height=%.2f\textheight,keepaspectratio]{%s}"
                      % (height, os.path.basename(path)),
                      r"\caption{%s}" % caption, r"\end{figure}", ""])


# ASCII notation of READMEs, results.csv metrics and test headers set as LaTeX: exponents (32^2,
# [1/s^2], 10^-4), one-letter or Greek symbols with a short subscript (c_D, u_min, v_0.30, rho_s)
# as math, everything else escaped. Names of several letters joined by '_' (drag_coefficient_max,
# n_surface_points) are not subscripts and stay text.
_GREEK = ("alpha", "beta", "gamma", "delta", "Delta", "epsilon", "mu", "nu", "omega", "Omega", "phi", "rho",
          "sigma", "tau", "theta", "kappa", "lambda", "xi", "zeta", "eta", "pi")
_NOTATION = re.compile(
    r"\^(?P<exp>\{[^{}]*\}|-?\d+(?:\.\d+)?|[A-Za-z](?![A-Za-z]))"
    r"|(?<![\w\\.])(?P<base>%s|[A-Za-z]|[ρνΔωδζπμ])_(?P<sub>[A-Za-z0-9]{1,4}(?:\.\d+)?)(?![\w])" % "|".join(_GREEK))


def _sub(text):
    return text if len(text) == 1 or re.fullmatch(r"[0-9.]+", text) else r"\mathrm{%s}" % text


def notation(text):
    """Plain text (no code spans) with its ASCII exponents and subscripts as LaTeX math, the rest
    escaped (esc)."""
    out, pos = [], 0
    for m in _NOTATION.finditer(text):
        out.append(esc(text[pos:m.start()]))
        if m.group("exp") is not None:
            out.append(r"$^{%s}$" % esc(m.group("exp").strip("{}")).replace("-{}", "-"))
        else:
            base = m.group("base")
            symbol = "\\" + base if base in _GREEK else _UNICODE[base].strip("$") if base in _UNICODE else base
            out.append(r"$%s_{%s}$" % (symbol, _sub(m.group("sub"))))
        pos = m.end()
    out.append(esc(text[pos:]))
    return "".join(out)


def md_text(text):
    """Markdown-ish text of a README or a source header as LaTeX: `code` spans in typewriter
    (breakable after '_' and '/'), **bold** markers dropped, ASCII notation set by notation();
    an unpaired backtick (text cut inside a code span) is dropped."""
    text = str(text).replace("**", "")
    parts = text.split("`")
    if len(parts) % 2 == 0:  # an unpaired backtick: the last one opens nothing
        parts = parts[:-2] + [parts[-2] + parts[-1]]
    return "".join(tt(p) if k % 2 else notation(p) for k, p in enumerate(parts))
