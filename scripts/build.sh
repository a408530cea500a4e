#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Configures and builds the Release tree in build/ (tests and benchmarks included).
# SCULPT_WERROR=ON in the environment makes any warning in our code an error (CI sets it).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DSCULPT_WERROR="${SCULPT_WERROR:-OFF}"
cmake --build build -j"$(nproc)"
