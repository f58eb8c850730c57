#!/usr/bin/env bash
# Threads on an idle and on a busy machine, as a user runs them (docs/design.md §9): the wall time
# of `ibms run` on one thread, on the default (the cores this process may use, OpenMP's passive
# wait, the thread governor), and on the previous default (all cores, libgomp's own spin of 300000, no
# governor), first alone, then beside a competing load: a second `ibms run` (lid-driven cavity 256²)
# on all cores. Prints a table and the ratios the default is held to: busy, default / one thread
# (<= 1.2); idle, default / previous default (<= 1).
# usage: bench/bench_threads.sh IBMS_BINARY [STEPS]   (run from anywhere; STEPS per run, default 120)
set -euo pipefail
ibms=$(realpath "$1"); steps=${2:-120}
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
cores=$(nproc)

declare -A scene=(
  [settling_disk]="$src/validation/settling_disk/scene.toml"
  [cavity_re1000_128]="$src/validation/lid_driven_cavity_re1000/scene.toml --set domain.cells_x=128 --set domain.cells_y=128"
)

# seconds MODE SCENE: the wall time of one run of STEPS steps.
seconds() {
  local mode=$1 name=$2 start end
  local -a env_mode=() args=()
  case $mode in
    one) args=(--threads 1) ;;
    default) env_mode=(env -u OMP_NUM_THREADS -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT) ;;
    previous) env_mode=(env -u OMP_WAIT_POLICY GOMP_SPINCOUNT=300000 OMP_NUM_THREADS="$cores") ;;
  esac
  start=$(date +%s.%N)
  # shellcheck disable=SC2086
  "${env_mode[@]}" "$ibms" run ${scene[$name]} --set run.max_steps="$steps" --set run.steady_tolerance=0 \
    -o "$work/$name-$mode.h5" --quiet "${args[@]}" > /dev/null
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}

declare -A t
measure() {
  local load=$1
  for name in "${!scene[@]}"; do
    for mode in one default previous; do
      t[$load,$name,$mode]=$(seconds "$mode" "$name")
      printf '%-5s %-18s %-9s %8.2f s\n' "$load" "$name" "$mode" "${t[$load,$name,$mode]}"
    done
  done
}

echo "bench_threads: $cores cores, $steps steps per run, $(uptime | sed 's/.*load/load/')"
measure idle
# The competing load: the 256² cavity on all cores, restarted until the bench ends.
( while true; do
    OMP_NUM_THREADS=$cores "$ibms" run "$src/validation/lid_driven_cavity_re1000/scene.toml" \
      --set domain.cells_x=256 --set domain.cells_y=256 --set run.steady_tolerance=0 -o "$work/load.h5" --quiet \
      > /dev/null 2>&1 || true
  done ) &
sleep 2
measure busy
echo
echo "ratios (wall time):"
for name in "${!scene[@]}"; do
  printf '%-18s busy: default / one thread %.2f (target <= 1.2), previous / one thread %.2f; ' "$name" \
    "$(echo "${t[busy,$name,default]} / ${t[busy,$name,one]}" | bc -l)" \
    "$(echo "${t[busy,$name,previous]} / ${t[busy,$name,one]}" | bc -l)"
  printf 'idle: default / previous %.2f (target <= 1), one / previous %.2f\n' \
    "$(echo "${t[idle,$name,default]} / ${t[idle,$name,previous]}" | bc -l)" \
    "$(echo "${t[idle,$name,one]} / ${t[idle,$name,previous]}" | bc -l)"
done
