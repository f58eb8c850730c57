#!/usr/bin/python3
"""Helpers around the workflow's status files (workflow/runner.py).

  ibms_workflow.py forget-failed BUILD   remove the status files of jobs that did not pass, so the
                                         next workflow run runs exactly those again
  ibms_workflow.py summary BUILD         one line per job that did not pass, counts, and exit
                                         status 1 when any did not pass (0 otherwise)
  ibms_workflow.py schedule BUILD [LEVEL] [--cores N] [--jobs]
                                         estimated wall time of the level's jobs on N cores (default
                                         2) from their last measured times (workflow/priorities.py):
                                         the order before priorities (all benches exclusive, no
                                         priorities: the exclusive jobs run last) and with them
                                         (exclusive jobs first, and last); --jobs lists every job's
                                         seconds, their source, cores and priority
"""
import glob
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import ctest_jobs  # noqa: E402


def statuses(build):
    wf = ctest_jobs.state_dir(build)
    files = (glob.glob(os.path.join(wf, "tests", "*.status")) + glob.glob(os.path.join(wf, "bench", "*.status"))
             + glob.glob(os.path.join(wf, "verification.status"))
             + glob.glob(os.path.join(wf, "sweeps", "*", "*.json")))
    for path in sorted(files):
        try:
            with open(path) as f:
                st = json.load(f)
        except (OSError, ValueError):
            st = {"name": os.path.basename(path), "status": "unreadable"}
        yield path, st


def schedule(build, level="default", cores=2, list_jobs=False):
    import yaml
    import priorities
    import sweeps as sweep_files
    source = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    with open(os.path.join(source, "workflow", "config", level + ".yaml")) as f:
        config = yaml.safe_load(f)
    wf = ctest_jobs.state_dir(build)
    ibms = os.path.join(build, "solver", "ibms")
    jobs = ctest_jobs.load_jobs(build, source, labels=config.get("labels", ["validation"]),
                                exclude_cases=config.get("exclude_cases", []))
    sweeps = {}
    for path in config.get("sweeps", []):
        s = sweep_files.load(os.path.join(source, path), source, build)
        sweeps[s["name"]] = s
    benches, bench_level = config.get("benches", []), config.get("bench_level", "default")
    times = priorities.measured(build, wf)
    shared = sweep_files.shared_runs(sweeps, jobs)
    cases = [("before: every bench exclusive, no priorities", dict(one_core_benches=set()), "none"),
             ("after: map benches on one core, longest first, exclusive jobs first", {}, "first"),
             ("after, exclusive jobs last (config exclusive=last)", {}, "last")]
    for title, extra, exclusive in cases:
        plan = priorities.plan(jobs, benches, bench_level, sweeps, build, wf, ibms, cores,
                               exclusive if exclusive != "none" else "first", times=times,
                               shared_points=shared if exclusive != "none" else None, **extra)
        order = {j: 0 for j in plan} if exclusive == "none" else None  # ties: the plan's order
        makespan, _ = priorities.simulate(plan, cores, order)
        excl = sum(v["seconds"] for v in plan.values() if v["cores"] > 1)
        one = sum(v["seconds"] for v in plan.values() if v["cores"] == 1)
        print("%s\n  estimated wall time on %d cores: %.0f s (%.1f min); exclusive jobs %.0f s, "
              "one-core jobs %.0f s (%.0f s on %d cores)" % (title, cores, makespan, makespan / 60, excl, one,
                                                           one / cores, cores))
    if list_jobs:
        plan = priorities.plan(jobs, benches, bench_level, sweeps, build, wf, ibms, cores, times=times,
                               shared_points=shared)
        _, started = priorities.simulate(plan, cores)
        print("\n%-78s %9s %6s %8s %8s  %s" % ("job", "seconds", "cores", "priority", "start", "source"))
        for j, v in sorted(plan.items(), key=lambda kv: started[kv[0]][0]):
            print("%-78s %9.1f %6d %8d %8.0f  %s" % (j, v["seconds"], v["cores"], v["priority"], started[j][0],
                                                     v["source"]))
    return 0


def main(argv):
    if len(argv) >= 3 and argv[1] == "schedule":
        args = [a for a in argv[2:] if not a.startswith("--")]
        cores = 2
        if "--cores" in argv:
            cores = int(argv[argv.index("--cores") + 1])
            args.remove(str(cores))
        return schedule(os.path.abspath(args[0]), args[1] if len(args) > 1 else "default", cores,
                        "--jobs" in argv)
    if len(argv) != 3 or argv[1] not in ("forget-failed", "summary"):
        sys.exit(__doc__)
    build = os.path.abspath(argv[2])
    bad = [(p, s) for p, s in statuses(build) if s.get("status") not in ("pass", "skipped")]
    if argv[1] == "forget-failed":
        for p, s in bad:
            os.remove(p)
            print("workflow: %s did not pass last time (%s): it runs again" % (s.get("name", s.get("point")), s.get("status")))
        return 0
    total = sum(1 for _ in statuses(build))
    for p, s in bad:
        print("  %-50s %s (exit code %s)" % (s.get("name", s.get("point")), s.get("status"), s.get("exit_code")))
    print("workflow jobs: %d recorded, %d did not pass" % (total, len(bad)))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
