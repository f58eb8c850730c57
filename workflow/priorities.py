"""Job priorities of the workflow: the longest jobs start first (docs/workflow.md, "Order").

Snakemake 7.21 has one `priority` per rule, and its local scheduler starts, whenever cores free up,
the ready jobs that maximise the sum of their priorities (ILP; the greedy fallback takes the
highest priority that fits). So the Snakefile defines each job rule once per *priority class*
(`case_run_p7`, `bench_p1010`, ...), each class a rule whose wildcard constraint lists its members:
the same jobs, commands and outputs, only the order changes.

A job's cost, in order of preference:
  1. its last measured wall time: the seconds of its status file in BUILD/workflow_state (tests,
     sweep points, the verification), else the times file BUILD/workflow_times.json, into which
     the workflow copies its jobs' status files when it ends (`record`, from the Snakefile's
     onsuccess / onerror; status files are removed before a job reruns and by forget-failed, the
     times file keeps the time; a bench's status file does not name its level, so benches come
     from the times file only, keyed by level), else for a ctest test ctest's own average time of
     the same test (BUILD/Testing/Temporary/CTestCostData.txt, written by `ctest`, e.g.
     scripts/run-tests.sh). A job that did not pass (killed, timed out) counts at least its
     fallback below: its time is a lower bound;
  2. for a case run or sweep point not run yet: the cell-steps of `ibms info`, when cached in
     BUILD/workflow_estimates.json (made by the Slurm mode, workflow/estimates.py), times
     estimates.SECONDS_PER_CELL_STEP (the measured cost of a cell-step, no margin); `ibms info`
     is not called for it: on a clean build its 2-12 s per scene would cost more than the order
     saves;
  3. the jobs' times measured on the 2-core development machine: workflow/measured_seconds.json
     for case runs, checks and sweep points (a clean clone has timed nothing, and without them
     its longest runs started last), FALLBACK_SECONDS for the benches per bench level and the ctest
     verification; else UNKNOWN_SECONDS (CHECK_SECONDS for a check).
A sweep point that is a validation run of the level (sweeps.shared_runs) reads that run's output:
it costs a check and waits for the run.

Class of a cost: 0 below 1 s, else floor(log2(seconds)) + 1 (factor-2 bins, at most MAX_CLASS).
A job that claims every core (a timing bench, the ctest verification) gets EXCLUSIVE_OFFSET on top
(`exclusive: first`, the default) so that one of them outranks any set of one-core jobs that could
fill the cores instead (the ILP compares sums): the exclusive jobs then run back to back at the
start, longest first, and the one-core jobs fill both cores after them, longest first. With
`exclusive: last` there is no offset; Snakemake then starts an exclusive job only when both cores
are free and no one-core job is ready, i.e. after the one-core jobs. On a fixed number of cores
both orders take the same time (an exclusive job blocks every core wherever it runs; `simulate`
shows it on the measured times); on a cluster the first one starts the longest job first.
"""
import glob
import json
import math
import os

import estimates
from runner import read_json

MAX_CLASS = 16
EXCLUSIVE_OFFSET = 1000  # > MAX_CLASS x cores: one exclusive job outranks any set of one-core jobs
UNKNOWN_SECONDS = 10.0   # a case run or sweep point with neither a measured time nor an estimate
CHECK_SECONDS = 0.2      # a check, gate or compare of a case (measured 0.01-0.25 s)
REPORT_SECONDS = 30.0    # the PDF report (LaTeX); an assumption, the same for every order

# Benches whose printed figures are accuracy or stability maps, not timings (their sources read no
# clock: errors, outcomes stable / unstable / stopped, energies, counts): they run as ordinary
# one-core jobs beside the others. Every other bench times something and claims every core.
ONE_CORE_BENCHES = {
    "stability": "maps of outcome (stable, unstable, blow-up stopped, too deep) over time step and "
                 "spring / DEM stiffness, with area change, speed ratio and contact-pair counts",
    "fluid_stability": "maps of outcome over CFL number and cell Reynolds number, with measured CFL, "
                       "energy ratios and speeds, beside the von Neumann limit",
    "forcing_passes": "errors and rim slip per forcing-pass count; its ms per step compare passes "
                      "measured one after another in one process on one thread: a ratio, and a "
                      "one-thread job on the other core shares no core with it",
    "work_precision_bodies": "the DFG cylinders' errors per grid under both couplings; their times "
                             "give the ratio of the two couplings' time to 3 % on 2D-2's max c_D, "
                             "both measured in one process on one thread beside the same neighbours",
}

