"""Report sections fed by bench/ and by verification tables other than convergence:
kernel-moment table (BUILD/verification_results/kernel_moments.csv, written by test_delta_kernel),
work-precision plots with fitted slopes (BUILD/bench/work_precision_<case>.csv; the DFG cylinders
under both immersed-boundary couplings in a figure of their own, with the bench's time to 3 % on
DFG 2D-2's max c_D from BUILD/bench/time_to_target_dfg_2d2.csv), stability maps
(BUILD/bench/stability_<case>.csv), the cost of what a scene uses (BUILD/bench/overhead.csv) and
run times per validation case (ctest logs). Reads files only; the one fit is the least-squares
slope of log(error) against log(wall time), the same fit bench_work_precision prints."""
import csv
import glob
import math
import os
import re
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import report_figures as figs  # noqa: E402
from report_latex import esc, md_text, num, figure, longtable  # noqa: E402
import report_cases  # noqa: E402


def _rows(path):
    """Data rows of a CSV with '#' comment lines and one header line, as dicts (None if absent)."""
    if not os.path.isfile(path):
        return None
    with open(path, encoding="utf-8", errors="replace") as f:
        lines = [line for line in f if line.strip() and not line.startswith("#")]
    return list(csv.DictReader(lines))


def _comments(path):
    with open(path, encoding="utf-8", errors="replace") as f:
        return [line[1:].strip() for line in f if line.startswith("#")]


