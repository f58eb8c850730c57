"""Figures (vector PDF) from run outputs. Each function writes one file and returns its path, or
None when the inputs are missing."""
import glob
import math
import os
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402

import report_data as data  # noqa: E402

plt.rcParams.update({"font.size": 9, "axes.titlesize": 9, "legend.fontsize": 7,
                     "pdf.fonttype": 42, "figure.dpi": 100, "savefig.bbox": "tight"})


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


def cavity_profiles(case_dir, case, ref_dir, out):
    """Centre-line u(y) and v(x) of every grid, with reference points where the repo has them
    (flagged reference points drawn hollow), and for a case without reference the point-mirrored
    finest profile (the symmetry the two-sided cavity check measures)."""
    runs_u, runs_v = profile_runs(case_dir, case, "u"), profile_runs(case_dir, case, "v")
    if not runs_u and not runs_v:
        return None
    refs = {}
    for comp in ("u", "v"):
        found = sorted(glob.glob(os.path.join(ref_dir, "ghia_%s_*.csv" % comp)))
        if found:
            refs[comp] = data.read_reference_profile(found[0])
    fig, axes = plt.subplots(1, 2, figsize=(7.0, 3.2))
    for ax, comp, runs in ((axes[0], "u", runs_u), (axes[1], "v", runs_v)):
        for n, path in runs:
            names, units, arr, _ = data.read_table_csv(path)
            if arr.shape[0] == 0:
                continue
            x, y = arr[:, 0], arr[:, 1]
            label = "%d$^2$" % n if n else os.path.basename(path)
            if comp == "u":
                ax.plot(y, x, lw=1, label=label)
            else:
                ax.plot(x, y, lw=1, label=label)
        if comp in refs:
            c, val, flag, _ = refs[comp]
            pts = (val, c) if comp == "u" else (c, val)
            ax.plot(pts[0][~flag], pts[1][~flag], "ko", ms=3.5, mfc="k", label="Ghia et al. 1982")
            if flag.any():
                ax.plot(pts[0][flag], pts[1][flag], "ko", ms=3.5, mfc="none", label="Ghia (flagged)")
        elif runs:
            names, units, arr, _ = data.read_table_csv(runs[-1][1])
            if arr.shape[0]:
                x, y = arr[:, 0], arr[:, 1]
                mx, my = 1.0 - x[::-1], -y[::-1]
                if comp == "u":
                    ax.plot(my, mx, "k:", lw=1, label="finest, point-mirrored")
                else:
                    ax.plot(mx, my, "k:", lw=1, label="finest, point-mirrored")
        if comp == "u":
            ax.set_xlabel("u on x = mid-width")
            ax.set_ylabel("y")
        else:
            ax.set_xlabel("x")
            ax.set_ylabel("v on y = mid-height")
        ax.grid(alpha=0.3)
        ax.legend(loc="best")
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
    return out


def _finest_h5(case_dir, case):
    files = glob.glob(os.path.join(case_dir, "*.h5"))
    if not files:
        return None
    return max(files, key=lambda p: (_grid_of(p, case) or 0, os.path.getsize(p)))


def _body_outlines(group):
    """Point arrays (x, y) of every body group in a snapshot group, if the output has them."""
    outlines = []
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


