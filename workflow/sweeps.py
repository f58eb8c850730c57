"""Sweep files (docs/workflow.md): a scene and a parameter grid, expanded into independent runs
whose metrics are collected into one CSV per sweep.

    name = "settling_disk_convergence"          # optional; default: the file name without .toml
    title = "Settling disk: grid convergence"   # for the report
    scene = "validation/settling_disk/scene.toml"   # relative to the source tree
    accept_exit_codes = [0, 3]                  # exit codes that count as a finished run
    [grid]                                      # every combination of these lists (outer product)
    "domain.cells_x" = [100, 150, 200]
    [linked]                                    # per point, from the grid values (arithmetic only)
    "domain.cells_y" = "3 * cells_x"
    "bodies.0.n_surface_points" = "cells_x * 2 // 5"
    [metrics]
    compare = "settling_disk"                   # `ibms compare CASE FILE...` on the run's outputs
    files = ["{output}_bodies.csv"]             # {output}: the run's output path without .h5
    [metrics.columns]                           # CSV column = metric whose text starts with this
    error_published = "|max settling speed / 5.5 cm/s (published) - 1|"
    [plot]                                      # the report's figure
    x = "domain.cells_x"
    y = ["error_published"]
    log = true

In an expression a grid key is known by its last part (`cells_x`) when that is unique, and always
by its full name with dots as underscores (`domain_cells_x`). Every point is one `ibms run` with
the `--set` values of the point; its metrics are the measured values of the gated lines of
`ibms compare` and the submitted values of its info lines, plus `seconds` (wall time of the run)
and `exit_code`.
"""
import ast
import csv
import hashlib
import itertools
import json
import operator
import os
import re
import subprocess
import time
import tomllib

_OPS = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
        ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod, ast.Pow: operator.pow,
        ast.USub: operator.neg, ast.UAdd: operator.pos}
_FUNCS = {"int": int, "round": round, "min": min, "max": max, "float": float}


def evaluate(expr, names):
    """An arithmetic expression over `names` (numbers, + - * / // % **, int round min max)."""
    def ev(node):
        if isinstance(node, ast.Expression):
            return ev(node.body)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)):
            return node.value
        if isinstance(node, ast.Name):
            if node.id not in names:
                raise ValueError("unknown name '%s' in '%s' (known: %s)" % (node.id, expr, ", ".join(sorted(names))))
            return names[node.id]
        if isinstance(node, ast.BinOp) and type(node.op) in _OPS:
            return _OPS[type(node.op)](ev(node.left), ev(node.right))
        if isinstance(node, ast.UnaryOp) and type(node.op) in _OPS:
            return _OPS[type(node.op)](ev(node.operand))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in _FUNCS:
            return _FUNCS[node.func.id](*[ev(a) for a in node.args])
        raise ValueError("not allowed in a linked key: '%s'" % expr)
    return ev(ast.parse(str(expr), mode="eval"))


def _value(v):
    if isinstance(v, float) and v.is_integer() and abs(v) < 1e15:
        return repr(v)
    return str(v).lower() if isinstance(v, bool) else str(v)


def _point_id(values):
    parts = []
    for k, v in values.items():
        parts.append("%s=%s" % (k.split(".")[-1], _value(v)))
    return re.sub(r"[^A-Za-z0-9_.=-]", "_", "_".join(parts))


