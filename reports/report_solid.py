"""Report section on the solid and contact verification tables: the undamped
wheel's energy error against time per sub-step with its order table
(BUILD/verification_results/wheel_energy.csv and wheel_energy_history.csv, written by
test_wheel_energy), restitution measured against target (restitution.csv, written by
test_restitution and test_wheel_restitution), the e = 1 energy table (restitution_elastic.csv) and
the normal relative velocity and overlap through each contact (contact_history.csv). Reads files
only: the one arithmetic is the signed relative error (e_measured - e_target) / e_target for the
plot. The tests append; a rerun's rows replace the earlier ones (see each reader)."""
import csv
import math
import os
import textwrap
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402

import report_figures as figs  # noqa: E402
from report_latex import esc, md_text, mathtext, num, figure, longtable  # noqa: E402


def _rows(path, required):
    """Data rows of a CSV with one header line, as dicts; None if the file is absent or its header
    lacks one of the required columns (another version's file)."""
    if not os.path.isfile(path):
        return None
    with open(path, newline="", encoding="utf-8", errors="replace") as f:
        lines = [line for line in f if line.strip() and not line.startswith("#")]
    reader = csv.DictReader(lines)
    if not set(required) <= set(reader.fieldnames or []):
        return None
    return list(reader)


def _float(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


def _series(rows, key, x):
    """Rows grouped by key(row) into OrderedDict key -> list of rows in file order. A rerun
    appends again: where x does not increase, the series starts over (the last run wins)."""
    out = OrderedDict()
    for r in rows:
        k, v = key(r), _float(r.get(x))
        if not math.isfinite(v):
            continue
        s = out.get(k)
        if s is None or not s or not v > _float(s[-1].get(x)):
            out.pop(k, None)
            out[k] = s = []
        s.append(r)
    return out


def _not_run(out, files, writer):
    out.append(r"{\sloppy\emph{Not run: %s not found in \texttt{verification\_results/} (or "
               r"without the expected columns; written by %s under ctest, which sets "
               r"\texttt{IBMS\_RESULTS\_DIR}).}\par}" %
               (", ".join(r"\texttt{%s}" % esc(f) for f in files), writer) + "\n")


def solid_section(out, build, fig_dir):
    out.append(r"\section{Solid and contact verification: energy and restitution}")
    results = os.path.join(build, "verification_results")
    energy_subsection(out, results, fig_dir)
    restitution_subsection(out, results, fig_dir)
    contact_history_subsection(out, results, fig_dir)


def _energy_table(rows):
    """The last table of wheel_energy.csv: a row with an empty order starts a new one."""
    table = []
    for r in rows:
        if not (r.get("order") or "").strip():
            table = []
        table.append(r)
    return table


def energy_subsection(out, results, fig_dir):
    out.append(r"\subsection{Undamped wheel: energy error over 1000 periods}")
    table_rows = _rows(os.path.join(results, "wheel_energy.csv"),
                       ["dt", "steps_per_period", "omega_max_dt", "max_rel_error", "first_100T_max",
                        "last_100T_max", "bound", "order"])
    hist_rows = _rows(os.path.join(results, "wheel_energy_history.csv"),
                      ["dt", "periods", "max_rel_error_over_period"])
    if not table_rows and not hist_rows:
        _not_run(out, ["wheel_energy.csv", "wheel_energy_history.csv"], r"\texttt{test\_wheel\_energy}")
        return
    out.append("An undamped wheel ($N_l = 20$, $k = 10^3$) released from an elliptic deformation, "
               "integrated with symplectic Euler at three sub-steps for 1000 periods $T$ "
               "(\\texttt{verification/solid/test\\_wheel\\_energy.cpp}). Symplectic Euler "
               "conserves a modified energy $H + O(\\Delta t)$, so $|E - E_0|/E_0$ stays bounded "
               "(no drift: a flat envelope) and falls to first order in the sub-step. The test "
               "requires the maximum below the bound $\\omega_{\\max}\\Delta t / (1 - "
               "\\omega_{\\max}\\Delta t/2)$, the last 100 periods' maximum within 1.2 times the "
               "first 100 periods' and each observed order $\\ge 0.9$.\n")
    table = _energy_table(table_rows or [])
    if table:
        out.append(longtable(r"rrrrrrrr", ["$\\Delta t$", "steps/$T$", "$\\omega_{\\max}\\Delta t$",
                                           "max $|\\Delta E|/E_0$", "first 100 $T$", "last 100 $T$",
                                           "bound", "order"],
                             [[num(r["dt"], 3), num(r["steps_per_period"], 4), num(r["omega_max_dt"], 3),
                               num(r["max_rel_error"], 3), num(r["first_100T_max"], 3),
                               num(r["last_100T_max"], 3), num(r["bound"], 3), num(r["order"], 3)]
                              for r in table],
                             caption="Energy error per sub-step (\\texttt{wheel\\_energy.csv}); "
                                     "order: $\\log_2$ of the ratio of successive maxima."))
    else:
        out.append(r"\emph{No table: \texttt{wheel\_energy.csv} not found.}" + "\n")
    series = _series(hist_rows or [], lambda r: r["dt"], "periods")
    series = OrderedDict(sorted(series.items(), key=lambda kv: -_float(kv[0])))
    if not series:
        out.append(r"\emph{No history: \texttt{wheel\_energy\_history.csv} not found.}" + "\n")
        return
    fig, ax = plt.subplots(figsize=(6.4, 3.0))
    bounds = {_float(r["dt"]): _float(r["bound"]) for r in table}
    for k, (dt, rs) in enumerate(series.items()):
        colour = "C%d" % k
        t = [_float(r["periods"]) for r in rs]
        e = [_float(r["max_rel_error_over_period"]) for r in rs]
        steps = next((_float(r["steps_per_period"]) for r in table if _float(r["dt"]) == _float(dt)), math.nan)
        label = r"$\Delta t$ = %.3g" % _float(dt) + ("" if math.isnan(steps) else " (%.0f steps/T)" % steps)
        ax.semilogy(t, e, lw=0.8, color=colour, label=label)
        b = bounds.get(_float(dt))
        if b is not None and b > 0:
            ax.axhline(b, color=colour, ls=":", lw=0.9)
    ax.set_xlabel("time / T (periods)")
    ax.set_ylabel(r"max $|E - E_0|/E_0$ over each period")
    ax.yaxis.set_minor_formatter(matplotlib.ticker.FuncFormatter(_minor_label))
    ax.tick_params(axis="y", which="minor", labelsize=7)
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="center right", fontsize=7)
    path = os.path.join(fig_dir, "wheel_energy.pdf")
    fig.tight_layout()
    figs.save(fig, path)
    out.append(figure(path, "Relative energy error of the undamped wheel against time, its maximum "
                            "over each period (\\texttt{wheel\\_energy\\_history.csv}), one line per "
                            "sub-step; dotted: the test's bound for that sub-step. Flat lines: no "
                            "drift; the spacing between lines: the first-order dependence on "
                            "$\\Delta t$.", height=0.36))