def _float(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def _plain(text):
    """A number as %.8g (ranges in a narrow column), a power of ten as one (no e-notation)."""
    value = _float(text)
    if math.isnan(value):
        return "nan"
    mant, _, ten = ("%.8g" % value).partition("e")
    return r"$%s\times10^{%d}$" % (mant, int(ten)) if ten else mant.replace("-", "$-$")


def log_log_slope(x, y):
    """Least-squares slope of log y against log x."""
    lx, ly = [math.log(v) for v in x], [math.log(v) for v in y]
    n = len(lx)
    mx, my = sum(lx) / n, sum(ly) / n
    sxx = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx if sxx > 0 else math.nan


def _bench_section(out, build, title, name, missing):
    """Opens the section `title` of one bench and returns the rows of BUILD/bench/<name>; without
    them it says so (`missing`, LaTeX) and returns None."""
    out.append(r"\section{%s}" % title)
    rows = _rows(os.path.join(build, "bench", name))
    if not rows:
        out.append(r"\emph{%s}" % missing + "\n")
    return rows


def kernel_moment_section(out, build):
    out.append(r"\section{Kernel moments}")
    path = os.path.join(build, "verification_results", "kernel_moments.csv")
    rows = _rows(path)
    if not rows:
        out.append(r"\emph{Not run: \texttt{verification\_results/kernel\_moments.csv} not found "
                   r"(written by \texttt{test\_delta\_kernel} under ctest).}" + "\n")
        return
    last = OrderedDict()
    for r in rows:  # a rerun appends again: the last row per kernel and moment wins
        last[(r["kernel"], r["moment"])] = r
    out.append("Discrete moment sums of the four regularised delta kernels (\\texttt{roma3} %s, \\texttt{peskin4} and "
               "\\texttt{cosine4} %s, \\texttt{bkp6} %s) over 1201 marker offsets "
               "in $[0,1]$ (\\texttt{verification/ibm/test\\_delta\\_kernel.cpp}, docs/method.md \\S4 and "
               "A9): the largest deviation from the expected value and the range of the sum.\n"
               % (report_cases.cite("roma1999"), report_cases.cite("peskin2002"), report_cases.cite("bao2016")))
    table = [[r"\texttt{%s}" % esc(k), _formula(m), _formula(r["expected"]), _max_error(r["max_error"]),
              "[%s, %s]" % (_plain(r["min_sum"]), _plain(r["max_sum"])), num(r["tolerance"], 2)]
             for (k, m), r in last.items()]
    out.append(longtable(r"lp{3.4cm}p{3.2cm}rp{3.6cm}r",
                         ["kernel", "moment", "expected", "max error", "range of the sum", "tolerance"],
                         table, caption="Kernel moments (from \\texttt{kernel\\_moments.csv}; max error "
                                        "--: a range claim, whose sum must lie in the stated range, has no "
                                        "single expected value to differ from; the range of the sum is the "
                                        "result)."))


# Words a kernel moment's formula may hold (kernel_moments.csv: "sum (x-j)^2 phi", "K = 59/60 -
# sqrt(29)/20", "in [1/3, 2/3]"); a text with any other word ("closed form (A9)") stays text.
_FORMULA_WORDS = {"sum": r"\sum", "phi": r"\phi", "sqrt": r"\sqrt", "in": r"\in"}


def _formula(text):
    """A moment or expected value of kernel_moments.csv in math mode where it is a formula (one
    unbreakable formula: its '-' a minus inside it), else as text (md_text)."""
    words = re.findall(r"[A-Za-z]{2,}", text)
    if not words and not re.search(r"[=^]", text) or not all(w in _FORMULA_WORDS for w in words) \
            or not re.fullmatch(r"[\w\s()\[\]/^=+*.,-]+", text):
        return md_text(text)
    s = re.sub(r"sqrt\(([^()]*)\)", r"sqrt{\1}", text)
    s = re.sub(r"\^(\d+)", r"^{\1}", s)
    s = re.sub(r"[A-Za-z]{2,}", lambda m: _FORMULA_WORDS[m.group(0)] + " ", s)
    return r"$%s$" % s.strip()


def _max_error(value):
    """The largest deviation, '--' where there is none (a range claim's nan)."""
    x = _float(value)
    return num(x, 3) if math.isfinite(x) else "--"


# The DFG cylinders' work-precision files, work_precision_<family>_<coupling>.csv: family -> (title,
# validation case, reference file, quantity); coupling -> (legend, marker and line, colour).
_BODY_FAMILIES = OrderedDict([
    ("dfg_2d1", ("DFG 2D-1 (Re 20): $c_D$", "dfg_cylinder_2d1", "dfg_2d1.csv", "drag_coefficient")),
    ("dfg_2d2", ("DFG 2D-2 (Re 100): max $c_D$", "dfg_cylinder_2d2", "dfg_2d2.csv", "drag_coefficient_max")),
])
_COUPLINGS = OrderedDict([
    ("uhlmann", ("uhlmann (papers')", "o-", "tab:orange")),
    ("no_slip", ("no_slip (faces)", "s-", "tab:blue")),
])


def _body_case(name):
    """(family, coupling) of a DFG cylinder's work-precision case name, else None."""
    for family in _BODY_FAMILIES:
        for coupling in _COUPLINGS:
            if name == "%s_%s" % (family, coupling):
                return family, coupling
    return None


def _basilisk_points(source, name):
    """Basilisk's measured (Re, N, seconds, error) on the cavity case `name` (cavity_re100, cavity_re1000),
    from bench/reference/basilisk_cavity.csv: published figures of this machine, not re-measured."""
    if not source or not name.startswith("cavity_re"):
        return []
    path = os.path.join(source, "bench", "reference", "basilisk_cavity.csv")
    rows = _rows(path) if os.path.exists(path) else []
    return [(r["re"], r["n"], _float(r["seconds"]), _float(r["error"])) for r in rows or []
            if "cavity_re" + r["re"] == name]


def peer_versions(build, source):
    """(peer, LaTeX text) of every other code this report compares ibms with: Basilisk, where the
    build has a cavity work-precision table (its figure draws Basilisk's points). The version is the
    one the reference file's '#' lines name (a line with 'version', 'darcs' or 'commit'), else it
    says that none is recorded, with the date the figures were measured."""
    path = os.path.join(source or "", "bench", "reference", "basilisk_cavity.csv")
    if not glob.glob(os.path.join(build, "bench", "work_precision_cavity_re*.csv")) or not os.path.isfile(path):
        return []
    comments = " ".join(_comments(path))
    version = re.search(r"[^.;]*\b(?:version|darcs|commit)\b[^.;]*", comments, re.I)
    date = re.search(r"recorded (\d{4}-\d{2}-\d{2})", comments)
    text = (esc(version.group(0).strip()) if version else r"\textbf{version not recorded}") + \
        " (lid-driven cavity work-precision, \\texttt{bench/reference/basilisk\\_cavity.csv}%s; not re-run by " \
        "the workflow)" % (", measured %s on this project's machine" % date.group(1) if date else "")
    return [("Basilisk", text)]


def work_precision_section(out, build, fig_dir, source=None):
    out.append(r"\section{Work-precision: error against run time}")
    files = sorted(glob.glob(os.path.join(build, "bench", "work_precision_*.csv")))
    files = [f for f in files if not f.endswith("_slopes.csv")]
    if not files:
        out.append(r"\emph{Not run: no \texttt{bench/work\_precision\_*.csv} (run "
                   r"\texttt{bench/bench\_work\_precision}).}" + "\n")
        return
    out.append("From \\texttt{bench/bench\\_work\\_precision}: each case at the resolutions of the table "
               "(four or more for the fluid cases; the DFG cylinders at two at the default level, so that two "
               "points give their slope, and four at full), error against the wall time of the whole run on this machine "
               "(shared, so times carry some noise). The slope is the least-squares fit of "
               "$\\log(\\mathrm{error})$ against $\\log(\\mathrm{time})$ over all points (over two points, "
               "as the DFG cylinders have at the default level, the slope of the line through them: a "
               "\\emph{two-point slope}, no fit); for a "
               "second-order method with $\\Delta t \\propto h$ in 2D the ideal is $-2/3$. In the "
               "main job the fluid cases (MMS, cavities, settling disk) are timed with the machine to "
               "themselves (job \\texttt{bench\\_work\\_precision}, every core claimed); the DFG "
               "cylinders (job \\texttt{bench\\_work\\_precision\\_bodies}) on one core beside "
               "other one-thread jobs, so their times are those of a shared machine, and their figure "
               "is the ratio of the two couplings' times, both measured so. The bench runs its own cases, so "
               "its errors are not the validation checks' figures of the same grids (\\S\\ref{sec:checks}): the cavities "
               "here run to a velocity change rate of $10^{-6}$ (the Basilisk comparison's criterion) and take "
               "each extremum from the parabola through the discrete extremum and its two neighbours, where "
               "the cavity checks take cubic-spline extrema of the validation runs' profiles; the DFG "
               "cylinders' settings are in \\S\\ref{sec:wp-bodies}.\n")
    cases, table = [], []
    for f in files:
        rows = _rows(f)
        pts = [(_float(r["wall_seconds"]), _float(r["error"]), r["N"]) for r in rows or []]
        pts = [p for p in pts if p[0] > 0 and p[1] > 0]
        if len(pts) < 2:
            continue
        name = os.path.basename(f)[len("work_precision_"):-len(".csv")]
        slope = log_log_slope([p[0] for p in pts], [p[1] for p in pts])
        definition = next((c.split("error = ", 1)[1] for c in _comments(f) if "error = " in c), "")
        scheme = next((c.split("fluid scheme: ", 1)[1] for c in _comments(f) if "fluid scheme: " in c), "")
        if scheme:
            definition += "; ibms's scheme: " + scheme
        cases.append((name, pts, slope))
        table.append([r"\texttt{%s}" % esc(name), ", ".join(p[2] for p in pts),
                      num(slope, 3) if len(pts) > 2 else
                      r"\begin{tabular}[t]{@{}r@{}}%s\\ {\scriptsize two-point}\end{tabular}" % num(slope, 3),
                      num(pts[-1][1], 3), num(pts[-1][0], 3), md_text(definition)])
    if not cases:
        out.append(r"\emph{No usable rows in the work-precision files.}" + "\n")
        return
    out.append(longtable(r"lp{2.4cm}rrrp{6.2cm}", ["case", "N", "slope", "finest error",
                                                   "its time [s]", "error measured"], table,
                         caption="Work-precision slopes: least-squares over three or more points; over two "
                                 "points (\\emph{two-point}) the slope of the line through them, no fit and no "
                                 "estimate of its uncertainty."))
    fluid = [c for c in cases if _body_case(c[0]) is None]
    if fluid:
        # at most three panels a row: each wide enough for its tick labels and grid labels at 7 pt
        ncol = min(3, len(fluid))
        nrow = -(-len(fluid) // ncol)
        fig, axes = plt.subplots(nrow, ncol, figsize=(2.4 * ncol, 2.4 * nrow), squeeze=False)
        for ax in axes.flat[len(fluid):]:
            ax.set_visible(False)
        for ax, (name, pts, slope) in zip(axes.flat, fluid):
            t, e = [p[0] for p in pts], [p[1] for p in pts]
            ax.loglog(t, e, "o-", ms=4)
            # grid labels above-left of ibms's points, below-right of Basilisk's (B64, B128 beside
            # ibms's 64, 128 do not overlap), all inside the axes (margins)
            for p in pts:
                ax.annotate(p[2], (p[0], p[1]), fontsize=7, xytext=(-4, 4), textcoords="offset points",
                            ha="right", va="bottom")
            lt, le = [math.log(v) for v in t], [math.log(v) for v in e]
            mx, my = sum(lt) / len(lt), sum(le) / len(le)
            ax.loglog(t, [math.exp(my + slope * (math.log(v) - mx)) for v in t], "k--", lw=0.8,
                      label=("two-point slope %.2f" if len(pts) == 2 else "slope %.2f") % slope)
            for k, (re_number, n, seconds, error) in enumerate(_basilisk_points(source, name)):
                ax.loglog([seconds], [error], "s", color="C3", ms=5, label="Basilisk (B$N$)" if k == 0 else None)
                ax.annotate("B%s" % n, (seconds, error), fontsize=7, xytext=(4, -4), textcoords="offset points",
                            ha="left", va="top")
            ax.margins(x=0.25, y=0.25)
            ax.set_title(name)
            ax.set_xlabel("wall time [s]")
            ax.set_ylabel("error")
            ax.legend(loc="best", fontsize=7)
        path = os.path.join(fig_dir, "work_precision.pdf")
        fig.tight_layout()
        figs.save(fig, path)
        out.append(figure(path, "Error against wall time; labels: grid N; dashed: least-squares fit (a two-point slope "
                                "where a case has two points). Squares (B$N$): Basilisk %s on the same cavity and error rule, one core of this machine, "
                                "recorded 2026-12-03 (\\texttt{bench/reference/basilisk\\_cavity.csv}; "
                                "both codes stopped at a velocity change rate of $10^{-6}$)." % report_cases.cite("popinet_basilisk")))
    body_work_precision(out, build, fig_dir, source, [c for c in cases if _body_case(c[0]) is not None])


def _reference_text(source, family):
    """The published value and bounds of a DFG family's error, as its case's reference file states them."""
    import report_cases
    _, case, filename, quantity = _BODY_FAMILIES[family]
    ref = report_cases.read_reference(source, case, filename) if source else {}
    row = ref.get(quantity, {})
    value, lower, upper = (_float(row.get(k)) for k in ("value", "lower", "upper"))
    if family == "dfg_2d1":
        return ("$|c_D/%s - 1|$ against the value of John \\& Matthies %s (the published bounds %s--%s of "
                "Sch\\\"afer \\& Turek %s)" % (num(value, 6), report_cases.cite("john2001"), num(lower), num(upper),
                                               report_cases.cite("schafer1996")))
    return ("$|\\max c_D/%s - 1|$ over $t \\in [8, 12]$ against the midpoint of the published bounds %s--%s of "
            "Sch\\\"afer \\& Turek %s" % (num(value), num(lower), num(upper), report_cases.cite("schafer1996")))


def body_work_precision(out, build, fig_dir, source, cases):
    """The DFG cylinders under both couplings (bench_work_precision's dfg_* cases): one panel per case,
    one curve per coupling; the time to 3 % on 2D-2's max c_D as the bench wrote it."""
    if not cases:
        return
    out.append(r"\subsection{Bodies: the DFG cylinders under both immersed-boundary couplings}\label{sec:wp-bodies}")
    out.append("The cylinder of the DFG benchmarks at $D/h = 10$ and 20 (the bench's default level; 30 and 40 at its "
               "\\texttt{full} level) (labels; \\texttt{validation/dfg\\_cylinder\\_2d1} "
               "and \\texttt{\\_2d2}, each scene's grid refined as its CMakeLists does) under the papers' direct forcing "
               "%s (\\texttt{uhlmann}: 3 passes, markers retracted by $0.25h$, $\\nu\\Delta t/h^2 \\le 0.2$, as the 2D-1 "
               "case calibrated it) and under the no-slip coupling on the face velocities (\\texttt{no\\_slip}: slip tolerance "
               "$10^{-4}$, markers retracted by $0.3h$, as both scenes ship it; docs/method.md \\S3.7). 2D-1 runs to the steady "
               "criterion under \\texttt{uhlmann} and to $t = 10$ under \\texttt{no\\_slip}, 2D-2 to $t = 12$; the no-slip "
               "coupling is the end-of-step constraint of Taira \\& Colonius %s. These are not the validation runs: "
               "the bench runs its own grids ($D/h = 10$ and 20 here) with the case scenes' \\texttt{no\\_slip} settings, "
               "while the cases' lines (\\S\\ref{sec:checks}) come from the validation runs; and the figures the case READMEs "
               "state (quoted in Known limitations, e.g.\\ the excess of max $c_D$ under the papers' coupling) "
               "come from the READMEs' own runs and settings, not from these.\n" % (report_cases.cite("uhlmann2005"),
                                                                                report_cases.cite("taira2007")))
    families = [f for f in _BODY_FAMILIES if any(_body_case(c[0])[0] == f for c in cases)]
    fig, axes = plt.subplots(1, len(families), figsize=(3.6 * len(families), 3.0), squeeze=False)
    for ax, family in zip(axes[0], families):
        for name, pts, slope in sorted(cases, key=lambda c: list(_COUPLINGS).index(_body_case(c[0])[1])):
            fam, coupling = _body_case(name)
            if fam != family:
                continue
            legend, style, colour = _COUPLINGS[coupling]
            ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, color=colour, ms=4,
                      label=("%s, two-point slope %.2f" if len(pts) == 2 else "%s, slope %.2f") % (legend, slope))
            for p in pts:
                ax.annotate(p[2], (p[0], p[1]), fontsize=7, xytext=(3, 3), textcoords="offset points")
        if family == "dfg_2d2":
            ax.axhline(0.03, color="0.4", ls=":", lw=0.8, label="3 %")
        ax.set_title(_BODY_FAMILIES[family][0], fontsize=9)
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel("error")
        ax.margins(x=0.2, y=0.2)
        # below the panel, outside the axes: the curves and their labels fill the panel's corners
        ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.3), fontsize=7, frameon=False)
    path = os.path.join(fig_dir, "work_precision_bodies.pdf")
    fig.tight_layout()
    figs.save(fig, path)
    caption = "; ".join("%s: %s" % (_BODY_FAMILIES[f][0], _reference_text(source, f)) for f in families)
    out.append(figure(path, "Error (its absolute value) against wall time of the DFG cylinders, both couplings "
                      "(labels: $D/h$). " +
                      caption + "; dotted: 3\\,\\%."))
    rows = _rows(os.path.join(build, "bench", "time_to_target_dfg_2d2.csv"))
    if rows:
        get = {r["what"]: r for r in rows}
        said = {"=": "", ">": "more than ", "<=": "at most "}

        def seconds(r):
            text = "%s%s\\,s" % (said.get(r["relation"], ""), num(r["seconds"], 4))
            if r["relation"] == ">":
                text += " (not reached: smallest error %s)" % num(r["smallest_error"], 3)
            return text
        if all(k in get for k in ("uhlmann", "no_slip", "ratio")):
            ratio = get["ratio"]
            ratio_text = ("undefined" if ratio["relation"] == "undefined" else
                          "%s%s" % ({"=": "", ">": "$>$ ", "<=": "$\\le$ "}[ratio["relation"]], num(ratio["seconds"], 3)))
            out.append("Wall time to 3\\,\\%% on DFG 2D-2's max $c_D$ (log-log interpolation between the two runs "
                       "that bracket it, \\texttt{bench/time\\_to\\_target\\_dfg\\_2d2.csv}): \\texttt{uhlmann} %s, "
                       "\\texttt{no\\_slip} %s; ratio %s.\n" % (seconds(get["uhlmann"]), seconds(get["no_slip"]),
                                                               ratio_text))


