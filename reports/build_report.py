#!/usr/bin/python3
"""Builds the ibms validation report (one PDF) from a build directory's outputs and check results.

usage: /usr/bin/python3 reports/build_report.py --build DIR --output FILE.pdf [--source REPO]

It reads only: DIR/validation/results.csv, DIR/validation/<case>/ outputs (HDF5, centre-line and
body CSVs), the repo's validation/<case>/reference/ data, the CSV tables under
DIR/verification_results/ (convergence, kernel moments, wheel energy, restitution), the sweep tables DIR/sweeps/*.csv and ctest's DIR/Testing/Temporary/LastTest*.log (reports/README.md lists what each section reads).
It recomputes no physics. Figures are vector PDF (matplotlib); the document is LaTeX compiled with
`latexmk -pdf` in a temporary directory under DIR, removed on success and kept on failure.
"""
import argparse
import glob
import math
import os
import shutil
import subprocess
import sys
import tempfile
import re
import time
from collections import OrderedDict

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report_data as data  # noqa: E402
import report_figures as figs  # noqa: E402
import report_bench as bench  # noqa: E402
import report_solid as solid  # noqa: E402
import report_sweeps as sweeps  # noqa: E402
import report_cases as cases_mod  # noqa: E402
import report_trace as trace  # noqa: E402
from report_latex import (TABLE_PT, esc, join_lines, md_text, num, sentences_within, status_cell, figure,  # noqa: E402
                          longtable, tt)

PREAMBLE = r"""\documentclass[10pt,a4paper]{article}
\usepackage[T1]{fontenc}
\usepackage[utf8]{inputenc}
\usepackage{lmodern}
\usepackage[margin=1.6cm,top=1.4cm,bottom=1.6cm]{geometry}
\usepackage{graphicx,booktabs,longtable,array,float}
\usepackage[table]{xcolor}
\usepackage[hidelinks]{hyperref}
\definecolor{passgreen}{rgb}{0.0,0.5,0.0}
\definecolor{missorange}{rgb}{0.85,0.33,0.0}
\setlength{\LTcapwidth}{\textwidth}
\setlength{\emergencystretch}{2em}
% Sub- and superscripts at 7 pt or more whatever the text size (LaTeX's defaults set them at 5 and
% 6 pt in 7 to 9 pt text): no text of the report prints below 7 pt.
\DeclareMathSizes{7}{7}{7}{7}
\DeclareMathSizes{7.5}{7.5}{7}{7}
\DeclareMathSizes{8}{8}{7}{7}
\DeclareMathSizes{9}{9}{7}{7}
\DeclareMathSizes{10}{10}{7}{7}
\DeclareMathSizes{10.95}{10.95}{8}{7}
\DeclareMathSizes{12}{12}{8}{7}
\begin{document}
"""

def case_list(build, source, results):
    """The validation cases: folders of the repo's validation/ with a README or a scene (source
    order), results.csv case names mapped to their folder (dfg_cylinder_2d1_slow -> its folder) in
    results order first. Folders of the build directory that are no case (the reference-compare
    mutations, reference regeneration) are not cases. Returns (ordered case names, folders)."""
    folders = []
    for d in sorted(glob.glob(os.path.join(source, "validation", "*", ""))):
        name = os.path.basename(os.path.dirname(d))
        if os.path.isfile(os.path.join(d, "README.md")) or glob.glob(os.path.join(d, "scene*.toml")):
            folders.append(name)
    order = []
    for rc in results:
        f = cases_mod.case_folder(rc, folders)
        if f not in order:
            order.append(f)
    order += [f for f in folders if f not in order]
    return order, folders


# A README excerpt longer than this (characters) is cut at the last sentence end before it, and the
# report says where the rest is (every case's first paragraph is shorter).
EXCERPT_LIMIT = 1600


def _readme_lines(source, case):
    """The stripped lines of validation/<case>/README.md ([] without one)."""
    path = os.path.join(source, "validation", case, "README.md")
    if not os.path.isfile(path):
        return []
    with open(path, encoding="utf-8", errors="replace") as f:
        return [line.strip() for line in f]


def readme_summary(source, case):
    """First paragraph of validation/<case>/README.md after its heading and the Validates /
    Compared-with lines, if any: (text, cut), the paragraph whole, or its sentences up to
    EXCERPT_LIMIT characters with cut True; None without one."""
    lines, started = [], False
    for s in _readme_lines(source, case):
        if s.startswith("#") or s.startswith("**Validates.**") or s.startswith("**Compared with.**"):
            if started:
                break
            continue
        if not s:
            if started:
                break
            continue
        started = True
        lines.append(s)
    return _excerpt(lines)


def readme_titled_paragraph(source, case, title):
    """The paragraph of validation/<case>/README.md whose bold title starts with `title` (a regex),
    as readme_summary gives it: (text, cut), or None."""
    lines = []
    for s in _readme_lines(source, case):
        if lines and not s:
            break
        if lines or re.match(r"\*\*(?:%s)" % title, s):
            lines.append(s)
    return _excerpt(lines)


def _excerpt(lines):
    """README lines as one quoted text: (text, cut) or None."""
    # Markdown kept (code spans, ASCII notation): the quoting code sets it as LaTeX (md_text).
    text = join_lines(lines).replace("**", "")
    # Pointers to the project's issue tracker mean nothing to a reader of the report.
    text = re.sub(r"\s*\((?:see )?issue \d+(?:\s*(?:§|item)\s*\d+)?\)", "", text)
    text = re.sub(r"[:;,]?\s*issue \d+(?:\s*(?:§|item)\s*\d+)?", "", text)
    # whole sentences, never a sentence or a word cut in two
    return sentences_within(text, EXCERPT_LIMIT) if text.strip() else None


# ---------------------------------------------------------------- run parameters (from the outputs)
def _toml(text):
    try:
        import tomllib
    except ImportError:  # Python < 3.11: no parameters table
        return None
    try:
        return tomllib.loads(text)
    except Exception:  # noqa: BLE001 - an unreadable scene attribute leaves the row empty
        return None


def coupling_text(ibm, bodies):
    """The coupling of a run with bodies (ibm.coupling), and under "no_slip" with rigid bodies how they
    answer their force (ibm.rigid_response: in the marker system, or one step late with a virtual mass)."""
    if not bodies:
        return "--"
    coupling = ibm.get("coupling", "uhlmann")
    if coupling == "no_slip" and any(b.get("kind") == "rigid" for b in bodies):
        coupling += " (rigid: %s)" % ibm.get("rigid_response", "implicit")
    return coupling


