#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: install what is missing, build, then make the
# default clay ball, measure it and export it as a printable mesh into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh

mkdir -p out
sculpt=build/sculpt/sculpt
"$sculpt" new -o out/clay.vdb
"$sculpt" info out/clay.vdb
"$sculpt" mesh out/clay.vdb -o out/clay.ply
echo
echo "Files:"
echo "  document: $(realpath out/clay.vdb)"
echo "  mesh:     $(realpath out/clay.ply)"