def _legend_above(fig, axes):
    """One legend for all panels, above them (a legend inside a map covers its points)."""
    handles, labels = [], []
    for ax in axes:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            if lab not in labels:
                handles.append(h)
                labels.append(lab)
    if labels:
        fig.legend(handles, labels, loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=len(labels),
                   fontsize=7, frameon=False)


_SYMBOL = {"stable": ("o", "tab:green"), "unstable": ("^", "tab:orange"), "blow-up": ("x", "tab:red"),
           "too-deep": ("s", "tab:purple")}


def stability_section(out, build, fig_dir):
    out.append(r"\section{Stability maps}")
    all_files = sorted(glob.glob(os.path.join(build, "bench", "stability_*.csv")))
    files = [f for f in all_files if not os.path.basename(f).startswith("stability_fluid_")]
    fluid_files = [f for f in all_files if f not in files]
    if not files:
        out.append(r"\emph{Not run: no \texttt{bench/stability\_*.csv} (run "
                   r"\texttt{bench/bench\_stability}).}" + "\n")
        fluid_stability_maps(out, fluid_files, fig_dir)
        return
    out.append("From \\texttt{bench/bench\\_stability}: fluid time step against spring or DEM "
               "stiffness, with the solid sub-stepped automatically (docs/method.md \\S5.3) or advanced "
               "once per fluid step (fixed). Circles: stable; triangles: unstable (rim area changed "
               "by more than 50\\,\\%, or a body point faster than twice the initial approach speed, "
               "and the run reached its end: the solver did not stop it); "
               "crosses: stopped by the solver's blow-up check with its message (after crossing a bound, if it did); "
               "squares: stopped because a contact overlap exceeded the contact-sphere radius (a contact too "
               "soft for its spheres at this approach speed: the model's limit, not counted as an instability). "
               "The bench's source states each scene.\n")
    table = []
    for f in files:
        rows = _rows(f) or []
        name = os.path.basename(f)[len("stability_"):-len(".csv")]
        if not rows:
            continue
        fig, axes = plt.subplots(1, 2, figsize=(6.4, 2.6), sharey=True)
        for ax, mode in zip(axes, ("auto", "fixed")):
            for kind, (marker, colour) in _SYMBOL.items():
                pts = [(_float(r["dt"]), _float(r["stiffness"])) for r in rows
                       if r["mode"] == mode and r["outcome"] == kind]
                if pts:
                    ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker, color=colour,
                              ms=6, ls="none", label=kind)
            ax.set_title("%s: %s solid steps" % (name, mode))
            ax.set_xlabel("fluid dt [s]")
        _legend_above(fig, axes)
        # the stiffness and its unit as the bench's '#' line names them ("against contact_stiffness
        # [dyn/cm^2 per unit depth]")
        found = next((m for c in _comments(f) for m in [re.search(r"against (\w+)(?: \[([^\]]*)\])?", c)] if m), None)
        quantity = found.group(1).replace("_", " ") if found else "stiffness"
        unit = found.group(2) if found and found.group(2) else "unit not recorded"
        axes[0].set_ylabel("%s\n[%s]" % (quantity, unit.replace("^2", "$^2$")), fontsize=8)
        path = os.path.join(fig_dir, "stability_%s.pdf" % name)
        fig.tight_layout()
        figs.save(fig, path)
        out.append(figure(path, "Stability map \\texttt{%s} (\\texttt{bench/stability\\_%s.csv})." %
                          (esc(name), esc(name)), height=0.3))
        for mode in ("auto", "fixed"):
            sel = [r for r in rows if r["mode"] == mode]
            count = lambda k: sum(r["outcome"] == k for r in sel)  # noqa: E731
            subs = [int(_float(r["substeps"])) for r in sel if not math.isnan(_float(r["substeps"]))]
            table.append([r"\texttt{%s}" % esc(name), mode, str(len(sel)), str(count("stable")),
                          str(count("unstable")), str(count("blow-up")), str(count("too-deep")),
                          str(max(subs)) if subs else "--"])
        blow = next((r["message"] for r in rows if r["outcome"] == "blow-up" and r["message"]), None)
        if blow:
            out.append(r"{\raggedright\noindent Example stop message (in full): \texttt{%s}\par}" % esc(blow) + "\n")
    out.append(longtable(r"llrrrrrr", ["map", "solid steps", "runs", "stable", "unstable", "blow-up",
                                       "too deep", "max sub-steps"], table, caption="Stability map summary."))
    fluid_stability_maps(out, fluid_files, fig_dir)


