"""Readers for the files the report uses. They read run outputs and check results only; nothing
here recomputes physics (the one computation is the least-squares slope through the finest three
points of a convergence table, the same fit the tests print)."""
import csv
import glob
import io
import math
import os
import platform
import re
import subprocess
import sys
from collections import OrderedDict

import numpy as np


def read_results(path):
    """results.csv lines `case,"metric",tolerance,measured,status`; the last line per
    (case, metric) wins (reruns append). Returns OrderedDict case -> list of dicts."""
    rows = OrderedDict()
    if not os.path.isfile(path):
        return OrderedDict()
    with open(path, newline="", encoding="utf-8", errors="replace") as f:
        for cells in csv.reader(f):
            if not cells or cells[0].startswith("#") or len(cells) < 5:
                continue
            case, metric, tol, measured, status = (c.strip() for c in cells[:5])
            rows[(case, metric)] = dict(case=case, metric=metric, tolerance=tol, measured=measured,
                                        status=status)
    by_case = OrderedDict()
    for (case, _), row in rows.items():
        by_case.setdefault(case, []).append(row)
    return by_case


def read_table_csv(path):
    """A CSV with '#' comment lines and a header 'name [units],...'. Returns (names, units,
    2-D float array, comments); rows that do not parse as numbers become NaN."""
    comments, names, units, data = [], None, None, []
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            if line.startswith("#"):
                comments.append(line.lstrip("# ").rstrip())
                continue
            cells = next(csv.reader(io.StringIO(line)))
            if names is None:
                names, units = [], []
                for c in cells:
                    m = re.match(r"\s*([^\[]*?)\s*(\[(.*)\])?\s*$", c)
                    names.append(m.group(1))
                    units.append(m.group(3) or "")
                continue
            row = []
            for c in cells[:len(names)]:
                try:
                    row.append(float(c))
                except ValueError:
                    row.append(math.nan)
            row += [math.nan] * (len(names) - len(row))
            data.append(row)
    arr = np.array(data, dtype=float).reshape(-1, len(names) if names else 0)
    return names or [], units or [], arr, comments


def read_reference_profile(path):
    """Ghia-style reference: columns y,u,flag (flag non-empty marks an excluded point).
    Returns (coord, value, flagged bool array, comment lines)."""
    comments, coord, value, flagged = [], [], [], []
    with open(path, encoding="utf-8", errors="replace") as f:
        header_seen = False
        for line in f:
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                comments.append(s.lstrip("# "))
                continue
            cells = next(csv.reader(io.StringIO(s)))
            if not header_seen:
                header_seen = True
                continue
            coord.append(float(cells[0]))
            value.append(float(cells[1]))
            flagged.append(len(cells) > 2 and cells[2].strip() != "")
    return np.array(coord), np.array(value), np.array(flagged, dtype=bool), comments


def read_convergence(path):
    """convergence.csv (title,N,h,error,order,fit_order,fit_standard_error,formal_order,
    asserted_min,asserted_max,refined) appended by the convergence tests; the fit (least-squares
    order over the finest three levels and its standard error, computed by the tests through
    metrics::observed_order) and the test's claim (formal order, asserted band, h or dt refined)
    are on a table's finest row. A row with an empty order starts a new table; the last table per
    title wins. Returns OrderedDict title -> dict(N, h, error, order arrays, fit_order, fit_stderr,
    formal, asserted_min, asserted_max: NaN where not written, refined)."""
    tables = OrderedDict()
    if not os.path.isfile(path):
        return tables
    current = {}
    with open(path, newline="", encoding="utf-8", errors="replace") as f:
        for cells in csv.reader(f):
            if len(cells) < 5 or cells[:2] == ["title", "N"]:
                continue
            title = cells[0]
            try:
                n, h, e = int(cells[1]), float(cells[2]), float(cells[3])
            except ValueError:
                continue
            if cells[4].strip() == "" or title not in current:
                current[title] = dict(N=[], h=[], error=[], order=[], fit_order=math.nan,
                                      fit_stderr=math.nan, formal=math.nan, asserted_min=math.nan,
                                      asserted_max=math.nan, refined="h")
                tables.pop(title, None)
                tables[title] = current[title]
            t = current[title]
            t["N"].append(n)
            t["h"].append(h)
            t["error"].append(e)
            t["order"].append(float(cells[4]) if cells[4].strip() else math.nan)
            if len(cells) >= 7 and cells[5].strip():
                t["fit_order"] = float(cells[5])
                t["fit_stderr"] = float(cells[6]) if cells[6].strip() else math.nan
            if len(cells) >= 11 and cells[10].strip():  # the test's claim, on the finest row
                for key, cell in zip(("formal", "asserted_min", "asserted_max"), cells[7:10]):
                    t[key] = float(cell) if cell.strip() else math.nan
                t["refined"] = cells[10].strip()
    return tables