def restitution_subsection(out, results, fig_dir):
    out.append(r"\subsection{Restitution: measured against target}")
    rows = _rows(os.path.join(results, "restitution.csv"),
                 ["case", "e_target", "e_measured", "rel_error", "tolerance", "steps_per_contact"])
    elastic = _rows(os.path.join(results, "restitution_elastic.csv"),
                    ["case", "ke_before", "ke_after", "rel_change", "tolerance"])
    if not rows:
        _not_run(out, ["restitution.csv"], r"\texttt{test\_restitution} and \texttt{test\_wheel\_restitution}")
    else:
        last = OrderedDict()
        for r in rows:  # a rerun appends again: the last row per case and target wins
            last[(r["case"], r["e_target"])] = r
        cases = sorted({c for c, _ in last})
        out.append("Head-on collisions through the linear spring-dashpot contact built for a "
                   "restitution coefficient $e$ (docs/method.md \\S1.5, \\S1.9, A8): two mass points "
                   "(\\texttt{verification/solid/test\\_restitution.cpp}) and stiff wheels, "
                   "wheel-wheel and wheel-wall, with no fluid "
                   "(\\texttt{verification/contact/test\\_wheel\\_restitution.cpp}); $e$ measured "
                   "on the (centre-of-mass) velocities before and after.\n")
        table = [[md_text(c), num(r["e_target"], 3), num(r["e_measured"], 6), num(r["rel_error"], 3),
                  num(r["tolerance"], 3), num(r["steps_per_contact"], 4)]
                 for (c, _), r in sorted(last.items(), key=lambda kv: (kv[0][0], _float(kv[0][1])))]
        out.append(longtable(r">{\raggedright\arraybackslash}p{6.4cm}rrrrr", ["case", "$e$ target", "$e$ measured",
                                               "rel. error", "tolerance", "steps/contact"], table,
                             caption="Restitution (\\texttt{restitution.csv}); the tests require "
                                     "the relative error within the tolerance."))
        fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.0))
        markers = "osD^vx+*"
        tol = max((t for t in (_float(r["tolerance"]) for r in last.values()) if math.isfinite(t)),
                  default=math.nan)
        lo, hi = 0.0, 1.0
        xs = [v / 100.0 for v in range(0, 101)]
        if not math.isnan(tol):
            axes[0].fill_between(xs, [x * (1 - tol) for x in xs], [x * (1 + tol) for x in xs],
                                 color="0.8", label=r"$\pm$%.3g %% band" % (100 * tol))
            axes[1].axhspan(-100 * tol, 100 * tol, color="0.85", label=r"$\pm$%.3g %%" % (100 * tol))
        axes[0].plot([lo, hi], [lo, hi], "k-", lw=0.6)
        axes[1].axhline(0, color="k", lw=0.6)
        for k, case in enumerate(cases):
            pts = sorted((_float(r["e_target"]), _float(r["e_measured"])) for (c, _), r in last.items() if c == case)
            et, em = [p[0] for p in pts], [p[1] for p in pts]
            m = markers[k % len(markers)]
            axes[0].plot(et, em, m, ms=5, mfc="none", label=mathtext(_wrap(case, 34)))
            signed = [(a, 100 * (b - a) / a) for a, b in zip(et, em) if a != 0 and math.isfinite(a)]
            axes[1].plot([a + 0.012 * (k - (len(cases) - 1) / 2) for a, _ in signed],
                         [d for _, d in signed], m, ms=5, mfc="none")
        axes[0].set_xlim(lo, hi)
        axes[0].set_ylim(lo, hi)
        axes[0].set_aspect("equal")
        axes[0].set_xlabel(r"$e$ target")
        axes[0].set_ylabel(r"$e$ measured")
        # above the panels: in the left one it would cover the points near e = 1
        fig.legend(*axes[0].get_legend_handles_labels(), loc="lower center", bbox_to_anchor=(0.5, 1.0), ncol=2,
                   fontsize=7, frameon=False)
        axes[1].set_xlabel(r"$e$ target (cases offset slightly)")
        axes[1].set_ylabel(r"$(e_{meas} - e_{target})/e_{target}$ [%]")
        axes[1].legend(loc="best", fontsize=7)
        for ax in axes:
            ax.grid(alpha=0.3)
        path = os.path.join(fig_dir, "restitution.pdf")
        fig.tight_layout()
        figs.save(fig, path)
        out.append(figure(path, "Left: measured against target restitution, on the diagonal within "
                                "the grey tolerance band. Right: the signed relative error, the "
                                "same points enlarged (from \\texttt{restitution.csv}).", height=0.36))
    if elastic:
        last = OrderedDict((r["case"], r) for r in elastic)
        out.append(longtable(r"lrrrr", ["case ($e = 1$)", "KE before", "KE after", "rel. change",
                                        "tolerance"],
                             [[md_text(c), num(r["ke_before"], 6), num(r["ke_after"], 6),
                               num(r["rel_change"], 3), num(r["tolerance"], 3)] for c, r in last.items()],
                             caption="Elastic collisions of stiff wheels: centre-of-mass kinetic "
                                     "energy before and after (\\texttt{restitution\\_elastic.csv})."))
    elif rows:
        out.append(r"\emph{Elastic ($e = 1$) table not run: \texttt{restitution\_elastic.csv} not found.}" + "\n")