_FLUID_SYMBOL = {"stable": ("o", "tab:green"), "unstable": ("^", "tab:orange"), "stopped": ("x", "tab:red")}


def fluid_measured_limits(rows, mode="no_cfl_guard"):
    """Per cell Reynolds number of one fluid map: the largest CFL number stable together with every
    smaller one, the smallest CFL number that is not stable (None if all are), and the measured
    CFL number dt max(|u|/dx + |v|/dy) of that largest stable run. Rows as read by _rows."""
    limits = OrderedDict()
    by_re = OrderedDict()
    for r in rows:
        if r["mode"] == mode:
            by_re.setdefault(_float(r["cell_reynolds"]), []).append(r)
    for re_h in sorted(by_re):
        points = sorted(by_re[re_h], key=lambda r: _float(r["cfl"]))
        stable, first_bad, measured = None, None, None
        for r in points:
            if r["outcome"] != "stable":
                first_bad = _float(r["cfl"])
                break
            stable, measured = _float(r["cfl"]), _float(r["max_cfl_measured"])
        limits[re_h] = (stable, first_bad, measured)
    return limits


SEED_TO_BOUND = 2e16  # a mode seeded at round-off (1e-16 U) grows this much to reach the map's 2 U bound


def fluid_above_line_text(rows, name, theory):
    """What the runs marked stable above the von Neumann line show against the analysis, from the
    map's rows: how many, their steps, the analysed growth per step at the map's CFL number (the
    CSV's theory_max_g) and at the run's own largest measured CFL number, and how many ran long
    enough for that growth to take a round-off seed past the 2 U bound. None when no such run."""
    stable = [r for r in rows if r["outcome"] == "stable"]
    above = [r for r in stable if _float(r["theory_max_g"]) > 1 + 1e-12]
    if not above:
        return None
    steps = [int(_float(r["steps"])) for r in above]
    growth_nominal = [_float(r["theory_max_g"]) for r in above]
    growth_measured = [theory.max_amplification(_float(r["max_cfl_measured"]), _float(r["viscous_number"]))
                       for r in above]
    limit = math.log(SEED_TO_BOUND)
    long_nominal = sum(n * math.log(g) > limit for n, g in zip(steps, growth_nominal))
    still = [(n, g) for n, g in zip(steps, growth_measured) if g > 1 + 1e-12]
    long_measured = sum(n * math.log(g) > limit for n, g in still)
    speeds = [_float(r["max_speed"]) for r in above]
    ratio = [_float(r["max_cfl_measured"]) / _float(r["cfl"]) for r in above]
    late = [_float(r["late_energy_ratio"]) for r in above]
    why = ("the velocity reaches $U$ only in the cell row under the lid, where a mode is carried out and damped "
           "by the wall" if name.startswith("cavity")
           else "the layers' velocity changes sign across the shear layers and decays by viscosity")
    return ("%d of the %d runs marked stable in \\texttt{%s} (of %d runs, both guard modes) lie above the von Neumann "
            "line. The line is the analysis of this scheme (AB2 convection, Crank--Nicolson diffusion, central "
            "differences) for one uniform velocity in a periodic box, which the solver reproduces there to 1e-9 "
            "(\\texttt{test\\_time\\_scheme\\_stability}, docs/fluid-stability.md); its growth per step is taken "
            "at the map's $C = U\\Delta t/h$ and the run's viscous number. These runs ran %d to %d steps (to "
            "$t = 10\\,L/U$) with an analysed growth of up to %s per step; %d of them ran long enough for that growth to "
            "take a mode seeded at round-off ($10^{-16}U$) past the map's $2U$ bound. At each run's own largest measured "
            "CFL number ($%s$ to $%s$ times the map's) %d of the %d stay above the line, %d of them long enough. None "
            "crossed a bound (largest velocity component $%s$ to $%s\\,U$; energy at the end over half-way: %s to %s), "
            "so the analysed mode does not grow in these flows at its analysed rate: %s. The runs too short for the "
            "growth to show (%d at the map's $C$) are no evidence either way; stable above the line does not "
            "contradict the analysis for a uniform velocity, unstable below it would.\n" %
            (len(above), len(stable), esc(name), len(rows), min(steps), max(steps), num(max(growth_nominal), 4),
             long_nominal, num(min(ratio), 2), num(max(ratio), 2), len(still), len(above), long_measured,
             num(min(speeds), 3), num(max(speeds), 3), num(min(late), 3), num(max(late), 3), why,
             len(above) - long_nominal))