# Seconds of the benches and of the ctest verification on the shared 2-core machine, used until
# the workflow has measured them in this build. Default level: the clean-clone run of f07dec1
# (docs/workflow.md), bench_work_precision's 273 s split between its fluid cases (100 s) and its
# cylinders (173 s); the verification `ctest -j 2 -L "unit|convergence"` 150 s. Quick: the same
# cylinder grids as default, the fluid cases 1 min (bench/README.md), bench_forcing_passes a guess
# (a third of its grids); full: bench/README.md's "adds 39 min" for the cylinders, forcing passes a
# guess. bench_forcing_passes at default: 105 s measured alone on one core (the disk at 1 and 3
# passes); bench_scale --report 21 s alone on one core.
FALLBACK_SECONDS = {
    ("bench", "default"): {"work_precision": 100, "work_precision_bodies": 173, "fluid_stability": 202,
                           "forcing_passes": 105, "stability": 8, "overhead": 2, "scale": 21},
    ("bench", "quick"): {"work_precision": 60, "work_precision_bodies": 173, "fluid_stability": 201,
                         "forcing_passes": 30, "stability": 40, "overhead": 5, "scale": 21},
    ("bench", "full"): {"work_precision": 600, "work_precision_bodies": 2600, "fluid_stability": 201,
                        "forcing_passes": 900, "stability": 40, "overhead": 5, "scale": 21},
    ("verification", None): {"verification": 150},
}
BENCH_UNKNOWN_SECONDS = 300.0


def priority_class(seconds):
    if seconds is None or seconds < 1:
        return 0
    return min(MAX_CLASS, int(math.floor(math.log2(seconds))) + 1)


def priority(seconds, cores, exclusive="first"):
    return priority_class(seconds) + (EXCLUSIVE_OFFSET if cores > 1 and exclusive == "first" else 0)


def bench_cores(name, all_cores):
    return 1 if name in ONE_CORE_BENCHES else all_cores


# ---- measured times

def times_path(build):
    # beside, not inside, the workflow's state directory (the Slurm test removes that one)
    return os.path.join(os.path.abspath(build), "workflow_times.json")


def key(kind, name, level=None):
    """Key of a job in the times files: run/<test>, check/<test>, sweep/<sweep>/<point>,
    bench/<bench>/<level> (a bench's work depends on its level), verification."""
    if kind == "verification":
        return "verification"
    if kind == "bench":
        return "bench/%s/%s" % (name, level)
    return "%s/%s" % (kind, name)


def _status_paths(wf, planned, bench_level):
    """key -> status file of every job of the plan that has one."""
    out = {}
    for v in planned.values():
        kind, name = v["kind"], v["name"]
        if kind in ("run", "check"):
            out[key(kind, name)] = os.path.join(wf, "tests", name + ".status")
        elif kind == "sweep":
            out[key(kind, name)] = os.path.join(wf, "sweeps", name + ".json")
        elif kind == "bench":
            out[key(kind, name, bench_level)] = os.path.join(wf, "bench", name + ".status")
        elif kind == "verification":
            out["verification"] = os.path.join(wf, "verification.status")
    return out


def record(build, wf, planned, bench_level):
    """At the end of a workflow run (main process only, so one writer): the seconds and verdict of
    the status file of every job of the plan go to the times file. Never raises: a missing time
    only makes the next order less good."""
    try:
        times = read_json(times_path(build)) or {}
        for k, path in _status_paths(wf, planned, bench_level).items():
            st = read_json(path)
            if st and st.get("seconds") is not None:
                times[k] = {"seconds": st["seconds"], "status": st.get("status"), "finished": st.get("finished")}
        tmp = "%s.%d.tmp" % (times_path(build), os.getpid())
        with open(tmp, "w") as f:
            json.dump(times, f, indent=1, sort_keys=True)
        os.replace(tmp, times_path(build))
    except Exception:  # noqa: BLE001
        pass


