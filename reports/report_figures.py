"""Figures (vector PDF) from run outputs. Each function writes one file and returns its path, or
None when the inputs are missing."""
import glob
import math
import os
import re
from collections import OrderedDict
import textwrap
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

import matplotlib.patheffects  # noqa: E402
import matplotlib.text  # noqa: E402
import report_data as data  # noqa: E402
from report_latex import FIGURE_TEXT, TEXT_WIDTH_PT, mathtext, pdf_size  # noqa: E402

# An axis's offset and scale factor as mathtext ($\times10^{-14}$), not e-notation (1e-14).
plt.rcParams.update({"font.size": 9, "axes.titlesize": 9, "legend.fontsize": 7,
                     "pdf.fonttype": 42, "figure.dpi": 100, "savefig.bbox": "tight",
                     "axes.formatter.use_mathtext": True})

# Sub- and superscripts of matplotlib's mathtext ($c_D$, the exponents of log-axis ticks) are set at
# SCRIPT_RATIO of their text per level. matplotlib's 0.7 (TeX's ratio at 10 pt) prints the 9 pt
# ticks' exponents at 6.3 pt; 0.78 prints them at 7 pt, as the preamble's \DeclareMathSizes sets
# LaTeX's. Text with scripts is set at script_size() or larger.
SCRIPT_RATIO = 0.78
try:
    import matplotlib._mathtext as _mathtext  # noqa: E402
    if hasattr(_mathtext, "SHRINK_FACTOR"):
        _mathtext.SHRINK_FACTOR = SCRIPT_RATIO
    else:  # a matplotlib without the constant: its own ratio, which save() then measures
        SCRIPT_RATIO = 0.7
except ImportError:
    SCRIPT_RATIO = 0.7


def script_depth(text):
    """How many levels of sub- or superscript the mathtext of a text holds (0 without math): 1 for
    '$c_D$' or '$10^{-3}$', 2 for '$x_{a_b}$'."""
    if text.replace("\\$", "").count("$") < 2:
        return 0
    deepest = 0
    for group in re.findall(r"(?<!\\)\$(.*?)(?<!\\)\$", text):
        level, stack, pending = 0, [], False
        for c in group:
            if c in "^_":
                pending = True
                deepest = max(deepest, level + 1)
            elif c == "{":
                stack.append(level)
                if pending:
                    level += 1
                pending = False
            elif c == "}":
                level = stack.pop() if stack else 0
            elif pending and not c.isspace():
                pending = False  # a one-character script: the level is back after it
    return deepest


def script_size(texts, size=7.0, minimum=7.0):
    """The smallest font size at or above `size` at which every script of `texts` (labels of one
    legend, say) prints at `minimum` pt at full size: `size` when none has a script."""
    depth = max([script_depth(t) for t in texts] or [0])
    return max(size, math.ceil(10 * minimum / SCRIPT_RATIO ** depth - 1e-9) / 10)


def _scripts_legible(fig):
    """Text with sub- or superscripts set at script_size(), so that its scripts are 7 pt at full
    size: a log axis's tick labels through the axis, the axes' titles of the figure at one size and
    each legend at one size for all its entries, every other text alone."""
    fig.canvas.draw()  # tick labels exist from here on
    done = set()
    for ax in fig.axes:
        for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
            for which, labels in (("major", axis.get_majorticklabels()), ("minor", axis.get_minorticklabels())):
                labels = [t for t in labels if t.get_visible() and t.get_text().strip()]
                done.update(id(t) for t in labels)
                if labels:
                    now = max(t.get_fontsize() for t in labels)
                    size = script_size([t.get_text() for t in labels], now)
                    if size > now:
                        ax.tick_params(axis=name, which=which, labelsize=size)
    # the axes' titles of one figure at one size, each legend at one size for all its entries
    groups = [[ax.title for ax in fig.axes if ax.title.get_text().strip()]]
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend()] + list(fig.legends)
    groups += [legend.get_texts() for legend in legends]
    for texts in groups:
        done.update(id(t) for t in texts)
        if texts:
            now = max(t.get_fontsize() for t in texts)
            size = script_size([t.get_text() for t in texts], now)
            if size > now:
                for t in texts:
                    t.set_fontsize(size)
    for t in fig.findobj(matplotlib.text.Text):
        if id(t) not in done and t.get_visible() and t.get_text().strip():
            t.set_fontsize(script_size([t.get_text()], t.get_fontsize()))


