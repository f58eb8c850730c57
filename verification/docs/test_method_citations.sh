#!/usr/bin/env bash
# Every "method.md §N" or "method.md §N.M" cited in the project names a section that exists in
# docs/method.md (a heading "## N." or "### N.M"). Prints each citation that does not resolve
# with its file and line, and fails.
# Usage: test_method_citations.sh SOURCE_DIR
set -euo pipefail
cd "$1"
sections=$(grep -oE '^#{2,3} [0-9]+(\.[0-9]+)?[. ]' docs/method.md | sed -E 's/^#+ //; s/[. ]$//' | sort -u)
count=0
missing=0
while IFS= read -r hit; do
  file_line=${hit%%:method.md*}
  section=$(sed -E 's/.*§ ?([0-9]+(\.[0-9]+)*).*/\1/' <<<"$hit")
  count=$((count + 1))
  if ! grep -qxF "$section" <<<"$sections"; then
    echo "$file_line: method.md §$section: no such section in docs/method.md"
    missing=$((missing + 1))
  fi
done < <(grep -rnoE --include='*.cpp' --include='*.hpp' --include='*.py' --include='*.sh' --include='*.md' \
           --include='*.toml' --include='*.txt' --include='*.cmake' 'method\.md ?§ ?[0-9]+(\.[0-9]+)*' \
           solver verification bench validation reports scripts workflow docs README.md CMakeLists.txt)
echo "test_method_citations: $count citations, $missing unresolved"
((count > 0)) && ((missing == 0))