def contact_history_subsection(out, results, fig_dir):
    out.append(r"\subsection{Through the contact: normal relative velocity and overlap}")
    rows = _rows(os.path.join(results, "contact_history.csv"),
                 ["case", "e_target", "t_over_contact_time", "normal_velocity_over_approach",
                  "overlap_over_diameter"])
    if not rows:
        _not_run(out, ["contact_history.csv"], r"\texttt{test\_restitution} and \texttt{test\_wheel\_restitution}")
        return
    series = _series(rows, lambda r: (r["case"], r["e_target"]), "t_over_contact_time")
    cases = sorted({c for c, _ in series})
    ncol = min(len(cases), 4)
    fig, axes = plt.subplots(2, ncol, figsize=(1.7 * ncol + 0.6, 4.6), squeeze=False, sharex=True)
    for j, case in enumerate(cases[:ncol]):
        keys = sorted((k for k in series if k[0] == case), key=lambda k: _float(k[1]))
        for k, key in enumerate(keys):
            rs = series[key]
            t = [_float(r["t_over_contact_time"]) for r in rs]
            colour = "C%d" % k
            e = _float(key[1])
            axes[0][j].plot(t, [_float(r["normal_velocity_over_approach"]) for r in rs], lw=1,
                            color=colour, label="e = %.3g" % e)
            axes[0][j].axhline(e, color=colour, ls=":", lw=0.8)
            axes[1][j].plot(t, [100 * _float(r["overlap_over_diameter"]) for r in rs], lw=1, color=colour)
        axes[0][j].set_title(mathtext(_wrap(case, 20)), fontsize=9)
        axes[1][j].set_xlabel("time / contact duration")
        for ax in (axes[0][j], axes[1][j]):
            ax.axvline(1.0, color="0.5", lw=0.6, ls="--")
            ax.grid(alpha=0.3)
            ax.tick_params(labelsize=7)
        axes[1][j].set_ylim(bottom=0)
    axes[0][0].set_ylabel("normal rel. velocity / approach", fontsize=7)
    axes[1][0].set_ylabel("overlap / diameter [%]", fontsize=7)
    axes[0][0].legend(loc="center right", fontsize=7)
    path = os.path.join(fig_dir, "contact_history.pdf")
    fig.tight_layout()
    figs.save(fig, path)
    extra = "" if len(cases) <= ncol else " (first %d of %d cases)" % (ncol, len(cases))
    out.append(figure(path, "Through each collision%s, from \\texttt{contact\\_history.csv}: top, the "
                            "normal relative velocity over the approach speed, from $-1$ at impact "
                            "to $e$ after (dotted: the target $e$); bottom, the overlap (largest "
                            "one for the wheels). Time from the first contact over the contact "
                            "duration (dashed: its end); the wheel runs continue for as long again "
                            "to show that no second contact follows. Near the end of a contact the "
                            "dashpot term outweighs the spring and the linear force, not clipped to "
                            "stay repulsive (as the tests' headers note, docs/method.md A8), pulls, so the velocity overshoots $e$ before it settles." % extra,
                      height=0.5))


def _minor_label(value, _pos):
    """Minor log-axis labels at 2 and 5 times a power of ten only (readable)."""
    if value <= 0:
        return ""
    mantissa = value / 10 ** math.floor(math.log10(value) + 1e-9)
    return "%.2g" % value if min(abs(mantissa - 2), abs(mantissa - 5)) < 1e-6 else ""


def _wrap(text, width):
    return "\n".join(textwrap.wrap(text, width)) or text
