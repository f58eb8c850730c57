#!/usr/bin/env bash
# Set-up and the main job in one command: installs missing Debian packages (with LaTeX), builds
# ibms, runs the validation cases (ctest label `validation`) with their outputs in
# <build>/validation/<case>/, and prints the table of checks (<build>/validation/results.csv).
# Usage: scripts/run-main.sh [build-dir]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
scripts/install-deps.sh --report
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)"
rm -f "$build/validation/results.csv"
(cd "$build" && ctest --output-on-failure -j "$(nproc)" -L validation)
echo
echo "validation checks (case, metric, tolerance, measured, result):"
cat "$build/validation/results.csv"
if [[ -x reports/build_report.py ]]; then
  /usr/bin/python3 reports/build_report.py --build "$build" --output "$build/ibms_validation_report.pdf"
fi