def run_parameters(build, case):
    """One dict per HDF5 output of the case (its folder and sub-folders): run name, grid, h, dt
    rule, fluid scheme (convection / wall closure), markers, kernel, forcing passes, coupling, run
    time, from the resolved scene the solver
    stores in the file (root attribute `scene`) and /timing/run."""
    rows = []
    case_dir = os.path.join(build, "validation", case)
    paths = sorted(glob.glob(os.path.join(case_dir, "**", "*.h5"), recursive=True))
    if not paths:
        return rows
    import h5py
    for path in paths:
        try:
            with h5py.File(path, "r") as f:
                text = f.attrs.get("scene", b"")
                text = text.decode() if isinstance(text, bytes) else str(text)
                seconds = float(np.asarray(f["timing/run"])) if "timing/run" in f else math.nan
        except (OSError, ValueError, TypeError):
            continue
        scene = _toml(text) or {}
        run, dom, ibm = scene.get("run", {}), scene.get("domain", {}), scene.get("ibm", {})
        fluid = scene.get("fluid", {})
        nx, ny = dom.get("cells_x"), dom.get("cells_y")
        h = dom.get("length_x", math.nan) / nx if nx else math.nan
        if run.get("time_step", 0) and run["time_step"] > 0:
            dt = "fixed %s" % num(run["time_step"], 3)
        elif run:
            dt = "CFL %s" % num(run.get("cfl"), 3)
            if math.isfinite(run.get("max_time_step", math.inf)):
                dt += r"; $\Delta t \le$ %s" % num(run["max_time_step"], 3)
            if run.get("max_viscous_number", 0) > 0:
                dt += r"; $\nu\Delta t/h^2 \le$ %s" % num(run["max_viscous_number"], 3)
        else:
            dt = "--"
        bodies = scene.get("bodies", [])
        markers = sorted({b.get("n_surface_points") for b in bodies if b.get("n_surface_points")})
        startup = None
        for side in scene.get("walls", {}).values():
            if isinstance(side, dict) and side.get("kind") == "inflow" and side.get("time_factor") == "ramp":
                startup = 2.0 * side.get("ramp_time", 0.0)
        rows.append(dict(
            run=os.path.relpath(path, case_dir)[:-3], nx=nx, ny=ny, h=h, dt=dt,
            scheme="%s / %s" % (fluid.get("convection", "central"), fluid.get("wall_closure", "linear")),
            bodies=len(bodies), markers=", ".join(str(m) for m in markers) if markers else "--",
            kernel=ibm.get("kernel", "--") if bodies else "--",
            passes=str(ibm.get("forcing_passes", "--")) if bodies else "--",
            coupling=coupling_text(ibm, bodies),
            seconds=seconds, startup=startup, scene=scene))
    return sorted(rows, key=lambda r: ((r["nx"] or 0) * (r["ny"] or 0), r["run"]))


def grids_text(params, rows):
    """Grids of a case: the cells of its runs, else the D/h its results name."""
    grids = []
    for p in params:
        if p["nx"] and p["ny"]:
            g = "%d$\\times$%d" % (p["nx"], p["ny"])
            if g not in grids:
                grids.append(g)
    if grids:
        return ", ".join(grids)
    found = []
    for r in rows:
        for g in re.findall(r"D/h = ([0-9.]+)", r["metric"]):
            g = "%g" % float(g)
            if g not in found:
                found.append(g)
    return ("$D/h$ = " + ", ".join(sorted(found, key=float))) if found else "--"


def grid_statement(params, source, case):
    """What the grids this level ran allow: one grid (no estimate; the README's own statement where
    it says why the case has no grid study, or its grid study of finer grids), two (a
    difference only), or three and more (orders and GCIs, in the results, where the sequence
    converges)."""
    grids = sorted({(p["nx"], p["ny"]) for p in params if p["nx"] and p["ny"]}, key=lambda g: g[0] * g[1])
    if not grids:
        return None
    if len(grids) == 1:
        # The README's own paragraph, quoted: why the case has no grid study, or its study of finer grids.
        for title, lead in (("No grid study", "One grid (%d$\\times$%d), and no grid study at any level; the case "
                                              "README says why, and what stands for it"),
                            ("Grid study", "One grid (%d$\\times$%d) at this level; the case README's grid study, "
                                           "on finer grids")):
            paragraph = readme_titled_paragraph(source, case, title)
            if paragraph:
                text, cut = paragraph
                return (lead % grids[0] + " (\\texttt{validation/%s/README.md}%s): ``%s''" %
                        (esc(case), ", its first sentences" if cut else "", md_text(text)))
        return ("One grid (%d$\\times$%d): no grid study and no GCI at this level; the case README gives what "
                "is known beyond it (finer grids at the paper level, or why there are none)." % grids[0])
    if len(grids) == 2:
        return ("Two grids (%s): their difference only; an observed order and a GCI need three." %
                ", ".join("%d$\\times$%d" % g for g in grids))
    return ("%d grids (%s): observed orders, Richardson values and GCIs (Roache %s) in the results above where "
            "the sequence converges (none where it does not)." %
            (len(grids), ", ".join("%d$\\times$%d" % g for g in grids), cases_mod.cite("roache1994")))


# ---------------------------------------------------------------- title and page 1
def commit_flag(commits, state):
    """LaTeX text: whether the outputs' commit (HDF5 root attribute git_commit, which carries no
    dirty flag) is the code that ran: one commit across the outputs, and the build's source tree at
    report time at that commit with no tracked file changed (clean), else dirty, another commit, or
    a mix of commits."""
    if not commits:
        return "no HDF5 output"
    flags = []
    if len(commits) > 1:
        flags.append(r"\textcolor{red}{\textbf{mixed}}: outputs of %d commits (environment section)" % len(commits))
    main = max(commits, key=commits.get)
    if state is None:
        flags.append("dirty flag unknown (the build's source tree is not found)")
    elif not re.fullmatch(r"[0-9a-f]{7,40}", main):
        flags.append("the outputs record no commit")
    elif main[:min(len(main), len(state["head"]))] != state["head"][:len(main)]:
        flags.append(r"\textcolor{red}{\textbf{not the build's tree}}: its HEAD is \texttt{%s}" % esc(state["head"]))
    elif state["changed"]:
        flags.append(r"\textcolor{red}{\textbf{dirty}}: \texttt{%s} at report time, %d tracked file(s) changed"
                     % (esc(state["describe"]), len(state["changed"])))
    else:
        flags.append(r"\textcolor{passgreen}{\textbf{clean}}: \texttt{%s} at report time, no tracked file changed"
                     % esc(state["describe"]))
    return r"\texttt{%s} (%s)" % (esc(main), "; ".join(flags))


def title_block(out, env, build, commits=None, state=None, peers=()):
    get = dict(env)
    threads = ("1 per run (workflow jobs, \\texttt{OMP\\_NUM\\_THREADS=1})"
               if os.path.isdir(os.path.join(build, "workflow_state", "tests")) else "not recorded")
    rows = [["ibms version", esc(get.get("ibms version (from outputs)", "--"))],
            ["outputs' commit", commit_flag(commits or {}, state)],
            ["report's source tree", "\\texttt{%s} (reference data, case READMEs, this report's code)"
             % esc(get.get("source tree at report time", "--"))],
            ["date", esc(get.get("report date", "--"))],
            ["main job level / time", "%s / %s" % (esc(get.get("main job level", "--")),
                                                   esc(get.get("main job time to this report", "--")))],
            ["machine", esc(get.get("CPU", "--"))],
            ["newest output", esc(get.get("newest output started", "--"))],
            ["threads / build type", "%s / %s" % (threads, esc(get.get("build type", "--")))]]
    for name, text in peers:
        rows.append(["peer: " + esc(name), text])
    out.append(r"\begin{center}{\LARGE ibms verification and validation report}\\[0.5ex]")
    out.append(r"{\footnotesize\begin{tabular}{@{}lp{13.2cm}@{}}" +
               "\n".join("%s: & %s\\\\" % (a, b) for a, b in rows) + r"\end{tabular}}\end{center}")


def _headline(c):
    h = c.get("headline")
    if not h:
        return "--"
    return "%s: %s (target %s)" % (md_text(h["metric"]), cases_mod.measured_text(h), h["target_text"])


def slow_checks_not_run(build, defined):
    """The `slow` checks of the validation cases (`defined`: ctest's list in the build, runs left
    out) that have no status in this build's workflow state: the verdicts this level does not give."""
    return [name for name, labels, _ in defined
            if "slow" in labels and not re.search(r"_run(_|$)", name)
            and not os.path.exists(os.path.join(build, "workflow_state", "tests", name + ".status"))]


