#!/usr/bin/python3
"""Compares a regenerated ibms reference CSV with the shipped one (the `slow` tests
<case>_reference_regenerates, validation/CMakeLists.txt; docs/compare.md).

usage: compare-reference.py SHIPPED REGENERATED ABS REL
       compare-reference.py --mean-path T0 T1 SHIPPED REGENERATED REL
       compare-reference.py --extrema T0 SHIPPED REGENERATED REL

Lines starting with '#' (the provenance header: commits, paths, run time) are ignored in both
files. The first remaining line is the header and must be identical; then both files must have
the same number of rows, every row as many cells as the header, and every cell a finite number.
A cell passes if |regenerated - shipped| <= ABS + REL * |shipped|. Prints the largest absolute
and relative deviation of every column and the worst cell (relative to its allowance).
--mean-path (trajectory files `time, particle, x, y, ...`, chaotic cases): the same header and
numeric cells are required, the row count may differ; the gated figure is the particles' mean
centroid path length over T0 <= t <= T1 (chords between consecutive rows of a particle with both
ends inside), |regenerated / shipped - 1| <= REL.
--extrema (periodic force histories `time, ...`, whose phase round-off sets: the vortex shedding
of DFG 2D-2 grows from the round-off of the start, and FFTW's measured plans differ between runs of
one binary, so the shedding's phase at t = 8 differs by ~1e-3 of a period between two runs): the same
header (first column time) and numeric cells are required, the row count may differ but both
series must start and end within one output interval of each other; gated are the largest,
smallest and mean value of every column but the first over t >= T0, each within REL times the
largest |value| of the shipped column there (REL itself for a column of zeros).
Exit 0: every cell passes; 1: a cell is outside the tolerance; 2: different structure or a
non-numeric cell (either file).
"""
import math
import sys


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(2)


def read(path):
    try:
        with open(path) as f:
            lines = [(n + 1, l.rstrip("\n")) for n, l in enumerate(f) if not l.startswith("#")]
    except OSError as e:
        fail("%s: %s" % (path, e))
    lines = [(n, l) for n, l in lines if l.strip() != ""]
    if not lines:
        fail("%s: no header" % path)
    header = lines[0][1].split(",")
    rows = []
    for n, l in lines[1:]:
        cells = l.split(",")
        if len(cells) != len(header):
            fail("%s:%d: %d cells, header has %d" % (path, n, len(cells), len(header)))
        row = []
        for c in cells:
            try:
                v = float(c)
            except ValueError:
                fail("%s:%d: not a number: %r" % (path, n, c))
            if not math.isfinite(v):
                fail("%s:%d: not finite: %r" % (path, n, c))
            row.append(v)
        rows.append((n, row))
    return header, rows


def mean_path(rows, t0, t1):
    tracks = {}
    for _, r in rows:
        tracks.setdefault(int(r[1]), []).append((r[0], r[2], r[3]))
    total = 0.0
    for pts in tracks.values():
        for (ta, xa, ya), (tb, xb, yb) in zip(pts, pts[1:]):
            if ta >= t0 and tb <= t1:
                total += math.hypot(xb - xa, yb - ya)
    return total / len(tracks), len(tracks)


def main_mean_path():
    t0, t1, shipped, regenerated, tol_rel = sys.argv[2:7]
    t0, t1, tol_rel = float(t0), float(t1), float(tol_rel)
    h0, r0 = read(shipped)
    h1, r1 = read(regenerated)
    if h0 != h1:
        fail("headers differ: %s has %r, %s has %r" % (shipped, h0, regenerated, h1))
    if h0[:4] != ["time [-]", "particle [-]", "x [-]", "y [-]"]:
        fail("%s: not a trajectory file (time, particle, x, y, ...): %r" % (shipped, h0))
    p0, n0 = mean_path(r0, t0, t1)
    p1, n1 = mean_path(r1, t0, t1)
    if n0 != n1:
        fail("%s has %d particles, %s has %d" % (shipped, n0, regenerated, n1))
    dev = p1 / p0 - 1.0
    print("%s: mean path %g <= t <= %g: shipped %.6g, regenerated %.6g (%+.2f %%; %d and %d rows); tolerance %.3g %%"
          % (shipped, t0, t1, p0, p1, 100 * dev, len(r0), len(r1), 100 * tol_rel))
    if abs(dev) > tol_rel:
        print("FAIL: mean path outside the tolerance")
        sys.exit(1)
    print("pass")


