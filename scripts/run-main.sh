#!/usr/bin/env bash
# Set-up and the main job in one command: installs missing Debian packages (with LaTeX and
# Snakemake), builds ibms, then runs the main job as a Snakemake workflow on this machine with all
# cores (workflow/Snakefile, docs/workflow.md): the unit and convergence tests (their tables go to
# <build>/verification_results/), the validation cases of the level (outputs in
# <build>/validation/<case>/, one job per ctest run and check), the benches (CSV in <build>/bench/),
# the sweeps of the level (sweeps/*.toml, one CSV each in <build>/sweeps/), the table of checks
# (<build>/validation/results.csv) and the PDF report <build>/ibms_validation_report.pdf
# (reports/README.md). Test failures are reported but do not stop the others or the report.
#
# Usage: scripts/run-main.sh [--level quick|default|paper] [build-dir]     (default: default, build)
#   quick    validation cases without the Re 1000 cavity (its 256^2 run), benches at their quick
#            setting, the two convergence sweeps (workflow/config/quick.yaml)
#   default  every validation case at test resolution, benches at their default setting, every
#            sweep (workflow/config/default.yaml)
#   paper    also the `slow` label: the cases at the papers' resolution (about an hour)
# Reruns run only what is out of date: Snakemake compares each job's outputs with its declared
# inputs (scene, binaries, case code, references, the job's command) and reruns a job whose inputs
# changed, plus every job after it; jobs that failed last time run again. The same workflow runs
# on a Slurm cluster with `--profile workflow/profiles/slurm` (docs/workflow.md).
# Extra arguments after `--` go to snakemake (e.g. `-- -n` for a dry run, `-- --summary`).
set -euo pipefail
cd "$(dirname "$0")/.."
level=default
if [[ ${1:-} == --level ]]; then level=${2:?"--level needs quick, default or paper"}; shift 2; fi
case $level in quick|default|paper) ;; *) echo "run-main.sh: unknown level '$level' (quick|default|paper)" >&2; exit 2;; esac
build=build
if [[ $# -gt 0 && $1 != -- ]]; then build=$1; shift; fi
[[ ${1:-} == -- ]] && shift
jobs=${IBMS_JOBS:-$(nproc)}   # parallel build and workflow jobs
start=$(date +%s)
scripts/install-deps.sh --report
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"
build=$(realpath "$build")
# The level and the start (before install and build) for the report's title page.
mkdir -p "$build/workflow_state"
printf '{"level": "%s", "cores": %s, "started": %s}\n' "$level" "$jobs" "$start" > "$build/workflow_state/main_job.json"
# Jobs that did not pass last time run again (their status files are removed).
/usr/bin/python3 workflow/ibms_workflow.py forget-failed "$build"
echo "== workflow (level $level, $jobs cores)"
status=0
# Runs and checks side by side on all cores, one OpenMP thread each (the runner sets it). The
# `run:` jobs run in threads of this process (--force-use-threads): each would otherwise start a
# snakemake process of its own that parses the workflow again (about a second a job).
snakemake -s workflow/Snakefile --directory "$build" --configfile "workflow/config/$level.yaml" \
  --config build="$build" --cores "$jobs" --keep-going --rerun-incomplete --force-use-threads "$@" || status=1
echo
echo "validation checks (case, metric, tolerance, measured, result):"
cat "$build/validation/results.csv" 2>/dev/null || true
/usr/bin/python3 workflow/ibms_workflow.py summary "$build" || status=1
report="$build/ibms_validation_report.pdf"
[[ -f $report ]] && echo "report written to $report (level $level, $(( $(date +%s) - start )) s)"
exit $status