def save(fig, path):
    """Writes the figure (vector PDF, tight bounding box) and closes it. Text with sub- or
    superscripts is first set large enough for its scripts (_scripts_legible). A figure wider than
    the text is narrowed (its text kept at its size, the layout redone) until it fits, so that
    LaTeX prints it at full size; records its smallest visible text size (tick labels, legends,
    annotations, titles, and the sub- and superscripts in them) for the print-size check of
    report_latex.figure()."""
    _scripts_legible(fig)
    fig.savefig(path)  # draws the figure again, with the sizes set
    for _ in range(4):
        width = pdf_size(path)[0]
        if width is None or width <= TEXT_WIDTH_PT:
            break
        w_in, h_in = fig.get_size_inches()
        fig.set_size_inches(max(w_in - 1.02 * (width - TEXT_WIDTH_PT) / 72.0, 1.5), h_in)
        with warnings.catch_warnings():  # figures whose layout tight_layout cannot redo keep theirs
            warnings.simplefilter("ignore")
            fig.tight_layout()
        fig.savefig(path)
    # each text's smallest glyphs: its size, or its deepest script's (SCRIPT_RATIO per level)
    sizes = [t.get_fontsize() * SCRIPT_RATIO ** script_depth(t.get_text()) for t in fig.findobj(matplotlib.text.Text)
             if t.get_visible() and t.get_text().strip() and t.get_figure() is fig]
    plt.close(fig)
    if sizes:
        FIGURE_TEXT[path] = min(sizes)
    return path


_CGS = {"length": "cm", "time": "s", "mass": "g"}


def unit_system(csv_comments):
    """The scene's unit system from a run CSV's '# ... source scene: PATH' comment: the scene's
    leading comment names cgs units ("cgs units: cm, g, s") or the scene is dimensionless. Returns
    a dict word -> unit, or {} for a dimensionless scene (and when the scene cannot be read)."""
    path = None
    for c in csv_comments:
        if "source scene:" in c:
            path = c.split("source scene:", 1)[1].strip()
    if not path or not os.path.isfile(path):
        return {}
    with open(path, encoding="utf-8", errors="replace") as f:
        head = "".join(line for _, line in zip(range(6), f) if line.startswith("#"))
    return dict(_CGS) if re.search(r"cgs units", head) else {}


def real_units(units, system):
    """'length/time' -> 'cm/s' in a cgs scene; '' for a dimensionless scene or '-'."""
    if not units or units == "-" or not system:
        return ""
    return re.sub(r"\b(length|time|mass)\b", lambda m: system[m.group(1)], units)


def _axis_label(name, units, system):
    u = real_units(units, system)
    return "%s [%s]" % (name, u) if u else name


def _grid_of(path, case):
    m = re.search(re.escape(case) + r"_(\d+)", os.path.basename(path))
    return int(m.group(1)) if m else None


def profile_runs(case_dir, case, component):
    """[(N, path)] of <case>_<N>_centreline_<component>.csv sorted by N."""
    runs = []
    for p in glob.glob(os.path.join(case_dir, "*_centreline_%s.csv" % component)):
        n = _grid_of(p, case)
        runs.append((n if n is not None else 0, p))
    return sorted(runs)


def _read_extrema(ref_dir):
    """Botella & Peyret extrema (quantity -> (value, position)) from botella_peyret_extrema.csv."""
    path = os.path.join(ref_dir, "botella_peyret_extrema.csv")
    out = {}
    if not os.path.isfile(path):
        return out
    with open(path, encoding="utf-8") as f:
        rows = [line.strip().split(",") for line in f if line.strip() and not line.startswith("#")][1:]
    for r in rows:
        try:
            out[r[0]] = (float(r[1]), float(r[2]))
        except (ValueError, IndexError):
            continue
    return out


