#!/usr/bin/env bash
# Claims (docs/compare.md, body cavities): `ibms compare cavity_swelling_particles` and
# `ibms compare cavity_deformable_objects` accept ibms's own results (the committed references in
# the long format, and the same data in ibms's wide _bodies.csv layout, with the same figures),
# reject perturbed copies (the two runs swapped, deformation scaled, area out of bounds: exit 1, a
# FAIL line), and stop on malformed files with exit 2 and one line naming the file and line.
# usage: test_compare_bodies.sh IBMS VALIDATION_DIR
set -u
ibms=$1; validation=$2
source "$(dirname "${BASH_SOURCE[0]}")/compare_test_lib.sh"  # expect_exit, scale_column
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
same_lines() {  # name, file a, file b, pattern: the matching lines must be identical
  if ! diff <(grep -E -- "$4" "$2" | sed 's/  */ /g') <(grep -E -- "$4" "$3" | sed 's/  */ /g') > /dev/null ||
     [[ $(grep -cE -- "$4" "$2") -eq 0 ]]; then
    echo "FAIL $1: lines '$4' differ:"; grep -E -- "$4" "$2" "$3"; failures=$((failures + 1))
  else
    echo "ok   $1"
  fi
}
header_line() { grep -n -m1 -E '^[a-z]' "$1" | cut -d: -f1; }  # the first non-comment line

# ---- cavity_swelling_particles ------------------------------------------------------------------
ref=$validation/cavity_swelling_particles/reference
plain=$ref/ibms_trajectories_nonswelling.csv; swell=$ref/ibms_trajectories_swelling.csv
run() { "$ibms" compare "$@" --validation-dir "$validation"; }
expect_exit "swelling: ibms's own trajectories accepted" 0 "cavity_swelling_particles: pass" \
  run cavity_swelling_particles "$plain" "$swell"
cp out.txt long.txt
expect_exit "swelling: runs swapped rejected" 1 "check 3\).* FAIL" run cavity_swelling_particles "$swell" "$plain"
grep -qE "check 4\).* FAIL" out.txt || { echo "FAIL swelling swapped: check 4 not failed"; failures=$((failures + 1)); }
# The same data in ibms's wide _bodies.csv layout (time, body_NNN/centroid_x, body_NNN/centroid_y).
to_wide() {  # in, out, quantities (column numbers after time and particle, as name:column ...)
  /usr/bin/python3 - "$@" <<'EOF'
import sys
src, dst, specs = sys.argv[1], sys.argv[2], [s.split(':') for s in sys.argv[3:]]
rows, header = {}, None
for line in open(src):
    if line.startswith('#') or not line.strip(): continue
    if header is None: header = line; continue
    c = line.strip().split(',')
    rows.setdefault(c[0], {})[int(float(c[1]))] = c
bodies = sorted(next(iter(rows.values())))
with open(dst, 'w') as out:
    out.write('# wide copy of %s\n' % src)
    out.write(','.join(['time [time]'] + ['body_%03d/%s [-]' % (b, n) for b in bodies for n, _ in specs]) + '\n')
    for t, r in rows.items():
        out.write(','.join([t] + [r[b][int(k)] for b in bodies for _, k in specs]) + '\n')
EOF
}
to_wide "$plain" plain_bodies.csv centroid_x:2 centroid_y:3; to_wide "$swell" swell_bodies.csv centroid_x:2 centroid_y:3
expect_exit "swelling: wide _bodies.csv layout accepted" 0 "cavity_swelling_particles: pass" \
  run cavity_swelling_particles plain_bodies.csv swell_bodies.csv
same_lines "swelling: wide layout gives the same figures" long.txt out.txt "^  .*(mean path|path length)"
# Rows in another order (by particle, then time): same figures.
{ grep '^#' "$plain"; sed -n "$(header_line "$plain")p" "$plain"; grep -v '^#' "$plain" | tail -n +2 | sort -t, -k2,2n -s; } \
  > plain_sorted.csv
expect_exit "swelling: rows ordered by particle accepted" 0 "cavity_swelling_particles: pass" \
  run cavity_swelling_particles plain_sorted.csv "$swell"
same_lines "swelling: row order does not change the figures" long.txt out.txt "^  .*(mean path|path length)"
# Malformed input.
h=$(header_line "$plain")
awk -F, -v OFS=, -v h="$h" 'NR >= h { print $1, $2, $4 ; next } { print }' "$plain" > no_x.csv
expect_exit "swelling: missing x column: exit 2" 2 "^ibms: error: no_x.csv:$h: header needs the columns time, particle, x, y" \
  run cavity_swelling_particles no_x.csv "$swell"