def summary_page(out, order, metas, judged, params, not_run=()):
    out.append(r"\vspace{-1ex}\section*{Summary: one row per validation case}")
    out.append(r"{\small The cases of \texttt{validation/}: validation against published or exact results, "
               r"except those marked O, which compare ibms only with its own runs (consistency checks, not "
               r"validation).}" + "\n")
    out.append(r"\addcontentsline{toc}{section}{Summary}")
    counts = {}
    rows = []
    for case in order:
        c = judged.get(case, dict(verdict="not run", rows=[]))
        counts[c["verdict"]] = counts.get(c["verdict"], 0) + 1
        m = metas[case]
        against = "%s %s%s" % (cases_mod.mark_cell(m["mark"]), esc(m["detail"]) + ": " if m["detail"] else "",
                               m["compared"])
        # A case compared only with ibms's own runs (mark own) is a consistency check, not a
        # validation: its row says so.
        validates = m["validates"] if m["mark"] != "own" else \
            r"\emph{Consistency check against ibms's own runs, not validation:} " + m["validates"]
        rows.append([r"\hyperref[case:%s]{%s}" % (case, tt(case)),
                     validates, against, grids_text(params.get(case, []), c["rows"]),
                     cases_mod.verdict_cell(c["verdict"]), _headline(c)])
    out.append(r"{\fontsize{%g}{%g}\selectfont\setlength{\tabcolsep}{3pt}" % TABLE_PT + "\n" +
               longtable(r">{\raggedright\arraybackslash}p{2.1cm}>{\raggedright\arraybackslash}p{3.6cm}"
                         r">{\raggedright\arraybackslash}p{3.5cm}>{\raggedright\arraybackslash}p{1.5cm}c"
                         r">{\raggedright\arraybackslash}p{4.6cm}",
                         ["case", "validates", "against (P published, E exact, O ibms's own)", "grid(s)",
                          "verdict", "headline: the principal published figure, else the worst, against its target"], rows, size=None,
                         caption="The validation cases: what each validates, against what (its README's source "
                                 "mark), its grids, its verdict and its headline figure.") + "}")
    out.append(r"{\small Cases (one verdict per case): %s. \emph{pass}: every judged figure meets its target; \emph{miss}: a figure "
               r"misses its published bounds (judged on them even where ibms's own gate passes) or, where no "
               r"published figure exists, a target the case sets (tolerance in \texttt{case\_criteria.hpp} or the "
               r"README), without a gated check failing; \emph{FAIL}: a gated check failed. Figures "
               r"without a target are \emph{info} (\S\ref{sec:checks}).}" %
               ", ".join("%d %s" % (n, v) for v, n in sorted(counts.items())) + "\n")
    out.append(class_counts_table(order, metas, judged))
    if not_run:
        out.append(r"{\small \emph{Not run at this level} (the paper level's \texttt{slow} label: finer grids, "
                   r"their Richardson values and gates, the references' regeneration): %s.}" %
                   ", ".join(tt(n) for n in not_run) + "\n")
    misses = [(case, r) for case in order for r in judged.get(case, {}).get("rows", [])
              if r["verdict"] in ("miss", "fail")]
    if misses:
        out.append(r"\paragraph{Every miss and failure} {\scriptsize (measured against target; causes in "
                   r"\S\ref{sec:limitations})}")
        items = ["%s \\texttt{%s}: %s: %s (target %s)" % (cases_mod.verdict_cell(r["verdict"]),
                                                          esc(r["row_case"]), md_text(r["metric"]),
                                                          cases_mod.measured_text(r), r["target_text"])
                 for case, r in misses]
        out.append(r"{\fontsize{%g}{%g}\selectfont\begin{itemize}\setlength{\itemsep}{0pt}\setlength{\parskip}{0pt}"
                   % TABLE_PT + "\n" +
                   "\n".join(r"\item " + i for i in items) + r"\end{itemize}}")
    else:
        out.append(r"\paragraph{No miss and no failure} among the judged figures.")


# The classes of evidence, counted apart on page 1: what a figure is compared with.
EVIDENCE_CLASSES = [("exact", "verification against exact solutions"),
                    ("published", "validation against published numbers"),
                    ("qualitative", "qualitative claims of the papers"),
                    ("own", "ibms against itself")]


def evidence_class(meta, row=None):
    """A case's class from its README mark (published, qualitative: the papers' claims); a figure
    of ibms against itself inside a case (GCI, wheel / rigid, ...) is `own` whatever the case."""
    if row is not None and row.get("own"):
        return "own"
    if meta["mark"] == "published" and "qualitative" in meta.get("detail", ""):
        return "qualitative"
    return meta["mark"]


def class_counts_table(order, metas, judged):
    """Judged figures per class of evidence, with their verdicts: one unit (figures, the
    results.csv lines judged against a target), since a case holds figures of several classes (its
    GCI and wheel-against-rigid lines are ibms against itself inside a published case)."""
    rows = []
    for key, name in EVIDENCE_CLASSES:
        figures = [r["verdict"] for c in order for r in judged.get(c, {}).get("rows", [])
                   if evidence_class(metas[c], r) == key and r["verdict"] != "info"]
        rows.append([esc(name), str(len(figures))] + [str(figures.count(v)) for v in ("pass", "miss", "fail")])
    total = [sum(int(r[k]) for r in rows) for k in range(1, 5)]
    rows.append([r"\textbf{all classes}"] + [str(n) for n in total])
    return (r"{\fontsize{8}{9}\selectfont" + "\n" +
            longtable("lrrrr", ["class of evidence", "judged figures", "pass", "miss", "FAIL"], rows, size=None, keep=True,
                      caption=r"Counts per class of evidence, in \emph{figures}: the lines of "
                              r"\texttt{validation/results.csv} judged against a target (\emph{info} lines not "
                              r"counted; \S\ref{sec:checks}). A case holds several figures, and a figure of ibms "
                              r"against itself (GCI, Richardson value, wheel against rigid, control-volume against "
                              r"immersed-boundary $c_D$) counts as such inside a published case; "
                              r"the cases' verdicts are counted above.") + "}")


def deviation_rows(points):
    """(number, deviation, band low, band high, verdict) in per cent of the reference for each
    point of predicted_against_reference with a non-zero reference: the band is the target's
    own (its bounds over the reference), independent of where the figure lies."""
    rows = []
    for k, (case, metric, v, y, lo, hi, verdict) in enumerate(points, 1):
        if v == 0:
            continue
        d, dlo, dhi = 100 * (y / v - 1), 100 * (lo / v - 1), 100 * (hi / v - 1)
        rows.append((k, d, min(dlo, dhi), max(dlo, dhi), verdict))
    return rows


def _symlog_margin(x):
    """An axis limit beyond x >= 0 on a symlog axis with linear range +-1: 1.5 inside it, else
    about half a decade beyond x."""
    return 1.5 if x < 1.0 else x * 3.0


