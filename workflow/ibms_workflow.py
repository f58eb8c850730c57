#!/usr/bin/python3
"""Helpers around the workflow's status files (workflow/runner.py).

  ibms_workflow.py forget-failed BUILD   remove the status files of jobs that did not pass, so the
                                         next workflow run runs exactly those again
  ibms_workflow.py summary BUILD         one line per job that did not pass, counts, and exit
                                         status 1 when any did not pass (0 otherwise)
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


def main(argv):
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
