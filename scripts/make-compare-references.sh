#!/usr/bin/env bash
# Makes the ibms high-resolution references that `ibms compare` reads (docs/compare.md):
#   validation/<cavity case>/reference/ibms_centreline_{u,v}.csv   (256^2 run of the case's scene)
#   validation/settling_disk/reference/ibms_settling_history.csv    (400 x 1200 run, D/h = 50)
# usage: scripts/make-compare-references.sh IBMS_BINARY WORK_DIR
# Runs that already have their output in WORK_DIR (<case>_<N>.h5 and its CSVs) are not rerun.
# CAVITY_CASES="..." restricts the cavity cases; SKIP_SETTLING=1 skips the settling disk.
set -euo pipefail
ibms=$1; work=$2
src=$(cd "$(dirname "$0")/.." && pwd)
commit=$(git -C "$src" rev-parse --short=12 HEAD)
mkdir -p "$work"
n_cavity=256
for case in ${CAVITY_CASES:-lid_driven_cavity_re100 lid_driven_cavity_re400 lid_driven_cavity_re1000 two_sided_cavity_re100}; do
  base=$work/${case}_${n_cavity}
  if [[ ! -s ${base}_centreline_v.csv ]]; then
    echo "running $case at ${n_cavity}^2"
    "$ibms" run "$src/validation/$case/scene.toml" --set domain.cells_x=$n_cavity --set domain.cells_y=$n_cavity \
      -o "$base.h5" --quiet
  fi
  made_by=$(/usr/bin/python3 -c "import h5py; f = h5py.File('$base.h5', 'r'); print(f.attrs['git_commit'])")
  for q in u v; do
    { echo "# ibms reference for 'ibms compare $case' (docs/compare.md): centre-line profile of ibms's own"
      echo "# ${n_cavity} x ${n_cavity} run of validation/$case/scene.toml (run to its steady-state criterion),"
      echo "# ibms commit $made_by; written by scripts/make-compare-references.sh at commit $commit."
      cat "${base}_centreline_$q.csv"; } > "$src/validation/$case/reference/ibms_centreline_$q.csv"
  done
done

n_x=400; n_y=1200; markers=160   # D/h = 50, rim spacing ~h (the slow label's finest grid)
[[ ${SKIP_SETTLING:-0} == 1 ]] && exit 0
base=$work/settling_disk_$n_x
if [[ ! -s ${base}_bodies.csv ]]; then
  echo "running settling_disk at ${n_x} x ${n_y}"
  "$ibms" run "$src/validation/settling_disk/scene.toml" --set domain.cells_x=$n_x --set domain.cells_y=$n_y \
    --set bodies.0.n_surface_points=$markers -o "$base.h5" --quiet || true  # stops at the bottom wall (exit 3)
fi
made_by=$(/usr/bin/python3 -c "import h5py; f = h5py.File('$base.h5', 'r'); print(f.attrs['git_commit'])")
{ echo "# ibms reference for 'ibms compare settling_disk' (docs/compare.md): settling history of ibms's own"
  echo "# ${n_x} x ${n_y} run (D/h = 50, ${markers} rim points) of validation/settling_disk/scene.toml, every fluid step"
  echo "# until the rim reaches the bottom wall; t: time, y: centre height (rim-polygon centroid), v: vertical"
  echo "# centre-of-mass velocity (negative downwards). ibms commit $made_by; written by"
  echo "# scripts/make-compare-references.sh at commit $commit."
  awk -F, 'BEGIN { OFS = "," } /^#/ { next }
    !h { h = 1; for (k = 1; k <= NF; ++k) { if ($k ~ /^body_000\/centroid_y/) cy = k; if ($k ~ /^body_000\/velocity_y/) cv = k }
         print "t [s],y [cm],v [cm/s]"; next }
    { print $1, $cy, $cv }' "${base}_bodies.csv"; } > "$src/validation/settling_disk/reference/ibms_settling_history.csv"
echo "references written"
