#!/usr/bin/env bash
# Claims: `ibms info` prints every time-step limit (CFL, viscous, marker travel,
# spring period, damping, contact duration) and the solid sub-steps it will use; it warns when a
# fixed time step exceeds the safe fraction of the CFL limit, and not for the adaptive step; it gives
# the von Neumann CFL limit at the scene's cell Reynolds number and a note when run.cfl is above it.
set -u
ibms=$1; cavity=$2; settling=$3
failures=0
expect() {  # name, file, pattern (grep -E), want (yes|no)
  if grep -qE -- "$3" "$2"; then got=yes; else got=no; fi
  if [[ $got != "$4" ]]; then echo "FAIL $1: pattern '$3' present: $got, expected $4"; failures=$((failures + 1));
  else echo "ok   $1"; fi
}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
"$ibms" info "$cavity" --set domain.cells_x=128 --set domain.cells_y=128 > "$work/adaptive.txt" || failures=$((failures + 1))
expect "cavity: CFL limit listed" "$work/adaptive.txt" "^  CFL \(advective.* 0.0078" yes
expect "cavity: viscous limit listed" "$work/adaptive.txt" "^  viscous" yes
expect "cavity adaptive: no warning" "$work/adaptive.txt" "WARNING" no
# The scene's own scheme, Fromm at run.cfl = 0.45: limit 0.50 at Re_h = 100 / 128 (docs/fluid-stability.md
# §1), above 0.45: no note.
expect "cavity (Fromm): von Neumann limit listed" "$work/adaptive.txt" "cell Reynolds number U h / nu = 0.781: .*\(Fromm\) CFL <= 0.5$" yes
expect "cavity (Fromm): cfl within the von Neumann limit" "$work/adaptive.txt" "^note: CFL" no
"$ibms" info "$cavity" --set domain.cells_x=128 --set domain.cells_y=128 --set run.cfl=0.55 > "$work/fromm_high.txt" \
  || failures=$((failures + 1))
expect "cavity (Fromm) at cfl 0.55: note on the von Neumann limit" "$work/fromm_high.txt" "^note: CFL 0.55 is above that limit" yes
# Central convection: Re_h = 100 / 128: limit 1.27, above cfl 0.5: no note.
central=(--set fluid.convection=central --set fluid.wall_closure=linear --set run.cfl=0.5)
"$ibms" info "$cavity" --set domain.cells_x=128 --set domain.cells_y=128 "${central[@]}" > "$work/central.txt" \
  || failures=$((failures + 1))
expect "cavity (central): von Neumann limit listed" "$work/central.txt" "cell Reynolds number U h / nu = 0.781: .*\(central\) CFL <= 1.27" yes
expect "cavity (central): cfl within the von Neumann limit" "$work/central.txt" "^note: CFL" no
# Re_h = 78.1: limit 0.413, below cfl 0.5: a note (not a warning).
"$ibms" info "$cavity" --set domain.cells_x=128 --set domain.cells_y=128 --set fluid.kinematic_viscosity=0.0001 \
  "${central[@]}" > "$work/high_re.txt" || failures=$((failures + 1))
expect "cavity Re_h 78: note on the von Neumann limit" "$work/high_re.txt" "^note: CFL 0.5 is above that limit" yes
expect "cavity Re_h 78: no warning" "$work/high_re.txt" "WARNING" no
# dt = 0.05 at h = 1/128, lid speed 1: CFL 6.4, far above the safe fraction 0.5.
"$ibms" info "$cavity" --set domain.cells_x=128 --set domain.cells_y=128 --set run.time_step=0.05 > "$work/fixed.txt" \
  || failures=$((failures + 1))
expect "cavity fixed dt 0.05: CFL warning" "$work/fixed.txt" "WARNING: fixed dt = 0.05 is 6.4 x the CFL" yes
# dt = 0.002: CFL 0.256, inside the safe fraction.
"$ibms" info "$cavity" --set domain.cells_x=128 --set domain.cells_y=128 --set run.time_step=0.002 > "$work/small.txt" \
  || failures=$((failures + 1))
expect "cavity fixed dt 0.002: no warning" "$work/small.txt" "WARNING" no
"$ibms" info "$settling" --set contact.stiffness=1e5 --set contact.cds_radius_fraction=0.05 --set run.time_step=1e-3 \
  > "$work/body.txt" || failures=$((failures + 1))
for limit in "marker travel" "body 0 spring period" "body 0 damping" "contact duration" "sub-steps per fluid step at dt = 0.001: [0-9]+"; do
  expect "settling disk: $limit" "$work/body.txt" "$limit" yes
done
expect "settling disk: fixed dt above the spring limit is sub-stepped" "$work/body.txt" "note: fixed dt = 0.001 is .* spring period" yes
echo "$failures failure(s)"
exit $((failures > 0))
