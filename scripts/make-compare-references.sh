#!/usr/bin/env bash
# Makes the ibms high-resolution references that `ibms compare` reads (docs/compare.md):
#   validation/<cavity case>/reference/ibms_centreline_{u,v}.csv   (256^2 run of the case's scene)
#   validation/settling_disk/reference/ibms_settling_history.csv    (400 x 1200 run, D/h = 50)
#   validation/cavity_swelling_particles/reference/ibms_trajectories_{nonswelling,swelling}.csv
#   validation/cavity_deformable_objects/reference/ibms_deformation_k{10,100}.csv
#     (the body cases at their validation grid, 100 x 100, as their ctest runs them)
#   validation/dfg_cylinder_2d1/reference/ibms_dfg_2d1.csv          (D/h = 40, the validation label's finest)
#   validation/dfg_cylinder_2d2/reference/ibms_dfg_2d2_forces.csv   (D/h = 30, t >= 8)
# usage: scripts/make-compare-references.sh IBMS_BINARY WORK_DIR
# REFERENCE_OUT=DIR writes DIR/<case>/reference/ibms_*.csv instead of into the source tree's
# validation/<case>/reference/ (the default); ONLY="<case> ..." (or "<case>/<ibms_file>.csv ...")
# makes only those references and only the runs they need (the `slow` tests <case>_reference_regenerates,
# validation/CMakeLists.txt, regenerate one case each this way).
# Runs that already have their output in WORK_DIR (<case>_<N>.h5 and its CSVs) are not rerun.
# CAVITY_CASES="..." restricts the cavity cases; SKIP_SETTLING=1 skips the settling disk;
# ONLY_BODIES=1 makes only the two body cases' references; ONLY_DFG=1 only the two DFG cases' (their
# runs WORK_DIR/dfg_2d1_40 and dfg_2d2_30, e.g. links to build/validation/dfg_cylinder_*/ outputs). Their runs are WORK_DIR/<case>_<variant>.h5
# (variant nonswelling|swelling|k10|k100); links to the ctest outputs are reused, e.g.
# build/validation/cavity_deformable_objects/k10{.h5,_bodies.csv} linked as
# WORK_DIR/cavity_deformable_objects_k10{.h5,_bodies.csv}.
set -euo pipefail
ibms=$1; work=$2
src=$(cd "$(dirname "$0")/.." && pwd)
commit=$(git -C "$src" rev-parse --short=12 HEAD)
mkdir -p "$work"
out=${REFERENCE_OUT:-$src/validation}
# wanted CASE [FILE...]: true if ONLY is unset or names CASE or one of CASE/FILE
wanted() {
  [[ -z ${ONLY:-} ]] && return 0
  local case=$1; shift
  local item f
  for item in $ONLY; do
    [[ $item == "$case" ]] && return 0
    for f in "$@"; do [[ $item == "$case/$f" ]] && return 0; done
  done
  return 1
}
# target CASE FILE: the path a reference is written to (its folder made)
target() { mkdir -p "$out/$1/reference"; echo "$out/$1/reference/$2"; }
n_cavity=256
[[ ${ONLY_BODIES:-0} == 1 || ${ONLY_DFG:-0} == 1 ]] && CAVITY_CASES=none SKIP_SETTLING=1
for case in ${CAVITY_CASES:-lid_driven_cavity_re100 lid_driven_cavity_re400 lid_driven_cavity_re1000 two_sided_cavity_re100}; do
  [[ $case == none ]] && continue
  wanted "$case" ibms_centreline_u.csv ibms_centreline_v.csv || continue
  base=$work/${case}_${n_cavity}
  if [[ ! -s ${base}_centreline_v.csv ]]; then
    echo "running $case at ${n_cavity}^2"
    "$ibms" run "$src/validation/$case/scene.toml" --set domain.cells_x=$n_cavity --set domain.cells_y=$n_cavity \
      -o "$base.h5" --quiet
  fi
  made_by=$(/usr/bin/python3 -c "import h5py; f = h5py.File('$base.h5', 'r'); print(f.attrs['git_commit'])")
  for q in u v; do
    wanted "$case" ibms_centreline_$q.csv || continue
    { echo "# ibms reference for 'ibms compare $case' (docs/compare.md): centre-line profile of ibms's own"
      echo "# ${n_cavity} x ${n_cavity} run of validation/$case/scene.toml (run to its steady-state criterion),"
      echo "# ibms commit $made_by; written by scripts/make-compare-references.sh at commit $commit."
      cat "${base}_centreline_$q.csv"; } > "$(target "$case" ibms_centreline_$q.csv)"
  done