def fluid_cfl_overshoot_text(rows, name):
    """Why an adaptive map's measured CFL number exceeds its run.cfl: the measured number is the step's
    dt times max(|u|/dx + |v|/dy) of the velocity at the end of the step, the rule's dt comes from the
    velocity at its start. None for fixed-step maps or when no run exceeds its run.cfl by 1 %."""
    if "adaptive" not in name:
        return None
    sel = [r for r in rows if r["mode"] == "no_cfl_guard" and r["outcome"] == "stable"]
    over = [r for r in sel if _float(r["max_cfl_measured"]) > 1.01 * _float(r["cfl"])]
    if not over:
        return None
    worst = max(over, key=lambda r: _float(r["max_cfl_measured"]) / _float(r["cfl"]))
    first_step = sum(int(_float(r["first_above_cfl_1"])) == 1 for r in over)
    return ("The measured CFL number is the step's $\\Delta t$ times $\\max(|u|/\\Delta x + |v|/\\Delta y)$ of the "
            "velocity at the \\emph{end} of that step, while the adaptive rule sets $\\Delta t$ from the velocity at "
            "its start%s. Where the velocity grows within a step the measured number exceeds "
            "\\texttt{run.cfl}: %d of the %d stable runs without the guard, largest at \\texttt{run.cfl} = %s, "
            "$\\mathrm{Re}_h = %s$ (measured %s, above 1 from step %s, %s; largest velocity "
            "component %s\\,$U$); %d of the %d cross 1 in their first step.\n" %
            (" (from rest: the lid speed; the first step's velocity overshoots it)" if name.startswith("cavity") else "",
             len(over), len(sel), num(_float(worst["cfl"])),
             num(_float(worst["cell_reynolds"])), num(_float(worst["max_cfl_measured"]), 3),
             worst["first_above_cfl_1"], "above 2 from step %s" % worst["first_above_cfl_2"]
             if int(_float(worst["first_above_cfl_2"])) >= 0 else "never above 2",
             num(_float(worst["max_speed"]), 3), first_step, len(over)))