def measured(build, wf):
    """key -> (seconds, status) of the jobs' last runs: the status files of the workflow state
    (tests, sweep points, verification), else the times file (benches from there only: a bench's
    status file does not say its level); "ctest/<test>" -> ctest's average time of a test."""
    out = {}
    for k, v in (read_json(times_path(build)) or {}).items():
        if isinstance(v, dict):
            out[k] = (v.get("seconds"), v.get("status"))
    for path in glob.glob(os.path.join(wf, "tests", "*.status")):
        st = read_json(path)
        if st and st.get("kind") in ("run", "check"):
            out[key(st["kind"], os.path.basename(path)[:-len(".status")])] = (st.get("seconds"), st.get("status"))
    for path in glob.glob(os.path.join(wf, "sweeps", "*", "*.json")):
        st = read_json(path)
        if st:
            name = "%s/%s" % (os.path.basename(os.path.dirname(path)), os.path.basename(path)[:-len(".json")])
            out[key("sweep", name)] = (st.get("seconds"), st.get("status"))
    st = read_json(os.path.join(wf, "verification.status"))
    if st:
        out["verification"] = (st.get("seconds"), st.get("status"))
    try:  # ctest's averages of the same tests: "name repeats seconds" lines, up to "---"
        with open(os.path.join(build, "Testing", "Temporary", "CTestCostData.txt")) as f:
            for line in f:
                if line.startswith("---"):
                    break
                parts = line.split()
                if len(parts) == 3:
                    out["ctest/" + parts[0]] = (float(parts[2]), "pass")
    except (OSError, ValueError):
        pass
    return out


def _with_fallback(m, fallback):
    """A measured time when there is one (at least the fallback when the job did not pass)."""
    if m is None or m[0] is None:
        return fallback, "estimate"
    seconds, status = float(m[0]), m[1]
    if status in ("pass", "skipped"):
        return seconds, "measured"
    if status == "not run" or seconds <= 0:
        return fallback, "estimate"
    return max(seconds, fallback), "measured (%s), at least the estimate" % status


SHIPPED_PATH = os.path.join(os.path.dirname(os.path.abspath(__file__)), "measured_seconds.json")
_shipped = None


def shipped_seconds():
    """key -> seconds of workflow/measured_seconds.json: the jobs' times measured on the project's
    machine, for the order on a build that has timed nothing yet (a clean clone)."""
    global _shipped
    if _shipped is None:
        _shipped = (read_json(SHIPPED_PATH) or {}).get("seconds", {})
    return _shipped


def run_seconds(scene, sets, m, ibms, wf, shipped=None):
    """A run's or sweep point's seconds: measured in this build, else its `ibms info` estimate when
    cached, else the shipped time, else UNKNOWN_SECONDS."""
    cost = estimates.cached_cost(scene, sets, wf) if scene else None
    if cost:
        fallback, how = cost * estimates.SECONDS_PER_CELL_STEP, "ibms info estimate"
    elif shipped is not None:
        fallback, how = shipped, "shipped time"
    else:
        fallback, how = UNKNOWN_SECONDS, "estimate"
    seconds, source = _with_fallback(m, fallback)
    return seconds, (how if source == "estimate" else source)


def _test_time(times, kind, name):
    """The job's own measured time, else ctest's average for the same test."""
    m = times.get(key(kind, name))
    if m is None and "ctest/" + name in times:
        return times["ctest/" + name], " (ctest average)"
    return m, ""


# ---- the plan: every job with its cost, cores, priority and the jobs it waits for

