#!/usr/bin/env bash
# Claims: (1) `ibms run` on bad input exits with code 2, prints exactly one line naming the scene
# file and the key, and creates no output file; (2) a run that blows up exits with code 3, the
# message names step, time and place, and the HDF5 output written so far is readable, also when the
# fluid guard stops it (sim/checks/fluid_guard.hpp); (3) a failed
# write of the output exits with code 5 and the system's reason, whether it fails at a flush or
# inside an HDF5 dataset write. Every run passes its thread count (--threads 1).
set -u
ibms=$1; good_scene=$2; body_scene=${3:-}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0
check_bad() {  # name, expected key, ibms arguments...
  local name=$1 key=$2; shift 2
  rm -f out.h5 out.xmf out_*.csv
  "$ibms" run "$@" -o out.h5 --quiet --threads 1 2> err.txt; local code=$?
  local lines; lines=$(wc -l < err.txt)
  local written; written=$(ls out.h5 out.xmf out_*.csv 2>/dev/null)  # no partial output of any kind
  if [[ $code -ne 2 || $lines -ne 1 || -n $written ]] || ! grep -q -- "$key" err.txt; then
    echo "FAIL $name: exit $code, $lines line(s), output files written: '${written}':"; cat err.txt
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
check_bad "negative end time" "run.end_time" good.toml --set run.end_time=-1
check_bad "zero fluid density" "fluid.density" good.toml --set fluid.density=0
if [[ -n $body_scene ]]; then  # a scene with two bodies (one swelling) and contacts
  cp "$body_scene" bodies.toml
  check_bad "body outside the box" "bodies.0.centre" bodies.toml --set "bodies.0.centre=[1.5, 0.5]"
  check_bad "body overlapping a wall" "bodies.0.centre" bodies.toml --set "bodies.0.centre=[0.5, 0.05]"
  check_bad "body overlapping another" "bodies.1.centre" bodies.toml --set "bodies.1.centre=[0.5, 0.2]"
  check_bad "fewer than 3 surface points" "bodies.0.n_surface_points" bodies.toml --set bodies.0.n_surface_points=2
  check_bad "restitution above 1" "bodies.1.restitution_coefficient" bodies.toml --set bodies.1.restitution_coefficient=1.2
  check_bad "contact restitution 0" "contact.restitution_coefficient" bodies.toml --set contact.restitution_coefficient=0
  check_bad "swelling maximum below the diameter" "bodies.1.swelling.max_diameter" bodies.toml \
    --set bodies.1.swelling.max_diameter=0.1
  check_bad "override of a key of a missing body" "bodies.7" bodies.toml --set bodies.7.diameter=0.1
  check_bad "negative time step" "run.time_step" bodies.toml --set run.time_step=-0.1
  check_bad "restart file missing" "no_such_checkpoint.h5" bodies.toml --restart no_such_checkpoint.h5
  check_bad "restart file not HDF5" "bodies.toml" bodies.toml --restart bodies.toml
fi

# Blow-up: a fixed time step far beyond the CFL limit on a coarse cavity.
rm -f blow.h5
"$ibms" run good.toml --set domain.cells_x=16 --set domain.cells_y=16 --set run.time_step=5.0 \
  --set run.end_time=100 -o blow.h5 --quiet --threads 1 2> err.txt; code=$?
if [[ $code -ne 3 ]] || ! grep -q "step" err.txt || ! grep -q "cell (" err.txt; then
  echo "FAIL blow-up: exit $code:"; cat err.txt; failures=$((failures + 1))
elif ! /usr/bin/python3 -c "import h5py,sys; f=h5py.File('blow.h5','r'); assert 'grid' in f and 'scene' in f.attrs" 2>/dev/null; then
  echo "FAIL blow-up: blow.h5 is not readable"; failures=$((failures + 1))
else
  echo "ok   blow-up: $(cat err.txt)"
fi

# Fluid guard: the same cavity at CFL 1.6 with the CFL guard out of the way (run.max_cfl = 1000)
# grows slowly until its largest speed passes 1.75 times the lid speed.
rm -f guard.h5
"$ibms" run good.toml --set domain.cells_x=16 --set domain.cells_y=16 --set run.time_step=0.1 \
  --set run.max_cfl=1000 --set run.end_time=100 -o guard.h5 --quiet --threads 1 2> err.txt; code=$?
if [[ $code -ne 3 || $(wc -l < err.txt) -ne 1 ]] || ! grep -q "at step .*, t = .*: fluid speed .* in cell (" err.txt; then
  echo "FAIL fluid guard: exit $code:"; cat err.txt; failures=$((failures + 1))
elif ! /usr/bin/python3 -c "import h5py,sys; f=h5py.File('guard.h5','r'); assert f['series/time'].shape[0] > 0" 2>/dev/null; then
  echo "FAIL fluid guard: guard.h5 is not readable"; failures=$((failures + 1))
else
  echo "ok   fluid guard: $(cat err.txt)"
fi

# Output failure: writes past a file-size limit fail with EFBIG, as on a full disk; the run exits
# with code 5 (not 2: the input was good), one line naming the file and the system's reason, no
# crash (HDF5's exit handler is skipped), no stray XDMF temporary. 32^2 fields (8 kB) stay in
# HDF5's buffers until a flush meets the 40 kB limit; a 128^2 field (128 kB, beyond HDF5's 64 kB
# sieve buffer) goes to the file inside its dataset write, which meets the 100 kB limit.
check_full() {  # name, expected message, ulimit -f in kB, ibms arguments...
  local name=$1 message=$2 limit=$3; shift 3
  rm -f full.*
  ( trap '' XFSZ; ulimit -f "$limit"; "$ibms" run good.toml "$@" -o full.h5 --quiet --threads 1 ) 2> err.txt; local code=$?
  if [[ $code -ne 5 ]] || ! grep -q "$message" err.txt || [[ $(wc -l < err.txt) -ne 1 ]] || ls full.xmf.tmp 2>/dev/null; then
    echo "FAIL $name: exit $code:"; cat err.txt; failures=$((failures + 1))
  else
    echo "ok   $name: $(cat err.txt)"
  fi
}
check_full "output failure at a flush" "full.h5: cannot flush the HDF5 output: File too large" 40 \
  --set domain.cells_x=32 --set domain.cells_y=32 --set run.end_time=0.5
check_full "output failure inside a dataset write" "full.h5: cannot write dataset 'u': File too large" 100 \
  --set domain.cells_x=128 --set domain.cells_y=128 --set run.end_time=0.05 --set output.snapshot_interval=0.01
echo "$failures failure(s)"
exit $((failures > 0))
