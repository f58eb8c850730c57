#!/usr/bin/env bash
# Builds a libFuzzer target with Debian's clang (ASan + UBSan + fuzzer coverage) and runs it on its
# seeds and a copy of its committed corpus, then replaces the corpus with the minimised merge of the
# old corpus and what it found (only inputs that add coverage). Targets:
#   scene    fuzz_scene: scene parsing (seeds/: the validation scenes and two test scenes; corpus/)
#   compare  fuzz_compare: `ibms compare`'s CSV readers (compare_seeds/: the shipped references and
#            the compare tests' bad inputs, make_compare_seeds.py; compare_corpus/)
# A crash input is left in the work directory as crash-* and must become a file in
# verification/fuzz/regressions/ (scene) or compare_regressions/ (compare), which the corpus tests read.
# Usage: scripts/run-fuzz.sh [seconds=600] [build-dir=build-fuzz] [target=scene]
# Needs clang-14 and libclang-rt-14-dev (scripts/install-deps.sh --checkers).
set -euo pipefail
seconds=${1:-600}
build=${2:-build-fuzz}
target=${3:-scene}
case $target in
  scene) seeds=verification/fuzz/seeds; corpus=verification/fuzz/corpus; max_len=8192 ;;
  compare) seeds=verification/fuzz/compare_seeds; corpus=verification/fuzz/compare_corpus; max_len=20000 ;;
  *) echo "run-fuzz: unknown target '$target' (scene or compare)"; exit 2 ;;
esac
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -DIBMS_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target "fuzz_$target" -j1
fuzzer=$(cd "$build" && pwd)/verification/fuzz/fuzz_$target
work="$build/fuzz-work-$target"
mkdir -p "$work/corpus" "$work/artifacts"
cp "$seeds"/* "$work/corpus/"
cp "$corpus"/* "$work/corpus/" 2>/dev/null || true
# Output paths in fuzzed scenes are only checked (exists, writable), never created; run inside
# the work directory so relative ones point there.
(cd "$work" && "$fuzzer" -max_total_time="$seconds" -max_len="$max_len" \
   -timeout=10 -rss_limit_mb=2048 -artifact_prefix=artifacts/ -print_final_stats=1 corpus \
   2>&1 | tee fuzz.log | grep -E "^#[0-9]+ +(INITED|DONE)|stat::|==ERROR|SUMMARY|Test unit written" || true)
# Minimised merge of the new corpus into the committed one.
mkdir -p "$work/merged"
rm -f "$work/merged"/*
(cd "$work" && "$fuzzer" -merge=1 merged "$root/$corpus" corpus >merge.log 2>&1)
mkdir -p "$corpus"
rm -f "$corpus"/*
cp "$work/merged"/* "$corpus"/
echo "run-fuzz: merged corpus $(ls "$work/merged" | wc -l) files, $(du -sh "$work/merged" | cut -f1);"\
     "crashes: $(ls "$work/artifacts" | wc -l) (in $work/artifacts)"