def fit_line(h, e, slope):
    """Intercept of the line of the given slope through the finest three (h, e) in log-log (the
    least-squares intercept for that slope), for drawing the tests' fit; NaN without a slope."""
    h, e = np.asarray(h, float)[-3:], np.asarray(e, float)[-3:]
    ok = (h > 0) & (e > 0) & np.isfinite(e)
    if ok.sum() < 2 or not np.isfinite(slope):
        return math.nan
    return float(np.mean(np.log(e[ok])) - slope * np.mean(np.log(h[ok])))


def read_ctest_logs(build):
    """Per-test status and time from ctest's Testing/Temporary/LastTest*.log (every file; the
    newest entry per test wins). Returns list of dicts name, status, seconds, log."""
    files = sorted(glob.glob(os.path.join(build, "Testing", "Temporary", "LastTest*.log")),
                   key=os.path.getmtime)
    tests = OrderedDict()
    for path in files:
        name = None
        with open(path, encoding="utf-8", errors="replace") as f:
            for line in f:
                m = re.match(r"\s*\d+/\d+ Test: (\S+)", line)
                if m:
                    name = m.group(1)
                    tests.pop(name, None)
                    tests[name] = dict(name=name, status="?", seconds=math.nan,
                                       log=os.path.basename(path))
                    continue
                if name is None:
                    continue
                m = re.match(r"Test time =\s*([0-9.]+) sec", line.strip())
                if m:
                    tests[name]["seconds"] = float(m.group(1))
                    continue
                s = line.strip()
                if s == "Test Passed.":
                    tests[name]["status"] = "pass"
                elif s.startswith("Test Failed"):
                    tests[name]["status"] = "FAIL"
                elif s.startswith("Test Not Run") or "Skipped" in s and s.startswith("Test"):
                    tests[name]["status"] = "skipped"
    return list(tests.values())


def _run(cmd):
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, timeout=20)
        return (out.stdout or out.stderr).strip().splitlines()[0]
    except Exception:  # noqa: BLE001 - a missing tool is reported as such
        return "not available"


def h5_root_attributes(h5_paths):
    """ibms_version, git_commit, start_time, host from the newest HDF5 output found."""
    try:
        import h5py
    except ImportError:
        return {}
    for path in sorted(h5_paths, key=os.path.getmtime, reverse=True):
        try:
            with h5py.File(path, "r") as f:
                attrs = {}
                for key in ("ibms_version", "git_commit", "start_time", "host"):
                    if key in f.attrs:
                        v = f.attrs[key]
                        attrs[key] = v.decode() if isinstance(v, bytes) else str(v)
                attrs["file"] = path
                return attrs
        except OSError:
            continue
    return {}


def output_commits(h5_paths):
    """commit -> number of HDF5 outputs recording it (root attribute git_commit): outputs of more
    than one commit in a build directory are a mix of builds."""
    try:
        import h5py
    except ImportError:
        return {}
    commits = {}
    for path in h5_paths:
        try:
            with h5py.File(path, "r") as f:
                v = f.attrs.get("git_commit", "not recorded")
        except OSError:
            continue
        v = v.decode() if isinstance(v, bytes) else str(v)
        commits[v] = commits.get(v, 0) + 1
    return commits


def build_source_state(build):
    """The source tree the build directory was configured from (CMAKE_HOME_DIRECTORY of
    BUILD/CMakeCache.txt) at report time: (path, its HEAD, `git describe --dirty`, the tracked files
    changed against HEAD), or None when the cache or git cannot say. The outputs record their
    commit only (git_commit), without a dirty flag: the tree they were built from, read right after
    the run (the report is the main job's last step), is the evidence whether that commit is the
    code that ran."""
    path = None
    try:
        with open(os.path.join(build, "CMakeCache.txt"), errors="replace") as f:
            for line in f:
                if line.startswith("CMAKE_HOME_DIRECTORY:"):
                    path = line.split("=", 1)[1].strip()
    except OSError:
        return None
    if not path or not os.path.isdir(path):
        return None
    try:
        head = subprocess.run(["git", "-C", path, "rev-parse", "--short=12", "HEAD"], capture_output=True,
                              text=True, timeout=20)
        status = subprocess.run(["git", "-C", path, "status", "--porcelain", "--untracked-files=no"],
                                capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.SubprocessError):
        return None
    if head.returncode != 0 or status.returncode != 0:
        return None
    changed = [line[3:] for line in status.stdout.splitlines() if line.strip()]
    describe = _run(["git", "-C", path, "describe", "--always", "--dirty", "--abbrev=12"])
    return dict(path=path, head=head.stdout.strip(), describe=describe, changed=changed)


