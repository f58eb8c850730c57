#!/usr/bin/env bash
# Threads on an idle and on a busy machine, as a user runs them (docs/design.md §9): the wall time
# of `ibms run` on one thread, on the default (the cores this process may use, a spin bounded at
# GOMP_SPINCOUNT=10000, the thread governor), and on the previous default (all cores, libgomp's own spin of 300000, no
# governor), first alone, then beside a competing load: a second `ibms run` (lid-driven cavity 256²)
# on all cores. Prints a table and the ratios the default is held to: busy, default / one thread
# (<= 1.2); idle, default / previous default (<= 1).
# usage: bench/bench_threads.sh IBMS_BINARY [STEPS]   (run from anywhere; STEPS per run, default 600)
set -euo pipefail
ibms=$(realpath "$1"); steps=${2:-600}
src=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
load_group=""
# The load runs in its own process group, so that the trap stops the loop and its ibms alike.
trap '[ -n "$load_group" ] && kill -- -"$load_group" 2>/dev/null; rm -rf "$work"' EXIT
cores=$(nproc)

declare -A scene=(
  [settling_disk]="$src/validation/settling_disk/scene.toml"
  [cavity_re1000_128]="$src/validation/lid_driven_cavity_re1000/scene.toml --set domain.cells_x=128 --set domain.cells_y=128 --set fluid.convection=central --set fluid.wall_closure=linear"
)

# run MODE SCENE STEPS: prints the wall time of the whole run (start-up and FFT planning included)
# and of its steps (the run loop, as `ibms run` reports it), in seconds.
run() {
  local mode=$1 name=$2 n=$3 start end log
  local -a env_mode=() args=()
  case $mode in
    one) args=(--threads 1) ;;
    default) env_mode=(env -u OMP_NUM_THREADS -u OMP_WAIT_POLICY -u GOMP_SPINCOUNT) ;;
    previous) env_mode=(env -u OMP_WAIT_POLICY GOMP_SPINCOUNT=300000 OMP_NUM_THREADS="$cores") ;;
  esac
  log="$work/$name-$mode.log"
  start=$(date +%s.%N)
  # shellcheck disable=SC2086
  "${env_mode[@]}" "$ibms" run ${scene[$name]} --set run.max_steps="$n" --set run.steady_tolerance=0 \
    -o "$work/$name-$mode.h5" "${args[@]}" > /dev/null 2> "$log"
  end=$(date +%s.%N)
  echo "$(echo "$end - $start" | bc -l) $(sed -n 's/^ibms: [0-9]* steps to .* in \([0-9.]*\) s;.*/\1/p' "$log")"
}

# The previous default on a busy machine takes minutes per hundred steps: it runs a tenth of the
# steps, and its figures are per step.
declare -A wall step
measure() {
  local load=$1 n
  for name in "${!scene[@]}"; do
    for mode in one default previous; do
      n=$steps
      [ "$load,$mode" = busy,previous ] && n=$(( (steps + 9) / 10 ))
      read -r w s < <(run "$mode" "$name" "$n")
      wall[$load,$name,$mode]=$w
      step[$load,$name,$mode]=$(echo "1000 * $s / $n" | bc -l)
      printf '%-5s %-18s %-9s %5d steps %8.2f s in all %8.3f ms per step\n' "$load" "$name" "$mode" "$n" "$w" \
        "${step[$load,$name,$mode]}"
    done
  done
}

echo "bench_threads: $cores cores, $steps steps per run, $(uptime | sed 's/.*load/load/')"
measure idle
# The competing load: the 256² cavity on all cores, restarted until the bench ends.
setsid bash -c 'while true; do
    OMP_NUM_THREADS=$0 "$1" run "$2/validation/lid_driven_cavity_re1000/scene.toml" \
      --set domain.cells_x=256 --set domain.cells_y=256 --set run.steady_tolerance=0 -o "$3/load.h5" --quiet \
      --set fluid.convection=central --set fluid.wall_closure=linear \
      > /dev/null 2>&1 || true
  done' "$cores" "$ibms" "$src" "$work" &
load_group=$!
sleep 2
measure busy
echo
echo "ratios (per step: the run loop; in all: start-up and planning included, equal step counts):"
for name in "${!scene[@]}"; do
  r() { echo "${1} / ${2}" | bc -l; }
  printf '%-18s busy: default / one thread %.2f per step, %.2f in all (target <= 1.2); previous / one %.1f per step\n' \
    "$name" "$(r "${step[busy,$name,default]}" "${step[busy,$name,one]}")" \
    "$(r "${wall[busy,$name,default]}" "${wall[busy,$name,one]}")" \
    "$(r "${step[busy,$name,previous]}" "${step[busy,$name,one]}")"
  printf '%-18s idle: default / previous %.2f per step, %.2f in all (target <= 1); one / previous %.2f per step\n' \
    "$name" "$(r "${step[idle,$name,default]}" "${step[idle,$name,previous]}")" \
    "$(r "${wall[idle,$name,default]}" "${wall[idle,$name,previous]}")" \
    "$(r "${step[idle,$name,one]}" "${step[idle,$name,previous]}")"
done