def cavity_profiles(case_dir, case, ref_dir, out, labels=None):
    """Centre-line u(y) and v(x) of every grid with the reference points (Ghia et al.: flagged
    points hollow; Botella & Peyret's extrema as stars) and, below, each grid's difference from them
    (the profile linearly interpolated at the reference coordinates; the checks use a cubic spline).
    Without a reference: the point-mirrored finest profile and the difference from it (the symmetry
    the two-sided cavity check measures). `labels`: citation text for the legends."""
    labels = labels or {}
    runs_u, runs_v = profile_runs(case_dir, case, "u"), profile_runs(case_dir, case, "v")
    if not runs_u and not runs_v:
        return None
    refs = {}
    for comp in ("u", "v"):
        found = sorted(glob.glob(os.path.join(ref_dir, "ghia_%s_*.csv" % comp)))
        if found:
            refs[comp] = data.read_reference_profile(found[0])
    extrema = _read_extrema(ref_dir)
    ghia_label = labels.get("ghia", "Ghia et al. (1982)")
    bp_label = labels.get("botella", "Botella & Peyret (1998) extrema")
    fig, axes = plt.subplots(2, 2, figsize=(7.0, 5.6), gridspec_kw={"height_ratios": [3, 2]})
    for col, (comp, runs) in enumerate((("u", runs_u), ("v", runs_v))):
        ax, dax = axes[0][col], axes[1][col]
        for n, path in runs:
            names, units, arr, _ = data.read_table_csv(path)
            if arr.shape[0] == 0:
                continue
            x, y = arr[:, 0], arr[:, 1]
            label = "%d$\\times$%d" % (n, n) if n else os.path.basename(path)
            line, = (ax.plot(y, x, lw=1, label=label) if comp == "u" else ax.plot(x, y, lw=1, label=label))
            if comp in refs:
                c, val, flag, _ = refs[comp]
                diff = np.interp(c, x, y) - val
                dax.plot(c[~flag], diff[~flag], "o-", ms=2.5, lw=0.7, color=line.get_color(), label=label)
            else:
                mx, my = 1.0 - x[::-1], -y[::-1]
                dax.plot(x, y - np.interp(x, mx, my), lw=0.8, color=line.get_color(), label=label)
            for q, (value, pos) in extrema.items():
                if q.startswith(comp + "_"):
                    found = y.min() if q.endswith("min") else y.max()
                    dax.plot(pos, found - value, "*", ms=7, color=line.get_color())
        if comp in refs:
            c, val, flag, _ = refs[comp]
            pts = (val, c) if comp == "u" else (c, val)
            ax.plot(pts[0][~flag], pts[1][~flag], "ko", ms=3.5, mfc="k", label=ghia_label)
            if flag.any():
                ax.plot(pts[0][flag], pts[1][flag], "ko", ms=3.5, mfc="none", label=ghia_label + ", flagged")
        elif runs:
            names, units, arr, _ = data.read_table_csv(runs[-1][1])
            if arr.shape[0]:
                x, y = arr[:, 0], arr[:, 1]
                mx, my = 1.0 - x[::-1], -y[::-1]
                (ax.plot(my, mx, "k:", lw=1, label="finest, point-mirrored") if comp == "u" else
                 ax.plot(mx, my, "k:", lw=1, label="finest, point-mirrored"))
        for q, (value, pos) in extrema.items():
            if q.startswith(comp + "_"):
                lab = bp_label if q in ("u_min", "v_max") else None
                (ax.plot(value, pos, "k*", ms=8, mfc="none", label=lab) if comp == "u" else
                 ax.plot(pos, value, "k*", ms=8, mfc="none", label=lab))
        if comp == "u":
            ax.set_xlabel("u on x = 0.5 (lid speed 1)")
            ax.set_ylabel("y")
            dax.set_xlabel("y")
        else:
            ax.set_xlabel("x")
            ax.set_ylabel("v on y = 0.5 (lid speed 1)")
            dax.set_xlabel("x")
        dax.axhline(0, color="k", lw=0.5)
        dax.set_ylabel(("%s $-$ Ghia" % comp) + (" (stars: extremum $-$ B&P)" if extrema else "")
                       if comp in refs else "%s $-$ point-mirrored" % comp, fontsize=7)
        ax.grid(alpha=0.3)
        dax.grid(alpha=0.3)
        ax.legend(loc="best", fontsize=7)
    fig.tight_layout()
    save(fig, out)
    return out


