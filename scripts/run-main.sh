#!/usr/bin/env bash
# Set-up and the main job in one command: installs missing Debian packages (with LaTeX), builds
# ibms, runs the unit and convergence tests (their convergence tables go to
# <build>/verification_results/convergence.csv), runs the validation cases (ctest labels by level)
# with their outputs in <build>/validation/<case>/, runs the benches (work-precision, stability
# maps, stage costs; CSV in <build>/bench/), prints the table of checks
# (<build>/validation/results.csv) and builds the PDF report <build>/ibms_validation_report.pdf
# (reports/README.md). Test failures are reported but do not stop the report.
#
# Usage: scripts/run-main.sh [--level quick|default|paper] [build-dir]     (default: default, build)
#   quick    validation cases without the Re 1000 cavity (its 256^2 run), benches at their quick
#            setting: about 5 minutes on 2 cores
#   default  every validation case at test resolution, benches at their default setting: <= 30 min
#   paper    also the `slow` label: the cases at the papers' resolution (hours)
# Reruns reuse a case's finished outputs when neither its inputs (validation/<case>/, the shared
# validation code) nor the binaries (ibms and the checks) changed since they were made (stamp
# <build>/validation/<case>/.inputs.<level>.sha256); the benches likewise (<build>/bench/.inputs.<level>.sha256).
set -euo pipefail
cd "$(dirname "$0")/.."
level=default
if [[ ${1:-} == --level ]]; then level=${2:?"--level needs quick, default or paper"}; shift 2; fi
case $level in quick|default|paper) ;; *) echo "run-main.sh: unknown level '$level' (quick|default|paper)" >&2; exit 2;; esac
build=${1:-build}
jobs=${IBMS_JOBS:-$(nproc)}   # parallel build and test jobs
start=$(date +%s)
scripts/install-deps.sh --report
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"
status=0
rm -f "$build/verification_results/convergence.csv" "$build/verification_results/kernel_moments.csv"
echo "== unit and convergence tests"
# Tests and cases run side by side on all cores: one OpenMP thread each.
export OMP_NUM_THREADS=${OMP_NUM_THREADS:-1}
(cd "$build" && ctest --output-on-failure -j "$jobs" -L "unit|convergence") || status=1
# ctest keeps only the last run's log; keep this one for the report's run times.
cp "$build/Testing/Temporary/LastTest.log" "$build/Testing/Temporary/LastTest_verification.log" || true

echo "== validation cases (level $level)"
labels=validation
[[ $level == paper ]] && labels="validation|slow"
excluded='^$' excluded_cases='^$'
[[ $level == quick ]] && excluded='^lid_driven_cavity_re1000_' excluded_cases='^lid_driven_cavity_re1000$'
# Fingerprint of what a case's outputs depend on: the binaries, the shared validation code, its folder.
binaries_hash=$(cat "$build/solver/ibms" $(find "$build/validation" -maxdepth 2 -type f -executable | sort) | sha256sum | cut -c1-64)
shared_hash=$(cat validation/CMakeLists.txt validation/common/* | sha256sum | cut -c1-64)
case_hash() { (echo "$binaries_hash $shared_hash $level"; find "validation/$1" -type f | sort | xargs cat) | sha256sum | cut -c1-64; }
previous_results=$(mktemp)
cp "$build/validation/results.csv" "$previous_results" 2>/dev/null || true
rm -f "$build/validation/results.csv"
mkdir -p "$build/validation"
rerun=() reused=()
for dir in validation/*/; do
  c=$(basename "$dir")
  [[ $c == common || ! ( -f $dir/scene.toml || -f $dir/CMakeLists.txt ) ]] && continue
  [[ $c =~ $excluded_cases ]] && continue
  stamp="$build/validation/$c/.inputs.$level.sha256"
  # The stamp is written only after every test of the case passed; its result lines (if it writes
  # any to results.csv) are carried over.
  if [[ -f $stamp && $(cat "$stamp") == $(case_hash "$c") ]]; then
    reused+=("$c"); grep "^$c," "$previous_results" >> "$build/validation/results.csv" || true
  else
    rerun+=("$c"); rm -f "$stamp"
  fi
done
rm -f "$previous_results"
[[ ${#reused[@]} -gt 0 ]] && echo "reusing finished outputs (inputs and binaries unchanged): ${reused[*]}"
if [[ ${#rerun[@]} -gt 0 ]]; then
  regex="^($(IFS='|'; echo "${rerun[*]}"))_"
  log="$build/Testing/Temporary/LastTest.log"
  validation_status=0
  (cd "$build" && ctest --output-on-failure -j "$jobs" -L "$labels" -R "$regex" -E "$excluded") || validation_status=1
  [[ $validation_status -ne 0 ]] && status=1
  # A case is stamped only when none of its tests failed; failed cases run again next time.
  failed="$build/Testing/Temporary/LastTestsFailed.log"
  for c in "${rerun[@]}"; do
    if [[ $validation_status -ne 0 && -f $failed ]] && grep -q ":${c}_" "$failed"; then continue; fi
    mkdir -p "$build/validation/$c" && case_hash "$c" > "$build/validation/$c/.inputs.$level.sha256"
  done
  cp "$log" "$build/Testing/Temporary/LastTest_validation_$(date +%Y%m%d%H%M%S).log" 2>/dev/null || true
fi
echo
echo "validation checks (case, metric, tolerance, measured, result):"
cat "$build/validation/results.csv" || true

echo "== benches (level $level)"
bench_level=$([[ $level == quick ]] && echo quick || echo default)
bench_stamp="$build/bench/.inputs.$level.sha256"
bench_hash=$( (cat "$build"/bench/bench_* validation/*/reference/ibms_* 2>/dev/null; echo "$level") | sha256sum | cut -c1-64)
if [[ -f $bench_stamp && $(cat "$bench_stamp") == "$bench_hash" ]]; then
  echo "reusing bench outputs (binaries unchanged)"
else
  rm -f "$bench_stamp"
  bench_status=0
  "$build/bench/bench_overhead" "$build/bench" || bench_status=1
  "$build/bench/bench_work_precision" "$bench_level" "$build/bench" || bench_status=1
  "$build/bench/bench_stability" "$build/bench" || bench_status=1
  # Fluid maps, 64^2 to t = 10 L/U (3.7 min on one core); not at the quick level (a shorter horizon
  # would hide the slow instabilities the maps are for).
  if [[ $bench_level != quick ]]; then
    "$build/bench/bench_fluid_stability" "$build/bench" || bench_status=1
  fi
  "$build/bench/bench_forcing_passes" "$bench_level" || bench_status=1
  if [[ $bench_status -eq 0 ]]; then echo "$bench_hash" > "$bench_stamp"; else status=1; fi
fi

echo "== report"
report="$build/ibms_validation_report.pdf"
/usr/bin/python3 reports/build_report.py --build "$build" --output "$report"
echo "report written to $(realpath "$report") (level $level, $(( $(date +%s) - start )) s)"
exit $status