def main_job(build):
    """(level, time from the main job's start to now) from BUILD/workflow_state/main_job.json, which
    scripts/run-main.sh writes when it starts (before the install and the build); the report is the
    main job's last step, so that time is the main job's."""
    import json
    import time
    try:
        with open(os.path.join(build, "workflow_state", "main_job.json")) as f:
            job = json.load(f)
        minutes = (time.time() - float(job["started"])) / 60.0
        return ("%s (%s cores)" % (job["level"], job.get("cores", "?")),
                "%.1f min, install and build included" % minutes)
    except (OSError, ValueError, KeyError):
        return "not recorded (not started by scripts/run-main.sh)", "not recorded"


def environment(build, source, h5_paths):
    """Ordered (label, value) pairs describing versions, commit and machine."""
    import datetime
    env = []
    attrs = h5_root_attributes(h5_paths)
    env.append(("ibms version (from outputs)", attrs.get("ibms_version", "no HDF5 output found")))
    env.append(("git commit (from outputs)", attrs.get("git_commit", "no HDF5 output found")))
    if attrs.get("start_time"):
        env.append(("newest output started", attrs["start_time"] + " on " + attrs.get("host", "?")))
    else:
        env.append(("newest output started", "no HDF5 output; report made on " + platform.node()))
    commits = output_commits(h5_paths)
    if commits:
        env.append(("commits of the outputs", "; ".join("%s (%d output%s)" % (c, n, "s" if n > 1 else "")
                                                         for c, n in sorted(commits.items(), key=lambda x: -x[1]))))
    state = build_source_state(build)
    if state:
        env.append(("build's source tree at report time", "%s: %s, %s" % (
            state["path"], state["describe"],
            "%d tracked file(s) changed against HEAD: %s" % (
                len(state["changed"]), ", ".join(state["changed"][:6]) +
                (" and %d more (git status in %s)" % (len(state["changed"]) - 6, state["path"])
                 if len(state["changed"]) > 6 else ""))
            if state["changed"] else "no tracked file changed against HEAD")))
    else:
        env.append(("build's source tree at report time", "not found (no CMakeCache.txt or no git tree)"))
    env.append(("source tree at report time", _run(["git", "-C", source, "describe", "--always",
                                                    "--dirty", "--abbrev=12"])))
    cache = os.path.join(build, "CMakeCache.txt")
    compiler, build_type = None, None
    if os.path.isfile(cache):
        with open(cache, errors="replace") as f:
            for line in f:
                if line.startswith("CMAKE_CXX_COMPILER:"):
                    compiler = line.split("=", 1)[1].strip()
                elif line.startswith("CMAKE_BUILD_TYPE:"):
                    build_type = line.split("=", 1)[1].strip()
    env.append(("compiler (c++ --version)", _run(["c++", "--version"])))
    if compiler:
        env.append(("compiler used by the build", compiler + " (" + (build_type or "?") + ")"))
    env.append(("build type", build_type or "not found (no CMakeCache.txt)"))
    cpu = "unknown"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    cpu = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    env.append(("CPU", "%s, %d logical cores" % (cpu, os.cpu_count() or 0)))
    os_name = platform.system()
    try:
        with open("/etc/os-release") as f:
            for line in f:
                if line.startswith("PRETTY_NAME="):
                    os_name = line.split("=", 1)[1].strip().strip('"')
    except OSError:
        pass
    env.append(("operating system", "%s, kernel %s" % (os_name, platform.release())))
    env.append(("report date", datetime.datetime.now().astimezone().strftime("%Y-%m-%d %H:%M %Z")))
    level, elapsed = main_job(build)
    env.append(("main job level", level))
    env.append(("main job time to this report", elapsed))
    env.append(("Python", sys.version.split()[0] + " (" + sys.executable + ")"))
    import matplotlib
    env.append(("numpy / matplotlib", np.__version__ + " / " + matplotlib.__version__))
    try:
        import h5py
        env.append(("h5py / HDF5", h5py.version.version + " / " + h5py.version.hdf5_version))
    except ImportError:
        env.append(("h5py", "not installed"))
    env.append(("LaTeX", _run(["pdflatex", "--version"])))
    return env
