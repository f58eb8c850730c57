#!/usr/bin/env bash
# Every "method.md §N" cited in the project names a section that exists in docs/method.md (a
# heading "## N.", "### N.M", or an appendix heading "## AN.", "### ANa."). One written form: each
# section with its own "§" (method.md §N.M, method.md §ANa), and a list after one "method.md" joined
# by ",", "and" or "/" (method.md §N.M, §AN; §N and §AN), as reports/report_trace.py reads them.
# (Letters, not numbers, in these examples: this script is a test's source, and the report would
# take a real number here for a citation.)
# Prints each citation that does not resolve with its file and line, and fails.
# Usage: test_method_citations.sh SOURCE_DIR
set -euo pipefail
cd "$1"
number='A?[0-9]+(\.[0-9]+)?[a-z]?'
sections=$(grep -oE "^#{2,3} $number[. ]" docs/method.md | sed -E 's/^#+ //; s/[. ]$//' | sort -u)
count=0
missing=0
while IFS= read -r hit; do
  file_line=${hit%%:method.md*}
  while IFS= read -r section; do
    count=$((count + 1))
    if ! grep -qxF "$section" <<<"$sections"; then
      echo "$file_line: method.md §$section: no such section in docs/method.md"
      missing=$((missing + 1))
    fi
  done < <(grep -oE "§ *$number" <<<"${hit#*:method.md}" | sed -E 's/^§ *//')
done < <(grep -rnoE --include='*.cpp' --include='*.hpp' --include='*.py' --include='*.sh' --include='*.md' \
           --include='*.toml' --include='*.txt' --include='*.cmake' \
           "method\.md *§ *$number( *(,|and|/) *§ *$number)*" \
           solver verification bench validation reports scripts workflow docs README.md CMakeLists.txt)
echo "test_method_citations: $count citations, $missing unresolved"
((count > 0)) && ((missing == 0))
