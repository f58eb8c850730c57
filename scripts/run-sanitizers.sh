#!/usr/bin/env bash
# The memory and undefined-behaviour checkers (run by .ci/run after the tests): an AddressSanitizer +
# UndefinedBehaviorSanitizer build that runs the `unit` and `convergence` tests (any report fails
# the test: -fno-sanitize-recover=all, leaks included; the script also fails if any report shows
# up in the test log), then a valgrind memcheck of a short `ibms run` of a scene with two bodies,
# swelling and contacts on the ordinary build (any error or definite/indirect leak fails).
# Usage: scripts/run-sanitizers.sh [asan-build-dir=build-asan] [build-dir=build]
# Installs what is missing (scripts/install-deps.sh --checkers: valgrind, ...).
# IBMS_JOBS=n sets the parallel jobs (default: all cores when CI=true, else 1).
set -euo pipefail
asan=${1:-build-asan}
build=${2:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
if [[ "${CI:-}" == "true" ]]; then jobs=${IBMS_JOBS:-$(nproc)}; else jobs=${IBMS_JOBS:-1}; fi
start=$SECONDS
scripts/install-deps.sh --checkers
# RelWithDebInfo: optimised (the convergence tests stay within minutes) with line numbers in reports.
cmake -S . -B "$asan" -DIBMS_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$asan" -j"$jobs"
built=$SECONDS
echo "run-sanitizers: ASan+UBSan build ($jobs jobs) took $((built - start)) s"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Every test's output in ctest's JUnit file: Testing/Temporary/LastTest.log cannot serve, a test
# that lists the tests (workflow_helpers runs `ctest --show-only`) rewrites it meanwhile.
junit=$(realpath -m "$asan")/sanitizer_tests.xml
(cd "$asan" && OMP_NUM_THREADS=1 ctest -L "unit|convergence" --output-on-failure -j"$jobs" --output-junit "$junit")
unset ASAN_OPTIONS UBSAN_OPTIONS
# A report from a process whose exit code a test does not check would not fail that test: count them.
reports=$(grep -c -E "ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:" "$junit" || true)
outputs=$(grep -c "<testcase" "$junit" || true)
echo "run-sanitizers: $outputs tests' output searched"
if ((outputs == 0)); then echo "run-sanitizers: no test output to search"; exit 1; fi
echo "run-sanitizers: sanitizer reports in the test log: $reports; tests took $((SECONDS - built)) s"
if ((reports > 0)); then exit 1; fi

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target ibms -j"$jobs"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
# verification/sim/restart_scene.toml: two wheels, the upper one swelling from t = 0; the wheels
# touch at t = 0.136, the lower one touches the bottom wall at t = 0.28 (100 steps, seconds under valgrind).
valgrind_start=$SECONDS
rc=0
# A wait policy given: `ibms run` does not start itself again (outside valgrind) to set one.
OMP_WAIT_POLICY=passive valgrind --tool=memcheck --leak-check=full --show-leak-kinds=definite,indirect --errors-for-leak-kinds=definite,indirect \
  --error-exitcode=99 --log-file="$work/memcheck.log" \
  "$build/solver/ibms" run verification/sim/restart_scene.toml --set run.end_time=0.4 -o "$work/out.h5" --quiet || rc=$?
if ((rc != 0)); then
  cat "$work/memcheck.log"
  echo "run-sanitizers: valgrind run failed (exit $rc)"
  exit 1
fi
grep -E "ERROR SUMMARY|definitely lost|indirectly lost|possibly lost|in use at exit" "$work/memcheck.log"
# The run must have exercised what it is meant to check: bodies, swelling, body-body and wall contacts.
/usr/bin/python3 - "$work/out.h5" <<'EOF'
import sys
import h5py
s = h5py.File(sys.argv[1], "r")["series"]
diameter = s["per_body/diameter"][:]  # rows x bodies
bodies = range(diameter.shape[1])
grown = max(diameter[-1, :] - diameter[0, :])
pairs = s["contact/n_active_pairs"][:].max()
walls = s["contact/n_wall_contacts"][:].max()
print(f"run-sanitizers: valgrind scene: {len(bodies)} bodies, largest diameter growth {grown:.4f}, "
      f"max {pairs:.0f} body-body and {walls:.0f} wall contact pairs, {len(s['time'])} steps")
if len(bodies) < 2 or grown <= 0 or pairs <= 0 or walls <= 0:
    sys.exit("run-sanitizers: the valgrind run did not exercise bodies, swelling and contacts")
EOF
echo "run-sanitizers: valgrind took $((SECONDS - valgrind_start)) s"
echo "run-sanitizers: ASan+UBSan unit|convergence clean, valgrind memcheck clean ($((SECONDS - start)) s in all)"
