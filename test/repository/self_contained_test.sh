#!/usr/bin/env bash
# The repository stands on its own: no tracked file refers to a path outside it (the
# parent's shared folder), and no code comment cites a document outside the repository or an
# issue tracker's number (they cite docs/REFERENCE.md or the thesis instead).
#
#   test/repository/self_contained_test.sh [REPOSITORY_ROOT]
set -uo pipefail
root=${1:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)}
cd "$root" || exit 2
self=test/repository/self_contained_test.sh
outside='\.\./'shared
citations='INTERFACE(\.md| section)|[Ii]ssue [0-9]'
code=('*.cpp' '*.h' '*.txt' '*.cmake' '*.py' '*.sh' '*.yaml' '*.launch')
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  found_outside=$(git grep -nIE "$outside" -- . ":!$self")
  found_citations=$(git grep -nE "$citations" -- "${code[@]}" ":!$self")
else
  includes=()
  for pattern in "${code[@]}"; do includes+=(--include="$pattern"); done
  found_outside=$(grep -rnIE "$outside" --exclude-dir='build*' --exclude-dir=.git . |
    grep -v "^\./$self:")
  found_citations=$(grep -rnE "$citations" "${includes[@]}" --exclude-dir='build*' . |
    grep -v "^\./$self:")
fi
status=0
if [ -n "$found_outside" ]; then
  echo "FAIL: files that refer to a folder outside the repository:"
  echo "$found_outside"
  status=1
fi
if [ -n "$found_citations" ]; then
  echo "FAIL: comments that cite a document outside the repository or an issue number:"
  echo "$found_citations"
  status=1
fi
[ $status -eq 0 ] && echo "the repository refers to nothing outside it"
exit $status