def quantities_summary_section(out, order, metas, judged, fig_dir):
    """All quantities with a reference value: predicted against reference (one scatter plot, the
    reference's band as an error bar), and the bias and scatter per class of evidence (as the NIST
    FDS validation guide summarises its quantities)."""
    points = cases_mod.predicted_against_reference(judged)
    if not points:
        return
    out.append(r"\section{All quantities against their references}\label{sec:quantities}")
    out.append("Every judged figure whose target names a reference value (%d figures): the prediction "
               "against the reference, the bar the target's band (published bounds or reading uncertainty, "
               "else the case's own tolerance), in each quantity's units; a relative deviation $x$ of a "
               "reference $v$ is drawn as $v(1+x)$. Below, the bias (mean of prediction / reference $-1$) and "
               "its scatter (standard deviation) per class of evidence." % len(points))
    import matplotlib.pyplot as plt
    fig, (ax, dax) = plt.subplots(1, 2, figsize=(7.2, 3.6), gridspec_kw=dict(width_ratios=[1, 1.3]))
    colours = {"pass": "tab:green", "miss": "tab:orange", "fail": "tab:red"}
    # The target's band on the ibms axis at the reference (grey, capped), the figure as its point:
    # a miss lies off its bar. Bands narrower than the marker (most published ones on a log axis)
    # hide behind it; the right panel shows them in per cent.
    for case, metric, v, y, lo, hi, verdict in points:
        if v > 0 and lo > 0:
            ax.vlines([v], [lo], [hi], colors="0.5", linewidth=3, alpha=0.7)
            ax.plot([v, v], [lo, hi], "_", color="0.3", ms=6)
        ax.plot([v], [y], "o", ms=4, color=colours.get(verdict, "grey"), zorder=3)
    values = [abs(p[2]) for p in points] + [abs(p[3]) for p in points]
    lo_v, hi_v = max(min(values) * 0.5, 1e-6), max(values) * 2
    ax.plot([lo_v, hi_v], [lo_v, hi_v], "k-", lw=0.8)
    for f in (0.9, 1.1):
        ax.plot([lo_v, hi_v], [f * lo_v, f * hi_v], "k:", lw=0.6)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("reference value (its units)", fontsize=8)
    ax.set_ylabel("ibms (same units)", fontsize=8)
    for verdict, colour in colours.items():
        ax.plot([], [], "o", color=colour, label=verdict)
    ax.plot([], [], "k:", label="$\\pm$10 %")
    ax.legend(loc="upper left", fontsize=7)
    # The same figures as deviations from their references, numbered as in the table below: each
    # target's band drawn from its lower to its upper bound and the figure as its own point, so a
    # miss shows outside its band (per-cent misses that the log-log panel cannot show).
    rows = deviation_rows(points)
    for k, d, dlo, dhi, verdict in rows:
        dax.vlines([k], [dlo], [dhi], colors="0.6", linewidth=4, alpha=0.6)
        dax.plot([k], [d], "o", ms=4, color=colours.get(verdict, "grey"), zorder=3)
    dax.axhline(0.0, color="k", lw=0.6)
    dax.set_xticks(range(1, len(points) + 1))
    dax.set_xlim(0.3, len(points) + 0.7)
    dax.set_xlabel("figure (table below)", fontsize=8)
    dax.set_ylabel("ibms / reference $-$ 1 [%] (bar: target band)", fontsize=8)
    dax.set_yscale("symlog", linthresh=1.0)
    # Every point and band inside the frame: the axis reaches half a decade beyond the largest
    # value on either side (symlog: logarithmic beyond +-1 %).
    ext = [v for _, d, dlo, dhi, _ in rows for v in (d, dlo, dhi) if math.isfinite(v)] or [0.0]
    dax.set_ylim(-_symlog_margin(-min(ext)), _symlog_margin(max(ext)))
    dax.tick_params(axis="x", labelsize=7)  # one number per figure: many, and without scripts
    fig.tight_layout()
    path = os.path.join(fig_dir, "quantities_summary.pdf")
    figs.save(fig, path)
    out.append(figure(path, "Left: every quantity with a reference value against it (green pass, orange miss, red "
                            "FAIL; grey bars: the target's band on the ibms axis, most narrower than the marker; dotted: "
                            "$\\pm$10\\,\\%). Right: the same figures as per-cent deviations from their references "
                            "(linear within $\\pm$1\\,\\%, logarithmic beyond), numbered as in the table below; each "
                            "grey bar spans its target's band from its lower to its upper bound, the point is the "
                            "figure itself (outside its bar: a miss).", height=0.28))
    out.append(longtable("rlp{6.4cm}rrrl", ["\\#", "case", "figure", "reference", "ibms", "deviation", "verdict"],
                         [[str(k), tt(case), md_text(metric), num(v, 5), num(y, 5),
                           "%+.3g\\,\\%%" % (100 * (y / v - 1)) if v else "--", cases_mod.verdict_cell(verdict)]
                          for k, (case, metric, v, y, lo, hi, verdict) in enumerate(points, 1)],
                         caption="The figures of the summary plot.", size="scriptsize"))
    rows = []
    for key, name in EVIDENCE_CLASSES:
        dev = [p[3] / p[2] - 1.0 for p in points
               if p[2] != 0 and evidence_class(metas.get(p[0], dict(mark="own", detail=""))) == key]
        if not dev:
            rows.append([esc(name), "0", "--", "--"])
            continue
        mean = float(np.mean(dev))
        spread = float(np.std(dev)) if len(dev) > 1 else 0.0
        rows.append([esc(name), str(len(dev)), cases_mod.fmt_value(mean, True, True),
                     cases_mod.fmt_value(spread, True)])
    out.append(r"{\fontsize{8}{9}\selectfont" + "\n" +
               longtable("lrrr", ["class of evidence", "figures with a reference value", "bias", "scatter"], rows,
                         size=None,
                         caption="Bias (mean of ibms / reference $-$ 1) and scatter per class; a class without "
                                 "figures judges differences or claims, not values (the tables of \\S1).") + "}")


def checks_by_case_section(out, order, metas, judged):
    out.append(r"\section{Validation checks by case}\label{sec:checks}")
    out.append("Every line of \\texttt{validation/results.csv} (last line per case and metric), grouped by "
               "case. Source: P published, E exact, O ibms's own (the case's mark from its README; lines "
               "comparing ibms with itself, such as the grid convergence index GCI of Roache %s in the form of "
               "Celik et al. %s, observed orders, Richardson values of ibms's own grids, the change over the "
               "grid before, wheel against rigid and control-volume against immersed-boundary $c_D$, are O). \\emph{gate}: "
               "\\emph{check} when the case's check program judged the line, \\emph{report} when this report "
               "judged an \\emph{info} line against its target (rules in \\texttt{reports/report\\_cases.py}).\n"
               % (cases_mod.cite("roache1994"), cases_mod.cite("celik2008")))
    rows = []
    for case in order:
        c = judged.get(case)
        if not c:
            continue
        m = metas[case]
        rows.append([r"\multicolumn{6}{p{16.5cm}}{\textbf{\texttt{%s}}: %s (%s: %s)}" %
                     (esc(case), cases_mod.verdict_cell(c["verdict"]), esc(m["qualifier"]), m["compared"])])
        for r in c["rows"]:
            mark = "own" if r["own"] else m["mark"]
            metric = md_text(r["metric"]) + ("" if r["row_case"] == case else
                                         r" {\scriptsize(\texttt{%s})}" % esc(r["row_case"][len(case):].lstrip("_")))
            target = r["target_text"] + (r"\newline{\scriptsize %s}" % r["target_source"] if r["target_source"] else "")
            rows.append([cases_mod.mark_cell(mark), metric, target, cases_mod.measured_text(r),
                         cases_mod.verdict_cell(r["verdict"]), r["gate"]])
    if rows:
        out.append(longtable(r"c>{\raggedright\arraybackslash}p{8.0cm}>{\raggedright\arraybackslash}p{3.0cm}rcl",
                                                   ["src", "claim / metric", "target", "measured", "verdict", "gate"],
                                                   [r if len(r) > 1 else [r[0]] for r in rows], size="footnotesize",
                                                   caption="Every line of \\texttt{validation/results.csv} by case, "
                                                           "with its source mark, target, measured value, verdict "
                                                           "and gate."))
    else:
        out.append(r"\emph{No validation results: \texttt{validation/results.csv} not found (not run).}" + "\n")


# ---------------------------------------------------------------- verification
def _is_verification_test(t):
    """A test of the unit and convergence run: not from a workflow job's log (LastTest_wf_*: the
    validation cases' runs, checks and reference comparisons) and not a case's run, check or gate
    by name (<case>_run..., _check..., _gate...); a unit test (test_*) whatever its name holds
    (test_end_of_run_forces)."""
    if t.get("log", "").startswith("LastTest_wf_"):
        return False
    name = t["name"]
    return name.startswith("test_") or not re.search(r"_(run|check|gate)(_|$)", name)