def snapshots(case_dir, case, out, max_panels=3, path=None):
    """Vorticity (filled contours) with velocity vectors and any body outlines, from the finest
    run's HDF5 (or `path`): the last snapshot, or up to max_panels evenly spread snapshots."""
    path = path or _finest_h5(case_dir, case)
    if path is None:
        return None, None
    import h5py
    try:
        f = h5py.File(path, "r")
    except OSError:  # a run still writing it (locked) or a truncated file: no figure from it
        return None, None
    with f:
        if "snapshots" not in f or "grid" not in f:
            return None, None
        steps = sorted(f["snapshots"].keys())
        if not steps:
            return None, None
        if len(steps) > max_panels:
            idx = np.unique(np.linspace(0, len(steps) - 1, max_panels).round().astype(int))
            steps = [steps[i] for i in idx]
        xc, yc = np.asarray(f["grid/x_centres"]), np.asarray(f["grid/y_centres"])
        lx = float(np.ptp(xc)) or 1.0
        ly = float(np.ptp(yc)) or 1.0
        nrow = 1 if len(steps) <= 3 else 2  # four panels: 2 x 2, readable on a page
        ncol = -(-len(steps) // nrow)
        panel_w = min(3.4, 7.0 / ncol)
        panel_h = min(panel_w * ly / lx, 8.0)
        fig, axes = plt.subplots(nrow, ncol, figsize=(panel_w * ncol + 0.6, (panel_h + 0.6) * nrow),
                                 squeeze=False)
        for ax in axes.flat[len(steps):]:
            ax.set_visible(False)
        for ax, step in zip(axes.flat, steps):
            g = f["snapshots"][step]
            if "vorticity" not in g:
                continue
            w = np.asarray(g["vorticity"])
            lim = np.nanpercentile(np.abs(w), 98) or 1.0
            cs = ax.contourf(xc, yc, np.clip(w, -lim, lim), levels=np.linspace(-lim, lim, 25),
                             cmap="RdBu_r", extend="both")
            if "u" in g and "v" in g:
                u, v = np.asarray(g["u"]), np.asarray(g["v"])
                sx = max(1, len(xc) // 24)
                sy = max(1, int(round(sx * (yc[1] - yc[0]) / (xc[1] - xc[0])))) if len(yc) > 1 else 1
                ax.quiver(xc[::sx], yc[::sy], u[::sy, ::sx], v[::sy, ::sx], color="k", width=0.003,
                          scale=None)
            for bx, by in _body_outlines(g):
                ax.fill(bx, by, facecolor="none", edgecolor="k", lw=1)
            t = g.attrs.get("time", None)
            ax.set_title("t = %.4g (step %s)" % (float(t), step) if t is not None else "step " + step)
            ax.set_aspect("equal")
            ax.set_xlabel("x")
            ax.set_ylabel("y")
            fig.colorbar(cs, ax=ax, shrink=0.8, label="vorticity", format="%.2g")
        fig.tight_layout()
        fig.savefig(out)
        plt.close(fig)
    return out, path


def body_histories(case_dir, out):
    """Centroid height, vertical velocity and diameter of every body against time (or drag and
    lift coefficients when the bodies have them), from each run's <stem>_bodies.csv (the CSV the
    solver writes beside its HDF5)."""
    files = sorted(glob.glob(os.path.join(case_dir, "*_bodies.csv")))
    if not files:
        return None, []
    wanted = [("centroid_y", "centroid y"), ("velocity_y", "velocity y"), ("diameter", "diameter")]
    tables = [(os.path.basename(p)[:-len("_bodies.csv")], data.read_table_csv(p)) for p in files]
    # Force histories for bodies with a reference speed (fixed cylinders of the DFG cases): drag
    # and lift coefficients instead of the (constant) position and size.
    if any(any(n.endswith("/drag_coefficient") for n in t[1][0]) for t in tables):
        wanted = [("drag_coefficient", "drag coefficient"), ("lift_coefficient", "lift coefficient")]
    present = [(k, lab) for k, lab in wanted
               if any(any(n.endswith("/" + k) for n in t[1][0]) for t in tables)]
    if not present:
        return None, files
    fig, axes = plt.subplots(1, len(present), figsize=(2.4 * len(present) + 0.6, 2.8), squeeze=False)
    for ax, (key, label) in zip(axes[0], present):
        for stem, (names, units, arr, _) in tables:
            if not names or arr.shape[0] == 0 or names[0] != "time":
                continue
            cols = [i for i, n in enumerate(names) if n.endswith("/" + key)]
            for i in cols[:16]:
                body = names[i].split("/")[0]
                lab = stem if len(cols) == 1 else (stem + " " + body if i == cols[0] else None)
                ax.plot(arr[:, 0], arr[:, i], lw=0.9, label=lab)
            if cols:
                ax.set_ylabel("%s [%s]" % (label, units[cols[0]]) if units[cols[0]] else label)
                ax.set_xlabel("time [%s]" % units[0] if units[0] else "time")
        ax.grid(alpha=0.3)
    axes[0][0].legend(loc="best")
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
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
    ax.set_title("%.3g <= t <= %.3g" % (arr[:, 0].min(), arr[:, 0].max()))
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
    return out


def generic_csv(path, out):
    """Every column of a numeric CSV against its first column (histories written by checks)."""
    names, units, arr, comments = data.read_table_csv(path)
    if len(names) < 2 or arr.shape[0] < 2:
        return None
    fig, ax = plt.subplots(figsize=(6.0, 3.0))
    for i in range(1, min(len(names), 10)):
        lab = names[i] + (" [%s]" % units[i] if units[i] else "")
        ax.plot(arr[:, 0], arr[:, i], lw=1, label=lab)
    ax.set_xlabel(names[0] + (" [%s]" % units[0] if units[0] else ""))
    ax.grid(alpha=0.3)
    ax.legend(loc="best")
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
    return out


def convergence(tables, out):
    """Error against h (log-log) per table, with the least-squares line through the finest three
    levels and its slope in the legend."""
    if not tables:
        return None
    titles = list(tables)
    ncol = 3 if len(titles) > 4 else 2
    nrow = int(math.ceil(len(titles) / ncol))
    fig, axes = plt.subplots(nrow, ncol, figsize=(2.4 * ncol, 1.9 * nrow), squeeze=False)
    for k, title in enumerate(titles):
        ax = axes[k // ncol][k % ncol]
        t = tables[title]
        h, e = np.array(t["h"]), np.array(t["error"])
        ax.loglog(h, e, "o-", ms=3.5, lw=1, label="measured")
        slope = t.get("fit_order", math.nan)
        icpt = data.fit_line(h, e, slope)
        if np.isfinite(slope) and np.isfinite(icpt):
            hh = h[-3:]
            ax.loglog(hh, np.exp(icpt) * hh ** slope, "k--", lw=1, label="fit: slope %.2f" % slope)
        ax.set_title("(%d) %s" % (k + 1, _short(title.split(": ", 1)[-1], 40)), fontsize=7)
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_xlabel("h")
        ax.set_ylabel("error")
        ax.grid(alpha=0.3, which="both")
        ax.legend(loc="best", fontsize=6)
    for k in range(len(titles), nrow * ncol):
        axes[k // ncol][k % ncol].axis("off")
    fig.tight_layout()
    fig.savefig(out)
    plt.close(fig)
    return out


def _short(title, width=48):
    title = title.replace("_", " ")
    return title if len(title) <= width else title[:width - 3] + "..."
