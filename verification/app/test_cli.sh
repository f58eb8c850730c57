#!/usr/bin/env bash
# Claims: (1) `ibms run` on bad input exits with code 2, prints exactly one line naming the scene
# file and the key, and creates no output file; (2) a run that blows up exits with code 3, the
# message names step, time and place, and the HDF5 output written so far is readable.
set -u
ibms=$1; good_scene=$2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
check_bad() {  # name, expected key, ibms arguments...
  local name=$1 key=$2; shift 2
  rm -f out.h5 out.xmf
  "$ibms" run "$@" -o out.h5 --quiet 2> err.txt; local code=$?
  local lines; lines=$(wc -l < err.txt)
  if [[ $code -ne 2 || $lines -ne 1 ]] || ! grep -q -- "$key" err.txt || [[ -e out.h5 ]]; then
    echo "FAIL $name: exit $code, $lines line(s), output file $( [[ -e out.h5 ]] && echo written || echo absent ):"; cat err.txt
    failures=$((failures + 1))
  else
    echo "ok   $name: $(cat err.txt)"
  fi
}
cp "$good_scene" good.toml
sed 's/kinematic_viscosity = 0.01/kinematic_viscosity = -0.01/' good.toml > negative_viscosity.toml
sed 's/cells_x = 128/cells_x = 0/' good.toml > zero_cells.toml
sed 's/^\[fluid\]/[fluid]\nviscosty = 1.0/' good.toml > unknown_key.toml
sed 's/end_time = 200.0/end_time = "long"/' good.toml > wrong_type.toml
printf '[run\nend_time = 1\n' > malformed.toml
check_bad "negative viscosity" "fluid.kinematic_viscosity" negative_viscosity.toml
check_bad "zero cell count" "domain.cells_x" zero_cells.toml
check_bad "unknown key" "viscosty" unknown_key.toml
check_bad "wrong type" "run.end_time" wrong_type.toml
check_bad "malformed TOML" "malformed.toml" malformed.toml
check_bad "missing scene file" "no_such_scene.toml" no_such_scene.toml
check_bad "override of an unknown key" "fluid.nonsense" good.toml --set fluid.nonsense=1
check_bad "override with a non-physical value" "run.time_step" good.toml --set run.time_step=-1
check_bad "unwritable output directory" "no_such_dir" good.toml --set output.file=no_such_dir/x.h5

# Blow-up: a fixed time step far beyond the CFL limit on a coarse cavity.
rm -f blow.h5
"$ibms" run good.toml --set domain.cells_x=16 --set domain.cells_y=16 --set run.time_step=5.0 \
  --set run.end_time=100 -o blow.h5 --quiet 2> err.txt; code=$?
if [[ $code -ne 3 ]] || ! grep -q "step" err.txt || ! grep -q "cell (" err.txt; then
  echo "FAIL blow-up: exit $code:"; cat err.txt; failures=$((failures + 1))
elif ! /usr/bin/python3 -c "import h5py,sys; f=h5py.File('blow.h5','r'); assert 'grid' in f and 'scene' in f.attrs" 2>/dev/null; then
  echo "FAIL blow-up: blow.h5 is not readable"; failures=$((failures + 1))
else
  echo "ok   blow-up: $(cat err.txt)"
fi
echo "$failures failure(s)"
exit $((failures > 0))
