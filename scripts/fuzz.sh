#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Fuzzes the parsers with libFuzzer under AddressSanitizer and UndefinedBehaviorSanitizer, each
# target for SECONDS (default 120: the fifteen targets take about 15 minutes on 2 cores), starting
# from the seed corpus kept in tests/fuzz/corpus/.
#   usage: scripts/fuzz.sh [SECONDS] [TARGET...]     (targets: see tests/fuzz/CMakeLists.txt)
# Runs as many targets at once as there are cores and prints each one's executions and findings.
# A finding (crash, sanitizer report, hang over 20 s, allocation over 2 GB) is written to
# build-sanitize/findings/TARGET/; shrink it with `build-sanitize/tests/fuzz/fuzz_TARGET -minimize_crash=1
# -runs=10000 FILE`, fix the cause, and add the file to tests/bad-inputs/ (its README and the
# SculptCliRegression list) so that the ordinary suite replays it.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-120}"
shift || true
all=$(sed -n 's/^set(SCULPT_FUZZ_TARGETS \(.*\))$/\1/p' tests/fuzz/CMakeLists.txt)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || read -r -a targets <<<"$all"

source scripts/sanitizer-tree.sh
cmake --build build-sanitize -j"$(nproc)" --target "${targets[@]/#/fuzz_}"

run_one() {
  local target=$1 seconds=$2
  local corpus=build-sanitize/corpus/$target findings=build-sanitize/findings/$target
  mkdir -p "$corpus" "$findings" build-sanitize/logs
  find tests/fuzz/corpus/"$target" -type f ! -name '*.md' -exec cp -n {} "$corpus"/ \;
  UBSAN_OPTIONS=print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
    build-sanitize/tests/fuzz/fuzz_"$target" "$corpus" -max_total_time="$seconds" -timeout=20 \
      -rss_limit_mb=2048 -malloc_limit_mb=2048 -print_final_stats=1 \
      -artifact_prefix="$findings"/ >"build-sanitize/logs/$target.log" 2>&1 || true
  local runs
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "build-sanitize/logs/$target.log" | tail -1)
  echo "$target: ${runs:-0} executions in ${seconds} s, $(ls "$findings" | wc -l) findings in $findings"
}
export -f run_one
printf '%s\n' "${targets[@]}" | xargs -P "$(nproc)" -I{} bash -c "run_one {} $seconds"
