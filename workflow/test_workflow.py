#!/usr/bin/python3
"""Unit test of the workflow's helpers (no Snakemake run but a dry run, no solver): sweep files
expand into the right --set values (linked keys, two axes, ids), bad expressions are refused; jobs
come out of a ctest test list as runs and checks with their fixtures, inputs and per-check results
file; the runner's status file and its ctest-format log (read back by the report's reader) for a
passing, a failing and a not-run test; `ibms compare` lines parse; the report's sweep section
draws a figure; job priorities (workflow/priorities.py) come out longest first for a synthetic set
of jobs, the exclusive jobs above (or, with `exclusive: last`, among) the one-core ones, the classes
partition the jobs, measured times survive in the times file, and the list schedule finishes
sooner longest first.
With a build directory, also: the convergence sweeps run the same grids as their validation cases
register in CMake (so the two cannot drift apart), and a dry run of the default level
(`snakemake -n`, when installed) gives every job exactly one rule, <kind>_p<priority>, carrying
that priority.
usage: test_workflow.py WORK_DIR [BUILD_DIR]   exit 0 pass, 1 fail, 77 skipped (matplotlib missing)"""
import json
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.dirname(HERE)
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(SOURCE, "reports"))
try:
    import matplotlib  # noqa: F401
    import numpy  # noqa: F401
except ImportError:
    sys.exit(77)
import ctest_jobs  # noqa: E402
import priorities  # noqa: E402
import runner  # noqa: E402
import sweeps  # noqa: E402

failures = []


def check(cond, what):
    print(("pass  " if cond else "FAIL  ") + what)
    if not cond:
        failures.append(what)


