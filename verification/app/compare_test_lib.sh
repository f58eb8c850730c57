# Helpers shared by test_compare.sh and test_compare_bodies.sh (sourced, not run). The caller sets
# `failures=0` and works in a scratch directory (out.txt is written there).
expect_exit() {  # name, expected code, pattern expected in the output (grep -E), command...
  local name=$1 want=$2 pattern=$3; shift 3
  "$@" > out.txt 2>&1; local code=$?
  if [[ $code -ne $want ]] || ! grep -qE -- "$pattern" out.txt; then
    echo "FAIL $name: exit $code (expected $want), pattern '$pattern':"; cat out.txt; failures=$((failures + 1))
  else
    echo "ok   $name (exit $code)"; grep -E -- "$pattern" out.txt | head -3
  fi
}
# Scales one column of the data rows (after the '#' comments and the header) by a factor.
scale_column() {  # in, out, column (1-based), factor
  awk -F, -v OFS=, -v c="$3" -v f="$4" '/^#/ || !h { if (!/^#/) h = 1; print; next } { $c = $c * f; print }' "$1" > "$2"
}
