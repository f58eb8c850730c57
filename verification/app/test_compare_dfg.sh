#!/usr/bin/env bash
# Claims (docs/compare.md, DFG cylinders): `ibms compare dfg_cylinder_2d1` gates c_D against the
# published 5.57954 within 1 % (one 2 % off fails, exit 1) and against ibms's own reference only
# where that lies inside the published interval (ibms's 5.5843 does: gated; one of 5.6006, in a copy
# of the case folder, does not: shown, not gated), and
# `ibms compare dfg_cylinder_2d2` recovers the Strouhal number and max c_D of a
# synthetic force history (c_L = sin(2 pi f t), St = f D / U = 0.3 exactly; max c_D = 3.23 + 0.01)
# with the same figures the case check uses, passes it against the published values and against
# ibms's own St; ibms's own max c_D (3.1618 at D/h = 30) lies outside the published [3.22, 3.24] and
# is shown, not gated, while a reference whose max c_D lies inside (the shipped one scaled to 3.23,
# in a copy of the case folder) is gated; fails it when the frequency is 2 % off; malformed files exit 2 naming the file and line. A file with a
# control-volume drag column gets its relative difference from the drag as an info line (last row
# for 2D-1, time means over the window for 2D-2).
# usage: test_compare_dfg.sh IBMS VALIDATION_DIR
set -u
ibms=$1; validation=$2
source "$(dirname "${BASH_SOURCE[0]}")/compare_test_lib.sh"  # expect_exit
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
run() { "$ibms" compare "$@" --validation-dir "$validation"; }
# copy_reference DIR CASE FILE EDIT: the case's reference folder copied to DIR/CASE, then its FILE
# rewritten by the Python statements EDIT, which change `lines` (the file's lines; `data` holds the
# indices of the data rows, after the header).
copy_reference() {
  mkdir -p "$1/$2"
  cp -r "$validation/$2/reference" "$1/$2/"
  /usr/bin/python3 - "$1/$2/reference/$3" "$4" <<'PY'
import sys
path, edit = sys.argv[1], sys.argv[2]
lines = open(path).read().splitlines()
data = [k for k, l in enumerate(lines) if l and not l.startswith("#")][1:]
exec(edit)
open(path, "w").write("\n".join(lines) + "\n")
PY
}

# 2D-1: ibms's reference is 5.5843 (+0.09 % from the published value): 5.62 is within 1 % of both.
printf '# synthetic\nc_d,c_l,delta_p\n5.62,0.0106,0.1175\n' > within.csv
expect_exit "2D-1 c_D 5.62 passes" 0 "dfg_cylinder_2d1: pass" run dfg_cylinder_2d1 within.csv
printf 'drag_coefficient,lift_coefficient\n5.80,0.0106\n' > off.csv
expect_exit "2D-1 c_D 5.80 fails against the published value" 1 "John & Matthies.*FAIL" run dfg_cylinder_2d1 off.csv
expect_exit "2D-1 ibms's own reference inside the published interval is gated" 0 \
  "\|c_D / 5.58[0-9]* \(ibms reference\) - 1\|.*pass" \
  run dfg_cylinder_2d1 "$validation/dfg_cylinder_2d1/reference/ibms_dfg_2d1.csv"
# A reference outside the published interval (5.6006, the 0.25 h scene's, in a copy of the case
# folder) is shown, not gated.
copy_reference outside dfg_cylinder_2d1 ibms_dfg_2d1.csv '
cells = lines[data[0]].split(",")
cells[0] = "5.6006"
lines[data[0]] = ",".join(cells)'
expect_exit "2D-1 ibms's own reference outside the published interval is not gated" 0 \
  "not gated: ibms's own c_D 5.6006 lies outside the published \[5.57, 5.59\]" \
  "$ibms" compare dfg_cylinder_2d1 within.csv --validation-dir outside
printf 'c_d,c_l,cv_drag_coefficient\n5.62,0.0106,5.6762\n' > cv.csv
expect_exit "2D-1 control-volume drag reported" 0 "control-volume c_D vs c_D, last row .*\(\+1.00e-02\)   info" \
  run dfg_cylinder_2d1 cv.csv
