#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# check-layers.sh refuses a panel, a mode or a tool that includes the window (ui/app): each gets
# one such include in a copy of the sources, and the check must fail naming that file; the copy
# as it is must pass (so a failure is the include's).
set -euo pipefail
source_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cp -r "$source_dir/core" "$source_dir/sculpt" "$source_dir/ui" "$source_dir/scripts" "$work/"
bash "$work/scripts/check-layers.sh" > /dev/null || { echo "the unchanged copy fails check-layers"; exit 1; }

for file in ui/panels/status_bar.cpp ui/modes/morph_mode.cpp ui/tools/sculpt/sculpt_tool.cpp; do
  cp "$work/$file" "$work/$file.orig"
  sed -i '1i #include "ui/app/sculpt_app.h"' "$work/$file"
  if output=$(bash "$work/scripts/check-layers.sh" 2>&1); then
    echo "check-layers passed although $file includes ui/app"
    exit 1
  fi
  grep -q "$file includes ui/app/" <<< "$output" || { echo "check-layers did not name $file: $output"; exit 1; }
  mv "$work/$file.orig" "$work/$file"
done
echo "check-layers refuses a panel, a mode and a tool that include ui/app"