def fluid_stability_maps(out, files, fig_dir):
    """The fluid's maps (bench/bench_fluid_stability: BUILD/bench/stability_fluid_<case>.csv): CFL
    number against cell Reynolds number, with the von Neumann limit of AB2 + CN (central
    differences) from fluid_stability_theory.py, the analysis of docs/fluid-stability.md."""
    if not files:
        return
    import fluid_stability_theory as theory  # numpy; only needed when there are fluid maps
    out.append(r"\subsection{Fluid: CFL number against cell Reynolds number}")
    out.append("From \\texttt{bench/bench\\_fluid\\_stability} (docs/fluid-stability.md): fixed time step, "
               "$C = U\\Delta t/h$ against $\\mathrm{Re}_h = Uh/\\nu$ (viscous number "
               "$\\nu\\Delta t/h^2 = C/\\mathrm{Re}_h$). Left: the default blow-up guard "
               "(\\texttt{run.max\\_cfl}) and the non-finite check; right: the non-finite check only. "
               "Maps named \\texttt{\\_adaptive}: the adaptive step at that \\texttt{run.cfl}. "
               "Circles: stable (finite, no velocity component above $2U$, kinetic energy within the bound the "
               "file states); triangles: unstable (a bound crossed, no check stopped the run); crosses: stopped by "
               "the solver's check. Line: von Neumann limit of AB2 convection + Crank--Nicolson diffusion for a "
               "constant velocity $U$, stable below it.\n")
    cfl_axis = [0.05 + 0.01 * k for k in range(196)]
    boundary = theory.stability_boundary(cfl_axis)
    table = []
    for f in files:
        rows = _rows(f) or []
        if not rows:
            continue
        name = os.path.basename(f)[len("stability_fluid_"):-len(".csv")]
        modes = [m for m in ("default_guard", "no_cfl_guard") if any(r["mode"] == m for r in rows)]
        fig, axes = plt.subplots(1, len(modes), figsize=(3.3 * len(modes), 2.8), sharey=True, squeeze=False)
        for ax, mode in zip(axes[0], modes):
            for kind, (marker, colour) in _FLUID_SYMBOL.items():
                pts = [(_float(r["cfl"]), _float(r["cell_reynolds"])) for r in rows
                       if r["mode"] == mode and r["outcome"] == kind]
                if pts:
                    ax.plot([p[0] for p in pts], [p[1] for p in pts], marker, color=colour, ms=5, ls="none",
                            label=kind)
            ax.plot([b[0] for b in boundary], [b[1] for b in boundary], "k-", lw=0.8, label="von Neumann")
            ax.set_yscale("log")
            ax.set_xlim(0.0, max(_float(r["cfl"]) for r in rows) * 1.05)
            ax.set_ylim(min(_float(r["cell_reynolds"]) for r in rows) / 1.5,
                        max(_float(r["cell_reynolds"]) for r in rows) * 1.5)
            ax.set_title("%s: %s" % (name, mode.replace("_", " ")), fontsize=8)
            ax.set_xlabel("run.cfl (adaptive $\\Delta t$)" if "adaptive" in name else "CFL number $U\\Delta t/h$")
        axes[0][0].set_ylabel("$\\mathrm{Re}_h = Uh/\\nu$")
        _legend_above(fig, axes[0])
        path = os.path.join(fig_dir, "stability_fluid_%s.pdf" % name)
        fig.tight_layout()
        figs.save(fig, path)
        out.append(r"{\small %s.}" % md_text("; ".join(_comments(f))) + "\n")
        out.append(figure(path, "Fluid stability map \\texttt{%s} (\\texttt{bench/stability\\_fluid\\_%s.csv})." %
                          (esc(name), esc(name)), height=0.3))
        for mode in modes:
            sel = [r for r in rows if r["mode"] == mode]
            count = lambda k: sum(r["outcome"] == k for r in sel)  # noqa: E731
            theory_unstable = sum(_float(r["theory_max_g"]) > 1 + 1e-12 for r in sel)
            table.append([r"\texttt{%s}" % esc(name), esc(mode.replace("_", " ")), str(len(sel)),
                          str(count("stable")), str(count("unstable")), str(count("stopped")), str(theory_unstable)])
        text = fluid_above_line_text(rows, name, theory)
        if text:
            out.append(text)
        limits = fluid_measured_limits(rows)
        out.append(longtable("rrrrr", ["$\\mathrm{Re}_h$", "largest stable", "(its measured CFL)", "first not stable",
                                       "von Neumann limit"],
                             [[num(re_h, 4), num(lim[0], 3) if lim[0] is not None else "--",
                               num(lim[2], 3) if lim[2] is not None else "--",
                               num(lim[1], 3) if lim[1] is not None else "--", num(theory.cfl_limit(re_h), 3)]
                              for re_h, lim in limits.items()],
                             caption="\\texttt{%s} without the CFL guard: CFL numbers of the map (largest stable with "
                                     "every smaller one stable), the measured CFL number "
                                     "$\\Delta t\\max(|u|/\\Delta x + |v|/\\Delta y)$ of that run, and the "
                                     "von Neumann limit at the same $\\mathrm{Re}_h$." % esc(name)))
        text = fluid_cfl_overshoot_text(rows, name)
        if text:
            out.append(text)
        stop = next((r["message"] for r in rows if r["outcome"] == "stopped" and r["message"]), None)
        if stop:
            out.append(r"{\raggedright\noindent Example stop message (in full): \texttt{%s}\par}" % esc(stop) + "\n")
    out.append(longtable(r"llrrrrr", ["map", "mode", "points", "stable", "unstable", "stopped",
                                      "von Neumann unstable"], table, caption="Fluid stability map summary."))


def overhead_section(out, build):
    rows = _bench_section(out, build, "A scene pays only for what it uses", "overhead.csv",
                          r"Not run: no \texttt{bench/overhead.csv} (run \texttt{bench/bench\_overhead}).")
    if not rows:
        return
    get = {(r["scene"], r["stage"]): r for r in rows}
    ratio = get.get(("fluid_only_cavity_128", "ratio"))
    if ratio:
        sim = get[("fluid_only_cavity_128", "simulation_step")]["calls"]
        bare = get[("fluid_only_cavity_128", "bare_fluid_solver_step")]["calls"]
        out.append("Fluid-only lid-driven cavity ($128^2$, same $\\Delta t$): %s s per step through "
                   "the Simulation pipeline, %s s with the bare FluidSolver (predictor and projection), "
                   "ratio %s (best of five interleaved repeats; \\texttt{bench/bench\\_overhead}).\n" %
                   (num(sim), num(bare), num(ratio["calls"], 3)))
    scenes = OrderedDict()
    for r in rows:
        if r["seconds_per_step"]:
            scenes.setdefault(r["scene"], OrderedDict())[r["stage"]] = r
    if not scenes:
        return
    stages = list(next(iter(scenes.values())))
    table = []
    for stage in stages:  # one row per stage, one column per scene: stays narrow
        cells = []
        for per_stage in scenes.values():
            r = per_stage.get(stage)
            cells.append("%s (%s)" % (num(r["seconds_per_step"], 2), r["calls"]) if r else "--")
        table.append([esc(stage)] + cells)
    table.append(["CDS pair checks (run)"] +
                 [get.get((scene, "pair_checks_total"), {}).get("calls", "--") for scene in scenes])
    out.append(longtable("l" + "p{3.3cm}" * len(scenes), ["stage"] + [esc(s.replace("_", " ")) for s in scenes],
                         table,
                         caption="Seconds per step by stage (calls) from the solver's stage timers; "
                                 "\\emph{contacts} runs inside \\emph{bodies}, once per sub-step. "
                                 "The one-body scene evaluates wall contacts but examines no CDS pair."))


