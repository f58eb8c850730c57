#!/usr/bin/python3
"""The unit test reference_compare_rejects_changes (validation/CMakeLists.txt): scripts/compare-reference.py
must pass a shipped reference against itself (with its provenance lines changed) and reject mutated
copies of it: one number changed by more than the tolerance, a non-numeric cell, a missing row, a
different header, an extra column.
usage: test-compare-reference.py SHIPPED_CSV WORK_DIR ABS REL
"""
import os
import subprocess
import sys

shipped, work, tol_abs, tol_rel = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
compare = os.path.join(os.path.dirname(os.path.abspath(__file__)), "compare-reference.py")
os.makedirs(work, exist_ok=True)
lines = open(shipped).read().splitlines(True)
comments = [l for l in lines if l.startswith("#")]
body = [l for l in lines if not l.startswith("#")]
header, rows = body[0], body[1:]
mid = len(rows) // 2


def changed_cell(row, k, new):
    cells = row.rstrip("\n").split(",")
    cells[k] = new
    return ",".join(cells) + "\n"


def first_value(row, k):
    return float(row.rstrip("\n").split(",")[k])


last = len(header.split(",")) - 1
v = first_value(rows[mid], last)
bumped = v + 10 * (tol_abs + tol_rel * abs(v)) + 1e-12
within = v + 0.1 * (tol_abs + tol_rel * abs(v))
cases = {  # name: (file body, expected exit code)
    "identical, other provenance lines": (["# regenerated at another commit\n"] + body, 0),
    "one number changed within the tolerance": ([header] + rows[:mid] + [changed_cell(rows[mid], last, "%.17g" % within)] + rows[mid + 1:], 0),
    "one number changed": ([header] + rows[:mid] + [changed_cell(rows[mid], last, "%.17g" % bumped)] + rows[mid + 1:], 1),
    "non-numeric cell": ([header] + rows[:mid] + [changed_cell(rows[mid], 0, "nan?")] + rows[mid + 1:], 2),
    "nan cell": ([header] + rows[:mid] + [changed_cell(rows[mid], 0, "nan")] + rows[mid + 1:], 2),
    "missing row": ([header] + rows[:mid] + rows[mid + 1:], 2),
    "different header": ([header.replace(",", ",x", 1)] + rows, 2),
    "extra column": ([header.rstrip("\n") + ",extra\n"] + [r.rstrip("\n") + ",0\n" for r in rows], 2),
}
failed = 0
# --extrema (periodic histories, tolerance 1e-3, window from the middle row on): the values moved
# by one row against the times (another phase: not identical, within the tolerance) pass, a column
# scaled by 1 + 1e-2 fails, a series cut at three quarters fails.
extrema_rel = 1e-3
def scaled(row, k, factor):
    cells = row.rstrip("\n").split(",")
    cells[k] = "%.17g" % (float(cells[k]) * factor)
    return ",".join(cells) + "\n"


def shifted(rows):
    values = [r.rstrip("\n").split(",") for r in rows]
    return [",".join([a[0]] + b[1:]) + "\n" for a, b in zip(values, values[1:])] + [rows[-1]]


t0 = first_value(rows[mid], 0)
extrema_cases = {
    "extrema: values one row later (another phase)": ([header] + shifted(rows), 0),
    "extrema: last column scaled by 1 + 1e-2": ([header] + [scaled(r, last, 1 + 10 * extrema_rel) for r in rows], 1),
    "extrema: series cut at three quarters": ([header] + rows[:3 * len(rows) // 4], 1),
}
def check(name, path, text, arguments, expected):
    """Writes text to path, runs the comparer with arguments; True if it exits with expected."""
    with open(path, "w") as f:
        f.writelines(text)
    got = subprocess.run([sys.executable, compare] + arguments, stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    ok = got.returncode == expected
    print("%s: %s (exit %d, expected %d)" % ("ok" if ok else "WRONG", name, got.returncode, expected))
    if not ok:
        print(got.stdout)
    return ok


for n, (name, (text, expected)) in enumerate(extrema_cases.items()):
    path = os.path.join(work, "extrema_%d.csv" % n)
    failed += not check(name, path, comments + text, ["--extrema", str(t0), shipped, path, str(extrema_rel)], expected)
for n, (name, (text, expected)) in enumerate(cases.items()):
    path = os.path.join(work, "mutation_%d.csv" % n)
    failed += not check(name, path, text if n == 0 else comments + text,
                        [shipped, path, str(tol_abs), str(tol_rel)], expected)
sys.exit(1 if failed else 0)