def plan(jobs, benches, bench_level, sweeps, build, wf, ibms, all_cores, exclusive="first",
         one_core_benches=None, times=None, shared_points=None):
    """jobs: ctest_jobs.load_jobs of the level; benches: names; sweeps: name -> sweeps.load.
    Returns an ordered dict: job id -> dict(kind, name, seconds, source, cores, priority, deps).
    Job ids: run/<test>, check/<test>, bench/<name>, verification, sweep/<sweep>/<point>,
    sweep_collect/<sweep>, results, report. shared_points: (sweep, point) -> the validation run
    whose output the point reads (sweeps.shared_runs): a check's cost, after that run."""
    shared_points = shared_points or {}
    shipped = shipped_seconds()
    one_core = ONE_CORE_BENCHES if one_core_benches is None else one_core_benches
    times = measured(build, wf) if times is None else times
    out = {}

    def add(jid, kind, name, seconds, source, cores, deps=(), prio=None):
        out[jid] = dict(kind=kind, name=name, seconds=seconds, source=source, cores=cores, deps=list(deps),
                        priority=priority(seconds, cores, exclusive) if prio is None else prio)
    for name, j in jobs.items():
        k = key(j["kind"], name)
        if j["kind"] == "run":
            m, how = _test_time(times, "run", name)
            s, src = run_seconds(j.get("scene"), j.get("sets", []), m, ibms, wf, shipped.get(k))
            add(k, "run", name, s, src + (how if src.startswith("measured") else ""), 1)
    for name, j in jobs.items():
        if j["kind"] == "check":
            m, how = _test_time(times, "check", name)
            s, src = _with_fallback(m, shipped.get(key("check", name), CHECK_SECONDS))
            add(key("check", name), "check", name, s, src + (how if src.startswith("measured") else ""), 1,
                ["run/" + r for r in j["requires"]])
    s, src = _with_fallback(times.get("verification"), FALLBACK_SECONDS[("verification", None)]["verification"])
    add("verification", "verification", "verification", s, src, all_cores)
    table = FALLBACK_SECONDS.get(("bench", bench_level), FALLBACK_SECONDS[("bench", "default")])
    for b in benches:
        s, src = _with_fallback(times.get(key("bench", b, bench_level)), table.get(b, BENCH_UNKNOWN_SECONDS))
        add("bench/" + b, "bench", b, s, src, 1 if b in one_core else all_cores)
    for sname, sw in sweeps.items():
        for p in sw["points"]:
            n = "%s/%s" % (sname, p["id"])
            shared = shared_points.get((sname, p["id"]))
            if shared:
                add(key("sweep", n), "sweep", n, CHECK_SECONDS, "reads run " + shared, 1, ["run/" + shared])
                continue
            s, src = run_seconds(sw.get("scene"), p.get("sets", []), times.get(key("sweep", n)), ibms, wf,
                                 shipped.get(key("sweep", n)))
            add(key("sweep", n), "sweep", n, s, src, 1)
        add("sweep_collect/" + sname, "sweep_collect", sname, 0.0, "negligible", 1,
            ["sweep/%s/%s" % (sname, p["id"]) for p in sw["points"]], prio=0)
    checks = [j for j, v in out.items() if v["kind"] == "check"]
    add("results", "results", "results", 0.0, "negligible", 1, checks, prio=0)
    add("report", "report", "report", REPORT_SECONDS, "assumed", 1,
        [j for j, v in out.items() if v["kind"] != "report"], prio=0)
    return out


def classes(planned, kind):
    """priority -> [names] of the jobs of one kind, highest priority first."""
    out = {}
    for v in planned.values():
        if v["kind"] == kind:
            out.setdefault(v["priority"], []).append(v["name"])
    return dict(sorted(out.items(), reverse=True))


# ---- what the order buys: a list schedule as Snakemake's local scheduler makes it

def simulate(planned, cores, order=None):
    """Start times of a list schedule on `cores` cores: whenever a job ends, the ready jobs are
    taken by priority (highest first, ties in the plan's order) and started when their cores are
    free; a job that does not fit is passed over (an exclusive job waits for every core while
    one-core jobs are ready), as Snakemake 7.21's selectors do. `order`: job id -> rank replacing
    the priority (lower first). Returns (makespan, {job id: (start, end)})."""
    import heapq
    ids = list(planned)
    rank = {j: ((order[j],) if order else (-planned[j]["priority"],)) + (i,) for i, j in enumerate(ids)}
    done, started, events = set(), {}, []
    free, t = cores, 0.0
    while len(done) < len(ids):
        ready = sorted((j for j in ids if j not in started and all(d in done for d in planned[j]["deps"])),
                       key=rank.get)
        for j in ready:
            need = min(planned[j]["cores"], cores)
            if need <= free:
                free -= need
                started[j] = (t, t + planned[j]["seconds"])
                heapq.heappush(events, (t + planned[j]["seconds"], rank[j], j))
        if not events:
            raise RuntimeError("jobs waiting on jobs that never run: %s" % sorted(set(ids) - set(started)))
        t, _, j = heapq.heappop(events)
        done.add(j)
        free += min(planned[j]["cores"], cores)
        while events and events[0][0] <= t:
            _, _, j = heapq.heappop(events)
            done.add(j)
            free += min(planned[j]["cores"], cores)
    return max(e for _, e in started.values()), started