def main():
    if len(sys.argv) < 2:
        # The scratch directory is always named: ctest gives one in the build tree
        # (workflow/CMakeLists.txt), so nothing is written into the source tree.
        sys.exit("usage: test_workflow.py WORK_DIR [BUILD_DIR]")
    work = os.path.abspath(sys.argv[1])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    build = os.path.join(work, "build")
    os.makedirs(os.path.join(build, "validation"))

    # -- sweeps: the settling-disk file of the repository, and a two-axis one
    s = sweeps.load(os.path.join(SOURCE, "sweeps", "settling_disk_convergence.toml"), SOURCE, build)
    check([p["sets"] for p in s["points"]] == [
        ["domain.cells_x=100", "domain.cells_y=300", "bodies.0.n_surface_points=40"],
        ["domain.cells_x=150", "domain.cells_y=450", "bodies.0.n_surface_points=60"],
        ["domain.cells_x=200", "domain.cells_y=600", "bodies.0.n_surface_points=80"]],
        "settling-disk sweep: cells_y = 3 cells_x and N_l = 0.4 cells_x as in its CMakeLists.txt")
    two = os.path.join(work, "two.toml")
    with open(two, "w") as f:
        f.write('scene = "validation/lid_driven_cavity_re100/scene.toml"\n[grid]\n'
                '"domain.cells_x" = [64, 128]\n"ibm.forcing_passes" = [1, 3]\n'
                '[linked]\n"domain.cells_y" = "domain_cells_x * forcing_passes"\n')
    t = sweeps.load(two, SOURCE, build)
    check(len(t["points"]) == 4 and t["name"] == "two", "two axes: 4 points, name from the file")
    check(t["points"][3]["sets"] == ["domain.cells_x=128", "ibm.forcing_passes=3", "domain.cells_y=384"],
          "linked key by full and by short name: %s" % t["points"][3]["sets"])
    check(len({p["id"] for p in t["points"]}) == 4, "point ids distinct: %s" % [p["id"] for p in t["points"]])
    for bad in ("__import__('os')", "cells_x.real", "open('x')", "unknown * 2"):
        try:
            sweeps.evaluate(bad, {"cells_x": 1})
            check(False, "expression refused: %s" % bad)
        except ValueError:
            check(True, "expression refused: %s" % bad)

    text = ("ibms compare settling_disk: a.csv\n"
            "  metric                                                          tolerance     measured   result\n"
            "  |max settling speed / 5.5 cm/s (published) - 1|                      0.03     0.010647   pass\n"
            "  max settling speed [cm/s]                                      submitted 5.44144, reference 5.54151   info\n"
            "settling_disk: pass\n")
    m = sweeps.parse_compare(text)
    check(m == {"|max settling speed / 5.5 cm/s (published) - 1|": 0.010647, "max settling speed [cm/s]": 5.44144},
          "ibms compare lines parsed: %s" % m)

    # -- jobs from a ctest test list (the json-v1 layout)
    ok, fail = os.path.join(build, "ok.sh"), os.path.join(build, "fail.sh")
    for path, rc in ((ok, 0), (fail, 1)):
        with open(path, "w") as f:
            f.write("#!/bin/sh\necho \"$@\"\necho line >> \"$IBMS_VALIDATION_RESULTS\"\nexit %d\n" % rc)
        os.chmod(path, 0o755)
    scene = os.path.join(SOURCE, "validation", "settling_disk", "scene.toml")
    shared = os.path.join(build, "validation", "results.csv")

    def test(name, command, **props):
        return {"name": name, "command": command,
                "properties": [{"name": k, "value": v} for k, v in props.items()]}
    tests = [
        test("settling_disk_100_run", [ok, "-DSCENE=" + scene, "-DSETS=a=1\\;b=2", "-DOUTPUT=" + os.path.join(build, "sd.h5")],
             LABELS=["validation"],
             FIXTURES_SETUP=["settling_disk_runs"], WORKING_DIRECTORY=build),
        test("settling_disk_check", [ok, shared], LABELS=["validation"], FIXTURES_REQUIRED=["settling_disk_runs"],
             ENVIRONMENT=["IBMS_VALIDATION_RESULTS=" + shared], WORKING_DIRECTORY=build),
        test("dkt_two_disks_run_160", [fail], LABELS=["validation"], FIXTURES_SETUP=["dkt"], WORKING_DIRECTORY=build),
        test("dkt_two_disks_check_160", [ok], LABELS=["validation"], FIXTURES_REQUIRED=["dkt"], WORKING_DIRECTORY=build),
        test("settling_disk_300_run", [ok], LABELS=["slow"], FIXTURES_SETUP=["slow_runs"], WORKING_DIRECTORY=build),
        test("test_unit", [ok], LABELS=["unit"], WORKING_DIRECTORY=build),
    ]
    jobs = ctest_jobs.load_jobs(build, SOURCE, ["validation"], tests=tests)
    check(list(jobs) == ["settling_disk_100_run", "settling_disk_check", "dkt_two_disks_run_160",
                         "dkt_two_disks_check_160"], "validation label selects 4 jobs: %s" % list(jobs))
    run, chk = jobs["settling_disk_100_run"], jobs["settling_disk_check"]
    check(run["kind"] == "run" and chk["kind"] == "check" and chk["requires"] == ["settling_disk_100_run"],
          "run and check kinds, check requires the fixture's run")
    check(run["inputs"] == [ok, scene] and run["scene"] == scene and run["sets"] == ["a=1", "b=2"]
          and run["output"] == os.path.join(build, "sd.h5") and chk["output"] is None,
          "run inputs (program, scene), --set values from -DSETS, output from -DOUTPUT: %s %s %s"
          % (run["inputs"], run["sets"], run["output"]))
    check(any("/settling_disk/reference/" in p for p in chk["inputs"]), "check inputs hold the case's references")
    check(chk["command"][1] == chk["results"] and chk["env"]["IBMS_VALIDATION_RESULTS"] == chk["results"],
          "check writes its own results file, not results.csv")
    excl = ctest_jobs.load_jobs(build, SOURCE, ["validation"], exclude_cases=["dkt_two_disks"], tests=tests)
    check("dkt_two_disks_run_160" not in excl, "exclude_cases leaves a case out")

    for name in jobs:
        runner.run_test(jobs[name], build)
    st = {n: runner.read_json(jobs[n]["status"])["status"] for n in jobs}
    check(st == {"settling_disk_100_run": "pass", "settling_disk_check": "pass", "dkt_two_disks_run_160": "FAIL",
                 "dkt_two_disks_check_160": "not run"}, "statuses: %s" % st)
    with open(chk["results"]) as f:
        check(f.read() == "line\n", "one result line in the check's file")
    runner.run_test(chk, build)
    with open(chk["results"]) as f:
        check(f.read() == "line\n", "a rerun replaces the check's lines (no duplicates)")
    import report_data
    logs = {t["name"]: t["status"] for t in report_data.read_ctest_logs(build)}
    check(logs == {"settling_disk_100_run": "pass", "settling_disk_check": "pass", "dkt_two_disks_run_160": "FAIL",
                   "dkt_two_disks_check_160": "skipped"} or logs.get("dkt_two_disks_run_160") == "FAIL"
          and logs.get("settling_disk_check") == "pass", "the report reads the runner's logs: %s" % logs)
    # The verification job's verdicts come from ctest's JUnit file, in LastTest.log's layout.
    junit = os.path.join(work, "verification_junit.xml")
    with open(junit, "w") as f:
        f.write('<?xml version="1.0"?>\n<testsuite tests="3">\n'
                '<testcase name="test_a" time="1.5" status="run"><system-out>ok</system-out></testcase>\n'
                '<testcase name="test_b" time="0.25" status="fail"><failure message="Failed"/></testcase>\n'
                '<testcase name="test_c" time="0" status="notrun"/>\n</testsuite>\n')
    n = runner.junit_to_ctest_log(junit, os.path.join(build, "Testing", "Temporary", "LastTest_verification.log"))
    read = {t["name"]: (t["status"], t["seconds"]) for t in report_data.read_ctest_logs(build)}
    check(n == 3 and read.get("test_a") == ("pass", 1.5) and read.get("test_b") == ("FAIL", 0.25)
          and read.get("test_c", ("?",))[0] == "skipped",
          "the verification's JUnit verdicts reach the report's reader: %s" % {k: read.get(k) for k in ("test_a", "test_b", "test_c")})

    # -- collect and the report's figure
    pts = []
    for k, p in enumerate(s["points"]):
        path = os.path.join(work, "p%d.json" % k)
        with open(path, "w") as f:
            json.dump(dict(values=p["values"], status="pass", exit_code=3, seconds=1.0 + k,
                           metrics={"error_published": 0.02 / (k + 1), "error_ibms_reference": 0.03 / (k + 1) ** 2}), f)
        pts.append(path)
    csv_path = os.path.join(build, "sweeps", s["name"] + ".csv")
    sweeps.collect(s, pts, csv_path)
    import report_sweeps
    title, plot, header, rows = report_sweeps.read_sweep(csv_path)
    check(header[:4] == ["domain.cells_x", "status", "exit_code", "seconds"] and len(rows) == 3 and plot["log"],
          "sweep CSV: header %s, %d rows" % (header, len(rows)))
    out = []
    report_sweeps.sweeps_section(out, build, work)
    check(os.path.isfile(os.path.join(work, "sweep0.pdf")) and any("includegraphics" in o for o in out),
          "the report's sweep section draws the figure")
    test_priorities(build, jobs)
    # -- the sweeps and the cases' own convergence studies use the same grids
    if len(sys.argv) > 2:
        real = ctest_jobs.load_jobs(os.path.abspath(sys.argv[2]), SOURCE, ["validation"])
        for sweep_file, prefix in (("settling_disk_convergence.toml", "settling_disk_"),
                                   ("cavity_re100_convergence.toml", "lid_driven_cavity_re100_run_")):
            sw = sweeps.load(os.path.join(SOURCE, "sweeps", sweep_file), SOURCE, build)
            case = sorted(int(a.split("=")[1]) for n, j in real.items()
                          if n.startswith(prefix) and "rigid" not in n and j["kind"] == "run"
                          for a in j["sets"] if a.startswith("domain.cells_x="))
            grid = sorted(sw["grid"]["domain.cells_x"])
            check(case == grid, "%s: grids %s = the case's validation runs %s" % (sweep_file, grid, case))
            # ... and are those runs: every point reads its validation run instead of running again
            shared = sweeps.shared_runs({sw["name"]: sw}, real)
            check(sorted(shared) == sorted((sw["name"], p["id"]) for p in sw["points"])
                  and all(n.startswith(prefix) for n in shared.values()),
                  "%s: every point is a validation run: %s" % (sweep_file, shared))
        test_dry_run_rules(os.path.abspath(sys.argv[2]))
    print("%d failure(s)" % len(failures))
    return 1 if failures else 0


