#!/usr/bin/env bash
# Claim: `ibms --version` prints exactly one line, "ibms VERSION (commit COMMIT)", with the project
# version and the git commit of the source tree now (the values every output file records as
# ibms_version and git_commit; the build regenerates the commit, so a commit made after configure
# shows once ibms is rebuilt), and exits 0; it needs no subcommand.
set -u
ibms=$1; version=$2; source_dir=$3
commit=$(git -C "$source_dir" rev-parse --short=12 HEAD 2>/dev/null) || commit=unknown
out=$("$ibms" --version 2>&1); code=$?
expected="ibms $version (commit $commit)"
lines=$(printf '%s\n' "$out" | wc -l)
if [[ $code -ne 0 || $lines -ne 1 || "$out" != "$expected" ]]; then
  echo "FAIL ibms --version: exit $code, $lines line(s): '$out' (expected '$expected'; a commit since the"
  echo "     last build needs a rebuild)"
  exit 1
fi
# The format itself: a dotted version and a 12-digit abbreviated commit (or "unknown" outside git).
if ! [[ "$out" =~ ^ibms\ [0-9]+\.[0-9]+\.[0-9]+\ \(commit\ ([0-9a-f]{12}|unknown)\)$ ]]; then
  echo "FAIL ibms --version: '$out' is not 'ibms X.Y.Z (commit <12 hex digits>)'"
  exit 1
fi
echo "ok   ibms --version: $out"