def load(path, source, build):
    with open(path, "rb") as f:
        d = tomllib.load(f)
    name = d.get("name", os.path.splitext(os.path.basename(path))[0])
    if not re.fullmatch(r"[A-Za-z0-9_-]+", name):
        raise ValueError("%s: sweep name '%s' must be letters, digits, _ and -" % (path, name))
    if "scene" not in d or "grid" not in d:
        raise ValueError("%s: a sweep needs `scene` and a [grid] table" % path)
    scene = os.path.join(source, d["scene"])
    grid = d["grid"]
    for k, v in grid.items():
        if not isinstance(v, list) or not v:
            raise ValueError("%s: grid key %s needs a non-empty list" % (path, k))
    linked = d.get("linked", {})
    last = {}
    for k in grid:
        last.setdefault(k.split(".")[-1], []).append(k)
    out_dir = os.path.join(build, "sweeps", name)
    points = []
    for combo in itertools.product(*grid.values()):
        values = dict(zip(grid.keys(), combo))
        names = {k.replace(".", "_"): v for k, v in values.items()}
        names.update({s: values[ks[0]] for s, ks in last.items() if len(ks) == 1})
        sets = dict(values)
        for k, expr in linked.items():
            sets[k] = evaluate(expr, names)
        pid = _point_id(values)
        set_args = ["%s=%s" % (k, _value(v)) for k, v in sets.items()]
        points.append(dict(id=pid, values=values, sets=set_args, output=os.path.join(out_dir, pid),
                           definition=hashlib.sha256(json.dumps([set_args, d.get("metrics", {}),
                                                                 d.get("accept_exit_codes", [0])]).encode()).hexdigest()[:16]))
    if len({p["id"] for p in points}) != len(points):
        raise ValueError("%s: two grid points have the same id" % path)
    metrics = d.get("metrics", {})
    inputs = [scene, path]
    return dict(name=name, file=path, title=d.get("title", name), scene=scene, grid=grid, linked=linked,
                points=points, metrics=metrics, accept=d.get("accept_exit_codes", [0]),
                plot=d.get("plot", {}), inputs=inputs, out_dir=out_dir)


_GATED = re.compile(r"^\s+(\S.*?)\s{2,}(\S+)\s+(\S+)\s+(pass|FAIL)\s*$")
_INFO = re.compile(r"^\s+(\S.*?)\s{2,}submitted (\S+), reference (\S+)\s+info\s*$")


def parse_compare(text):
    """Metric text -> value from `ibms compare` output (measured for gated lines, submitted for info)."""
    found = {}
    for line in text.splitlines():
        m = _GATED.match(line)
        if m and m.group(1) != "metric":
            found[m.group(1)] = float(m.group(3))
            continue
        m = _INFO.match(line)
        if m:
            found[m.group(1)] = float(m.group(2))
    return found


def _assignments(sets):
    """`key=value` strings as a dict, numbers compared as numbers and strings without their quotes."""
    out = {}
    for s in sets:
        k, _, v = s.partition("=")
        v = v.strip()
        try:
            out[k.strip()] = float(v)
        except ValueError:
            out[k.strip()] = v.strip('"').strip("'")
    return out


_PLAIN_OPTIONS = {"--set", "-o", "--quiet", "-P"}  # and -D... of run_to_wall.cmake


def _plain_run(command):
    """A run of a scene with --set values and an output only (no restart or other option that
    would make it another run than the sweep point's)."""
    return all(not a.startswith("-") or a in _PLAIN_OPTIONS or a.startswith("-D") for a in command)


def shared_runs(sweeps, jobs):
    """(sweep, point id) -> name of the validation run of the level that is the same run (the same
    scene and the same --set values, an output file named, no other option): the point reads that
    run's output instead of running it again."""
    runs = {}
    for name, j in jobs.items():
        if j["kind"] == "run" and j.get("scene") and j.get("output") and _plain_run(j["command"]):
            runs.setdefault(os.path.realpath(j["scene"]), []).append((_assignments(j["sets"]), name))
    out = {}
    for sname, sw in sweeps.items():
        if not sw.get("scene"):
            continue
        for p in sw["points"]:
            wanted = _assignments(p["sets"])
            for sets, name in runs.get(os.path.realpath(sw["scene"]), []):
                if sets == wanted:
                    out[(sname, p["id"])] = name
                    break
    return out


