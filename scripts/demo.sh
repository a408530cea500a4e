#!/usr/bin/env bash
# The main job, from a fresh Debian 12 machine: install what is missing, build, then make the
# default clay ball, sculpt a face on it by replaying a stroke script, measure it and export it
# as a printable mesh and a rendered picture into out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh

mkdir -p out
sculpt=build/sculpt/cli/sculpt
"$sculpt" new -o out/clay.vdb
"$sculpt" apply out/clay.vdb data/strokes/face.json -o out/face.vdb
"$sculpt" info out/face.vdb
"$sculpt" mesh out/face.vdb -o out/face.ply
"$sculpt" render out/face.vdb -o out/face.png
echo
echo "Files:"
echo "  clay ball: $(realpath out/clay.vdb)"
echo "  sculpted:  $(realpath out/face.vdb)"
echo "  mesh:      $(realpath out/face.ply)"
echo "  picture:   $(realpath out/face.png)"