# Delete the row of particle 5 at the 3rd time: particle 5 has no row at that time (named at
# particle 0's row of that time).
awk -v l=$((h + 2 * 16 + 6)) 'NR != l' "$plain" > missing_row.csv
expect_exit "swelling: particle missing at one time: exit 2" 2 \
  "^ibms: error: missing_row.csv:$((h + 2 * 16 + 1)): particle 5 has no row at time" \
  run cavity_swelling_particles missing_row.csv "$swell"
awk -v l=$((h + 20)) '{ print } NR == l { print }' "$plain" > repeated_time.csv
expect_exit "swelling: time not increasing for a particle: exit 2" 2 \
  "^ibms: error: repeated_time.csv:$((h + 21)): particle 3: time .* after .*increase strictly" \
  run cavity_swelling_particles repeated_time.csv "$swell"
head -n $((h + 16)) "$plain" > one_time.csv
expect_exit "swelling: one output time: exit 2" 2 "^ibms: error: one_time.csv:$h: needs at least 2 output times, got 1" \
  run cavity_swelling_particles one_time.csv "$swell"
awk -F, -v h="$h" 'NR <= h || $1 + 0 <= 15' "$plain" > short.csv
expect_exit "swelling: times not covering [10, 20]: exit 2" 2 "^ibms: error: short.csv:[0-9]+: times cover .* needs 10 <= t <= 20" \
  run cavity_swelling_particles short.csv "$swell"
awk -v l=$((h + 7)) 'NR == l { sub(/,[^,]*$/, ",nan") } { print }' "$plain" > nan.csv
expect_exit "swelling: non-number: exit 2" 2 "^ibms: error: nan.csv:$((h + 7)): column 'diameter'" \
  run cavity_swelling_particles nan.csv "$swell"
expect_exit "swelling: one file: exit 2" 2 "give exactly two CSV files" run cavity_swelling_particles "$plain"
"$ibms" compare cavity_swelling_particles missing_row.csv "$swell" --validation-dir "$validation" > /dev/null 2> err.txt
if [[ $(wc -l < err.txt) -ne 1 ]]; then echo "FAIL: bad input printed $(wc -l < err.txt) lines"; failures=$((failures + 1)); fi

# ---- cavity_deformable_objects ------------------------------------------------------------------
ref=$validation/cavity_deformable_objects/reference
k10=$ref/ibms_deformation_k10.csv; k100=$ref/ibms_deformation_k100.csv
expect_exit "deformable: ibms's own series accepted" 0 "cavity_deformable_objects: pass" \
  run cavity_deformable_objects "$k10" "$k100"
cp out.txt long.txt
grep -qE "max area / A0.*pass" out.txt || { echo "FAIL deformable: area bounds not checked"; failures=$((failures + 1)); }
expect_exit "deformable: k = 10 and k = 100 swapped rejected" 1 "k = 10 / k = 100 \(check 5\).* FAIL" \
  run cavity_deformable_objects "$k100" "$k10"
scale_column "$k10" k10_less.csv 3 0.7   # the measured ratio 2.49 becomes 1.74
expect_exit "deformable: k = 10 deformation x 0.7 rejected" 1 "check 5\).* FAIL" run cavity_deformable_objects k10_less.csv "$k100"
scale_column "$k10" k10_shrunk.csv 4 0.7  # min area 0.65 A0 becomes 0.46 A0
expect_exit "deformable: area x 0.7 rejected" 1 "k = 10: min area / A0.* FAIL" \
  run cavity_deformable_objects k10_shrunk.csv "$k100"
cut -d, -f1-3 "$k10" > k10_no_area.csv; cut -d, -f1-3 "$k100" > k100_no_area.csv
expect_exit "deformable: without area accepted (area not checked)" 0 "area bounds .* not checked" \
  run cavity_deformable_objects k10_no_area.csv k100_no_area.csv
to_wide "$k10" k10_bodies.csv deformation:2 area:3; to_wide "$k100" k100_bodies.csv deformation:2 area:3
expect_exit "deformable: wide _bodies.csv layout accepted" 0 "cavity_deformable_objects: pass" \
  run cavity_deformable_objects k10_bodies.csv k100_bodies.csv
same_lines "deformable: wide layout gives the same figures" long.txt out.txt "^  .*(deformation|area)"
h=$(header_line "$k10")
awk -v l=$((h + 30)) 'NR == l { sub(/,[^,]*,/, ",x,") } { print }' "$k10" > bad_id.csv
expect_exit "deformable: non-number: exit 2" 2 "^ibms: error: bad_id.csv:$((h + 30)): column 'particle'" \
  run cavity_deformable_objects bad_id.csv "$k100"
awk -v l=$((h + 13)) 'NR != l' "$k10" > k10_missing.csv   # body 3 at the 2nd time
expect_exit "deformable: body missing at the 2nd time: exit 2" 2 \
  "^ibms: error: k10_missing.csv:$((h + 10)): particle 3 has no row at time" \
  run cavity_deformable_objects k10_missing.csv "$k100"
echo "$failures failure(s)"
exit $((failures > 0))
