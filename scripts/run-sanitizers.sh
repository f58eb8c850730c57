#!/usr/bin/env bash
# The checkers of issue 6: an AddressSanitizer + UndefinedBehaviorSanitizer build that runs the
# `unit` and `convergence` tests (any report fails the test: -fno-sanitize-recover=all, leaks
# included), then a valgrind memcheck of a short `ibms run` of a scene with two bodies, swelling
# and contacts on the ordinary build (any error or definite/indirect leak fails).
# Usage: scripts/run-sanitizers.sh [asan-build-dir=build-asan] [build-dir=build]
# Needs valgrind (scripts/install-deps.sh --checkers).
set -euo pipefail
asan=${1:-build-asan}
build=${2:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
jobs=${IBMS_JOBS:-1}
# RelWithDebInfo: optimised (the convergence tests stay within minutes) with line numbers in reports.
cmake -S . -B "$asan" -DIBMS_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$asan" -j"$jobs"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
(cd "$asan" && ctest -L "unit|convergence" --output-on-failure)
unset ASAN_OPTIONS UBSAN_OPTIONS

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target ibms -j"$jobs"
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
valgrind --tool=memcheck --leak-check=full --show-leak-kinds=definite,indirect --errors-for-leak-kinds=definite,indirect \
  --error-exitcode=99 --log-file="$work/memcheck.log" \
  "$build/solver/ibms" run verification/sim/restart_scene.toml --set run.end_time=0.1 -o "$work/out.h5" --quiet
grep -E "ERROR SUMMARY|definitely lost|indirectly lost|possibly lost|in use at exit" "$work/memcheck.log"
echo "run-sanitizers: ASan+UBSan unit|convergence clean, valgrind memcheck clean"