def test_priorities(build, jobs):
    """Longest first on synthetic jobs: the ctest jobs above with made-up times, benches, a sweep."""
    wf = ctest_jobs.state_dir(build)
    times = {"run/settling_disk_100_run": (40.0, "pass"), "run/dkt_two_disks_run_160": (3.0, "FAIL"),
             "check/settling_disk_check": (0.05, "pass"), "bench/work_precision/default": (900.0, "pass"),
             "bench/stability/default": (35.0, "pass"), "sweep/s/a": (300.0, "pass"), "sweep/s/b": (0.5, "pass"),
             "sweep/s/c": (7.0, "pass")}
    sw = {"s": {"scene": None, "points": [{"id": "a", "sets": []}, {"id": "b", "sets": []}, {"id": "c", "sets": []}]}}
    benches = ["work_precision", "overhead", "stability"]
    plan = priorities.plan(jobs, benches, "default", sw, build, wf, None, 2, times=times)
    one = sorted((v for v in plan.values()
                  if v["cores"] == 1 and v["kind"] not in ("report", "results", "sweep_collect")),
                 key=lambda v: -v["seconds"])
    prios = [v["priority"] for v in one]
    check(prios == sorted(prios, reverse=True) and prios[0] > prios[-1],
          "one-core jobs: a longer one never below a shorter one: %s"
          % [(v["name"], v["seconds"], v["priority"]) for v in one])
    check(plan["bench/stability"]["cores"] == 1 and plan["bench/work_precision"]["cores"] == 2
          and plan["bench/overhead"]["cores"] == 2, "map benches on one core, timing benches on every core")
    excl = sorted((v for v in plan.values() if v["cores"] > 1), key=lambda v: -v["seconds"])
    check([v["name"] for v in excl] == ["work_precision", "verification", "overhead"]
          and [v["priority"] for v in excl] == sorted([v["priority"] for v in excl], reverse=True)
          and min(v["priority"] for v in excl) > 2 * max(prios),
          "exclusive jobs longest first, each above any two one-core jobs: %s"
          % [(v["name"], v["seconds"], v["priority"]) for v in excl])
    shipped = priorities.shipped_seconds()
    untimed = dict(jobs, dfg_2d2_20_run=dict(jobs["dkt_two_disks_run_160"], name="dfg_2d2_20_run"))
    up = priorities.plan(untimed, benches, "default", sw, build, wf, None, 2, times=times)
    check(shipped.get("run/dfg_2d2_20_run", 0) > shipped.get("run/settling_disk_100_run", 1e9)
          and up["run/dfg_2d2_20_run"]["seconds"] == shipped["run/dfg_2d2_20_run"]
          and up["run/dfg_2d2_20_run"]["source"] == "shipped time",
          "a run this build has not timed takes the shipped time: %s" % up.get("run/dfg_2d2_20_run"))
    check(plan["run/dkt_two_disks_run_160"]["seconds"]
          == max(3.0, shipped.get("run/dkt_two_disks_run_160", priorities.UNKNOWN_SECONDS))
          and plan["bench/overhead"]["seconds"] == priorities.FALLBACK_SECONDS[("bench", "default")]["overhead"]
          and plan["sweep/s/a"]["seconds"] == 300.0,
          "a failed run's time is a lower bound; a bench not measured takes the table's seconds")
    # a sweep point that is a validation run of the level reads it: same scene, same values
    # (numbers compared as numbers), the run's output named; another value runs on its own
    run = jobs["settling_disk_100_run"]
    sd = {"sd": {"scene": run["scene"], "points": [{"id": "same", "sets": ["b=2", "a=1.0"]},
                                                   {"id": "other", "sets": ["a=1", "b=3"]}]}}
    shared = sweeps.shared_runs(sd, jobs)
    check(shared == {("sd", "same"): "settling_disk_100_run"},
          "sweep point = validation run: %s (run sets %s, output %s)" % (shared, run["sets"], run["output"]))
    restarted = dict(jobs, settling_disk_100_run=dict(run, command=run["command"] + ["--restart", "x.h5"]))
    check(sweeps.shared_runs(sd, restarted) == {}, "a run with another option (--restart) is not the point's run")
    sp = priorities.plan(jobs, benches, "default", sd, build, wf, None, 2, times=times, shared_points=shared)
    check(sp["sweep/sd/same"]["deps"] == ["run/settling_disk_100_run"]
          and sp["sweep/sd/same"]["seconds"] == priorities.CHECK_SECONDS and not sp["sweep/sd/other"]["deps"],
          "a shared point costs a check after its run: %s" % sp["sweep/sd/same"])
    last = priorities.plan(jobs, benches, "default", sw, build, wf, None, 2, exclusive="last", times=times)
    check(last["bench/work_precision"]["priority"] == priorities.priority_class(900.0),
          "exclusive=last: no offset (%s)" % last["bench/work_precision"]["priority"])
    for kind in ("run", "check", "bench", "sweep"):
        cl = priorities.classes(plan, kind)
        names = [n for members in cl.values() for n in members]
        check(sorted(names) == sorted(v["name"] for v in plan.values() if v["kind"] == kind)
              and len(names) == len(set(names)), "%s: the classes partition the jobs: %s" % (kind, cl))
    # the list schedule: longest first beats the given order when the long job comes last
    syn = {"a%d" % i: dict(seconds=1.0, cores=1, deps=[]) for i in range(4)}
    syn["long"] = dict(seconds=8.0, cores=1, deps=[])
    for v in syn.values():
        v["priority"] = priorities.priority(v["seconds"], v["cores"])
    in_order, _ = priorities.simulate(syn, 2, order={j: 0 for j in syn})
    longest, starts = priorities.simulate(syn, 2)
    check(in_order == 10 and longest == 8 and starts["long"][0] == 0,
          "2 cores, 4 x 1 s + 8 s: %g s in the given order, %g s longest first" % (in_order, longest))
    # an exclusive job blocks both cores wherever it runs: first or last, the same end
    mix = {"x": dict(seconds=5.0, cores=2, deps=[]), "p": dict(seconds=8.0, cores=1, deps=[]),
           "q": dict(seconds=4.0, cores=1, deps=[]), "r": dict(seconds=4.0, cores=1, deps=[]),
           "end": dict(seconds=1.0, cores=1, deps=["x", "p", "q", "r"])}
    spans = []
    for exclusive in ("first", "last"):
        for v in mix.values():
            v["priority"] = priorities.priority(v["seconds"], v["cores"], exclusive) if not v["deps"] else 0
        span, st = priorities.simulate(mix, 2)
        spans.append((span, st["x"][0]))
    check(spans == [(14.0, 0.0), (14.0, 8.0)], "exclusive job first or last: (end, its start) %s" % spans)
    # the times file keeps what the status files said, benches under their level
    os.makedirs(os.path.join(wf, "bench"), exist_ok=True)
    with open(os.path.join(wf, "bench", "stability.status"), "w") as f:
        json.dump({"name": "bench_stability", "status": "pass", "seconds": 12.5}, f)
    priorities.record(build, wf, plan, "quick")
    os.remove(os.path.join(wf, "bench", "stability.status"))
    m = priorities.measured(build, wf)
    check(m.get("bench/stability/quick") == (12.5, "pass") and "bench/stability/default" not in m
          and m.get("run/settling_disk_100_run", (None,))[0] is not None,
          "times file: a bench under its level; runs from their status files")


