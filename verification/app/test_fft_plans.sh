#!/usr/bin/env bash
# Claims (fluid/fft_wisdom_cache.hpp, scene key run.fft_plans):
# - a run of measured plans writes the machine's wisdom cache (IBMS_FFT_WISDOM) when it planned sizes
#   the cache lacked; a second run of the same scene reads it, adds nothing (the file stays the same
#   bytes) and gives the same bits as the first (it found the first run's plans);
# - a new size joins the cache without losing the earlier ones; `ibms info` plans as the run does;
# - a cache FFTW cannot read is ignored: the run succeeds and replaces it; IBMS_FFT_WISDOM=off
#   writes no file;
# - run.fft_plans = "estimate" neither reads nor writes the cache, and gives the same bits at every
#   run on one and on two threads.
set -u
ibms=$1; scene=$2; compare=$3
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
fail=0
say() { echo "$1"; [[ $1 == FAIL* ]] && fail=1; return 0; }
run() {  # run OUTPUT PLANS [ibms options...]: a 32 x 32 cavity over 40 steps
  local out=$1 plans=$2; shift 2
  "$ibms" run "$scene" --set domain.cells_x=32 --set domain.cells_y=32 --set run.max_steps=40 \
    --set run.fft_plans="\"$plans\"" -o "$work/$out" --quiet "$@" > "$work/log" 2>&1 ||
    say "FAIL ibms run $plans $*: exit $?: $(tail -2 "$work/log")"
}
same_bits() {  # same_bits A B: the final checkpoints (the whole state) bit for bit
  /usr/bin/python3 "$compare" "$work/$1" "$work/$2" > "$work/cmp" 2>&1
}

export IBMS_FFT_WISDOM=$work/cache/wisdom.txt
run a.h5 measure --threads 1
[[ -s $IBMS_FFT_WISDOM ]] && say "ok   first measured run wrote the cache ($(wc -c < "$IBMS_FFT_WISDOM") bytes)" \
  || say "FAIL first measured run wrote no cache at $IBMS_FFT_WISDOM"
cp "$IBMS_FFT_WISDOM" "$work/first.txt"
inode=$(stat -c %i "$IBMS_FFT_WISDOM")
run b.h5 measure --threads 1
# A run that did not read the cache would measure again and write it anew (a new file by rename).
[[ $(stat -c %i "$IBMS_FFT_WISDOM") == "$inode" ]] && cmp -s "$IBMS_FFT_WISDOM" "$work/first.txt" &&
  say "ok   second run read the cache and added nothing to it" ||
  say "FAIL second run of the same scene rewrote the cache"
same_bits a.h5 b.h5 && say "ok   second run (plans from the cache) gives the first run's bits" \
  || say "FAIL second run differs from the first: $(tail -3 "$work/cmp")"
"$ibms" run "$scene" --set domain.cells_x=48 --set domain.cells_y=40 --set run.max_steps=2 -o "$work/c.h5" \
  --set run.fft_plans='"measure"' --quiet --threads 1 > "$work/log" 2>&1 || say "FAIL 48 x 40 run: $(tail -2 "$work/log")"
if [[ $(wc -c < "$IBMS_FFT_WISDOM") -gt $(wc -c < "$work/first.txt") ]]; then
  say "ok   a new size joined the cache ($(wc -c < "$work/first.txt") -> $(wc -c < "$IBMS_FFT_WISDOM") bytes)"
else
  say "FAIL a new size did not grow the cache"
fi
cp "$IBMS_FFT_WISDOM" "$work/second.txt"
"$ibms" info "$scene" --set domain.cells_x=64 --set domain.cells_y=24 --set run.fft_plans='"measure"' > "$work/log" 2>&1 || say "FAIL ibms info: $(tail -2 "$work/log")"
[[ $(wc -c < "$IBMS_FFT_WISDOM") -gt $(wc -c < "$work/second.txt") ]] && say "ok   ibms info's plans joined the cache" \
  || say "FAIL ibms info planned without the cache"

printf 'not FFTW wisdom\n' > "$IBMS_FFT_WISDOM"
run d.h5 measure --threads 1
grep -q "not FFTW wisdom" "$IBMS_FFT_WISDOM" && say "FAIL an unreadable cache was kept" \
  || say "ok   an unreadable cache is ignored and replaced ($(wc -c < "$IBMS_FFT_WISDOM") bytes)"
ls "$work"/cache/*.part* > /dev/null 2>&1 && say "FAIL a partial cache file was left behind"

IBMS_FFT_WISDOM=$work/off/wisdom.txt run e1.h5 estimate --threads 1
IBMS_FFT_WISDOM=$work/off/wisdom.txt run e2.h5 estimate --threads 1
IBMS_FFT_WISDOM=$work/off/wisdom.txt run e3.h5 estimate --threads 2
[[ -e $work/off/wisdom.txt ]] && say "FAIL an estimate run wrote the cache" || say "ok   estimate runs leave the cache alone"
same_bits e1.h5 e2.h5 && say "ok   estimate: two runs give the same bits" || say "FAIL estimate: two runs differ: $(tail -3 "$work/cmp")"
same_bits e1.h5 e3.h5 && say "ok   estimate: one and two threads give the same bits" \
  || say "FAIL estimate: one and two threads differ: $(tail -3 "$work/cmp")"
IBMS_FFT_WISDOM=off run f.h5 measure --threads 1
[[ -e $work/off ]] && say "FAIL IBMS_FFT_WISDOM=off wrote a file" || say "ok   IBMS_FFT_WISDOM=off writes no cache"
exit $fail