done

n_x=400; n_y=1200; markers=160   # D/h = 50, rim spacing ~h (the slow label's finest grid)
if [[ ${SKIP_SETTLING:-0} != 1 ]] && wanted settling_disk ibms_settling_history.csv; then
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
    { print $1, $cy, $cv }' "${base}_bodies.csv"; } > "$(target settling_disk ibms_settling_history.csv)"
fi

# DFG cylinders (docs/compare.md): the slow label's finest runs.
dfg_run() {  # case scene_dir n -> runs unless WORK_DIR has its _bodies.csv
  local base=$work/$1_$3
  if [[ ! -s ${base}_bodies.csv ]]; then
    echo "running $1 at D/h = $3"
    "$ibms" run "$src/validation/$2/scene.toml" --set domain.cells_x=$((22 * $3)) \
      --set domain.cells_y=$(((41 * $3 + 5) / 10)) --set bodies.0.n_surface_points=$(((314159 * $3 + 50000) / 100000)) \
      -o "$base.h5" --quiet
  fi
}
if [[ ${ONLY_BODIES:-0} != 1 ]]; then
  wanted dfg_cylinder_2d1 ibms_dfg_2d1.csv && dfg_run dfg_2d1 dfg_cylinder_2d1 40
  wanted dfg_cylinder_2d2 ibms_dfg_2d2_forces.csv && dfg_run dfg_2d2 dfg_cylinder_2d2 30
  for spec in "dfg_2d1_40 dfg_cylinder_2d1 ibms_dfg_2d1.csv steady" \
              "dfg_2d2_30 dfg_cylinder_2d2 ibms_dfg_2d2_forces.csv periodic"; do
    read -r run dfg_case file kind <<< "$spec"
    wanted "$dfg_case" "$file" || continue
    made_by=$(/usr/bin/python3 -c "import h5py; f = h5py.File('$work/$run.h5', 'r'); print(f.attrs['git_commit'])")
    /usr/bin/python3 - "$work/${run}_bodies.csv" "$(target "$dfg_case" "$file")" "$kind" "$made_by" "$commit" <<'PY'
import sys, numpy as np
src, dst, kind, made_by, commit = sys.argv[1:]
lines = [l for l in open(src) if not l.startswith("#")]
names = [c.split(" [")[0] for c in lines[0].strip().split(",")]
data = np.array([[float(x) for x in l.split(",")] for l in lines[1:]])
col = {n: data[:, k] for k, n in enumerate(names)}
rim = lambda a, b, c: 6 * a - 8 * b + 3 * c  # quadratic to the rim from 0.01, 0.015, 0.02 (force_metrics.hpp)
p = [col["probe_%03d/pressure" % k] for k in range(6)]
dp = rim(p[0], p[1], p[2]) - rim(p[3], p[4], p[5])
with open(dst, "w") as f:
    what = "the steady coefficients (last row)" if kind == "steady" else "the force history for t >= 8, every step"
    f.write("# ibms reference for 'ibms compare' (docs/compare.md): %s of ibms's own run %s\n" % (what, src.split("/")[-1]))
    f.write("# (validation/<case>/scene.toml at the grid in the name: D/h), ibms commit %s; written by\n" % made_by)
    f.write("# scripts/make-compare-references.sh at commit %s. Delta p from the probes extrapolated to the rim.\n" % commit)
    if kind == "steady":
        f.write("drag_coefficient [-],lift_coefficient [-],pressure_difference [mass/(length time^2)]\n")
        f.write("%.10g,%.10g,%.10g\n" % (col["body_000/drag_coefficient"][-1], col["body_000/lift_coefficient"][-1], dp[-1]))
    else:
        f.write("time [time],drag_coefficient [-],lift_coefficient [-],pressure_difference [mass/(length time^2)]\n")
        for k in np.nonzero(col["time"] >= 8.0)[0]:
            f.write("%.10g,%.10g,%.10g,%.10g\n" % (col["time"][k], col["body_000/drag_coefficient"][k],
                                                   col["body_000/lift_coefficient"][k], dp[k]))
PY
  done
fi
[[ ${ONLY_DFG:-0} == 1 ]] && { echo "references written"; exit 0; }