def main_extrema():
    t0, shipped, regenerated, tol_rel = sys.argv[2:6]
    t0, tol_rel = float(t0), float(tol_rel)
    h0, r0 = read(shipped)
    h1, r1 = read(regenerated)
    if h0 != h1:
        fail("headers differ: %s has %r, %s has %r" % (shipped, h0, regenerated, h1))
    if not h0[0].startswith("time"):
        fail("%s: the first column is not time: %r" % (shipped, h0[0]))
    a = [r for _, r in r0 if r[0] >= t0]
    b = [r for _, r in r1 if r[0] >= t0]
    if len(a) < 2 or len(b) < 2:
        fail("fewer than two rows at t >= %g (%d shipped, %d regenerated)" % (t0, len(a), len(b)))
    spacing = max(y[0] - x[0] for x, y in zip(a, a[1:]))
    if abs(b[-1][0] - a[-1][0]) > spacing or abs(b[0][0] - a[0][0]) > spacing:
        print("FAIL: the regenerated series spans %.10g .. %.10g, the shipped %.10g .. %.10g (largest spacing %.3g)"
              % (b[0][0], b[-1][0], a[0][0], a[-1][0], spacing))
        sys.exit(1)
    bad = 0
    print("%s: t >= %g, %d and %d rows; tolerance %.3g of each column's largest |value|" % (shipped, t0, len(a), len(b), tol_rel))
    for k in range(1, len(h0)):
        col0 = [r[k] for r in a]
        col1 = [r[k] for r in b]
        scale = max(abs(v) for v in col0)
        allowance = tol_rel * scale if scale > 0.0 else tol_rel
        for name, f in (("max", max), ("min", min), ("mean", lambda c: sum(c) / len(c))):
            x, y = f(col0), f(col1)
            ok = abs(y - x) <= allowance
            bad += not ok
            print("  %-44s %-4s shipped %.10g regenerated %.10g  |d| %.3e  %s" %
                  (h0[k], name, x, y, abs(y - x), "pass" if ok else "FAIL (allowance %.3e)" % allowance))
    if bad:
        print("FAIL: %d figures outside the tolerance" % bad)
        sys.exit(1)
    print("pass")


def main():
    if len(sys.argv) == 7 and sys.argv[1] == "--mean-path":
        return main_mean_path()
    if len(sys.argv) == 6 and sys.argv[1] == "--extrema":
        return main_extrema()
    if len(sys.argv) != 5:
        print(__doc__)
        sys.exit(2)
    shipped, regenerated = sys.argv[1], sys.argv[2]
    tol_abs, tol_rel = float(sys.argv[3]), float(sys.argv[4])
    h0, r0 = read(shipped)
    h1, r1 = read(regenerated)
    if h0 != h1:
        fail("headers differ: %s has %r, %s has %r" % (shipped, h0, regenerated, h1))
    if len(r0) != len(r1):
        fail("%s has %d rows, %s has %d" % (shipped, len(r0), regenerated, len(r1)))
    max_abs = [0.0] * len(h0)
    max_rel = [0.0] * len(h0)
    worst = (0.0, None)  # (deviation / allowance, description)
    bad = 0
    for (n0, a), (n1, b) in zip(r0, r1):
        for k, (x, y) in enumerate(zip(a, b)):
            d = abs(y - x)
            max_abs[k] = max(max_abs[k], d)
            if x != 0.0:
                max_rel[k] = max(max_rel[k], d / abs(x))
            allowed = tol_abs + tol_rel * abs(x)
            ratio = d / allowed if allowed > 0 else (0.0 if d == 0 else math.inf)
            if d > allowed:
                bad += 1
            if ratio > worst[0]:
                worst = (ratio, "line %d (shipped) / %d (regenerated), column %r: shipped %.10g, regenerated %.10g"
                         % (n0, n1, h0[k], x, y))
    print("%s: %d rows x %d columns; tolerance |d| <= %g + %g |shipped|" % (shipped, len(r0), len(h0), tol_abs, tol_rel))
    for k, name in enumerate(h0):
        print("  %-45s max |d| %.3e  max |d|/|shipped| %.3e" % (name, max_abs[k], max_rel[k]))
    if worst[1]:
        print("  worst cell (%.3g of its allowance): %s" % (worst[0], worst[1]))
    if bad:
        print("FAIL: %d cells outside the tolerance" % bad)
        sys.exit(1)
    print("pass")


main()
