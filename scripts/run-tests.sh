#!/usr/bin/env bash
# Set-up and tests in one command: installs missing Debian packages, configures and builds ibms
# (Release), then runs every ctest except the `slow` and `cluster` labels (unit, convergence,
# validation; `cluster` is the Slurm test, scripts/run-cluster-test.sh).
# Usage: scripts/run-tests.sh [build-dir]     (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
scripts/install-deps.sh
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)"
cd "$build"
# The tests run side by side on all cores: one OpenMP thread each (no oversubscription).
OMP_NUM_THREADS=1 ctest --output-on-failure -j "$(nproc)" -LE "slow|cluster"