# Body cavities (docs/compare.md): ibms's own validation runs at the cases' 100 x 100.
run_body_case() {  # case, variant -> sets base; runs the scene unless WORK_DIR has its _bodies.csv
  base=$work/$1_$2
  if [[ ! -s ${base}_bodies.csv ]]; then
    echo "running $1 $2"
    "$ibms" run "$src/validation/$1/scene_$2.toml" -o "$base.h5" --quiet
  fi
  # The root attribute git_commit (docs/output.md), without h5py: the first string of exactly 12 hex digits in the file.
  made_by=$(/usr/bin/python3 -c "import h5py; f = h5py.File('$base.h5', 'r'); print(f.attrs['git_commit'])" 2>/dev/null ||
            strings -n 12 "$base.h5" | grep -m1 -xE '[0-9a-f]{12}|unknown' || echo unknown)
}
# Trajectories as cavity_swelling_particles/check.cpp writes them (10 <= t <= 20, 10 digits), every
# ${TRAJECTORY_STRIDE:-1}-th output time (to keep the files small).
stride=${TRAJECTORY_STRIDE:-2}   # 2: ~200 kB per file instead of ~400 kB
for variant in nonswelling swelling; do
  wanted cavity_swelling_particles ibms_trajectories_$variant.csv || continue
  run_body_case cavity_swelling_particles $variant
  { echo "# ibms reference for 'ibms compare cavity_swelling_particles' (docs/compare.md): particle centroids"
    echo "# (rim-polygon area centroid) and diameters of ibms's own $variant run of"
    echo "# validation/cavity_swelling_particles/scene_$variant.toml (100 x 100, DEM stiffness 1e4, as ctest runs it),"
    echo "# 10 <= t <= 20, one output time in ${stride}. ibms commit $made_by; written by"
    echo "# scripts/make-compare-references.sh at commit $commit."
    echo "time [-],particle [-],x [-],y [-],diameter [-]"
    awk -F, -v stride="$stride" 'BEGIN { OFS = "," } /^#/ { next }
      !h { h = 1; for (k = 1; k <= NF; ++k) { if ($k ~ /^body_[0-9]+\/centroid_x/) { n = split($k, a, /[_\/]/); cx[a[2] + 0] = k }
                                               if ($k ~ /^body_[0-9]+\/centroid_y/) { split($k, a, /[_\/]/); cy[a[2] + 0] = k }
                                               if ($k ~ /^body_[0-9]+\/diameter/) { split($k, a, /[_\/]/); cd[a[2] + 0] = k } }
           nb = length(cx); next }
      $1 + 0 >= 10 && $1 + 0 <= 20 { if (m++ % stride) next; for (b = 0; b < nb; ++b) printf "%.10g,%d,%.10g,%.10g,%.10g\n", $1, b, $cx[b], $cy[b], $cd[b] }' \
      "${base}_bodies.csv"; } > "$(target cavity_swelling_particles ibms_trajectories_$variant.csv)"
done
# Deformation parameter and area / A0 (A0: the body's first output) of every body, t <= 20.
for k in 10 100; do
  wanted cavity_deformable_objects ibms_deformation_k$k.csv || continue
  run_body_case cavity_deformable_objects k$k
  { echo "# ibms reference for 'ibms compare cavity_deformable_objects' (docs/compare.md): deformation parameter"
    echo "# (r_max - r_min)/(r_max + r_min) of the rim distances from the rim centroid and rim-polygon area / A0 of"
    echo "# every body, every output time t <= 20, of ibms's own run of validation/cavity_deformable_objects/scene_k$k.toml"
    echo "# (100 x 100, as ctest runs it). ibms commit $made_by; written by scripts/make-compare-references.sh at commit $commit."
    echo "time [-],particle [-],deformation [-],area_ratio [-]"
    awk -F, 'BEGIN { OFS = "," } /^#/ { next }
      !h { h = 1; for (k = 1; k <= NF; ++k) { if ($k ~ /^body_[0-9]+\/deformation/) { split($k, a, /[_\/]/); cd[a[2] + 0] = k }
                                               if ($k ~ /^body_[0-9]+\/area/) { split($k, a, /[_\/]/); ca[a[2] + 0] = k } }
           nb = length(cd); next }
      $1 + 0 <= 20 { for (b = 0; b < nb; ++b) { if (!(b in a0)) a0[b] = $ca[b]; printf "%.10g,%d,%.10g,%.10g\n", $1, b, $cd[b], $ca[b] / a0[b] } }' \
      "${base}_bodies.csv"; } > "$(target cavity_deformable_objects ibms_deformation_k$k.csv)"
done
echo "references written"
