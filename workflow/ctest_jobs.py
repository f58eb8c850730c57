"""The validation cases as workflow jobs, read from ctest's own description of its tests.

Why generate instead of declaring the rules by hand: the cases are registered once, in
validation/CMakeLists.txt and validation/<case>/CMakeLists.txt (commands, grids, working
directories, environment, labels, fixtures). `ctest --show-only=json-v1` prints exactly that, so
the workflow reads it and makes one job per test: a *run* job per fixture-setup test and a *check*
job per other test, the check depending on the run jobs of the fixtures it requires (as ctest
runs them). A case added, or a grid changed, in CMake is then in the workflow too, with no second
list to keep in step, and `ctest -L validation` keeps running the same tests by hand.

Inputs of a job, for Snakemake's out-of-date test (modification times):
  - every executable the command names (the test's program, `-DIBMS=.../ibms`, ...),
  - every file of the source tree the command names (scene, run_to_wall.cmake, reference tables),
  - for a check, every file of its case's reference/ folder (`ibms compare` finds them through a
    folder argument) and the status files of the run jobs it requires.
The command itself (with working directory and environment) is a parameter of the job, so a test
whose definition changed in CMake reruns too (Snakemake's `params` rerun trigger).
"""
import hashlib
import json
import os
import re
import subprocess

RESULTS_NAME = "results.csv"
# The workflow's own files in the build directory (status files, per-check results, logs, Slurm
# job logs). Not `workflow/`: that is CMake's binary directory of the source folder workflow/.
STATE_DIR = "workflow_state"


def state_dir(build):
    return os.path.join(os.path.abspath(build), STATE_DIR)


def _properties(test):
    return {p["name"]: p["value"] for p in test.get("properties", [])}


def _pieces(arg):
    """Paths an argument may carry: 'a=b', '100:/x/y', 'k=v\\;k=v' are split into their parts."""
    return [p for p in re.split(r"[=:;\\]", arg) if p.startswith("/")]


def case_names(source):
    root = os.path.join(source, "validation")
    return sorted(d for d in os.listdir(root)
                  if d != "common" and os.path.isdir(os.path.join(root, d)))


def case_of(name, cases):
    """The case a test belongs to: the longest case name that prefixes the test name."""
    best = None
    for c in cases:
        if name.startswith(c + "_") and (best is None or len(c) > len(best)):
            best = c
    return best


def show_tests(build):
    out = subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)["tests"]


def inputs_of(command, build, source):
    """Executables and source-tree files the command names (existing files only)."""
    found = []
    for i, arg in enumerate(command):
        for p in ([arg] if i == 0 else []) + _pieces(arg):
            p = os.path.normpath(p)
            if not os.path.isfile(p):
                continue
            under_build = p.startswith(build + os.sep)
            if (under_build and os.access(p, os.X_OK)) or p.startswith(source + os.sep) and not under_build:
                if p not in found:
                    found.append(p)
    return found


def scene_and_sets(command):
    """The scene file and `--set` assignments of an ibms run (direct or through run_to_wall.cmake),
    for `ibms info` (cost estimate); (None, []) when the command runs no scene."""
    scene, sets = None, []
    for i, arg in enumerate(command):
        if arg.endswith(".toml") and os.path.isfile(arg):
            scene = arg
        elif arg.startswith("-DSCENE="):
            scene = arg.split("=", 1)[1]
        elif arg.startswith("-DSETS="):
            sets += [s for s in arg.split("=", 1)[1].replace("\\;", ";").split(";") if s]
        elif arg == "--set" and i + 1 < len(command):
            sets.append(command[i + 1])
    return scene, sets


def output_of(command):
    """The output file an ibms run writes (`-o FILE`, or `-DOUTPUT=FILE` through run_to_wall.cmake),
    None when the command names none."""
    for i, arg in enumerate(command):
        if arg.startswith("-DOUTPUT="):
            return arg.split("=", 1)[1]
        if arg == "-o" and i + 1 < len(command):
            return command[i + 1]
    return None


def load_jobs(build, source, labels, exclude_cases=(), tests=None):
    """Jobs of the tests carrying one of `labels` (plus the fixture-setup tests they require, as
    ctest adds them), cases in exclude_cases left out. Returns an ordered dict name -> job."""
    build, source = os.path.abspath(build), os.path.abspath(source)
    cases = case_names(source)
    tests = show_tests(build) if tests is None else tests
    wf = state_dir(build)
    shared_results = os.path.join(build, "validation", RESULTS_NAME)
    setups = {}  # fixture -> [test names]
    by_name = {}
    for t in tests:
        props = _properties(t)
        by_name[t["name"]] = (t, props)
        for f in props.get("FIXTURES_SETUP", []):
            setups.setdefault(f, []).append(t["name"])
    wanted = set()
    for name, (t, props) in by_name.items():
        if set(props.get("LABELS", [])) & set(labels) and case_of(name, cases) not in exclude_cases:
            wanted.add(name)
            for f in props.get("FIXTURES_REQUIRED", []):
                wanted.update(setups.get(f, []))
    jobs = {}
    for t in tests:  # ctest's order
        name = t["name"]
        if name not in wanted:
            continue
        props = by_name[name][1]
        if "command" not in t:
            raise RuntimeError("ctest has no command for %s (is the build complete?)" % name)
        case = case_of(name, cases)
        kind = "run" if props.get("FIXTURES_SETUP") else "check"
        command = list(t["command"])
        env = dict(e.split("=", 1) for e in props.get("ENVIRONMENT", []))
        requires = []
        for f in props.get("FIXTURES_REQUIRED", []):
            requires += [s for s in setups.get(f, []) if s not in requires]
        inputs = inputs_of(command, build, source)
        results = None
        if kind == "check":
            # Each check writes its own result lines; rule `results` joins them into results.csv.
            results = os.path.join(wf, "results", name + ".csv")
            command = [results if a == shared_results else a for a in command]
            env["IBMS_VALIDATION_RESULTS"] = results
            ref = os.path.join(source, "validation", case or "-", "reference")
            if os.path.isdir(ref):
                for root, _, files in os.walk(ref):
                    inputs += sorted(os.path.join(root, f) for f in files
                                     if os.path.join(root, f) not in inputs)
        job = dict(name=name, kind=kind, case=case, command=command, env=env,
                   cwd=props.get("WORKING_DIRECTORY", build), labels=props.get("LABELS", []),
                   requires=requires, inputs=inputs, results=results,
                   timeout=float(props.get("TIMEOUT", 0) or 0),
                   pass_regex=props.get("PASS_REGULAR_EXPRESSION", []),
                   fail_regex=props.get("FAIL_REGULAR_EXPRESSION", []),
                   skip_code=props.get("SKIP_RETURN_CODE"), will_fail=bool(props.get("WILL_FAIL", False)),
                   status=os.path.join(wf, "tests", name + ".status"))
        job["scene"], job["sets"] = scene_and_sets(command)
        output = output_of(command) if kind == "run" else None
        job["output"] = os.path.join(job["cwd"], output) if output else None
        job["definition"] = hashlib.sha256(json.dumps(
            [job["command"], job["env"], job["cwd"], job["pass_regex"], job["fail_regex"],
             job["skip_code"], job["will_fail"]]).encode()).hexdigest()[:16]
        jobs[name] = job
    return jobs
