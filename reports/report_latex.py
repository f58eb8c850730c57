"""LaTeX helpers: escaping of strings read from files, number formatting, tables, figures."""
import math
import os

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


def longtable(spec, header, rows, caption=None, size="small"):
    """A longtable in the given font size environment (None: the surrounding size)."""
    lines = ([r"\begin{%s}" % size, r"\setlength{\tabcolsep}{4pt}"] if size else []) + \
        [r"\begin{longtable}{%s}" % spec]
    if caption:
        lines.append(r"\caption{%s}\\" % caption)
    head = " & ".join(r"\textbf{%s}" % h for h in header) + r" \\ \midrule"
    lines += [r"\toprule", head, r"\endfirsthead", r"\toprule", head, r"\endhead",
              r"\bottomrule", r"\endlastfoot"]
    for r in rows:
        lines.append(" & ".join(r) + r" \\")
    lines += [r"\end{longtable}"] + ([r"\end{%s}" % size] if size else []) + [""]
    return "\n".join(lines)


def figure(path, caption, height=0.42):
    return "\n".join([r"\begin{figure}[H]", r"\centering",
                      r"\includegraphics[width=\textwidth,height=%.2f\textheight,keepaspectratio]{%s}"
                      % (height, os.path.basename(path)),
                      r"\caption{%s}" % caption, r"\end{figure}", ""])
