#!/usr/bin/env bash
# Set-up and the main job in one command: installs missing Debian packages (with LaTeX), builds
# ibms, runs the unit and convergence tests (their convergence tables go to
# <build>/verification_results/convergence.csv), runs the validation cases (ctest label
# `validation`) with their outputs in <build>/validation/<case>/, prints the table of checks
# (<build>/validation/results.csv) and builds the PDF report <build>/ibms_validation_report.pdf
# (reports/README.md). Test failures are reported but do not stop the report.
# Usage: scripts/run-main.sh [build-dir]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
scripts/install-deps.sh --report
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)"
status=0
rm -f "$build/verification_results/convergence.csv" "$build/validation/results.csv"
echo "== unit and convergence tests"
(cd "$build" && ctest --output-on-failure -j "$(nproc)" -L "unit|convergence") || status=1
# ctest keeps only the last run's log; keep this one for the report's run times.
cp "$build/Testing/Temporary/LastTest.log" "$build/Testing/Temporary/LastTest_verification.log" || true
echo "== validation cases"
(cd "$build" && ctest --output-on-failure -j "$(nproc)" -L validation) || status=1
echo
echo "validation checks (case, metric, tolerance, measured, result):"
cat "$build/validation/results.csv" || true
echo "== report"
report="$build/ibms_validation_report.pdf"
/usr/bin/python3 reports/build_report.py --build "$build" --output "$report"
echo "report written to $(realpath "$report")"
exit $status
