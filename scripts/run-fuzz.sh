#!/usr/bin/env bash
# Builds the libFuzzer scene target with Debian's clang (ASan + UBSan + fuzzer coverage) and runs it
# on the seeds (verification/fuzz/seeds: the validation scenes and two test scenes) and a copy of
# the committed corpus, then replaces verification/fuzz/corpus with the minimised merge of the old
# corpus and what it found (only inputs that add coverage). A crash input is left in the work directory as
# crash-* and must become a file in verification/fuzz/regressions/ (test_fuzz_corpus reads it).
# Usage: scripts/run-fuzz.sh [seconds=600] [build-dir=build-fuzz]
# Needs clang-14 and libclang-rt-14-dev (scripts/install-deps.sh --checkers).
set -euo pipefail
seconds=${1:-600}
build=${2:-build-fuzz}
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -DIBMS_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target fuzz_scene -j1
fuzzer=$(cd "$build" && pwd)/verification/fuzz/fuzz_scene
work="$build/fuzz-work"
mkdir -p "$work/corpus" "$work/artifacts"
cp verification/fuzz/seeds/* "$work/corpus/"
cp verification/fuzz/corpus/* "$work/corpus/" 2>/dev/null || true
# Output paths in fuzzed scenes are only checked (exists, writable), never created; run inside
# the work directory so relative ones point there.
(cd "$work" && "$fuzzer" -max_total_time="$seconds" -max_len=8192 \
   -timeout=10 -rss_limit_mb=2048 -artifact_prefix=artifacts/ -print_final_stats=1 corpus \
   2>&1 | tee fuzz.log | grep -E "^#[0-9]+ +(INITED|DONE)|stat::|==ERROR|SUMMARY|Test unit written" || true)
# Minimised merge of the new corpus into the committed one.
mkdir -p "$work/merged"
rm -f "$work/merged"/*
(cd "$work" && "$fuzzer" -merge=1 merged "$root/verification/fuzz/corpus" corpus >merge.log 2>&1)
rm -f verification/fuzz/corpus/*
cp "$work/merged"/* verification/fuzz/corpus/
echo "run-fuzz: merged corpus $(ls "$work/merged" | wc -l) files, $(du -sh "$work/merged" | cut -f1);"\
     "crashes: $(ls "$work/artifacts" | wc -l) (in $work/artifacts)"
