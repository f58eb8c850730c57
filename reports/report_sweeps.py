"""Report section of the sweeps (docs/workflow.md): one table and one figure per
BUILD/sweeps/<name>.csv, written by the workflow's sweep_collect rule. Reads files only.

The CSV: '#' comment lines (the first carries `sweep NAME: TITLE`, a `plot {json}` line names the
x column, the y columns, an optional `series` column and `log`), one header line, one row per
grid point (grid keys, status, exit_code, seconds, metric columns)."""
import csv
import glob
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from report_bench import _float  # noqa: E402
import report_figures as figs  # noqa: E402
from report_latex import esc, figure, longtable, stacked_tt  # noqa: E402


def read_sweep(path):
    """(title, plot dict, header list, rows as dicts) of a sweep CSV."""
    title, plot, lines = os.path.splitext(os.path.basename(path))[0], {}, []
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("#"):
                text = line[1:].strip()
                if text.startswith("sweep ") and ":" in text:
                    title = text.split(":", 1)[1].strip()
                elif text.startswith("plot "):
                    try:
                        plot = json.loads(text[5:])
                    except ValueError:
                        plot = {}
            elif line.strip():
                lines.append(line)
    reader = csv.DictReader(lines)
    rows = list(reader)
    return title, plot, reader.fieldnames or [], rows


SHARED_PREFIX = "points read from the validation runs"


def shared_note(path):
    """The CSV's note naming the points that are validation runs (read, not run again), or ""."""
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.startswith("#") and line[1:].strip().startswith(SHARED_PREFIX):
                return line[1:].strip()
    return ""


def _cell(text):
    value = _float(text)
    if math.isfinite(value) and not str(text).lstrip("-").isdigit():
        return ("%.4g" % value).replace("-", "$-$")
    return esc(text or "")


def _status_cell(row):
    """pass only for a run that exited 0; a run that ended with another exit code the sweep accepts
    (e.g. 3: a body left the box, the expected end without a contact model) says so."""
    status, code = (row.get("status") or "").strip(), (row.get("exit_code") or "").strip()
    if status == "pass" and code not in ("0", ""):
        return r"\textcolor{missorange}{accepted exit %s}" % esc(code)
    if status == "pass":
        return r"\textcolor{passgreen}{pass}"
    return r"\textcolor{red}{\textbf{%s}}" % esc(status or "--")


def plot_sweep(plot, rows, path):
    """y columns against x, one line per y column and per value of the series column."""
    x_key, ys, series = plot.get("x"), plot.get("y", []), plot.get("series")
    if not x_key or not ys or not rows:
        return None
    groups = {}
    for r in rows:
        groups.setdefault(r.get(series, "") if series else "", []).append(r)
    fig, ax = plt.subplots(figsize=(6.0, 3.6))
    drawn = 0
    for g, grows in sorted(groups.items()):
        grows = sorted(grows, key=lambda r: _float(r.get(x_key)))
        for y in ys:
            pts = [(_float(r.get(x_key)), _float(r.get(y))) for r in grows]
            pts = [(a, b) for a, b in pts if math.isfinite(a) and math.isfinite(b) and (b > 0 or not plot.get("log"))]
            if not pts:
                continue
            label = y + ("" if not series else ", %s = %s" % (series, g))
            ax.plot([a for a, _ in pts], [b for _, b in pts], "o-", label=label)
            drawn += 1
    if not drawn:
        plt.close(fig)
        return None
    if plot.get("log"):
        ax.set_xscale("log")
        ax.set_yscale("log")
    ax.set_xlabel(x_key)
    # The y axis named by the plot line's "ylabel", else by what the y columns share
    # (error_ghia, error_ibms_reference -> error), the columns in the legend.
    shared = (figs._common_prefix(ys) if len(ys) > 1 else ys[0]) or "value"
    ax.set_ylabel(plot.get("ylabel") or "%s (legend: column)" % shared)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    figs.save(fig, path)
    return path


def sweeps_section(out, build, fig_dir):
    files = sorted(glob.glob(os.path.join(build, "sweeps", "*.csv")))
    out.append(r"\section{Sweeps}")
    if not files:
        out.append(r"\emph{No sweep results: \texttt{sweeps/*.csv} not found in the build directory "
                   r"(the workflow's sweeps, \texttt{docs/workflow.md}).}")
        return
    out.append("Each sweep file (\\texttt{sweeps/*.toml}) names a scene and a parameter grid; the "
               "workflow runs every point and collects its metrics (\\texttt{ibms compare} on the "
               "run's outputs, and the wall time) into \\texttt{BUILD/sweeps/<name>.csv}. Status: "
               "\\emph{pass} for a run that exited 0; \\emph{accepted exit N} for a run that ended with "
               "another exit code its sweep file accepts (\\texttt{accept\\_exit\\_codes}, e.g. 3 when a "
               "body leaves the box, the end of a scene without a contact model). A point with the "
               "scene and values of a validation run of the level is that run: it reads the run's "
               "outputs and takes its wall time instead of running again (the table's caption names "
               "those runs).\n")
    for k, path in enumerate(files):
        title, plot, header, rows = read_sweep(path)
        out.append(r"\subsection{%s}" % esc(title))
        if not rows:
            out.append(r"\emph{The sweep has no rows.}")
            continue
        table = [[_status_cell(r) if h == "status" else _cell(r.get(h, "")) for h in header] for r in rows]
        spec = "".join("r" for _ in header)
        out.append(longtable(spec, [stacked_tt(h) for h in header], table, size="footnotesize",
                             caption="Sweep \\texttt{%s}: one row per grid point.%s" %
                                     (esc(os.path.basename(path)),
                                      (" The " + esc(shared_note(path)) + ".") if shared_note(path) else "")))
        p = plot_sweep(plot, rows, os.path.join(fig_dir, "sweep%d.pdf" % k))
        if p:
            out.append(figure(p, "Sweep \\texttt{%s}: %s against \\texttt{%s}." %
                              (esc(os.path.basename(path)), esc(", ".join(plot.get("y", []))),
                               esc(plot.get("x", ""))), height=0.4))