def _add_metrics(sweep, output, ibms, result):
    """The sweep's metrics of the run whose output path (without .h5) is `output`, into result."""
    m = sweep["metrics"]
    if result["status"] == "pass" and m.get("compare"):
        files = [f.format(output=output) for f in m.get("files", [])]
        c = subprocess.run([ibms, "compare", m["compare"]] + files, capture_output=True, text=True)
        found = parse_compare(c.stdout)
        cols = m.get("columns")
        if cols:
            for col, prefix in cols.items():
                hits = [v for k, v in found.items() if k.startswith(prefix)]
                result["metrics"][col] = hits[0] if hits else None
        else:
            result["metrics"] = found
        result["compare_exit_code"] = c.returncode


def _write(sweep, point, result, out_json):
    tmp = out_json + ".tmp"
    with open(tmp, "w") as f:
        json.dump(result, f, indent=1)
    os.replace(tmp, out_json)
    print("sweep %s %-40s %s %.1f s%s" % (sweep["name"], point["id"], result["status"], result["seconds"] or 0.0,
                                          " (run %s)" % result["run"] if result.get("run") else ""), flush=True)


def run_point(sweep, point, ibms, out_json, threads=1):
    os.makedirs(os.path.dirname(point["output"]), exist_ok=True)
    cmd = [ibms, "run", sweep["scene"], "-o", point["output"] + ".h5", "--quiet"]
    for s in point["sets"]:
        cmd += ["--set", s]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    start = time.time()
    p = subprocess.run(cmd, capture_output=True, text=True, cwd=os.path.dirname(point["output"]), env=env)
    seconds = time.time() - start
    result = dict(sweep=sweep["name"], point=point["id"], values=point["values"], sets=point["sets"],
                  exit_code=p.returncode, seconds=round(seconds, 3),
                  status="pass" if p.returncode in sweep["accept"] else "FAIL",
                  stderr=p.stderr[-2000:], metrics={})
    _add_metrics(sweep, point["output"], ibms, result)
    _write(sweep, point, result, out_json)


def reuse_point(sweep, point, run, run_status, ibms, out_json):
    """A point that is a validation run (shared_runs): its metrics from that run's output, its
    seconds and exit code from the run's status file; a run that did not pass gives a point that
    did not either."""
    st = {}
    try:
        with open(run_status) as f:
            st = json.load(f)
    except (OSError, ValueError):
        pass
    output = os.path.splitext(run["output"])[0]
    result = dict(sweep=sweep["name"], point=point["id"], values=point["values"], sets=point["sets"],
                  exit_code=st.get("exit_code"), seconds=st.get("seconds"), run=run["name"],
                  status="pass" if st.get("status") == "pass" else "not run", stderr="", metrics={})
    _add_metrics(sweep, output, ibms, result)
    _write(sweep, point, result, out_json)


def collect(sweep, json_files, out_csv):
    rows = []
    for path in json_files:
        with open(path) as f:
            rows.append(json.load(f))
    keys = list(sweep["grid"].keys())
    metric_names = list(sweep["metrics"].get("columns", {}).keys())
    for r in rows:
        for k in r["metrics"]:
            if k not in metric_names:
                metric_names.append(k)
    os.makedirs(os.path.dirname(out_csv), exist_ok=True)
    with open(out_csv, "w", newline="") as f:
        f.write("# sweep %s: %s\n" % (sweep["name"], sweep["title"]))
        f.write("# scene %s; linked keys: %s\n" % (os.path.relpath(sweep["scene"], os.path.dirname(os.path.dirname(sweep["file"]))),
                                                   "; ".join("%s = %s" % kv for kv in sweep["linked"].items()) or "none"))
        shared = ["%s (%s)" % (r["point"], r["run"]) for r in rows if r.get("run")]
        if shared:
            f.write("# points read from the validation runs of the same scene and values, not run again: %s\n"
                    % ", ".join(shared))
        if sweep["plot"]:
            f.write("# plot %s\n" % json.dumps(sweep["plot"]))
        w = csv.writer(f)
        w.writerow(keys + ["status", "exit_code", "seconds"] + metric_names)
        for r in rows:
            w.writerow([r["values"][k] for k in keys] + [r["status"], r["exit_code"], r["seconds"]] +
                       ["" if r["metrics"].get(k) is None else r["metrics"][k] for k in metric_names])