def _finest_h5(case_dir, case):
    files = glob.glob(os.path.join(case_dir, "*.h5"))
    if not files:
        return None
    return max(files, key=lambda p: (_grid_of(p, case) or 0, os.path.getsize(p)))


def _body_outlines(group):
    """Closed rims (x, y) of every body in a snapshot group: `bodies/x`, `bodies/y` split at
    `bodies/first_point` (docs/output.md; all points one rim without it), or per-body groups
    `body*` with `x`, `y` or an (n, 2) `positions` / `points` / `position` array."""
    outlines = []
    if "bodies" in group and hasattr(group["bodies"], "keys"):
        g = group["bodies"]
        if "x" in g and "y" in g:
            x, y = np.asarray(g["x"]), np.asarray(g["y"])
            first = np.asarray(g["first_point"]).astype(int) if "first_point" in g else np.array([0, len(x)])
            for a, b in zip(first[:-1], first[1:]):
                if b - a >= 2:
                    outlines.append((np.append(x[a:b], x[a]), np.append(y[a:b], y[a])))
        return outlines
    for key in sorted(group.keys()):
        if not key.startswith("body"):
            continue
        g = group[key]
        if not hasattr(g, "keys"):
            continue
        if "x" in g and "y" in g:
            outlines.append((np.asarray(g["x"]), np.asarray(g["y"])))
        else:
            for name in ("positions", "points", "position"):
                if name in g and g[name].ndim == 2 and g[name].shape[1] == 2:
                    p = np.asarray(g[name])
                    outlines.append((p[:, 0], p[:, 1]))
                    break
    return outlines


