"""Runs one workflow job (a ctest test or a bench) and records its verdict.

The verdict goes to a status file (JSON: name, status pass|FAIL|skipped|not run, exit code,
seconds). The job itself always succeeds for Snakemake, so a failing case neither stops the others
nor the report (as `ctest` keeps going); `workflow/ibms_workflow.py forget-failed` removes the
status files of failed jobs before the next run so that exactly those run again, and
`ibms_workflow.py summary` turns the verdicts into the main job's exit status.

For a ctest test the runner applies the test's properties as ctest does (working directory,
ENVIRONMENT, TIMEOUT, PASS/FAIL_REGULAR_EXPRESSION, SKIP_RETURN_CODE, WILL_FAIL; a test whose
required fixture setup failed is not run) and writes its output in ctest's log layout to
<build>/Testing/Temporary/LastTest_wf_<name>.log, where the report reads run times
(reports/report_data.py read_ctest_logs).
"""
import json
import os
import re
import subprocess
import time

import ctest_jobs


def _write_json(path, data):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    os.replace(tmp, path)


def read_json(path):
    """A status file's (or the times file's) contents; None when it is missing or unreadable."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def _execute(command, cwd, env_extra, timeout, log_path):
    env = dict(os.environ)
    env.update(env_extra)
    start = time.time()
    timed_out = False
    os.makedirs(cwd, exist_ok=True)
    os.makedirs(os.path.dirname(log_path), exist_ok=True)
    with open(log_path, "w") as log:
        try:
            proc = subprocess.run(command, cwd=cwd, env=env, stdout=log, stderr=subprocess.STDOUT,
                                  timeout=timeout if timeout > 0 else None)
            rc = proc.returncode
        except subprocess.TimeoutExpired:
            rc, timed_out = -1, True
        except OSError as e:
            log.write("could not start %s: %s\n" % (command[0], e))
            rc = -2
    with open(log_path, errors="replace") as f:
        output = f.read()
    return rc, timed_out, output, time.time() - start


def run_test(job, build, threads=1):
    """One ctest test (a job of ctest_jobs.load_jobs)."""
    name = job["name"]
    logs = os.path.join(ctest_jobs.state_dir(build), "logs")
    for r in job["requires"]:
        st = read_json(os.path.join(ctest_jobs.state_dir(build), "tests", r + ".status"))
        if not st or st.get("status") != "pass":
            _finish(job, build, "not run", None, 0.0, "required run %s did not pass\n" % r)
            return
    if job["results"]:
        os.makedirs(os.path.dirname(job["results"]), exist_ok=True)
        if os.path.exists(job["results"]):
            os.remove(job["results"])
    env = dict(job["env"])
    env.setdefault("OMP_NUM_THREADS", str(threads))
    rc, timed_out, output, seconds = _execute(job["command"], job["cwd"], env, job["timeout"],
                                              os.path.join(logs, name + ".log"))
    if timed_out:
        status = "FAIL"
    elif job["skip_code"] is not None and rc == int(job["skip_code"]):
        status = "skipped"
    else:
        if job["pass_regex"]:
            ok = any(re.search(p, output) for p in job["pass_regex"])
        else:
            ok = rc == 0
        if job["fail_regex"] and any(re.search(p, output) for p in job["fail_regex"]):
            ok = False
        if job["will_fail"]:
            ok = not ok
        status = "pass" if ok else "FAIL"
    if job["results"] and not os.path.exists(job["results"]):
        open(job["results"], "a").close()  # a check that writes no result line (ibms compare)
    _finish(job, build, status, rc, seconds, output, timed_out)


def _finish(job, build, status, rc, seconds, output, timed_out=False):
    name = job["name"]
    now = time.strftime("%b %d %H:%M %Z")
    ctest_log = os.path.join(build, "Testing", "Temporary", "LastTest_wf_%s.log" % name)
    os.makedirs(os.path.dirname(ctest_log), exist_ok=True)
    verdict = {"pass": "Test Passed.", "FAIL": "Test Failed.", "skipped": "Test Skipped.",
               "not run": "Test Not Run."}[status]
    with open(ctest_log, "w") as f:
        f.write("Workflow job of ctest test %s (workflow/runner.py)\n" % name)
        f.write("----------------------------------------------------------\n")
        f.write("1/1 Test: %s\n" % name)
        f.write("Command: %s\n" % " ".join('"%s"' % a for a in job["command"]))
        f.write("Directory: %s\n" % job["cwd"])
        f.write('"%s" start time: %s\n' % (name, now))
        f.write("Output:\n----------------------------------------------------------\n")
        f.write(output if output.endswith("\n") or not output else output + "\n")
        f.write("<end of output>\n")
        f.write("Test time = %7.2f sec\n" % seconds)
        f.write("----------------------------------------------------------\n")
        if timed_out:
            f.write("Test time out\n")
        f.write(verdict + "\n")
        f.write('"%s" end time: %s\n' % (name, now))
    _write_json(job["status"], dict(name=name, kind=job["kind"], case=job["case"], status=status,
                                    exit_code=rc, seconds=round(seconds, 3), host=os.uname().nodename,
                                    finished=time.strftime("%Y-%m-%dT%H:%M:%S%z")))
    print("%-50s %-8s %8.1f s" % (name, status, seconds), flush=True)


def junit_to_ctest_log(junit_path, log_path):
    """ctest's JUnit file (--output-junit) as a log in LastTest.log's layout, one entry per test
    (name, time, output, verdict), which the report reads (reports/report_data.read_ctest_logs).
    ctest's own LastTest.log cannot serve: any `ctest` started in the build directory meanwhile
    (a test that lists the tests, `ctest --show-only`) rewrites it. Returns the number of tests."""
    import xml.etree.ElementTree as ET
    cases = list(ET.parse(junit_path).getroot().iter("testcase"))
    verdicts = {"run": "Test Passed.", "fail": "Test Failed.", "disabled": "Test Not Run.",
                "notrun": "Test Not Run."}
    with open(log_path, "w") as f:
        f.write("ctest --output-junit %s, in LastTest.log's layout (workflow/runner.py)\n" % junit_path)
        f.write("----------------------------------------------------------\n")
        for k, case in enumerate(cases, 1):
            name = case.get("name")
            out = case.findtext("system-out") or ""
            f.write("%d/%d Test: %s\n" % (k, len(cases), name))
            f.write("Output:\n----------------------------------------------------------\n")
            f.write(out.rstrip("\n") + "\n")
            f.write("<end of output>\n")
            f.write("Test time = %8.2f sec\n" % float(case.get("time") or "nan"))
            f.write("----------------------------------------------------------\n")
            f.write(verdicts.get(case.get("status"), "Test Failed.") + "\n")
    return len(cases)


def run_command(name, command, cwd, status_path, log_path, env_extra=None, accept=(0,)):
    """A bench or another plain command: pass when its exit code is in `accept`."""
    rc, timed_out, output, seconds = _execute(command, cwd, env_extra or {}, 0, log_path)
    status = "pass" if rc in accept else "FAIL"
    _write_json(status_path, dict(name=name, kind="bench", status=status, exit_code=rc,
                                  seconds=round(seconds, 3), host=os.uname().nodename,
                                  finished=time.strftime("%Y-%m-%dT%H:%M:%S%z")))
    print("%-50s %-8s %8.1f s" % (name, status, seconds), flush=True)
    return status
