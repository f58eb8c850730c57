#!/usr/bin/env bash
# Claims (docs/compare.md): `ibms compare CASE FILE...` accepts an ibms run's own
# output (exit 0), rejects a deliberately perturbed copy (exit 1, a FAIL line), and stops on a
# malformed CSV with exit 2 and one line naming the file and line.
# usage: test_compare.sh IBMS VALIDATION_DIR
set -u
ibms=$1; validation=$2
source "$(dirname "${BASH_SOURCE[0]}")/compare_test_lib.sh"  # expect_exit, scale_column
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0

# Lid-driven cavity Re 100 on the check's own grid (128^2, ~5 s): the validation run's profiles.
"$ibms" run "$validation/lid_driven_cavity_re100/scene.toml" --set domain.cells_x=128 --set domain.cells_y=128 \
  -o cavity.h5 --quiet || { echo "FAIL: cavity run"; exit 1; }
expect_exit "cavity Re 100: own output accepted" 0 "lid_driven_cavity_re100: pass" \
  "$ibms" compare lid_driven_cavity_re100 cavity_centreline_u.csv cavity_centreline_v.csv --validation-dir "$validation"
scale_column cavity_centreline_u.csv perturbed_u.csv 2 1.05
expect_exit "cavity Re 100: u scaled by 1.05 rejected" 1 "FAIL" \
  "$ibms" compare lid_driven_cavity_re100 perturbed_u.csv cavity_centreline_v.csv --validation-dir "$validation"
# A small interior perturbation: u + 0.015 (lid speed 1) away from the walls, above the 0.01 tolerance.
awk -F, -v OFS=, '/^#/ || !h { if (!/^#/) h = 1; print; next } $1 > 0 && $1 < 1 { $2 = $2 + 0.015 } { print }' \
  cavity_centreline_u.csv > shifted_u.csv
expect_exit "cavity Re 100: interior u + 0.015 rejected" 1 "ibms reference.* FAIL" \
  "$ibms" compare lid_driven_cavity_re100 shifted_u.csv cavity_centreline_v.csv --validation-dir "$validation"
# Malformed input: a non-number on data line 10, a ragged row, a missing profile, unknown case.
awk 'NR == 10 { sub(/,.*/, ",abc") } { print }' cavity_centreline_u.csv > bad_number.csv
expect_exit "non-number: exit 2 naming file and line" 2 "^ibms: error: bad_number.csv:10: column 'u'" \
  "$ibms" compare lid_driven_cavity_re100 bad_number.csv cavity_centreline_v.csv --validation-dir "$validation"
awk 'NR == 12 { $0 = $0 ",7" } { print }' cavity_centreline_u.csv > ragged.csv
expect_exit "ragged row: exit 2 naming file and line" 2 "^ibms: error: ragged.csv:12: 3 values" \
  "$ibms" compare lid_driven_cavity_re100 ragged.csv cavity_centreline_v.csv --validation-dir "$validation"
expect_exit "missing v profile: exit 2" 2 "no v profile" \
  "$ibms" compare lid_driven_cavity_re100 cavity_centreline_u.csv --validation-dir "$validation"
expect_exit "unknown case: exit 2" 2 "unknown case 'no_such_case'" \
  "$ibms" compare no_such_case cavity_centreline_u.csv --validation-dir "$validation"
# Exactly one line on stderr for bad input.
"$ibms" compare lid_driven_cavity_re100 bad_number.csv cavity_centreline_v.csv --validation-dir "$validation" \
  > /dev/null 2> err.txt
if [[ $(wc -l < err.txt) -ne 1 ]]; then echo "FAIL: bad input printed $(wc -l < err.txt) lines"; failures=$((failures + 1)); fi

# Settling disk on the middle validation grid (D/h = 18.75; 1.2 % from the reference, where D/h = 12.5
# is 2.9 %, too close to the 3 % tolerance to make a robust test) to t = 0.7 s (past the maximum speed).
"$ibms" run "$validation/settling_disk/scene.toml" --set domain.cells_x=150 --set domain.cells_y=450 \
  --set bodies.0.n_surface_points=60 --set run.end_time=0.7 -o disk.h5 --quiet || { echo "FAIL: disk run"; exit 1; }
expect_exit "settling disk: own body series accepted" 0 "settling_disk: pass" \
  "$ibms" compare settling_disk disk_bodies.csv --validation-dir "$validation"
awk -F, 'BEGIN { OFS = "," } /^#/ { next }
  !h { h = 1; for (k = 1; k <= NF; ++k) if ($k ~ /^body_000\/velocity_y/) c = k; print "t [s],v [cm/s]"; next }
  { print $1, $c }' disk_bodies.csv > disk_tv.csv
expect_exit "settling disk: t,v file accepted" 0 "settling_disk: pass" \
  "$ibms" compare settling_disk disk_tv.csv --validation-dir "$validation"
scale_column disk_tv.csv disk_fast.csv 2 1.05
expect_exit "settling disk: v scaled by 1.05 rejected" 1 "FAIL" \
  "$ibms" compare settling_disk disk_fast.csv --validation-dir "$validation"
# DKT of two disks: a synthetic history (the trailing disk's speed peaks at 1.69 cm/s at t = 1.12 s,
# it ends below the leading one) passes; its speed scaled by 0.9 fails; a missing column is bad input.
awk 'BEGIN { print "t [s],y_trailing [cm],y_leading [cm],v_trailing [cm/s],v_leading [cm/s]";
  for (k = 0; k <= 300; ++k) { t = k / 100; v = -1.69 * exp(-((t - 1.12) / 0.5)^2);
    printf "%.2f,%.6f,%.6f,%.6f,%.6f\n", t, 7.2 - 1.1 * t, 6.8 - 0.8 * t, v, 0.9 * v } }' > dkt.csv
expect_exit "dkt: synthetic history accepted" 0 "dkt_two_disks: pass" \
  "$ibms" compare dkt_two_disks dkt.csv --validation-dir "$validation"
scale_column dkt.csv dkt_slow.csv 4 0.9
expect_exit "dkt: trailing speed scaled by 0.9 rejected" 1 "FAIL" \
  "$ibms" compare dkt_two_disks dkt_slow.csv --validation-dir "$validation"
cut -d, -f1,2,4 dkt.csv > dkt_missing.csv
expect_exit "dkt: missing y_leading is bad input" 2 "y_leading" \
  "$ibms" compare dkt_two_disks dkt_missing.csv --validation-dir "$validation"
echo "$failures failure(s)"
exit $((failures > 0))
