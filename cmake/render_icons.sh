#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Renders the application icon with the program itself: the clay ball with the face the example
# stroke script sculpts, ray-traced at each size on a transparent background.
# usage: render_icons.sh SCULPT STROKES OUTDIR NAME
set -euo pipefail
sculpt=$1 strokes=$2 outdir=$3 name=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$sculpt" new -o "$work/clay.vdb" --quiet
"$sculpt" apply "$work/clay.vdb" "$strokes" -o "$work/face.vdb" --quiet
for size in 48 64 128 256; do
  mkdir -p "$outdir/hicolor/${size}x$size/apps"
  "$sculpt" render "$work/face.vdb" -o "$outdir/hicolor/${size}x$size/apps/$name.png" --width "$size" --height "$size" \
    --background none --quiet
done
