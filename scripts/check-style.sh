#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Checks that every C++ source is formatted by .clang-format (a CTest entry runs this), and, with
# --tidy BUILD_DIR, that it follows .clang-tidy's naming rules too (slower: run before a commit).
set -euo pipefail
cd "$(dirname "$0")/.."
mapfile -t sources < <(git ls-files 'core/*.cpp' 'core/*.h' 'sculpt/*.cpp' 'sculpt/*.h' 'ui/*.cpp' 'ui/*.h' \
                                     'tests/*.cpp' 'tests/*.h' 2>/dev/null || find core sculpt ui tests -name '*.cpp' -o -name '*.h')
clang-format --dry-run --Werror "${sources[@]}"
echo "check-style: ${#sources[@]} files formatted"
# Every source says its licence in its first line (after a script's #!), as SPDX writes it.
mapfile -t others < <(git ls-files 'CMakeLists.txt' '*/CMakeLists.txt' '*.cmake' '*.sh' '*.py' '.ci/run' 2>/dev/null)
unlicensed=0
for file in "${sources[@]}" "${others[@]}"; do
  if ! head -n 2 "$file" | grep -q "^\(//\|#\) SPDX-License-Identifier: Apache-2.0$"; then
    echo "check-style: $file: no 'SPDX-License-Identifier: Apache-2.0' line at its top" >&2
    unlicensed=1
  fi
done
((unlicensed == 0)) || exit 1
echo "check-style: $((${#sources[@]} + ${#others[@]})) files name their licence"
if [[ ${1:-} == --tidy ]]; then
  build=${2:-build}
  failed=0
  for source in "${sources[@]}"; do
    [[ $source == *.cpp ]] || continue
    if clang-tidy -p "$build" --quiet --warnings-as-errors='*' "$source" 2>/dev/null | grep -q "error:"; then
      clang-tidy -p "$build" --quiet "$source" 2>/dev/null | grep "warning:" || true
      failed=1
    fi
  done
  ((failed == 0)) && echo "check-style: naming rules hold"
  exit $failed
fi