printf 'c_d\nabc\n' > bad.csv
expect_exit "2D-1 non-number exits 2" 2 "bad.csv:2:" run dfg_cylinder_2d1 bad.csv
printf 'c_l\n0.01\n' > nodrag.csv
expect_exit "2D-1 missing drag column exits 2" 2 "nodrag.csv:1: .*drag_coefficient" run dfg_cylinder_2d1 nodrag.csv

# 2D-2: 8 time units at dt = 1e-3 of c_L = sin(2 pi f t), c_D = 3.23 + 0.01 cos(4 pi f t), f = 3.
history() {  # out, frequency
  /usr/bin/python3 - "$1" "$2" <<'PY'
import sys, math
out, f = sys.argv[1], float(sys.argv[2])
with open(out, "w") as h:
    h.write("time,drag_coefficient,lift_coefficient,cv_drag_coefficient\n")
    for k in range(8001):
        t = 4.0 + 1e-3 * k
        drag = 3.23 + 0.01 * math.cos(4 * math.pi * f * t)
        h.write("%.6f,%.9f,%.9f,%.9f\n" % (t, drag, math.sin(2 * math.pi * f * t + 0.3), 0.99 * drag))
PY
}
history st.csv 3.0
expect_exit "2D-2 St = 0.3 and max c_D = 3.24 pass against the published values" 0 \
  "St / 0.3 \(Schaefer & Turek 1996\) - 1\|.*pass" run dfg_cylinder_2d2 st.csv
# A reference whose max c_D lies inside the published interval is gated: the shipped one with its
# drag scaled to a largest value of 3.23, in a copy of the case folder.
copy_reference inside dfg_cylinder_2d2 ibms_dfg_2d2_forces.csv '
largest = max(float(lines[k].split(",")[1]) for k in data)
for k in data:
    cells = lines[k].split(",")
    cells[1] = "%.10g" % (float(cells[1]) * 3.23 / largest)
    lines[k] = ",".join(cells)'
"$ibms" compare dfg_cylinder_2d2 st.csv --validation-dir inside > inside.txt 2>&1
grep -qE "\|max c_D / 3\.23[0-9]* \(ibms reference\) - 1\|.*pass" inside.txt ||
  { echo "FAIL 2D-2 a reference max c_D inside the published interval should be gated (and pass)"; failures=$((failures + 1)); }
# ibms's own D/h = 30 reference has max c_D 3.1618 (-2.11 %, the scene with 0.3 h retraction), outside
# the published [3.22, 3.24]: it is reported, not gated (as 2D-1's c_D of 5.6006 above).
grep -qE "not gated: ibms's own max c_D 3\.1[0-9]* lies outside the published \[3\.22, 3\.24\]" out.txt ||
  { echo "FAIL 2D-2 ibms's own max c_D outside the published interval should not be gated"; failures=$((failures + 1)); }
grep -qE "max c_D / 3.23 \(Schaefer & Turek 1996\) - 1\|.*pass" out.txt ||
  { echo "FAIL 2D-2 max c_D 3.24 should pass the 2 % gate"; failures=$((failures + 1)); }
grep -qE "control-volume c_D vs c_D, means over the last 4 time units .*\(-1.00e-02\)   info" out.txt ||
  { echo "FAIL 2D-2 control-volume drag (0.99 c_D) should be reported as -1.00e-02"; failures=$((failures + 1)); }
history st_off.csv 3.06
expect_exit "2D-2 St 2 % high fails" 1 "St / 0.3 \(Schaefer & Turek 1996\) - 1\| .* 0.02.*FAIL" run dfg_cylinder_2d2 st_off.csv
printf 'time,drag_coefficient,lift_coefficient\n0,3,0\n1,3,1\n' > short.csv
expect_exit "2D-2 too short a history exits 2" 2 "short.csv" run dfg_cylinder_2d2 short.csv

[[ $failures -eq 0 ]] && echo "all DFG compare claims hold" || echo "$failures claim(s) failed"
exit $(( failures > 0 ))