def scale_section(out, build, fig_dir):
    """Cost against the number of bodies (BUILD/bench/scale.csv, bench_scale --report): each stage's
    ms per step against N for rigid disks and wheels, the least-squares exponents, the ratios to the
    fluid stages at 1024 bodies and in the beds, against ibms's own cost targets (bench/README.md)."""
    rows = _bench_section(out, build, "Cost against the number of bodies", "scale.csv",
                          r"Not run at this level: no \texttt{bench/scale.csv} (run \texttt{bench/bench\_scale "
                          r"--report DIR}); \texttt{bench/README.md} gives the figures.")
    if not rows:
        return
    stages = [("fluid", "fluid stages"), ("ib", "immersed boundary"), ("bodies_stage", "bodies (with contacts)"),
              ("output", "output"), ("run", "whole step")]
    def ratio(a, b):
        return num(a / b, 3) if a > 0 and b > 0 else "--"

    def slope(x, y):
        return num(log_log_slope(x, y), 3) if len(x) > 1 and all(v > 0 for v in x + y) else "--"

    spread = OrderedDict()
    for r in rows:
        if r["set"] == "spread":
            spread.setdefault(r["kind"], []).append(r)
    steps = sorted({r["steps"] for r in rows})
    out.append("From \\texttt{bench/bench\\_scale --report} (\\texttt{bench/README.md}): $n\\times n$ bodies settling "
               "in a closed box whose grid grows with them (1.6 $D$ per body and direction, $D/h = 16$, 50 rim points, "
               "the papers' contacts $k_{Dn} = 10^7$ with contact spheres on the rim points, the papers' coupling, "
               "series every 10 steps, the final snapshot and checkpoint), %s steps on one thread, each stage's "
               "time from the solver's own timers; the beds start with their bodies in touch. These are ibms's "
               "measurements against its own cost targets, not a validation.\n" % ", ".join(steps))
    if spread:
        fig, axes = plt.subplots(1, len(spread), figsize=(3.3 * len(spread), 2.9), squeeze=False)
        table = []
        for ax, (kind, rs) in zip(axes.flat, spread.items()):
            n = [_float(r["bodies"]) for r in rs]
            for key, label in stages:
                y = [_float(r[key]) for r in rs]
                if len(y) > 1 and all(v > 0 for v in n + y):
                    ax.loglog(n, y, "o-", ms=3, label="%s ($N^{%.2f}$)" % (label, log_log_slope(n, y)))
            ax.set_title({"rigid": "rigid disks", "wheel": "mass-spring wheels"}.get(kind, kind), fontsize=9)
            ax.set_xlabel("bodies $N$", fontsize=8)
            ax.set_ylabel("ms per step", fontsize=8)
            ax.tick_params(labelsize=7)
            ax.legend(fontsize=7, loc="upper left")
            last = rs[-1]
            fluid = _float(last["fluid"])
            table.append([esc(kind), last["bodies"], ratio(_float(last["run"]), fluid),
                          ratio(_float(last["bodies_stage"]), fluid), ratio(_float(last["output"]), fluid),
                          slope(n, [_float(r["run"]) for r in rs]), slope(n, [_float(r["fluid"]) for r in rs])])
        path = os.path.join(fig_dir, "scale.pdf")
        fig.tight_layout()
        figs.save(fig, path)
        out.append(figure(path, "Milliseconds per step of each stage against the number of bodies (16 to 1024, the "
                                "cells growing like $N$); legend: the least-squares exponent of each stage."))
        out.append(longtable("lrrrrrr", ["kind", "bodies", "run / fluid", "bodies / fluid", "output / fluid",
                                         "exponent (run)", "exponent (fluid)"], table,
                             caption="The largest run of each kind against the fluid stages, and the exponents of "
                                     "cost per step against $N$ over all sizes. Targets (ibms's own): the whole "
                                     "run of 1024 rigid disks $\\le 2\\times$ the fluid stages, the bodies stage "
                                     "$\\le 0.5\\times$ (rigid) and $\\le 1\\times$ (wheels), exponent "
                                     "$\\le 1.1$."))
    beds = [r for r in rows if r["set"].startswith("bed")]
    if beds:
        names = {"bed": "papers' law ($k_{Dn} = 10^7$)",
                 "bed_outer_step_0.5": "papers' law, outer step 1/2",
                 "bed_collision_time": "collision-time law (10 fluid steps)"}
        table = [[names.get(r["set"], esc(r["set"])), esc(r["kind"]), r["bodies"],
                  num(_float(r["fluid"]), 3), num(_float(r["bodies_stage"]), 3), num(_float(r["contacts"]), 3),
                  ratio(_float(r["bodies_stage"]), _float(r["fluid"]))] for r in beds]
        out.append(longtable("p{5.2cm}lrrrrr", ["contacts", "kind", "bodies", "fluid [ms]", "bodies [ms]",
                                                "contacts [ms]", "bodies / fluid"], table,
                             caption="Beds: bodies started in touch, settling under gravity. Target (ibms's "
                                     "own): the bodies stage $\\le 3\\times$ the fluid stages at the papers' "
                                     "stiffness. The wheels' outer step (\\texttt{contact.outer\\_step\\_fraction}, docs/method.md "
                                     "\\S5.4) defaults to 1/16 of their springs' sub-step, which elastic impacts need; "
                                     "these damped contacts ($e_D = 0.5$) keep their result at 1/2."))