def verification_section(out, conv, tests, fig_dir):
    out.append(r"\section{Verification: observed orders against formal orders}")
    ver = [t for t in tests if _is_verification_test(t)]
    if ver:
        n_fail = sum(t["status"] == "FAIL" for t in ver)
        out.append("Unit and convergence tests from ctest's logs: %d tests, %d failed: the tests of the unit and "
                   "convergence run, not the validation cases' runs, checks and reference comparisons (the "
                   "workflow's jobs); the per-test table of the environment section lists all %d tests of all "
                   "logs, these and those. Each program passes only if all its claims (Boost test cases) hold.\n"
                   % (len(ver), n_fail, len(tests)))
        rows = [[tt(t["name"]), status_cell(t["status"]), num(t["seconds"])] for t in ver]
        out.append(longtable(r">{\raggedright\arraybackslash}p{10cm}cr", ["test", "verdict", "time [s]"], rows,
                                                  caption="Unit and convergence tests (ctest).", size="footnotesize"))
    else:
        out.append(r"\emph{Unit and convergence tests: none in ctest's logs (\texttt{Testing/Temporary/LastTest*.log}) "
                   r"of the build directory: not run, or their log was overwritten by a later ctest run.}" + "\n")
    if not conv:
        out.append(r"\emph{Not run: \texttt{verification\_results/convergence.csv} not found. Run "
                   r"\texttt{ctest -L convergence} in the build directory (ctest sets "
                   r"\texttt{IBMS\_RESULTS\_DIR}).}")
        return
    out.append("Each table is written by a convergence test (\\texttt{verification/common/convergence.hpp}) "
               "with the test's claim: the formal order of the scheme and the band the test asserts the "
               "fitted order in. The order is the least-squares slope of $\\log e$ against $\\log h$ (or "
               "$\\log\\Delta t$) over the finest three levels with its standard error (most of the order tests "
               "also require the standard error $\\le 0.1$, \\texttt{max\\_order\\_standard\\_error}; "
               "a table whose test does not shows a larger one); the report fits nothing. Verdict: \\emph{pass} "
               "inside the asserted band, \\emph{FAIL} outside; \\emph{info} where the test asserts no "
               "order (it asserts something else, e.g. a decreasing difference).\n")
    rows, studies = [], OrderedDict()
    for k, (title, t) in enumerate(conv.items()):
        fit, se = t["fit_order"], t["fit_stderr"]
        lo, hi, formal = t.get("asserted_min", math.nan), t.get("asserted_max", math.nan), t.get("formal", math.nan)
        if math.isfinite(lo) or math.isfinite(hi):
            lo_ok = not math.isfinite(lo) or fit >= lo
            hi_ok = not math.isfinite(hi) or fit <= hi
            verdict = status_cell("pass" if math.isfinite(fit) and lo_ok and hi_ok else "FAIL")
            band = "[%s, %s]" % (num(lo, 3) if math.isfinite(lo) else r"$-\infty$",
                                 num(hi, 3) if math.isfinite(hi) else r"$\infty$")
        else:
            verdict, band = status_cell("info"), "--"
        program, refined = figs.study_of(title, t)
        studies.setdefault((program, refined), []).append((k + 1, title, t))
        rows.append([str(k + 1), md_text(title), "$\\Delta t$" if refined == "dt" else "$h$",
                     ", ".join(str(n) for n in t["N"]), num(t["error"][-1], 3),
                     "--" if not math.isfinite(formal) else num(formal, 3),
                     "--" if not math.isfinite(fit) else num(fit, 3) + ("" if not math.isfinite(se) else r" $\pm$ " + num(se, 2)),
                     band, verdict])
    out.append(longtable(r"r>{\raggedright\arraybackslash}p{4.6cm}c>{\raggedright\arraybackslash}p{1.5cm}rrrcc",
                                              ["", "table", "refines", "N", "finest error", "formal",
                                               "observed (3 finest)", "asserted", "verdict"], rows,
                                              caption="Observed orders beside formal orders.", size="footnotesize"))
    for (program, refined), items in studies.items():
        path = figs.convergence_study(program, refined, items, os.path.join(
            fig_dir, "convergence_%s_%s.pdf" % (re.sub(r"\W", "_", program), refined)))
        out.append(figure(path, "\\texttt{%s}: error against %s, tables numbered as above (legend: fitted order). "
                                "Triangle: reference slope of the formal order." %
                          (esc(program), "the time step $\\Delta t$" if refined == "dt" else "the grid spacing $h$"),
                          height=0.3))


# ---------------------------------------------------------------- case sections
def literature_for(case, source, params):
    """Published values drawn on the case's body-history figure (report_figures.body_histories),
    read from the case's reference files; and the caption text naming them."""
    lit, notes = dict(bands={}, lines={}, points={}), []
    rd = cases_mod.read_reference
    startups = [p["startup"] for p in params if p.get("startup")]
    if startups:
        lit["startup"] = max(startups)
    if case in ("dfg_cylinder_2d1", "dfg_cylinder_2d2"):
        ref = rd(source, case, "dfg_2d1.csv" if case.endswith("1") else "dfg_2d2.csv")
        for q, key in (("drag_coefficient", "drag_coefficient"), ("lift_coefficient", "lift_coefficient"),
                       ("drag_coefficient_max", "drag_coefficient"), ("lift_coefficient_max", "lift_coefficient")):
            if q in ref and isinstance(ref[q].get("lower"), float):
                what = "max " if q.endswith("_max") else ""
                lit["bands"].setdefault(key, []).append((ref[q]["lower"], ref[q]["upper"],
                                                         "%sSch\u00e4fer & Turek (1996) bounds" % what))
                if case.endswith("1"):
                    lit["lines"].setdefault(key, []).append((ref[q]["value"], "John & Matthies (2001)"))
        notes.append("Grey bands: the published bounds of Sch\\\"afer \\& Turek %s%s. Every sample is drawn; the "
                     "vertical axis is scaled to the samples after the inflow ramp-up ($t \\ge %s$) without each "
                     "run's last, shortened step, so the start-up transient and that last step may run off the "
                     "axes." %
                     (cases_mod.cite("schafer1996"),
                      "; dashed: the refined values of John \\& Matthies " + cases_mod.cite("john2001")
                      if case.endswith("1") else " for the maxima", num(lit.get("startup", 0), 3)))
        # The slip panel: the tolerance the end-of-step constraint holds the face velocities to, and
        # what the cell velocities' slip is (report_figures.body_histories draws both).
        tols = sorted({p["scene"].get("ibm", {}).get("slip_tolerance", 1e-3) for p in params
                       if p["scene"].get("ibm", {}).get("coupling") == "no_slip"})
        for tol in tols:
            lit["lines"].setdefault("face_slip_max", []).append(
                (tol, "ibm.slip_tolerance %g" % tol))
        notes.append("Right: the largest slip at the markers relative to $U_{\\rm mean}$, log scale. Solid: the "
                     "face velocities' slip (\\texttt{face\\_slip\\_max}), the one the end-of-step "
                     "\\texttt{no\\_slip} coupling holds to \\texttt{ibm.slip\\_tolerance}%s; dashed: the "
                     "cell-centred velocity interpolated at the markers (\\texttt{slip\\_max}), which no "
                     "constraint holds: the cell velocities differ from the face velocities by the momentum "
                     "interpolation's face term, $\\Delta t\\,(I-MA)(S_f\\mathbf F-G_fp)$ (\\texttt{docs/method.md} \\S2.3), "
                     "largest where the pressure and the force jump across the rim." % (" (dotted line, %s)" % ", ".join(num(t) for t in tols)
                                                          if tols else ""))
    if case == "settling_disk":
        ref = rd(source, case, "settling_disk_rho1.25.csv")
        curves, _ = cases_mod.read_long_reference(source, case, "wan_turek_settling_digitized.csv")
        if "max_settling_speed_glowinski" in ref:
            v = ref["max_settling_speed_glowinski"]["value"]
            lit["lines"]["velocity_y"] = [(-v, "max speed %s cm/s, Glowinski et al. (2001)" % num(v))]
        if "max_settling_speed" in ref:
            v, u = ref["max_settling_speed"]["value"], ref["max_settling_speed"].get("reading_uncertainty", 0.0)
            lit["bands"]["velocity_y"] = [(-v - u, -v + u, "max speed %s $\\pm$ %s cm/s, Wan & Turek (2006)" % (num(v), num(u)))]
        for q, key in (("centre_y", "centroid_y"), ("velocity_y", "velocity_y")):
            if q in curves:
                lit["points"][key] = [(curves[q][0], curves[q][1], "Wan & Turek (2006), digitised (third-hand)")]
        speeds = [ref[q]["value"] for q in ("max_settling_speed", "max_settling_speed_glowinski") if q in ref]
        if speeds:
            lit["zoom"] = {"velocity_y": (-max(speeds) * 1.025, -min(speeds) * 0.975, "near the maximum speed")}
        notes.append("Right: the velocity near its maximum. Dashed: the maximum settling speed of Glowinski et al. %s; grey band: the maximum read off "
                     "the curves of Wan \\& Turek %s with its reading uncertainty; squares: Wan \\& Turek's "
                     "symbols digitised third-hand (\\texttt{reference/wan\\_turek\\_settling\\_digitized.csv}, "
                     "provenance %s)." % (cases_mod.cite("glowinski2001"), cases_mod.cite("wan2006"),
                                          cases_mod.cite("rezaee2nnf")))
    if case == "dkt_two_disks":
        ref = rd(source, case, "wan_turek_dkt_digitized.csv")
        curves, _ = cases_mod.read_long_reference(source, case, "wan_turek_dkt_positions_digitized.csv")
        lit["body_names"] = {0: "trailing", 1: "leading"}
        pts = []
        for q, lab in (("centre_y_trailing", "trailing"), ("centre_y_leading", "leading")):
            if q in curves:
                pts.append((curves[q][0], curves[q][1], "Wan & Turek (2006), %s, digitised (third-hand)" % lab))
        if pts:
            lit["points"]["centroid_y"] = pts
        vpts = [(ref[t]["value"], -ref[v]["value"]) for v, t in (
            ("max_settling_speed_trailing", "time_of_max_speed_trailing"),
            ("max_settling_speed_leading", "time_of_max_speed_leading")) if v in ref and t in ref]
        if vpts:
            lit["points"]["velocity_y"] = [([p[0] for p in vpts], [p[1] for p in vpts],
                                            "Wan & Turek (2006): max speeds, digitised")]
        notes.append("Squares (trailing disk) and triangles (leading disk): Wan \\& Turek's symbols %s digitised "
                     "third-hand %s (centre heights, "
                     "\\texttt{reference/wan\\_turek\\_dkt\\_positions\\_digitized.csv}; the maximum speeds and their "
                     "times, \\texttt{reference/wan\\_turek\\_dkt\\_digitized.csv})." %
                     (cases_mod.cite("wan2006"), cases_mod.cite("rezaee2nnf")))
    return lit, " ".join(notes)


