#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The main job, from a fresh Debian 12 machine: install what is missing, build, and open
# sculpt-ui on the default clay ball. On a machine with no display, say so, then show the same
# thing headless: replay the face script in sculpt-ui under Xvfb, save the sculpted document,
# its mesh and a screenshot of the window, render a picture with `sculpt render`, and print
# where they went.
#
# For its test (tests/CMakeLists.txt): SCULPT_DEMO_BUILD names a tree already built (nothing is
# installed or built then), SCULPT_DEMO_OUT where the files go (default out/).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${SCULPT_DEMO_BUILD:-}
if [[ -z $build ]]; then
  bash scripts/install-deps.sh
  bash scripts/build.sh
  build=build
fi
out=${SCULPT_DEMO_OUT:-out}

ui=$build/ui/sculpt-ui
sculpt=$build/sculpt/cli/sculpt
if [[ -n ${DISPLAY:-} ]]; then
  status=0
  "$ui" || status=$?
  ((status != 2)) && exit $status  # 2: no window could be opened on this display
  echo "demo: sculpt-ui could not open a window on DISPLAY=$DISPLAY, so it runs headless under Xvfb instead"
else
  echo "demo: no display here (DISPLAY is not set), so sculpt-ui runs headless under Xvfb: it replays the face script"
fi
mkdir -p "$out"
xvfb-run -a -s '-screen 0 1280x800x24' "$ui" --strokes data/strokes/face.json \
  --save-as "$out/face.vdb" --export "$out/face.ply" --screenshot "$out/face-ui.png" --state-dir "$out/.state"
xvfb-run -a -s '-screen 0 1280x800x24' "$ui" --play data/ui/mid-sculpt.json \
  --screenshot "$out/clay-ui.png" --state-dir "$out/.state"
"$sculpt" info "$out/face.vdb"
"$sculpt" render "$out/face.vdb" -o "$out/face.png"
echo
echo "Files:"
echo "  sculpted in the UI:     $(realpath "$out/face.vdb")"
echo "  its mesh:               $(realpath "$out/face.ply")"
echo "  the window:             $(realpath "$out/face-ui.png")"
echo "  the clay ball mid-sculpt: $(realpath "$out/clay-ui.png")"
echo "  rendered picture:       $(realpath "$out/face.png")"