def forcing_passes_text(couette, disk):
    """What the forcing-passes tables show, from their rows: the coupling, and how the rim slip and the
    errors change from the fewest to the most passes at the coarsest and finest grid."""
    text = ("Both tables run the papers' coupling, the direct forcing of Uhlmann %s repeated over "
            "\\texttt{ibm.forcing\\_passes} passes (multi-direct forcing, Luo et al.\\ 2007; "
            "\\texttt{bench/bench\\_forcing\\_passes}: \\texttt{ibm.coupling = \\textquotedbl{}uhlmann\\textquotedbl{}}, "
            "no marker retraction), not the end-of-step \\texttt{no\\_slip} coupling the settling and DFG scenes "
            "ship; the papers' coupling has no slip tolerance. Their rim slip is the slip of the cell-centred "
            "velocity interpolated at the markers after the step." % report_cases.cite("uhlmann2005"))

    def by(rows, passes, res):
        return next((r for r in rows if _float(r["passes"]) == passes and _float(r["cells_per_diameter"]) == res), None)

    for rows, name in ((couette, "couette"), (disk, "disk")):
        passes = sorted({_float(r["passes"]) for r in rows})
        grids = sorted({_float(r["cells_per_diameter"]) for r in rows})
        if len(passes) < 2 or not grids:
            continue
        lo, hi = passes[0], passes[-1]
        parts = []
        for res in (grids[0], grids[-1]) if len(grids) > 1 else (grids[0],):
            a, b = by(rows, lo, res), by(rows, hi, res)
            if not a or not b:
                continue
            if name == "couette":
                parts.append("at $D_1/h = %s$ the rim slip falls from %s to %s (%s times lower) while the L2 "
                             "error rises from %s to %s (%s times higher)" %
                             (num(res, 3), num(_float(a["rim_slip"]), 3), num(_float(b["rim_slip"]), 3),
                              num(_float(a["rim_slip"]) / _float(b["rim_slip"]), 2),
                              num(_float(a["l2_error_or_speed_deviation"]), 3),
                              num(_float(b["l2_error_or_speed_deviation"]), 3),
                              num(_float(b["l2_error_or_speed_deviation"]) / _float(a["l2_error_or_speed_deviation"]), 2)))
            else:
                parts.append("at $D/h = %s$ the rim slip / speed falls from %s to %s and the maximum speed from "
                             "%s to %s cm/s" %
                             (num(res, 4), num(_float(a["rim_slip"]), 3), num(_float(b["rim_slip"]), 3),
                              num(_float(a["max_error_or_max_speed"]), 5), num(_float(b["max_error_or_max_speed"]), 5)))
        if not parts:
            continue
        if name == "couette":
            text += (" On the circular Couette flow, from %d to %d passes, %s. More passes hold the cells at "
                     "the markers closer to the rim speed, but through kernels three cells wide they impose it "
                     "on a band about a cell wide: the cylinder acts larger than its rim (the effective radius "
                     "grows by 0.03$h$ with one pass and 0.25$h$ with three, \\texttt{bench/README.md}, "
                     "\\texttt{bench\\_forcing\\_passes radius}, not run by this build), so the flow in the "
                     "annulus is further from the exact one." % (lo, hi, "; ".join(parts)))
        else:
            text += (" On the rigid settling disk, from %d to %d passes, %s: the disk acting larger settles "
                     "more slowly." % (lo, hi, "; ".join(parts)))
    return text + "\n"


def forcing_passes_section(out, build, source):
    """Multi-direct forcing study (BUILD/bench/forcing_passes.csv, bench/bench_forcing_passes); the
    disk's speeds against the settling case's Glowinski et al. value (its reference file)."""
    rows = _bench_section(out, build, "Multi-direct forcing passes", "forcing_passes.csv",
                          r"Not run: no \texttt{bench/forcing\_passes.csv} (run \texttt{bench/bench\_forcing\_passes}).")
    if not rows:
        return
    couette = [r for r in rows if r["case"] == "couette"]
    disk = [r for r in rows if r["case"] != "couette"]
    out.append(forcing_passes_text(couette, disk))
    if couette:
        out.append(longtable("rrrrrr", ["passes", "$D_1/h$", "L2 error", "max error", "rim slip", "ms/step"],
                             [[r["passes"], num(r["cells_per_diameter"], 3), num(r["l2_error_or_speed_deviation"], 3),
                               num(r["max_error_or_max_speed"], 3), num(r["rim_slip"], 3), num(r["ms_per_step"], 3)]
                              for r in couette],
                             caption="Circular Couette flow between prescribed cylinders ($\\nu\\Delta t/h^2 = 0.5$) "
                                     "under the papers' coupling with 1 to 5 forcing passes: "
                                     "velocity errors in the annulus and the largest $|U - J u|$ at the markers "
                                     "($u$ the cell-centred velocity after the step), relative to the inner rim speed."))
    if disk:
        import report_cases
        ref = report_cases.read_reference(source, "settling_disk", "settling_disk_rho1.25.csv")
        value = ref.get("max_settling_speed_glowinski", {}).get("value", math.nan)
        out.append(longtable("rrrrrr", ["passes", "$D/h$", "max speed", "vs %s" % num(value), "rim slip / speed",
                                        "ms/step"],
                             [[r["passes"], num(r["cells_per_diameter"], 4), num(r["max_error_or_max_speed"], 5),
                               "%+.2f\\,\\%%" % (100 * _float(r["l2_error_or_speed_deviation"])),
                               num(r["rim_slip"], 3), num(r["ms_per_step"], 3)] for r in disk],
                             caption="Rigid settling disk ($\\nu\\Delta t/h^2 \\le 0.25$) under the papers' coupling "
                                     "(\\texttt{bench\\_forcing\\_passes} sets \\texttt{ibm.coupling = \\textquotedbl{}uhlmann\\textquotedbl{}}, "
                                     "no marker retraction; the settling case's scene and its lines in \\S\\ref{sec:checks} use the "
                                     "end-of-step \\texttt{no\\_slip} coupling, so their speeds at the same $D/h$ "
                                     "differ): maximum settling speed "
                                     "[cm/s] against the maximum speed %s cm/s of Glowinski et al. %s (the deviation "
                                     "as the bench computed it), and the largest slip of the cell-centred velocity "
                                     "at the markers relative to the disk's speed (every 10th step while the speed "
                                     "exceeds 0.5 cm/s, to touchdown): the papers' coupling holds no slip tolerance." %
                                     (num(value), report_cases.cite("glowinski2001"))))


def run_times_section(out, tests, folders=(), not_cases=()):
    """Wall time per validation case: the sum of its ctest runs and check. A test belongs to the
    case folder its name starts with (`folders`: the longest such, so settling_disk_rigid_100_run
    goes with settling_disk), else to the name before its grid and run/check suffix
    (dfg_2d1_20_run -> dfg_2d1); unit tests (test_*, and `not_cases`: the tests the build labels
    unit or convergence, such as dfg_check_gates) are no case's, whatever their name holds
    (test_end_of_run_forces)."""
    cases = OrderedDict()
    for t in tests:
        # <case>[_<grid>]_run[_...], _check[_...], _gate[_...], _compare: one row per case, its grids together
        m = re.match(r"(.+?)(?:_\d+)?_(run(_\w+)?|check(_\w+)?|gate(_\w+)?|compare)$", t["name"])
        if not m or math.isnan(t["seconds"]) or t["name"].startswith("test_") or t["name"] in not_cases:
            continue
        owner = max((f for f in folders if t["name"].startswith(f + "_")), key=len, default=m.group(1))
        c = cases.setdefault(owner, [0.0, 0, True])
        c[0] += t["seconds"]
        c[1] += 1
        c[2] = c[2] and t["status"] == "pass"
    out.append(r"\subsection{Run time per validation case}")
    if not cases:
        out.append(r"\emph{No validation runs in the ctest logs.}" + "\n")
        return
    rows = [[r"\texttt{%s}" % esc(k), str(v[1]), num(v[0], 3), "all pass" if v[2] else "not all pass"]
            for k, v in cases.items()]
    out.append(longtable("lrrl", ["case", "ctest runs + check", "sum of times [s]", "status"], rows,
                         caption="Per-case sums of ctest wall times (runs of one case may run in parallel)."))