def parameter_table(out, params):
    if not params:
        out.append(r"{\small\emph{Run parameters: no HDF5 output of this case in the build directory (not run).}}" + "\n")
        return
    rows = [[tt(p["run"]), "%s$\\times$%s" % (p["nx"], p["ny"]), num(p["h"], 3), p["dt"], esc(p["scheme"]),
             str(p["bodies"]), p["markers"], esc(p["kernel"]), p["passes"], esc(p["coupling"]),
             num(p["seconds"], 3)] for p in params]
    # Eleven columns in the text width at 3 pt column separation: run, time step, convection /
    # wall, markers and coupling (e.g. "no_slip (rigid: implicit)") wrap.
    out.append(r"{\setlength{\tabcolsep}{3pt}")
    out.append(longtable(r">{\raggedright\arraybackslash}p{2.1cm}lr>{\raggedright\arraybackslash}p{2.3cm}"
                         r">{\raggedright\arraybackslash}p{1.7cm}r>{\raggedright\arraybackslash}p{1.25cm}lr"
                         r">{\raggedright\arraybackslash}p{1.8cm}r",
                                              ["run", "grid", "$h$", "time step", "convection / wall", "bodies",
                                               "markers", "kernel",
                                               "passes", "coupling", "run [s]"], rows,
                                              caption="Run parameters from each output's resolved scene "
                                                      "(\\texttt{fluid.convection} / \\texttt{fluid.wall\\_closure}; "
                                                      "\\texttt{ibm.coupling}: \\emph{uhlmann} %s where the scene "
                                                      "has no such key, \\emph{no\\_slip} the end-of-step constraint "
                                                      "%s; bodies carry the inner fluid's inertia of Kempe \\& "
                                                      "Fr\\\"ohlich %s) and its \\texttt{/timing/run}."
                                                      % (cases_mod.cite("uhlmann2005"), cases_mod.cite("taira2007"),
                                                         cases_mod.cite("kempe2012")), size="footnotesize",
                         tabcolsep=None))
    out.append("}")


def contact_pairs_rows(case_dir):
    """Per run of a case (every <stem>_bodies.csv in its folder and sub-folders) with a contact
    column: the mean and largest contact/n_active_pairs over the late window t >= 0.75 t_end (the
    swelling cavity's check takes 15 <= t <= 20), the mean contact/max_overlap there, and the
    smallest bodies/min_rim_distance there. The count is of contact-sphere (CDS) pairs, so a softer
    contact law that overlaps deeper engages more spheres per touching pair of bodies; the overlap
    and the rim distance say whether the bodies themselves come closer. [] with fewer than two runs."""
    rows = []
    for path in sorted(glob.glob(os.path.join(case_dir, "**", "*_bodies.csv"), recursive=True)):
        names, _, arr, _ = data.read_table_csv(path)
        if "contact/n_active_pairs" not in names or not names or names[0] != "time" or arr.shape[0] < 2:
            continue
        t = arr[:, 0]
        late = t >= 0.75 * np.nanmax(t)

        def column(name, reduce):
            if name not in names:
                return math.nan
            v = arr[late, names.index(name)]
            v = v[np.isfinite(v)]
            return float(reduce(v)) if v.size else math.nan
        rows.append(dict(run=os.path.relpath(path, case_dir)[:-len("_bodies.csv")], start=float(np.nanmax(t)) * 0.75,
                         mean_pairs=column("contact/n_active_pairs", np.mean),
                         max_pairs=column("contact/n_active_pairs", np.max),
                         overlap=column("contact/max_overlap", np.mean),
                         rim=column("bodies/min_rim_distance", np.min)))
    return rows if len(rows) >= 2 else []


def contact_pairs_table(out, case_dir):
    rows = contact_pairs_rows(case_dir)
    if not rows:
        return
    out.append(longtable("lrrrr", ["run", "mean pairs", "largest", "mean max overlap", "min rim distance"],
                         [[tt(r["run"]), num(r["mean_pairs"], 4), num(r["max_pairs"], 3), num(r["overlap"], 3),
                           num(r["rim"], 3)] for r in rows],
                         caption="Touching contact-sphere (CDS) pairs per run from its body series "
                                 "(\\texttt{contact/n\\_active\\_pairs}, the largest over a step's sub-steps, at each "
                                 "output row), mean and largest over $t \\ge %s$, with the mean of "
                                 "\\texttt{contact/max\\_overlap} and the smallest rim distance between bodies there. "
                                 "The count is of sphere pairs, not of bodies in contact: a softer contact law "
                                 "(\\texttt{contact.model = \\textquotedbl{}collision\\_time\\textquotedbl{}}, "
                                 "$T_c = 10\\,\\Delta t$, docs/method.md \\S5.5) overlaps deeper and engages more "
                                 "spheres of each touching pair of rims, so its counts are not comparable with the "
                                 "paper's law's; the rim distance says whether the bodies come closer." %
                                 num(min(r["start"] for r in rows), 3), size="footnotesize"))