def test_dry_run_rules(build):
    """A dry run of the default level: each job exactly one rule, <kind>_p<priority> carrying that
    priority, the map benches on one core. Skipped without snakemake."""
    import re
    import subprocess
    if not shutil.which("snakemake"):
        print("skip  dry run: no snakemake")
        return
    # --nolock, --rerun-incomplete: this test also runs inside the workflow's verification job
    out = subprocess.run(["snakemake", "-s", os.path.join(HERE, "Snakefile"), "--directory", build,
                          "--configfile", os.path.join(HERE, "config", "default.yaml"), "--config", "build=" + build,
                          "--cores", "2", "-n", "--forceall", "--nolock", "--rerun-incomplete"],
                         capture_output=True, text=True)
    jobs, cur = [], None
    for line in out.stdout.splitlines():
        m = re.match(r"^(?:local)?rule (\S+):", line)
        if m:
            cur = {"rule": m.group(1), "priority": 0, "threads": 1}
            jobs.append(cur)
        elif cur is not None and ":" in line:
            k, v = line.strip().split(":", 1)
            if k in ("output", "wildcards", "input"):
                cur[k] = v.strip()
            elif k in ("priority", "threads"):
                cur[k] = int(float(v))
    outputs = [j.get("output") for j in jobs if j.get("output")]
    check(out.returncode == 0 and len(jobs) > 50 and len(outputs) == len(set(outputs)),
          "dry run: %d jobs, each output made by one job (exit %d) %s"
          % (len(jobs), out.returncode, out.stderr[-500:] if out.returncode else ""))
    kinds, bad = {}, []
    for j in jobs:
        m = re.match(r"^(case_run|case_check|bench|sweep_run)_p(\d+)$", j["rule"])
        if m:
            kinds[m.group(1)] = kinds.get(m.group(1), 0) + 1
            if int(m.group(2)) != j["priority"]:
                bad.append(j["rule"])
        elif j["rule"] not in ("all", "results", "report", "sweep_collect", "verification"):
            bad.append(j["rule"])
    check(not bad and set(kinds) == {"case_run", "case_check", "bench", "sweep_run"},
          "dry run: rules <kind>_p<priority> with that priority; jobs per kind %s %s" % (kinds, bad))
    threads = {j.get("wildcards", "").replace("bench=", ""): j["threads"] for j in jobs if j["rule"].startswith("bench_")}
    check(threads.get("stability") == 1 and threads.get("fluid_stability") == 1
          and threads.get("work_precision_bodies") == 1
          and threads.get("work_precision", 1) > 1, "dry run: bench threads %s" % threads)
    # the sweep points that are validation runs wait for them and run nothing themselves
    shared_points = [j for j in jobs if j["rule"].startswith("sweep_run")
                     and "/workflow_state/tests/" in j.get("input", "")]
    check(len(shared_points) == 6, "dry run: %d sweep points read validation runs (the two convergence "
          "sweeps' 6)" % len(shared_points))


if __name__ == "__main__":
    sys.exit(main())
