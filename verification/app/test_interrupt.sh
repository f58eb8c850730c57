#!/usr/bin/env bash
# Claims, on verification/sim/restart_scene.toml (bodies, swelling, contacts):
# (1) SIGTERM: the run writes a complete checkpoint and exits with code 4; `ibms run --restart`
#     from it ends bit-identical (every /checkpoint value) to the run that was never interrupted.
# (2) SIGINT: the same exit code 4 and a complete checkpoint.
# (3) SIGKILL: the HDF5 file stays readable (h5py opens it; the series are aligned and as long as
#     the last flush) and its last periodic checkpoint restarts to the same bit-identical end.
# Usage: test_interrupt.sh IBMS SCENE COMPARE_SCRIPT
set -u
ibms=$1; scene=$2; compare=$3
python=/usr/bin/python3
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
# A longer run of the restart scene, so that a signal sent after a short wait arrives mid-run.
long=(--set run.end_time=5.0 --quiet)

start=$(date +%s.%N)
"$ibms" run "$scene" "${long[@]}" -o whole.h5 || fail "uninterrupted run: exit $?"
whole_seconds=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { print e - s }')
# Signals go out at fractions of the uninterrupted run's duration, so they land mid-run on any machine.
at() { awk -v t="$whole_seconds" -v f="$1" 'BEGIN { printf "%.3f", t * f }'; }
echo "     uninterrupted run: $whole_seconds s"

interrupt() {  # signal, output file, seconds to wait, extra arguments; sets $code
  local signal=$1 out=$2 wait=$3; shift 3
  "$ibms" run "$scene" "${long[@]}" -o "$out" "$@" 2> "$out.err" &
  local pid=$!
  sleep "$wait"
  kill -s "$signal" "$pid"
  wait "$pid"; code=$?
}

# (1) SIGTERM, then restart.
interrupt TERM term.h5 "$(at 0.4)"
if [[ $code -ne 4 ]]; then
  fail "SIGTERM: exit $code (expected 4): $(cat term.h5.err)"
else
  echo "ok   SIGTERM: $(cat term.h5.err)"
  "$ibms" run "$scene" "${long[@]}" --restart term.h5 -o term_restart.h5 || fail "restart after SIGTERM: exit $?"
  if out=$($python "$compare" whole.h5 term_restart.h5); then echo "ok   SIGTERM restart: $out"
  else fail "SIGTERM restart: $out"; fi
fi

# (2) SIGINT.
interrupt INT int.h5 "$(at 0.2)"
steps=$($python -c "import h5py; print(int(h5py.File('int.h5','r')['checkpoint'].attrs['step']))" 2>&1)
if [[ $code -ne 4 ]] || ! [[ $steps =~ ^[0-9]+$ ]]; then fail "SIGINT: exit $code, checkpoint step '$steps'"
else echo "ok   SIGINT: exit 4, checkpoint at step $steps"; fi

# (3) SIGKILL with a checkpoint every 25 steps. A kill before the first checkpoint (a loaded
# machine), or after the run ended (a machine that got faster), proves nothing: try another moment.
for wait_seconds in "$(at 0.5)" "$(at 0.8)" "$(at 0.3)" "$(at 0.15)"; do
  interrupt KILL kill.h5 $wait_seconds --set output.checkpoint_every=25
  summary=$($python - <<'PY' 2>&1
import h5py, numpy as np
with h5py.File("kill.h5", "r") as f:
    lengths = {name: f["series"][name].shape[0] for name in ["time", "step", "kinetic_energy"]}
    assert len(set(lengths.values())) == 1, lengths
    steps = f["series/step"][()]
    assert np.array_equal(steps, np.arange(1, len(steps) + 1)), "series/step is not 1..n"
    if len(steps) < 25:
        print(f"only {len(steps)} steps before the kill")
    else:
        group = f["checkpoint"] if "checkpoint" in f else f["checkpoint_next"]
        step = int(group.attrs["step"])
        assert group.attrs["complete"] == 1 and step % 25 == 0 and 0 < step <= len(steps), (step, len(steps))
        print(f"{len(steps)} series rows readable, checkpoint at step {step}")
PY
); read_status=$?
  [[ $code -eq 137 && $summary != "only "* ]] && break
  echo "     SIGKILL after $wait_seconds s: exit $code, $(echo "$summary" | tail -n 1); trying another moment"
done
if [[ $code -ne 137 || $read_status -ne 0 || $summary == "only "* ]]; then
  fail "SIGKILL: exit $code: $(echo "$summary" | tail -n 3)"
else
  echo "ok   SIGKILL: exit 137, $summary"
  "$ibms" run "$scene" "${long[@]}" --restart kill.h5 -o kill_restart.h5 || fail "restart after SIGKILL: exit $?"
  if out=$($python "$compare" whole.h5 kill_restart.h5); then echo "ok   SIGKILL restart: $out"
  else fail "SIGKILL restart: $out"; fi
fi

# A restart onto its own checkpoint file is refused (exit 2, one line), the file untouched.
cp term.h5 before.h5
"$ibms" run "$scene" "${long[@]}" --restart term.h5 -o term.h5 2> err.txt; code=$?
if [[ $code -ne 2 || $(wc -l < err.txt) -ne 1 ]] || ! cmp -s term.h5 before.h5; then
  fail "restart onto its own file: exit $code: $(cat err.txt)"
else echo "ok   restart onto its own file refused: $(cat err.txt)"; fi

echo "$failures failure(s)"
exit $((failures > 0))