def case_section(out, case, meta, build, source, judged, params, fig_dir):
    # a case judged only against ibms's own runs (mark own) is titled a consistency case
    out.append(r"\section{%s case \texttt{%s}}\label{case:%s}" %
               ("Consistency (ibms against itself)" if meta["mark"] == "own" else "Validation", esc(case), case))
    c = judged.get(case)
    out.append(r"\noindent\textbf{%s.} Validates: %s. Against (%s %s): %s. Verdict: %s." %
               (esc(meta["title"]), meta["validates"], cases_mod.mark_cell(meta["mark"]), esc(meta["qualifier"]),
                meta["compared"], cases_mod.verdict_cell(c["verdict"] if c else "not run")) + "\n")
    summary = readme_summary(source, case)
    if summary:
        # The README's own words, set apart and labelled: figures in it were measured in the runs its
        # authors made, not in this one (this run's are in the tables and figures below).
        text, cut = summary
        out.append(r"\begin{quote}\small\textbf{The case README's text} (\texttt{validation/%s/README.md}, its "
                   r"first paragraph%s; any figure in it is the README's, from an earlier run, not this run's "
                   r"result): ``%s''%s\end{quote}" %
                   (esc(case), ", its first sentences" if cut else "", md_text(text),
                    r" (the paragraph goes on in the README, under its title)" if cut else "") + "\n")
    parameter_table(out, params)
    statement = grid_statement(params, source, case)
    if statement:
        out.append(r"\noindent\textbf{Numerical uncertainty at this level.} " + statement + "\n")
    if not c:
        out.append(r"\emph{Not run: no lines for this case in \texttt{validation/results.csv}.}" + "\n")
    case_dir = os.path.join(build, "validation", case)
    ref_dir = os.path.join(source, "validation", case, "reference")
    made, misses_shown = 0, False
    if os.path.isdir(case_dir):
        stem = case.replace(".", "_")
        labels = {"ghia": "Ghia et al. (1982)", "botella": "Botella & Peyret (1998) extrema"}
        p = figs.cavity_profiles(case_dir, case, ref_dir, os.path.join(fig_dir, stem + "_profiles.pdf"), labels)
        if p:
            made += 1
            has_ref = bool(glob.glob(os.path.join(ref_dir, "ghia_*.csv")))
            has_bp = os.path.isfile(os.path.join(ref_dir, "botella_peyret_extrema.csv"))
            out.append(figure(p, "Centre-line profiles of every grid and, below, their difference from the reference. " +
                              ("Points: Ghia, Ghia \\& Shin %s, hollow where flagged in the reference file and "
                               "excluded from the check%s; the difference is the profile linearly interpolated at "
                               "Ghia's points (the check uses a cubic spline)." %
                               (cases_mod.cite("ghia1982"),
                                "; stars: the extrema of Botella \\& Peyret %s (below: extremum of the profile minus "
                                "theirs)" % cases_mod.cite("botella1998") if has_bp else "")
                               if has_ref else
                               "Dotted: the finest profile mirrored through the cavity centre ($u(y)\\to -u(1-y)$), "
                               "which a point-symmetric solution matches; below: each profile minus its mirror."),
                              height=0.5))
        h5s = sorted(glob.glob(os.path.join(case_dir, "**", "*.h5"), recursive=True))
        system = {}
        bodies_csv = sorted(glob.glob(os.path.join(case_dir, "*_bodies.csv")))
        if bodies_csv:
            system = figs.unit_system(data.read_table_csv(bodies_csv[0])[3])
        vlim = figs.vorticity_limit(h5s)
        # Cases with several runs of one grid (body cavities: k = 10 / 100, swelling or not) show
        # every run, at four times each; grid-convergence cases their finest run.
        runs = [p for p in h5s if os.path.dirname(p) == case_dir] if case.startswith("cavity_") else [None]
        for k, run in enumerate(runs):
            p, h5 = figs.snapshots(case_dir, case, os.path.join(fig_dir, "%s_snapshots%d.pdf" % (stem, k)),
                                   max_panels=4 if run else 3, path=run, vlim=vlim, system=system)
            if p:
                made += 1
                out.append(figure(p, "Vorticity with velocity vectors (every few cells) and the bodies' rims "
                                     "(black on white) where the run has bodies, from \\texttt{%s}; one colour "
                                     "scale for every snapshot of the case "
                                     "(98th percentile of $|\\omega|$, clipped beyond)." % esc(os.path.basename(h5)),
                                  height=0.6 if run else 0.34))
        for k, f in enumerate(sorted(glob.glob(os.path.join(case_dir, "trajectories_*.csv")))):
            p = figs.trajectories(f, os.path.join(fig_dir, "%s_trajectories%d.pdf" % (stem, k)))
            if p:
                made += 1
                out.append(figure(p, "Particle centre trajectories from \\texttt{%s} (red: last position)." %
                                  esc(os.path.basename(f)), height=0.3))
        lit, note = literature_for(case, source, params)
        p, files = figs.body_histories(case_dir, os.path.join(fig_dir, stem + "_bodies.pdf"), lit)
        if p:
            made += 1
            out.append(figure(p, "Body histories from %s. %s" %
                              (", ".join(tt(os.path.basename(f)) for f in files), note)))
            misses_shown = case_misses(out, case, c)  # below the histories that show them against the literature
        contact_pairs_table(out, case_dir)
        others = [f for f in sorted(glob.glob(os.path.join(case_dir, "*.csv")))
                  if "_centreline_" not in f and not f.endswith("_bodies.csv")
                  and not os.path.basename(f).startswith("trajectories_")]
        for k, f in enumerate(others[:6]):
            p = figs.generic_csv(f, os.path.join(fig_dir, "%s_csv%d.pdf" % (stem, k)))
            if p:
                made += 1
                out.append(figure(p, "Columns of \\texttt{%s} (written by the case's check) against its first "
                                     "column, one panel per unit." % esc(os.path.basename(f))))
    if made == 0:
        out.append(r"\emph{No figures: no run outputs in \texttt{BUILD/validation/%s} (not run).}" % esc(case) + "\n")
    if not misses_shown:
        case_misses(out, case, c)


def case_misses(out, case, c):
    """Once per case, where its figures show them (below its body histories, else at the section's
    end): every figure of the case that misses its target or fails its check, measured against
    target, with its cause as the case README states it (report_cases.CAUSES, the text Known
    limitations repeats). Returns whether it printed any."""
    rows = [r for r in (c or {}).get("rows", []) if r["verdict"] in ("miss", "fail")]
    if not rows:
        return False
    out.append(r"\paragraph{Misses of this case and their causes} (the causes and their figures are the case "
               r"README's, from its own runs; this run's figure is the one before the cause)")
    out.append(r"\begin{itemize}\setlength{\itemsep}{1pt}" + "\n" + "\n".join(
        r"\item %s %s%s: %s (target %s). %s" % (
            cases_mod.verdict_cell(r["verdict"]), md_text(r["metric"]),
            "" if r["row_case"] == case else r" (\texttt{%s})" % esc(r["row_case"][len(case):].lstrip("_")),
            cases_mod.measured_text(r), r["target_text"], cases_mod.cause_of(case, r["metric"])) for r in rows)
        + r"\end{itemize}" + "\n")
    return True


# ---------------------------------------------------------------- closing sections
def known_limitations(out, order, judged):
    out.append(r"\section{Known limitations}\label{sec:limitations}")
    rows = [(case, r) for case in order for r in judged.get(case, {}).get("rows", [])
            if r["verdict"] in ("miss", "fail")]
    if not rows:
        out.append("No judged figure misses its target in this build.\n")
        return
    out.append("Every figure of this build that misses its target (\\emph{miss}) or fails its check "
               "(\\emph{FAIL}), with its cause as the case README states it: the figures in a cause are the "
               "README's, measured in the runs it reports, not this run's (which are in the third column).\n")
    out.append(longtable(r"p{2.5cm}p{4.6cm}p{2.4cm}p{6.9cm}",
                                              ["case", "figure", "measured (target)",
                                               "cause (the README's text and figures)"],
                                              [[tt(r["row_case"]),
                                                md_text(r["metric"]),
                                                "%s (%s) %s" % (cases_mod.measured_text(r), r["target_text"],
                                                                cases_mod.verdict_cell(r["verdict"])),
                                                cases_mod.cause_of(case, r["metric"])] for case, r in rows], size="footnotesize",
                                              caption="Every miss and failure with its cause."))