def vorticity_limit(paths, percentile=98):
    """One colour range for all snapshots of a case: the percentile of |vorticity| over every
    snapshot of the given HDF5 files (None without snapshots)."""
    import h5py
    samples = []
    for path in paths:
        try:
            with h5py.File(path, "r") as f:
                for step in f.get("snapshots", {}):
                    g = f["snapshots"][step]
                    if "vorticity" in g:
                        w = np.abs(np.asarray(g["vorticity"])).ravel()
                        samples.append(w[:: max(1, w.size // 20000)])
        except OSError:
            continue
    if not samples:
        return None
    lim = float(np.nanpercentile(np.concatenate(samples), percentile))
    return lim if lim > 0 else 1.0


def snapshots(case_dir, case, out, max_panels=3, path=None, vlim=None, system=None):
    """Vorticity (filled contours, one colour scale `vlim` for the figure and, when given, for the
    whole case) with velocity vectors and any body outlines, from the finest run's HDF5 (or
    `path`): up to max_panels evenly spread snapshots, one colour bar."""
    path = path or _finest_h5(case_dir, case)
    if path is None:
        return None, None
    import h5py
    try:
        f = h5py.File(path, "r")
    except OSError:  # a run still writing it (locked) or a truncated file: no figure from it
        return None, None
    system = system or {}
    with f:
        if "snapshots" not in f or "grid" not in f:
            return None, None
        steps = sorted(k for k in f["snapshots"].keys() if "vorticity" in f["snapshots"][k])
        if not steps:
            return None, None
        if len(steps) > max_panels:
            idx = np.unique(np.linspace(0, len(steps) - 1, max_panels).round().astype(int))
            steps = [steps[i] for i in idx]
        xc, yc = np.asarray(f["grid/x_centres"]), np.asarray(f["grid/y_centres"])
        lx = float(np.ptp(xc)) or 1.0
        ly = float(np.ptp(yc)) or 1.0
        lim = vlim or vorticity_limit([path]) or 1.0
        nrow = 1 if len(steps) <= 3 else 2  # four panels: 2 x 2, readable on a page
        ncol = -(-len(steps) // nrow)
        panel_w = 6.0 if ncol == 1 and lx > 1.5 * ly else min(3.2, 6.4 / ncol)
        panel_h = min(panel_w * ly / lx, 8.0)
        fig, axes = plt.subplots(nrow, ncol, figsize=(panel_w * ncol + 1.0, (panel_h + 0.7) * nrow),
                                 squeeze=False)
        for ax in axes.flat[len(steps):]:
            ax.set_visible(False)
        cs = None
        for ax, step in zip(axes.flat, steps):
            g = f["snapshots"][step]
            w = np.asarray(g["vorticity"])
            cs = ax.contourf(xc, yc, np.clip(w, -lim, lim), levels=np.linspace(-lim, lim, 25),
                             cmap="RdBu_r", extend="both")
            if "u" in g and "v" in g:
                u, v = np.asarray(g["u"]), np.asarray(g["v"])
                sx = max(1, len(xc) // 24)
                sy = max(1, int(round(sx * (yc[1] - yc[0]) / (xc[1] - xc[0])))) if len(yc) > 1 else 1
                ax.quiver(xc[::sx], yc[::sy], u[::sy, ::sx], v[::sy, ::sx], color="k", width=0.003,
                          scale=None)
            # rims black on a white halo: visible over the colours and the black vectors alike
            for bx, by in _body_outlines(g):
                ax.plot(bx, by, color="k", lw=0.9, zorder=4,
                        path_effects=[matplotlib.patheffects.withStroke(linewidth=2.2, foreground="w")])
            t = g.attrs.get("time", None)
            tu = real_units("time", system)
            ax.set_title("t = %.4g%s" % (float(t), " " + tu if tu else "") if t is not None else "step " + step)
            ax.set_aspect("equal")
            ax.set_xlabel(_axis_label("x", "length", system))
            ax.set_ylabel(_axis_label("y", "length", system))
        if cs is not None:
            fig.colorbar(cs, ax=[a for a in axes.flat if a.get_visible()], shrink=0.85,
                         label=_axis_label("vorticity", "1/time", system),
                         format=matplotlib.ticker.FuncFormatter(lambda v, _: _number(v)),
                         ticks=np.linspace(-lim, lim, 5))
        save(fig, out)
    return out, path


def _number(value):
    """A tick value to three digits, a power of ten as mathtext ($3.83\\times10^{-5}$, not 3.83e-05)."""
    mant, _, ten = ("%.3g" % value).partition("e")
    return r"$%s\times10^{%d}$" % (mant, int(ten)) if ten else mant


def _body_label(names, k):
    return names.get(k, "body %d" % k) if names else "body %d" % k


def body_histories(case_dir, out, literature=None):
    """Body series against time from each run's <stem>_bodies.csv (the CSV the solver writes beside
    its HDF5): drag and lift coefficients for bodies with a reference speed (fixed cylinders), else
    centroid height, vertical velocity and (when it changes) diameter. Runs with more than three
    bodies draw all of them thin in one colour with one legend entry; literature values (`literature`:
    'bands' key -> [(lo, hi, label)], 'lines' key -> [(value, label)], 'points' key -> [(t, v,
    label)], 'body_names' {index: name}, 'startup' time) are drawn on the matching panel. The
    y range leaves out t < startup and each run's last sample (the shortened final step), which
    are still drawn."""
    lit = literature or {}
    files = sorted(glob.glob(os.path.join(case_dir, "*_bodies.csv")))
    if not files:
        return None, []
    tables = [(os.path.basename(p)[:-len("_bodies.csv")], data.read_table_csv(p)) for p in files]
    wanted = [("centroid_y", "centroid y"), ("velocity_y", "velocity y"), ("diameter", "diameter")]
    # The slip panel: the face velocities' slip (face_slip_max, solid), the one the no-slip coupling
    # holds to ibm.slip_tolerance at the end of the step, with the cell velocities' slip (slip_max,
    # dashed) on the same log axis; the cells differ from the faces by the momentum interpolation
    # (docs/method.md §2.3), so their slip is not held to the tolerance. Outputs without face_slip_max
    # show the cell slip alone, labelled as such.
    overlay = {"face_slip_max": "slip_max"}
    if any(any(n.endswith("/drag_coefficient") for n in t[1][0]) for t in tables):
        wanted = [("drag_coefficient", "drag coefficient $c_D$"), ("lift_coefficient", "lift coefficient $c_L$")]
        if any(any(n.endswith("/face_slip_max") for n in t[1][0]) for t in tables):
            wanted.append(("face_slip_max", "largest rim slip"))
        else:
            wanted.append(("slip_max", "largest cell-velocity slip"))
    present = []
    for key, label in wanted:
        cols = [(stem, t, i) for stem, t in tables for i, n in enumerate(t[0]) if n.endswith("/" + key)]
        if not cols:
            continue
        if key == "diameter" and all(np.nanmax(t[2][:, i]) - np.nanmin(t[2][:, i]) <= 1e-12 * max(1.0, abs(np.nanmax(t[2][:, i])))
                                     for _, t, i in cols if t[2].shape[0]):
            continue  # a constant diameter: no panel
        present.append((key, label))
    if not present:
        return None, files
    for key, (lo, hi, title) in lit.get("zoom", {}).items():
        if any(k == key for k, _ in present):
            present.append((key + "@zoom", dict(present)[key]))
    system = unit_system(tables[0][1][3])
    fig, axes = plt.subplots(1, len(present), figsize=(3.3 * len(present) + 0.4, 3.0), squeeze=False)
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    startup = lit.get("startup")
    t_max = 0.0
    for ax, (panel, label) in zip(axes[0], present):
        key, zoom = panel.split("@")[0], lit.get("zoom", {}).get(panel.split("@")[0]) if "@" in panel else None
        lows, highs = [], []
        # A series that changes by round-off only (a disk at rest) is drawn as its change from the
        # first value, not against an axis offset such as 1e-12 + 1.
        values = np.concatenate([t[2][:, i] for _, t in tables for i, n in enumerate(t[0]) if n.endswith("/" + key)])
        values = values[np.isfinite(values)]
        shift = 0.0
        if values.size and np.ptp(values) <= 1e-9 * np.max(np.abs(values)) and key not in overlay:
            shift = float(values[0])
        for r, (stem, (names, units, arr, comments)) in enumerate(tables):
            if not names or arr.shape[0] == 0 or names[0] != "time":
                continue
            cols = [i for i, n in enumerate(names) if n.endswith("/" + key)]
            t = arr[:, 0]
            t_max = max(t_max, float(np.nanmax(t)))
            keep = np.ones(len(t), bool)
            keep[-1] = len(t) < 2  # the last (shortened) step stays out of the range
            if startup is not None:
                keep &= t >= startup
            colour = colours[r % len(colours)]
            many = len(cols) > 3
            for i in ([n for n, name in enumerate(names) if name.endswith("/" + overlay[key])]
                      if key in overlay else []):
                ax.plot(t, arr[:, i], lw=0.9, color=colour, ls="--")
                if keep.any():
                    lows.append(np.nanmin(np.where(arr[:, i] > 0, arr[:, i], np.nan)[keep]))
                    highs.append(np.nanmax(arr[:, i][keep]))
            for j, i in enumerate(cols):
                body = int(re.sub(r"\D", "", names[i].split("/")[0]) or 0)
                y = arr[:, i] - shift
                if many:
                    lab = "%s: %d bodies" % (stem, len(cols)) if j == 0 else None
                    ax.plot(t, y, lw=0.5, color=colour, alpha=0.7, label=lab)
                else:
                    lab = stem if len(cols) == 1 else "%s, %s" % (stem, _body_label(lit.get("body_names"), body))
                    ax.plot(t, y, lw=0.9, label=lab,
                            color=colour if len(cols) == 1 else None, ls=("-", "--", ":")[j % 3])
                if keep.any():
                    lows.append(np.nanmin((np.where(y > 0, y, np.nan) if key in overlay else y)[keep]))
                    highs.append(np.nanmax(y[keep]))
            if cols:
                ax.set_ylabel(_axis_label(label + (" $-$ %.10g" % shift if shift else ""), units[cols[0]], system))
                ax.set_xlabel(_axis_label("time", units[0], system))
        for lo, hi, lab in lit.get("bands", {}).get(key, []):
            ax.axhspan(lo, hi, color="k", alpha=0.15, lw=0, label=lab)
            lows.append(lo)
            highs.append(hi)
        for value, lab in lit.get("lines", {}).get(key, []):
            ax.axhline(value, color="k", ls=":" if key in overlay else "--", lw=0.8, label=lab)
            lows.append(value)
            highs.append(value)
        for j, (t_ref, v_ref, lab) in enumerate(lit.get("points", {}).get(key, [])):
            ax.plot(t_ref, v_ref, "k" + "s^o"[j % 3], ms=3.5, mfc="none", ls="none", label=lab)
        if zoom:
            lows, highs = [zoom[0]], [zoom[1]]
            ax.set_title(zoom[2], fontsize=8)
        if key in overlay:  # slips over decades: a log axis, and the two line styles in the legend
            ax.set_yscale("log")
            ax.plot([], [], "k-", lw=0.9, label="slip of the face velocities (constrained)")
            ax.plot([], [], "k--", lw=0.9, label="slip of the cell velocities (interpolated)")
            lows, highs = [v for v in lows if np.isfinite(v) and v > 0], [v for v in highs if np.isfinite(v) and v > 0]
            if lows and highs:
                ax.set_ylim(min(lows) / 2, max(highs) * 2)
            lows, highs = [], []
        if lows and highs:
            lo, hi = min(lows), max(highs)
            pad = 0.06 * (hi - lo) if hi > lo else 0.05 * max(abs(hi), 1e-12)
            ax.set_ylim(lo - pad, hi + pad)
        if key not in overlay:
            ax.yaxis.get_major_formatter().set_useOffset(False)
        if t_max > 0:  # reference points beyond the runs' end stay off the axis
            ax.set_xlim(min(0.0, ax.get_xlim()[0]), t_max * 1.02)
        ax.grid(alpha=0.3)
    handles, labels = [], []
    for ax in axes[0]:
        for h, l in zip(*ax.get_legend_handles_labels()):
            if l not in labels:
                handles.append(h)
                labels.append(l)
    fig.legend(handles, labels, loc="lower center", ncol=min(3, len(labels)), fontsize=7,
               bbox_to_anchor=(0.5, 1.0), frameon=False)
    fig.tight_layout()
    save(fig, out)
    return out, files


def trajectories(path, out):
    """Particle centre paths (papers' Fig. 4 style) from a long-format trajectories CSV
    (time, particle, x, y, diameter) written by a case check; dot: the last position."""
    names, units, arr, _ = data.read_table_csv(path)
    if arr.ndim != 2 or arr.shape[0] == 0 or names[:4] != ["time", "particle", "x", "y"]:
        return None
    fig, ax = plt.subplots(figsize=(3.6, 3.6))
    for particle in np.unique(arr[:, 1]):
        rows = arr[arr[:, 1] == particle]
        ax.plot(rows[:, 2], rows[:, 3], lw=0.9)
        ax.plot(rows[-1, 2], rows[-1, 3], "o", color="r", ms=3)
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1)
    ax.set_aspect("equal")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_title("%.3g $\\leq t \\leq$ %.3g" % (arr[:, 0].min(), arr[:, 0].max()))
    ax.grid(alpha=0.3)
    fig.tight_layout()
    save(fig, out)
    return out


def generic_csv(path, out):
    """Every column of a numeric CSV against its first column (histories written by checks): one
    panel per unit, its y axis labelled with the unit (a diameter in cm and velocities in cm/s are
    not drawn on one axis), the legend beside the panel's data."""
    names, units, arr, comments = data.read_table_csv(path)
    if len(names) < 2 or arr.shape[0] < 2:
        return None
    groups = OrderedDict()
    for i in range(1, min(len(names), 10)):
        groups.setdefault(units[i] or "", []).append(i)
    fig, axes = plt.subplots(1, len(groups), figsize=(3.4 * len(groups) + 0.6, 3.0), squeeze=False)
    for ax, (unit, cols) in zip(axes[0], groups.items()):
        for i in cols:
            ax.plot(arr[:, 0], arr[:, i], lw=1, label=names[i])
        ax.set_xlabel(names[0] + (" [%s]" % units[0] if units[0] else ""))
        what = names[cols[0]] if len(cols) == 1 else _common_prefix([names[i] for i in cols]) or "value"
        ax.set_ylabel(what + (" [%s]" % unit if unit else " [-]"))
        ax.yaxis.get_major_formatter().set_useOffset(False)
        ax.grid(alpha=0.3)
        if len(cols) > 1:
            ax.legend(loc="best", fontsize=7)
    fig.tight_layout()
    save(fig, out)
    return out


def _common_prefix(names):
    """The common leading words of column names (velocity_y_swelling, velocity_y_d025 -> velocity_y)."""
    prefix = os.path.commonprefix(names)
    return prefix[:prefix.rfind("_")] if "_" in prefix else prefix.rstrip("_")


def study_of(title, table):
    """(study, 'h' or 'dt') of a convergence table: tables of one test program and one set-up (the
    title without its last two comma-separated parts, the variable and the norm) that refine the
    same variable form one study (one figure)."""
    program, rest = title.split(": ", 1) if ": " in title else ("convergence", title)
    parts = re.sub(r" \(table \d+\)$", "", rest).split(",")
    # "<set-up>, <variable>, <norm>": the set-up names the study within its program
    study = program + (": " + ",".join(parts[:-2]).strip() if len(parts) > 2 else "")
    return study, table.get("refined") or "h"


def convergence_study(name, refined, items, out):
    """One figure per study: error against h (or dt) of each of its tables, log-log, numbered as in
    the order table, with a reference-slope triangle of the formal order at the finest point."""
    fig, ax = plt.subplots(figsize=(6.2, 3.4))
    formal_done = set()
    # triangles below every table's finest point, so that they cross no data
    finest_errors = [min(e for e in t["error"] if e > 0) for _, _, t in items if any(e > 0 for e in t["error"])]
    y_floor = min(finest_errors) if finest_errors else 1.0
    for k, title, t in items:
        h, e = np.array(t["h"]), np.array(t["error"])
        ok = (h > 0) & (e > 0)
        if ok.sum() < 2:
            continue
        slope = t.get("fit_order", math.nan)
        # the set-up is the figure's title: the legend names what differs (variable and norm)
        rest = title[len(name):].lstrip(", ") if title.startswith(name + ",") else title.split(": ", 1)[-1]
        # ASCII notation (64^2, nu, <=) as mathtext, after wrapping at spaces
        lab = "(%d) %s" % (k, mathtext(_wrap(rest, 40)))
        if np.isfinite(slope):
            lab += ": %.2f" % slope
        line, = ax.loglog(h[ok], e[ok], "o-", ms=3.5, lw=1, label=lab)
        p = t.get("formal", math.nan)
        if np.isfinite(p) and p not in formal_done:
            formal_done.add(p)
            x1 = h[ok].min()
            x0 = x1 * 2.0
            y0 = y_floor * 0.5  # the top of this triangle, below the data and the previous triangle
            y1 = y0 / 2.0 ** p
            y_floor = y1 / 1.3 / 0.5
            ax.loglog([x0, x1, x0, x0], [y0, y1, y1, y0], "k-", lw=0.8)
            ax.annotate("%g" % p, (x0, math.sqrt(y0 * y1)), xytext=(3, 0), textcoords="offset points",
                        fontsize=7, va="center")
    ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
    ax.set_xlabel("time step $\\Delta t$" if refined == "dt" else "grid spacing $h$")
    ax.set_ylabel("error")
    ax.set_title(name.replace("_", " "), fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), fontsize=7, frameon=False)
    fig.tight_layout()
    save(fig, out)
    return out


def _wrap(title, width=40):
    """A legend entry in full, broken into lines of at most `width` characters at spaces."""
    return "\n".join(textwrap.wrap(title.replace("_", " "), width)) or title
