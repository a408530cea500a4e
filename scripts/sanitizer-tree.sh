# SPDX-License-Identifier: Apache-2.0
# Sourced by scripts/fuzz.sh and scripts/sanitize.sh: configures build-sanitize/, one clang tree
# compiled with AddressSanitizer, UndefinedBehaviorSanitizer and libFuzzer's coverage hooks, so
# that the fuzz targets and the test suite are built from the same objects, once.
bash scripts/install-deps.sh --sanitizers
sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
sanitizers+=" -fsanitize-ignorelist=$PWD/tests/sanitizers/ubsan_ignorelist.txt"  # TBB's tagged pointers
CC=clang CXX=clang++ cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=None -DSCULPT_FUZZ=ON \
  -DSCULPT_BUILD_BENCHMARKS=OFF -DSCULPT_PRECOMPILE_HEADERS=OFF \
  -DCMAKE_CXX_FLAGS="-O1 -gline-tables-only -fsanitize=fuzzer-no-link $sanitizers" \
  -DCMAKE_EXE_LINKER_FLAGS="$sanitizers" >/dev/null