def environment_section(out, env, tests):
    out.append(r"\section{Environment and run times}")
    out.append(longtable(r"p{4.5cm}p{11.5cm}", ["item", "value"], [[esc(k), esc(v)] for k, v in env],
                         caption="The environment of the outputs and of this report."))
    if not tests:
        out.append(r"\emph{Run times: not available (no \texttt{Testing/Temporary/LastTest.log}).}")
        return
    total = sum(t["seconds"] for t in tests if not math.isnan(t["seconds"]))
    rows = [[tt(t["name"]), status_cell(t["status"]), num(t["seconds"]), tt(t["log"])] for t in tests]
    out.append(longtable(r">{\raggedright\arraybackslash}p{8.5cm}cr>{\raggedright\arraybackslash}p{4.5cm}", ["ctest test", "result", "time [s]", "log"], rows,
                                              caption="Per-test wall times from ctest's logs: all %d tests of all logs, "
                                                      "the unit and convergence run's (%d, the count of the verification "
                                                      "section) and the workflow jobs' (validation runs, checks and "
                                                      "reference comparisons) (sum %.1f s; tests ran in parallel, so wall "
                                                      "time is lower)." % (len(tests), sum(map(_is_verification_test, tests)),
                                                                           total), size="footnotesize"))


def write_sources(tex, fig_files, directory):
    """report.tex and the figure PDFs it names, in one directory (what latexmk compiles)."""
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "report.tex"), "w", encoding="utf-8") as f:
        f.write(tex)
    for p in fig_files:
        shutil.copy(p, directory)


def build_pdf(tex, fig_files, build, output):
    work = tempfile.mkdtemp(prefix="report-", dir=build)
    write_sources(tex, fig_files, work)
    cmd = ["latexmk", "-pdf", "-interaction=nonstopmode", "-halt-on-error", "report.tex"]
    proc = subprocess.run(cmd, cwd=work, capture_output=True, text=True, errors="replace")
    pdf = os.path.join(work, "report.pdf")
    if proc.returncode != 0 or not os.path.isfile(pdf):
        sys.stderr.write(proc.stdout[-4000:] + proc.stderr[-2000:])
        sys.stderr.write("\nbuild_report: latexmk failed; sources kept in %s\n" % work)
        sys.exit(1)
    # Text or table columns running into the margin (clipped at print): named on stderr with the
    # source lines (the synthetic PDF test fails on it); the PDF is still written.
    try:
        with open(os.path.join(work, "report.log"), encoding="latin-1") as f:
            over = re.findall(r"Overfull \\hbox \(([0-9.]+)pt too wide\) (?:in|detected at) ([^\n]*)", f.read())
    except OSError:
        over = []
    over = [(float(w), where) for w, where in over if float(w) > 1.0]
    if over:
        sys.stderr.write("build_report: %d overfull lines (text wider than the page's text), widest %.1f pt: %s\n"
                         % (len(over), max(w for w, _ in over), "; ".join("%.1f pt %s" % o for o in over[:8])))
    os.makedirs(os.path.dirname(os.path.abspath(output)), exist_ok=True)
    shutil.copy(pdf, output)
    shutil.rmtree(work, ignore_errors=True)


def document(build, source, fig_dir):
    """The LaTeX source (a list of chunks) of the whole report."""
    results = data.read_results(os.path.join(build, "validation", "results.csv"))
    conv = data.read_convergence(os.path.join(build, "verification_results", "convergence.csv"))
    tests = data.read_ctest_logs(build)
    order, folders = case_list(build, source, results)
    metas = OrderedDict((case, cases_mod.read_case_meta(source, case)) for case in order)
    judged = cases_mod.judge(results, source, folders)
    params = {case: run_parameters(build, case) for case in order}
    h5s = glob.glob(os.path.join(build, "validation", "**", "*.h5"), recursive=True)
    env = data.environment(build, source, h5s)
    out = [PREAMBLE]
    title_block(out, env, build, data.output_commits(h5s), data.build_source_state(build),
                bench.peer_versions(build, source))
    defined = trace.ctest_tests(build)  # every test the build defines, read once
    summary_page(out, order, metas, judged, params, slow_checks_not_run(build, defined))
    out.append(r"\newpage\tableofcontents\newpage")
    checks_by_case_section(out, order, metas, judged)
    quantities_summary_section(out, order, metas, judged, fig_dir)
    verification_section(out, conv, tests, fig_dir)
    bench.kernel_moment_section(out, build)
    solid.solid_section(out, build, fig_dir)
    for case in order:
        case_section(out, case, metas[case], build, source, judged, params[case], fig_dir)
    bench.work_precision_section(out, build, fig_dir, source)
    bench.stability_section(out, build, fig_dir)
    bench.overhead_section(out, build)
    bench.scale_section(out, build, fig_dir)
    bench.forcing_passes_section(out, build, source)
    sweeps.sweeps_section(out, build, fig_dir)
    trace.traceability_section(out, source, defined, tests)
    environment_section(out, env, tests)
    # Tests the build labels unit or convergence are no case's runs, whatever their names hold.
    not_cases = {name for name, labels, _ in defined if {"unit", "convergence"} & set(labels)}
    bench.run_times_section(out, tests, folders, not_cases)
    known_limitations(out, order, judged)
    cases_mod.bibliography_section(out)
    out.append(r"\end{document}")
    return out, len(order), len(conv)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--build", required=True, help="build directory with the run outputs")
    ap.add_argument("--output", help="PDF to write")
    ap.add_argument("--tex-dir", help="write report.tex and its figures to this directory and stop "
                    "before LaTeX (the data-to-figures-and-LaTeX part, tested without a TeX installation)")
    ap.add_argument("--source", default=os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                    help="repository root (reference data, case READMEs); default: this repo")
    args = ap.parse_args()
    if (args.output is None) == (args.tex_dir is None):
        ap.error("give --output (the PDF) or --tex-dir (the LaTeX source and figures), not both")
    start = time.time()
    build, source = os.path.abspath(args.build), os.path.abspath(args.source)
    if not os.path.isdir(build):
        sys.exit("build_report: no build directory " + build)
    fig_dir = tempfile.mkdtemp(prefix="report-figures-", dir=build)
    try:
        try:
            out, n_cases, n_conv = document(build, source, fig_dir)
        except cases_mod.ReportError as e:
            sys.exit("build_report: %s" % e)
        # Figure text below 7 pt at print size (report_latex.figure): named on stderr (the synthetic
        # test fails on it); the report is still written.
        from report_latex import SMALL_TEXT, MIN_PRINT_PT
        if SMALL_TEXT:
            sys.stderr.write("build_report: figure text below %g pt at print size: %s\n" % (
                MIN_PRINT_PT, ", ".join("%s (%.1f pt)" % f for f in SMALL_TEXT)))
        # Figures are referenced by base name from the LaTeX work directory.
        fig_files = glob.glob(os.path.join(fig_dir, "*.pdf"))
        if args.tex_dir is not None:
            write_sources("\n".join(out), fig_files, args.tex_dir)
            target = os.path.join(args.tex_dir, "report.tex")
        else:
            build_pdf("\n".join(out), fig_files, build, args.output)
            target = args.output
    finally:
        shutil.rmtree(fig_dir, ignore_errors=True)
    print("report: %s (%d validation cases, %d convergence tables, built in %.1f s)" %
          (os.path.abspath(target), n_cases, n_conv, time.time() - start))


if __name__ == "__main__":
    main()
